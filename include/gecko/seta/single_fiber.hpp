// gecko/seta/single_fiber.hpp — the single-level fiber of He et al. 2013 (docs/theory/two_level_seta.md,
// "Single-level fiber", used in Fig 4): one segment of length l, EI, EA, base angle alpha, with
// M = Ft + w and l = int_alpha^{pi/2} dtheta / theta'(theta) at the critical state.
// Same machinery as the two-level seta: Carlson forms (gecko/seta/elastica_segment.hpp), unknowns
// z = (Fn, q = sqrt(EI/2) theta'(0)) with F1 = L - l, F2 = q^2 - R(alpha), exact Jacobian, the
// natural state by homotopy from the linear theory, pseudo-arclength continuation.
// Results come as critical_state with theta_joint = NaN (no joint); the fiber's turning points
// are reported in turning_points_beam.
// Defaults: EI = 1/2, EA = 50, l = 1, w = 1 (Fig 4: EI/(w l^2) = 1/2, EA/w = 50), alpha = pi/3
// (the reference seta's alpha1 + alpha2).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/elastica_segment.hpp"
#include "gecko/seta/extensibility.hpp"

namespace gecko {

template <class T = double>
struct SingleFiber {
  T EI = T(0.5);
  T EA = T(50);
  T l = T(1);
  T alpha = T(1.047197551196597746154214461093167628L);  // pi/3
  T w = T(1);
};

template <class T>
inline T ft_max(const SingleFiber<T>& f) {
  using std::sqrt;
  return sqrt(2 * f.EA * f.w);
}

namespace detail {

template <class T, class Policy>
inline bool check_fiber(const SingleFiber<T>& f, const char* function) {
  using std::isfinite;
  const T half_pi = T(1.570796326794896619231321691639751442L);
  if (!(f.EI > 0 && isfinite(f.EI))) { raise_domain_error<T, Policy>(function, "EI", f.EI, "0 < EI < infinity"); return false; }
  if (!(f.EA > 0)) { raise_domain_error<T, Policy>(function, "EA", f.EA, "EA > 0 (infinity allowed: inextensible)"); return false; }
  if (!(f.l > 0 && isfinite(f.l))) { raise_domain_error<T, Policy>(function, "l", f.l, "0 < l < infinity"); return false; }
  if (!(f.w > 0 && isfinite(f.w))) { raise_domain_error<T, Policy>(function, "w", f.w, "0 < w < infinity"); return false; }
  if (!(f.alpha > 0 && f.alpha < half_pi)) { raise_domain_error<T, Policy>(function, "alpha", f.alpha, "0 < alpha < pi/2"); return false; }
  return true;
}

template <class T, class Policy, bool E>
struct fiber_system {
  static constexpr int n = 2;
  using value_type = T;
  using vec = Eigen::Matrix<T, 2, 1>;
  using mat = Eigen::Matrix<T, 2, 2>;
  using plan_type = segment_plan;

  T EI, c, l, alpha, w;
  T sa, ca, sh, ch, sm, cm;  // sin/cos of alpha, of h = (pi/2 - alpha)/2, of (pi/2 + alpha)/2
  T ftmax;

  fiber_system(T EI_, T c_, T l_, T alpha_, T w_) : EI(EI_), c(c_), l(l_), alpha(alpha_), w(w_) {
    using std::cos; using std::sin; using std::sqrt;
    const T half_pi = seta_pi<T>() / 2;
    sa = sin(alpha); ca = cos(alpha);
    sh = sin((half_pi - alpha) / 2); ch = cos((half_pi - alpha) / 2);
    sm = sin((half_pi + alpha) / 2); cm = cos((half_pi + alpha) / 2);
    ftmax = E ? sqrt(2 * w / c) : std::numeric_limits<T>::infinity();
  }

