// gecko/seta/characteristics.hpp — the characteristic quantities of a two-level seta
// (docs/theory/two_level_seta.md, "Critical line of adhesion" and "Small-deformation approximations"):
//   (Fn)0           critical Fn at Ft = 0 (> 0: not sticky at rest, like a gecko)
//   slope k         dFn/dFt at Ft = 0, the exact tangent of the line (the linear theory's k, eq 21,
//                   is the slope of its straight line; both are reported)
//   max pull-off    -min Fn along the line followed from Ft = 0, and the Ft where it occurs: the
//                   smaller of the two ends of the followed range and every interior stationary
//                   minimum, each refined to dFn/ds = 0 and its slope verified (see below)
//   (Ft)max         sqrt(2 EA2 w), and Fn where the line ends there
//   sticky at rest  (Fn)0 < 0
// next to the small-deformation formulas (gecko/seta/small_deformation.hpp).
//
// Interior minima. Every segment between two traced nodes over which dFn/ds (the Fn component of
// the line's unit tangent, exact at the converged nodes) goes from < 0 to > 0 holds a minimum of
// Fn along the line. It is refined on the segment's chord: states x = (z, mu) with F(x) = 0 and
// c.(x - x_a) = sigma, c the unit chord (a pseudo-arclength condition, so a fold inside the
// segment costs nothing), guessed by the cubic Hermite of the two nodes, corrected by the
// continuation's bordered Newton (gecko/seta/detail/continuation.hpp) and accepted only on a plan
// valid at the solution (or on the boundary between two forms, where both plans give the state)
// and close to the guess (not another branch). The Carlson plan is chosen per state: the
// elastica's turning points may leave and re-enter a segment between two nodes, so one node's
// plan does not hold over the whole bracket (it did not: the refinement failed at its first
// state and the node's Fn was reported, up to 0.12% short of the max pull-off in 23 of 2000
// random designs; tests/seta/characteristics.cpp). The root of g(sigma) = dFn/dsigma, from the
// bordered system [J dF/dmu; c^T] dx = e_last (at the nodes: their tangents), is found by
// Illinois false position with bisection safeguard; the state with the smallest |g| is kept
// (near the minimiser the Fn values differ by less than their accuracy), and certified by its
// slope dFn/dmu at fixed mu (implicit differentiation): |dFn/dmu| <= sqrt(eps) max(1, |Fn|) /
// scale, which bounds the error of min Fn by about eps |Fn| (location error slope / Fn'', value
// error slope^2 / (2 Fn''), Fn'' ~ |Fn| / scale^2; measured slopes ~1e-13). A node lower than
// every minimum found means one was missed. A minimum that cannot be refined or certified gives
// min_status = not_certified and NaN, never the value at a node.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/small_deformation.hpp"
#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/detail/dual.hpp"
#include "gecko/seta/extensibility.hpp"

