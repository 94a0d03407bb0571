// gecko/friction/fit.hpp — fit the steady-sliding model (eqs 9–10 of paper 000,
// docs/theory/frictional_adhesion.md) to measured (V, F_par, F_perp) by weighted least squares;
// beyond the paper, which fitted Fig 6 by eye.
//
// Model. Only N f_par1, N f_perp1, N^2 K_par_par G(V) and rho = K_perp_par / K_par_par enter
// eqs 9–10 (t_off = 0). The fit works in those combinations, in units of a force scale S (the
// rms of the data, so that data scaled by 1e200 or 1e-200 are fitted alike):
//     u = N f_par1 / S,  v = N f_perp1 / S,  w(V) = 2 N^2 K_par_par G(V) / S^2,
//     q = sqrt(u^2 + w),  F_par / S = (u + q) / 2,  F_perp / S = v + rho (q - u) / 2.
// Coordinates: the law's positive parameters as logarithms (G0, V*, n > 0 by construction),
// u, v and rho as they are; N, K_par_par and K_perp_perp are held (they are not identifiable
// separately from the combinations above).
//
// Solver. Levenberg–Marquardt; each damped Gauss–Newton step is the least-squares solution of
// [J; sqrt(lambda) D] s = -[r; 0] by Householder QR (never the normal equations, which square
// the condition number), D = the running maximum of the column norms of J (scale invariance).
// Status "converged" only when a first-order criterion holds at a finite chi^2: the cosine
// between the residual and every column of J is below gtol, or the data are reproduced to
// rounding, or an undamped Gauss–Newton step predicts and achieves a relative reduction below
// ftol. `reason` says which criterion stopped the fit.
//
// Errors. Residuals are whitened by sigma (per point, per component) when given. With
// absolute_sigma the covariance is (J^T J)^-1 (sigma known); otherwise it is rescaled by the
// reduced chi^2 = chi^2 / (2n - p) (sigma known only up to a factor, or not at all). (J^T J)^-1
// comes from the SVD of J. Directions the data cannot determine are the right singular vectors
// of J with its columns scaled to unit norm whose squared singular value is below
// 1/max_condition of the largest; they make the status "not_identifiable", are reported by name,
// and profile-likelihood intervals (re-minimising chi^2 over the other coordinates with one held)
// are then computed for every parameter (on request otherwise).
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/detachment.hpp"
#include "gecko/friction/steady_sliding.hpp"

namespace gecko {

// singular: kept for compatibility (no longer produced: QR steps exist at any rank).
enum class fit_status { converged, max_iterations, singular, not_identifiable, no_progress, non_finite };

inline const char* to_string(fit_status s) {
  switch (s) {
    case fit_status::converged: return "converged";
    case fit_status::max_iterations: return "max_iterations";
    case fit_status::not_identifiable: return "not_identifiable";
    case fit_status::no_progress: return "no_progress";
    case fit_status::non_finite: return "non_finite";
    default: return "singular";
  }
}

// Whether a force offset is fitted: true, false, or (default-constructed) automatic. Assigning a
// bool (`opt.fit_f_par1 = false`) sets it explicitly.
class fit_flag {
 public:
  constexpr fit_flag() = default;
  constexpr fit_flag(bool b) : v_(b ? 1 : 0) {}  // NOLINT(google-explicit-constructor): bool-like
  static constexpr fit_flag automatic() { return fit_flag(); }
  constexpr bool is_automatic() const { return v_ < 0; }
  // The explicit choice, or `automatic_choice` when none was made.
  constexpr bool resolve(bool automatic_choice) const { return v_ < 0 ? automatic_choice : v_ == 1; }

