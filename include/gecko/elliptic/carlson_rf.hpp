// gecko/elliptic/carlson_rf.hpp — Carlson's symmetric integral of the first kind
//   R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t + x)(t + y)(t + z))       (DLMF 19.16.1)
//
// Algorithm: Carlson's duplication (DLMF 19.26.18, 19.36.1; Carlson 1995, Numer. Algorithms 10)
// followed by the Taylor series in E2 = XY - Z^2, E3 = XYZ (DLMF 19.19.7 with a = 1/2):
//   R_F = A^(-1/2) sum_{m,n} (-1)^m (1/2)_(m+n) / (m! n! (4m + 6n + 1)) E2^m E3^n
//       = A^(-1/2) (1 - E2/10 + E3/14 + E2^2/24 - 3 E2 E3/44 - 5 E2^3/208 + 3 E3^2/104
//                   + E2^2 E3/16 + ...),
// here truncated after degree 15 (2m + 3n <= 15; DLMF 19.36.1 stops at degree 7). The longer
// series lets the duplication stop at max|X| < 0.113 instead of 0.0116 for double
// (gecko/elliptic/carlson_tolerance.hpp): about 1.6 steps fewer, each of which costs three
// dependent square roots, while the 27 series terms are cheap multiply-adds evaluated in six
// independent chains. Each step costs the three square roots that cannot be avoided and no
// division; the end costs one square root and one division.
//
// Domain: x, y, z >= 0 with at most one of them zero. Any argument +inf gives 0 (the limit).
// NaN in any argument gives NaN quietly (no error is raised for NaN input).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_arguments.hpp"
#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {
namespace detail {

// The series after the duplication loop: X, Y are the scaled deviations (Z = -X - Y); returns
// the bracket sum - 1 of the degree-15 series (coefficients exact: (-1)^m (1/2)_(m+n) /
// (m! n! (4m + 6n + 1)), generated with Python's fractions). Estrin's scheme in E2 and E3:
// the Horner form of the same polynomial is a chain of 12 dependent multiply-adds, which
// measured slower than the duplication step it saves.
template <class T>
inline T carlson_rf_series_tail(T X, T Y) {
  const T Z = -(X + Y);
  const T E2 = X * Y - Z * Z;
  const T E3 = X * Y * Z;
  const T e4 = E2 * E2;
  const T e8 = e4 * e4;
  // coefficient of E3^n, n = 0..5, as polynomials in E2 (p0 without its constant 1)
  const T p0 = E2 * ((T(-1) / 10 + E2 * (T(1) / 24)) + e4 * (T(-5) / 208 + E2 * (T(35) / 2176)) +
                     e8 * ((T(-3) / 256 + E2 * (T(231) / 25600)) + e4 * (T(-429) / 59392)));
  const T p1 = (T(1) / 14 + E2 * (T(-3) / 44)) + e4 * (T(1) / 16 + E2 * (T(-35) / 608)) +
               e8 * ((T(315) / 5888 + E2 * (T(-77) / 1536)) + e4 * (T(3003) / 63488));
  const T p2 = (T(3) / 104 + E2 * (T(-15) / 272)) + e4 * (T(5) / 64 + E2 * (T(-63) / 640)) +
               e8 * (T(3465) / 29696);
  const T p3 = (T(5) / 304 + E2 * (T(-35) / 736)) + e4 * (T(35) / 384 + E2 * (T(-1155) / 7936));
  const T p4 = T(7) / 640 + E2 * (T(-315) / 7424);
  const T p5 = T(63) / 7936;
  const T t2 = E3 * E3;
  const T t4 = t2 * t2;
  return (p0 + E3 * p1) + t2 * (p2 + E3 * p3) + t4 * (p4 + E3 * p5);
}

// The same series truncated after degree 11 (2m + 3n <= 11, 16 terms), for the Legendre F kernel
// (gecko/elliptic/ellint_f.hpp), which stops the duplication at max|X| < 0.0526 (double;
// gecko/elliptic/carlson_tolerance.hpp). Measured there: the 11 terms fewer cost more time than
// the duplication step they save about half the time.
template <class T>
inline T carlson_rf_series11_tail(T X, T Y) {
  const T Z = -(X + Y);
  const T XY = X * Y;
  const T E2 = XY - Z * Z;
  const T E3 = XY * Z;
  const T e2 = E2 * E2;
  const T e4 = e2 * e2;
  const T q0 = E2 * (((T(-1) / 10 + E2 * (T(1) / 24)) + e2 * (T(-5) / 208 + E2 * (T(35) / 2176))) +
                     e4 * (T(-3) / 256));
  const T q1 = ((T(1) / 14 + E2 * (T(-3) / 44)) + e2 * (T(1) / 16 + E2 * (T(-35) / 608))) +
               e4 * (T(315) / 5888);
  const T q2 = (T(3) / 104 + E2 * (T(-15) / 272)) + e2 * (T(5) / 64);
  const T q3 = T(5) / 304 + E2 * (T(-35) / 736);
  return q0 + E3 * (q1 + E3 * (q2 + E3 * q3));
}

// R_F from the final mean A, the initial deviations dx, dy and f = 4^-n. The division f/A and
// the square root of A are independent, so they overlap instead of chaining.
template <class T>
inline T carlson_rf_finish(T dx, T dy, T A, T f) {
  using std::sqrt;
  const T s = f / A;
  const T root = sqrt(A);
  // the 1 is added last so the small correction is rounded once relative to 1
  return (1 + carlson_rf_series_tail(dx * s, dy * s)) / root;
}

// Unchecked kernel: x, y, z finite, >= 0, at most one zero, sum not overflowing.
template <class T, class Policy = policies::default_policy>
inline T carlson_rf_imp(T x, T y, T z) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol = carlson_tolerance<T, Policy::precision_bits>::rf;
  T A = (x + y + z) * (T(1) / 3);  // multiply: a division would sit on the critical path
  const T dx = A - x;
  const T dy = A - y;
  const T dz = A - z;
  // Stop when 4^-n max|A0 - x_i| < tol A_n, i.e. every |X| < tol. Written without dividing by
  // tol so that huge arguments cannot overflow the test.
  const T D = max_of(max_of(fabs(dx), fabs(dy)), fabs(dz));
  T f = 1;  // 4^-n
  for (int step = 0; step < carlson_max_steps<T> && f * D >= tol * A; ++step) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * (sy + sz) + sy * sz;
    x = (x + lambda) * T(0.25);
    y = (y + lambda) * T(0.25);
    z = (z + lambda) * T(0.25);
    A = (A + lambda) * T(0.25);
    f *= T(0.25);
  }
  return carlson_rf_finish(dx, dy, A, f);
}

