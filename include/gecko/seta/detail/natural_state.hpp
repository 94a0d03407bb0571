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
// Last, where the first path stalled because a segment lies on its separatrix to double precision
// (a beam tens of saddle time constants long), the separatrix limit system is followed in lambda
// from that stall (natural_state_on_separatrix below), in a type wider than double on by
// arclength where its steps collapse (detail/separatrix_homotopy.hpp). Where every route fails
// and one ran into the edge of the model's forms, the natural state is unsupported (status 3; in
// double only where the first path met it, see natural_state).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/homotopy_system.hpp"
#include "gecko/seta/detail/separatrix_homotopy.hpp"
#include "gecko/seta/detail/separatrix_limit.hpp"
#include "gecko/seta/solve_critical.hpp"

namespace gecko {
namespace detail {

// The line parameter of a homotopy followed in arclength, mu = scale x lambda: the state grows like
// lambda (eq 18), so with scale ~ |z0|/lambda0 a step moves lambda and z alike (homotopy_system).
template <class Vec, class T>
inline T homotopy_scale(const Vec& z0, T lambda0) {
  using std::fabs;
  T scale = T(1);
  for (int i = 0; i < z0.size(); ++i) scale = std::max(scale, fabs(z0[i]) / lambda0);
  return scale;
}

// A homotopy System (homotopy_system, separatrix_homotopy_system) followed by pseudo-arclength from
// z0 at lambda0 to lambda = 1, through folds in lambda.
template <class HomotopySystem>
inline traced_line<HomotopySystem> follow_homotopy(const HomotopySystem& hs, const typename HomotopySystem::vec& z0,
                                                   typename HomotopySystem::value_type lambda0,
                                                   const typename HomotopySystem::plan_type& plan0) {
  using T = typename HomotopySystem::value_type;
  continuation_options<T> copt;
  copt.ft_stop = hs.scale;
  copt.ft_max = std::numeric_limits<T>::infinity();
  copt.scale = hs.scale;
  copt.tolerance = T(1e-10);
  copt.max_nodes = 2000;
  copt.stall_window = 200;
  return follow_line(hs, z0, lambda0 * hs.scale, plan0, 1, copt);
}

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
  const homotopy_system<System> hs{sys, path, homotopy_scale(z0, lambda0)};
  const traced_line<homotopy_system<System>> line = follow_homotopy(hs, z0, lambda0, plan0);
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

// Where a path's monotone steps stalled: the last state solved, at lambda, with its plan.
template <class System>
struct homotopy_stall {
  bool valid = false;
  typename System::vec z;
  typename System::value_type lambda = 0;
  typename System::plan_type plan;
};

// One homotopy path: monotone steps in lambda, then (where they stall) the arclength follower.
// stall, where given, records where the monotone steps stalled.
template <class System>
inline critical_status natural_state_on_path(const System& sys, const homotopy_path<typename System::value_type>& path,
                                             typename System::vec& z, typename System::plan_type& plan,
                                             int& iterations, homotopy_stall<System>* stall = nullptr) {
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
        if (stall) {
          stall->valid = true;
          stall->z = z;
          stall->lambda = lam;
          stall->plan = plan;
        }
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

// The natural state past a path's stall next to a separatrix (the generic System: none).
template <class System>
inline critical_status natural_state_on_separatrix(const System&, const homotopy_path<typename System::value_type>&,
                                                   const homotopy_stall<System>&, typename System::vec&,
                                                   typename System::plan_type&, int&) {
  return critical_status::not_converged;
}

// The limit system's path followed by pseudo-arclength in (z, lambda) from its state zc at lambda
// (where the monotone steps in lambda collapsed) to lambda = 1, as natural_state_around_folds
// follows the full system's (detail/separatrix_homotopy.hpp). converged with zc the state at
// lambda = 1; unsupported_state where the path runs into the edge of the model's forms (an axial
// load comparable to EA, follow_line's line_end::unsupported_state); else not_converged.
template <class T, class Policy, bool E1, bool E2>
inline critical_status limit_path_around_folds(const seta_system<T, Policy, E1, E2>& sys, const homotopy_path<T>& path,
                                               int mask, typename seta_system<T, Policy, E1, E2>::vec& zc, T lambda,
                                               int& iterations) {
  const separatrix_homotopy_system<T, Policy, E1, E2> hs{sys, path, homotopy_scale(zc, lambda), mask};
  const auto line = follow_homotopy(hs, zc, lambda, hs.plan(zc, lambda * hs.scale));
  iterations += static_cast<int>(line.nodes.size());
  if (line.end == line_end::unsupported_state) return critical_status::unsupported_state;
  if (line.end != line_end::reached_ft_end) return critical_status::not_converged;
  zc = line.nodes.back().z;
  return critical_status::converged;
}

// The seta: where the monotone steps stalled with a segment many saddle time constants long on its
// separatrix (separatrix_measures, separatrix_mask: the stall of a followed critical line, met on
// the way to the natural state; validation/README.md, "Where the status-1 give-ups come from"),
// the separatrix limit system (detail/separatrix_limit.hpp) is followed in lambda to the design,
// as extend_on_separatrix follows it in Ft, and its state at lambda = 1, Ft = 0 is corrected to
// the exact one and certified by separatrix_target_state (the turning points within one of the
// stall's). Kept only where the design's own plan at that state gives the same turning points.
template <class T, class Policy, bool E1, bool E2>
inline critical_status natural_state_on_separatrix(const seta_system<T, Policy, E1, E2>& sys,
                                                   const homotopy_path<T>& path,
                                                   const homotopy_stall<seta_system<T, Policy, E1, E2>>& stall,
                                                   typename seta_system<T, Policy, E1, E2>::vec& z, seta_plan& plan,
                                                   int& iterations) {
  constexpr critical_status failed = critical_status::not_converged;
  using std::fabs;
  using Sys = seta_system<T, Policy, E1, E2>;
  using Lim = separatrix_system<T, Policy, E1, E2>;
  using vec = typename Sys::vec;
  if (!stall.valid) return failed;
  const T tol = T(1e-12);
  T lengths[2], gaps[2];
  int expected[2];
  int mask;
  bool joined;  // as in extend_on_separatrix: the ends stay joined (keep_ends_joined)
  vec zc = stall.z;
  {
    const Sys hs = path.at(sys, stall.lambda);
    separatrix_measures(hs, zc, T(0), lengths, gaps);
    mask = separatrix_mask(lengths, gaps);
    if (!mask) return failed;
    hs.turning_points(stall.plan, zc, T(0), expected[0], expected[1]);
    const Lim lim{hs, mask};
    seta_plan p = lim.plan(zc, T(0));
    if (!solve_separatrix(lim, zc, T(0), p, tol, iterations)) return failed;
    joined = limit_ends_joined(lim, zc, T(0));
  }
  // March in lambda: secant predictor, the step grown after a success and halved after a failure;
  // the state grows about like lambda (eq 18), so a step may move it by about its relative share.
  T lam = stall.lambda, lam_prev = stall.lambda, h = T(0.01);
  vec z_prev = zc;
  for (int step = 0; step < 4000 && lam < 1; ++step) {
    const T lt = lam + h < 1 ? lam + h : T(1);
    vec zt = zc;
    if (lam != lam_prev) zt += (zc - z_prev) * ((lt - lam) / (lam - lam_prev));
    const Sys ht = path.at(sys, lt);
    const Lim lim{ht, mask};
    seta_plan pt = lim.plan(zt, T(0));
    int its = 0;
    const bool ok = solve_separatrix(lim, zt, T(0), pt, tol, its) &&
                    lim.step_norm(zt - zc, zc) <= T(0.5) + 4 * (lt - lam) / lam &&
                    (!joined || keep_ends_joined(lim, zc, zt, T(0)));
    iterations += its;
    if (!ok) {
      h /= 2;
      if (h < T(1e-9)) {
        // The steps in lambda collapsed (a fold of the path in lambda, or a point Newton in
        // lambda cannot pass): go on by arclength in (z, lambda) to lambda = 1.
        // Only in a type wider than double, as the march in Ft (critical_line.hpp): only the
        // long-double retry of give-ups goes on, so no state solved in double changes.
        if (!wider_than_double<T>()) return failed;
        const critical_status around = limit_path_around_folds(sys, path, mask, zc, lam, iterations);
        if (around != critical_status::converged) return around;
        lam = 1;
        break;
      }
      continue;
    }
    z_prev = zc;
    lam_prev = lam;
    zc = zt;
    lam = lt;
    h = std::min(h * T(1.5), T(0.08));
    // a segment that has come next to its separatrix on the way joins the limit ones
    separatrix_measures(ht, zc, T(0), lengths, gaps);
    const int grown = mask | separatrix_mask(lengths, gaps);
    if (grown != mask || !joined) joined = limit_ends_joined(Lim{ht, grown}, zc, T(0));  // else kept joined
    mask = grown;
  }
  if (lam < 1) return failed;
  critical_state<T> r;
  vec zs;
  if (!separatrix_target_state(Lim{sys, mask}, zc, T(0), T(0), tol, expected, iterations, r, &zs)) return failed;
  seta_plan full = plan_at_solution(sys, zs, T(0));
  int tb, ts;
  sys.turning_points(full, zs, T(0), tb, ts);
  if (tb != r.turning_points_beam || ts != r.turning_points_spatula) return failed;
  z = zs;
  plan = full;
  return critical_status::converged;
}

// The natural state at Ft = 0 by homotopy (see the header comment).
// Returns converged, or why not (unsupported_state when the first path runs into states whose
// axial load reaches EA, outside the model's forms; in a type wider than double, also where every
// route failed and one of them ran into that edge).
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
  bool edge = false;  // a route ran into the edge of the model's forms
  homotopy_stall<System> stall;
  for (int k = 0; k < 3; ++k) {
    const critical_status st = natural_state_on_path(sys, paths[k], z, plan, iterations, k == 0 ? &stall : nullptr);
    if (st == critical_status::converged) return st;
    if (k == 0) first = st;
    edge = edge || st == critical_status::unsupported_state;
  }
  // Last, past the first path's stall on the separatrix limit (the seta only; it goes on past a
  // collapse of its steps in a wider type only, and may meet the edge there).
  const critical_status limit = natural_state_on_separatrix(sys, paths[0], stall, z, plan, iterations);
  if (limit == critical_status::converged || limit == critical_status::unsupported_state) return limit;
  // Every route failed and one ran into the edge (an axial load comparable to EA), the others
  // turning back or stalling before it: the natural state, as far as the homotopies reach it, lies
  // beyond what the model represents (status 3, as where the first path meets the edge). Only in a
  // type wider than double: a double give-up stays status 1, so the long-double retry of give-ups
  // (critical_line.hpp) runs and decides, and no state it solved before changes (validation/README.md,
  // "Where the give-ups end, and natural states at the edge of the forms").
  if (edge && wider_than_double<T>())
    return critical_status::unsupported_state;
  return first;
}

}  // namespace detail
}  // namespace gecko
