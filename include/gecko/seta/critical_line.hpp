// gecko/seta/critical_line.hpp — the critical line of adhesion of the two-level seta.
//
// docs/theory/two_level_seta.md "Critical line of adhesion": the curve of critical (Fn, Ft), followed from the
// natural state at Ft = 0 by pseudo-arclength continuation (gecko/seta/detail/continuation.hpp)
// through folds, up to (Ft)max = sqrt(2 EA2 w) or to where it ends (reported in `end`).
// The natural state needs no guess: it is reached by homotopy from the small-deformation limit
// (docs/theory/two_level_seta.md, paper 001 eq 18), scaling the angle deficit pi/2 - alpha1 - alpha2 by lambda and w by
// lambda^2 (the linear theory is exact as lambda -> 0), lambda = 0.02 -> 1.
// critical_line_at gives the line at requested Ft values: the first crossing of each Ft along
// the line from Ft = 0 (negative Ft: along the line followed from Ft = 0 towards negative Ft),
// each re-solved by Newton at that Ft to full accuracy from a cubic Hermite guess.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/extensibility.hpp"
#include "gecko/seta/solve_critical.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

template <class T>
struct critical_line_options {
  // End of the followed range. NaN: (Ft)max for finite EA2, else 3 sqrt(EI1 w)/l1 (an arbitrary
  // but stated scale: the inextensible line has no (Ft)max). Negative: follow towards negative Ft.
  T ft_end = std::numeric_limits<T>::quiet_NaN();
  // Newton tolerance of the states at requested Ft values: a state is accepted when the scaled
  // correction (|dFn|/max(1,|Fn|), |dbeta|, rates relative) is below it, or when the
  // Newton-Kantorovich bound omega/2 |dz|^2 of the error after the first step is (omega estimated
  // by the continuation; gecko/seta/detail/newton.hpp).
  T tolerance = T(1e-12);
  T line_tolerance = T(1e-10);  // corrector tolerance of the traced nodes
  int max_points = 100000;
  // critical_line(): re-solve every traced node to `tolerance` before returning it (a node is a
  // predictor-corrector point accepted at line_tolerance, and near form boundaries, where the
  // Jacobian is ill-conditioned, that step test let errors of ~1e-8 through). Costs about one
  // Jacobian evaluation per node; false returns the raw nodes with status not_converged (all but
  // the natural state).
  bool resolve_nodes = true;
  // States whose largest axial strain |T|/EA exceeds this are inadmissible (status 7, see
  // gecko/seta/admissibility.hpp); the default is no limit (the paper's reference design reaches
  // 20 % strain at (Ft)max).
  T strain_limit = std::numeric_limits<T>::infinity();
};

template <class T>
struct critical_line_point {
  T Ft, Fn, theta_joint, theta_rate_joint, theta_rate_base;
  int turning_points_beam, turning_points_spatula;
  int branch;  // folds passed since Ft = 0
  // converged: re-solved to critical_line_options::tolerance (or the natural state, or the
  // landed end of the line). not_converged: the node could not be re-solved; its values are the
  // continuation's, accurate to about line_tolerance only, and kept so the line can be drawn.
  // inadmissible: a re-solved node where the seta crosses the substrate (or exceeds the strain
  // limit); its values are kept so the line can be drawn.
  critical_status status;
  // Admissibility of converged and inadmissible nodes (see critical_state); NaN otherwise.
  T min_z = std::numeric_limits<T>::quiet_NaN();
  T min_z_at = std::numeric_limits<T>::quiet_NaN();
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();
};

template <class T>
struct critical_line_result {
  std::vector<critical_line_point<T>> points;  // the traced nodes, in order along the line
  std::vector<T> folds;                        // Ft at each fold (dFt/ds = 0)
  line_end end = line_end::reached_ft_end;
  critical_state<T> natural;                   // the natural state at Ft = 0
};

