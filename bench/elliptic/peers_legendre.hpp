// bench/elliptic/peers_legendre.hpp — two published algorithms for F(phi|m), implemented here for
// the benchmark only (the library never uses them): written from the papers' descriptions, so a
// row measures the algorithm as this file implements it, not the authors' own code.
//
//   bulirsch_el1  R. Bulirsch, "Numerical calculation of elliptic integrals and elliptic
//                 functions", Numer. Math. 7 (1965) 78-90, procedure el1(x, kc):
//                 F = int_0^atan(x) dt / sqrt(cos^2 t + kc^2 sin^2 t), x = tan phi,
//                 kc = sqrt(1 - m). Gauss (Landen) transformation in the tangent variable,
//                 quadratically convergent; one division and one square root per step, atan at the end.
//   fukushima_f   T. Fukushima, "Fast computation of incomplete elliptic integral of first kind by
//                 half argument transformation", Numer. Math. 116 (2010) 687-719: the half-argument
//                 formulas of the Jacobi functions, sn^2(u/2) = sn^2 u / ((1 + cn u)(1 + dn u)),
//                 cn^2(u/2) = (cn u + dn u)/(1 + dn u), dn^2(u/2) = (1 - m + dn u + m cn u)/(1 + dn u),
//                 applied until sn^2 < 0.01, then the Maclaurin series of u = F(arcsin sqrt(y)|m) in
//                 y = sn^2, times 2^N. Amplitudes with sin^2 phi > 1/2 go through the complement
//                 sn(K - u) = cn u / dn u when that argument is below 1/2 (K by the AGM). The paper's
//                 tuned thresholds and its piecewise K are not reproduced.
// Domain of both as used here: 0 <= phi <= pi/2, 0 <= m < 1.
#pragma once

#include <cmath>

namespace gecko_bench {

inline double bulirsch_el1(double x, double kc) {
  constexpr double ca = 1e-8;   // 10^(-D/2) for D = 16 digits: the Landen step stops at |g - kc| <= ca g
  constexpr double cb = 1e-14;  // 10^(-D+2): keeps y away from 0
  if (x == 0) return 0;
  if (kc == 0) return std::asinh(x);  // m = 1: F = atanh(sin phi) = asinh(tan phi)
  double y = std::fabs(1 / x);
  kc = std::fabs(kc);
  double m = 1;
  int l = 0;
  for (;;) {
    const double e = m * kc;
    const double g = m;
    m = kc + m;
    y = -(e / y) + y;
    if (y == 0) y = std::sqrt(e) * cb;
    if (!(std::fabs(g - kc) > ca * g)) break;
    kc = 2 * std::sqrt(e);
    l = 2 * l;
    if (y < 0) ++l;
  }
  if (y < 0) ++l;
  const double f = (std::atan(m / y) + M_PI * l) / m;
  return x < 0 ? -f : f;
}

// 1 + sum_j a_j(m) y^j, j = 1..7, with a_j(m) = (1/(2j+1)) sum_i b_i b_(j-i) m^i, b_i = (1/2)_i / i!
// (the series of F(arcsin sqrt(y)|m)/sqrt(y)); for y < 0.01 and m <= 1 the omitted tail is below
// y^8 / 17 < 1e-17.
inline double fukushima_series(double y, double m) {
  constexpr double b1 = 0.5, b2 = 0.375, b3 = 0.3125, b4 = 0.2734375, b5 = 0.24609375, b6 = 0.2255859375,
                   b7 = 0.20947265625;
  const double a1 = (b1 + m * b1) / 3;
  const double a2 = (b2 + m * (b1 * b1 + m * b2)) / 5;
  const double a3 = (b3 + m * (b1 * b2 + m * (b2 * b1 + m * b3))) / 7;
  const double a4 = (b4 + m * (b1 * b3 + m * (b2 * b2 + m * (b3 * b1 + m * b4)))) / 9;
  const double a5 = (b5 + m * (b1 * b4 + m * (b2 * b3 + m * (b3 * b2 + m * (b4 * b1 + m * b5))))) / 11;
  const double a6 =
      (b6 + m * (b1 * b5 + m * (b2 * b4 + m * (b3 * b3 + m * (b4 * b2 + m * (b5 * b1 + m * b6)))))) / 13;
  const double a7 =
      (b7 + m * (b1 * b6 + m * (b2 * b5 + m * (b3 * b4 + m * (b4 * b3 + m * (b5 * b2 + m * (b6 * b1 + m * b7)))))))
      / 15;
  return 1 + y * (a1 + y * (a2 + y * (a3 + y * (a4 + y * (a5 + y * (a6 + y * a7))))));
}

// u >= 0 with sn^2 u = y, cn u = c, dn u = d.
inline double fukushima_half(double y, double c, double d, double m) {
  const double mc = 1 - m;
  double scale = 1;
  while (y > 0.01) {
    const double t = 1 / (1 + d);
    const double cn = std::sqrt((c + d) * t);
    const double dn = std::sqrt((mc + d + m * c) * t);  // every term >= 0: no cancellation as m -> 1
    y = y * t / (1 + c);
    c = cn;
    d = dn;
    scale *= 2;
  }
  return scale * std::sqrt(y) * fukushima_series(y, m);
}

// K(m) = pi / (2 AGM(1, sqrt(1 - m))).
inline double agm_k(double m) {
  double a = 1, b = std::sqrt(1 - m);
  while (std::fabs(a - b) > 1e-8 * a) {  // quadratic convergence: the next mean is exact to eps
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return M_PI / (a + b);
}

inline double fukushima_f(double phi, double m) {
  const double s = std::sin(phi), c = std::cos(phi);
  const double mc = 1 - m;
  const double d = std::sqrt(c * c + mc * (s * s));  // dn, without the cancellation of 1 - m s^2
  const double y = s * s;
  if (y > 0.5) {
    const double sc = c / d;  // sn(K - u); cn(K - u) = kc sn/dn, dn(K - u) = kc/dn
    if (sc * sc < 0.5) {
      const double kc = std::sqrt(mc);
      return agm_k(m) - fukushima_half(sc * sc, kc * s / d, kc / d, m);
    }
  }
  return fukushima_half(y, c, d, m);
}

}  // namespace gecko_bench
