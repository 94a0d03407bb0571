// gecko/elliptic/ellint_k.hpp — complete elliptic integral of the first kind, parameter m = k^2:
//   K(m) = int_0^(pi/2) dtheta / sqrt(1 - m sin^2 theta) = R_F(0, 1 - m, 1)     (DLMF 19.25.1)
//
// Evaluated as K = pi / (2 M(1, sqrt(1 - m))) with Gauss's arithmetic-geometric mean M
// (DLMF 19.8.1; equivalently R_F(0, y, z) = pi / (2 M(sqrt y, sqrt z)), DLMF 19.22.1): one
// square root per step and quadratic convergence, against three square roots per duplication
// step of R_F. The iteration stops once |a - b| <= 2 sqrt(r) a (r the target relative error,
// gecko/elliptic/carlson_tolerance.hpp); the next arithmetic mean then equals M to within
// (a - b)^2 / (16 a) <= r/4, so that mean is returned without forming the last geometric one.
//
// Domain: m <= 1. K(1) = +inf (the logarithmic pole, returned, not an error); K(-inf) = 0 (the
// limit). m > 1 is a domain error. NaN gives NaN quietly.
// 1 - m is exact for 1/2 <= m <= 1 (Sterbenz), so K keeps full relative accuracy up to the pole.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {
namespace detail {

// Unchecked kernel: finite m < 1.
template <class T, class Policy = policies::default_policy>
inline T ellint_k_imp(T m) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol = carlson_tolerance<T, Policy::precision_bits>::agm;
  T a = 1;
  T b = sqrt(1 - m);
  while (fabs(a - b) > tol * a) {
    const T g = sqrt(a * b);
    a = (a + b) * T(0.5);
    b = g;
  }
  return T(3.141592653589793238462643383279502884L) / (a + b);
}

}  // namespace detail

template <class T, class Policy>
inline T ellint_k(T m, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::ellint_k: T must be a floating-point type");
  using std::isinf;
  using std::isnan;
  if (isnan(m)) return std::numeric_limits<T>::quiet_NaN();
  if (m > 1) return raise_domain_error<T, Policy>("gecko::ellint_k", "m", m, "m <= 1");
  if (m == 1) return std::numeric_limits<T>::infinity();
  if (isinf(m)) return T(0);
  return detail::ellint_k_imp<T, Policy>(m);
}

template <class T>
inline T ellint_k(T m) {
  return ellint_k(m, policies::default_policy());
}

}  // namespace gecko
