// gecko/elliptic/angle_reduction.hpp — phi = j (pi/2) + r with |r| <= pi/4, accurately.
//
// The Legendre integrals are periodic up to a secular term (DLMF 19.2.10:
// F(phi + pi) = F(phi) + 2K, E(phi + pi) = E(phi) + 2E), so any phi is reduced to a multiple j of
// pi/2 and a remainder r. The remainder is computed Cody-Waite style with pi/2 split into three
// parts hi + lo + lo2 of T's precision and fused multiply-adds: for 0 <= phi < 2^(digits - 1)
// the first step phi - j*hi is exact (both sides are multiples of ulp(hi) and the result is
// below 2), so r carries a relative error of a few ulps however large j is.
// Larger phi (j not an exact integer any more) are left to the caller (the secular term then
// dominates the periodic part by a factor above 2^digits).
#pragma once

#include <cmath>
#include <limits>

namespace gecko {
namespace detail {

// pi/2 = hi + lo + lo2 (each rounded to nearest in T), pio2_below = largest T <= pi/2,
// 2/pi = two_over_pi + two_over_pi_lo. Generated with mpmath at 400 bits.
template <class T, int Digits = std::numeric_limits<T>::digits>
struct pi_constants;

template <class T>
struct pi_constants<T, 24> {
  static constexpr T pio2_hi = 0x1.921fb6p+0f;
  static constexpr T pio2_lo = -0x1.777a5cp-25f;
  static constexpr T pio2_lo2 = -0x1.ee59dap-50f;
  static constexpr T pio2_below = 0x1.921fb4p+0f;
  static constexpr T two_over_pi = 0x1.45f306p-1f;
  static constexpr T two_over_pi_lo = 0x1.b93910p-26f;
};

template <class T>
struct pi_constants<T, 53> {
  static constexpr T pio2_hi = 0x1.921fb54442d18p+0;
  static constexpr T pio2_lo = 0x1.1a62633145c07p-54;
  static constexpr T pio2_lo2 = -0x1.f1976b7ed8fbcp-110;
  static constexpr T pio2_below = 0x1.921fb54442d18p+0;
  static constexpr T two_over_pi = 0x1.45f306dc9c883p-1;
  static constexpr T two_over_pi_lo = -0x1.6b01ec5417056p-55;
};

// x87 80-bit long double.
template <class T>
struct pi_constants<T, 64> {
  static constexpr T pio2_hi = 0x1.921fb54442d1846ap+0L;
  static constexpr T pio2_lo = -0x1.d9cceba3f91f1976p-66L;
  static constexpr T pio2_lo2 = -0x1.6fdb1f77598338c0p-131L;
  static constexpr T pio2_below = 0x1.921fb54442d18468p+0L;
  static constexpr T two_over_pi = 0x1.45f306dc9c882a54p-1L;
  static constexpr T two_over_pi_lo = -0x1.ec54170565911f92p-71L;
};

// IEEE binary128 long double.
template <class T>
struct pi_constants<T, 113> {
  static constexpr T pio2_hi = 0x1.921fb54442d18469898cc51701b8p+0L;
  static constexpr T pio2_lo = 0x1.cd129024e088a67cc74020bbea64p-115L;
  static constexpr T pio2_lo2 = -0x1.3b19376bad7de19c72fec8841abap-229L;
  static constexpr T pio2_below = 0x1.921fb54442d18469898cc51701b8p+0L;
  static constexpr T two_over_pi = 0x1.45f306dc9c882a53f84eafa3ea6ap-1L;
  static constexpr T two_over_pi_lo = -0x1.11f924eb53361de37df00d74e2a1p-115L;
};

template <class T>
struct quadrant_reduction {
  T j;  // integer-valued multiple of pi/2 (T holds it exactly)
  T r;  // remainder, |r| <= pi/4 (plus rounding)
};

// Largest phi handled by reduce_quadrant: 2^(digits - 1).
template <class T>
constexpr T reduction_limit() {
  T v = 1;
  for (int i = 1; i < std::numeric_limits<T>::digits; ++i) v *= 2;
  return v;
}

// 0 <= a < reduction_limit<T>().
template <class T>
inline quadrant_reduction<T> reduce_quadrant(T a) {
  using std::fma;
  using std::nearbyint;
  using C = pi_constants<T>;
  const T j = nearbyint(a * C::two_over_pi);
  T r = fma(-j, C::pio2_hi, a);  // exact
  r = fma(-j, C::pio2_lo, r);
  r = fma(-j, C::pio2_lo2, r);
  return {j, r};
}

// Parity of an integer-valued j (exact: j/2 is exact in binary floating point).
template <class T>
inline bool is_even(T j) {
  using std::trunc;
  const T half = j * T(0.5);
  return half == trunc(half);
}

// a * (2/pi) as an unevaluated sum hi + lo, for the secular term of huge arguments.
template <class T>
inline void times_two_over_pi(T a, T& hi, T& lo) {
  using std::fma;
  using C = pi_constants<T>;
  hi = a * C::two_over_pi;
  lo = fma(a, C::two_over_pi, -hi) + a * C::two_over_pi_lo;
}

}  // namespace detail
}  // namespace gecko
