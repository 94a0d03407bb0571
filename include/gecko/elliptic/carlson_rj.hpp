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
// The public layer rescales arguments outside 2^(+-max_exponent/8) (products of three square
// roots are formed); arguments spread over more than 2 max_exponent/5 binades first take
// duplication steps at their own scale (carlson_rj_spread_step), and the large-p route and the
// principal value keep p's scale apart from that of x, y, z (fuzz findings F2-F4).
// p > 16 max(x, y, z): the duplication stalls (see carlson_rj_duplication), so DLMF 19.21.11
// maps p to q in [z, 1.07 z] first (carlson_rj_imp).
//
// p < 0: Cauchy principal value through DLMF 19.20.14 (x <= y <= z after permuting, q = -p):
//   (z + q) R_J(x,y,z,-q) = (p' - z) R_J(x,y,z,p') - 3 R_F(x,y,z)
//                           + 3 sqrt(xyz/(xy + p'q)) R_C(xy + p'q, p'q),
//   p' = (z(x + y + q) - xy)/(z + q) > 0,  p' - z = -(z - x)(z - y)/(z + q),
//   every product formed as a ratio (carlson_rj_pv, carlson_rj_pv_rc_term).
//   The three terms have mixed signs and the principal value passes through zero, so its
//   relative error is that of the terms times the cancellation factor sum|terms| / |sum|
//   (tests: within 4 eps times that factor, which reaches 370 in the table, i.e. up to 223
//   ulps of the result there; p > 0 stays within a few ulps). Next to a zero of the sum the factor
//   has no bound, and the result may carry no digit: rj_pv_cancellation_beyond_max in
//   tests/data/fuzz_regressions.csv has factor 8.9e15 and value -1.2e460 and comes back 0, which
//   meets the bound (the next double below its p nearly doubles the value).
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
  const T xs = ldexp(x, -e), ys = ldexp(y, -e), zs = ldexp(z, -e);
  const int ep = ilogb(p);
  if (ep - e > 4 * std::numeric_limits<T>::digits) {
    // p/z beyond 2^(4 digits): the two subtracted terms below are smaller than 3 R_F by
    // sqrt(z/p) log(p/z) < eps^2, and p - z = p to rounding, so R_J = 3 R_F(x, y, z)/p. p keeps
    // its own scale: p 2^-e overflowed for p/z > 2^1023 and gave 0 (fuzz finding F3:
    // R_J(2^-1000, 2^-997, 2^-1001, 2^63) = 6.3e131).
    const T rf = carlson_rf_imp<T, Policy>(xs, ys, zs);
    return ldexp(3 * rf / ldexp(p, -ep), -e / 2 - ep);
  }
  const T ps = ldexp(p, -e);
  const T pz = ps - zs;
  const T qz = (zs - xs) * (zs - ys) / pz;  // q - z >= 0
  const T qs = zs + qz;
  const T rj_q = carlson_rj_duplication<T, Policy>(xs, ys, zs, qs);
  const T rf = carlson_rf_imp<T, Policy>(xs, ys, zs);
  const T rc = carlson_rc_imp<T, Policy>(xs * ys, ps * qs);
  return ldexp((3 * rf - 3 * sqrt(zs) * rc - qz * rj_q) / pz, -3 * e / 2);
}

