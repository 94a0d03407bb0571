// gecko/seta/detail/natural_state.hpp — the natural state at Ft = 0 without a guess.
//
// docs/theory/two_level_seta.md "Critical line of adhesion": homotopy from the small-deformation
// limit (paper 001 eq 18), scaling the angle deficit pi/2 - alpha1 - alpha2 by lambda and w by
// lambda^2 (the linear theory is exact as lambda -> 0), lambda = 0.02 -> 1, each step a Newton
// solve at Ft = 0 from a secant prediction in lambda.
// Where that stalls (a fold of z(lambda), or the path running into the edge of the region the
// forms cover), the same path is followed by pseudo-arclength continuation in (z, lambda)
// (gecko/seta/detail/homotopy_system.hpp), and then other paths to the same design are tried
// (deficit and w scaled at different rates). Any converged end is polished at lambda = 1 by Newton
// with the exact Jacobian at the state tolerance, with the plan checked at the solution
// (solve_with_plans), so it is a root of the design's own equations whatever path led there.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/homotopy_system.hpp"
#include "gecko/seta/solve_critical.hpp"

namespace gecko {
namespace detail {

// The path followed by pseudo-arclength continuation in (z, lambda) from the solved start (z0 at
// lambda0) through folds in lambda to lambda = 1, then polished there (see the header comment).
// converged with (z, plan) set; unsupported_state where the path ran into the edge of the model's
// forms (an axial load comparable to EA); else not_converged.
template <class System>
inline critical_status natural_state_around_folds(const System& sys, const homotopy_path<typename System::value_type>& path,
                                                  const typename System::vec& z0, typename System::value_type lambda0,
                                                  const typename System::plan_type& plan0, typename System::vec& z,
                                                  typename System::plan_type& plan, int& iterations) {
  using T = typename System::value_type;
  using std::fabs;
  T scale = T(1);
  for (int i = 0; i < System::n; ++i) scale = std::max(scale, fabs(z0[i]) / lambda0);
  const homotopy_system<System> hs{sys, path, scale};
  continuation_options<T> copt;
  copt.ft_stop = scale;
  copt.ft_max = std::numeric_limits<T>::infinity();
  copt.scale = scale;
  copt.tolerance = T(1e-10);
  copt.max_nodes = 2000;
  copt.stall_window = 200;
  const traced_line<homotopy_system<System>> line = follow_line(hs, z0, lambda0 * scale, plan0, 1, copt);
  iterations += static_cast<int>(line.nodes.size());
  if (line.end == line_end::unsupported_state) return critical_status::unsupported_state;
  if (line.end != line_end::reached_ft_end) return critical_status::not_converged;
  typename System::vec zn = line.nodes.back().z;
  auto pn = line.plans.back();
  int its = 0;
  const critical_status st = solve_with_plans(sys, zn, T(0), pn, T(1e-12), 40, its);
  iterations += its;
  if (st != critical_status::converged) return critical_status::not_converged;
  z = zn;
  plan = pn;
  return critical_status::converged;
}

// One homotopy path: monotone steps in lambda, then (where they stall) the arclength follower.
template <class System>
inline critical_status natural_state_on_path(const System& sys, const homotopy_path<typename System::value_type>& path,
                                             typename System::vec& z, typename System::plan_type& plan,
                                             int& iterations) {
  using T = typename System::value_type;
  T lam = T(0.02);
  bool started = false;
  critical_status last = critical_status::not_converged;
  for (int attempt = 0; attempt < 4 && !started; ++attempt) {
    const System hs = path.at(sys, lam);
    z = hs.small_deformation_state();
    plan = hs.plan(z, T(0));
    int its = 0;
    last = solve_with_plans(hs, z, T(0), plan, T(1e-12), 40, its);
    started = last == critical_status::converged;
    iterations += its;
    if (!started) lam *= T(0.25);
  }
  if (!started) return last;
  const typename System::vec z_start = z;
  const auto plan_start = plan;
  const T lam_start = lam;
  // As lambda -> 0 the state tends to (Fn, beta, p, q) = (0, pi/2, 0, 0): the previous point of
  // the first secant predictor.
  typename System::vec z_prev = z;
  T lam_prev = 0;
  z_prev.setZero();
  z_prev[1] = seta_pi<T>() / 2;
  T dl = T(0.05);
  while (lam < 1) {
    const T next = lam + dl < 1 ? lam + dl : T(1);
    typename System::vec zn = z + (z - z_prev) * ((next - lam) / (lam - lam_prev));
    const System hs = path.at(sys, next);
    auto pn = hs.plan(zn, T(0));
    int its = 0;
    const critical_status st = solve_with_plans(hs, zn, T(0), pn, T(1e-12), 15, its);
    iterations += its;
    if (st == critical_status::converged && (zn - z).template lpNorm<Eigen::Infinity>() < 1 + 4 * (z - z_prev).template lpNorm<Eigen::Infinity>()) {
      z_prev = z;
      lam_prev = lam;
      z = zn;
      plan = pn;
      lam = next;
      if (its <= 4) dl = dl * T(1.5) < T(0.25) ? dl * T(1.5) : T(0.25);
    } else {
      last = st;
      dl *= T(0.5);
      if (dl < T(1e-5)) {
        const critical_status around =
            natural_state_around_folds(sys, path, z_start, lam_start, plan_start, z, plan, iterations);
        // A path that ran into the edge of the model's forms, in the monotone steps or along the
        // arclength path, leads to a natural state beyond states the model cannot represent, as
        // for a critical line that ends there (status 3 for the Ft beyond,
        // gecko/seta/detail/continuation.hpp).
        return last == critical_status::unsupported_state && around != critical_status::converged ? last : around;
      }
    }
  }
  return critical_status::converged;
}

// The natural state at Ft = 0 by homotopy (see the header comment).
// Returns converged, or why not (unsupported_state when the first path runs into states whose
// axial load reaches EA, outside the model's forms).
template <class System>
inline critical_status natural_state(const System& sys, typename System::vec& z, typename System::plan_type& plan,
                                     int& iterations) {
  using T = typename System::value_type;
  iterations = 0;
  // The paper's path first (deficit and sqrt(w) together); then paths that reach the full w
  // before the full deficit (on the stress campaign's failures these found most of the states the
  // first path missed; the reverse order, w last, found almost none).
  const homotopy_path<T> paths[] = {{1, 1}, {4, 1}, {2, 1}};
  critical_status first = critical_status::not_converged;
  for (int k = 0; k < 3; ++k) {
    const critical_status st = natural_state_on_path(sys, paths[k], z, plan, iterations);
    if (st == critical_status::converged) return st;
    if (k == 0) first = st;
  }
  return first;
}

}  // namespace detail
}  // namespace gecko
