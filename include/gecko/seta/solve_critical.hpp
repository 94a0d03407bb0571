// gecko/seta/solve_critical.hpp — one critical state of the two-level seta by Newton.
//
// docs/theory/two_level_seta.md "Critical line of adhesion": for a given Ft, solve the length equations (with the
// first-integral identities of gecko/seta/critical_residual.hpp) for Fn and beta = theta2(l1),
// from a guess. Newton with the exact Jacobian (dual numbers; R_F's gradient is -R_D/6) and
// affine-invariant damping (gecko/seta/detail/newton.hpp). After convergence the Carlson plan of
// each segment is checked at the solution (turning points, quarter periods) and the solve is
// repeated with a fresh plan when the state has moved out of the old one, so a converged state is
// always measured with the forms that are exact there. Without a guess, the state is found by
// following the critical line from Ft = 0 (gecko/seta/critical_line.hpp).
#pragma once

#include <cmath>
#include <limits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/admissibility.hpp"
#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/detail/newton.hpp"
#include "gecko/seta/detail/plan_at_solution.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/extensibility.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

// What happened to one critical-state solve. 0 means a verified solution that is physically
// admissible (gecko/seta/admissibility.hpp); everything else comes with NaN in Fn and theta_joint,
// except inadmissible (7), which keeps the solved Fn, theta_joint, rates, turning points, min_z,
// max_axial_strain and min_stretch so that the state can be drawn and inspected: it solves paper
// 001 eq (15) but the seta crosses the substrate there, or a segment is compressed to zero length
// or beyond (min_stretch <= 0), or it exceeds the caller's strain limit, so it is no state of a
// real seta.
enum class critical_status : int {
  converged = 0,
  not_converged = 1,      // Newton did not converge from the guess it was given
  no_critical_state = 2,  // the critical line followed from Ft = 0 does not reach this Ft (states off it may exist)
  unsupported_state = 3,  // the state leaves the model (axial load comparable to EA): past the edge of
                          // the forms, or on a followed line past its first state compressed to zero
                          // length (a stretch 1 + T/EA <= 0, gecko/seta/detail/line_trace.hpp)
  singular = 4,           // singular Jacobian: Ft at a fold of the line (use the line instead)
  invalid_input = 5,      // bad input under nan_policy
  not_reached = 6,        // the line followed from Ft = 0 stopped before this Ft without ending
                          // (point budget, step collapse, corrector failure): unknown, not "none"
  inadmissible = 7        // solves the equations, but the deformed seta crosses the substrate
                          // (joint or beam below z = 0) or exceeds the caller's strain limit
};

template <class T>
struct critical_state {
  T Ft = std::numeric_limits<T>::quiet_NaN();
  T Fn = std::numeric_limits<T>::quiet_NaN();
  T theta_joint = std::numeric_limits<T>::quiet_NaN();       // beta = theta2(l1)
  critical_status status = critical_status::not_converged;
  // Evaluations of the equations by the solve: with their Jacobian in Newton's iterations, the
  // residual alone in the chord steps that read a state off a traced line (detail/line_output.hpp).
  int iterations = 0;
  T theta_rate_joint = std::numeric_limits<T>::quiet_NaN();  // theta2'(l1)
  T theta_rate_base = std::numeric_limits<T>::quiet_NaN();   // theta1'(0)
  int turning_points_beam = -1;                               // sign changes of theta' inside
  int turning_points_spatula = -1;
  // Admissibility (gecko/seta/admissibility.hpp), for converged and inadmissible states: the
  // lowest height of the seta above the substrate over [0, a] (0: the contact edge is the lowest
  // point; negative: it crosses the substrate), the arc length s where it is, and the largest
  // axial strain |T|/EA along the seta, and its lowest stretch 1 + T/EA (<= 0: inadmissible). NaN
  // where no state was solved (or the check failed).
  T min_z = std::numeric_limits<T>::quiet_NaN();
  T min_z_at = std::numeric_limits<T>::quiet_NaN();
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();
  T min_stretch = std::numeric_limits<T>::quiet_NaN();
};

// The admissibility check of a solved state (status converged or inadmissible).
template <class T>
inline admissibility_result<T> admissibility_check(const TwoLevelSeta<T>& seta, const critical_state<T>& state,
                                                   T strain_limit = std::numeric_limits<T>::infinity()) {
  if (state.status != critical_status::converged && state.status != critical_status::inadmissible)
    return admissibility_result<T>();
  const seta_pose<T> pose{state.Fn, state.Ft, state.theta_joint, state.theta_rate_base, state.theta_rate_joint,
                          state.turning_points_beam, state.turning_points_spatula,
                          std::numeric_limits<T>::quiet_NaN()};
  return admissibility_check(seta, pose, strain_limit);
}

// A starting point: Fn and beta, optionally the rates (NaN: the monotone branch, rates >= 0).
template <class T>
struct critical_guess {
  T Fn;
  T theta_joint;
  T theta_rate_joint = std::numeric_limits<T>::quiet_NaN();
  T theta_rate_base = std::numeric_limits<T>::quiet_NaN();
};

template <class T>
struct solve_options {
  // Newton stops when the scaled correction (|dFn|/max(1,|Fn|), |dbeta|, rates relative) is
  // below this; the accepted state is then accurate to far better (quadratic convergence).
  T tolerance = T(1e-12);
  int max_iterations = 40;
  // States whose largest axial strain |T|/EA exceeds this are inadmissible (status 7); the default
  // is no limit (the paper's reference design reaches 20 % strain at (Ft)max).
  T strain_limit = std::numeric_limits<T>::infinity();
};

