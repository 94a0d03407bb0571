// gecko/seta/detail/natural_state.hpp — the natural state at Ft = 0 without a guess.
//
// docs/theory/two_level_seta.md "Critical line of adhesion": homotopy from the small-deformation
// limit (paper 001 eq 18), scaling the angle deficit pi/2 - alpha1 - alpha2 by lambda and w by
// lambda^2 (the linear theory is exact as lambda -> 0), lambda = 0.02 -> 1, each step a Newton
// solve at Ft = 0 from a secant prediction in lambda.
#pragma once

#include <Eigen/Dense>

#include "gecko/seta/detail/continuation.hpp"
#include "gecko/seta/solve_critical.hpp"

namespace gecko {
namespace detail {

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

}  // namespace detail
}  // namespace gecko
