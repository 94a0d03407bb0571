// gecko/elliptic/carlson_tolerance.hpp — when the Carlson duplication may stop.
//
// The duplication theorem (DLMF 19.26.18) maps R(x, y, z) to R(x', y', z') with the arguments
// pulled together by a factor 4 per step; once the scaled deviations X = 1 - x_n/A_n ... are
// small, a truncated Taylor series in the elementary symmetric functions finishes the job
// (DLMF 19.19.7, 19.36.1, Carlson 1995, Numer. Algorithms 10, 13-26). The truncation error of
// the series is O(|X|^(d+1)) for a series of degree d, so the loop stops once
//   max|X| < t_F  for R_F (degree-15 series, gecko/elliptic/carlson_rf.hpp), where t_F solves
//                 (3 t^2 / 2)^8 / 160 = r: the first omitted term is E2^8 times a coefficient
//                 below 1/160, and |E2| = (X^2 + Y^2 + Z^2)/2 <= 3 t^2 / 2 (the E3 terms of that
//                 degree are smaller, |E3| <= t^3 / 4). t_F is capped at 1/2 so that the omitted
//                 tail stays a geometric series of ratio <= 3/8 even at low precision targets
//                 (precision<Bits> below about 20 bits all stop there: the series is then
//                 already far more accurate than asked).
//                 (Carlson's degree-7 series would need (3r)^(1/8): 0.0116 for double, against
//                 t_F = 0.113 here, i.e. about 1.6 duplication steps more.)
//   max|X| < t_F11 for the degree-11 R_F series of the Legendre F kernel (gecko/elliptic/ellint_f.hpp):
//                 the terms of degree 12 (E2^6, E2^3 E3^2, E3^4) have |coefficients| times the bounds
//                 |E2| <= 3 t^2 / 2, |E3| <= t^3 / 4 summing to C12 t^12, C12 = 0.12359
//                 (coefficients as in gecko/elliptic/carlson_rf.hpp); t_F11 solves 2 C12 t^12 = r
//                 (the factor 2 covers the later degrees, each smaller by about t), capped at 1/2:
//                 0.0526 for double.
//   max|X| < t_D  for R_D (degree-11 series in S = X + Y, P = XY, gecko/elliptic/carlson_rd.hpp):
//                 the terms of degree N have absolute coefficients (in X, Y monomials) summing
//                 to C_N, slowly decreasing from 0.114 (N = 6) to C_12 = 0.0531
//                 (tests/data/gen_elliptic_series.py); t_D solves 2 C_12 t^12 = r (the factor 2
//                 covers the tail of later degrees, C_N t^N decreasing), capped at 1/2
//                 (where the omitted tail is below 3e-5, so coarse targets stay honest).
//   max|X| < (r / 4)^(1/6) for R_J (degree-5 series, DLMF 19.36.2),
// where r is the target relative error: 2^-Bits from the precision policy, or the unit
// roundoff of T when Bits = 0 (full precision).
//
// The thresholds are compile-time constants: no pow() and no static initialisation guard on the
// hot path. They are computed with constexpr Newton iterations in long double.
#pragma once

#include <limits>

namespace gecko {
namespace detail {

// Newton from above converges monotonically for both roots; stop when it stops decreasing.
constexpr long double constexpr_sqrt(long double a) {
  if (a <= 0) return 0;
  long double x = a > 1 ? a : 1.0L;
  for (int i = 0; i < 4096; ++i) {
    const long double next = 0.5L * (x + a / x);
    if (!(next < x)) break;
    x = next;
  }
  return x;
}

constexpr long double constexpr_cbrt(long double a) {
  if (a <= 0) return 0;
  long double x = a > 1 ? a : 1.0L;
  for (int i = 0; i < 4096; ++i) {
    const long double next = (2 * x + a / (x * x)) / 3;
    if (!(next < x)) break;
    x = next;
  }
  return x;
}

constexpr long double constexpr_pow2(int e) {
  long double v = 1;
  for (; e > 0; --e) v *= 2;
  for (; e < 0; ++e) v /= 2;
  return v;
}

template <class T, unsigned Bits>
struct carlson_tolerance {
  static constexpr int digits = std::numeric_limits<T>::digits;
  // Bits = 0 or more than T holds: full precision of T.
  static constexpr int bits = (Bits == 0 || Bits > static_cast<unsigned>(digits))
                                  ? digits : static_cast<int>(Bits);
  // Target relative truncation error of the series.
  static constexpr long double r = constexpr_pow2(-bits);
  // R_F (degree-15 series): sqrt((160 r)^(1/8) / 1.5), at most 1/2.
  static constexpr long double rf_raw =
      constexpr_sqrt(constexpr_sqrt(constexpr_sqrt(constexpr_sqrt(160 * r))) / 1.5L);
  static constexpr T rf = static_cast<T>(rf_raw < 0.5L ? rf_raw : 0.5L);
  // R_F, degree-11 series: (r / (2 * 0.12358947753906249))^(1/12), at most 1/2.
  static constexpr long double rf11_raw =
      constexpr_sqrt(constexpr_sqrt(constexpr_cbrt(r / (2 * 0.12358947753906249L))));
  static constexpr T rf11 = static_cast<T>(rf11_raw < 0.5L ? rf11_raw : 0.5L);
  // Arithmetic-geometric mean (gecko/elliptic/ellint_k.hpp): stop at |a - b| <= 2 sqrt(r) a.
  static constexpr T agm = static_cast<T>(2 * constexpr_sqrt(r));
  // R_D (degree-11 series): (r / (2 * 0.05305240792088293))^(1/12), at most 1/2.
  static constexpr long double rd_raw =
      constexpr_sqrt(constexpr_sqrt(constexpr_cbrt(r / (2 * 0.05305240792088293L))));
  static constexpr T rd = static_cast<T>(rd_raw < 0.5L ? rd_raw : 0.5L);
  // R_J (degree-5 series): (r/4)^(1/6).
  static constexpr T rj = static_cast<T>(constexpr_cbrt(constexpr_sqrt(r / 4)));
};

// Upper bound on duplication steps. For valid arguments the tolerance test ends the loop long
// before: at the latest when 4^-n underflows to zero while the means stay positive. Only invalid
// arguments given to an unchecked kernel (two of them zero) keep the test true forever -- every
// mean then shrinks like 4^-n, exactly as the test's left side -- so the unchecked kernels stop
// here and return a non-finite value instead of hanging (found by the seta stress campaign).
template <class T>
constexpr int carlson_max_steps =
    (std::numeric_limits<T>::max_exponent - std::numeric_limits<T>::min_exponent +
     std::numeric_limits<T>::digits) / 2 + 4;

}  // namespace detail
}  // namespace gecko