// The same, for callers that already hold the square roots of the arguments (the Legendre F
// has sqrt(cos^2 phi) = cos phi and sqrt(1) = 1 for free): the first duplication step then
// costs one square root instead of three. sx, sy, sz must be sqrt(x), sqrt(y), sqrt(z) to
// within an ulp or so (they define the first step exactly as a perturbed argument would).
// The first step is taken unconditionally: it is cheap, an extra step only shrinks X, and a
// data-dependent branch here was measured to cost more than the step.
template <class T, class Policy = policies::default_policy>
inline T carlson_rf_roots_imp(T x, T y, T z, T sx, T sy, T sz) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol = carlson_tolerance<T, Policy::precision_bits>::rf;
  T A = (x + y + z) * (T(1) / 3);  // multiply: a division would sit on the critical path
  const T dx = A - x;
  const T dy = A - y;
  const T dz = A - z;
  const T D = max_of(max_of(fabs(dx), fabs(dy)), fabs(dz));
  T f = 1;
  if (D >= tol * A) {
    T lambda = sx * (sy + sz) + sy * sz;
    for (int step = 1;; ++step) {
      x = (x + lambda) * T(0.25);
      y = (y + lambda) * T(0.25);
      z = (z + lambda) * T(0.25);
      A = (A + lambda) * T(0.25);
      f *= T(0.25);
      if (!(f * D >= tol * A) || step >= carlson_max_steps<T>) break;
      const T rx = sqrt(x), ry = sqrt(y), rz = sqrt(z);
      lambda = rx * (ry + rz) + ry * rz;
    }
  }
  return carlson_rf_finish(dx, dy, A, f);
}

}  // namespace detail

template <class T, class Policy>
inline T carlson_rf(T x, T y, T z, const Policy& pol) {
  static_assert(std::is_floating_point<T>::value, "gecko::carlson_rf: T must be a floating-point type");
  using std::isinf;
  using std::isnan;
  using std::ldexp;
  constexpr const char* function = "gecko::carlson_rf";
  constexpr const char* range = "x, y, z >= 0 with at most one of them zero";
  if (isnan(x) || isnan(y) || isnan(z)) return std::numeric_limits<T>::quiet_NaN();
  if (x < 0) return raise_domain_error<T, Policy>(function, "x", x, range);
  if (y < 0) return raise_domain_error<T, Policy>(function, "y", y, range);
  if (z < 0) return raise_domain_error<T, Policy>(function, "z", z, range);
  if ((x == 0) + (y == 0) + (z == 0) > 1)
    return raise_domain_error<T, Policy>(function, z == 0 ? "z" : "y", T(0), range);
  if (isinf(x) || isinf(y) || isinf(z)) return T(0);
  const int e = detail::carlson_scale_exponent(detail::max_of(detail::max_of(x, y), z));
  if (e != 0) {
    if (detail::carlson_rescaling_flushes(detail::min_positive(x, y, z), e)) {
      // Arguments too far apart for one exact rescaling (fuzz finding F2): one duplication step
      // at their own scale, R_F(x, y, z) = R_F(x', y', z') (DLMF 19.26.18), halves the spread;
      // the recursion ends after at most a few steps.
      const auto d = detail::carlson_duplicate_once(x, y, z);
      return carlson_rf(d.x, d.y, d.z, pol);
    }
    // R_F(x, y, z) = 2^(-e/2) R_F(2^-e x, 2^-e y, 2^-e z), exactly (e is even).
    return ldexp(detail::carlson_rf_imp<T, Policy>(ldexp(x, -e), ldexp(y, -e), ldexp(z, -e)),
                 -e / 2);
  }
  return detail::carlson_rf_imp<T, Policy>(x, y, z);
}

template <class T>
inline T carlson_rf(T x, T y, T z) {
  return carlson_rf(x, y, z, policies::default_policy());
}

}  // namespace gecko