// 3 sqrt(xyz/(xy + p'q)) R_C(xy + p'q, p'q)/(z + q), the third term of DLMF 19.20.14 over
// z + q, from the ratio w = xy/(p'q) (homogeneity: R_C(xy + p'q, p'q) = R_C(1 + w, 1)/sqrt(p'q)):
// the products xy, xyz and p'q themselves under- or overflow for arguments far apart (fuzz
// finding F4b: R_J(100, DBL_MAX, 1.0005, -50.3) was 23% off), and so can sqrt(p') sqrt(q)
// (subnormal: 1500 eps). Every factor is taken apart into mantissa and exponent, and the
// exponents are applied once at the end. x, y, z, z + q, p', q > 0 and finite.
template <class T, class Policy = policies::default_policy>
inline T carlson_rj_pv_rc_term(T x, T y, T z, T zq, T pp, T q) {
  using std::frexp;
  using std::ldexp;
  using std::log;
  using std::sqrt;
  int ex, ey, ez, ezq, ep, eq;
  const T mx = frexp(x, &ex), my = frexp(y, &ey), mz = frexp(z, &ez), mzq = frexp(zq, &ezq);
  const T mp = frexp(pp, &ep), mq = frexp(q, &eq);
  const T r = (mx * my) / (mp * mq);  // in (1/4, 4)
  const int k = ex + ey - ep - eq;     // w = r 2^k
  if (k > 2 * std::numeric_limits<T>::digits + 2) {
    // w > 2^(2 digits): R_C(1 + w, 1) = log(4w)/(2 sqrt w) (1 + O(log(w)/w)) and the factor
    // sqrt(w/(1 + w)) is 1, both to rounding: the term is 3 log(4w) sqrt(z/(xy))/(2 (z + q)).
    const int s = ez - ex - ey, par = s & 1;  // s - par is even
    const T lg = log(4 * r) + k * T(0.693147180559945309417232121458176568L);
    return ldexp(T(1.5) * lg * sqrt(mz * T(1 + par) / (mx * my)) / mzq, (s - par) / 2 - ezq);
  }
  // w below the normal range: the term is below sqrt(w) < 2^-500 relative to the R_F term, which
  // it is added to (flushing it costs nothing); otherwise w is a normal number.
  const T w = ldexp(r, k);
  const int s = ez - ep - eq, par = s & 1;  // sqrt(z/(p'q)) = sqrt(mz 2^par/(mp mq)) 2^((s-par)/2)
  const T f = 3 * sqrt(w / (1 + w)) * carlson_rc_imp<T, Policy>(1 + w, T(1)) *
              sqrt(mz * T(1 + par) / (mp * mq)) / mzq;
  return ldexp(f, (s - par) / 2 - ezq);
}

}  // namespace detail

template <class T, class Policy>
inline T carlson_rj(T x, T y, T z, T p, const Policy&);

