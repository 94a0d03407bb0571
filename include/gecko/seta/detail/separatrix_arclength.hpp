// gecko/seta/detail/separatrix_arclength.hpp — the separatrix march continued in arclength where
// its steps in Ft collapse.
//
// The march in Ft (detail/separatrix_extend.hpp) solves the limit system
// (detail/separatrix_limit.hpp) at each Ft, so it cannot pass a fold of the line in Ft: there the
// limit system's Jacobian in the state is singular, and beyond it no state exists at that Ft on the
// followed branch. Where its step falls below its floor, the march goes on by pseudo-arclength on
// the same limit system (tangent_at and arclength_corrector of detail/continuation.hpp, as the
// followed line does), through folds. A target is the line's first crossing of its Ft, as for the
// followed line (detail/line_output.hpp): it is taken where the march passes beyond all the Ft it
// has reached before. A march that comes back over the line's start after a fold has turned back,
// as a followed line can (line_end::turned_back), and stops there: the targets it has not reached
// then have no critical state on the line (status 2), as beyond a followed line that turned back.
// validation/folds.py checks the folds behind a sample of such claims in arbitrary precision (the
// line's own states short of the fold confirmed by the bracketing shot, their square-root law, and
// the partner root it predicts on the returning branch; validation/README.md, "Targets past a
// turned-back march").
// Only the long-double retry of give-ups marches in arclength (critical_line.hpp). Run in double,
// it reached states that the retry had reached before on another path: campaign design 162 has two
// critical states at Ft = 1250.04, 0.78 % apart in Fn, with theta1'(0) of opposite signs and 2 or 1
// beam turning points, both confirmed by the bracketing shot in arbitrary precision; the line
// followed by the full system alone in long double stalls at Ft = 792.3 with theta1'(0) -> 0, so
// which of the two the line reaches is not settled (validation/README.md, "The separatrix march in
// arclength"). In the retry alone, every state solved before stays as it was.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "gecko/seta/critical_line_types.hpp"
#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/separatrix_limit.hpp"