namespace gecko {

// Where the most tensile critical Fn of the followed line lies, and how far it is established.
enum class minimum_status : int {
  stationary = 0,       // interior: dFn/dFt = 0 there, verified (slope_at_min_fn)
  range_start = 1,      // at Ft = 0, the start of the followed range (the line rises from it)
  range_end = 2,        // at the end of the followed range ((Ft)max or the requested end)
  line_incomplete = 3,  // the line stopped before the end of the range (see `end`): the values are
                        // the minimum over the followed part only
  not_certified = 4,    // a minimum could not be refined or its slope not verified: NaN values
  admissible_end = 5,   // at the end of the admissible part of the line (admissible_end_ft): beyond
                        // it the seta crosses the substrate (or the strain limit), see below
  no_admissible_state = 6  // already the natural state is inadmissible: NaN values
};

template <class T>
struct seta_characteristics {
  T fn0 = std::numeric_limits<T>::quiet_NaN();
  // dFn/dFt at Ft = 0: the exact tangent of the line at the natural state.
  T slope_at_zero = std::numeric_limits<T>::quiet_NaN();
  // Deprecated alias of slope_at_zero (kept for existing callers; it is not the paper's k).
  T slope_k = std::numeric_limits<T>::quiet_NaN();
  // The paper's k (paper 001 eq (16): Fn = (Fn)0 + k Ft, "the slope of the straight line" of the
  // lower, bending-dominated part of the critical line): the least-squares slope of a straight
  // line through the natural state (0, (Fn)0) fitted to the line over its lower part, Ft from 0
  // to the Ft of the max pull-off (where the axial-dominated upper part begins):
  //     k = int_0^Ft* Ft (Fn(Ft) - (Fn)0) dFt / int_0^Ft* Ft^2 dFt,
  // by 16-point Gauss-Legendre on exact states (first crossings along the line). NaN where the
  // line has no lower part (the minimum at Ft = 0) or its minimum was not established.
  T paper_k = std::numeric_limits<T>::quiet_NaN();
  // The max pull-off at the end of the followed range, where that end is not the line's own end
  // ((Ft)max): the maximum is not established (EA2 = inf has no (Ft)max; a line given up early).
  // Then max_pull_off is NaN and max_pull_off_bound = max(0, -min Fn over the followed range), a
  // lower bound of the line's max pull-off, with max_pull_off_is_bound = true.
  bool max_pull_off_is_bound = false;
  T max_pull_off_bound = std::numeric_limits<T>::quiet_NaN();
  T min_fn = std::numeric_limits<T>::quiet_NaN();       // most tensile critical Fn on the line
  T ft_at_min_fn = std::numeric_limits<T>::quiet_NaN();
  bool min_fn_interior = false;   // true: a verified stationary minimum (min_status stationary)
  minimum_status min_status = minimum_status::not_certified;
  // dFn/dFt at the minimiser: ~0 at a stationary minimum (|.| <= sqrt(eps) max(1,|Fn|)/scale in
  // the line parameter), slope_k at Ft = 0, NaN at (Ft)max (the tangent is vertical there).
  T slope_at_min_fn = std::numeric_limits<T>::quiet_NaN();
  T max_pull_off = std::numeric_limits<T>::quiet_NaN();  // max(0, -min_fn)
  T ft_max = std::numeric_limits<T>::quiet_NaN();        // sqrt(2 EA2 w)
  T ft_at_line_end = std::numeric_limits<T>::quiet_NaN();
  T fn_at_line_end = std::numeric_limits<T>::quiet_NaN();
  bool sticky_at_rest = false;
  line_end end = line_end::no_natural_state;
  std::vector<T> folds;
  small_deformation_line<T> small;  // the linear theory's (Fn)0, k, contact length, criterion
  // The admissible part of the line (gecko/seta/admissibility.hpp): from Ft = 0 along the line to
  // the first state where the seta crosses the substrate (or exceeds the strain limit). The max
  // pull-off is the minimum of Fn over this part only: it never comes from an inadmissible state.
  // admissible_to_end: the whole followed line is admissible (admissible_end_ft is then the Ft of
  // the line's end); else admissible_end_ft / _fn locate the boundary (refined along the line to
  // ~1e-10 of its arclength), NaN when the natural state itself is inadmissible.
  bool admissible_to_end = false;
  T admissible_end_ft = std::numeric_limits<T>::quiet_NaN();
  T admissible_end_fn = std::numeric_limits<T>::quiet_NaN();
};

namespace detail {

// dFn/dmu and the state at mu (Newton from z), or false.
template <class System, class T>
inline bool slope_at(const System& sys, typename System::vec& z, T mu, typename System::plan_type& plan,
                     T& dfn) {
  int its = 0;
  if (solve_with_plans(sys, z, mu, plan, T(1e-13), 40, its) != critical_status::converged) return false;
  typename System::vec F, JF;
  typename System::mat J;
  T u14[2];
  if (!sys.eval(z, mu, plan, F, J, &JF, u14)) return false;
  const typename System::vec dz = -J.partialPivLu().solve(JF);
  dfn = dz[0];
  return std::isfinite(dfn);
}

// dFt/dmu of the line parameter (1 for an inextensible spatula, cos(mu/(Ft)max) otherwise).
template <class System, class T>
inline T dft_dmu(const System& sys, T mu) {
  using D = dual<T, 1>;
  D ft, edge;
  sys.forces(D::variable(mu, 0), ft, edge);
  return ft.d[0];
}

// States of the traced line between nodes i and i + 1, parametrised by sigma = c.(x - x_i) along
// the unit chord c (see the header comment).
template <class System>
class segment_probe {
 public:
  using T = typename System::value_type;
  static constexpr int n = System::n;
  using xvec = Eigen::Matrix<T, n + 1, 1>;
  using plan_type = typename System::plan_type;