namespace detail {

template <class T>
inline T default_ft_end(const TwoLevelSeta<T>& s) {
  using std::isinf; using std::sqrt;
  return isinf(s.EA2) ? 3 * sqrt(s.EI1 * s.w) / s.l1 : ft_max(s);
}

// The natural state at Ft = 0 by homotopy (see the header comment).
// Returns converged, or why not (unsupported_state when the homotopy runs into states whose
// axial load reaches EA, outside the model's forms).
template <class System>
inline critical_status natural_state(const System& sys, typename System::vec& z, typename System::plan_type& plan,
                                     int& iterations) {
  using T = typename System::value_type;
  iterations = 0;
  T lam = T(0.02);
  bool started = false;
  critical_status last = critical_status::not_converged;
  for (int attempt = 0; attempt < 4 && !started; ++attempt) {
    const System hs = sys.at_homotopy(lam);
    z = hs.small_deformation_state();
    plan = hs.plan(z, T(0));
    int its = 0;
    last = solve_with_plans(hs, z, T(0), plan, T(1e-12), 40, its);
    started = last == critical_status::converged;
    iterations += its;
    if (!started) lam *= T(0.25);
  }
  if (!started) return last;
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
    const System hs = sys.at_homotopy(next);
    auto pn = hs.plan(zn, T(0));
    int its = 0;
    const critical_status st = solve_with_plans(hs, zn, T(0), pn, T(1e-12), 15, its);
    iterations += its;
#ifdef GECKO_SETA_DEBUG
    std::fprintf(stderr, "homotopy lam %g -> %g st %d its %d\n", double(lam), double(next), int(st), its);
#endif
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
      if (dl < T(1e-5))
        return last == critical_status::unsupported_state ? last : critical_status::not_converged;
    }
  }
  return critical_status::converged;
}

template <class System, class T>
inline critical_line_point<T> line_point(const System& sys, const line_node<T, System::n>& node,
                                         const typename System::plan_type& plan, critical_status status) {
  critical_line_point<T> p;
  p.status = status;
  p.Ft = sys.ft_of(node.Ft);  // node.Ft holds the line parameter mu
  p.Fn = node.z[0];
  p.theta_joint = sys.theta_joint(node.z);
  p.theta_rate_joint = sys.rate_joint(node.z);
  p.theta_rate_base = sys.rate_base(node.z);
  sys.turning_points(plan, node.z, node.Ft, p.turning_points_beam, p.turning_points_spatula);
  p.branch = node.branch;
  if (status == critical_status::converged) {
    critical_state<T> st;
    st.Fn = p.Fn;
    st.Ft = p.Ft;
    st.theta_joint = p.theta_joint;
    st.theta_rate_joint = p.theta_rate_joint;
    st.theta_rate_base = p.theta_rate_base;
    st.turning_points_beam = p.turning_points_beam;
    st.turning_points_spatula = p.turning_points_spatula;
    st.status = status;
    apply_admissibility(sys, st);
    p.status = st.status;
    p.min_z = st.min_z;
    p.min_z_at = st.min_z_at;
    p.max_axial_strain = st.max_axial_strain;
  }
  return p;
}

// The line parameter of the end of a followed range, with |Ft| within rounding of (Ft)max mapped
// to the line's end. (Ft)max has two roundings: sqrt(2 EA2 w) (ft_max, the validation and the
// default end) and the System's sqrt(2 w / (1/EA2)); they differ by an ulp in ~7% of designs.
// Taken literally, a default end an ulp below sys.ftmax stopped the line ~sqrt(2 eps) (Ft)max
// short of its end in mu (labelled reached_ft_end, Fn there off by ~1e-7 from the line's end).
template <class System, class T>
inline T line_parameter(const System& sys, T Ft) {
  using std::fabs;
  if (fabs(Ft) >= sys.ftmax * (1 - 4 * std::numeric_limits<T>::epsilon()))
    return Ft > 0 ? sys.mu_limit() : -sys.mu_limit();
  return sys.mu_of(Ft);
}