 private:
  signed char v_ = -1;
};

template <class T>
struct fit_options {
  // f_par1 by default (automatic): fitted when the guess law has G(0) = 0 (Eyring, eq 8: the
  // low-speed lateral force is N f_par1 alone), held at the guess when G(0) > 0 (viscoelastic,
  // eq 7: the plateau N sqrt(K G0 / 2) and f_par1 both set the low-speed force, and only the
  // curvature of the rise separates them). For Fig 6 at 25 speeds and 0.5 mN noise the standard
  // error of f_par1 so fitted is 1 to 10 times the whole plateau / N, and in 1 fit of 8 the
  // least-squares optimum is the degenerate V* -> 0, f_par1 = plateau / N (status
  // not_identifiable); the paper's viscoelastic fit sets f_par1 = 0. Set it to true to fit it.
  fit_flag fit_f_par1;
  bool fit_f_perp1 = true;
  bool fit_coupling = false;  // also fit K_perp_par
  int max_iterations = 200;
  T xtol = T(1e-10);  // relative size of an undamped step at which the fit has converged
  T ftol = T(1e-12);  // relative chi^2 reduction (predicted and actual) of an undamped step
  T gtol = T(1e-8);   // cosine between the residual and the columns of J
  // Per-point standard deviations of F_par and F_perp (null: unknown, unit weights).
  const T* sigma_par = nullptr;
  const T* sigma_perp = nullptr;
  bool absolute_sigma = true;   // with sigma given: use it as known (no chi^2 rescaling)
  T max_condition = T(1e10);    // of the column-scaled J^T J; above it: not identifiable
  bool profile = false;         // profile-likelihood intervals for every parameter
  T profile_delta = T(1);       // chi^2 rise defining them (1: one standard error; 3.84: 95 %)
};

// A user detachment law G(V; p) with named parameters: `G` fills G[i] for V[i], i < n, from
// the parameter values p (in the order of `names`). Parameters flagged positive are fitted as
// logarithms. Derivatives by central differences.
template <class T>
struct custom_detachment {
  std::vector<std::string> names;
  std::vector<T> values;
  std::vector<bool> positive;
  std::function<void(const T* V, std::size_t n, const T* p, T* G)> G;
};

template <class T, class Law>
struct steady_sliding_fit {
  sliding_params<T> params;  // fitted (held entries as given)
  Law law;                   // fitted
  std::vector<std::string> names;     // free parameters, in order
  std::vector<T> values;              // their fitted values
  std::vector<T> standard_errors;     // and standard errors
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> covariance;  // of values
  T rss = T(0);                       // sum of squared (unweighted) residuals, force^2
  T chi2 = T(0);                      // sum of squared weighted residuals (= rss without sigma)
  int dof = 0;                        // 2 len(V) - free parameters
  int iterations = 0;
  fit_status status = fit_status::max_iterations;
  std::string reason;                 // why the fit stopped
  T condition = T(0);                 // of the column-scaled J^T J
  std::vector<std::string> undetermined;   // directions the data do not determine
  std::vector<T> profile_lower, profile_upper;  // profile-likelihood intervals (NaN: not run)
};

namespace detail {

// The law in fit coordinates: w[i] = c G(V[i]) and dw/dtheta (column-major n x k).
template <class Law>
struct fit_law_adapter;

template <class T, class P>
struct fit_law_adapter<viscoelastic_detachment<T, P>> {
  using law_type = viscoelastic_detachment<T, P>;
  int k() const { return 3; }
  std::vector<std::string> names() const { return {"G0", "V_star", "n"}; }
  std::vector<bool> positive() const { return {true, true, true}; }
  // theta: ln(c G0), ln V*, ln n.
  void get(const law_type& l, T c, T* th) const {
    th[0] = std::log(c) + std::log(l.G0); th[1] = std::log(l.V_star); th[2] = std::log(l.n);
  }
  void values(const T* th, T c, T* v) const {
    v[0] = std::exp(th[0] - std::log(c)); v[1] = std::exp(th[1]); v[2] = std::exp(th[2]);
  }
  law_type make(const T* v) const { return {v[0], v[1], v[2]}; }
  bool eval(const T* th, const T* V, std::size_t n, T* w, T* dw) const {
    const T A = std::exp(th[0]), Vs = std::exp(th[1]), e = std::exp(th[2]);
    for (std::size_t i = 0; i < n; ++i) {
      const T r = V[i] / Vs;
      const T rn = r > T(0) ? std::pow(r, e) : T(0);
      w[i] = A * (T(1) + rn);
      if (dw) {
        dw[i] = w[i];
        dw[n + i] = -A * e * rn;
        dw[2 * n + i] = r > T(0) ? A * e * std::log(r) * rn : T(0);
      }
    }
    return true;
  }
};

template <class T, class P>
struct fit_law_adapter<eyring_detachment<T, P>> {
  using law_type = eyring_detachment<T, P>;
  int k() const { return 2; }
  std::vector<std::string> names() const { return {"G0", "V_star"}; }
  std::vector<bool> positive() const { return {true, true}; }
  void get(const law_type& l, T c, T* th) const {
    th[0] = std::log(c) + std::log(l.G0); th[1] = std::log(l.V_star);
  }
  void values(const T* th, T c, T* v) const {
    v[0] = std::exp(th[0] - std::log(c)); v[1] = std::exp(th[1]);
  }
  law_type make(const T* v) const { return {v[0], v[1]}; }
  bool eval(const T* th, const T* V, std::size_t n, T* w, T* dw) const {
    const T A = std::exp(th[0]), Vs = std::exp(th[1]);
    for (std::size_t i = 0; i < n; ++i) {
      const T r = V[i] / Vs;
      w[i] = A * std::asinh(r);
      if (dw) {
        dw[i] = w[i];
        dw[n + i] = -A * r / std::sqrt(T(1) + r * r);
      }
    }
    return true;
  }
};

template <class T>
struct fit_law_adapter<custom_detachment<T>> {
  using law_type = custom_detachment<T>;
  const law_type* proto = nullptr;
  mutable T c = T(1);
  mutable std::vector<T> p, g0, g1;
  int k() const { return int(proto->names.size()); }
  std::vector<std::string> names() const { return proto->names; }
  std::vector<bool> positive() const { return proto->positive; }
  void get(const law_type& l, T cc, T* th) const {
    c = cc;
    for (int j = 0; j < k(); ++j) th[j] = proto->positive[j] ? std::log(l.values[j]) : l.values[j];
  }
  void values(const T* th, T, T* v) const {
    for (int j = 0; j < k(); ++j) v[j] = proto->positive[j] ? std::exp(th[j]) : th[j];
  }
  law_type make(const T* v) const {
    law_type l = *proto;
    l.values.assign(v, v + k());
    return l;
  }
  bool eval(const T* th, const T* V, std::size_t n, T* w, T* dw) const {
    using std::isfinite;
    const int kk = k();
    p.resize(kk);
    values(th, c, p.data());
    proto->G(V, n, p.data(), w);
    for (std::size_t i = 0; i < n; ++i) {
      if (!isfinite(w[i])) return false;
      w[i] *= c;
    }
    if (!dw) return true;
    g0.resize(n);
    g1.resize(n);
    std::vector<T> th2(th, th + kk);
    for (int j = 0; j < kk; ++j) {
      // Central difference, step ~ eps^(1/3) in the coordinate: error ~ eps^(2/3) relative.
      const T h = std::cbrt(std::numeric_limits<T>::epsilon()) * std::max(T(1), std::abs(th[j]));
      th2[j] = th[j] + h;
      values(th2.data(), c, p.data());
      proto->G(V, n, p.data(), g1.data());
      th2[j] = th[j] - h;
      values(th2.data(), c, p.data());
      proto->G(V, n, p.data(), g0.data());
      th2[j] = th[j];
      for (std::size_t i = 0; i < n; ++i) {
        dw[std::size_t(j) * n + i] = c * (g1[i] - g0[i]) / (T(2) * h);
        if (!isfinite(dw[std::size_t(j) * n + i])) return false;
      }
    }
    return true;
  }
};

template <class Law>
fit_law_adapter<Law> make_adapter(const Law&) { return {}; }
template <class T>
fit_law_adapter<custom_detachment<T>> make_adapter(const custom_detachment<T>& l) {
  fit_law_adapter<custom_detachment<T>> a;
  a.proto = &l;
  return a;
}

// The whitened least-squares problem in fit coordinates.
template <class T, class Adapter>
struct sliding_problem {
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  const Adapter& law;
  const T* V;
  std::size_t n;
  Vec y;       // whitened scaled data (2n)
  Vec wt;      // whitening weights S / sigma (2n), 1 without sigma
  int k, i_u, i_v, i_rho, p;
  T u0, v0, rho0;  // held values
  mutable Vec w, dw;

