// gecko/elliptic/carlson_rj.hpp — Carlson's integral of the third kind
//   R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t + p) sqrt((t + x)(t + y)(t + z)))   (DLMF 19.16.2)
//
// Algorithm (p > 0): duplication (DLMF 19.26.19) with Carlson's sum (Carlson 1995, eq. 2.19)
//   sum_n 4^-n R_C(alpha_n, beta_n),  alpha = (p (sqrt x + sqrt y + sqrt z) + sqrt(xyz))^2,
//                                     beta = p (p + lambda)^2,
// rather than the d_n / e_n form of DLMF 19.36.2: e_n = 4^-3n delta / d_n^2 tends to -1 when one
// argument is far below p, and atanh(sqrt(-e))/sqrt(-e) then amplifies the rounding of e by
// 1/(1 + e) (measured: 1e8 ulps for arguments spread over 1e-12..1e12). alpha and beta are
// formed from the current arguments without subtraction, and R_C itself does not cancel
// (evaluated as R_C(t^2, p)/(p + lambda) with t = sqrt(alpha)/(p + lambda), so that nothing of
// size p^3 is ever formed).
// Then the degree-5 series of DLMF 19.36.2 with P = -(X + Y + Z)/2:
//   E2 = XY + XZ + YZ - 3P^2, E3 = XYZ + 2 E2 P + 4P^3, E4 = (2XYZ + E2 P + 3P^3) P, E5 = XYZP^2,
//   R_J = 4^-n A^(-3/2) (1 - 3E2/14 + E3/6 + 9E2^2/88 - 3E4/22 - 9E2E3/52 + 3E5/26) + 3 sum.
// The public layer still rescales arguments outside 2^(+-max_exponent/8) (products of three
// square roots are formed), and the large-p route rescales its own sub-problem.
// p > 16 max(x, y, z): the duplication stalls (see carlson_rj_duplication), so DLMF 19.21.11
// maps p to q in [z, 1.07 z] first (carlson_rj_imp).
//
// p < 0: Cauchy principal value through DLMF 19.20.14 (x <= y <= z after permuting, q = -p):
//   (z + q) R_J(x,y,z,-q) = (p' - z) R_J(x,y,z,p') - 3 R_F(x,y,z)
//                           + 3 sqrt(xyz/(xy + p'q)) R_C(xy + p'q, p'q),
//   p' = (z(x + y + q) - xy)/(z + q) > 0,  p' - z = -(z - x)(z - y)/(z + q).
//   The three terms have mixed signs and the principal value passes through zero, so its
//   relative error is that of the terms times the cancellation factor sum|terms| / |sum|
//   (tests: within 8 eps times that factor, which reaches 370 in the table, i.e. up to 223
//   ulps of the result there; p > 0 stays within a few ulps).
//
// Domain: x, y, z >= 0 with at most one of them zero, p != 0. +inf in any argument gives 0.
// NaN gives NaN quietly. float arguments are evaluated in double (one rounding at the end).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_arguments.hpp"
#include "gecko/elliptic/carlson_rc.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {
namespace detail {

// The duplication proper. Its rate depends on lambda = sqrt(x)sqrt(y) + ..., which ignores p:
// when p is far above x, y, z every step divides p_n and A_n by 4 alike and the scaled
// deviations stop shrinking (p/max(x,y,z) = 1e121 took 200 steps and overflowed), so
// carlson_rj_imp routes that case through DLMF 19.21.11 first.
template <class T, class Policy = policies::default_policy>
inline T carlson_rj_duplication(T x, T y, T z, T p) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol = carlson_tolerance<T, Policy::precision_bits>::rj;
  T A = (x + y + z + 2 * p) * (T(1) / 5);
  const T dx = A - x, dy = A - y, dz = A - z, dp = A - p;
  const T D = max_of(max_of(fabs(dx), fabs(dy)), max_of(fabs(dz), fabs(dp)));
  T f = 1;  // 4^-n
  T sum = 0;
  for (int step = 0; step < carlson_max_steps<T> && f * D >= tol * A; ++step) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * (sy + sz) + sy * sz;
    // R_C(alpha, beta) = R_C(t^2, p) / (p + lambda), t = alpha^(1/2) / (p + lambda) (degree -1/2
    // homogeneity): alpha and beta themselves (~ p^3) under- or overflow for spread arguments.
    const T pl = p + lambda;
    const T t = (p * (sx + sy + sz) + sx * sy * sz) / pl;
    sum += f * carlson_rc_imp<T, Policy>(t * t, p) / pl;
    x = (x + lambda) * T(0.25);
    y = (y + lambda) * T(0.25);
    z = (z + lambda) * T(0.25);
    p = (p + lambda) * T(0.25);
    A = (A + lambda) * T(0.25);
    f *= T(0.25);
  }
  const T s = f / A;
  const T X = dx * s, Y = dy * s, Z = dz * s;
  const T P = -(X + Y + Z) / 2;
  const T XYZ = X * Y * Z;
  const T P2 = P * P;
  const T E2 = X * Y + X * Z + Y * Z - 3 * P2;
  const T E3 = XYZ + 2 * E2 * P + 4 * P2 * P;
  const T E4 = (2 * XYZ + E2 * P + 3 * P2 * P) * P;
  const T E5 = XYZ * P2;
  const T q = E2 * (T(-3) / 14 + E2 * (T(9) / 88) - E3 * (T(9) / 52)) + E3 * (T(1) / 6) -
              E4 * (T(3) / 22) + E5 * (T(3) / 26);
  return f * (1 + q) / (A * sqrt(A)) + 3 * sum;
}

