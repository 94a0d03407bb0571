// gecko/elliptic/ellint_f.hpp — incomplete elliptic integral of the first kind, parameter m = k^2:
//   F(phi|m) = int_0^phi dtheta / sqrt(1 - m sin^2 theta)                      (DLMF 19.2.4)
//
// |phi| <= pi/2:  F = s R_F(c^2, Delta^2, 1)  with s = sin phi, c = cos phi       (DLMF 19.25.5)
//   Delta^2 = c^2 + (1 - m) s^2 for m <= 1: a sum of non-negative terms, so it keeps full relative
//   accuracy when m -> 1 and phi -> pi/2 (1 - m s^2 would cancel catastrophically; 1 - m is exact
//   by Sterbenz for m >= 1/2, and cos phi of the exact phi is accurate near pi/2).
//   For m > 1, Delta^2 = 1 - m s^2 from double-word sin and cos (gecko/elliptic/edge_delta.hpp),
//   clamped at 0 on the boundary: next to the edge sin^2 phi = 1/m it cancels, and a rounded
//   sin phi alone moved F by up to eps/Delta (10.6 eps at m = 1.46e5, m sin^2 phi = 0.9993).
// |phi| > pi/2 (m <= 1):  phi = j pi/2 + r, |r| <= pi/4 (gecko/elliptic/angle_reduction.hpp),
//   j even: F = j K + F(r)                                                 (DLMF 19.2.10)
//   j odd:  F = j K + (K - F(pi/2 - r)), and the bracket is evaluated without cancellation as
//           K - F(pi/2 - r) = sin r R_F((1-m) cos^2 r, sin^2 r + (1-m) cos^2 r, 1 - m),
//           the tail integral over [pi/2 - r, pi/2] after theta -> pi/2 - theta, which has
//           parameter -m/(1-m) (imaginary-modulus transformation, DLMF 19.7.5), scaled by
//           homogeneity (DLMF 19.18.1); for 1 - m > 1/eps as sin r R_F(cos^2 r,
//           sin^2 r/(1-m) + cos^2 r, 1)/sqrt(1-m), whose arguments cannot overflow.
//   |phi| >= 2^(digits-1): F = (2/pi) phi K; the periodic part dropped is about 2^(1-digits)
//           relative at most.
// F is odd in phi. m = 1: F = atanh(sin phi) for |phi| < pi/2, +-inf beyond.
//
// Domain: finite phi; m <= 1, or m > 1 with |phi| <= arcsin(1/sqrt m). m = -inf gives 0.
// NaN in phi or m gives NaN quietly.
// Speed (this is the kernel the library calls most): sin and cos of the reduced amplitude come
// from an inline polynomial (gecko/elliptic/first_quadrant_sincos.hpp); R_F(c^2, Delta^2, 1) by
// the scaled product-form duplication of legendre_rf_imp below, whose first step uses the known
// roots sqrt(c^2) = c and sqrt(1) = 1, and a degree-11 series (Carlson's degree-7 one would need
// about 1.1 more steps; degree 15 saves half a step but its 11 extra terms cost more).
// Conditioning note: for m > 1 near the boundary, dF/dphi = 1/Delta is unbounded, but the
// argument phi is exact and Delta^2 is formed to full relative accuracy from it, so F stays
// within a few eps of its exact value at the given phi and m.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/angle_reduction.hpp"
#include "gecko/elliptic/edge_delta.hpp"
#include "gecko/elliptic/first_quadrant_sincos.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/ellint_k.hpp"
#include "gecko/elliptic/legendre_domain.hpp"