  // Residuals (model - data, whitened) and optionally J. False if anything is not finite.
  bool operator()(const Vec& th, Vec& r, Mat* J) const {
    using std::isfinite;
    using std::sqrt;
    w.resize(Eigen::Index(n));
    if (J) dw.resize(Eigen::Index(n) * k);
    if (!law.eval(th.data(), V, n, w.data(), J ? dw.data() : nullptr)) return false;
    const T u = i_u >= 0 ? th(i_u) : u0;
    const T v = i_v >= 0 ? th(i_v) : v0;
    const T rho = i_rho >= 0 ? th(i_rho) : rho0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index a = Eigen::Index(2 * i), b = a + 1;
      const T q = sqrt(u * u + w(Eigen::Index(i)));
      if (!isfinite(q)) return false;
      // (u + q)/2 and (q - u)/2 without cancellation.
      const T up = u >= T(0) ? (u + q) / T(2) : (q > T(0) ? w(Eigen::Index(i)) / (T(2) * (q - u)) : T(0));
      const T dn = u <= T(0) ? (q - u) / T(2) : w(Eigen::Index(i)) / (T(2) * (u + q));
      r(a) = wt(a) * up - y(a);
      r(b) = wt(b) * (v + rho * dn) - y(b);
      if (!J) continue;
      J->row(a).setZero();
      J->row(b).setZero();
      const T inv2q = q > T(0) ? T(1) / (T(2) * q) : T(0);
      for (int j = 0; j < k; ++j) {
        const T dq = dw(Eigen::Index(j) * Eigen::Index(n) + Eigen::Index(i)) * inv2q;
        (*J)(a, j) = wt(a) * dq / T(2);
        (*J)(b, j) = wt(b) * rho * dq / T(2);
      }
      if (i_u >= 0) {
        const T dq = q > T(0) ? u / q : T(0);
        (*J)(a, i_u) = wt(a) * (T(1) + dq) / T(2);
        (*J)(b, i_u) = wt(b) * rho * (dq - T(1)) / T(2);
      }
      if (i_v >= 0) (*J)(b, i_v) = wt(b);
      if (i_rho >= 0) (*J)(b, i_rho) = wt(b) * dn;
    }
    return isfinite(r.squaredNorm());
  }
};

template <class T>
struct lm_result {
  Eigen::Matrix<T, Eigen::Dynamic, 1> theta;
  T chi2 = T(0);
  int iterations = 0;
  fit_status status = fit_status::max_iterations;
  std::string reason;
};

// Levenberg–Marquardt on the coordinates not in `held` (held ones stay at theta's values).
template <class T, class Problem>
lm_result<T> levenberg_marquardt(const Problem& prob, Eigen::Matrix<T, Eigen::Dynamic, 1> theta,
                                 const fit_options<T>& opt, int held = -1) {
  using std::abs;
  using std::isfinite;
  using std::sqrt;
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  const Eigen::Index m = prob.y.size(), p = theta.size();
  const Eigen::Index pf = held >= 0 ? p - 1 : p;
  lm_result<T> res;
  Vec r(m), r_trial(m);
  Mat Jfull(m, p), J(m, pf);
  auto free_cols = [&]() {
    for (Eigen::Index j = 0, c = 0; j < p; ++j)
      if (j != held) J.col(c++) = Jfull.col(j);
  };
  if (!prob(theta, r, &Jfull)) {
    res.theta = theta;
    res.chi2 = std::numeric_limits<T>::infinity();
    res.status = fit_status::non_finite;
    res.reason = "the model or chi^2 is not finite (overflow or NaN) at the starting point";
    return res;
  }
  free_cols();
  T chi2 = r.squaredNorm();
  const T ynorm2 = prob.y.squaredNorm();
  const T eps = std::numeric_limits<T>::epsilon();
  Vec D = Vec::Zero(pf);
  T lambda = T(1e-3), nu = T(2);
  int it = 0;
  auto gradient_ok = [&]() {
    const T rn = sqrt(chi2);
    if (!(rn > T(0))) return true;
    const Vec g = J.transpose() * r;
    for (Eigen::Index j = 0; j < pf; ++j) {
      const T cn = J.col(j).norm();
      if (cn > T(0) && abs(g(j)) > opt.gtol * cn * rn) return false;
    }
    return true;
  };
  auto zero_residual = [&]() { return chi2 <= T(1e6) * eps * eps * ynorm2; };
  res.status = fit_status::max_iterations;
  res.reason = "max_iterations reached before a convergence criterion held";
  for (; it < opt.max_iterations; ++it) {
    if (zero_residual()) {
      res.status = fit_status::converged;
      res.reason = "the data are reproduced to rounding";
      break;
    }
    if (gradient_ok()) {
      res.status = fit_status::converged;
      res.reason = "gradient: residual orthogonal to the Jacobian within gtol";
      break;
    }
    for (Eigen::Index j = 0; j < pf; ++j) D(j) = std::max(D(j), J.col(j).norm());
    for (Eigen::Index j = 0; j < pf; ++j)
      if (!(D(j) > T(0))) D(j) = T(1);
    bool accepted = false, done = false;
    for (int tries = 0; tries < 40 && !accepted; ++tries) {
      Mat A(m + pf, pf);
      A.topRows(m) = J;
      A.bottomRows(pf) = (sqrt(lambda) * D).asDiagonal();
      Vec rhs = Vec::Zero(m + pf);
      rhs.head(m) = -r;
      const Vec s = Eigen::HouseholderQR<Mat>(A).solve(rhs);
      if (!s.allFinite()) { lambda *= nu; nu *= T(2); continue; }
      Vec trial = theta;
      for (Eigen::Index j = 0, c = 0; j < p; ++j)
        if (j != held) trial(j) += s(c++);
      const bool ok = prob(trial, r_trial, nullptr);
      const T chi2_trial = ok ? r_trial.squaredNorm() : std::numeric_limits<T>::infinity();
      const Vec Js = J * s;
      const T pred = -(T(2) * r.dot(Js) + Js.squaredNorm());  // predicted reduction
      const T act = chi2 - chi2_trial;
      if (ok && isfinite(chi2_trial) && act > T(0)) {
        const T ratio = pred > T(0) ? act / pred : T(0);
        const bool gauss_newton = lambda <= T(1);
        const T snorm = (D.asDiagonal() * s).norm();
        Vec Dth(pf);
        for (Eigen::Index j = 0, c = 0; j < p; ++j)
          if (j != held) { Dth(c) = D(c) * theta(j); ++c; }
        theta = trial;
        r = r_trial;
        const T old = chi2;
        chi2 = chi2_trial;
        prob(theta, r, &Jfull);
        free_cols();
        const T f = T(2) * ratio - T(1);
        lambda *= std::max(T(1) / T(3), T(1) - f * f * f);
        lambda = std::max(lambda, T(1e-12));
        nu = T(2);
        accepted = true;
        if (gauss_newton && pred <= opt.ftol * old && act <= opt.ftol * old) {
          res.status = fit_status::converged;
          res.reason = "ftol: an undamped step predicts and achieves a negligible reduction";
          done = true;
        } else if (gauss_newton && snorm <= opt.xtol * (Dth.norm() + opt.xtol)) {
          res.status = fit_status::converged;
          res.reason = "xtol: an undamped Gauss-Newton step is negligible";
          done = true;
        }
      } else {
        lambda *= nu;
        nu *= T(2);
        if (!(lambda < T(1e16))) break;
      }
    }
    if (!accepted) {
      // The undamped Gauss–Newton step's predicted reduction is the most any step can gain to
      // first order: when it is below ftol_stationary of chi^2 and rounding defeats every
      // step, the point is stationary to the resolution of the arithmetic.
      const Vec sgn = J.colPivHouseholderQr().solve(-r);
      const T pred_gn = (J * sgn).squaredNorm();
      if (gradient_ok() || zero_residual()) {
        res.status = fit_status::converged;
        res.reason = "gradient: residual orthogonal to the Jacobian within gtol";
      } else if (pred_gn <= T(1e-8) * chi2) {
        res.status = fit_status::converged;
        res.reason = "stationary to rounding: no step reduces chi^2 and a Gauss-Newton step "
                     "predicts a relative reduction below 1e-8";
      } else {
        res.status = fit_status::no_progress;
        res.reason = "no step reduces chi^2 at any damping, but the gradient criterion fails";
      }
      break;
    }
    if (done) { ++it; break; }
  }
  res.theta = theta;
  res.chi2 = chi2;
  res.iterations = it;
  return res;
}

template <class T>
std::string format_direction(const Eigen::Matrix<T, Eigen::Dynamic, 1>& d,
                             const std::vector<std::string>& coords) {
  std::string s;
  for (Eigen::Index j = 0; j < d.size(); ++j) {
    if (std::abs(d(j)) < T(0.05)) continue;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%.2f*", s.empty() ? "" : " ", double(d(j)));
    if (!s.empty() && d(j) >= T(0)) s += " +";
    s += buf;
    s += coords[std::size_t(j)];
  }
  return s;
}

}  // namespace detail

