// gecko/elliptic/carlson_rf_gradient.hpp — R_F(x, y, z) and its gradient from ONE duplication.
//
// The partial derivatives of R_F are R_D's with the differentiated argument last
// (DLMF 19.18.1):  dR_F/dx = -R_D(y, z, x)/6,  dR_F/dy = -R_D(z, x, y)/6,  dR_F/dz = -R_D(x, y, z)/6.
// All four integrals share the duplication sequence x_n, y_n, z_n (DLMF 19.26.18, 19.26.20);
// only the means A and the R_D tail sums differ, so one loop with three square roots per step
// gives all four at about 1.5 times the cost of R_F alone. The series after the loop are the
// library's own (gecko/elliptic/carlson_rf.hpp, degree 15; carlson_rd.hpp, degree 11) with the
// stopping rules of gecko/elliptic/carlson_tolerance.hpp, so the values carry the same error
// bounds as carlson_rf and carlson_rd.
//
// Used by the seta's Newton Jacobian (every elastica length is one R_F whose arguments depend on
// the unknowns: gecko/seta/detail/rf_gradient.hpp), and public for anyone differentiating R_F.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_arguments.hpp"
#include "gecko/elliptic/carlson_rd.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {

template <class T>
struct carlson_rf_gradient_result {
  T rf;          // R_F(x, y, z)
  T dx, dy, dz;  // dR_F/dx, dR_F/dy, dR_F/dz
};

namespace detail {

// Unchecked kernel: x, y, z > 0, finite, moderately scaled. ZeroLast: z == 0 identically (the
// complete integrals); dR_F/dz is then -infinity, is not computed and is returned as -inf.
// Arguments outside that domain (two zeros, as a continuation can produce at a degenerate
// state) give NaN within carlson_max_steps instead of looping.
template <class T, class Policy = policies::default_policy, bool ZeroLast = false>
inline carlson_rf_gradient_result<T> carlson_rf_gradient_imp(T x, T y, T z) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol_f = carlson_tolerance<T, Policy::precision_bits>::rf;
  constexpr T tol_d = carlson_tolerance<T, Policy::precision_bits>::rd;
  // Means of R_F, and of R_D with z, x, y respectively as the distinguished (last) argument.
  T AF = (x + y + z) * (T(1) / 3);
  T Az = (x + y + 3 * z) * (T(1) / 5);
  T Ax = (y + z + 3 * x) * (T(1) / 5);
  T Ay = (z + x + 3 * y) * (T(1) / 5);
  const T fx = AF - x, fy = AF - y;
  const T zx = Az - x, zy = Az - y;  // R_D(x, y, z): deviations of its first two arguments
  const T xy = Ax - y, xz = Ax - z;  // R_D(y, z, x)
  const T yz = Ay - z, yx = Ay - x;  // R_D(z, x, y)
  const T DF = max_of(max_of(fabs(fx), fabs(fy)), fabs(AF - z));
  const T Dz = max_of(max_of(fabs(zx), fabs(zy)), fabs(Az - z));
  const T Dx = max_of(max_of(fabs(xy), fabs(xz)), fabs(Ax - x));
  const T Dy = max_of(max_of(fabs(yz), fabs(yx)), fabs(Ay - y));
  T f = 1;  // 4^-n
  T sx_sum = 0, sy_sum = 0, sz_sum = 0;
  int step = 0;
  for (; step < carlson_max_steps<T> &&
         (f * DF >= tol_f * AF || (!ZeroLast && f * Dz >= tol_d * Az) || f * Dx >= tol_d * Ax ||
          f * Dy >= tol_d * Ay);
       ++step) {
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
  carlson_rf_gradient_result<T> r;
  if (step >= carlson_max_steps<T> || !(AF > 0)) {
    r.rf = r.dx = r.dy = r.dz = std::numeric_limits<T>::quiet_NaN();
    return r;
  }
  const T s_z = f / Az, s_x = f / Ax, s_y = f / Ay;
  r.rf = carlson_rf_finish(fx, fy, AF, f);
  r.dx = -(carlson_rd_series(xy * s_x, xz * s_x, Ax, f) + 3 * sx_sum) / 6;
  r.dy = -(carlson_rd_series(yz * s_y, yx * s_y, Ay, f) + 3 * sy_sum) / 6;
  r.dz = ZeroLast ? -std::numeric_limits<T>::infinity()
                  : -(carlson_rd_series(zx * s_z, zy * s_z, Az, f) + 3 * sz_sum) / 6;
  return r;
}

}  // namespace detail