namespace detail {

// Cauchy principal value for p < 0 (DLMF 19.20.14), at the arguments' own scale: every quantity
// below is a ratio or goes through the public R_F and R_J (which rescale and compress spread
// arguments themselves), so |p| far above or below x, y, z needs no common rescaling. Rescaling
// all four by |p| flushed x, y, z and gave inf * 0 = NaN (fuzz finding F4:
// R_J(0, 40.8, 48.7, -2^1009)). x, y, z as for carlson_rj_imp, p < 0, all finite.
template <class T, class Policy = policies::default_policy>
inline T carlson_rj_pv(T x, T y, T z, T p, const Policy& pol) {
  using std::sqrt;
  if (x > y) std::swap(x, y);
  if (y > z) std::swap(y, z);
  if (x > y) std::swap(x, y);
  const T q = -p;
  {
    // All four near the bottom of the range: the ratios below round to subnormal numbers or to
    // zero (p' = 0 raised a domain error for R_J(0, 2^-1074, 2^-1074, -2^-1074)). Scale them UP
    // to order one (exact, nothing flushes) and the result back.
    using std::ilogb;
    using std::ldexp;
    const int le = ilogb(max_of(z, q));
    if (le < std::numeric_limits<T>::min_exponent / 2) {
      const int e = le & ~1;
      return ldexp(carlson_rj_pv<T, Policy>(ldexp(x, -e), ldexp(y, -e), ldexp(z, -e), ldexp(p, -e), pol),
                   -3 * e / 2);
    }
  }
  // z + q overflows only when z and q are both above 2^(max_exponent - 2): then every division
  // by z + q below is one by c (z + q) with c = 1/4, and c is taken out again (exact there).
  // Scaling all four arguments instead flushed a subnormal x or y (R_J(0, 2^-1074, DBL_MAX,
  // -1e300) raised a domain error).
  T c = 1;
  T zq = z + q;
  if (!(zq <= std::numeric_limits<T>::max())) {
    c = T(0.25);
    zq = z * c + q * c;
  }
  const T xq = x * c + q * c;      // c (x + q)
  const T zx = (z - x) * c / zq;   // (z - x)/(z + q), in [0, 1]
  // p' = (z(x + y + q) - xy)/(z + q) = z (x + q)/(z + q) + y (z - x)/(z + q): non-negative terms
  // (z >= x), and ratios, so that nothing of size z q is formed; the factor of (x + q) z/(z + q)
  // that is divided is the larger one, so that the quotient (in [1/2, 1]) cannot underflow.
  // p' >= min(z, q)/2 > 0.
  // p' <= z exactly (p' - z <= 0); the rounded sum can exceed z, and DBL_MAX near the top of the
  // range (R_J(DBL_MAX, DBL_MAX, DBL_MAX, -1e300) gave inf): clamp.
  const T pp = min_of((z >= q ? xq * (z / zq) : z * (xq / zq)) + y * zx, z);
  // Each term of 19.20.14 is divided by z + q before it is added: the terms themselves overflow
  // where the result does not (R_J(2^619, 1.3e-313, 2^-591, -2^-1071) gave inf).
  // (p' - z) R_J(x, y, z, p')/(z + q) with p' - z = -(z - x)(z - y)/(z + q) <= 0. For x, y, z
  // below 2^(2 min_exponent / 3), R_J (~ z^(-3/2)) overflows while p' - z may underflow (inf * 0
  // when q >> z: R_J(2^-1000, 2^-999, 2^-998, -2^1000)); there R_J is taken at arguments scaled
  // UP by 2^-e (exact, nothing flushes) and (z - y) R_J ~ z^(-1/2) scaled back.
  const T rj = carlson_rj(x, y, z, pp, pol);
  T value;
  if (rj <= std::numeric_limits<T>::max() || !(z < 1)) {  // z >= 1: a genuine overflow
    value = -(zx * ((z - y) * c / zq)) * rj;
  } else {
    using std::ilogb;
    using std::ldexp;
    const int e = ilogb(z) & ~1;
    const T zs = ldexp(z, -e);
    const T rj_s = carlson_rj(ldexp(x, -e), ldexp(y, -e), zs, ldexp(pp, -e), pol);
    value = -zx * (ldexp((zs - ldexp(y, -e)) * rj_s, -e / 2) * c / zq);
  }
  value -= 3 * carlson_rf(x, y, z, pol) * c / zq;
  if (x != 0) value += carlson_rj_pv_rc_term<T, Policy>(x, y, z, zq, pp, q) * c;
  if (!(value >= -std::numeric_limits<T>::max() && value <= std::numeric_limits<T>::max())) {
    // A term overflowed: inf - inf = NaN, or inf where the result is just below DBL_MAX
    // (R_J(2^-1022, 2^-1021, 48.7, -2^-1074) = 1.7956e308), and the result may overflow too:
    // R_J(2^-1034, 2^-829, 2^-765, -2^-831) = -9.8e364, R_J(2^-1074, 2^-1027, 1.6, -2^-1071) =
    // 5.2e315). The terms fall as the arguments grow (degree -3/2): evaluate at arguments scaled
    // UP (exact, nothing flushes) so that the largest is near 1, or at least by 2^(max_exponent/2)
    // (not so far that the largest terms underflow), and scale the result back: +-inf with the
    // right sign, or the finite value.
    using std::ilogb;
    using std::ldexp;
    constexpr int half = std::numeric_limits<T>::max_exponent / 2;
    const int le = ilogb(max_of(z, q));
    const int e = le < half - 8 ? ((le < -half ? le : -half) & ~1) : 0;
    if (e < 0)
      return ldexp(carlson_rj_pv<T, Policy>(ldexp(x, -e), ldexp(y, -e), ldexp(z, -e), ldexp(p, -e), pol),
                   -3 * e / 2);
  }
  return value;
}

// 2^(2 max_exponent / 5): the largest ratio of the largest of x, y, z to the smallest positive
// argument that the rescaled duplication takes without underflowing intermediates.
template <class T>
constexpr T carlson_rj_spread_limit() {
  T v = 1;
  for (int i = 0; i < 2 * std::numeric_limits<T>::max_exponent / 5; ++i) v *= 2;
  return v;
}

// One duplication step of R_J at the arguments' own scale (see carlson_rj), p > 0:
//   R_J(x, y, z, p) = R_J(x', y', z', p')/4 + 3 R_C(t^2, p)/(4 p'),
//   t = (p (sx + sy + sz) + sx sy sz)/(4 p'),  p' = (p + lambda)/4,
// with t formed from bounded ratios ((sx + sy + sz)/p' <= 12/sqrt(y_mid), and sy sz/p' <= 4 for
// the two largest roots: sy sz <= lambda) and R_C(t^2, p) = R_C(u^2, 1)/sqrt(p), u = t/sqrt(p), so that neither t^2 nor p^3
// is formed. For u > 2^(digits/2 + 1), R_C(u^2, 1) = log(2u)/u to rounding (u itself may
// overflow: it is used through its logarithm there).
template <class T, class Policy>
inline T carlson_rj_spread_step(T x, T y, T z, T p, const Policy& pol) {
  using std::log;
  using std::sqrt;
  const auto d = carlson_duplicate_once(x, y, z);
  const T p4 = p * T(0.25) + d.lambda4;
  T r0 = d.sx, r1 = d.sy, r2 = d.sz;  // sorted: r0 <= r1 <= r2
  if (r0 > r1) std::swap(r0, r1);
  if (r1 > r2) std::swap(r1, r2);
  if (r0 > r1) std::swap(r0, r1);
  // p times the ratio, not p/p' times the sum: p may be subnormal, and p/p' even more so.
  const T t = p * (T(0.25) * (r0 + r1 + r2) / p4) + T(0.25) * (r0 * (r1 * r2 / p4));
  constexpr T ln2 = T(0.693147180559945309417232121458176568L);
  const T sp = sqrt(p);
  const T u = t / sp;
  T rc_over_sp;  // R_C(t^2, p)
  if (u > T(1 << (std::numeric_limits<T>::digits / 4)) * T(1 << (std::numeric_limits<T>::digits / 4 + 1))) {
    // R_C(u^2, 1)/sqrt(p) = log(2u)/(u sqrt(p)) = log(2u)/t
    const T log_u = u <= std::numeric_limits<T>::max() ? log(u) : log(t) - log(sp);
    rc_over_sp = (log_u + ln2) / t;
  } else {
    rc_over_sp = carlson_rc_imp<T, Policy>(u * u, T(1)) / sp;
  }
  // R_J(x', y', z', p')/4 = 2 R_J(4x', 4y', 4z', 4p') (degree -3/2): the left side overflows for
  // results near DBL_MAX (R_J(2^-1074, 0, 2^-591, 2^-719) = 9.3e307 gave inf).
  const T inner = max_of(max_of(d.x, d.y), max_of(d.z, p4)) < std::numeric_limits<T>::max() / 4
                      ? 2 * carlson_rj(4 * d.x, 4 * d.y, 4 * d.z, 4 * p4, pol)
                      : carlson_rj(d.x, d.y, d.z, p4, pol) * T(0.25);
  return inner + (T(0.75) * rc_over_sp) / p4;
}

}  // namespace detail