// guess: starting point (its N, K_par_par, K_perp_perp are held; the rest is refined).
template <class T, class Law, class Policy = policies::default_policy>
steady_sliding_fit<T, Law> fit_steady_sliding(const T* V, const T* F_par, const T* F_perp,
                                              std::size_t n, const sliding_params<T>& guess,
                                              const Law& guess_law,
                                              const fit_options<T>& opt = {},
                                              const Policy& = Policy()) {
  using std::abs;
  using std::isfinite;
  using std::sqrt;
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  static const char* function = "gecko::fit_steady_sliding";
  const auto adapter = detail::make_adapter(guess_law);
  steady_sliding_fit<T, Law> res{guess, guess_law, {}, {}, {}, Mat(), T(0), T(0), 0, 0,
                                 fit_status::non_finite, "invalid input", T(0), {}, {}, {}};
  const T nan = std::numeric_limits<T>::quiet_NaN();

  // steady_sliding accepts K_perp_par >= 0 too; the fit only needs K symmetric, K_par_par > 0.
  if (!detail::check_sliding_params<T, Policy>(function, guess)) return res;
  const int k = adapter.k();
  {
    const auto pos = adapter.positive();
    std::vector<T> lv(std::size_t(k), T(1));
    if constexpr (std::is_same_v<Law, custom_detachment<T>>) {
      if (guess_law.values.size() != std::size_t(k) || guess_law.positive.size() != std::size_t(k) ||
          !guess_law.G) {
        raise_domain_error<T, Policy>(function, "law", T(k),
                                      "as many values and positive flags as names, and a G");
        return res;
      }
      lv = guess_law.values;
    } else {
      // The built-in laws validate their parameters when evaluated.
      if (!isfinite(static_cast<T>(guess_law(T(0))))) return res;
    }
    for (int j = 0; j < k; ++j)
      if (pos[std::size_t(j)] && !(lv[std::size_t(j)] > T(0) && isfinite(lv[std::size_t(j)]))) {
        raise_domain_error<T, Policy>(function, adapter.names()[std::size_t(j)].c_str(),
                                      lv[std::size_t(j)], "a positive finite starting value");
        return res;
      }
  }
  // Automatic f_par1 (see fit_options): fitted iff the guess law vanishes at V = 0.
  bool fit_u = true;
  if (opt.fit_f_par1.is_automatic()) {
    const T zero = T(0);
    T g0 = T(0);
    if constexpr (std::is_same_v<Law, custom_detachment<T>>) guess_law.G(&zero, 1, guess_law.values.data(), &g0);
    else g0 = static_cast<T>(guess_law(zero));
    fit_u = !(isfinite(g0) && g0 > T(0));
  } else {
    fit_u = opt.fit_f_par1.resolve(true);
  }
  const int p = k + int(fit_u) + int(opt.fit_f_perp1) + int(opt.fit_coupling);
  if (2 * n <= std::size_t(p)) {
    raise_domain_error<T, Policy>(function, "len(V)", T(n),
                                  "more data than parameters: 2 len(V) > the free parameters");
    return res;
  }
  if (!(opt.max_iterations >= 0)) {
    raise_domain_error<T, Policy>(function, "max_iterations", T(opt.max_iterations), ">= 0");
    return res;
  }
  if (!(opt.max_condition > T(1)) || !(opt.profile_delta > T(0)) || !isfinite(opt.profile_delta)) {
    raise_domain_error<T, Policy>(function, "max_condition / profile_delta",
                                  !(opt.max_condition > T(1)) ? opt.max_condition : opt.profile_delta,
                                  "max_condition > 1 and 0 < profile_delta < inf");
    return res;
  }
  // Each message names the array and the element: "F_par[3] = nan is out of range".
  auto element = [](const char* name, std::size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; };
  for (std::size_t i = 0; i < n; ++i) {
    if (!(V[i] >= T(0) && isfinite(V[i]))) {
      raise_domain_error<T, Policy>(function, element("V", i).c_str(), V[i], "0 <= V < inf (drag velocity)");
      return res;
    }
    if (!isfinite(F_par[i])) {
      raise_domain_error<T, Policy>(function, element("F_par", i).c_str(), F_par[i], "finite measured forces");
      return res;
    }
    if (!isfinite(F_perp[i])) {
      raise_domain_error<T, Policy>(function, element("F_perp", i).c_str(), F_perp[i], "finite measured forces");
      return res;
    }
    if (opt.sigma_par && !(opt.sigma_par[i] > T(0) && isfinite(opt.sigma_par[i]))) {
      raise_domain_error<T, Policy>(function, element("sigma_par", i).c_str(), opt.sigma_par[i], "0 < sigma < inf");
      return res;
    }
    if (opt.sigma_perp && !(opt.sigma_perp[i] > T(0) && isfinite(opt.sigma_perp[i]))) {
      raise_domain_error<T, Policy>(function, element("sigma_perp", i).c_str(), opt.sigma_perp[i], "0 < sigma < inf");
      return res;
    }
  }

  // Force scale: the rms of the data, computed without overflow.
  T fmax = T(0);
  for (std::size_t i = 0; i < n; ++i) fmax = std::max({fmax, abs(F_par[i]), abs(F_perp[i])});
  T S = T(1);
  if (fmax > T(0)) {
    T s2 = T(0);
    for (std::size_t i = 0; i < n; ++i)
      s2 += (F_par[i] / fmax) * (F_par[i] / fmax) + (F_perp[i] / fmax) * (F_perp[i] / fmax);
    S = fmax * sqrt(s2 / T(2 * n));
  }
  const T N = guess.N, Kpp = guess.K(0, 0);
  // c = 2 N^2 K_par_par / S^2 as a logarithm (it may over- or underflow on its own).
  const T log_c = std::log(T(2) * Kpp) + T(2) * (std::log(N) - std::log(S));
  const T c = std::exp(log_c);

  detail::sliding_problem<T, decltype(adapter)> prob{adapter, V, n, Vec(2 * n), Vec(2 * n), k,
                                                     -1, -1, -1, p, T(0), T(0), T(0), Vec(), Vec()};
  for (std::size_t i = 0; i < n; ++i) {
    prob.wt(Eigen::Index(2 * i)) = opt.sigma_par ? S / opt.sigma_par[i] : T(1);
    prob.wt(Eigen::Index(2 * i + 1)) = opt.sigma_perp ? S / opt.sigma_perp[i] : T(1);
    prob.y(Eigen::Index(2 * i)) = prob.wt(Eigen::Index(2 * i)) * (F_par[i] / S);
    prob.y(Eigen::Index(2 * i + 1)) = prob.wt(Eigen::Index(2 * i + 1)) * (F_perp[i] / S);
  }
  int idx = k;
  if (fit_u) prob.i_u = idx++;
  if (opt.fit_f_perp1) prob.i_v = idx++;
  if (opt.fit_coupling) prob.i_rho = idx++;
  prob.u0 = N * guess.f_par1 / S;
  prob.v0 = N * guess.f_perp1 / S;
  prob.rho0 = guess.K(1, 0) / Kpp;
  Vec theta(p);
  // Built-in laws fold c into ln G0 (theta_0 = ln(c G0)); a custom law gets c as a factor.
  adapter.get(guess_law, c, theta.data());
  if constexpr (!std::is_same_v<Law, custom_detachment<T>>) theta(0) = log_c + std::log(guess_law.G0);
  if (prob.i_u >= 0) theta(prob.i_u) = prob.u0;
  if (prob.i_v >= 0) theta(prob.i_v) = prob.v0;
  if (prob.i_rho >= 0) theta(prob.i_rho) = prob.rho0;

  // A guess off by orders of magnitude in force is brought to the data's scale first (forces
  // are homogeneous of degree 1 in (u, v, sqrt(c G0))).
  if constexpr (!std::is_same_v<Law, custom_detachment<T>>) {
    Vec model(2 * n);
    auto bare = prob;  // the model alone (r = model - y would lose a tiny model to rounding)
    bare.y.setZero();
    if (bare(theta, model, nullptr)) {
      const T ratio = (prob.y.norm()) / model.norm();
      if (isfinite(ratio) && ratio > T(0) && (ratio > T(10) || ratio < T(0.1))) {
        theta(0) += T(2) * std::log(ratio);
        if (prob.i_u >= 0) theta(prob.i_u) *= ratio;
        if (prob.i_v >= 0) theta(prob.i_v) *= ratio;
      }
    }
  }

  const auto lm = detail::levenberg_marquardt<T>(prob, theta, opt);
  theta = lm.theta;
  res.iterations = lm.iterations;
  res.status = lm.status;
  res.reason = lm.reason;
  res.dof = int(2 * n) - p;

  // Values in the user's parameters; d value / d theta for the delta method.
  const auto pos = adapter.positive();
  std::vector<T> vals(static_cast<std::size_t>(p));
  Vec dvdth(p);
  adapter.values(theta.data(), c, vals.data());
  for (int j = 0; j < k; ++j) dvdth(j) = pos[std::size_t(j)] ? vals[std::size_t(j)] : T(1);
  if (prob.i_u >= 0) { vals[std::size_t(prob.i_u)] = theta(prob.i_u) * S / N; dvdth(prob.i_u) = S / N; }
  if (prob.i_v >= 0) { vals[std::size_t(prob.i_v)] = theta(prob.i_v) * S / N; dvdth(prob.i_v) = S / N; }
  if (prob.i_rho >= 0) { vals[std::size_t(prob.i_rho)] = theta(prob.i_rho) * Kpp; dvdth(prob.i_rho) = Kpp; }
  auto to_value = [&](int j, T th) -> T {
    if (j < k) {
      Vec t2 = theta;
      t2(j) = th;
      std::vector<T> v2(static_cast<std::size_t>(p));
      adapter.values(t2.data(), c, v2.data());
      return v2[std::size_t(j)];
    }
    return th * dvdth(j);
  };
  res.values = vals;
  res.names = adapter.names();
  if (prob.i_u >= 0) res.names.push_back("f_par1");
  if (prob.i_v >= 0) res.names.push_back("f_perp1");
  if (prob.i_rho >= 0) res.names.push_back("K_perp_par");
  std::vector<T> lawvals(vals.begin(), vals.begin() + k);
  res.law = adapter.make(lawvals.data());
  res.params.f_par1 = prob.i_u >= 0 ? vals[std::size_t(prob.i_u)] : guess.f_par1;
  res.params.f_perp1 = prob.i_v >= 0 ? vals[std::size_t(prob.i_v)] : guess.f_perp1;
  if (prob.i_rho >= 0) res.params.K(1, 0) = res.params.K(0, 1) = vals[std::size_t(prob.i_rho)];

  // chi^2 and the unweighted rss in force units (S^2 may overflow: then inf, and honest).
  Vec r(2 * n);
  Mat J(2 * n, p);
  const bool finite = prob(theta, r, &J);
  res.chi2 = opt.sigma_par || opt.sigma_perp ? lm.chi2 : lm.chi2 * S * S;
  T rss = T(0);
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const T e = r(i) / prob.wt(i) * S;
    rss += e * e;
  }
  res.rss = rss;
  bool values_finite = true;
  for (int j = 0; j < p; ++j)  // a positive parameter that underflows to 0 is not finite either
    values_finite = values_finite && isfinite(vals[std::size_t(j)]) &&
                    !(j < k && pos[std::size_t(j)] && !(vals[std::size_t(j)] > T(0)));
  if (lm.status == fit_status::non_finite) {
    // keep the solver's reason (e.g. not finite at the starting point)
  } else if (!finite || !isfinite(rss) || !isfinite(res.chi2) || !values_finite) {
    res.status = fit_status::non_finite;
    res.reason = "the fitted values, chi^2 or rss overflow or are not finite in this precision";
  }

  // Covariance from the SVD of J: (J^T J)^-1 = V S^-2 V^T.
  res.standard_errors.assign(std::size_t(p), nan);
  res.covariance = Mat::Constant(p, p, nan);
  res.profile_lower.assign(std::size_t(p), nan);
  res.profile_upper.assign(std::size_t(p), nan);
  if (!finite) return res;
  const bool known_sigma = (opt.sigma_par || opt.sigma_perp) && opt.absolute_sigma;
  const T s2 = known_sigma ? T(1) : lm.chi2 / T(res.dof);
  Vec colnorm(p);
  for (int j = 0; j < p; ++j) colnorm(j) = J.col(j).norm();
  Mat Js = J;
  for (int j = 0; j < p; ++j)
    if (colnorm(j) > T(0)) Js.col(j) /= colnorm(j);
  Eigen::JacobiSVD<Mat> svd_s(Js, Eigen::ComputeThinV);
  const Vec sv = svd_s.singularValues();
  const T smax = sv(0), smin = sv(p - 1);
  res.condition = smin > T(0) ? (smax / smin) * (smax / smin) : std::numeric_limits<T>::infinity();
  std::vector<std::string> coords;
  for (int j = 0; j < p; ++j)
    coords.push_back(j < k && pos[std::size_t(j)] ? "ln(" + res.names[std::size_t(j)] + ")"
                                                  : res.names[std::size_t(j)]);
  for (int j = 0; j < p; ++j) {
    if (!(sv(j) * sv(j) * opt.max_condition > smax * smax)) {
      Vec d = svd_s.matrixV().col(j);
      for (int i = 0; i < p; ++i) d(i) = colnorm(i) > T(0) ? d(i) / colnorm(i) : d(i);
      d /= d.norm();
      Eigen::Index imax;
      d.cwiseAbs().maxCoeff(&imax);
      if (d(imax) < T(0)) d = -d;
      res.undetermined.push_back(detail::format_direction<T>(d, coords));
    }
  }
  if (!res.undetermined.empty() && res.status == fit_status::converged) {
    res.status = fit_status::not_identifiable;
    res.reason = "converged, but the data do not determine " + res.undetermined.front() +
                 (res.undetermined.size() > 1 ? " (and more; see undetermined)" : "") +
                 ": column-scaled J^T J has condition " + detail::format_value(res.condition);
  }
  if (smin > T(0)) {
    Mat cov_th = Mat::Zero(p, p);
    const Mat Vs = svd_s.matrixV();
    for (int j = 0; j < p; ++j) cov_th += Vs.col(j) * Vs.col(j).transpose() / (sv(j) * sv(j));
    for (int i = 0; i < p; ++i)
      for (int j = 0; j < p; ++j)
        cov_th(i, j) /= (colnorm(i) > T(0) ? colnorm(i) : T(1)) * (colnorm(j) > T(0) ? colnorm(j) : T(1));
    cov_th *= s2;
    res.covariance = dvdth.asDiagonal() * cov_th * dvdth.asDiagonal();
    for (int j = 0; j < p; ++j) res.standard_errors[std::size_t(j)] = sqrt(res.covariance(j, j));

    // Profile likelihood: for each coordinate, re-minimise with it held, and find where the
    // (rescaled) chi^2 rises by profile_delta on either side; infinite where it never does
    // within 40 standard errors (or 40 units of a logarithm).
    const bool do_profile = opt.profile || res.status == fit_status::not_identifiable;
    if (do_profile && (res.status == fit_status::converged ||
                       res.status == fit_status::not_identifiable)) {
      fit_options<T> po = opt;
      po.max_iterations = 100;
      auto excess = [&](int j, T th, Vec& start) -> T {
        start(j) = th;
        const auto sub = detail::levenberg_marquardt<T>(prob, start, po, j);
        if (sub.status == fit_status::non_finite) return std::numeric_limits<T>::infinity();
        start = sub.theta;
        return (sub.chi2 - lm.chi2) / s2;
      };
      for (int j = 0; j < p; ++j) {
        const T se_th = sqrt(cov_th(j, j));
        const bool is_log = j < k && pos[std::size_t(j)];
        T h = isfinite(se_th) && se_th > T(0) ? se_th : (is_log ? T(1) : abs(theta(j)) + T(1));
        if (is_log) h = std::min(h, T(1));
        const T span = is_log ? T(40) : T(40) * h;
        for (int side = -1; side <= 1; side += 2) {
          Vec start = theta;
          T lo = T(0), hi = h, e_hi = T(0);
          bool bracketed = false;
          while (hi <= span) {
            e_hi = excess(j, theta(j) + side * hi, start);
            if (!(e_hi < opt.profile_delta)) { bracketed = true; break; }
            lo = hi;
            hi *= T(2);
          }
          T bound;
          if (!bracketed) {
            bound = side * std::numeric_limits<T>::infinity();
          } else {
            Vec st = theta;
            for (int b = 0; b < 30 && hi - lo > T(1e-4) * h; ++b) {
              const T mid = (lo + hi) / T(2);
              Vec s_try = st;
              const T e = excess(j, theta(j) + side * mid, s_try);
              if (e < opt.profile_delta) { lo = mid; st = s_try; } else { hi = mid; }
            }
            bound = theta(j) + side * (lo + hi) / T(2);
          }
          const T value = isfinite(bound) ? to_value(j, bound)
                          : (is_log ? (side < 0 ? T(0) : std::numeric_limits<T>::infinity())
                                    : bound * (dvdth(j) > T(0) ? T(1) : T(-1)));
          if (side < 0) res.profile_lower[std::size_t(j)] = value;
          else res.profile_upper[std::size_t(j)] = value;
        }
        if (res.profile_lower[std::size_t(j)] > res.profile_upper[std::size_t(j)])
          std::swap(res.profile_lower[std::size_t(j)], res.profile_upper[std::size_t(j)]);
      }
    }
  } else if (res.status == fit_status::converged) {
    res.status = fit_status::not_identifiable;
    res.reason = "converged, but J is rank deficient";
  }
  return res;
}

}  // namespace gecko