  segment_probe(const System& sys, const traced_line<System>& line, std::size_t i, T scale, T tol)
      : sys_(sys), a_(line.nodes[i]), b_(line.nodes[i + 1]), pa_(line.plans[i]), pb_(line.plans[i + 1]),
        scale_(scale), tol_(tol) {
    xa_.template head<n>() = a_.z;
    xa_[n] = a_.Ft;
    xb_.template head<n>() = b_.z;
    xb_[n] = b_.Ft;
    h_ = (xb_ - xa_).norm();
    c_ = (xb_ - xa_) / h_;
    // sigma is a valid parameter when both ends' tangents point along the chord; the Hermite
    // cubic's sigma(s) is then monotone (end slopes c.t <= 1 < 3 times the secant).
    valid_ = h_ > 0 && std::isfinite(h_) && c_.dot(a_.tangent) > 0 && c_.dot(b_.tangent) > 0;
  }
  bool valid() const { return valid_; }
  // dFn/dsigma at node a (end 0) or b (end 1), from the node's unit tangent.
  T node_slope(int end) const {
    const auto& t = end == 0 ? a_.tangent : b_.tangent;
    return t[0] / c_.dot(t);
  }
  T length() const { return h_; }

  // The state at sigma: x, its plan, Fn and g = dFn/dsigma. False when it is not found on this
  // stretch of the line.
  bool at(T sigma, xvec& x, plan_type& plan, T& g) const {
    using std::fabs;
    const T s = solve_s(sigma);
    const xvec guess = hermite_at(s);
    const T near = h_ / 4;  // the Hermite guess is O(h^4) off; another branch is O(h) away
    for (int start = 0; start < 2; ++start) {
      // First the plan of the nearer node, then one made at the guess; a plan found invalid at
      // the converged state is replaced by the state's own and the state corrected again.
      plan = start == 0 ? (s <= T(0.5) ? pa_ : pb_) : sys_.plan(guess.template head<n>(), guess[n]);
      xvec x_prev = guess;
      for (int round = 0; round < 3; ++round) {
        if (System::plan_state(plan) != segment_state::ok) break;
        x = guess;
        int its = 0;
        T u14[2] = {1, 1};
        T omega = 0;
        if (!arclength_corrector(sys_, x, c_, plan, tol_, scale_, its, u14, omega)) break;
        if ((x - guess).norm() > near) break;
        // A valid plan; or a state on the boundary between two forms (a turning point on a
        // segment's end), where the plans alternate and both give the same state.
        if (sys_.plan_valid(plan, x.template head<n>(), x[n], u14) ||
            (round > 0 && sys_.step_norm((x - x_prev).template head<n>(), x.template head<n>()) <= tol_ &&
             fabs(x[n] - x_prev[n]) <= tol_ * scale_))
          return derivative(x, plan, g);
        x_prev = x;
        plan = sys_.plan(x.template head<n>(), x[n]);
      }
    }
    return false;
  }