namespace detail {

// Newton at a fixed line parameter mu (Ft, or tau for an extensible spatula: see
// seta_system::forces) with plan refresh (see the header comment). z: the converged state.
template <class System, class T>
inline critical_status solve_with_plans(const System& sys, typename System::vec& z, T Ft,
                                        typename System::plan_type& plan, T tol, int max_iterations,
                                        int& iterations, T omega = T(0)) {
  iterations = 0;
  for (int round = 0; round < 4; ++round) {
    const segment_state st = System::plan_state(plan);
    if (st == segment_state::unsupported) return critical_status::unsupported_state;
    if (st != segment_state::ok) return critical_status::not_converged;
    int its = 0;
    T u14[2] = {1, 1};
    const newton_code code = newton_fixed_ft(sys, z, Ft, plan, tol, max_iterations, its, u14,
                                             round == 0 ? omega : T(0));
    iterations += its;
    if (code == newton_code::singular) return critical_status::singular;
    if (code != newton_code::converged) return critical_status::not_converged;
    if (sys.plan_valid(plan, z, Ft, u14)) return critical_status::converged;
    plan = detail::plan_at_solution(sys, z, Ft);
  }
  return critical_status::not_converged;
}

// Admissibility of a converged state: sets min_z, min_z_at, max_axial_strain, min_stretch, and
// status 7 where the seta crosses the substrate, is compressed to zero length somewhere, or exceeds
// the strain limit (or the check could not be made).
template <class System, class T>
inline void apply_admissibility(const System&, critical_state<T>&) {}

template <class T, class Policy, bool E1, bool E2>
inline void apply_admissibility(const seta_system<T, Policy, E1, E2>& sys, critical_state<T>& r) {
  const seta_pose<T> pose{r.Fn, r.Ft, r.theta_joint, r.theta_rate_base, r.theta_rate_joint,
                          r.turning_points_beam, r.turning_points_spatula, std::numeric_limits<T>::quiet_NaN()};
  const admissibility_result<T> a = admissibility_imp(sys.d, pose, sys.strain_limit);
  r.min_z = a.min_z;
  r.min_z_at = a.where;
  r.max_axial_strain = a.max_axial_strain;
  r.min_stretch = a.min_stretch;
  if (!a.admissible) r.status = critical_status::inadmissible;
}

// turning: the state's turning points (beam, spatula) where the caller has them already
// (System::plan_valid_turning_points), else null.
template <class System, class T>
inline critical_state<T> state_from(const System& sys, const typename System::vec& z, T Ft, T mu,
                                    const typename System::plan_type& plan, critical_status status,
                                    int iterations, const int* turning = nullptr) {
  critical_state<T> r;
  r.Ft = Ft;
  r.status = status;
  r.iterations = iterations;
  if (status == critical_status::converged) {
    r.Fn = z[0];
    r.theta_joint = sys.theta_joint(z);
    r.theta_rate_joint = sys.rate_joint(z);
    r.theta_rate_base = sys.rate_base(z);
    if (turning) {
      r.turning_points_beam = turning[0];
      r.turning_points_spatula = turning[1];
    } else {
      sys.turning_points(plan, z, mu, r.turning_points_beam, r.turning_points_spatula);
    }
    apply_admissibility(sys, r);
  }
  return r;
}

template <class Policy, bool E1, bool E2, class T>
inline critical_state<T> solve_critical_imp(const seta_params<T>& d, T Ft, const critical_guess<T>& g,
                                            const solve_options<T>& opt) {
  const seta_system<T, Policy, E1, E2> sys(d, opt.strain_limit);
  if (!(Ft >= -sys.ftmax)) {  // |Ft| > (Ft)max: Griffith's condition cannot hold at the edge
    critical_state<T> r;
    r.Ft = Ft;
    r.status = critical_status::no_critical_state;
    return r;
  }
  const T mu = sys.mu_of(Ft);
  auto z = sys.from_guess(g.Fn, g.theta_joint, g.theta_rate_joint, g.theta_rate_base, Ft);
  auto plan = sys.plan(z, mu);
  int its = 0;
  const critical_status st = solve_with_plans(sys, z, mu, plan, opt.tolerance, opt.max_iterations, its);
  return state_from(sys, z, Ft, mu, plan, st, its);
}

}  // namespace detail

template <class T, class Policy = policies::default_policy>
inline critical_state<T> solve_critical(const TwoLevelSeta<T>& seta, T Ft, const critical_guess<T>& guess,
                                        const solve_options<T>& options = solve_options<T>(),
                                        const Policy& = Policy()) {
  constexpr const char* fn = "gecko::solve_critical";
  critical_state<T> bad;
  bad.Ft = Ft;
  bad.status = critical_status::invalid_input;
  if (!detail::check_seta<T, Policy>(seta, fn)) return bad;
  if (!detail::check_ft<T, Policy>(Ft, ft_max(seta), fn)) return bad;
  if (!(guess.Fn == guess.Fn) || !(guess.theta_joint == guess.theta_joint)) {
    raise_domain_error<T, Policy>(fn, "guess", guess.Fn == guess.Fn ? guess.theta_joint : guess.Fn,
                                  "finite Fn and theta_joint");
    return bad;
  }
  const auto d = detail::make_seta_params(seta);
  return detail::visit_extensibility(seta, [&](auto E1, auto E2) {
    return detail::solve_critical_imp<Policy, decltype(E1)::value, decltype(E2)::value>(d, Ft, guess, options);
  });
}

}  // namespace gecko
