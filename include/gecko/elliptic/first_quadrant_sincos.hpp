// gecko/elliptic/first_quadrant_sincos.hpp — sin and cos of 0 <= a <= pi/2 together, inline.
//
// The Legendre integrals need both sin(phi) and cos(phi) of the reduced amplitude; for double,
// a call to the C library's sincos is a fifth of the whole cost of F(phi|m). On [0, pi/2] no
// range reduction is needed beyond the reflection a -> pi/2 - a, which is exact with a two-part
// pi/2 (Sterbenz: pi/4 <= a <= pi/2), and cos of a near pi/2 keeps full relative accuracy
// because pi/2 - a is formed before the polynomial sees it.
//   sin x = x + x^3 P(x^2),        P: degree 6, approximation error < 1e-4 ulp on [0, pi/4]
//   cos x = 1 - x^2/2 + x^4 Q(x^2), Q: degree 5, approximation error < 1e-2 ulp on [0, pi/4]
// (near-minimax Chebyshev fits made with mpmath.chebyfit at 50 digits, rounded to double); the
// 1 - x^2/2 is compensated so that cos is within about an ulp. Tested against long double sinl,
// cosl in tests/elliptic/first_quadrant_sincos.cpp. Types other than double use std::sin/cos
// (float goes through the double kernel and is rounded once).
#pragma once

#include <cmath>

#include "gecko/elliptic/angle_reduction.hpp"

namespace gecko {
namespace detail {

// sin and cos of |x| <= pi/4 (double).
inline void sincos_kernel(double x, double& s, double& c) {
  const double z = x * x;
  const double z2 = z * z;
  const double p = (-0.16666666666666666 + z * 0.0083333333333333315) +
                   z2 * ((-0.00019841269841265065 + z * 2.7557319219339167e-06) +
                         z2 * ((-2.5052106232447578e-08 + z * 1.6058531618986147e-10) +
                               z2 * -7.5866971177069183e-13));
  const double q = (0.041666666666666664 + z * -0.0013888888888887398) +
                   z2 * ((2.4801587298765689e-05 + z * -2.7557317271729793e-07) +
                         z2 * (2.0876146268403199e-09 + z * -1.1382632425521717e-11));
  s = x + (x * z) * p;
  const double hz = 0.5 * z;
  const double w = 1 - hz;  // rounding error of w recovered exactly below (hz <= 0.31)
  c = w + (((1 - w) - hz) + z2 * q);
}

// 0 <= a <= pi/2: s = sin a, c = cos a.
template <class T>
inline void first_quadrant_sincos(T a, T& s, T& c) {
  using std::cos;
  using std::sin;
  s = sin(a);
  c = cos(a);
}

inline void first_quadrant_sincos(double a, double& s, double& c) {
  using C = pi_constants<double>;
  if (a <= 0.78539816339744828) {
    sincos_kernel(a, s, c);
  } else {
    const double b = (C::pio2_hi - a) + C::pio2_lo;  // pi/2 - a; the first difference is exact
    sincos_kernel(b, c, s);
  }
}

inline void first_quadrant_sincos(float a, float& s, float& c) {
  double sd, cd;
  first_quadrant_sincos(static_cast<double>(a), sd, cd);
  s = static_cast<float>(sd);
  c = static_cast<float>(cd);
}

}  // namespace detail
}  // namespace gecko
