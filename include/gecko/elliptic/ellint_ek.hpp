// gecko/elliptic/ellint_ek.hpp — both complete integrals E(m) and K(m) from one duplication.
//
//   K(m) = R_F(0, 1 - m, 1)                                          (DLMF 19.25.1)
//   m <= 0:      E = R_F(0, y, 1) - (m/3) R_D(0, y, 1),    y = 1 - m  (DLMF 19.25.1; both terms >= 0)
//   0 < m < 1:   E = y K + (m y/3) R_D(0, 1, y)                       (DLMF 19.25.1, E - k'^2 K form)
// The second form has only positive terms: near m = 1 the first one would subtract two
// logarithmically large numbers (K ~ R_D ~ log(16/(1-m))) to get E ~ 1. In both cases R_F and
// R_D share their arguments up to order, so carlson_rf_rd_imp computes them together.
//
// Domain: m <= 1; E(1) = 1, K(1) = +inf; m = -inf gives E = +inf, K = 0. NaN gives NaN quietly.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_rf_rd.hpp"

namespace gecko {

template <class T>
struct ellint_ek_result {
  T E;
  T K;
};

namespace detail {

// Unchecked kernel: finite m < 1.
template <class T, class Policy = policies::default_policy>
inline ellint_ek_result<T> ellint_ek_imp(T m) {
  const T y = 1 - m;
  if (m <= 0) {
    const auto r = carlson_rf_rd_imp<T, Policy>(T(0), y, T(1));
    return {r.rf - (m / 3) * r.rd, r.rf};
  }
  const auto r = carlson_rf_rd_imp<T, Policy>(T(0), T(1), y);
  return {y * r.rf + (m * y / 3) * r.rd, r.rf};
}

// E(m) alone (same formulas; the seta and Legendre code call it for the secular term).
template <class T, class Policy = policies::default_policy>
inline T ellint_e_complete_imp(T m) {
  return ellint_ek_imp<T, Policy>(m).E;
}

}  // namespace detail

template <class T, class Policy>
inline ellint_ek_result<T> ellint_ek(T m, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::ellint_ek: T must be a floating-point type");
  using std::isinf;
  using std::isnan;
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (isnan(m)) return {m, m};
  if (m > 1) {
    const T nan = raise_domain_error<T, Policy>("gecko::ellint_ek", "m", m, "m <= 1");
    return {nan, nan};
  }
  if (m == 1) return {T(1), inf};
  if (isinf(m)) return {inf, T(0)};
  return detail::ellint_ek_imp<T, Policy>(m);
}

template <class T>
inline ellint_ek_result<T> ellint_ek(T m) {
  return ellint_ek(m, policies::default_policy());
}

}  // namespace gecko
