// gecko/seta/detail/homotopy_system.hpp — the natural-state homotopy as a curve in (z, lambda).
//
// docs/theory/two_level_seta.md "Critical line of adhesion": the natural state at Ft = 0 is reached
// by a homotopy from the small-deformation limit (paper 001 eq 18): System::at_homotopy(la, lw)
// scales the angle deficit pi/2 - alpha1 - alpha2 by la and w by lw^2. A homotopy_path picks how
// (la, lw) move with one parameter lambda in (0, 1]; all paths end at the design (la = lw = 1),
// and the linear theory is exact at their start as lambda -> 0. homotopy_system presents F(z; lambda)
// at Ft = 0 as a System whose line parameter is lambda (scaled), so the pseudo-arclength follower
// of gecko/seta/detail/continuation.hpp (bordered corrector, regular at folds in lambda; plan
// refresh when a segment crosses a form boundary) can follow the path where stepping lambda
// monotonically stalls. dF/dlambda is a central difference (the homotopy's parameters are plain
// numbers in System): it only enters the tangent and the bordered corrector's last column, and the
// state is polished at lambda = 1 by Newton with the exact Jacobian afterwards.
#pragma once

#include <cmath>

#include "gecko/seta/elastica_segment.hpp"

namespace gecko {
namespace detail {

// la = lambda^angle_power, lw = lambda^w_power. (1, 1): the paper's homotopy (deficit and sqrt(w)
// together). Other powers give other paths through the design space to the same end, used when
// the first one runs into a fold in lambda or the edge of the forms.
template <class T>
struct homotopy_path {
  int angle_power = 1;
  int w_power = 1;
  template <class System>
  System at(const System& sys, T lambda) const {
    return sys.at_homotopy(ipow(lambda, angle_power), ipow(lambda, w_power));
  }
  static T ipow(T x, int k) {
    T r = 1;
    for (int i = 0; i < k; ++i) r *= x;
    return r;
  }
};

template <class System>
struct homotopy_system {
  static constexpr int n = System::n;
  using value_type = typename System::value_type;
  using T = value_type;
  using vec = typename System::vec;
  using mat = typename System::mat;
  using plan_type = typename System::plan_type;

  const System& base;
  homotopy_path<T> path;
  // The line parameter is mu = scale x lambda: the state grows like lambda (eq 18), so with scale
  // ~ |z|/lambda an arclength step moves lambda and z alike (the follower's step sizes and its
  // norm of the parameter are in units of its scale).
  T scale;

  System at(T mu) const { return path.at(base, mu / scale); }

  // Ft = 0 throughout: the line parameter of the base system is 0.
  bool eval(const vec& z, T mu, const plan_type& plan, vec& F, mat& J, vec* dF_dmu, T u14[2]) const {
    if (!(mu > 0)) return false;
    if (!at(mu).eval(z, T(0), plan, F, J, nullptr, u14)) return false;
    if (!dF_dmu) return true;
    // Central difference: truncation ~h^2, rounding ~eps/h; h = 1e-5 mu balances them near 1e-10.
    const T h = T(1e-5) * mu;
    vec Fp, Fm;
    mat Jh;
    T uh[2];
    if (!at(mu + h).eval(z, T(0), plan, Fp, Jh, nullptr, uh)) return false;
    if (!at(mu - h).eval(z, T(0), plan, Fm, Jh, nullptr, uh)) return false;
    *dF_dmu = (Fp - Fm) / (2 * h);
    return dF_dmu->allFinite();
  }
  plan_type plan(const vec& z, T mu) const { return at(mu).plan(z, T(0)); }
  plan_type plan_solved(const vec& z, T mu) const { return at(mu).plan_solved(z, T(0)); }
  static segment_state plan_state(const plan_type& p) { return System::plan_state(p); }
  bool plan_valid(const plan_type& p, const vec& z, T mu, const T u14[2]) const {
    return at(mu).plan_valid(p, z, T(0), u14);
  }
  T step_norm(const vec& dz, const vec& z) const { return base.step_norm(dz, z); }
};

}  // namespace detail
}  // namespace gecko