  T ft_of(T mu) const { using std::sin; if constexpr (E) return ftmax * sin(mu / ftmax); else return mu; }
  T mu_of(T Ft) const { using std::asin; if constexpr (E) return ftmax * asin(Ft / ftmax); else return Ft; }
  T mu_limit() const {
    if constexpr (E) return ftmax * seta_pi<T>() / 2;
    else return std::numeric_limits<T>::infinity();
  }
  template <class S>
  void forces(const S& mu, S& Ft, S& edge) const {
    using std::cos; using std::sin;
    if constexpr (E) { const S a = mu / ftmax; Ft = ftmax * sin(a); edge = cos(a); }
    else { Ft = mu; edge = S(T(1)); }
  }

  // Geometry and residual of the fiber (see the header comment).
  template <class S>
  void residual_imp(const S& Fn, const S& q, const S& Ft, const S& edge, const segment_plan& plan, S F[2],
                    T* u14, bool angles_only_plan, segment_plan* planned, T* h_out,
                    T target = std::numeric_limits<T>::quiet_NaN()) const {
    using std::atan2; using std::sqrt;
    const S N = sqrt(Fn * Fn + Ft * Ft);
    const S cphi = Ft / N, sphi = Fn / N;
    const S M = Ft + w;  // the contact-edge first integral, paper 001 eq (9)
    const auto g = make_segment<E>(S(EI), S(c), M, N);
    const S u0 = sa * cphi - ca * sphi;
    const S X3s = q / seg_sqrt_f4(g, u0);
    S X3e;
    if constexpr (E) X3e = sqrt(S(w)) * edge / seg_sqrt_f4(g, cphi);
    else X3e = sqrt(S(w)) * edge;
    const direct_trig<S> trig{cphi, u0, S(sh), S(ch), sm * cphi - cm * sphi};
    S psi_s = S(T(0)), psi_e = S(T(0));
    if (!plan.direct || angles_only_plan) {
      const S phi = atan2(Fn, Ft);
      psi_s = alpha - phi;
      psi_e = T(seta_pi<T>() / 2) - phi;
    }
    if (h_out) *h_out = (seta_pi<T>() / 2 - alpha) / 2;
    if (planned) {
      if constexpr (!is_dual<S>::value) {
        T* const no_length = nullptr;
        const libration_end<T>* const no_end = nullptr;
        *planned = plan_segment<Policy>(g, psi_s, X3s, psi_e, X3e, T(0.75), no_length, no_end, target);
      }
      return;
    }
    T u = 1;
    F[0] = segment_length<Policy>(g, plan, psi_s, X3s, psi_e, X3e, &u, &trig) - l;
    S R = M - N * u0;
    if constexpr (E) R = R - c * N * N * u0 * u0 * T(0.5);
    F[1] = q * q - R;
    if (u14) { u14[0] = u; u14[1] = 1; }
  }