namespace gecko {
namespace detail {

// Where the march in Ft stopped: the last state (z, mu), the state before it (z_prev, mu_prev; the
// same where no step was taken), their plan and mask, and whether its ends were joined.
template <class T, class Policy, bool E1, bool E2>
struct limit_march {
  using vec = typename seta_system<T, Policy, E1, E2>::vec;
  separatrix_system<T, Policy, E1, E2>& lim;
  vec z, z_prev;
  T mu, mu_prev;
  seta_plan plan;
  bool joined;
  int iterations = 0;
};

// The limit system corrected by arclength from the predictor x (plan carried from the last state;
// where that fails or no longer holds, the plan at the predictor or at the solution). False where
// no plan gives a state.
template <class T, class Policy, bool E1, bool E2>
inline bool correct_limit_state(const separatrix_system<T, Policy, E1, E2>& lim, Eigen::Matrix<T, 5, 1>& x,
                                const Eigen::Matrix<T, 5, 1>& t, seta_plan& plan, T tol, T scale, int& iterations) {
  using base = seta_system<T, Policy, E1, E2>;
  const Eigen::Matrix<T, 5, 1> xp = x;
  for (int round = 0; round < 3; ++round) {
    if (base::plan_state(plan) != segment_state::ok) return false;
    x = xp;
    int its = 0;
    T u14[2] = {1, 1};
    T omega = 0;
    const bool ok = arclength_corrector(lim, x, t, plan, tol, scale, its, u14, omega);
    iterations += its;
    if (ok && lim.plan_valid(plan, x.template head<4>().eval(), x[4], u14)) return true;
    // Converged under a plan that no longer holds: plan at the solution. Not converged: plan at
    // the predictor (the carried plan may not reach it).
    plan = ok ? lim.plan(x.template head<4>().eval(), x[4]) : lim.plan(xp.template head<4>().eval(), xp[4]);
  }
  return false;
}

// The march from m onward by arclength. targets: (distance in mu from mu0 along dir, index into
// Ft/out), sorted, those from `next` on not yet taken; mu_start: the line's start (its natural
// state), where a march that turned back stops; line_tangent: the followed line's last tangent,
// the direction where the march in Ft took no step. Each target crossed beyond the reach so far is
// solved at its Ft from the chord between the two states around it and accepted where
// separatrix_target_state holds. True where the march turned back: the targets from `next` on are
// beyond the line (the caller gives them status 2). folds0 > 0: the line had passed that many
// folds and stopped inside what it covered; the march goes on along line_tangent as it is oriented
// (the line's own way, which may lead back towards its start), and the reach so far is mu0.
template <class T, class Policy, bool E1, bool E2>
inline bool march_limit_in_arclength(const seta_system<T, Policy, E1, E2>& sys, limit_march<T, Policy, E1, E2>& m,
                                     const Eigen::Matrix<T, 5, 1>& line_tangent, T mu0, T dir, T mu_start, T scale,
                                     T mtol, T tol, const std::vector<std::pair<T, std::size_t>>& targets,
                                     std::size_t& next, const T* Ft, const int expected[2], critical_state<T>* out,
                                     int folds0 = 0) {
  using std::fabs;
  using vec = typename seta_system<T, Policy, E1, E2>::vec;
  using xvec = Eigen::Matrix<T, 5, 1>;
  auto& lim = m.lim;
  xvec x, t_prev, t;
  x.template head<4>() = m.z;
  x[4] = m.mu;
  t_prev.template head<4>() = m.z - m.z_prev;
  t_prev[4] = m.mu - m.mu_prev;
  if (folds0 > 0) t_prev = line_tangent;
  else if (!(t_prev[4] * dir > 0)) t_prev = line_tangent * (line_tangent[4] * dir < 0 ? T(-1) : T(1));
  t_prev.normalize();
  if (!t_prev.allFinite() || !tangent_at(lim, m.z, m.mu, m.plan, t_prev, t)) return false;
  const T ds_min = T(1e-9) * scale, ds_max = T(0.04) * scale;
  T ds = T(1e-3) * scale;
  T reach = folds0 > 0 ? mu0 : m.mu;  // the farthest mu along dir that the line has reached
  int folds = folds0;
  for (int step = 0; step < 4000 && next < targets.size(); ++step) {
    xvec xc = x + ds * t;
    seta_plan pc = m.plan;
    bool ok = correct_limit_state(lim, xc, t, pc, mtol, scale, m.iterations) && (xc - x).norm() <= 3 * ds &&
              fabs(xc[4]) <= sys.mu_limit();
    vec zc = xc.template head<4>();
    if (ok && m.joined) {
      ok = keep_ends_joined(lim, m.z, zc, xc[4]);
      xc.template head<4>() = zc;
    }
    xvec tn;
    ok = ok && tangent_at(lim, zc, xc[4], pc, t, tn);
    if (!ok) {
      ds /= 2;
      if (ds < ds_min) return false;
      continue;
    }
    if (tn[4] * t[4] < 0) ++folds;
    const vec za = x.template head<4>();
    const T mua = x[4];
    x = xc;
    t = tn;
    m.z_prev = m.z;
    m.mu_prev = m.mu;
    m.z = zc;
    m.mu = xc[4];
    m.plan = pc;
    ds = std::min(ds * T(1.5), ds_max);
    // A limit segment no longer long is no longer on its separatrix to O(e^-10): the limit
    // system stops describing the line, and the march stops. A segment that has come next to its
    // separatrix joins the limit ones (as in the march in Ft).
    T lengths[2], gaps[2];
    separatrix_measures(sys, m.z, m.mu, lengths, gaps);
    for (int k = 0; k < 2; ++k)
      if ((lim.mask >> k & 1) && !(lengths[k] >= T(separatrix_long_segment))) return false;
    const int grew = grow_limit_segments(lim, lengths, gaps, m.z, m.mu, m.plan, mtol, m.iterations, m.joined);
    if (grew < 0) return false;
    if (grew > 0) {
      x.template head<4>() = m.z;
      if (!tangent_at(lim, m.z, m.mu, m.plan, t, tn)) return false;
      t = tn;
    }
    // Back over the line's start after a fold: the line has turned back (detail/continuation.hpp,
    // the same test as the followed line's), and the march stops.
    if (folds > 0 && (m.mu - mu_start) * dir < -T(1e-3) * scale) return true;
    if (!((m.mu - reach) * dir > 0)) continue;
    // Targets first crossed on this step: between the reach and the new state (the step starts at
    // or short of the reach, so its mu changed), from the chord between its ends.
    while (next < targets.size() && (mu0 + dir * targets[next].first - m.mu) * dir <= 0) {
      const T goal = mu0 + dir * targets[next].first;
      const std::size_t i = targets[next].second;
      const vec chord = za + (m.z - za) * ((goal - mua) / (m.mu - mua));
      vec zg = chord;
      seta_plan pg = m.plan;
      bool solved = solve_separatrix(lim, zg, goal, pg, mtol, m.iterations);
      if (!solved) {
        zg = chord;
        pg = lim.plan(zg, goal);
        solved = solve_separatrix(lim, zg, goal, pg, mtol, m.iterations);
      }
      critical_state<T> r;
      if (solved && separatrix_target_state(lim, zg, goal, Ft[i], tol, expected, m.iterations, r)) out[i] = r;
      ++next;
    }
    reach = m.mu;
  }
  return false;
}

}  // namespace detail
}  // namespace gecko
