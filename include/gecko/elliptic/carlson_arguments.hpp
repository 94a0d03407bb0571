// gecko/elliptic/carlson_arguments.hpp — shared argument handling of the public Carlson layer.
//
// The public functions check the domain, let NaN through quietly (NaN in -> NaN out, never an
// exception), answer the limits at +infinity, and rescale arguments whose sum could overflow or
// whose magnitudes sit in the subnormal range, using the homogeneity of the integrals
// (DLMF 19.18.1-19.18.2: R_F(l x, l y, l z) = l^(-1/2) R_F(x, y, z), R_D and R_J scale as
// l^(-3/2), R_C as l^(-1/2)). The unchecked kernels detail::*_imp assume finite, in-range,
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

}  // namespace detail
}  // namespace gecko