  bool eval(const vec& z, T mu, const plan_type& plan, vec& F, mat& J, vec* dF, T u14[2]) const {
    if (dF) {
      using S = dual<T, 3>;
      S r[2], Ft, edge;
      forces(S::variable(mu, 2), Ft, edge);
      residual_imp(S::variable(z[0], 0), S::variable(z[1], 1), Ft, edge, plan, r, u14, false, nullptr, nullptr);
      for (int i = 0; i < 2; ++i) { F[i] = r[i].v; J(i, 0) = r[i].d[0]; J(i, 1) = r[i].d[1]; (*dF)[i] = r[i].d[2]; }
      return F.allFinite() && J.allFinite() && dF->allFinite();
    }
    using S = dual<T, 2>;
    S r[2];
    T Ft, edge;
    forces(mu, Ft, edge);
    residual_imp(S::variable(z[0], 0), S::variable(z[1], 1), S(Ft), S(edge), plan, r, u14, false, nullptr, nullptr);
    for (int i = 0; i < 2; ++i) { F[i] = r[i].v; J(i, 0) = r[i].d[0]; J(i, 1) = r[i].d[1]; }
    return F.allFinite() && J.allFinite();
  }
  // F alone (no Jacobian); u14, where given, as eval's.
  bool residual(const vec& z, T mu, const plan_type& plan, vec& F, T* u14 = nullptr) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    T r[2];
    residual_imp(z[0], z[1], Ft, edge, plan, r, u14, false, nullptr, nullptr);
    F[0] = r[0];
    F[1] = r[1];
    return F.allFinite();
  }
  plan_type plan(const vec& z, T mu) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    segment_plan p;
    T F[2];
    residual_imp(z[0], z[1], Ft, edge, p, F, nullptr, true, &p, nullptr);
    return p;
  }
  // The plan at a solved state (a node of a followed line): the length l fixes the libration's
  // period count there (plan_segment's target; see seta_system::plan_solved).
  plan_type plan_solved(const vec& z, T mu) const {
    T Ft, edge;
    forces(mu, Ft, edge);
    segment_plan p;
    T F[2];
    residual_imp(z[0], z[1], Ft, edge, p, F, nullptr, true, &p, nullptr, l);
    return p;
  }
  static segment_state plan_state(const plan_type& p) { return p.state; }
  bool plan_valid(const plan_type& p, const vec& z, T mu, const T u14[2]) const {
    using std::atan2; using std::sqrt;
    T Ft, edge;
    forces(mu, Ft, edge);
    const T N = sqrt(z[0] * z[0] + Ft * Ft);
    const auto g = make_segment<E>(EI, c, Ft + w, N);
    const T phi = atan2(z[0], Ft);
    const T u0 = sa * (Ft / N) - ca * (z[0] / N);
    const T X3s = z[1] / seg_sqrt_f4(g, u0);
    const T X3e = E ? sqrt(w) * edge / seg_sqrt_f4(g, Ft / N) : sqrt(w) * edge;
    return segment_plan_valid(g, p, alpha - phi, X3s, seta_pi<T>() / 2 - phi, X3e, u14[0],
                              (seta_pi<T>() / 2 - alpha) / 2);
  }
  T step_norm(const vec& dz, const vec& z) const {
    using std::fabs;
    const T a = fabs(dz[0]) / (fabs(z[0]) > 1 ? fabs(z[0]) : T(1));
    const T b = fabs(dz[1]) / (fabs(z[1]) > 1 ? fabs(z[1]) : T(1));
    return a > b ? a : b;
  }
  vec small_deformation_state() const {
    using std::sqrt;
    const T Delta = seta_pi<T>() / 2 - alpha;
    const T Meq = sqrt(2 * EI * w);
    const T Q = 2 * EI * (Delta - Meq * l / EI) / (l * l);  // one-segment paper 001 eq (18) at Ft = 0
    vec z;
    z << Q / sa, (Meq + Q * l) / sqrt(2 * EI);
    return z;
  }
  // lambda_w scales sqrt(w) separately (see seta_system::at_homotopy).
  fiber_system at_homotopy(T lambda) const { return at_homotopy(lambda, lambda); }
  fiber_system at_homotopy(T lambda, T lambda_w) const {
    const T Delta = seta_pi<T>() / 2 - alpha;
    return fiber_system(EI, c, l, seta_pi<T>() / 2 - lambda * Delta, w * lambda_w * lambda_w);
  }
  T theta_joint(const vec&) const { return std::numeric_limits<T>::quiet_NaN(); }
  T rate_joint(const vec&) const { return std::numeric_limits<T>::quiet_NaN(); }
  T rate_base(const vec& z) const { using std::sqrt; return z[1] * sqrt(2 / EI); }
  void turning_points(const plan_type& p, const vec& z, T mu, int& beam, int& spatula) const {
    using std::sqrt;
    T Ft, edge;
    forces(mu, Ft, edge);
    const T N = sqrt(z[0] * z[0] + Ft * Ft);
    const auto g = make_segment<E>(EI, c, Ft + w, N);
    const T u0 = sa * (Ft / N) - ca * (z[0] / N);
    const T X3s = z[1] / seg_sqrt_f4(g, u0);
    // psi at both ends (read only for a libration plan that added a period)
    using std::atan2;
    const T phi = p.periods != 0 ? atan2(z[0], Ft) : T(0);
    beam = segment_turning_points<Policy>(g, p, alpha - phi, X3s, seta_pi<T>() / 2 - phi, edge,
                                          (seta_pi<T>() / 2 - alpha) / 2);
    spatula = 0;
  }
  bool plan_valid_turning_points(const plan_type& p, const vec& z, T mu, const T u14[2], int& beam,
                                 int& spatula) const {
    if (!plan_valid(p, z, mu, u14)) return false;
    turning_points(p, z, mu, beam, spatula);
    return true;
  }
};