 private:
  // s in [0, 1] with c.(H(s) - x_a) = sigma (safeguarded Newton on the monotone cubic).
  T solve_s(T sigma) const {
    using std::fabs;
    T lo = 0, hi = 1, s = sigma / h_;
    if (!(s > 0 && s < 1)) return s <= 0 ? T(0) : T(1);
    for (int it = 0; it < 60; ++it) {
      const T f = c_.dot(hermite_at(s) - xa_) - sigma;
      if (f == 0) break;
      if (f < 0) lo = s;
      else hi = s;
      const T s2 = s * s;
      const T df = c_.dot(((6 * s2 - 6 * s) * (xa_ - xb_) + (3 * s2 - 4 * s + 1) * h_ * a_.tangent +
                           (3 * s2 - 2 * s) * h_ * b_.tangent).eval());
      T next = s - f / df;
      if (!(next > lo && next < hi)) next = (lo + hi) / 2;
      if (fabs(next - s) <= 4 * std::numeric_limits<T>::epsilon()) return next;
      s = next;
    }
    return s;
  }
  xvec hermite_at(T s) const {
    const T s2 = s * s, s3 = s2 * s;
    return ((2 * s3 - 3 * s2 + 1) * xa_ + (s3 - 2 * s2 + s) * h_ * a_.tangent + (-2 * s3 + 3 * s2) * xb_ +
            (s3 - s2) * h_ * b_.tangent).eval();
  }
  // g = dFn/dsigma along the line: [J dF/dmu; c^T] dx = e_last.
  bool derivative(const xvec& x, const plan_type& plan, T& g) const {
    typename System::vec F, JF;
    typename System::mat J;
    T u14[2];
    if (!sys_.eval(x.template head<n>(), x[n], plan, F, J, &JF, u14)) return false;
    Eigen::Matrix<T, n + 1, n + 1> A;
    A.template topLeftCorner<n, n>() = J;
    A.template topRightCorner<n, 1>() = JF;
    A.template bottomRows<1>() = c_.transpose();
    xvec rhs = xvec::Zero();
    rhs[n] = 1;
    const xvec dx = A.partialPivLu().solve(rhs);
    g = dx[0];
    return std::isfinite(g);
  }

