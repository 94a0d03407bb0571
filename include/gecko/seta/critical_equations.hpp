// gecko/seta/critical_equations.hpp — the critical-state equations as a public function: residual
// and exact Jacobian at a given state (docs/theory/two_level_seta.md; the formulation of
// gecko/seta/critical_residual.hpp). For users who drive their own solver, and for tests.
//
// Unknowns: (Fn, theta_joint = beta, theta_rate_joint = theta2'(l1), theta_rate_base = theta1'(0));
// equations: F1 = L_spatula - l2, F2 = L_beam - l1, F3 = EI2 theta2'(l1)^2 / 2 - R2(beta),
// F4 = EI1 theta1'(0)^2 / 2 - R1(alpha1). The Carlson plan (which forms measure each segment) is
// the one chosen for this state.
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/extensibility.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

template <class T>
struct critical_equations_result {
  Eigen::Matrix<T, 4, 1> F;       // residual
  Eigen::Matrix<T, 4, 4> J;       // dF/d(Fn, theta_joint, theta_rate_joint, theta_rate_base)
  Eigen::Matrix<T, 4, 1> dF_dFt;  // dF/dFt
  bool valid = false;             // false: the state is outside every form (R < 0 on a path, ...)
};

namespace detail {
template <class Policy, bool E1, bool E2, class T>
inline critical_equations_result<T> critical_equations_imp(const seta_params<T>& d, T Ft, T Fn, T beta, T rj, T rb) {
  using std::sqrt; using std::cos;
  using System = seta_system<T, Policy, E1, E2>;
  const System sys(d);
  critical_equations_result<T> r;
  typename System::vec z;
  const T sp = sqrt(d.EI2 / 2), sq = sqrt(d.EI1 / 2);
  z << Fn, beta, rj * sp, rb * sq;
  const T mu = sys.mu_of(Ft);
  const auto plan = sys.plan(z, mu);
  if (System::plan_state(plan) != segment_state::ok) return r;
  typename System::vec JF;
  T u14[2];
  r.valid = sys.eval(z, mu, plan, r.F, r.J, &JF, u14);
  r.J.col(2) *= sp;
  r.J.col(3) *= sq;
  // dmu/dFt = 1 / cos(mu/(Ft)max) for an extensible spatula.
  r.dF_dFt = E2 ? (JF / cos(mu / sys.ftmax)).eval() : JF;
  return r;
}
}  // namespace detail

template <class T, class Policy = policies::default_policy>
inline critical_equations_result<T> critical_equations(const TwoLevelSeta<T>& seta, T Ft, T Fn, T theta_joint,
                                                       T theta_rate_joint, T theta_rate_base,
                                                       const Policy& = Policy()) {
  constexpr const char* fn = "gecko::critical_equations";
  if (!detail::check_seta<T, Policy>(seta, fn) || !detail::check_ft<T, Policy>(Ft, ft_max(seta), fn))
    return critical_equations_result<T>();
  const auto d = detail::make_seta_params(seta);
  return detail::visit_extensibility(seta, [&](auto E1, auto E2) {
    return detail::critical_equations_imp<Policy, decltype(E1)::value, decltype(E2)::value>(
        d, Ft, Fn, theta_joint, theta_rate_joint, theta_rate_base);
  });
}

}  // namespace gecko
