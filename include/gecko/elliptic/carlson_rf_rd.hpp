// gecko/elliptic/carlson_rf_rd.hpp — R_F(x, y, z) and R_D(x, y, z) from ONE duplication.
//
// Both integrals use the same duplication sequence x_n, y_n, z_n (DLMF 19.26.18/19.26.20); only
// the means differ (A = (x+y+z)/3 for R_F, (x+y+3z)/5 for R_D). Sharing the square roots halves
// the cost of code that needs both (the Legendre E, the seta Jacobian, ellint_ek).
// The loop runs until both stopping tests of gecko/elliptic/carlson_tolerance.hpp hold.
//
// Unchecked (detail) kernel; arguments as for carlson_rd: x, y >= 0 (at most one zero), z > 0.
#pragma once

#include <cmath>

#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_rd.hpp"
#include "gecko/elliptic/carlson_rf.hpp"

namespace gecko {
namespace detail {

template <class T>
struct carlson_rf_rd_result {
  T rf;
  T rd;
};

template <class T, class Policy = policies::default_policy>
inline carlson_rf_rd_result<T> carlson_rf_rd_imp(T x, T y, T z) {
  using std::fabs;
  using std::sqrt;
  constexpr T tol_f = carlson_tolerance<T, Policy::precision_bits>::rf;
  constexpr T tol_d = carlson_tolerance<T, Policy::precision_bits>::rd;
  T AF = (x + y + z) * (T(1) / 3);
  T AD = (x + y + 3 * z) * (T(1) / 5);
  const T fx = AF - x, fy = AF - y, fz = AF - z;
  const T dx = AD - x, dy = AD - y, dz = AD - z;
  const T DF = max_of(max_of(fabs(fx), fabs(fy)), fabs(fz));
  const T DD = max_of(max_of(fabs(dx), fabs(dy)), fabs(dz));
  T f = 1;
  T sum = 0;
  for (int step = 0; step < carlson_max_steps<T> && (f * DD >= tol_d * AD || f * DF >= tol_f * AF); ++step) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * (sy + sz) + sy * sz;
    sum += carlson_rd_sum_term(f, sz, z + lambda);  // (carlson_rd.hpp: no spurious overflow)
    x = (x + lambda) * T(0.25);
    y = (y + lambda) * T(0.25);
    z = (z + lambda) * T(0.25);
    AF = (AF + lambda) * T(0.25);
    AD = (AD + lambda) * T(0.25);
    f *= T(0.25);
  }
  const T sD = f / AD;
  return {carlson_rf_finish(fx, fy, AF, f), carlson_rd_series(dx * sD, dy * sD, AD, f) + 3 * sum};
}

}  // namespace detail
}  // namespace gecko
