// gecko/seta/detail/separatrix_extend.hpp — a followed critical line continued past its stall on
// the separatrix limit system (gecko/seta/detail/separatrix_limit.hpp), target by target.
// Apart from separatrix_limit.hpp so that the natural-state homotopy (detail/natural_state.hpp),
// which the line trace calls, can use the limit system without an include cycle.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "gecko/seta/detail/line_trace.hpp"
#include "gecko/seta/detail/separatrix_arclength.hpp"
#include "gecko/seta/detail/separatrix_limit.hpp"

namespace gecko {
namespace detail {

// The targets from `next` on, beyond a separatrix march that came back over the line's start after
// a fold (march_limit_in_arclength): no critical state on the line (status 2), as beyond a
// followed line that turns back.
template <class T>
inline void beyond_turned_back(const std::vector<std::pair<T, std::size_t>>& targets, std::size_t next,
                               critical_state<T>* out) {
  for (; next < targets.size(); ++next) out[targets[next].second].status = critical_status::no_critical_state;
}

// States at the requested targets (indices `which` into Ft/out, status not_reached) beyond the end
// of a line that stalled or whose corrector failed next to a separatrix: the limit system followed
// in mu from the line's last node, each target's state accepted where separatrix_state_exact holds.
// A line whose corrector failed at its first step (a natural state found on the separatrix,
// detail/natural_state.hpp) is marched from that state, towards its targets.
// march_tol (where above tol): the tolerance of the march's own steps; each target's state is
// solved to tol from the marched one all the same (separatrix_target_state). critical_line_at passes
// the line's corrector tolerance in a type wider than double (the long-double retry of give-ups,
// critical_line.hpp): there a march solved to the state tolerance stalled, or did not start, before
// targets that it now reaches and solves (validation/README.md, "The march at the line's tolerance
// in long double"). In double it passes none: a march at 1e-10 there, tried, lost states that the
// march at 1e-12 solves and left one 3.2e-11 off along the limit system's ill-conditioned direction
// ("Lines that never leave their start, and rounding floors").
// arclength: where the steps in Ft collapse, go on in arclength (detail/separatrix_arclength.hpp);
// critical_line_at asks for it in the long-double retry only.
template <class T, class Policy, bool E1, bool E2>
inline void extend_on_separatrix(const seta_system<T, Policy, E1, E2>& sys,
                                 const traced_line<seta_system<T, Policy, E1, E2>>& line, T scale, const T* Ft,
                                 std::size_t count, const std::size_t* which, T tol, critical_state<T>* out,
                                 T march_tol = T(0), bool arclength = false) {
  using std::fabs;
  using vec = typename seta_system<T, Policy, E1, E2>::vec;
  if (!(line.end == line_end::stalled || line.end == line_end::no_convergence) || line.nodes.empty()) return;
  const auto& last = line.nodes.back();
  const T mu0 = last.Ft;
  // The line must stop at the far end of what it covered (else the targets beyond were passed by
  // another part of it, and the first crossing is not the limit's), except for the march in
  // arclength from inside that range (below).
  T lo = mu0, hi = mu0;
  for (const auto& nd : line.nodes) {
    lo = std::min(lo, nd.Ft);
    hi = std::max(hi, nd.Ft);
  }
  // A line that never left its start goes the way it was followed.
  const T dir = line.nodes.size() == 1 ? T(line.direction) : (mu0 == hi ? T(1) : (mu0 == lo ? T(-1) : T(0)));
  // A line that stopped inside what it covered, after a fold, is continued in arclength from
  // where it stopped, along its own tangent (in the march in arclength only, below): its targets
  // lie beyond the farthest Ft it reached the way it was followed (`from`), and a march that comes
  // back over the line's start has turned back.
  const bool inside = dir == 0;
  if (inside && !(arclength && wider_than_double<T>() && last.branch > 0)) return;
  const T tdir = inside ? T(line.direction) : dir;
  const T from = inside ? (tdir > 0 ? hi : lo) : mu0;
  std::vector<std::pair<T, std::size_t>> targets;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = which[k];
    if (out[i].status != critical_status::not_reached) continue;
    const T mu = line_parameter(sys, Ft[i]);
    if ((mu - from) * tdir > 0) targets.push_back({(mu - from) * tdir, i});
  }
  if (targets.empty()) return;
  std::sort(targets.begin(), targets.end());
  T lengths[2], gaps[2];
  separatrix_measures(sys, last.z, mu0, lengths, gaps);
  const int mask = separatrix_mask(lengths, gaps);
  if (!mask) return;
  int expected[2];
  sys.turning_points(line.plans.back(), last.z, mu0, expected[0], expected[1]);
  separatrix_system<T, Policy, E1, E2> lim{sys, mask};
  vec z = last.z;
  seta_plan plan = lim.plan(z, mu0);
  int its = 0;
  const T mtol = march_tol > tol ? march_tol : tol;
  // Where the limit system does not converge at the line's last node, a type wider than double
  // (the long-double retry, critical_line.hpp) starts the march from a node before it on the same
  // branch, up to five back, and passes the last node on the limit system: in the 10,000-design
  // re-run this solved 23 of the 27 targets given up there (validation/README.md, "Where the
  // give-ups end"). mu_first: where the march starts.
  T mu_first = mu0;
  bool started = solve_separatrix(lim, z, mu0, plan, mtol, its);
  const T along = inside ? (last.tangent[4] > 0 ? T(1) : T(-1)) : dir;  // the line's way at its last node
  if (!started && wider_than_double<T>()) {
    for (std::size_t back = 1; back <= 5 && back < line.nodes.size() && !started; ++back) {
      const auto& node = line.nodes[line.nodes.size() - 1 - back];
      if (node.branch != last.branch || !((mu0 - node.Ft) * along > 0)) break;
      z = node.z;
      mu_first = node.Ft;
      plan = lim.plan(z, mu_first);
      started = solve_separatrix(lim, z, mu_first, plan, mtol, its);
    }
  }
  if (!started) return;
  // March in mu: secant predictor, the step grown after a success and halved after a failure.
  // A state whose ends a path joins stays so: a free rate's sign is kept through its zero, and a
  // step to ends that none joins otherwise has jumped to the limit system's mirror solution and is
  // retried shorter (keep_ends_joined).
  bool joined = limit_ends_joined(lim, z, mu_first);
  std::size_t next = 0;
  if (inside) {
    limit_march<T, Policy, E1, E2> m{lim, z, z, mu_first, mu_first, plan, joined};
    if (march_limit_in_arclength(sys, m, last.tangent, from, tdir, line.nodes.front().Ft, scale, mtol, tol, targets,
                                 next, Ft, expected, out, last.branch))
      beyond_turned_back(targets, next, out);
    return;
  }
  T mu = mu_first, h = T(0.01) * scale;
  vec z_prev = z;
  T mu_prev = mu_first;
  const T h_min = T(1e-9) * scale, h_max = T(0.08) * scale;
  bool collapsed = false;
  for (int step = 0; step < 4000 && next < targets.size(); ++step) {
    const T goal = mu0 + dir * targets[next].first;
    const T mu_try = fabs(goal - mu) <= h ? goal : mu + dir * h;
    if (fabs(mu_try) > sys.mu_limit()) break;
    vec zt = z;
    if (mu != mu_prev) zt += (z - z_prev) * ((mu_try - mu) / (mu - mu_prev));
    seta_plan pt = plan;
    int it = 0;
    const bool ok = solve_separatrix(lim, zt, mu_try, pt, mtol, it) &&
                    lim.step_norm(zt - z, z) <= T(0.5) + 4 * fabs(mu_try - mu) / scale &&
                    (!joined || keep_ends_joined(lim, z, zt, mu_try));
    its += it;
    if (!ok) {
      h /= 2;
      if (h < h_min) {
        collapsed = true;
        break;
      }
      continue;
    }
    z_prev = z;
    mu_prev = mu;
    z = zt;
    mu = mu_try;
    plan = pt;
    h = std::min(h * T(1.5), h_max);
    // A segment that has come next to its separatrix on the way joins the limit ones.
    separatrix_measures(sys, z, mu, lengths, gaps);
    if (grow_limit_segments(lim, lengths, gaps, z, mu, plan, mtol, its, joined) < 0) break;
    while (next < targets.size() && mu == mu0 + dir * targets[next].first) {
      const std::size_t i = targets[next].second;
      critical_state<T> r;
      if (separatrix_target_state(lim, z, mu, Ft[i], tol, expected, its, r)) out[i] = r;
      ++next;
    }
  }
  // Steps in Ft collapsed (a fold of the line in Ft, or a point the limit system cannot be solved
  // at by Newton in Ft): go on in arclength where asked (detail/separatrix_arclength.hpp).
  if (arclength && collapsed && next < targets.size()) {
    limit_march<T, Policy, E1, E2> m{lim, z, z_prev, mu, mu_prev, plan, joined};
    // A march that turned back: the targets beyond its reach have no critical state on the line.
    if (march_limit_in_arclength(sys, m, last.tangent, mu0, dir, line.nodes.front().Ft, scale, mtol, tol, targets,
                                 next, Ft, expected, out))
      beyond_turned_back(targets, next, out);
  }
}

}  // namespace detail
}  // namespace gecko