// Natural state + the followed line in one direction, up to Ft = ft_stop. outputs: how many
// states will be read off the line; many outputs make denser nodes pay (better Hermite guesses,
// one Newton step per output).
template <class System, class T>
inline bool trace(const System& sys, T ft_stop, T scale, const critical_line_options<T>& opt, std::size_t outputs,
                  typename System::vec& z0, typename System::plan_type& plan0, critical_state<T>& natural,
                  traced_line<System>& line) {
  int its = 0;
  const critical_status nat = natural_state(sys, z0, plan0, its);
  if (nat != critical_status::converged) {
    natural.status = nat;
    line.end = nat == critical_status::unsupported_state ? line_end::unsupported_state : line_end::no_natural_state;
    return false;
  }
  natural = state_from(sys, z0, T(0), T(0), plan0, critical_status::converged, its);
  if (ft_stop == 0) {
    line.nodes.push_back({z0, T(0), Eigen::Matrix<T, System::n + 1, 1>::Zero(), 0});
    line.plans.push_back(plan0);
    line.end = line_end::reached_ft_end;
    return true;
  }
  continuation_options<T> copt;
  using std::fabs;
  copt.ft_max = sys.mu_limit();
  copt.ft_stop = line_parameter(sys, ft_stop);
  copt.scale = scale;
  copt.tolerance = opt.line_tolerance;
  copt.max_nodes = opt.max_points;
  // About one node per 30 outputs (measured best on the reference scene: the cubic Hermite
  // guesses then take one Newton step), between 1/100 and 8/100 of the range per step.
  const T per_output = T(30) / static_cast<T>(outputs > 0 ? outputs : 1);
  copt.max_step = per_output < T(0.01) ? T(0.01) : (per_output > T(0.08) ? T(0.08) : per_output);
  line = follow_line(sys, z0, T(0), plan0, ft_stop > 0 ? 1 : -1, copt);
  return true;
}

// Is node k the landed end of the line? That node was accepted by the landing's own checks (at
// (Ft)max the Newton step has a rounding floor above a tight tolerance, see follow_line), so it is
// a state even where a re-solve at the state tolerance fails. Only the landed end: an interior
// node is a predictor-corrector point at the line tolerance, and a failed re-solve there must
// stay a failure.
template <class System>
inline bool is_landed_end(const traced_line<System>& line, std::size_t k) {
  return (line.end == line_end::reached_ft_max || line.end == line_end::reached_ft_end) &&
         k + 1 == line.nodes.size();
}

