// gecko/seta/detail/rf_gradient.hpp — R_F(x, y, z) and its gradient from ONE duplication.
//
// The Newton Jacobian of the seta needs dR_F/dx_i = -R_D(x_j, x_k, x_i)/6 (DLMF 19.18.1)
// for all three arguments at every length evaluation. The
// four integrals share the duplication sequence x_n, y_n, z_n (DLMF 19.26.18, 19.26.20); only the
// means A and the R_D tail sums differ, so one loop with three square roots per step gives all
// four, at roughly 1.5 times the cost of R_F alone. Series: gecko/elliptic/carlson_rf.hpp and
// carlson_rd.hpp (DLMF 19.36.1, 19.36.2), restated below.
//
// Unchecked kernel: x, y, z > 0, finite, moderately scaled (the seta arguments are U_ij^2 of
// order 1/length^2 in units of EI; they are never near the overflow range).
#pragma once

#include <cmath>
#include <cstddef>

#include <limits>

#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/seta/detail/dual.hpp"

namespace gecko {
namespace detail {

// Self-contained series and stopping thresholds (this kernel must not depend on the internals
// of gecko/elliptic, which tune their own series degrees): degree 7 for R_F (DLMF 19.36.1),
// degree 5 for R_D (DLMF 19.36.2, Carlson 1995 eq. 2.21); the duplication stops once
// max|X| < (3r)^(1/8) (R_F) and (r/4)^(1/6) (R_D), r the target relative error.
constexpr long double seta_root(long double a, int k) {  // a^(1/k), a in (0, 1], by Newton
  long double x = 1;
  for (int i = 0; i < 200; ++i) {
    long double p = 1;
    for (int j = 0; j < k - 1; ++j) p *= x;
    const long double next = x - (p * x - a) / (k * p);
    if (!(next < x)) break;
    x = next;
  }
  return x;
}
template <class T, unsigned Bits>
struct seta_carlson_tolerance {
  static constexpr int digits = std::numeric_limits<T>::digits;
  static constexpr int bits = (Bits == 0 || Bits > static_cast<unsigned>(digits)) ? digits : static_cast<int>(Bits);
  static constexpr long double r() {
    long double v = 1;
    for (int i = 0; i < bits; ++i) v /= 2;
    return v;
  }
  static constexpr T rf = static_cast<T>(seta_root(3 * r(), 8));
  static constexpr T rd = static_cast<T>(seta_root(r() / 4, 6));
};

template <class T>
inline T seta_max3(T a, T b, T c) {
  const T m = a < b ? b : a;
  return m < c ? c : m;
}

template <class T>
inline T seta_rf_series(T X, T Y, T A) {
  using std::sqrt;
  const T Z = -(X + Y);
  const T E2 = X * Y - Z * Z;
  const T E3 = X * Y * Z;
  const T p = E2 * (T(-1) / 10 + E2 * (T(1) / 24 - E2 * (T(5) / 208))) +
              E3 * (T(1) / 14 + E3 * (T(3) / 104) + E2 * (T(-3) / 44 + E2 * (T(1) / 16)));
  return (1 + p) / sqrt(A);
}

template <class T>
inline T seta_rd_series(T X, T Y, T A, T f) {
  using std::sqrt;
  const T Z = -(X + Y) / 3;
  const T XY = X * Y;
  const T Z2 = Z * Z;
  const T E2 = XY - 6 * Z2;
  const T E3 = (3 * XY - 8 * Z2) * Z;
  const T E4 = 3 * (XY - Z2) * Z2;
  const T E5 = XY * Z2 * Z;
  const T p = E2 * (T(-3) / 14 + E2 * (T(9) / 88) - E3 * (T(9) / 52)) + E3 * (T(1) / 6) -
              E4 * (T(3) / 22) + E5 * (T(3) / 26);
  return f * (1 + p) / (A * sqrt(A));
}

template <class T>
struct rf_with_gradient {
  T rf;
  T dx, dy, dz;  // dR_F/dx, dR_F/dy, dR_F/dz
};

// ZeroLast: z == 0 identically (complete integrals); dR_F/dz is then infinite and is not
// computed (returned as 0: the caller's z never varies).
template <class T, class Policy = policies::default_policy, bool ZeroLast = false>
inline rf_with_gradient<T> carlson_rf_gradient_imp(T x, T y, T z) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol_f = seta_carlson_tolerance<T, Policy::precision_bits>::rf;
  constexpr T tol_d = seta_carlson_tolerance<T, Policy::precision_bits>::rd;
  // Means: R_F, and R_D with the distinguished (last) argument z, x, y respectively.
  T AF = (x + y + z) / 3;
  T Az = (x + y + 3 * z) / 5;
  T Ax = (y + z + 3 * x) / 5;
  T Ay = (z + x + 3 * y) / 5;
  const T fx = AF - x, fy = AF - y;
  const T zx = Az - x, zy = Az - y;  // R_D(x, y, z): deviations of its first two arguments
  const T xy = Ax - y, xz = Ax - z;  // R_D(y, z, x)
  const T yz = Ay - z, yx = Ay - x;  // R_D(z, x, y)
  const T DF = seta_max3(fabs(fx), fabs(fy), fabs(AF - z));
  const T Dz = seta_max3(fabs(zx), fabs(zy), fabs(Az - z));
  const T Dx = seta_max3(fabs(xy), fabs(xz), fabs(Ax - x));
  const T Dy = seta_max3(fabs(yz), fabs(yx), fabs(Ay - y));
  T f = 1;
  T sx_sum = 0, sy_sum = 0, sz_sum = 0;
  // At most 40 steps (4^-40 reduces any admissible spread below the tolerance); a degenerate
  // call (two zero arguments) ends here instead of looping, and is answered with NaN below.
  int steps = 0;
  while ((f * DF >= tol_f * AF || (!ZeroLast && f * Dz >= tol_d * Az) || f * Dx >= tol_d * Ax ||
          f * Dy >= tol_d * Ay) && ++steps <= 40) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * (sy + sz) + sy * sz;
    if (!ZeroLast) sz_sum += f / (sz * (z + lambda));
    sx_sum += f / (sx * (x + lambda));
    sy_sum += f / (sy * (y + lambda));
    x = (x + lambda) * T(0.25);
    y = (y + lambda) * T(0.25);
    z = (z + lambda) * T(0.25);
    AF = (AF + lambda) * T(0.25);
    Az = (Az + lambda) * T(0.25);
    Ax = (Ax + lambda) * T(0.25);
    Ay = (Ay + lambda) * T(0.25);
    f *= T(0.25);
  }
  const T sF = f / AF, s_z = f / Az, s_x = f / Ax, s_y = f / Ay;
  rf_with_gradient<T> r;
  if (steps > 40 || !(AF > 0)) {
    r.rf = r.dx = r.dy = r.dz = std::numeric_limits<T>::quiet_NaN();
    return r;
  }
  r.rf = seta_rf_series(fx * sF, fy * sF, AF);
  const T rd_z = ZeroLast ? T(0) : seta_rd_series(zx * s_z, zy * s_z, Az, f) + 3 * sz_sum;
  const T rd_x = seta_rd_series(xy * s_x, xz * s_x, Ax, f) + 3 * sx_sum;
  const T rd_y = seta_rd_series(yz * s_y, yx * s_y, Ay, f) + 3 * sy_sum;
  r.dx = -rd_x / 6;
  r.dy = -rd_y / 6;
  r.dz = -rd_z / 6;
  return r;
}

