// gecko/seta/detail/line_output.hpp — dense output of a traced critical line.
//
// States at requested Ft values (the first crossing along the line, a cubic Hermite guess between
// nodes, then Newton at that Ft to full accuracy) and the re-solve of traced nodes to the state
// tolerance (Newton at the node's line parameter, or the bordered arclength corrector at a fold).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "gecko/seta/critical_line_types.hpp"
#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/detail/line_trace.hpp"

namespace gecko {
namespace detail {

// The state at line parameter mu from the guess z by chord steps: Newton steps with a fixed
// matrix in place of the Jacobian and residuals alone, which cost a fraction of a residual with
// its Jacobian (forward-mode duals in four directions: five numbers through every operation,
// derivatives of every Carlson form). The matrix is the Jacobian
// interpolated linearly between the two nodes around mu, J = J_near + E (E = w (J_other -
// J_near), w the fraction of the way to the other node), applied to first order, (J_near + E)^-1
// ~ J_near^-1 - J_near^-1 E J_near^-1: two products with the near node's inverse Jacobian Jinv
// (formed once per node from its LU factorisation; 4x4 products cost no divisions, where two
// triangular solves per step would), no factorisation per state. From the line's cubic Hermite guess (accurate to ~1e-7) the steps
// contract by theta ~ omega |z - z_line(mu)| plus the interpolation's error. A step is accepted
// as the last one when it is below tol and the contraction measured on it, ||dz_k|| /
// ||dz_k-1||, is at most 1/4: the error left after it is then below theta/(1 - theta) ||dz_k||
// <= tol/3. (Accepting from the measured contraction before a step falls below tol was tried:
// it missed the tolerance, the scaled max norm's ratio does not bound the error's.) False,
// with z unchanged, when a residual fails or the steps do not contract (the caller then runs
// Newton from the guess). evaluations: residuals evaluated; u14 as the last one left it (for
// plan_valid).
template <class System, class T>
inline bool chord_solve(const System& sys, const typename System::mat& Jinv,
                        const typename System::mat& E, typename System::vec& z, T mu,
                        const typename System::plan_type& plan, T tol, int& evaluations, T u14[2]) {
  using vec = typename System::vec;
  vec x = z, F;
  T previous = 0;
  for (int k = 0; k < 8; ++k) {
    ++evaluations;
    if (!sys.residual(x, mu, plan, F, u14)) return false;
    vec dx = -(Jinv * F);
    dx -= Jinv * (E * dx);
    if (!dx.allFinite()) return false;
    const T nd = sys.step_norm(dx, x);
    if (k > 0 && !(nd <= previous / 4)) return false;
    x += dx;
    if (k > 0 && nd <= tol) {
      z = x;
      return true;
    }
    previous = nd;
  }
  return false;
}

// An LU object in place of Jinv would convert to a matrix silently (Eigen evaluates it) and
// iterate with the wrong matrix: refused at compile time.
template <class System, class T>
bool chord_solve(const System&, const Eigen::PartialPivLU<typename System::mat>&, const typename System::mat&,
                 typename System::vec&, T, const typename System::plan_type&, T, int&, T*) = delete;

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
  // The nodes' inverse Jacobians, formed when a state first needs them (chord_solve).
  const bool chord = line.jacobians.size() == all.size();
  std::vector<typename System::mat> inverses(chord ? all.size() : 0);
  std::vector<char> factorised(inverses.size(), 0);
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
      // The cubic Hermite guess, formed once: every attempt below starts from it.
      Eigen::Matrix<T, n, 1> guess;
      if (!hermite_guess(nodes[i], nodes[i + 1], target, guess)) guess = nodes[i].z;
      Eigen::Matrix<T, n, 1> z = guess;
      using std::fabs;
      const std::size_t near = fabs(a) <= fabs(b) ? i : i + 1;
      auto plan = line.plans[near];
      int its = 0;
      critical_status st = critical_status::not_converged;
      int turning[2] = {0, 0};
      bool have_turning = false;  // the chord steps' plan check counted them (same z, same plan)
      if (chord) {
        if (!factorised[near]) {
          inverses[near] = line.jacobians[near].partialPivLu().inverse();
          factorised[near] = 1;
        }
        const std::size_t other = near == i ? i + 1 : i;
        const T w = (target - nodes[near].Ft) / (nodes[other].Ft - nodes[near].Ft);
        const typename System::mat E = w * (line.jacobians[other] - line.jacobians[near]);
        T u14[2] = {1, 1};
        if (chord_solve(sys, inverses[near], E, z, target, plan, tol, its, u14) &&
            sys.plan_valid_turning_points(plan, z, target, u14, turning[0], turning[1])) {
          st = critical_status::converged;
          have_turning = true;
        }
      }
      // Newton from the guess where the chord steps did not settle it. omega: the line's
      // Lipschitz estimate with a safety factor of 4 (early acceptance of the first Newton step,
      // see newton_fixed_ft); 0 when the line gave none.
      if (st != critical_status::converged) {
        z = guess;
        int newton_its = 0;
        st = solve_with_plans(sys, z, target, plan, tol, 40, newton_its, 4 * line.omega);
        its += newton_its;
      }
      if (st != critical_status::converged) {
        // Second chance: plan from the guess itself (the state may sit between two plans).
        Eigen::Matrix<T, n, 1> z2 = guess;
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
      r = state_from(sys, z, Ft[idx], target, plan, st, its, have_turning ? turning : nullptr);
      break;
    }
    out[idx] = r;
  }
}

// Re-solve traced node i to tol (see critical_line_options::resolve_nodes). First by chord steps
// with the node's Jacobian, then by Newton at the node's own line parameter; at a fold that
// Jacobian is singular (dmu/ds = 0), so then by the bordered arclength corrector, which moves the
// node orthogonally to the line's tangent. A re-solved state more than 1e-6 (scaled) from the node
// is not accepted: the node itself is within ~1e-8 of the line, so such a state is the other
// branch near a fold.
template <class System, class T>
inline critical_status resolve_node(const System& sys, const traced_line<System>& line, std::size_t i, T scale,
                                    T tol, line_node<T, System::n>& node, typename System::plan_type& plan) {
  constexpr int n = System::n;
  using std::fabs;
  const auto& orig = line.nodes[i];
  const T max_move = T(1e-6);
  if (line.jacobians.size() == line.nodes.size()) {
    // Chord steps with the node's own Jacobian (exact there; the node is within the line
    // tolerance of the state, so two residuals settle it).
    typename System::vec z = orig.z;
    T u14[2] = {1, 1};
    int its = 0;
    const typename System::mat Jinv = line.jacobians[i].partialPivLu().inverse();
    if (chord_solve(sys, Jinv, typename System::mat(System::mat::Zero()), z, orig.Ft, line.plans[i], tol, its, u14) &&
        sys.plan_valid(line.plans[i], z, orig.Ft, u14) && sys.step_norm(z - orig.z, orig.z) <= max_move) {
      node.z = z;
      plan = line.plans[i];
      return critical_status::converged;
    }
  }
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

}  // namespace detail
}  // namespace gecko
