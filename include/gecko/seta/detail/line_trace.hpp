// gecko/seta/detail/line_trace.hpp — following the critical line from the natural state.
//
// The natural state (gecko/seta/detail/natural_state.hpp), then pseudo-arclength continuation
// (gecko/seta/detail/continuation.hpp) in one direction up to a stop in Ft, through folds; the
// traced nodes become critical_line_points.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "gecko/seta/admissibility.hpp"
#include "gecko/seta/critical_line_types.hpp"
#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/natural_state.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {
namespace detail {

template <class T>
inline T default_ft_end(const TwoLevelSeta<T>& s) {
  using std::isinf; using std::sqrt;
  return isinf(s.EA2) ? 3 * sqrt(s.EI1 * s.w) / s.l1 : ft_max(s);
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
    p.min_stretch = st.min_stretch;
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

// The natural state at Ft = 0 (detail/natural_state.hpp), node 0 of every line followed from it:
// true where it converged (natural then holds it as a state), else natural.status says why.
// A design's natural state is computed once and shared by the lines followed from it in both
// directions (critical_line_at's positive and negative targets).
template <class System, class T>
inline bool start_line(const System& sys, typename System::vec& z0, typename System::plan_type& plan0,
                       critical_state<T>& natural) {
  int its = 0;
  const critical_status nat = natural_state(sys, z0, plan0, its);
  if (nat != critical_status::converged) {
    natural.status = nat;
    return false;
  }
  natural = state_from(sys, z0, T(0), T(0), plan0, critical_status::converged, its);
  return true;
}

// The followed line ends at its first node where a segment is compressed to zero length or beyond
// (a stretch 1 + T/EA <= 0 somewhere, T <= -EA: admissibility_imp's `inverted`). The equations of
// the extensible elastica go on solving there, but their linear law then maps a piece of the rod to
// a negative length, which no seta can take, and the edge of the forms (f4's root, where the
// solver's plans end: line_end::unsupported_state) lies further on (gecko/seta/admissibility.hpp,
// "Strain"). So the line leaves the model at that node, as a line that runs into the edge of the
// forms does: the node is kept (states read off the line up to it are solved and judged on their
// own, status 7 where inverted), the line ends unsupported_state, and the targets beyond it are
// status 3. Lines of the campaign's extensible beams compressed tens of times EA ran on along the
// edge of the forms until their step collapsed (validation/README.md, "Lines that run along the
// edge of the forms"). Cost: a comparison per node where c N < 1 (the stretch is then at least
// 1 - c N > 0), else the strain part of the admissibility check, without its quadrature.
template <class System>
inline void end_at_inverted_state(const System&, traced_line<System>&) {}

template <class T, class Policy, bool E1, bool E2>
inline void end_at_inverted_state(const seta_system<T, Policy, E1, E2>& sys,
                                  traced_line<seta_system<T, Policy, E1, E2>>& line) {
  using std::sqrt;
  const T c = sys.d.c1 > sys.d.c2 ? sys.d.c1 : sys.d.c2;
  if (!(c > 0)) return;
  for (std::size_t k = 0; k < line.nodes.size(); ++k) {
    const auto& node = line.nodes[k];
    const T Fn = node.z[0], Ft = sys.ft_of(node.Ft);
    if (!(c * sqrt(Fn * Fn + Ft * Ft) >= 1)) continue;
    seta_pose<T> pose{Fn, Ft, sys.theta_joint(node.z), sys.rate_base(node.z), sys.rate_joint(node.z), 0, 0,
                      std::numeric_limits<T>::quiet_NaN()};
    sys.turning_points(line.plans[k], node.z, node.Ft, pose.turning_points_beam, pose.turning_points_spatula);
    if (!admissibility_imp(sys.d, pose, std::numeric_limits<T>::infinity(), true).inverted) continue;
    line.nodes.resize(k + 1);
    line.plans.resize(k + 1);
    if (line.jacobians.size() > k + 1) line.jacobians.resize(k + 1);
    if (line.folds.size() > static_cast<std::size_t>(node.branch)) line.folds.resize(node.branch);
    line.end = line_end::unsupported_state;
    return;
  }
}

// The line followed from the natural state (z0, plan0) in one direction, up to Ft = ft_stop.
// outputs: how many states will be read off the line; many outputs make denser nodes pay (better
// Hermite guesses, fewer chord steps per output).
template <class System, class T>
inline void follow_from_natural(const System& sys, T ft_stop, T scale, const critical_line_options<T>& opt,
                                std::size_t outputs, const typename System::vec& z0,
                                const typename System::plan_type& plan0, traced_line<System>& line) {
  if (ft_stop == 0) {
    line.nodes.push_back({z0, T(0), Eigen::Matrix<T, System::n + 1, 1>::Zero(), 0});
    line.plans.push_back(plan0);
    line.end = line_end::reached_ft_end;
    return;
  }
  continuation_options<T> copt;
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
  end_at_inverted_state(sys, line);
}

// Natural state + the followed line in one direction, up to Ft = ft_stop (false, with line.end
// set, where there is no natural state).
template <class System, class T>
inline bool trace(const System& sys, T ft_stop, T scale, const critical_line_options<T>& opt, std::size_t outputs,
                  typename System::vec& z0, typename System::plan_type& plan0, critical_state<T>& natural,
                  traced_line<System>& line) {
  if (!start_line(sys, z0, plan0, natural)) {
    line.end = natural.status == critical_status::unsupported_state ? line_end::unsupported_state
                                                                    : line_end::no_natural_state;
    return false;
  }
  follow_from_natural(sys, ft_stop, scale, opt, outputs, z0, plan0, line);
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

}  // namespace detail
}  // namespace gecko
