// gecko/seta/detail/continuation.hpp — following a solution curve F(z, Ft) = 0 through folds.
//
// Pseudo-arclength continuation (Keller 1977; Allgower & Georg, "Numerical Continuation
// Methods", 1990, ch. 2) in x = (z, Ft): tangent t from [J_z J_Ft; t_prev^T] t = e_last,
// predictor x + ds t, corrector Newton on [F; t.(x - x_pred)] = 0 with the same affine-invariant
// damping as gecko/seta/detail/newton.hpp, step size adapted to the corrector's iteration count.
// The bordered system stays regular at a fold (dFt/ds = 0), so the line is followed around it.
// The Carlson plan is held fixed during a corrector and refreshed between steps
// (gecko/seta/elastica_segment.hpp). Also: the natural state by homotopy, and the dense-output
// evaluation of the line at requested Ft values (cubic Hermite guess + Newton at fixed Ft).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "gecko/seta/detail/newton.hpp"
#include "gecko/seta/detail/plan_at_solution.hpp"
#include "gecko/seta/elastica_segment.hpp"

namespace gecko {

// Why a followed critical line stopped.
enum class line_end : int {
  reached_ft_end = 0,     // reached the requested end of the Ft range
  reached_ft_max = 1,     // reached (Ft)max = sqrt(2 EA2 w), where the critical line ends
  turned_back = 2,        // after a fold the line came back below its starting Ft
  no_convergence = 3,     // the corrector failed even with the smallest step (singular point)
  unsupported_state = 4,  // the states left the model (axial load comparable to EA): the edge of the
                          // forms, or for the critical line a state compressed to zero length
  max_points = 5,         // the point budget ran out
  no_natural_state = 6,   // the natural state at Ft = 0 was not found
  stalled = 7             // the step collapsed: the line crawls (see continuation_options)
};

namespace detail {

template <class T, int N>
struct line_node {
  Eigen::Matrix<T, N, 1> z;
  T Ft;
  Eigen::Matrix<T, N + 1, 1> tangent;  // unit tangent in (z, Ft), oriented along the line
  int branch;                           // folds passed so far
};

template <class System>
struct traced_line {
  using T = typename System::value_type;
  std::vector<line_node<T, System::n>> nodes;
  std::vector<typename System::plan_type> plans;
  // dF/dz at each node (from its tangent's evaluation): the chord steps of the dense output
  // (gecko/seta/detail/line_output.hpp) reuse it instead of forming a Jacobian per output.
  std::vector<typename System::mat> jacobians;
  std::vector<T> folds;  // Ft at the folds (dFt/ds = 0), linearly located between nodes
  line_end end = line_end::reached_ft_end;
  T omega = 0;           // largest affine Lipschitz estimate 2 theta / ||dx|| seen by the corrector
  int direction = 1;     // the direction in mu it was followed in (+1: increasing Ft)
};

// The line parameter mu is the System's (Ft, or tau with Ft = (Ft)max sin(tau/(Ft)max)).
template <class T>
struct continuation_options {
  T ft_stop;                // stop at this mu (inclusive), in the direction of travel
  T ft_max;                 // the line ends at |mu| = ft_max (infinity: no end)
  T scale;                  // force scale for step sizes
  T tolerance = T(1e-11);   // corrector tolerance along the line (output points are re-solved)
  T max_step = T(0.08);     // largest arclength step, as a fraction of scale
  int max_nodes = 100000;
  // Stall test, bounding the cost where the step collapses (bench/results/stress.md: lines that
  // run along the edge of the region where the forms exist, every other predictor outside it,
  // took up to 10^5 nodes and several seconds for a few percent of the range). The line ends
  // (line_end::stalled) when stall_window corrector attempts, failed ones included, advance it by
  // less than stall_fraction x scale of arclength in (z, mu). A healthy line advances by at
  // least 1e-3 x scale per node, so 1000 nodes cover a full scale.
  int stall_window = 1000;
  T stall_fraction = T(0.01);
};

template <class System>
inline bool tangent_at(const System& sys, const typename System::vec& z, typename System::value_type Ft,
                       const typename System::plan_type& plan,
                       const Eigen::Matrix<typename System::value_type, System::n + 1, 1>& previous,
                       Eigen::Matrix<typename System::value_type, System::n + 1, 1>& t,
                       typename System::mat* J_out = nullptr) {
  using T = typename System::value_type;
  constexpr int n = System::n;
  typename System::vec F, JFt;
  typename System::mat J;
  T u14[2];
  if (!sys.eval(z, Ft, plan, F, J, &JFt, u14)) return false;
  if (J_out) *J_out = J;
  Eigen::Matrix<T, n + 1, n + 1> A;
  A.template topLeftCorner<n, n>() = J;
  A.template topRightCorner<n, 1>() = JFt;
  A.template bottomRows<1>() = previous.transpose();
  Eigen::Matrix<T, n + 1, 1> rhs = Eigen::Matrix<T, n + 1, 1>::Zero();
  rhs[n] = 1;
  t = A.partialPivLu().solve(rhs);
  if (!t.allFinite()) return false;
  t.normalize();
  return true;
}

// Corrector: Newton on [F(z, Ft); t.(x - xp)] = 0 from xp.
template <class System>
inline bool arclength_corrector(const System& sys, Eigen::Matrix<typename System::value_type, System::n + 1, 1>& x,
                                const Eigen::Matrix<typename System::value_type, System::n + 1, 1>& t,
                                const typename System::plan_type& plan, typename System::value_type tol,
                                typename System::value_type scale, int& iterations, typename System::value_type u14[2],
                                typename System::value_type& omega) {
  using T = typename System::value_type;
  constexpr int n = System::n;
  using xvec = Eigen::Matrix<T, n + 1, 1>;
  using xmat = Eigen::Matrix<T, n + 1, n + 1>;
  const xvec xp = x;
  auto norm = [&](const xvec& dx, const xvec& at) {
    using std::fabs;
    const typename System::vec dz = dx.template head<n>(), zz = at.template head<n>();
    T m = sys.step_norm(dz, zz);
    const T f = fabs(dx[n]) / scale;
    return f > m ? f : m;
  };
  auto evaluate = [&](const xvec& at, xvec& G, xmat& JG, T u[2]) {
    typename System::vec F, JFt;
    typename System::mat J;
    if (!sys.eval(at.template head<n>(), at[n], plan, F, J, &JFt, u)) return false;
    G.template head<n>() = F;
    G[n] = t.dot(at - xp);
    JG.template topLeftCorner<n, n>() = J;
    JG.template topRightCorner<n, 1>() = JFt;
    JG.template bottomRows<1>() = t.transpose();
    return true;
  };
  xvec G, Gt;
  xmat JG, JGt;
  T ut[2];
  iterations = 1;
  if (!evaluate(x, G, JG, u14)) return false;
  for (int it = 0; it < 12; ++it) {
    const Eigen::PartialPivLU<xmat> lu(JG);
    const xvec dx = -lu.solve(G);
    if (!dx.allFinite()) return false;
    const T nd = norm(dx, x);
    if (nd <= tol) {
      x += dx;
      return true;
    }
    T lambda = 1;
    for (;;) {
      const xvec xt = x + lambda * dx;
      ++iterations;
      if (evaluate(xt, Gt, JGt, ut)) {
        const xvec dxbar = -lu.solve(Gt);
        const T nb = norm(dxbar, xt);
        if (nb < nd) {
          if (lambda == 1 && nd > 0) {
            const T w = 2 * nb / (nd * nd);  // theta = nb/nd ~ omega ||dx|| / 2
            if (w > omega) omega = w;
          }
          x = xt;
          G = Gt;
          JG = JGt;
          u14[0] = ut[0];
          u14[1] = ut[1];
          if (lambda == 1 && nb <= tol) {
            x += dxbar;
            return true;
          }
          break;
        }
      }
      lambda /= 2;
      if (lambda < T(1) / 64) return false;
    }
    if (iterations > 10) return false;
  }
  return false;
}

// Follow the line from the solved state (z0, Ft0) in the direction dir (+1: increasing Ft).
template <class System>
inline traced_line<System> follow_line(const System& sys, const typename System::vec& z0,
                                       typename System::value_type Ft0, typename System::plan_type plan0,
                                       int dir, const continuation_options<typename System::value_type>& opt) {
  using T = typename System::value_type;
  using std::fabs;
  constexpr int n = System::n;
  using xvec = Eigen::Matrix<T, n + 1, 1>;
  traced_line<System> line;
  line.direction = dir;
  xvec t_prev = xvec::Zero();
  t_prev[n] = T(dir);
  xvec t;
  auto plan = plan0;
  typename System::mat J;
  if (!tangent_at(sys, z0, Ft0, plan, t_prev, t, &J)) {
    line.end = line_end::no_convergence;
    return line;
  }
  if (t[n] * dir < 0) t = -t;
  line.nodes.push_back({z0, Ft0, t, 0});
  line.plans.push_back(plan);
  line.jacobians.push_back(J);
  const T ds_max = opt.max_step * opt.scale;
  const T ds_min = T(1e-9) * opt.scale;
  T ds = (opt.max_step < T(0.02) ? opt.max_step : T(0.02)) * opt.scale;
  int branch = 0;
  const T ft_limit = opt.ft_stop;
  int attempts = 0;        // corrector attempts since the last stall check
  T advanced = 0;          // arclength covered since then
  while (static_cast<int>(line.nodes.size()) < opt.max_nodes) {
    if (++attempts > opt.stall_window) {
      if (advanced < opt.stall_fraction * opt.scale) {
        line.end = line_end::stalled;
        return line;
      }
      attempts = 1;
      advanced = 0;
    }
    const auto& last = line.nodes.back();
    xvec x0;
    x0.template head<n>() = last.z;
    x0[n] = last.Ft;
    const xvec tl = last.tangent;
    // Landing exactly on the end of the range when the step would pass it.
    xvec xp = x0 + ds * tl;
    if ((xp[n] - ft_limit) * dir >= 0 && tl[n] * dir > 0) {
      const typename System::vec z_guess = last.z + tl.template head<n>() * ((ft_limit - last.Ft) / tl[n]);
      typename System::vec z = z_guess;
      auto p = plan;
      int its = 0;
      const T u = ft_limit;
      bool ok = false;
      // Tolerances of the end state, tightest first: 1e-13 where that is attainable, else the
      // corrector's (the accuracy of every other node), and at the line's end (Ft)max sqrt(eps).
      // The scaled Newton step has a rounding floor: ~2e-12 near (Ft)max for Jacobians of
      // condition ~6e6, and at (Ft)max itself, where theta2'(a) = 0 puts the spatula's turning
      // point on the contact edge, the radicand of its angle form vanishes and rounding enters the
      // residual as sqrt(eps) (a residual floor ~1e-8, the step's ~1e-10). With 1e-13 alone such
      // lines never landed: they crawled into the end with halving steps and ended as
      // no_convergence (tests/seta/line_end.cpp).
      using std::sqrt;
      const bool line_end_here = opt.ft_max == fabs(ft_limit);
      const T tols[3] = {T(1e-13), opt.tolerance, line_end_here ? sqrt(std::numeric_limits<T>::epsilon()) : T(0)};
      T tried = 0;
      for (int attempt = 0; attempt < 3 && !ok; ++attempt) {
        if (!(tols[attempt] > tried)) continue;
        tried = tols[attempt];
        z = z_guess;
        p = plan;
        typename System::vec z_prev = z;
        for (int round = 0; round < 3 && !ok; ++round) {
          T u14[2] = {1, 1};
          if (System::plan_state(p) != segment_state::ok) break;
          const auto code = newton_fixed_ft(sys, z, u, p, tried, 30, its, u14);
          if (code != newton_code::converged) break;
          // Valid plan; or the state sits on the boundary between two forms (a turning point on
          // a segment's end, as at (Ft)max), where the plans alternate and both give it.
          if (sys.plan_valid(p, z, u, u14) || (round > 0 && sys.step_norm(z - z_prev, z) <= tried)) ok = true;
          else {
            z_prev = z;
            p = plan_at_solution(sys, z, u);
          }
        }
      }
      if (ok && (z - last.z).template lpNorm<Eigen::Infinity>() < 4 * ds) {
        xvec tn;
        if (tangent_at(sys, z, u, p, tl, tn, &J)) {
          line.nodes.push_back({z, u, tn, branch});
          line.plans.push_back(p);
          line.jacobians.push_back(J);
          line.end = (opt.ft_max == std::fabs(ft_limit)) ? line_end::reached_ft_max : line_end::reached_ft_end;
          return line;
        }
      }
      // Could not land (e.g. a fold just before the end): keep stepping with a smaller step.
      ds *= T(0.5);
      if (ds < ds_min) {
        line.end = line_end::no_convergence;
        return line;
      }
      continue;
    }
    xvec x = xp;
    int its = 0;
    T u14[2] = {1, 1};
    T omega = 0;
    bool ok = arclength_corrector(sys, x, tl, plan, opt.tolerance, opt.scale, its, u14, omega);
    auto p = plan;
    if (ok && !sys.plan_valid(p, x.template head<n>(), x[n], u14)) {
      // The state moved out of the plan: re-plan there and correct again. x solves the
      // equations (under the old plan), so its lengths give the period counts (plan_at_solution).
      p = plan_at_solution(sys, x.template head<n>(), x[n]);
      const segment_state st = System::plan_state(p);
      if (st == segment_state::unsupported) {
        line.end = line_end::unsupported_state;
        return line;
      }
      ok = st == segment_state::ok;
      if (ok) {
        x = xp;
        ok = arclength_corrector(sys, x, tl, p, opt.tolerance, opt.scale, its, u14, omega) &&
             sys.plan_valid(p, x.template head<n>(), x[n], u14);
      }
    }
    if (ok && (x - x0).norm() > 3 * ds) ok = false;  // jumped to another branch
    if (ok && fabs(x[n]) > opt.ft_max) ok = false;
    xvec tn;
    if (ok) ok = tangent_at(sys, x.template head<n>(), x[n], p, tl, tn, &J);
    if (!ok) {
      ds *= T(0.5);
      if (ds < ds_min) {
        // The step collapsed. Where even this shortest predictor leaves the forms for an axial
        // load comparable to EA (f4's root reaching the path, gecko/seta/elastica_segment.hpp),
        // the line has run into the edge of the model, not into a failure of the corrector:
        // the corrector's plan, made a step before, evaluates to NaN past that edge and never
        // converges. The states beyond are then unsupported (status 3), not unknown.
        const bool edge = System::plan_state(sys.plan(xp.template head<n>(), xp[n])) == segment_state::unsupported;
        line.end = edge ? line_end::unsupported_state : line_end::no_convergence;
        return line;
      }
      continue;
    }
    if (tn[n] * tl[n] < 0) {  // dFt/ds changed sign: a fold between the nodes
      const T f = tl[n] / (tl[n] - tn[n]);
      line.folds.push_back(last.Ft + f * (x[n] - last.Ft));
      ++branch;
    }
    // A fresh plan for the next step: a phase plan kept from a turning-point state would follow
    // the state into the libration/rotation change of a now monotone segment (K -> infinity),
    // where the direct form has no difficulty. x solves the equations, so the segments' lengths
    // fix the period counts of the fresh plan (plan_solved): the phases alone drop a period where
    // the ends' phases coincide, and the residual would jump by 4K from this node to the next.
    {
      const auto fresh = sys.plan_solved(x.template head<n>(), x[n]);
      if (System::plan_state(fresh) == segment_state::ok) p = fresh;
    }
    advanced += (x - x0).norm();
    line.nodes.push_back({x.template head<n>(), x[n], tn, branch});
    line.plans.push_back(p);
    line.jacobians.push_back(J);
    if (omega > line.omega) line.omega = omega;
    plan = p;
    if (branch > 0 && (x[n] - Ft0) * dir < -T(1e-3) * opt.scale) {
      line.end = line_end::turned_back;
      return line;
    }
    if (its <= 3) ds = ds * T(1.6) < ds_max ? ds * T(1.6) : ds_max;
    else if (its >= 6) ds *= T(0.6);
  }
  line.end = line_end::max_points;
  return line;
}

// Cubic Hermite guess on the line segment between nodes a and b, at mu = target (between their
// parameters). The scalar cubic mu(s) is solved by safeguarded Newton (bisection fallback), then
// all components are evaluated once. Returns false if the cubic misses the target.
template <class T, int N>
inline bool hermite_guess(const line_node<T, N>& a, const line_node<T, N>& b, T target,
                          Eigen::Matrix<T, N, 1>& z) {
  using std::fabs;
  Eigen::Matrix<T, N + 1, 1> xa, xb;
  xa.template head<N>() = a.z;
  xa[N] = a.Ft;
  xb.template head<N>() = b.z;
  xb[N] = b.Ft;
  const T h = (xb - xa).norm();
  const T ma = h * a.tangent[N], mb = h * b.tangent[N];
  // mu(s) = p0 + s (p1 + s (p2 + s p3)), the Hermite cubic of the parameter component.
  const T p0 = a.Ft, p1 = ma, p2 = 3 * (b.Ft - a.Ft) - 2 * ma - mb, p3 = 2 * (a.Ft - b.Ft) + ma + mb;
  auto f = [&](T s) { return p0 - target + s * (p1 + s * (p2 + s * p3)); };
  auto df = [&](T s) { return p1 + s * (2 * p2 + 3 * s * p3); };
  T lo = 0, hi = 1;
  T flo = f(lo);
  if (flo == 0) {
    z = a.z;
    return true;
  }
  // The end node itself: the cubic at s = 1 sums four terms and may round to the sign it has at
  // s = 0, which would discard an exact node and restart Newton from the previous one (a narrow
  // basin then fails: found by the scaling benchmark, 2 states in 2e6).
  if (b.Ft == target) {
    z = b.z;
    return true;
  }
  if ((flo < 0) == (f(hi) < 0)) return false;
  T sv = (target - a.Ft) / (b.Ft - a.Ft);
  if (!(sv > 0 && sv < 1)) sv = T(0.5);
  for (int i = 0; i < 60; ++i) {
    const T fs = f(sv);
    if (fs == 0) break;
    if ((fs < 0) == (flo < 0)) lo = sv;
    else hi = sv;
    T next = sv - fs / df(sv);
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (fabs(next - sv) <= 4 * std::numeric_limits<T>::epsilon()) {
      sv = next;
      break;
    }
    sv = next;
  }
  const T s = sv, s2 = s * s, s3 = s2 * s;
  z = ((2 * s3 - 3 * s2 + 1) * a.z + (s3 - 2 * s2 + s) * h * a.tangent.template head<N>() +
       (-2 * s3 + 3 * s2) * b.z + (s3 - s2) * h * b.tangent.template head<N>()).eval();
  return z.allFinite();
}

}  // namespace detail
}  // namespace gecko