// R_F(x, y, z) with its three partial derivatives. Domain as carlson_rf: x, y, z >= 0 with at
// most one of them zero; the derivative with respect to a zero argument is -infinity (R_D's
// last argument at 0). An infinite argument gives R_F = 0 and a zero gradient (the limits).
template <class T, class Policy>
inline carlson_rf_gradient_result<T> carlson_rf_gradient(T x, T y, T z, const Policy&) {
  static_assert(std::is_floating_point<T>::value,
                "gecko::carlson_rf_gradient: T must be a floating-point type");
  using std::isinf;
  using std::isnan;
  using std::ldexp;
  constexpr const char* function = "gecko::carlson_rf_gradient";
  constexpr const char* range = "x, y, z >= 0 with at most one of them zero";
  const auto all = [](T v) { return carlson_rf_gradient_result<T>{v, v, v, v}; };
  if (isnan(x) || isnan(y) || isnan(z)) return all(std::numeric_limits<T>::quiet_NaN());
  if (x < 0) return all(raise_domain_error<T, Policy>(function, "x", x, range));
  if (y < 0) return all(raise_domain_error<T, Policy>(function, "y", y, range));
  if (z < 0) return all(raise_domain_error<T, Policy>(function, "z", z, range));
  if ((x == 0) + (y == 0) + (z == 0) > 1)
    return all(raise_domain_error<T, Policy>(function, z == 0 ? "z" : "y", T(0), range));
  if (isinf(x) || isinf(y) || isinf(z)) return all(T(0));
  // R_F(2^-e v) = 2^(e/2) R_F(v) and its gradient 2^(3e/2) times: rescale exactly (e even).
  // The partials are R_D's (~ A^(-3/2)): R_D's window, not R_F's wider one, or A sqrt(A) over-
  // or underflows while the partials are still normal numbers.
  const int e = detail::carlson_rd_scale_exponent(detail::max_of(detail::max_of(x, y), z));
  const auto scaled = [e](carlson_rf_gradient_result<T> g) {
    if (e != 0) {
      g.rf = ldexp(g.rf, -e / 2);
      g.dx = ldexp(g.dx, -3 * e / 2);
      g.dy = ldexp(g.dy, -3 * e / 2);
      g.dz = ldexp(g.dz, -3 * e / 2);
    }
    return g;
  };
  x = ldexp(x, -e);
  y = ldexp(y, -e);
  z = ldexp(z, -e);
  // A zero argument goes last (R_F is symmetric), where the kernel skips its infinite R_D.
  if (x == 0) {
    const auto g = detail::carlson_rf_gradient_imp<T, Policy, true>(y, z, x);
    return scaled({g.rf, g.dz, g.dx, g.dy});
  }
  if (y == 0) {
    const auto g = detail::carlson_rf_gradient_imp<T, Policy, true>(z, x, y);
    return scaled({g.rf, g.dy, g.dz, g.dx});
  }
  if (z == 0) return scaled(detail::carlson_rf_gradient_imp<T, Policy, true>(x, y, z));
  return scaled(detail::carlson_rf_gradient_imp<T, Policy>(x, y, z));
}

template <class T>
inline carlson_rf_gradient_result<T> carlson_rf_gradient(T x, T y, T z) {
  return carlson_rf_gradient(x, y, z, policies::default_policy());
}

}  // namespace gecko
