// gecko/elliptic/ellint_e.hpp — incomplete elliptic integral of the second kind, parameter m:
//   E(phi|m) = int_0^phi sqrt(1 - m sin^2 theta) dtheta                        (DLMF 19.2.5)
//
// 0 <= phi <= pi/2, s = sin phi, c = cos phi, Delta^2 = c^2 + (1 - m) s^2 (m <= 1):
//   m <= 0:     E = s R_F(c^2, Delta^2, 1) - (m/3) s^3 R_D(c^2, Delta^2, 1)    (DLMF 19.25.9,
//               scaled by homogeneity; both terms >= 0 here)
//   0 < m <= 1: E = (1-m) s R_F(c^2, Delta^2, 1) + (m(1-m)/3) s^3 R_D(c^2, 1, Delta^2)
//                   + m s c / Delta                                            (DLMF 19.25.10)
//               All terms >= 0: the textbook form subtracts two numbers ~ log(1/Delta) to get
//               E ~ 1 when m -> 1, phi -> pi/2; this one cannot cancel.
//   m > 1:      E = ((m-1)/3) s^3 R_D(Delta^2, 1, c^2) + Delta s / c,
//               Delta^2 = 1 - m s^2                                           (DLMF 19.25.11,
//               with -k'^2 = m - 1 > 0: again only positive terms)
// In the first two cases R_F and R_D share their arguments and come from one duplication.
// |phi| > pi/2 (m <= 1): phi = j pi/2 + r, |r| <= pi/4,
//   j even: E = j E(m) + E(r)                                                  (DLMF 19.2.10)
//   j odd:  E = j E(m) + (E(m) - E(pi/2 - r)), the bracket evaluated as
//           (1-m) sin r R_F(L, sin^2 r + L, 1-m) + (m(1-m)/3) sin^3 r R_D(L, sin^2 r + L, 1-m),
//           L = (1-m) cos^2 r: the tail over [pi/2 - r, pi/2] after the imaginary-modulus
//           transformation (DLMF 19.7.5), scaled by homogeneity (for 1 - m > 1/eps the
//           arguments are divided by 1 - m first). m = 1: E(phi|1) = int |cos|.
//   |phi| >= 2^(digits-1): E = (2/pi) phi E(m).
// E is odd in phi.
//
// Domain as ellint_f: finite phi; m <= 1, or m > 1 with |phi| <= arcsin(1/sqrt m).
// m = -inf gives +-inf (0 at phi = 0). NaN gives NaN quietly.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/angle_reduction.hpp"
#include "gecko/elliptic/first_quadrant_sincos.hpp"
#include "gecko/elliptic/carlson_rd.hpp"
#include "gecko/elliptic/carlson_rf_rd.hpp"
#include "gecko/elliptic/edge_delta.hpp"
#include "gecko/elliptic/ellint_ek.hpp"
#include "gecko/elliptic/legendre_domain.hpp"
#include "gecko/elliptic/legendre_rf_rd.hpp"