// Evaluate a traced line at Ft values (first crossing along the line).
template <class System, class T>
inline void evaluate_line(const System& sys, const traced_line<System>& line, const T* Ft, std::size_t count,
                          const std::size_t* which, T tol, critical_state<T>* out) {
  constexpr int n = System::n;
  // The line is continuous, so the first crossing of a target lies in the first segment at whose
  // end the running range [min, max] of the parameter over the nodes so far covers it; the
  // running ranges only grow, so that segment is found by binary search.
  const auto& all = line.nodes;
  // A target the line never reached has no critical state only where the line really ended
  // (the requested end, (Ft)max, or back below its start after a fold); where it was given up
  // the state is unknown, and says so.
  critical_status beyond = critical_status::no_critical_state;
  if (line.end == line_end::unsupported_state) beyond = critical_status::unsupported_state;
  else if (line.end == line_end::no_convergence || line.end == line_end::max_points || line.end == line_end::stalled)
    beyond = critical_status::not_reached;
  std::vector<T> run_lo(all.size()), run_hi(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    run_lo[i] = i ? std::min(run_lo[i - 1], all[i].Ft) : all[i].Ft;
    run_hi[i] = i ? std::max(run_hi[i - 1], all[i].Ft) : all[i].Ft;
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t idx = which[k];
    critical_state<T> r;
    r.Ft = Ft[idx];
    r.status = critical_status::no_critical_state;
    const T slack = sys.ftmax * (1 + 4 * std::numeric_limits<T>::epsilon());
    if (!(Ft[idx] >= -slack && Ft[idx] <= slack)) {
      out[idx] = r;
      continue;
    }
    // Validation admits Ft up to ft_max = sqrt(2 EA2 w), which may lie an ulp above the System's
    // rounding of (Ft)max: such an Ft is the line's end. Below it Ft is taken literally (near the
    // end Fn ~ sqrt((Ft)max - Ft): an ulp of Ft is worth ~1e-7 in Fn, tests/seta/near_singular.cpp).
    const T target = std::fabs(Ft[idx]) >= sys.ftmax ? (Ft[idx] > 0 ? sys.mu_limit() : -sys.mu_limit())
                                                     : sys.mu_of(Ft[idx]);
    const auto& nodes = line.nodes;
    std::size_t first = 0;
    if (nodes.size() > 1) {
      std::size_t lo = 0, hi = nodes.size() - 1;  // smallest j with target in the running range at j
      if (!(target >= run_lo[hi] && target <= run_hi[hi])) {
        r.status = beyond;
        out[idx] = r;
        continue;
      }
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (target >= run_lo[mid] && target <= run_hi[mid]) hi = mid;
        else lo = mid + 1;
      }
      first = lo > 0 ? lo - 1 : 0;
    }
    for (std::size_t i = first; i + 1 < nodes.size() || (nodes.size() == 1 && i == 0); ++i) {
      if (nodes.size() == 1) {
        if (nodes[0].Ft == target) r = state_from(sys, nodes[0].z, Ft[idx], target, line.plans[0], critical_status::converged, 0);
        else r.status = beyond;
        break;
      }
      const T a = nodes[i].Ft - target, b = nodes[i + 1].Ft - target;
      if (a != 0 && b != 0 && ((a < 0) == (b < 0))) continue;
      Eigen::Matrix<T, n, 1> z;
      if (!hermite_guess(nodes[i], nodes[i + 1], target, z)) z = nodes[i].z;
      using std::fabs;
      auto plan = fabs(a) <= fabs(b) ? line.plans[i] : line.plans[i + 1];
      int its = 0;
      // omega: the line's Lipschitz estimate with a safety factor of 4 (early acceptance of the
      // first Newton step, see newton_fixed_ft); 0 when the line gave none.
      critical_status st = solve_with_plans(sys, z, target, plan, tol, 40, its, 4 * line.omega);
      if (st != critical_status::converged) {
        // Second chance: plan from the guess itself (the state may sit between two plans).
        Eigen::Matrix<T, n, 1> z2;
        if (!hermite_guess(nodes[i], nodes[i + 1], target, z2)) z2 = nodes[i].z;
        auto plan2 = sys.plan(z2, target);
        int its2 = 0;
        st = solve_with_plans(sys, z2, target, plan2, tol, 40, its2);
        its += its2;
        z = z2;
        plan = plan2;
      }
      // A Newton solution far from the line would be another branch: report, do not accept.
      if (st == critical_status::converged) {
        const T gap = std::min((z - nodes[i].z).template lpNorm<Eigen::Infinity>(),
                               (z - nodes[i + 1].z).template lpNorm<Eigen::Infinity>());
        const T span = (nodes[i + 1].z - nodes[i].z).template lpNorm<Eigen::Infinity>() + fabs(nodes[i + 1].Ft - nodes[i].Ft);
        if (gap > 2 * span + T(1e-8)) st = critical_status::not_converged;
      }
      // The target is exactly the landed end of the line: that node is the state. (The end is
      // always the later node of a segment here, since i + 1 < nodes.size().)
      if (st != critical_status::converged && b == 0 && is_landed_end(line, i + 1)) {
        z = nodes[i + 1].z;
        plan = line.plans[i + 1];
        st = critical_status::converged;
      }
      r = state_from(sys, z, Ft[idx], target, plan, st, its);
      break;
    }
    out[idx] = r;
  }
}

