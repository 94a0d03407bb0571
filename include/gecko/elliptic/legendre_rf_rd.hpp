// gecko/elliptic/legendre_rf_rd.hpp — R_F(x, y, z) and R_D(x, y, z) together, for the Legendre E
// (gecko/elliptic/ellint_e.hpp), from arguments whose square roots the caller already holds:
// x = cos^2 phi, and {y, z} = {1, Delta^2}, with roots cos phi, 1 and Delta.
//
// The duplication (DLMF 19.26.18, 19.26.20) in the scaled product form of the Legendre F kernel
// (legendre_rf_imp in gecko/elliptic/ellint_f.hpp): with X_n = 4^n x_n, ... and their roots,
//   X_(n+1) = (rx + ry)(rx + rz),  Y_(n+1) = (rx + ry)(ry + rz),  Z_(n+1) = (rx + rz)(ry + rz),
// three square roots, three additions and three multiplications a step. The two means are carried
// at the same scale, A'_(n+1) = A'_n + Lambda_n (both grow by 4^n lambda_n).
// R_D's sum term 4^-n / (sqrt(z_n) (z_n + lambda_n)) is, at that scale, 2^n / (rz (Z_n + Lambda_n)),
// Lambda_n = rx ry + rx rz + ry rz, and the tails are
//   R_F(x, y, z) = 2^n R_F(X_n, Y_n, Z_n),  4^-n R_D(x_n, y_n, z_n) = 2^n R_D(X_n, Y_n, Z_n)
// (homogeneity, DLMF 19.18.1, degrees -1/2 and -3/2), each finished by its series at the scaled
// deviations (A_0 - x_0) / A'_n (DLMF 19.36.1; A_n - x_n = 4^-n (A_0 - x_0)).
// The first step uses the known roots and is always taken, as in the F kernel. The loop stops once
// both series are accurate: max|X| < t_F11 for R_F's degree-11 series and < t_D for R_D's
// (gecko/elliptic/carlson_tolerance.hpp); the two thresholds are within 7 % of each other, so the
// longer R_F series would save no step.
// Against carlson_rf_rd_imp (gecko/elliptic/carlson_rf_rd.hpp), which scales five quantities by
// 1/4 a step, this skips two square roots in the first step and about a third of the other
// arithmetic. Measured with both versions of ellint_e on the E inputs of bench/elliptic/data
// (20,000 points, AMD EPYC): median 56.6 against 61.5 ns a call; error rms 0.590 against 0.594 eps
// (worst 2.43 against 2.32), near m = 1 0.524 against 0.524 (2.13 against 2.19); on the
// near-singular table 0.739 against 0.742 eps (worst 2.57 for both).
// Unchecked (detail) kernel: x = rx^2, y = ry^2, z = rz^2 to within rounding, x >= 0,
// y, z > 0, and every argument below 1/eps (the scaled arguments grow like 4^n; the ellint_e
// caller sends larger Delta^2, m -> -inf, to carlson_rf_rd_imp).
#pragma once

#include <cmath>

#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_arguments.hpp"
#include "gecko/elliptic/carlson_rd.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/carlson_rf_rd.hpp"
#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {
namespace detail {

template <class T, class Policy = policies::default_policy>
inline carlson_rf_rd_result<T> legendre_rf_rd_imp(T x, T y, T z, T rx, T ry, T rz) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol_f = carlson_tolerance<T, Policy::precision_bits>::rf11;
  constexpr T tol_d = carlson_tolerance<T, Policy::precision_bits>::rd;
  T AF = (x + y + z) * (T(1) / 3);
  T AD = (x + y + 3 * z) * (T(1) / 5);
  const T fx = AF - x, fy = AF - y;
  const T dx = AD - x, dy = AD - y;
  const T DF = max_of(max_of(fabs(fx), fabs(fy)), fabs(AF - z));
  const T DD = max_of(max_of(fabs(dx), fabs(dy)), fabs(AD - z));
  // Stop when every series argument is below its threshold: DF < tol_f A'_F and DD < tol_d A'_D.
  const T limF = DF * (1 / tol_f);
  const T limD = DD * (1 / tol_d);
  T xy = rx + ry, xz = rx + rz, yz = ry + rz;
  // The scaled means A'_(n+1) = A'_n + Lambda_n, Lambda_n = 4^n lambda_n: carried rather than
  // formed from X + Y + Z, whose products' roundings compound over the steps (measured on
  // 20,000 random E: 270 results beyond 1.5 eps that way, against 199).
  const T L0 = rx * yz + ry * rz;
  // R_D's sum term 2^n / (rz (Z + Lambda)): Z + Lambda equals (rx + rz)(ry + rz), but the sum
  // rounds less (measured on the near-singular E table, tests/data/elliptic_near_singular.csv:
  // results beyond 2 eps 16 -> 6, worst 2.80 -> 2.57 eps)
  T sum = 1 / (rz * (z + L0));
  AF += L0;
  AD += L0;
  T X = xy * xz, Y = xy * yz, Z = xz * yz;  // 4 x_1, 4 y_1, 4 z_1
  T g = 2;                                  // 2^n
  for (int step = 1; (AF <= limF || AD <= limD) && step < carlson_max_steps<T>; ++step) {
    const T sx = sqrt(X), sy = sqrt(Y), sz = sqrt(Z);
    xy = sx + sy;
    xz = sx + sz;
    yz = sy + sz;
    const T L = sx * yz + sy * sz;
    sum += g / (sz * (Z + L));
    AF += L;
    AD += L;
    X = xy * xz;
    Y = xy * yz;
    Z = xz * yz;
    g *= 2;
  }
  // one division for both series arguments: its roundings (3 ulp at most) reach the result only
  // through the series tails, which are below 0.06 relative
  const T q = 1 / (AF * AD);
  const T rA = AD * q, rB = AF * q;
  const T w = g / sqrt(AF);
  return {w + w * carlson_rf_series11_tail(fx * rA, fy * rA),
          carlson_rd_series(dx * rB, dy * rB, AD, g) + 3 * sum};
}

}  // namespace detail
}  // namespace gecko
