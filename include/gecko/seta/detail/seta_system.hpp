// gecko/seta/detail/seta_system.hpp — the critical-state equations of the two-level seta as a
// System for the Newton solver and the continuation (gecko/seta/detail/newton.hpp,
// gecko/seta/critical_line.hpp): residual and exact Jacobian through detail::dual
// (gecko/seta/critical_residual.hpp), plans, norms, and the small-deformation start.
// E1, E2: extensible beam / spatula, fixed at compile time (EA = infinity costs nothing).
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "gecko/core/policy.hpp"
#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/detail/dual.hpp"

namespace gecko {
namespace detail {

template <class T, class Policy, bool E1, bool E2>
struct seta_system {
  static constexpr int n = 4;
  using value_type = T;
  using vec = Eigen::Matrix<T, 4, 1>;
  using mat = Eigen::Matrix<T, 4, 4>;
  using plan_type = seta_plan;

  seta_params<T> d;
  T ftmax;  // (Ft)max = sqrt(2 EA2 w) (paper 001 eq (3)); infinity for an inextensible spatula
  // Largest admissible axial strain of a reported state (gecko/seta/admissibility.hpp).
  T strain_limit = std::numeric_limits<T>::infinity();

  explicit seta_system(const seta_params<T>& params, T strain_limit_ = std::numeric_limits<T>::infinity())
      : d(params), ftmax(E2 ? std::sqrt(2 * params.w / params.c2) : std::numeric_limits<T>::infinity()),
        strain_limit(strain_limit_) {}

  // The continuation parameter mu: tau with Ft = (Ft)max sin(tau/(Ft)max) for an extensible
  // spatula (smooth through the end of the line at Ft = (Ft)max, see make_seta_geometry), else Ft.
  T ft_of(T mu) const {
    using std::sin;
    if constexpr (E2) return ftmax * sin(mu / ftmax);
    else return mu;
  }
  T mu_of(T Ft) const {
    using std::asin;
    if constexpr (E2) return ftmax * asin(Ft / ftmax);
    else return Ft;
  }
  // The parameter range of the line (its ends at Ft = -+(Ft)max).
  T mu_limit() const {
    if constexpr (E2) return ftmax * seta_pi<T>() / 2;
    else return std::numeric_limits<T>::infinity();
  }
  template <class S>
  void forces(const S& mu, S& Ft, S& edge) const {
    using std::cos; using std::sin;
    if constexpr (E2) {
      const S a = mu / ftmax;
      Ft = ftmax * sin(a);
      edge = cos(a);
    } else {
      Ft = mu;
      edge = S(T(1));
    }
  }

  // F, dF/dz and (if dF_dmu) dF/dmu at (z, mu).
  bool eval(const vec& z, T mu, const plan_type& plan, vec& F, mat& J, vec* dF_dFt, T u14[2]) const {
    if (dF_dFt) {
      using S = dual<T, 5>;
      S r[4], Ft, edge;
      forces(S::variable(mu, 4), Ft, edge);
      seta_residual<Policy, E1, E2>(d, S::variable(z[0], 0), S::variable(z[1], 1), S::variable(z[2], 2),
                                    S::variable(z[3], 3), Ft, edge, plan, r, u14);
      for (int i = 0; i < 4; ++i) {
        F[i] = r[i].v;
        for (int j = 0; j < 4; ++j) J(i, j) = r[i].d[j];
        (*dF_dFt)[i] = r[i].d[4];
      }
      return F.allFinite() && J.allFinite() && dF_dFt->allFinite();
    }
    using S = dual<T, 4>;
    S r[4];
    T Ft, edge;
    forces(mu, Ft, edge);
    seta_residual<Policy, E1, E2>(d, S::variable(z[0], 0), S::variable(z[1], 1), S::variable(z[2], 2),
                                  S::variable(z[3], 3), S(Ft), S(edge), plan, r, u14);
    for (int i = 0; i < 4; ++i) {
      F[i] = r[i].v;
      for (int j = 0; j < 4; ++j) J(i, j) = r[i].d[j];
    }
    return F.allFinite() && J.allFinite();
  }

  // F alone (no Jacobian); u14, where given, as eval's.
  bool residual(const vec& z, T mu, const plan_type& plan, vec& F, T* u14 = nullptr) const {
    T r[4], Ft, edge;
    forces(mu, Ft, edge);
    seta_residual<Policy, E1, E2>(d, z[0], z[1], z[2], z[3], Ft, edge, plan, r, u14);
    for (int i = 0; i < 4; ++i) F[i] = r[i];
    return F.allFinite();
  }