template <class T, class Policy>
inline T carlson_rj(T x, T y, T z, T p, const Policy& pol) {
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
  if (p < 0) return detail::carlson_rj_pv<T, Policy>(x, y, z, p, pol);
  const T hi = max_of(max_of(x, y), z);  // > 0
  // Arguments spread over more than 2 max_exponent / 5 binades (p counted only below the
  // largest of x, y, z: p far above them is the large-p route's business): the duplication's
  // intermediates t^2 ~ p^2 x / lambda^2 underflow (R_J(48.7, 0, 2^-928, 2^-1000) was 2150 eps
  // off), and the rescaling below would flush the smallest arguments (ilogb(0), UB, in the
  // large-p route when all of x, y, z were flushed): fuzz finding F2. One duplication step at the
  // arguments' own scale (Carlson 1995, eq. 2.19 with homogeneity),
  //   R_J(x, y, z, p) = R_J(x', y', z', p')/4 + 3 R_C(t^2, p)/(p + lambda),
  // halves the spread; the recursion ends within a few steps.
  T lo = detail::min_positive(x, y, z);
  if (p < lo) lo = p;
  constexpr T spread_limit = detail::carlson_rj_spread_limit<T>();
  // Both tests below first check that their product is finite: it overflowed for arguments
  // near 1e300 and raised the flag on valid input (where it would overflow, the test is false).
  constexpr T largest = std::numeric_limits<T>::max();
  if (lo < largest / spread_limit && hi > lo * spread_limit)
    return detail::carlson_rj_spread_step<T, Policy>(x, y, z, p, pol);
  // p far above x, y, z: the kernel's large-p route works in units of max(x, y, z) and keeps p's
  // scale apart; a common rescaling would overflow p or flush x, y, z.
  if (hi < largest / 16 && p > 16 * hi) return detail::carlson_rj_imp<T, Policy>(x, y, z, p);
  // products of three square roots inside the kernel: keep the largest argument within
  // 2^(+-max_exponent/8).
  constexpr int window = std::numeric_limits<T>::max_exponent / 8;
  const int le = std::ilogb(max_of(hi, p));
  const int e = (le > window || le < -window) ? (le & ~1) : 0;
  if (e != 0) {
    x = ldexp(x, -e);
    y = ldexp(y, -e);
    z = ldexp(z, -e);
    p = ldexp(p, -e);
  }
  const T r = detail::carlson_rj_imp<T, Policy>(x, y, z, p);
  // R_J(x, y, z, p) = 2^(-3e/2) R_J(2^-e x, ...), exactly (e is even).
  return e != 0 ? ldexp(r, -3 * e / 2) : r;
}

template <class T>
inline T carlson_rj(T x, T y, T z, T p) {
  return carlson_rj(x, y, z, p, policies::default_policy());
}

}  // namespace gecko