namespace gecko {
namespace detail {

template <class T, class Policy>
inline T ellint_e_m_above_one(T s, T c, T d2, T m);

// E(phi|m) for 0 <= phi <= pi/2 from s = sin phi >= 0, c = cos phi >= 0, (phi, m) in domain.
template <class T, class Policy = policies::default_policy>
inline T ellint_e_sc(T s, T c, T m) {
  using std::fma;
  using std::sqrt;
  const T c2 = c * c;
  const T s2 = s * s;
  if (m <= 0) {
    const T d2 = c2 + (1 - m) * s2;
    // m -> -inf (Delta^2 >= 1/eps): the unscaled duplication, whose arguments cannot overflow
    const auto r = d2 < 1 / std::numeric_limits<T>::epsilon()
                       ? legendre_rf_rd_imp<T, Policy>(c2, d2, T(1), c, sqrt(d2), T(1))
                       : carlson_rf_rd_imp<T, Policy>(c2, d2, T(1));
    return s * (r.rf - (m / 3) * s2 * r.rd);
  }
  if (m <= 1) {
    const T k2 = 1 - m;
    const T d2 = c2 + k2 * s2;  // <= 1
    const T d = sqrt(d2);
    const auto r = legendre_rf_rd_imp<T, Policy>(c2, T(1), d2, c, T(1), d);
    return s * (k2 * r.rf + (m * k2 / 3) * s2 * r.rd + m * c / d);
  }
  // m > 1: ellint_e_m_above_one, with Delta^2 from double-word sin and cos.
  return ellint_e_m_above_one<T, Policy>(s, c, fma(-((m - 1) * s), s, c2), m);
}

// E(phi|m) for m > 1, 0 <= phi <= arcsin(1/sqrt m), from s = sin phi, c = cos phi and
// Delta^2 = 1 - m s^2 (DLMF 19.25.11 with -k'^2 = m - 1 > 0: only positive terms). Delta^2 must
// be consistent with s and c: near the boundary the two terms' singular parts in sqrt(Delta^2)
// cancel; a Delta^2 off by an ulp of 1 is amplified by the R_D term by about 0.1/(m-1): 4.8e6 eps
// at m = 1 + 1e-7 (found by fuzz/fuzz_legendre.cpp). The caller forms it from double-word sin and
// cos (gecko/elliptic/edge_delta.hpp), accurate at the exact phi.
template <class T, class Policy>
inline T ellint_e_m_above_one(T s, T c, T d2, T m) {
  using std::sqrt;
  const T c2 = c * c;
  const T s2 = s * s;
  if (d2 < 0) {
    // phi beyond the edge by rounding (accepted by the domain check): evaluate AT the edge,
    // sin^2 = 1/m, cos^2 = (m-1)/m, Delta = 0. Clamping Delta^2 alone would leave c^2 below
    // (m-1)/m, and the R_D term ~ (m-1)/c^2 would exceed E's maximum: E(1.5707963 | 1 + 7 ulp)
    // gave 1 + 1.8e-8 > sin phi (found by fuzz/fuzz_legendre.cpp).
    const T ce2 = (m - 1) / m;
    return ((m - 1) / (3 * m)) * carlson_rd_imp<T, Policy>(T(0), T(1), ce2) / sqrt(m);
  }
  const T rd = carlson_rd_imp<T, Policy>(d2, T(1), c2);
  return s * (((m - 1) / 3) * s2 * rd + sqrt(d2) / c);
}

// Unchecked kernel: finite phi, finite m, (phi, m) in the real domain.
template <class T, class Policy = policies::default_policy>
inline T ellint_e_imp(T phi, T m) {
  using std::copysign;
  using std::cos;
  using std::fabs;
  using std::fma;
  using std::sin;
  using std::sqrt;
  const T a = fabs(phi);
  if (m > 1) {
    const auto e = m_above_one_arguments(a, m);
    return copysign(ellint_e_m_above_one<T, Policy>(e.s, e.c, e.d2, m), phi);
  }
  if (a <= pi_constants<T>::pio2_below) {
    T s, c;
    first_quadrant_sincos(a, s, c);
    return copysign(ellint_e_sc<T, Policy>(s, c, m), phi);
  }
  // Beyond pi/2 only m <= 1 is in the domain.
  const T Em = (m == 1) ? T(1) : ellint_e_complete_imp<T, Policy>(m);
  if (!(a < reduction_limit<T>())) {
    T hi, lo;
    times_two_over_pi(a, hi, lo);
    return copysign(fma(Em, hi, Em * lo), phi);
  }
  const auto q = reduce_quadrant(a);
  const T s = sin(q.r);
  const T c = cos(q.r);
  T part;
  if (is_even(q.j)) {
    part = copysign(ellint_e_sc<T, Policy>(fabs(s), c, m), q.r);
  } else if (m == 1) {
    // E(pi/2 + r | 1) - 1 = sign(r) (1 - cos r) = sin r |sin r| / (1 + cos r).
    part = s * fabs(s) / (1 + c);
  } else {
    const T lam = 1 - m;
    const T s2 = s * s;
    if (lam > 1 / std::numeric_limits<T>::epsilon()) {
      // m -> -inf: the arguments above, divided by 1 - m (homogeneity), so that their sum cannot
      // overflow and R_D (~ (1-m)^(-3/2)) cannot underflow (fuzz finding F5: E(48.7 | -DBL_MAX)
      // gave NaN, E(2.17 | -2^698) was 5% off):
      //   part = s sqrt(1-m) (R_F(c^2, s^2/(1-m) + c^2, 1) + (m/(1-m))/3 s^2 R_D(.., 1)).
      // Only here: moderate m keep the route the accuracy tables test.
      const T c2 = c * c;
      const auto r = carlson_rf_rd_imp<T, Policy>(c2, s2 / lam + c2, T(1));
      part = s * sqrt(lam) * (r.rf + ((m / lam) / 3) * s2 * r.rd);
    } else {
      const T lc2 = lam * (c * c);
      const auto r = carlson_rf_rd_imp<T, Policy>(lc2, s2 + lc2, lam);
      part = s * lam * (r.rf + (m / 3) * s2 * r.rd);
    }
  }
  return copysign(fma(q.j, Em, part), phi);
}

}  // namespace detail

template <class T, class Policy>
inline T ellint_e(T phi, T m, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::ellint_e: T must be a floating-point type");
  using std::isfinite;
  using std::isinf;
  using std::isnan;
  constexpr const char* function = "gecko::ellint_e";
  if (isnan(phi) || isnan(m)) return std::numeric_limits<T>::quiet_NaN();
  if (!isfinite(phi)) return raise_domain_error<T, Policy>(function, "phi", phi, "finite phi");
  if (m > 1 && (isinf(m) || !detail::in_domain_m_above_one(phi, m)))
    return raise_domain_error<T, Policy>(function, "m", m, detail::legendre_m_range);
  if (isinf(m)) return phi == 0 ? phi : std::copysign(std::numeric_limits<T>::infinity(), phi);
  return detail::ellint_e_imp<T, Policy>(phi, m);
}

template <class T>
inline T ellint_e(T phi, T m) {
  return ellint_e(phi, m, policies::default_policy());
}

}  // namespace gecko