// Re-solve traced node i to tol (see critical_line_options::resolve_nodes). First by Newton at
// the node's own line parameter; at a fold that Jacobian is singular (dmu/ds = 0), so then by the
// bordered arclength corrector, which moves the node orthogonally to the line's tangent. A
// re-solved state more than 1e-6 (scaled) from the node is not accepted: the node itself is
// within ~1e-8 of the line, so such a state is the other branch near a fold.
template <class System, class T>
inline critical_status resolve_node(const System& sys, const traced_line<System>& line, std::size_t i, T scale,
                                    T tol, line_node<T, System::n>& node, typename System::plan_type& plan) {
  constexpr int n = System::n;
  using std::fabs;
  const auto& orig = line.nodes[i];
  const T max_move = T(1e-6);
  {
    typename System::vec z = orig.z;
    auto p = line.plans[i];
    int its = 0;
    if (solve_with_plans(sys, z, orig.Ft, p, tol, 40, its) == critical_status::converged &&
        sys.step_norm(z - orig.z, orig.z) <= max_move) {
      node.z = z;
      plan = p;
      return critical_status::converged;
    }
  }
  {
    Eigen::Matrix<T, n + 1, 1> x;
    x.template head<n>() = orig.z;
    x[n] = orig.Ft;
    auto p = line.plans[i];
    int its = 0;
    T u14[2] = {1, 1};
    T omega = 0;
    if (arclength_corrector(sys, x, orig.tangent, p, tol, scale, its, u14, omega) &&
        sys.plan_valid(p, x.template head<n>(), x[n], u14) && fabs(x[n]) <= sys.mu_limit() &&
        sys.step_norm(x.template head<n>() - orig.z, orig.z) <= max_move &&
        fabs(x[n] - orig.Ft) <= max_move * scale) {
      node.z = x.template head<n>();
      node.Ft = x[n];
      plan = p;
      return critical_status::converged;
    }
  }
  return is_landed_end(line, i) ? critical_status::converged : critical_status::not_converged;
}

template <class Policy, bool E1, bool E2, class T>
inline critical_line_result<T> critical_line_imp(const TwoLevelSeta<T>& s, const critical_line_options<T>& opt) {
  using System = seta_system<T, Policy, E1, E2>;
  const System sys(make_seta_params(s), opt.strain_limit);
  const T end = opt.ft_end == opt.ft_end ? opt.ft_end : default_ft_end(s);
  using std::fabs; using std::sqrt;
  const T scale = std::max(fabs(end), sqrt(s.EI1 * s.w) / s.l1);
  typename System::vec z0;
  typename System::plan_type plan0;
  critical_line_result<T> r;
  traced_line<System> line;
  trace(sys, end, scale, opt, 0, z0, plan0, r.natural, line);
  r.end = line.end;
  for (T f : line.folds) r.folds.push_back(sys.ft_of(f));
  for (std::size_t i = 0; i < line.nodes.size(); ++i) {
    // Node 0 is the natural state, solved to 1e-12 by natural_state.
    if (i == 0) {
      r.points.push_back(line_point(sys, line.nodes[0], line.plans[0], critical_status::converged));
      continue;
    }
    auto node = line.nodes[i];
    auto plan = line.plans[i];
    const critical_status st = opt.resolve_nodes ? resolve_node(sys, line, i, scale, opt.tolerance, node, plan)
                                                 : critical_status::not_converged;
    r.points.push_back(line_point(sys, node, plan, st));
  }
  return r;
}

template <class Policy, bool E1, bool E2, class T>
inline void critical_line_at_imp(const TwoLevelSeta<T>& s, const T* Ft, std::size_t count,
                                 const critical_line_options<T>& opt, critical_state<T>* out) {
  using System = seta_system<T, Policy, E1, E2>;
  const System sys(make_seta_params(s), opt.strain_limit);
  std::vector<std::size_t> pos, neg;
  T hi = 0, lo = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!(out[i].status == critical_status::invalid_input)) {
      if (Ft[i] >= 0) { pos.push_back(i); hi = std::max(hi, Ft[i]); }
      else { neg.push_back(i); lo = std::min(lo, Ft[i]); }
    }
  }
  if (pos.empty() && neg.empty()) return;
  using std::fabs; using std::sqrt;
  const T base_scale = sqrt(s.EI1 * s.w) / s.l1;
  typename System::vec z0;
  typename System::plan_type plan0;
  critical_state<T> natural;
  auto run = [&](const std::vector<std::size_t>& which, T stop) {
    traced_line<System> line;
    const T scale = std::max(fabs(stop), base_scale);
    if (!trace(sys, stop, scale, opt, which.size(), z0, plan0, natural, line)) {
      for (std::size_t i : which) {
        out[i].Ft = Ft[i];
        out[i].status = natural.status;
      }
      return;
    }
    evaluate_line(sys, line, Ft, which.size(), which.data(), opt.tolerance, out);
  };
  if (!pos.empty()) run(pos, hi);
  if (!neg.empty()) run(neg, lo);
}

