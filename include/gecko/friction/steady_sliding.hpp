// gecko/friction/steady_sliding.hpp — steady sliding forces of N spatulae out of phase
// (paper 000 eqs 5, 6, 9, 10 and A2.7–A2.8; docs/theory/frictional_adhesion.md "Rate-dependent detachment").
//
// A spatula re-sticks with lateral force f_par1 and normal force f_perp1, is stretched at the
// drag velocity V until the stored energy reaches G(V) (stretch dd, detachment_stretch), stays
// detached for t_off, and re-sticks. Its force is linear in time while attached, so eqs 5–6
// with t_on = dd / V give
//     F_par  = N t_on/(t_on + t_off) (f_par1 + K_par_par dd / 2)      = eq 9 when t_off = 0
//     F_perp = N t_on/(t_on + t_off) (f_perp1 + K_perp_par dd / 2)    = eq 10 when t_off = 0
// with f_par1 + K_par_par dd/2 = (f_par1 + sqrt(f_par1^2 + 2 K_par_par G))/2.
// Only N f_par1, N f_perp1, N^2 K_par_par G0 and K_perp_par / K_par_par enter (t_off = 0);
// K_perp_perp does not enter at all.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "gecko/beam/rigidity.hpp"
#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/detachment.hpp"

namespace gecko {

// N spatulae, each with rigidity K (symmetric positive definite; K_par_perp < 0 for the paper's
// curved beam, >= 0 for straight pillars or dragging against the curvature) and the forces
// (f_par1, f_perp1) just after re-sticking.
template <class T>
struct sliding_params {
  T N = T(1);
  Eigen::Matrix<T, 2, 2> K = Eigen::Matrix<T, 2, 2>::Identity();
  T f_par1 = T(0);
  T f_perp1 = T(0);
};

template <class T>
struct sliding_force {
  T F_par;    // time-averaged lateral force of the N spatulae
  T F_perp;   // time-averaged normal force (negative: tensile)
  T stretch;  // dd, lateral stretch at detachment (A2.6)
  T t_on;     // dd / V (infinite at V = 0)
};

// The Fig 6 fits as named presets, in SI units (V in m/s, forces in N, G0 in J, K in N/m).
// The paper gives only combinations; the values below satisfy them exactly and are chosen
// physically (N = 1e5 spatulae, K_par_par = 6 N/m: a stretch at detachment ~ 0.1 um and
// a force ~ 0.2 uN per spatula, the paper's orders of magnitude).
//   viscoelastic: f_par1 = 0, N sqrt(K_par_par G0 / 2) = 0.03 N, V* = 100 um/s, n = 0.45,
//                 N f_perp1 = 0.02 N, sqrt(K_perp_par^2 G0 / (2 K_par_par f_perp1^2)) = 0.8
//   plastic:      f_perp1 = 0, N f_par1 / 2 = 0.03 N, 2 K_par_par G0 / f_par1^2 = 1,
//                 V* = 600 um/s, N K_perp_par f_par1 / (2 K_par_par) = -0.025 N
// K_perp_perp (not in eqs 9–10) only makes K positive definite. The constants are long double
// literals so that every T gets them correctly rounded.
template <class T, class Law>
struct sliding_preset {
  sliding_params<T> params;
  Law law;
};

template <class T>
sliding_preset<T, viscoelastic_detachment<T>> fig6_viscoelastic() {
  sliding_preset<T, viscoelastic_detachment<T>> p;
  p.params.N = T(1e5L);
  p.params.K << T(6), T(-3.2L), T(-3.2L), T(2.4L);
  p.params.f_par1 = T(0);
  p.params.f_perp1 = T(2e-7L);
  p.law = viscoelastic_detachment<T>{T(3e-14L), T(1e-4L), T(0.45L)};
  return p;
}

template <class T>
sliding_preset<T, eyring_detachment<T>> fig6_plastic() {
  sliding_preset<T, eyring_detachment<T>> p;
  p.params.N = T(1e5L);
  p.params.K << T(6), T(-5), T(-5), T(5);
  p.params.f_par1 = T(6e-7L);
  p.params.f_perp1 = T(0);
  p.law = eyring_detachment<T>{T(3e-14L), T(6e-4L)};
  return p;
}

namespace detail {

template <class T, class Policy>
bool check_sliding_params(const char* function, const sliding_params<T>& p) {
  using std::isfinite;
  if (!check_positive<T, Policy>(function, "N", p.N, "0 < N < inf (number of spatulae)"))
    return false;
  // Any symmetric positive definite K: K_par_perp < 0 is the paper's curved beam (eq 1);
  // K_par_perp = 0 a straight pillar (no friction-adhesion coupling) and K_par_perp > 0 the
  // beam dragged against its curvature (the paper's control: the normal force grows
  // compressive with the stretch, regular friction).
  if (!check_spd<T, Policy>(function, "K", p.K)) return false;
  if (!isfinite(p.f_par1)) {
    raise_domain_error<T, Policy>(function, "f_par1", p.f_par1, "finite f_par1");
    return false;
  }
  if (!isfinite(p.f_perp1)) {
    raise_domain_error<T, Policy>(function, "f_perp1", p.f_perp1, "finite f_perp1");
    return false;
  }
  return true;
}

template <class T, class Policy>
bool check_t_off(const char* function, T t_off) {
  using std::isfinite;
  if (!(t_off >= T(0)) || !isfinite(t_off)) {
    raise_domain_error<T, Policy>(function, "t_off", t_off, "0 <= t_off < inf");
    return false;
  }
  return true;
}

template <class T>
sliding_force<T> nan_force() {
  const T nan = std::numeric_limits<T>::quiet_NaN();
  return {nan, nan, nan, nan};
}

// Parameters already checked; G = G(V) given.
// dG/dV at V = 0 where known: Eyring G0 / V*; otherwise NaN (t_on at V = 0 then stays inf).
template <class T, class Law>
T law_slope_at_zero(const Law&) { return std::numeric_limits<T>::quiet_NaN(); }
template <class T, class P>
T law_slope_at_zero(const eyring_detachment<T, P>& l) { return l.G0 / l.V_star; }

// dG0: dG/dV at V = 0 where the law knows it (NaN otherwise), for the limit of t_on at V = 0.
template <class T, class Policy>
sliding_force<T> steady_sliding_imp(const char* function, const sliding_params<T>& p, T V, T G,
                                    T t_off, T dG0 = std::numeric_limits<T>::quiet_NaN()) {
  using std::isfinite;
  using std::sqrt;
  if (!(G >= T(0)) || !isfinite(G)) {
    raise_domain_error<T, Policy>(function, "G", G,
                                  "0 <= G(V) < inf (the detachment law's value)");
    return nan_force<T>();
  }
  const T Kpp = p.K(0, 0);
  const T Kqp = p.K(1, 0);
  const T f1 = p.f_par1;
  const T q = sqrt(f1 * f1 + T(2) * Kpp * G);
  const T dd = f1 > T(0) ? T(2) * G / (f1 + q) : (q - f1) / Kpp;  // paper 000 eq (A2.6)
  // Mean lateral force while attached, (f1 + q)/2, without cancellation for f1 < 0.
  const T mean_par = f1 >= T(0) ? (f1 + q) / T(2) : Kpp * G / (q - f1);
  const T mean_perp = p.f_perp1 + Kqp * dd / T(2);  // paper 000 eqs (9)-(10) times the duty factor
  // Duty factor t_on / (t_on + t_off) = dd / (dd + V t_off): no division by V.
  T duty = T(1);
  if (t_off > T(0)) {
    const T denom = dd + V * t_off;
    if (!(denom > T(0))) {
      raise_domain_error<T, Policy>(function, "V", V,
                                    "V > 0 when t_off > 0 and the stretch at detachment is 0 "
                                    "(t_on = 0/0)");
      return nan_force<T>();
    }
    duty = dd / denom;
  }
  // At V = 0: t_on = dd / V -> inf if G(0) > 0 (never detaches). If G(0) = 0 (Eyring) and
  // f_par1 > 0, dd = 2G/(f1 + q) ~ G/f1 and t_on -> G'(0) / f_par1, finite (the plastic
  // spatula still detaches after a finite time as V -> 0); with f_par1 <= 0, dd ~ sqrt(2G/K)
  // and t_on ~ V^-1/2 -> inf.
  T t_on = std::numeric_limits<T>::infinity();
  if (V > T(0)) t_on = dd / V;
  else if (G == T(0) && f1 > T(0) && std::isfinite(dG0)) t_on = dG0 / f1;
  return {p.N * duty * mean_par, p.N * duty * mean_perp, dd, t_on};
}

}  // namespace detail

// From a known detachment energy G = G(V) (what the Python layer uses for a Python law).
template <class T, class Policy = policies::default_policy>
sliding_force<T> steady_sliding_from_energy(const sliding_params<T>& p, T V, T G, T t_off = T(0),
                                            const Policy& = Policy()) {
  static const char* function = "gecko::steady_sliding";
  if (!detail::check_sliding_params<T, Policy>(function, p) ||
      !detail::check_velocity<T, Policy>(function, V) ||
      !detail::check_t_off<T, Policy>(function, t_off))
    return detail::nan_force<T>();
  return detail::steady_sliding_imp<T, Policy>(function, p, V, G, t_off);
}

// Law: any callable T(T) giving G(V), e.g. viscoelastic_detachment<T>, eyring_detachment<T>.
template <class T, class Law, class Policy = policies::default_policy>
sliding_force<T> steady_sliding(const sliding_params<T>& p, const Law& law, T V, T t_off = T(0),
                                const Policy& = Policy()) {
  static const char* function = "gecko::steady_sliding";
  if (!detail::check_sliding_params<T, Policy>(function, p) ||
      !detail::check_velocity<T, Policy>(function, V) ||
      !detail::check_t_off<T, Policy>(function, t_off))
    return detail::nan_force<T>();
  return detail::steady_sliding_imp<T, Policy>(function, p, V, static_cast<T>(law(V)), t_off,
                                               detail::law_slope_at_zero<T>(law));
}

namespace detail {

// A law evaluated over a batch: a user callable as it is; the built-in laws with their
// parameters checked once (by one call at V = 0) instead of at every velocity — a quarter of
// the time of the whole kernel otherwise.
template <class T, class Law>
struct batch_law {
  const Law& law;
  bool valid() const { return true; }
  T operator()(T V) const { return static_cast<T>(law(V)); }
};

template <class T, class P>
struct batch_law<T, viscoelastic_detachment<T, P>> {
  const viscoelastic_detachment<T, P>& law;
  bool valid() const { using std::isnan; return !isnan(law(T(0))); }
  T operator()(T V) const { using std::pow; return law.G0 * (T(1) + pow(V / law.V_star, law.n)); }  // paper 000 eq (7)
};

template <class T, class P>
struct batch_law<T, eyring_detachment<T, P>> {
  const eyring_detachment<T, P>& law;
  bool valid() const { using std::isnan; return !isnan(law(T(0))); }
  T operator()(T V) const { using std::asinh; return law.G0 * asinh(V / law.V_star); }  // paper 000 eq (8)
};

}  // namespace detail

// Batch over n velocities: parameters checked once, not per element. F_perp, stretch and t_on
// may be null.
template <class T, class Law, class Policy = policies::default_policy>
void steady_sliding(const sliding_params<T>& p, const Law& law, const T* V, std::size_t n,
                    T* F_par, T* F_perp, T* stretch = nullptr, T* t_on = nullptr,
                    T t_off = T(0), const Policy& = Policy()) {
  static const char* function = "gecko::steady_sliding";
  const detail::batch_law<T, Law> G{law};
  const T slope0 = detail::law_slope_at_zero<T>(law);
  const bool ok = detail::check_sliding_params<T, Policy>(function, p) &&
                  detail::check_t_off<T, Policy>(function, t_off) && G.valid();
  for (std::size_t i = 0; i < n; ++i) {
    sliding_force<T> r = detail::nan_force<T>();
    if (ok && detail::check_velocity<T, Policy>(function, V[i]))
      r = detail::steady_sliding_imp<T, Policy>(function, p, V[i], G(V[i]), t_off, slope0);
    F_par[i] = r.F_par;
    if (F_perp) F_perp[i] = r.F_perp;
    if (stretch) stretch[i] = r.stretch;
    if (t_on) t_on[i] = r.t_on;
  }
}

}  // namespace gecko