template <class Policy, bool E, class T>
inline void fiber_line_at_imp(const SingleFiber<T>& f, const T* Ft, std::size_t count, const critical_line_options<T>& opt,
                              critical_state<T>* out) {
  using std::isinf; using std::fabs; using std::sqrt;
  using System = fiber_system<T, Policy, E>;
  const System sys(f.EI, isinf(f.EA) ? T(0) : T(1) / f.EA, f.l, f.alpha, f.w);
  std::vector<std::size_t> pos, neg;
  T hi = 0, lo = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (out[i].status == critical_status::invalid_input) continue;
    if (Ft[i] >= 0) { pos.push_back(i); hi = std::max(hi, Ft[i]); }
    else { neg.push_back(i); lo = std::min(lo, Ft[i]); }
  }
  if (pos.empty() && neg.empty()) return;
  const T base_scale = sqrt(f.EI * f.w) / f.l;
  // One natural state for the lines in both directions.
  typename System::vec z0;
  segment_plan plan0;
  critical_state<T> natural;
  const bool started = start_line(sys, z0, plan0, natural);
  auto run = [&](const std::vector<std::size_t>& which, T stop) {
    if (which.empty()) return;
    if (!started) {
      for (std::size_t i : which) out[i].status = natural.status;
      return;
    }
    traced_line<System> line;
    follow_from_natural(sys, stop, std::max(fabs(stop), base_scale), opt, which.size(), z0, plan0, line);
    evaluate_line(sys, line, Ft, which.size(), which.data(), opt.tolerance, out);
  };
  run(pos, hi);
  run(neg, lo);
}

}  // namespace detail

// The fiber's critical line at given Ft values (first crossing along the line from Ft = 0).
template <class T, class Policy = policies::default_policy>
inline void critical_line_at(const SingleFiber<T>& fiber, const T* Ft, std::size_t count, critical_state<T>* out,
                             const critical_line_options<T>& options = critical_line_options<T>(),
                             const Policy& = Policy()) {
  constexpr const char* fn = "gecko::critical_line_at(SingleFiber)";
  const bool ok = detail::check_fiber<T, Policy>(fiber, fn);
  const T fm = ft_max(fiber);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = critical_state<T>();
    out[i].Ft = Ft[i];
    if (!ok || !detail::check_ft<T, Policy>(Ft[i], fm, fn)) out[i].status = critical_status::invalid_input;
  }
  if (!ok) return;
  detail::visit_extensibility(detail::is_extensible(fiber.EA), [&](auto E) {
    detail::fiber_line_at_imp<Policy, decltype(E)::value>(fiber, Ft, count, options, out);
  });
}

template <class T, class Policy = policies::default_policy>
inline std::vector<critical_state<T>> critical_line_at(const SingleFiber<T>& fiber, const std::vector<T>& Ft,
                                                       const critical_line_options<T>& options = critical_line_options<T>(),
                                                       const Policy& pol = Policy()) {
  std::vector<critical_state<T>> out(Ft.size());
  critical_line_at(fiber, Ft.data(), Ft.size(), out.data(), options, pol);
  return out;
}

}  // namespace gecko