template <class T, class Policy>
inline bool check_line_inputs(const TwoLevelSeta<T>& s, const T* Ft, std::size_t count, critical_state<T>* out,
                              const char* fn) {
  if (!check_seta<T, Policy>(s, fn)) {
    for (std::size_t i = 0; i < count; ++i) {
      out[i] = critical_state<T>();
      out[i].Ft = Ft[i];
      out[i].status = critical_status::invalid_input;
    }
    return false;
  }
  const T fm = ft_max(s);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = critical_state<T>();
    out[i].Ft = Ft[i];
    if (!check_ft<T, Policy>(Ft[i], fm, fn)) out[i].status = critical_status::invalid_input;
  }
  return true;
}

}  // namespace detail

// The followed line from Ft = 0 (nodes of the continuation), with its folds and why it ended.
template <class T, class Policy = policies::default_policy>
inline critical_line_result<T> critical_line(const TwoLevelSeta<T>& seta,
                                             const critical_line_options<T>& options = critical_line_options<T>(),
                                             const Policy& = Policy()) {
  constexpr const char* fn = "gecko::critical_line";
  if (!detail::check_seta<T, Policy>(seta, fn)) {
    critical_line_result<T> r;
    r.end = line_end::no_natural_state;
    return r;
  }
  if (options.ft_end == options.ft_end && !detail::check_ft<T, Policy>(options.ft_end, ft_max(seta), fn)) {
    critical_line_result<T> r;
    r.end = line_end::no_natural_state;
    return r;
  }
  return detail::visit_extensibility(seta, [&](auto E1, auto E2) {
    return detail::critical_line_imp<Policy, decltype(E1)::value, decltype(E2)::value>(seta, options);
  });
}

// The line at given Ft values (any order, negative allowed), out[i] for Ft[i].
template <class T, class Policy = policies::default_policy>
inline void critical_line_at(const TwoLevelSeta<T>& seta, const T* Ft, std::size_t count, critical_state<T>* out,
                             const critical_line_options<T>& options = critical_line_options<T>(),
                             const Policy& = Policy()) {
  if (!detail::check_line_inputs<T, Policy>(seta, Ft, count, out, "gecko::critical_line_at")) return;
  detail::visit_extensibility(seta, [&](auto E1, auto E2) {
    detail::critical_line_at_imp<Policy, decltype(E1)::value, decltype(E2)::value>(seta, Ft, count, options, out);
  });
}

template <class T, class Policy = policies::default_policy>
inline std::vector<critical_state<T>> critical_line_at(const TwoLevelSeta<T>& seta, const std::vector<T>& Ft,
                                                       const critical_line_options<T>& options = critical_line_options<T>(),
                                                       const Policy& pol = Policy()) {
  std::vector<critical_state<T>> out(Ft.size());
  critical_line_at(seta, Ft.data(), Ft.size(), out.data(), options, pol);
  return out;
}

// Without a guess: the state on the line followed from Ft = 0.
template <class T, class Policy = policies::default_policy>
inline critical_state<T> solve_critical(const TwoLevelSeta<T>& seta, T Ft) {
  critical_state<T> r;
  critical_line_at(seta, &Ft, 1, &r, critical_line_options<T>(), Policy());
  return r;
}

}  // namespace gecko