// R_F on plain scalars (no gradient needed) and on duals (gradient through the chain rule).
template <class Policy, class T>
inline T carlson_rf_ad(T x, T y, T z) {
  return carlson_rf_imp<T, Policy>(x, y, z);
}
template <class Policy, class T, std::size_t K>
inline dual<T, K> carlson_rf_ad(const dual<T, K>& x, const dual<T, K>& y, const dual<T, K>& z) {
  const rf_with_gradient<T> g = carlson_rf_gradient_imp<T, Policy>(x.v, y.v, z.v);
  dual<T, K> r;
  r.v = g.rf;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = g.dx * x.d[i] + g.dy * y.d[i] + g.dz * z.d[i];
  return r;
}

// R_F(x, y, 0): the complete integrals (quarter periods) of the seta segments.
template <class Policy, class T>
inline T carlson_rf0_ad(T x, T y) {
  return carlson_rf_imp<T, Policy>(x, y, T(0));
}
template <class Policy, class T, std::size_t K>
inline dual<T, K> carlson_rf0_ad(const dual<T, K>& x, const dual<T, K>& y) {
  const rf_with_gradient<T> g = carlson_rf_gradient_imp<T, Policy, true>(x.v, y.v, T(0));
  dual<T, K> r;
  r.v = g.rf;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = g.dx * x.d[i] + g.dy * y.d[i];
  return r;
}

}  // namespace detail
}  // namespace gecko
