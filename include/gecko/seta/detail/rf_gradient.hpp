// gecko/seta/detail/rf_gradient.hpp — R_F on forward-mode duals, for the seta's Newton Jacobian.
//
// Every elastica length is one R_F whose arguments depend on the unknowns (Fn, theta_joint), so
// the Jacobian needs dR_F/dx_i = -R_D(x_j, x_k, x_i)/6 (DLMF 19.18.1) for all three arguments at
// every length evaluation. gecko/elliptic/carlson_rf_gradient.hpp gives the value and the three
// partials from one duplication; here they are pushed through the chain rule.
//
// Unchecked: x, y, z > 0, finite, moderately scaled (the seta arguments are U_ij^2 of order
// 1/length^2 in units of EI; they are never near the overflow range). Two zero arguments
// (a degenerate continuation state) give NaN, never a hang.
#pragma once

#include <cstddef>

#include "gecko/core/policy.hpp"
#include "gecko/elliptic/carlson_rf.hpp"
#include "gecko/elliptic/carlson_rf_gradient.hpp"
#include "gecko/seta/detail/dual.hpp"

namespace gecko {
namespace detail {

// R_F on plain scalars (no gradient needed) and on duals (gradient through the chain rule).
template <class Policy, class T>
inline T carlson_rf_ad(T x, T y, T z) {
  return carlson_rf_imp<T, Policy>(x, y, z);
}
template <class Policy, class T, std::size_t K>
inline dual<T, K> carlson_rf_ad(const dual<T, K>& x, const dual<T, K>& y, const dual<T, K>& z) {
  const carlson_rf_gradient_result<T> g = carlson_rf_gradient_imp<T, Policy>(x.v, y.v, z.v);
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
  const carlson_rf_gradient_result<T> g = carlson_rf_gradient_imp<T, Policy, true>(x.v, y.v, T(0));
  dual<T, K> r;
  r.v = g.rf;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = g.dx * x.d[i] + g.dy * y.d[i];
  return r;
}

}  // namespace detail
}  // namespace gecko
