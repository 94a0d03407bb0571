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
// The jobs live in their own headers: options and results (critical_line_types.hpp), the natural
// state (detail/natural_state.hpp), tracing (detail/line_trace.hpp), dense output
// (detail/line_output.hpp); solve_critical without a guess is in solve_on_line.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <type_traits>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/critical_line_types.hpp"
#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/line_output.hpp"
#include "gecko/seta/detail/line_trace.hpp"
#include "gecko/seta/detail/natural_state.hpp"
#include "gecko/seta/detail/separatrix_extend.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/extensibility.hpp"
#include "gecko/seta/solve_critical.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

namespace detail {

// Where double's homotopy to the natural state gave up (status 1), the natural state decided again
// in long double where that is wider, as critical_line_at's retry decides it: unsupported_state
// where every route there failed and one ran into the edge of the model's forms
// (detail/natural_state.hpp), so that the traced line and the characteristics report what the
// states at given Ft report. A natural state that only long double finds is not followed here
// (the traced line is double's): not_converged, as before.
template <class Policy, bool E1, bool E2, class T>
inline critical_status natural_state_decided_wider(const TwoLevelSeta<T>& s, T strain_limit) {
  if constexpr (std::is_same<T, double>::value && wider_than_double<long double>()) {
    using L = long double;
    const TwoLevelSeta<L> sl{L(s.EI1), L(s.EI2), L(s.EA1), L(s.EA2), L(s.l1), L(s.l2), L(s.alpha1), L(s.alpha2), L(s.w)};
    const seta_system<L, Policy, E1, E2> sys(make_seta_params(sl), L(strain_limit));
    typename seta_system<L, Policy, E1, E2>::vec z;
    seta_plan plan;
    int its = 0;
    // As in the retry, an error raised on a path double did not take decides nothing.
    try {
      if (natural_state(sys, z, plan, its) == critical_status::unsupported_state)
        return critical_status::unsupported_state;
    } catch (const std::exception&) {
    }
  } else {
    (void)s;
    (void)strain_limit;
  }
  return critical_status::not_converged;
}

// trace() on a design, with the natural state's verdict as critical_line_at's retry gives it: where
// double's homotopy gave up (status 1) and long double finds every route ending at the edge of the
// forms, the natural state is status 3 and the line ends unsupported_state. The traced line and the
// characteristics follow the line this way.
template <class Policy, bool E1, bool E2, class T>
inline bool trace_design(const TwoLevelSeta<T>& s, const seta_system<T, Policy, E1, E2>& sys, T ft_stop, T scale,
                         const critical_line_options<T>& opt, typename seta_system<T, Policy, E1, E2>::vec& z0,
                         seta_plan& plan0, critical_state<T>& natural,
                         traced_line<seta_system<T, Policy, E1, E2>>& line) {
  if (trace(sys, ft_stop, scale, opt, 0, z0, plan0, natural, line)) return true;
  if (natural.status == critical_status::not_converged &&
      natural_state_decided_wider<Policy, E1, E2>(s, opt.strain_limit) == critical_status::unsupported_state) {
    natural.status = critical_status::unsupported_state;
    line.end = line_end::unsupported_state;
  }
  return false;
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
  trace_design(s, sys, end, scale, opt, z0, plan0, r.natural, line);
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
                                 const critical_line_options<T>& opt, critical_state<T>* out);

// The states that double precision gave up on (status not_converged: the natural state's homotopy
// stalled; not_reached: the followed line, and its separatrix limit, stopped before them), solved
// again along the same line in long double where it is wider than double (x87's 64-bit
// significand on x86). Next to a segment's separatrix the solves stall at a rounding floor: the
// Newton step of the separatrix limit system stops shrinking at 1e-12 to 1e-9 of the state, above
// the tolerance (validation/README.md, "Lines that never leave their start, and rounding
// floors"); 11 more bits lower that floor, below the tolerance for two give-ups in five of the
// 10,000-design re-run (validation/README.md, "Give-ups retried in long double"). The retry's march
// goes on in arclength where its steps in Ft collapse (separatrix_arclength.hpp), and so does the
// natural state's march in lambda (natural_state.hpp). Only a converged or inadmissible answer
// replaces the double one; where double gave up with status 1, also an unsupported one (status 3)
// or a line given up before the target (status 6); and a line that turned back before the target
// (status 2, beyond the line); where double's line was given up (status 6), also a line that
// leaves the model before the target (status 3): any other status of the retry leaves the give-up
// as it was. States
// solved in double are not touched.
template <class Policy, bool E1, bool E2>
inline void retry_in_long_double(const TwoLevelSeta<double>& s, const double* Ft, std::size_t count,
                                 const critical_line_options<double>& opt, critical_state<double>* out) {
  using L = long double;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < count; ++i)
    if (out[i].status == critical_status::not_reached || out[i].status == critical_status::not_converged)
      which.push_back(i);
  if (which.empty()) return;
  const TwoLevelSeta<L> sl{L(s.EI1), L(s.EI2), L(s.EA1), L(s.EA2), L(s.l1), L(s.l2), L(s.alpha1), L(s.alpha2), L(s.w)};
  critical_line_options<L> ol;  // every field of critical_line_options, converted
  ol.ft_end = L(opt.ft_end);
  ol.tolerance = L(opt.tolerance);
  ol.line_tolerance = L(opt.line_tolerance);
  ol.max_points = opt.max_points;
  ol.resolve_nodes = opt.resolve_nodes;
  ol.strain_limit = L(opt.strain_limit);
  std::vector<L> ft(which.size());
  std::vector<critical_state<L>> res(which.size());
  for (std::size_t k = 0; k < which.size(); ++k) {
    ft[k] = L(Ft[which[k]]);
    res[k].Ft = ft[k];
  }
  // The retry can only add solved states: an error raised inside it (a kernel's domain error under
  // the raising policy, on a path the double solve did not take) leaves the give-ups as they were.
  try {
    critical_line_at_imp<Policy, E1, E2>(sl, ft.data(), ft.size(), ol, res.data());
  } catch (const std::exception&) {
    return;
  }
  for (std::size_t k = 0; k < which.size(); ++k) {
    const critical_state<L>& r = res[k];
    critical_state<double>& o = out[which[k]];
    // Where double gave up with status 1 (nearly always the natural state's homotopy), the retry
    // may find the edge of the model's forms instead (natural_state.hpp, or a line that ends
    // there): a state beyond what the model represents, status 3 as in double. Or it finds the
    // natural state and its line stops before this Ft: status 6, the line from Ft = 0 exists and
    // was given up on the way, not "Newton did not converge" (design 7775 of the 10,000-design
    // re-run, whose other Ft the retry solves, was such a state until the march in arclength
    // claimed the targets past a turned-back fold: it is status 2 now, below).
    // Where double's line was given up before this Ft (status 6), the retry's line may leave the
    // model before it (a state compressed to zero length, line_trace.hpp's end_at_inverted_state,
    // or the edge of the forms): status 3, as where double's own line leaves it.
    const bool retry_found_edge_or_line = ((r.status == critical_status::unsupported_state ||
                                            r.status == critical_status::not_reached) &&
                                           o.status == critical_status::not_converged) ||
                                          (r.status == critical_status::unsupported_state &&
                                           o.status == critical_status::not_reached);
    // The retry's line turned back short of this Ft after a fold (its separatrix march in
    // arclength came back over Ft = 0, separatrix_arclength.hpp): no critical state on the line,
    // as where double's own line turns back.
    const bool retry_turned_back = r.status == critical_status::no_critical_state;
    if (retry_found_edge_or_line || retry_turned_back) {
      o.status = r.status;
      o.iterations = r.iterations;
      continue;
    }
    if (r.status != critical_status::converged && r.status != critical_status::inadmissible) continue;
    o.Fn = double(r.Fn);
    o.theta_joint = double(r.theta_joint);
    o.status = r.status;
    o.iterations = r.iterations;
    o.theta_rate_joint = double(r.theta_rate_joint);
    o.theta_rate_base = double(r.theta_rate_base);
    o.turning_points_beam = r.turning_points_beam;
    o.turning_points_spatula = r.turning_points_spatula;
    o.min_z = double(r.min_z);
    o.min_z_at = double(r.min_z_at);
    o.max_axial_strain = double(r.max_axial_strain);
    o.min_stretch = double(r.min_stretch);
  }
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
  // One natural state for the lines in both directions.
  typename System::vec z0;
  typename System::plan_type plan0;
  critical_state<T> natural;
  const bool started = start_line(sys, z0, plan0, natural);
  auto run = [&](const std::vector<std::size_t>& which, T stop) {
    if (!started) {
      for (std::size_t i : which) {
        out[i].Ft = Ft[i];
        out[i].status = natural.status;
      }
      return;
    }
    traced_line<System> line;
    const T scale = std::max(fabs(stop), base_scale);
    follow_from_natural(sys, stop, scale, opt, which.size(), z0, plan0, line);
    evaluate_line(sys, line, Ft, which.size(), which.data(), opt.tolerance, out);
    // A type wider than double marches in the separatrix limit at the line's tolerance and solves
    // the targets to the state's (separatrix_extend.hpp says why not in double), and goes on in
    // arclength where its steps in Ft collapse (separatrix_arclength.hpp says why only there).
    constexpr bool wide = wider_than_double<T>();
    extend_on_separatrix(sys, line, scale, Ft, which.size(), which.data(), opt.tolerance, out,
                         wide ? opt.line_tolerance : T(0), wide);
  };
  if (!pos.empty()) run(pos, hi);
  if (!neg.empty()) run(neg, lo);
  if constexpr (std::is_same<T, double>::value && wider_than_double<long double>())
    retry_in_long_double<Policy, E1, E2>(s, Ft, count, opt, out);
  // A target still given up on (status 6) where the call asked for other Ft in its direction,
  // retried on a line followed to it alone. The farthest target sets the line's force scale, and
  // with it the step sizes and the stall test (follow_line): a line scaled for a far target can
  // stall at a nearer one that a line scaled for that one passes (validation/README.md, "Give-ups
  // that a call with their Ft alone solves"). The farthest target itself has the same line, but
  // the separatrix march past its stall stops at every target it passes (extend_on_separatrix),
  // and the long-double retry follows the call's give-ups together, so its march differs too
  // (campaign designs 574 and 3796: validation/README.md, "The give-ups left, on an Intel Xeon").
  // After the long-double retry, so that it sees the same give-ups as without this retry (its
  // line goes to the farthest of them, and every state it solves stays as it was); that retry
  // makes the same retry in long double, on its own line. Only a solved state (status 0 or 7)
  // replaces the give-up: no state solved before is touched.
  if (started) {
    const std::size_t pos_count = pos.size(), neg_count = neg.size();
    for (std::size_t i = 0; i < count; ++i) {
      if (out[i].status != critical_status::not_reached) continue;
      if ((Ft[i] >= 0 ? pos_count : neg_count) < 2) continue;  // its line is its own already
      const critical_state<T> given_up = out[i];
      run(std::vector<std::size_t>{i}, Ft[i]);
      if (out[i].status != critical_status::converged && out[i].status != critical_status::inadmissible)
        out[i] = given_up;
    }
  }
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

}  // namespace gecko