// Unchecked kernel: x, y, z >= 0 (at most one zero), p > 0, finite and moderately scaled.
// p > 16 max(x, y, z): DLMF 19.21.11 with z the largest of x, y, z,
//   (p - z) R_J(x,y,z,p) + (q - z) R_J(x,y,z,q) = 3 R_F(x,y,z) - 3 sqrt(z) R_C(xy, pq),
//   (p - z)(q - z) = (x - z)(y - z),
// trades p for q = z + (z - x)(z - y)/(p - z) in [z, 1.07 z], where the duplication converges
// at its usual rate. For p >> z the result is 3 R_F / p to leading order and the two
// subtracted terms are smaller by sqrt(z/p) log(p/z) at least, so little is lost to
// cancellation (measured: within the same bound as the direct route).
template <class T, class Policy = policies::default_policy>
inline T carlson_rj_imp(T x, T y, T z, T p) {
  using std::ilogb;
  using std::ldexp;
  using std::sqrt;
  if (x > z) std::swap(x, z);
  if (y > z) std::swap(y, z);
  if (!(p > 16 * z)) return carlson_rj_duplication<T, Policy>(x, y, z, p);
  // Work in units of z (an even power of two near it): x, y, z, q ~ 1 there, so nothing in the
  // duplication underflows however far below p they sit; p itself only enters R_C and the
  // final division. Every term of 19.21.11 scales as shown, the result as 2^(-3e/2).
  const int e = ilogb(z) & ~1;
  const T xs = ldexp(x, -e), ys = ldexp(y, -e), zs = ldexp(z, -e), ps = ldexp(p, -e);
  const T pz = ps - zs;
  const T qz = (zs - xs) * (zs - ys) / pz;  // q - z >= 0
  const T qs = zs + qz;
  const T rj_q = carlson_rj_duplication<T, Policy>(xs, ys, zs, qs);
  const T rf = carlson_rf_imp<T, Policy>(xs, ys, zs);
  const T rc = carlson_rc_imp<T, Policy>(xs * ys, ps * qs);
  return ldexp((3 * rf - 3 * sqrt(zs) * rc - qz * rj_q) / pz, -3 * e / 2);
}

// Cauchy principal value for p < 0 (DLMF 19.20.14); x, y, z as for carlson_rj_imp.
template <class T, class Policy = policies::default_policy>
inline T carlson_rj_pv_imp(T x, T y, T z, T p) {
  using std::sqrt;
  if (x > y) std::swap(x, y);
  if (y > z) std::swap(y, z);
  if (x > y) std::swap(x, y);
  const T q = -p;
  const T zq = z + q;
  const T pp = (z * (x + y + q) - x * y) / zq;
  const T pp_minus_z = -(z - x) * (z - y) / zq;
  const T xy = x * y;
  const T pq = pp * q;
  T value = pp_minus_z * carlson_rj_imp<T, Policy>(x, y, z, pp);  // pp <= z (sorted): no recursion
  value -= 3 * carlson_rf_imp<T, Policy>(x, y, z);
  if (xy != 0) value += 3 * sqrt(xy * z / (xy + pq)) * carlson_rc_imp<T, Policy>(xy + pq, pq);
  return value / zq;
}

}  // namespace detail

template <class T, class Policy>
inline T carlson_rj(T x, T y, T z, T p, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::carlson_rj: T must be a floating-point type");
  if constexpr (std::is_same<T, float>::value) {
    // float's exponent range is too narrow for the intermediate quantities of spread arguments
    // (p * (p + lambda)^2 and the rescalings below): evaluate in double, round once.
    return static_cast<float>(carlson_rj<double>(x, y, z, p, Policy()));
  }
  using std::isinf;
  using std::isnan;
  using std::ldexp;
  constexpr const char* function = "gecko::carlson_rj";
  constexpr const char* range = "x, y, z >= 0 with at most one of them zero, and p != 0";
  if (isnan(x) || isnan(y) || isnan(z) || isnan(p)) return std::numeric_limits<T>::quiet_NaN();
  if (x < 0) return raise_domain_error<T, Policy>(function, "x", x, range);
  if (y < 0) return raise_domain_error<T, Policy>(function, "y", y, range);
  if (z < 0) return raise_domain_error<T, Policy>(function, "z", z, range);
  if ((x == 0) + (y == 0) + (z == 0) > 1)
    return raise_domain_error<T, Policy>(function, z == 0 ? "z" : "y", T(0), range);
  if (p == 0) return raise_domain_error<T, Policy>(function, "p", p, range);
  if (isinf(x) || isinf(y) || isinf(z) || isinf(p)) return T(0);
  using detail::max_of;
  // products of three square roots inside the kernel: keep the largest argument within
  // 2^(+-max_exponent/8).
  constexpr int window = std::numeric_limits<T>::max_exponent / 8;
  const T largest = max_of(max_of(x, y), max_of(z, p < 0 ? -p : p));
  const int le = std::ilogb(largest);
  const int e = (le > window || le < -window) ? (le & ~1) : 0;
  if (e != 0) {
    x = ldexp(x, -e);
    y = ldexp(y, -e);
    z = ldexp(z, -e);
    p = ldexp(p, -e);
  }
  const T r = p > 0 ? detail::carlson_rj_imp<T, Policy>(x, y, z, p)
                    : detail::carlson_rj_pv_imp<T, Policy>(x, y, z, p);
  // R_J(x, y, z, p) = 2^(-3e/2) R_J(2^-e x, ...), exactly (e is even).
  return e != 0 ? ldexp(r, -3 * e / 2) : r;
}

template <class T>
inline T carlson_rj(T x, T y, T z, T p) {
  return carlson_rj(x, y, z, p, policies::default_policy());
}

}  // namespace gecko