  plan_type plan(const vec& z, T mu) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    return plan_seta<Policy, E1, E2>(d, z[0], z[1], z[2], z[3], Ft, edge);
  }
  // The plan at a state that solves the equations (a node of the followed line): the lengths
  // l1, l2 fix the libration period counts there (plan_seta).
  plan_type plan_solved(const vec& z, T mu) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    return plan_seta<Policy, E1, E2>(d, z[0], z[1], z[2], z[3], Ft, edge, true);
  }
  static segment_state plan_state(const plan_type& p) {
    if (p.beam.state == segment_state::unsupported || p.spatula.state == segment_state::unsupported)
      return segment_state::unsupported;
    if (p.beam.state != segment_state::ok || p.spatula.state != segment_state::ok)
      return segment_state::infeasible;
    return segment_state::ok;
  }
  bool plan_valid(const plan_type& p, const vec& z, T mu, const T u14[2]) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    return seta_plan_valid<E1, E2>(d, p, z[0], z[1], z[2], z[3], Ft, edge, u14);
  }

  // Scaled max norm: Fn relative to max(1, |Fn|) (the accuracy target), the angle absolute, the
  // rates relative to max(1, |rate|).
  T step_norm(const vec& dz, const vec& z) const {
    using std::fabs;
    T m = fabs(dz[0]) / (fabs(z[0]) > 1 ? fabs(z[0]) : T(1));
    const T b = fabs(dz[1]);
    const T p = fabs(dz[2]) / (fabs(z[2]) > 1 ? fabs(z[2]) : T(1));
    const T q = fabs(dz[3]) / (fabs(z[3]) > 1 ? fabs(z[3]) : T(1));
    if (b > m) m = b;
    if (p > m) m = p;
    if (q > m) m = q;
    return m;
  }

  // Linear (small-deformation) state at Ft = 0, docs/theory/two_level_seta.md eq 18 with its shape: the start of
  // the homotopy to the natural state.
  vec small_deformation_state() const {
    using std::sin; using std::sqrt;
    const T half_pi = seta_pi<T>() / 2;
    const T a12 = d.alpha1 + d.alpha2;
    const T Delta = half_pi - a12;
    const T Meq = sqrt(2 * d.EI2 * d.w);
    const T cP = d.l2 * d.l2 / (2 * d.EI2) + d.l1 * d.l2 / d.EI1;
    const T cQ = d.l1 * d.l1 / (2 * d.EI1);
    const T An = cP * sin(a12) + cQ * sin(d.alpha1);
    const T Fn = (Delta - Meq * (d.l2 / d.EI2 + d.l1 / d.EI1)) / An;  // (Fn)0, paper 001 eqs (19)-(20)
    const T P = Fn * sin(a12), Q = Fn * sin(d.alpha1);  // P, Q of paper 001 eq (18) at Ft = 0
    const T beta = a12 + Delta - Meq * d.l2 / d.EI2 - P * d.l2 * d.l2 / (2 * d.EI2);
    const T p = (Meq + P * d.l2) / sqrt(2 * d.EI2);
    const T q = (Meq + P * d.l2 + Q * d.l1) / sqrt(2 * d.EI1);
    vec z;
    z << Fn, beta, p, q;
    return z;
  }

  // The homotopy of the natural state: lambda in (0, 1] scales the angle deficit
  // pi/2 - alpha1 - alpha2 by lambda and w by lambda^2, so the state scales like lambda and is
  // given to O(lambda^2) by the linear theory as lambda -> 0.
  // lambda_w (default lambda) scales sqrt(w) separately: other paths to the same end at
  // lambda = lambda_w = 1 (gecko/seta/detail/natural_state.hpp tries them when one stalls).
  seta_system at_homotopy(T lambda) const { return at_homotopy(lambda, lambda); }
  seta_system at_homotopy(T lambda, T lambda_w) const {
    seta_params<T> h = d;
    const T half_pi = seta_pi<T>() / 2;
    const T a12 = d.alpha1 + d.alpha2;
    const T Delta = half_pi - a12;
    const T extra = (1 - lambda) * Delta;
    h.alpha1 = d.alpha1 + extra * d.alpha1 / a12;
    h.alpha2 = d.alpha2 + extra * d.alpha2 / a12;
    h.w = d.w * lambda_w * lambda_w;
    set_seta_angles(h);
    return seta_system(h);
  }

  T theta_joint(const vec& z) const { return z[1]; }
  // Rates of the state for reporting: theta2'(l1), theta1'(0).
  T rate_joint(const vec& z) const { using std::sqrt; return z[2] * sqrt(2 / d.EI2); }
  T rate_base(const vec& z) const { using std::sqrt; return z[3] * sqrt(2 / d.EI1); }

  // Unknowns from (Fn, beta) and optional rates (NaN: the rate of the monotone branch, >= 0).
  vec from_guess(T Fn, T beta, T rate_joint, T rate_base, T Ft) const {
    using std::sin; using std::sqrt; using std::atan2; using std::hypot;
    vec z;
    z[0] = Fn;
    z[1] = beta;
    const T N = hypot(Fn, Ft), phi = atan2(Fn, Ft);
    if (rate_joint == rate_joint) {
      z[2] = rate_joint * sqrt(d.EI2 / 2);
    } else {
      const T u = sin(beta - phi);
      const T R2 = Ft + d.w - N * u - d.c2 * N * N * u * u / 2;
      z[2] = R2 > 0 ? sqrt(R2) : T(0);
    }
    if (rate_base == rate_base) {
      z[3] = rate_base * sqrt(d.EI1 / 2);
    } else {
      const T v = sin(beta - d.alpha2 - phi), u0 = sin(d.alpha1 - phi);
      const T R1 = d.EI2 / d.EI1 * z[2] * z[2] + N * (v - u0) + d.c1 * N * N * (v * v - u0 * u0) / 2;
      z[3] = R1 > 0 ? sqrt(R1) : T(0);
    }
    return z;
  }

  void turning_points(const plan_type& p, const vec& z, T mu, int& beam, int& spatula) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    seta_turning_points<Policy, E1, E2>(d, p, z[0], z[1], z[2], z[3], Ft, edge, beam, spatula);
  }
  // plan_valid, and where it holds turning_points, from one geometry.
  bool plan_valid_turning_points(const plan_type& p, const vec& z, T mu, const T u14[2], int& beam,
                                 int& spatula) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    return seta_plan_valid_turning_points<Policy, E1, E2>(d, p, z[0], z[1], z[2], z[3], Ft, edge, u14, beam, spatula);
  }
};

}  // namespace detail
}  // namespace gecko