  const System& sys_;
  const line_node<T, n>& a_;
  const line_node<T, n>& b_;
  const plan_type& pa_;
  const plan_type& pb_;
  T scale_, tol_, h_ = 0;
  xvec xa_, xb_, c_;
  bool valid_ = false;
};

// A refined minimum of Fn along the line.
template <class T>
struct line_minimum {
  T mu, fn, slope;  // line parameter, Fn, dFn/dmu there
  bool has_state = false;
  Eigen::Matrix<T, 4, 1> z;  // the state (Fn, beta, p, q) of the two-level seta
};

// Refine the minimum of Fn on the segment after node i, where dFn/ds changes sign from - to +.
// False when it cannot be found and verified.
template <class System, class T>
inline bool refine_segment_minimum(const System& sys, const traced_line<System>& line, std::size_t i, T scale,
                                   line_minimum<T>& out) {
  using std::fabs; using std::sqrt;
  constexpr int n = System::n;
  const T eps = std::numeric_limits<T>::epsilon();
  const T tol = std::max(T(1e-13), 64 * eps);
  const segment_probe<System> probe(sys, line, i, scale, tol);
  if (!probe.valid()) return false;
  using xvec = typename segment_probe<System>::xvec;
  xvec x = xvec::Zero(), best_x = xvec::Zero();
  typename System::plan_type plan = line.plans[i], best_plan = line.plans[i];
  // The state reported is the one with the smallest |dFn/dsigma|, not the lowest Fn: within
  // ~sqrt(tol / Fn'') of the minimiser the Fn values differ by less than their own accuracy.
  T best_g = std::numeric_limits<T>::infinity();
  auto eval = [&](T sigma, T& g) {
    if (!probe.at(sigma, x, plan, g)) return false;
    if (fabs(g) < best_g) {
      best_g = fabs(g);
      best_x = x;
      best_plan = plan;
    }
    return true;
  };
  // The bracket's ends are the nodes, g there from their tangents (dFn/ds over dsigma/ds): no
  // solve at a node, which may sit on the boundary between two forms.
  T a = 0, b = probe.length();
  T ga = probe.node_slope(0), gb = probe.node_slope(1);
  if (!(ga <= 0 && gb >= 0)) return false;  // the nodes' tangents promised a sign change
  if (ga == 0 || gb == 0) {  // a node is itself the stationary point
    T g;
    if (!eval(ga == 0 ? a : b, g)) return false;
  }
  if (ga < 0 && gb > 0) {
    // Illinois false position; a bisection whenever the bracket fails to halve in two steps.
    int side = 0, slow = 0;
    const T xtol = 8 * eps * probe.length();
    for (int it = 0; it < 100 && b - a > xtol; ++it) {
      const T width = b - a;
      T m = slow >= 2 ? (a + b) / 2 : (a * gb - b * ga) / (gb - ga);
      if (!(m > a && m < b)) m = (a + b) / 2;
      T gm;
      if (!eval(m, gm)) return false;
      if (gm == 0) break;
      if (gm < 0) {
        a = m;
        ga = gm;
        if (side == -1) gb /= 2;
        side = -1;
      } else {
        b = m;
        gb = gm;
        if (side == 1) ga /= 2;
        side = 1;
      }
      slow = (b - a) > width / 2 ? slow + 1 : 0;
    }
  }
  if (!(best_g < std::numeric_limits<T>::infinity())) {  // a bracket too short to iterate on
    T g;
    if (!eval((a + b) / 2, g)) return false;
  }
  // Certificate: the slope dFn/dmu of the state found, at fixed mu (implicit differentiation).
  const typename System::vec z = best_x.template head<n>();
  typename System::vec F, JF;
  typename System::mat J;
  T u14[2];
  if (!sys.eval(z, best_x[n], best_plan, F, J, &JF, u14)) return false;
  const T d = -J.partialPivLu().solve(JF)[0];
  if (!(fabs(d) <= sqrt(eps) * std::max(T(1), fabs(z[0])) / scale)) return false;
  out.mu = best_x[n];
  out.fn = z[0];
  out.slope = d;
  if constexpr (n == 4) {
    out.z = z;
    out.has_state = true;
  }
  return true;
}

// Is the state z at line parameter mu admissible (gecko/seta/admissibility.hpp)?
template <class System>
inline bool state_admissible(const System& sys, const typename System::vec& z, typename System::value_type mu,
                             const typename System::plan_type& plan) {
  using T = typename System::value_type;
  critical_state<T> st;
  st.Ft = sys.ft_of(mu);
  st.Fn = z[0];
  st.theta_joint = sys.theta_joint(z);
  st.theta_rate_joint = sys.rate_joint(z);
  st.theta_rate_base = sys.rate_base(z);
  sys.turning_points(plan, z, mu, st.turning_points_beam, st.turning_points_spatula);
  st.status = critical_status::converged;
  apply_admissibility(sys, st);
  return st.status == critical_status::converged;
}

// The boundary of the admissible part on the segment after node i (node i admissible, i + 1 not):
// bisection in the chord parameter sigma of segment_probe. sigma_out: the last admissible sigma
// found, x_out its state. False when the segment cannot be probed (then node i is the boundary).
template <class System, class T>
inline bool refine_admissible_end(const System& sys, const traced_line<System>& line, std::size_t i, T scale,
                                  typename segment_probe<System>::xvec& x_out) {
  const T tol = std::max(T(1e-13), 64 * std::numeric_limits<T>::epsilon());
  const segment_probe<System> probe(sys, line, i, scale, tol);
  if (!probe.valid()) return false;
  using xvec = typename segment_probe<System>::xvec;
  constexpr int n = System::n;
  T a = 0, b = probe.length();
  bool have = false;
  xvec x;
  typename System::plan_type plan;
  for (int it = 0; it < 60 && b - a > T(1e-10) * probe.length(); ++it) {
    const T m = (a + b) / 2;
    T g;
    if (!probe.at(m, x, plan, g)) return have;
    const typename System::vec z = x.template head<n>();
    if (state_admissible(sys, z, x[n], sys.plan(z, x[n]))) {
      a = m;
      x_out = x;
      have = true;
    } else {
      b = m;
    }
  }
  return have;
}

template <class Policy, bool E1, bool E2, class T>
inline seta_characteristics<T> characteristics_imp(const TwoLevelSeta<T>& s, const critical_line_options<T>& opt) {
  using System = seta_system<T, Policy, E1, E2>;
  constexpr int n = System::n;
  const System sys(make_seta_params(s), opt.strain_limit);
  seta_characteristics<T> c;
  c.small = small_deformation(s, Policy());
  c.ft_max = ft_max(s);
  const T end = opt.ft_end == opt.ft_end ? opt.ft_end : default_ft_end(s);
  using std::fabs; using std::sqrt;
  const T scale = std::max(fabs(end), sqrt(s.EI1 * s.w) / s.l1);
  typename System::vec z0;
  typename System::plan_type plan0;
  critical_state<T> natural;
  traced_line<System> line;
  if (!trace_design(s, sys, end, scale, opt, z0, plan0, natural, line)) {
    c.end = line.end;
    return c;
  }
  c.end = line.end;
  for (T f : line.folds) c.folds.push_back(sys.ft_of(f));
  c.fn0 = natural.Fn;
  c.sticky_at_rest = natural.Fn < 0;
  // Slope at Ft = 0 (dFt/dmu = 1 there).
  {
    auto z = z0;
    auto plan = plan0;
    T d;
    if (slope_at(sys, z, T(0), plan, d)) c.slope_at_zero = c.slope_k = d;
  }
  const auto& nodes = line.nodes;
  c.ft_at_line_end = sys.ft_of(nodes.back().Ft);
  c.fn_at_line_end = nodes.back().z[0];
  // The admissible part: nodes [0, first_bad), and on the segment (first_bad - 1, first_bad) up to
  // the refined boundary.
  std::size_t first_bad = nodes.size();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!state_admissible(sys, nodes[i].z, nodes[i].Ft, line.plans[i])) {
      first_bad = i;
      break;
    }
  if (first_bad == 0) {
    c.min_status = minimum_status::no_admissible_state;
    return c;
  }
  c.admissible_to_end = first_bad == nodes.size();
  T bound_mu = nodes[first_bad - 1].Ft, bound_fn = nodes[first_bad - 1].z[0];
  if (c.admissible_to_end) {
    c.admissible_end_ft = c.ft_at_line_end;
    c.admissible_end_fn = c.fn_at_line_end;
  } else {
    typename segment_probe<System>::xvec xb;
    if (refine_admissible_end(sys, line, first_bad - 1, scale, xb)) {
      bound_mu = xb[n];
      bound_fn = xb[0];
    }
    c.admissible_end_ft = sys.ft_of(bound_mu);
    c.admissible_end_fn = bound_fn;
  }
  // Candidates: the two ends of the followed (admissible) range, and every interior minimum
  // (dFn/ds from - to + between consecutive nodes; the tangents are oriented along the line).
  const std::size_t last = c.admissible_to_end ? nodes.size() - 1 : first_bad - 1;
  T min_fn = nodes[0].z[0], min_mu = nodes[0].Ft, min_slope = c.slope_k;
  minimum_status kind = minimum_status::range_start;
  if (!c.admissible_to_end) {
    if (bound_fn < min_fn) {
      min_fn = bound_fn;
      min_mu = bound_mu;
      min_slope = std::numeric_limits<T>::quiet_NaN();
      kind = minimum_status::admissible_end;
    }
  } else if (last > 0 && nodes[last].z[0] < min_fn) {
    min_fn = nodes[last].z[0];
    min_mu = nodes[last].Ft;
    const T dmu = dft_dmu(sys, min_mu);
    const T dfn_ds = nodes[last].tangent[0], dmu_ds = nodes[last].tangent[n];
    min_slope = line.end == line_end::reached_ft_max ? std::numeric_limits<T>::quiet_NaN()
                                                     : dfn_ds / (dmu_ds * dmu);
    kind = minimum_status::range_end;
  }
  bool certified = true;
  const std::size_t seg_end = c.admissible_to_end ? last : first_bad;  // segments [0, seg_end)
  for (std::size_t i = 0; i < seg_end; ++i) {
    const T ta = nodes[i].tangent[0], tb = nodes[i + 1].tangent[0];
    if (!(ta < 0 && tb >= 0)) continue;
    line_minimum<T> m;
    if (!refine_segment_minimum(sys, line, i, scale, m)) {
      // On the boundary segment, a minimum beyond the boundary is not needed.
      if (i + 1 != first_bad) certified = false;
      continue;
    }
    if (i + 1 == first_bad) {
      // The boundary segment: the minimum counts only where the state is admissible.
      typename System::vec zm;
      if (!m.has_state) continue;
      zm = m.z;
      if (!state_admissible(sys, zm, m.mu, sys.plan(zm, m.mu))) continue;
    }
    if (m.fn < min_fn) {
      min_fn = m.fn;
      min_mu = m.mu;
      min_slope = m.slope / dft_dmu(sys, m.mu);
      kind = minimum_status::stationary;
    }
  }
  // Every node lies on the line: one below the minimum found means a minimum was missed (two
  // sign changes of dFn/ds between two nodes). Only the admissible nodes count.
  for (std::size_t i = 0; i <= last && i < nodes.size(); ++i)
    if (nodes[i].z[0] < min_fn - T(64) * std::numeric_limits<T>::epsilon() * std::max(T(1), fabs(min_fn)))
      certified = false;
  if (!certified) {
    c.min_status = minimum_status::not_certified;
    return c;
  }
  const bool complete = line.end == line_end::reached_ft_end || line.end == line_end::reached_ft_max ||
                        line.end == line_end::turned_back;
  c.min_status = complete || !c.admissible_to_end ? kind : minimum_status::line_incomplete;
  c.min_fn = min_fn;
  c.ft_at_min_fn = sys.ft_of(min_mu);
  c.slope_at_min_fn = min_slope;
  c.min_fn_interior = kind == minimum_status::stationary;
  c.max_pull_off = c.min_fn < 0 ? -c.min_fn : T(0);
  if (c.min_status == minimum_status::line_incomplete ||
      (c.min_status == minimum_status::range_end && line.end != line_end::reached_ft_max)) {
    c.max_pull_off_bound = c.max_pull_off;
    c.max_pull_off_is_bound = true;
    c.max_pull_off = std::numeric_limits<T>::quiet_NaN();
  }
  // The paper's k (eq (16)) over the lower part [0, Ft*].
  const T ft_star = c.ft_at_min_fn;
  if (ft_star > 0 && c.fn0 == c.fn0 &&
      (c.min_status == minimum_status::stationary || c.min_status == minimum_status::admissible_end ||
       c.min_status == minimum_status::range_end)) {
    const auto& q = gauss_legendre16<T>::get();
    T ft[16];
    std::size_t which[16];
    critical_state<T> st[16];
    for (int i = 0; i < 16; ++i) {
      ft[i] = ft_star * q.x[i];
      which[i] = static_cast<std::size_t>(i);
    }
    evaluate_line(sys, line, ft, 16, which, opt.tolerance, st);
    T num = 0;
    bool ok = true;
    for (int i = 0; i < 16; ++i) {
      if (st[i].status != critical_status::converged) ok = false;
      num += q.w[i] * ft[i] * (st[i].Fn - c.fn0);
    }
    // int_0^Ft* Ft (Fn - Fn0) dFt = Ft* * sum w_i Ft_i (Fn_i - Fn0); int_0^Ft* Ft^2 dFt = Ft*^3/3
    if (ok) c.paper_k = 3 * num / (ft_star * ft_star);
  }
  return c;
}

}  // namespace detail

template <class T, class Policy = policies::default_policy>
inline seta_characteristics<T> characteristics(const TwoLevelSeta<T>& seta,
                                               const critical_line_options<T>& options = critical_line_options<T>(),
                                               const Policy& = Policy()) {
  constexpr const char* fn = "gecko::characteristics";
  if (!detail::check_seta<T, Policy>(seta, fn)) return seta_characteristics<T>();
  if (options.ft_end == options.ft_end && !detail::check_ft<T, Policy>(options.ft_end, ft_max(seta), fn))
    return seta_characteristics<T>();
  return detail::visit_extensibility(seta, [&](auto E1, auto E2) {
    return detail::characteristics_imp<Policy, decltype(E1)::value, decltype(E2)::value>(seta, options);
  });
}

}  // namespace gecko
