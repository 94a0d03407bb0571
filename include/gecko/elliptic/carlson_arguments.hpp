// gecko/elliptic/carlson_arguments.hpp — shared argument handling of the public Carlson layer.
//
// The public functions check the domain, let NaN through quietly (NaN in -> NaN out, never an
// exception), answer the limits at +infinity, and rescale arguments whose sum could overflow or
// whose magnitudes sit in the subnormal range, using the homogeneity of the integrals
// (DLMF 19.18.1-19.18.2: R_F(l x, l y, l z) = l^(-1/2) R_F(x, y, z), R_D and R_J scale as
// l^(-3/2), R_C as l^(-1/2)). Arguments too far apart for one exact rescaling (it would flush the
// smallest) first take duplication steps at their own scale (carlson_duplicate_once), which
// halve the spread each. The unchecked kernels detail::*_imp assume finite, in-range,
// moderately scaled arguments.
#pragma once

#include <cmath>
#include <limits>

namespace gecko {
namespace detail {

// Even power-of-two exponent e (possibly 0) such that 2^-e * largest is of order one, when the
// largest argument is outside [2^(min_exponent + digits), 2^(max_exponent - 8)]; 0 otherwise.
// Scaling by an even power of two keeps the square root of the scale factor exact.
template <class T>
inline int carlson_scale_exponent(T largest) {
  using std::ilogb;
  constexpr int lo = std::numeric_limits<T>::min_exponent + std::numeric_limits<T>::digits;
  constexpr int hi = std::numeric_limits<T>::max_exponent - 8;
  if (!(largest > 0)) return 0;
  const int e = ilogb(largest);
  if (e > lo && e < hi) return 0;
  return e & ~1;  // round toward -infinity to an even exponent
}

template <class T>
inline T max_of(T a, T b) { return a < b ? b : a; }

template <class T>
inline T min_of(T a, T b) { return b < a ? b : a; }

// Window of the integrals that scale as A^(-3/2) (R_D, and the gradient of R_F): the kernels
// form A sqrt(A), which over- or underflows for largest arguments beyond 2^(2 max_exponent / 3)
// or below 2^(2 min_exponent / 3) (the mean A falls by up to 4^-n during the duplication: 64
// binades of margin) while the result is still a normal number: R_D(2^68, 2^68, 2^687) lost 3%,
// R_D(2^-1022, 2^-1000, 2^-676) 18 eps (found by fuzz/fuzz_carlson.cpp). Returns the even
// exponent e (possibly 0) that shifts the largest argument just inside
// [2^(2 min_exponent / 3 + 64), 2^(2 max_exponent / 3 - 8)], no further, so that the small
// arguments keep their bits (an even shift keeps the 3/2 power exact). largest > 0, finite.
template <class T>
inline int carlson_rd_scale_exponent(T largest) {
  constexpr int hi = 2 * std::numeric_limits<T>::max_exponent / 3 - 8;
  constexpr int lo = 2 * std::numeric_limits<T>::min_exponent / 3 + 64;
  const int le = std::ilogb(largest);
  if (le > hi) return (le - hi + 1) & ~1;
  if (le < lo) return -((lo - le + 1) & ~1);
  return 0;
}

// Smallest positive value among the arguments (at most one of them is zero; +inf when none is
// positive, which the callers exclude).
template <class T>
inline T min_positive(T a, T b, T c) {
  const T m = min_of(min_of(a, b), c);  // branch-free on the common path: all positive
  if (m > 0) return m;
  const T inf = std::numeric_limits<T>::infinity();
  return min_of(min_of(a > 0 ? a : inf, b > 0 ? b : inf), c > 0 ? c : inf);
}

// Whether scaling by 2^-e (e > 0: scaling down) would push the smallest positive argument below
// the normal range, i.e. flush it to zero or cut its bits. The rescaling is set by the LARGEST
// argument, so this happens for arguments more than about 2^(max_exponent - min_exponent - e)
// apart: R_F(1e-300, 1e-310, 1e308) flushed two arguments and gave NaN (fuzz finding F2).
template <class T>
inline bool carlson_rescaling_flushes(T smallest_positive, int e) {
  return e > 0 && std::ilogb(smallest_positive) - e < std::numeric_limits<T>::min_exponent - 1;
}

// One duplication step x_{n+1} = (x_n + lambda)/4 (DLMF 19.26.18-19.26.20) taken at the
// arguments' own scale, for arguments far apart: lambda >= sqrt(x_max x_mid) lifts every argument
// to at least the geometric mean of the two largest over 4 while none grows, so each step halves
// the spread in binades (log2(max/min) -> log2(max/min)/2 + 2), and after a few steps the usual
// exact rescaling no longer flushes anything. Written as x/4 + (sx/2)(sy/2 + sz/2) + (sy/2)(sz/2)
// so that nothing overflows up to the largest finite arguments (lambda/4 <= 3 max/4). The roots
// are returned for the integral's own step term.
template <class T>
struct carlson_step {
  T x, y, z;     // the arguments after the step
  T sx, sy, sz;  // square roots of the arguments before it
  T lambda4;     // lambda / 4
};

template <class T>
inline carlson_step<T> carlson_duplicate_once(T x, T y, T z) {
  using std::sqrt;
  carlson_step<T> s;
  s.sx = sqrt(x);
  s.sy = sqrt(y);
  s.sz = sqrt(z);
  const T hx = s.sx * T(0.5), hy = s.sy * T(0.5), hz = s.sz * T(0.5);
  s.lambda4 = hx * (hy + hz) + hy * hz;
  s.x = x * T(0.25) + s.lambda4;
  s.y = y * T(0.25) + s.lambda4;
  s.z = z * T(0.25) + s.lambda4;
  return s;
}

}  // namespace detail
}  // namespace gecko