namespace gecko {
namespace detail {

// s R_F(c^2, d2, 1): F for 0 <= phi <= pi/2 from s = sin phi >= 0, c = cos phi >= 0 and
// d2 = Delta^2 = 1 - m s^2 >= 0 (c and d2 not both zero), d2 < 1/eps (the scaled arguments below
// grow like 4^n).
// Carlson's duplication (DLMF 19.26.18) in product form: with the roots of the arguments,
//   x + lambda = (sqrt x + sqrt y)(sqrt x + sqrt z), lambda = sqrt(xy) + sqrt(xz) + sqrt(yz),
// and the arguments kept multiplied by 4^n (X_n = 4^n x_n, ...), so that a step is three square
// roots, three additions and three multiplications (the mean A_n is not carried; its deviations
// A_n - x_n = 4^-n (A_0 - x_0) are exact, DLMF 19.36.1, and stay dx, dy at that scale). At the end
// R_F(x_0, y_0, z_0) = 2^n R_F(X_n, Y_n, Z_n) (homogeneity, DLMF 19.18.1 with degree -1/2), with
// the degree-11 series (gecko/elliptic/carlson_rf.hpp) at X = dx/A'_n. The first step uses the
// known roots sqrt(c^2) = c, sqrt(1) = 1 and is always taken: it costs one square root, which is
// less than the mispredicted branch that skipped it for about a quarter of random inputs.
// The square root of A'_n and the division that applies it run beside the series, not after it.
template <class T, class Policy>
inline T legendre_rf_imp(T s, T c, T d2) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol = carlson_tolerance<T, Policy::precision_bits>::rf11;
  const T x = c * c;
  const T A0 = (x + d2 + 1) * (T(1) / 3);
  const T dx = A0 - x;
  const T dy = A0 - d2;
  const T D = max_of(max_of(fabs(dx), fabs(dy)), fabs(A0 - 1));
  const T d = sqrt(d2);
  const T cd = c + d, c1 = c + 1, d1 = d + 1;
  T X = cd * c1, Y = cd * d1, Z = c1 * d1;  // 4 x_1, 4 y_1, 4 z_1
  T g = 2;                                  // 2^n
  // Stop when max|A_0 - x_0| < tol A'_n, i.e. every series argument |X| < tol; 3 A'_n = X + Y + Z.
  const T lim = D * (3 / tol);
  for (int step = 1; X + Y + Z <= lim && step < carlson_max_steps<T>; ++step) {
    const T rx = sqrt(X), ry = sqrt(Y), rz = sqrt(Z);
    const T xy = rx + ry, xz = rx + rz, yz = ry + rz;
    X = xy * xz;
    Y = xy * yz;
    Z = xz * yz;
    g *= 2;
  }
  const T A = (X + Y + Z) * (T(1) / 3);
  const T r = 1 / A;
  const T w = (s * g) / sqrt(A);
  return w + w * carlson_rf_series11_tail(dx * r, dy * r);
}

// F(phi|m) for 0 <= phi <= pi/2 and m <= 1 from s = sin phi >= 0 and c = cos phi >= 0.
template <class T, class Policy = policies::default_policy>
inline T ellint_f_sc(T s, T c, T m) {
  using std::sqrt;
  const T c2 = c * c;
  const T d2 = c2 + (1 - m) * (s * s);
  if (d2 < 1 / std::numeric_limits<T>::epsilon()) return legendre_rf_imp<T, Policy>(s, c, d2);
  // m -> -inf: the unscaled duplication, whose arguments cannot overflow
  return s * carlson_rf_roots_imp<T, Policy>(c2, d2, T(1), c, sqrt(d2), T(1));
}

// |phi| = a <= pi/2 (below the double-rounded pi/2) and m <= 1, finite: the common case.
template <class T, class Policy = policies::default_policy>
inline T ellint_f_quadrant(T phi, T a, T m) {
  using std::copysign;
  T s, c;
  first_quadrant_sincos(a, s, c);
  return copysign(ellint_f_sc<T, Policy>(s, c, m), phi);
}

// Unchecked kernel: finite phi, finite m, (phi, m) in the real domain.
template <class T, class Policy = policies::default_policy>
inline T ellint_f_imp(T phi, T m) {
  using std::copysign;
  using std::cos;
  using std::fabs;
  using std::fma;
  using std::sin;
  using std::sqrt;
  const T a = fabs(phi);
  if (m > 1) {
    // Only |phi| <= arcsin(1/sqrt m) < pi/2 is in the domain: Delta^2 from double-word sin and
    // cos (gecko/elliptic/edge_delta.hpp), so that F is accurate at the exact phi up to the edge.
    const auto e = m_above_one_arguments(a, m);
    const T d2 = e.d2 < 0 ? T(0) : e.d2;
    return copysign(legendre_rf_imp<T, Policy>(e.s, e.c, d2), phi);
  }
  if (a <= pi_constants<T>::pio2_below) return ellint_f_quadrant<T, Policy>(phi, a, m);
  // Beyond pi/2 only m <= 1 is in the domain.
  if (m == 1) return copysign(std::numeric_limits<T>::infinity(), phi);
  const T K = ellint_k_imp<T, Policy>(m);
  if (!(a < reduction_limit<T>())) {
    T hi, lo;
    times_two_over_pi(a, hi, lo);
    return copysign(fma(K, hi, K * lo), phi);
  }
  const auto q = reduce_quadrant(a);
  const T s = sin(q.r);
  const T c = cos(q.r);
  T part;
  if (is_even(q.j)) {
    part = copysign(ellint_f_sc<T, Policy>(fabs(s), c, m), q.r);
  } else {
    const T lam = 1 - m;
    if (lam > 1 / std::numeric_limits<T>::epsilon()) {
      // m -> -inf: the arguments divided by 1 - m (homogeneity), or their sum overflows (fuzz
      // finding F5: NaN for 1 - m near DBL_MAX). Only here: moderate m keep the tested route.
      const T c2 = c * c;
      part = s * carlson_rf_imp<T, Policy>(c2, (s * s) / lam + c2, T(1)) / sqrt(lam);
    } else {
      const T lc2 = lam * (c * c);
      part = s * carlson_rf_imp<T, Policy>(lc2, s * s + lc2, lam);
    }
  }
  return copysign(fma(q.j, K, part), phi);
}

}  // namespace detail

template <class T, class Policy>
inline T ellint_f(T phi, T m, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::ellint_f: T must be a floating-point type");
  using std::copysign;
  using std::isfinite;
  using std::isinf;
  using std::isnan;
  constexpr const char* function = "gecko::ellint_f";
  // The common case first, ahead of the checks it cannot fail (false for NaN phi or m): measured
  // 5-10 % of the whole call when the checks and the rare paths came first.
  const T a = std::fabs(phi);
  if (a <= detail::pi_constants<T>::pio2_below && m <= 1 && m >= -std::numeric_limits<T>::max())
    return detail::ellint_f_quadrant<T, Policy>(phi, a, m);
  if (isnan(phi) || isnan(m)) return std::numeric_limits<T>::quiet_NaN();
  if (!isfinite(phi)) return raise_domain_error<T, Policy>(function, "phi", phi, "finite phi");
  if (m > 1 && (isinf(m) || !detail::in_domain_m_above_one(phi, m)))
    return raise_domain_error<T, Policy>(function, "m", m, detail::legendre_m_range);
  if (isinf(m)) return copysign(T(0), phi);  // m = -inf: F -> 0
  return detail::ellint_f_imp<T, Policy>(phi, m);
}

template <class T>
inline T ellint_f(T phi, T m) {
  return ellint_f(phi, m, policies::default_policy());
}

}  // namespace gecko
