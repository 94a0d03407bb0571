// gecko/seta/sensitivities.hpp — derivatives of the critical state with respect to the design.
//
// At a converged critical state F(z*, d) = 0 (gecko/seta/critical_residual.hpp), so by the
// implicit function theorem dz*/dd = -J_z^-1 dF/dd. dF/dd comes from one evaluation of the
// residual with the nine design parameters as dual numbers (exact, no finite differences); J_z is
// the Newton Jacobian at the state. Ft is held fixed (the contact-edge rate then depends on EA2
// and w through sqrt(1 - Ft^2/(2 EA2 w))). Order of the parameters: EI1, EI2, EA1, EA2, l1, l2,
// alpha1, alpha2, w (the fields of TwoLevelSeta). For EA = infinity the derivative is 0 (the
// 1/EA term vanishes to first order). States recovered on a separatrix beyond the digits of the
// state (gecko/seta/detail/separatrix_limit.hpp) get NaN derivatives.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/detail/dual.hpp"
#include "gecko/seta/detail/separatrix_limit.hpp"
#include "gecko/seta/detail/separatrix_scales.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/extensibility.hpp"

namespace gecko {

template <class T>
struct critical_sensitivity {
  critical_state<T> state;
  std::array<T, 9> dFn;           // dFn/d(EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w)
  std::array<T, 9> dtheta_joint;  // dbeta/d(...)
};

namespace detail {

template <class Policy, bool E1, bool E2, class T>
inline void design_derivatives(const TwoLevelSeta<T>& s, const critical_state<T>& st, critical_sensitivity<T>& out) {
  using std::sqrt; using std::isinf;
  using System = seta_system<T, Policy, E1, E2>;
  const System sys(make_seta_params(s));
  out.dFn.fill(std::numeric_limits<T>::quiet_NaN());
  out.dtheta_joint.fill(std::numeric_limits<T>::quiet_NaN());
  // An inadmissible state (status 7) is a solution of the equations all the same: its derivatives
  // are those of the equations' line there (the caller decides whether to use them).
  if (st.status != critical_status::converged && st.status != critical_status::inadmissible) return;
  const auto z = sys.from_guess(st.Fn, st.theta_joint, st.theta_rate_joint, st.theta_rate_base, st.Ft);
  const T mu = sys.mu_of(st.Ft);
  // A state recovered on a separatrix (detail/separatrix_limit.hpp) whose distance from it the
  // state's digits do not resolve: the length equations cannot be differentiated there (their
  // derivatives go like 1/delta, with delta formed by cancellation). Left NaN.
  {
    T lengths[2], gaps[2];
    separatrix_measures(sys, z, mu, lengths, gaps);
    for (int i = 0; i < 2; ++i)
      if (separatrix_unresolved(lengths, gaps, i)) return;
  }
  const auto plan = sys.plan(z, mu);
  typename System::vec F;
  typename System::mat J;
  T u14[2];
  if (!sys.eval(z, mu, plan, F, J, nullptr, u14)) return;
  // Design as duals: seeds on EI1, EI2, EA1, EA2 (through c = 1/EA), l1, l2, alpha1, alpha2, w.
  using D = dual<T, 9>;
  seta_params<D> d;
  d.EI1 = D::variable(s.EI1, 0);
  d.EI2 = D::variable(s.EI2, 1);
  d.c1 = isinf(s.EA1) ? D(T(0)) : T(1) / D::variable(s.EA1, 2);
  d.c2 = isinf(s.EA2) ? D(T(0)) : T(1) / D::variable(s.EA2, 3);
  d.l1 = D::variable(s.l1, 4);
  d.l2 = D::variable(s.l2, 5);
  d.alpha1 = D::variable(s.alpha1, 6);
  d.alpha2 = D::variable(s.alpha2, 7);
  d.w = D::variable(s.w, 8);
  set_seta_angles(d);
  // The state's rates p, q are fixed numbers (as in z); the edge rate factor depends on EA2, w.
  const D Ft(st.Ft);
  D edge(T(1));
  if constexpr (E2) edge = sqrt(T(1) - st.Ft * st.Ft * d.c2 / (T(2) * d.w));
  D r[4];
  seta_residual<Policy, E1, E2>(d, D(z[0]), D(z[1]), D(z[2]), D(z[3]), Ft, edge, plan, r);
  Eigen::Matrix<T, 4, 9> dF;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 9; ++j) dF(i, j) = r[i].d[static_cast<std::size_t>(j)];
  const Eigen::Matrix<T, 4, 9> dz = -J.partialPivLu().solve(dF);
  for (int j = 0; j < 9; ++j) {
    out.dFn[static_cast<std::size_t>(j)] = dz(0, j);
    out.dtheta_joint[static_cast<std::size_t>(j)] = dz(1, j);
  }
}

}  // namespace detail

// Sensitivities of the critical states at the given Ft values (states on the line followed from
// Ft = 0, as critical_line_at).
template <class T, class Policy = policies::default_policy>
inline std::vector<critical_sensitivity<T>> sensitivities(const TwoLevelSeta<T>& seta, const std::vector<T>& Ft,
                                                          const critical_line_options<T>& options = critical_line_options<T>(),
                                                          const Policy& pol = Policy()) {
  using std::isinf;
  const auto states = critical_line_at(seta, Ft, options, pol);
  std::vector<critical_sensitivity<T>> out(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    out[i].state = states[i];
    detail::visit_extensibility(seta, [&](auto E1, auto E2) {
      detail::design_derivatives<Policy, decltype(E1)::value, decltype(E2)::value>(seta, states[i], out[i]);
    });
    if (isinf(seta.EA1)) out[i].dFn[2] = out[i].dtheta_joint[2] = T(0);
    if (isinf(seta.EA2)) out[i].dFn[3] = out[i].dtheta_joint[3] = T(0);
  }
  return out;
}

}  // namespace gecko
