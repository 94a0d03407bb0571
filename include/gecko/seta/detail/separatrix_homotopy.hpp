// gecko/seta/detail/separatrix_homotopy.hpp — the separatrix limit system along the natural-state
// homotopy, as a curve in (z, lambda).
//
// The natural state's homotopy (detail/natural_state.hpp) follows the separatrix limit system
// (detail/separatrix_limit.hpp) in lambda where the full system stalls next to a separatrix. Its
// monotone steps in lambda cannot pass a fold of that path in lambda; this System presents the
// limit system at Ft = 0 with lambda (scaled) as its line parameter, so that the pseudo-arclength
// follower of detail/continuation.hpp follows it there, as homotopy_system
// (detail/homotopy_system.hpp) does for the full system. dF/dlambda is a central difference, as
// there: it enters only the tangent and the bordered corrector's last column, and the state at
// lambda = 1 is corrected and certified afterwards (separatrix_target_state).
#pragma once

#include "gecko/seta/detail/homotopy_system.hpp"
#include "gecko/seta/detail/separatrix_limit.hpp"

namespace gecko {
namespace detail {

template <class T, class Policy, bool E1, bool E2>
struct separatrix_homotopy_system {
  using base_type = seta_system<T, Policy, E1, E2>;
  using limit_type = separatrix_system<T, Policy, E1, E2>;
  static constexpr int n = 4;
  using value_type = T;
  using vec = typename base_type::vec;
  using mat = typename base_type::mat;
  using plan_type = seta_plan;

  const base_type& base;
  homotopy_path<T> path;
  T scale;  // the line parameter is mu = scale x lambda (see homotopy_system)
  int mask;

  // The limit system holds its base by reference: each call builds the design at lambda first.
  bool eval(const vec& z, T mu, const plan_type& plan, vec& F, mat& J, vec* dF_dmu, T u14[2]) const {
    if (!(mu > 0)) return false;
    {
      const base_type at = path.at(base, mu / scale);
      if (!limit_type{at, mask}.eval(z, T(0), plan, F, J, nullptr, u14)) return false;
    }
    if (!dF_dmu) return true;
    // As homotopy_system: h = 1e-5 mu balances truncation ~h^2 and rounding ~eps/h.
    const T h = T(1e-5) * mu;
    vec Fp, Fm;
    mat Jh;
    T uh[2];
    const base_type up = path.at(base, (mu + h) / scale), down = path.at(base, (mu - h) / scale);
    if (!limit_type{up, mask}.eval(z, T(0), plan, Fp, Jh, nullptr, uh)) return false;
    if (!limit_type{down, mask}.eval(z, T(0), plan, Fm, Jh, nullptr, uh)) return false;
    *dF_dmu = (Fp - Fm) / (2 * h);
    return dF_dmu->allFinite();
  }
  // The limit system's plan already counts periods from the segments' lengths (plan_at_solution).
  plan_type plan(const vec& z, T mu) const {
    const base_type at = path.at(base, mu / scale);
    return limit_type{at, mask}.plan(z, T(0));
  }
  plan_type plan_solved(const vec& z, T mu) const { return plan(z, mu); }
  static segment_state plan_state(const plan_type& p) { return base_type::plan_state(p); }
  bool plan_valid(const plan_type& p, const vec& z, T mu, const T u14[2]) const {
    const base_type at = path.at(base, mu / scale);
    return limit_type{at, mask}.plan_valid(p, z, T(0), u14);
  }
  T step_norm(const vec& dz, const vec& z) const { return base.step_norm(dz, z); }
};

}  // namespace detail
}  // namespace gecko
