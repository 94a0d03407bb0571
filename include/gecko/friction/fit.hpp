// gecko/friction/fit.hpp — fit the steady-sliding model (eqs 9–10 of paper 000, docs/theory/frictional_adhesion.md)
// to measured (V, F_par, F_perp) by Levenberg–Marquardt; beyond the paper, which fitted Fig 6
// by eye.
//
// Free parameters: the detachment law's (G0, V*, n) [viscoelastic] or (G0, V*) [Eyring], fitted
// as logarithms so that they stay positive, and optionally the force offsets f_par1, f_perp1
// and the coupling K_perp_par. N, K_par_par and K_perp_perp are held (only N^2 K_par_par G0 is
// identifiable together with G0). Residuals: model minus data of both force components,
// unweighted. Jacobian analytic:
//     q = sqrt(f1^2 + 2 K G0 g(V)),  F_par = N (f1 + q)/2,  F_perp = N (f2 + rho (q - f1)/2),
//     rho = K_perp_par / K_par_par,  dq/dln G0 = K G0 g / q,  dq/dg = K G0 / q,  dq/df1 = f1 / q.
// Standard errors: s^2 (J^T J)^-1 with s^2 = RSS / (2n - p), mapped back from the logarithms by
// the delta method (se(G0) = G0 se(ln G0)).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/detachment.hpp"
#include "gecko/friction/steady_sliding.hpp"

namespace gecko {

enum class fit_status { converged, max_iterations, singular };

inline const char* to_string(fit_status s) {
  switch (s) {
    case fit_status::converged: return "converged";
    case fit_status::max_iterations: return "max_iterations";
    default: return "singular";
  }
}

template <class T>
struct fit_options {
  bool fit_f_par1 = true;
  bool fit_f_perp1 = true;
  bool fit_coupling = false;  // also fit K_perp_par
  int max_iterations = 200;
  T xtol = T(1e-10);          // relative step size at which to stop
};

template <class T, class Law>
struct steady_sliding_fit {
  sliding_params<T> params;  // fitted (held entries as given)
  Law law;                   // fitted
  std::vector<std::string> names;     // free parameters, in order
  std::vector<T> values;              // their fitted values
  std::vector<T> standard_errors;     // and standard errors
  Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> covariance;  // of values
  T rss = T(0);                       // residual sum of squares
  int iterations = 0;
  fit_status status = fit_status::max_iterations;
};

namespace detail {

// Law parameters as logarithms; g = G / G0 and its derivatives by the shape parameters.
template <class Law>
struct fit_law_traits;

template <class T, class P>
struct fit_law_traits<viscoelastic_detachment<T, P>> {
  static constexpr int shape_params = 2;  // ln V*, ln n
  static std::vector<std::string> names() { return {"G0", "V_star", "n"}; }
  static void get(const viscoelastic_detachment<T, P>& l, T* lp) {
    lp[0] = std::log(l.G0); lp[1] = std::log(l.V_star); lp[2] = std::log(l.n);
  }
  static viscoelastic_detachment<T, P> make(const T* lp) {
    return {std::exp(lp[0]), std::exp(lp[1]), std::exp(lp[2])};
  }
  // g and dg/d(ln V*), dg/d(ln n).
  static T g(const T* lp, T V, T* dg) {
    const T Vs = std::exp(lp[1]), n = std::exp(lp[2]);
    const T r = V / Vs;
    if (r == T(0)) { dg[0] = dg[1] = T(0); return T(1); }
    const T rn = std::pow(r, n);
    dg[0] = -n * rn;
    dg[1] = n * std::log(r) * rn;
    return T(1) + rn;
  }
};

template <class T, class P>
struct fit_law_traits<eyring_detachment<T, P>> {
  static constexpr int shape_params = 1;  // ln V*
  static std::vector<std::string> names() { return {"G0", "V_star"}; }
  static void get(const eyring_detachment<T, P>& l, T* lp) {
    lp[0] = std::log(l.G0); lp[1] = std::log(l.V_star);
  }
  static eyring_detachment<T, P> make(const T* lp) { return {std::exp(lp[0]), std::exp(lp[1])}; }
  static T g(const T* lp, T V, T* dg) {
    const T r = V / std::exp(lp[1]);
    dg[0] = -r / std::sqrt(T(1) + r * r);
    return std::asinh(r);
  }
};

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
  using traits = detail::fit_law_traits<Law>;
  using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  static const char* function = "gecko::fit_steady_sliding";
  steady_sliding_fit<T, Law> res;
  res.params = guess;
  res.law = guess_law;
  res.status = fit_status::singular;
  const T nan = std::numeric_limits<T>::quiet_NaN();

  if (!detail::check_sliding_params<T, Policy>(function, guess)) return res;
  // The guess law is validated by evaluating it once.
  if (!isfinite(static_cast<T>(guess_law(T(0))))) return res;
  constexpr int nlaw = 1 + traits::shape_params;
  const int p = nlaw + int(opt.fit_f_par1) + int(opt.fit_f_perp1) + int(opt.fit_coupling);
  if (2 * n <= std::size_t(p)) {
    raise_domain_error<T, Policy>(function, "len(V)", T(n),
                                  "more data than parameters: 2 len(V) > the free parameters");
    return res;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!detail::check_velocity<T, Policy>(function, V[i])) return res;
    if (!isfinite(F_par[i])) {
      raise_domain_error<T, Policy>(function, "F_par", F_par[i], "finite measured forces");
      return res;
    }
    if (!isfinite(F_perp[i])) {
      raise_domain_error<T, Policy>(function, "F_perp", F_perp[i], "finite measured forces");
      return res;
    }
  }

  // Parameter vector: law logs, then f_par1, f_perp1, K_perp_par as enabled.
  const int i_f1 = opt.fit_f_par1 ? nlaw : -1;
  const int i_f2 = opt.fit_f_perp1 ? nlaw + int(opt.fit_f_par1) : -1;
  const int i_k = opt.fit_coupling ? nlaw + int(opt.fit_f_par1) + int(opt.fit_f_perp1) : -1;
  Vec theta(p);
  traits::get(guess_law, theta.data());
  if (i_f1 >= 0) theta(i_f1) = guess.f_par1;
  if (i_f2 >= 0) theta(i_f2) = guess.f_perp1;
  if (i_k >= 0) theta(i_k) = guess.K(1, 0);
  const T N = guess.N, Kpp = guess.K(0, 0);

  // Residuals and (optionally) the Jacobian at th.
  auto evaluate = [&](const Vec& th, Vec& r, Mat* J) {
    const T G0 = std::exp(th(0));
    const T f1 = i_f1 >= 0 ? th(i_f1) : guess.f_par1;
    const T f2 = i_f2 >= 0 ? th(i_f2) : guess.f_perp1;
    const T Kqp = i_k >= 0 ? th(i_k) : guess.K(1, 0);
    const T rho = Kqp / Kpp;
    T dg[traits::shape_params];
    for (std::size_t i = 0; i < n; ++i) {
      const T g = traits::g(th.data(), V[i], dg);
      const T q = sqrt(f1 * f1 + T(2) * Kpp * G0 * g);
      r(2 * i) = N * (f1 + q) / T(2) - F_par[i];
      r(2 * i + 1) = N * (f2 + rho * (q - f1) / T(2)) - F_perp[i];
      if (!J) continue;
      // dq by each parameter (0 where q = 0: G0 g = 0 and f1 = 0, a corner of measure zero).
      Vec dq = Vec::Zero(p);
      if (q > T(0)) {
        dq(0) = Kpp * G0 * g / q;
        for (int j = 0; j < traits::shape_params; ++j) dq(1 + j) = Kpp * G0 * dg[j] / q;
        if (i_f1 >= 0) dq(i_f1) = f1 / q;
      }
      for (int j = 0; j < p; ++j) {
        T dpar = N * dq(j) / T(2);
        T dperp = N * rho * dq(j) / T(2);
        if (j == i_f1) { dpar += N / T(2); dperp -= N * rho / T(2); }
        if (j == i_f2) dperp += N;
        if (j == i_k) dperp += N * (q - f1) / (T(2) * Kpp);
        (*J)(2 * i, j) = dpar;
        (*J)(2 * i + 1, j) = dperp;
      }
    }
  };

  Vec r(2 * n), r_trial(2 * n);
  Mat J(2 * n, p);
  evaluate(theta, r, &J);
  T rss = r.squaredNorm();
  T lambda = T(-1);
  int it = 0;
  fit_status status = fit_status::max_iterations;
  for (; it < opt.max_iterations; ++it) {
    const Mat A = J.transpose() * J;
    const Vec g = J.transpose() * r;
    Vec D = A.diagonal();
    for (int j = 0; j < p; ++j)
      if (!(D(j) > T(0))) D(j) = T(1);
    if (lambda < T(0)) lambda = T(1e-3);
    bool accepted = false;
    Vec step(p);
    for (int tries = 0; tries < 60; ++tries) {
      Mat Al = A;
      Al.diagonal() += lambda * D;  // Marquardt: scale-invariant damping
      Eigen::LDLT<Mat> ldlt(Al);
      step = ldlt.solve(-g);
      if (ldlt.info() != Eigen::Success || !step.allFinite()) {
        lambda *= T(10);
        continue;
      }
      const Vec trial = theta + step;
      evaluate(trial, r_trial, nullptr);
      const T rss_trial = r_trial.squaredNorm();
      if (isfinite(rss_trial) && rss_trial <= rss) {
        theta = trial;
        r = r_trial;
        const T old_rss = rss;
        rss = rss_trial;
        lambda = lambda / T(3) > T(1e-12) ? lambda / T(3) : T(1e-12);
        accepted = true;
        // Converged: the step is tiny against the parameters, or the fit no longer improves.
        bool small = true;
        for (int j = 0; j < p; ++j)
          if (abs(step(j)) > opt.xtol * (abs(theta(j)) + opt.xtol)) small = false;
        if (small || old_rss - rss <= T(1e-15) * old_rss) status = fit_status::converged;
        break;
      }
      lambda *= T(4);
    }
    if (!accepted) {
      // No downhill step at any damping: at a minimum to rounding, or stuck.
      status = g.norm() <= T(1e-8) * (J.norm() * r.norm() + std::numeric_limits<T>::min())
                   ? fit_status::converged
                   : fit_status::singular;
      break;
    }
    evaluate(theta, r, &J);
    if (status == fit_status::converged) { ++it; break; }
  }

  // Results and standard errors.
  res.iterations = it;
  res.rss = rss;
  res.law = traits::make(theta.data());
  if (i_f1 >= 0) res.params.f_par1 = theta(i_f1);
  if (i_f2 >= 0) res.params.f_perp1 = theta(i_f2);
  if (i_k >= 0) { res.params.K(1, 0) = theta(i_k); res.params.K(0, 1) = theta(i_k); }
  res.names = traits::names();
  if (i_f1 >= 0) res.names.push_back("f_par1");
  if (i_f2 >= 0) res.names.push_back("f_perp1");
  if (i_k >= 0) res.names.push_back("K_perp_par");
  res.values.resize(p);
  for (int j = 0; j < p; ++j) res.values[j] = j < nlaw ? std::exp(theta(j)) : theta(j);
  const Mat A = J.transpose() * J;
  Eigen::LDLT<Mat> ldlt(A);
  res.standard_errors.assign(p, nan);
  res.covariance = Mat::Constant(p, p, nan);
  if (ldlt.info() == Eigen::Success && ldlt.isPositive()) {
    const T s2 = rss / T(2 * n - std::size_t(p));
    Mat cov = s2 * ldlt.solve(Mat::Identity(p, p));
    // Delta method for the logarithms: d value / d theta = value for the law parameters.
    Vec jac(p);
    for (int j = 0; j < p; ++j) jac(j) = j < nlaw ? res.values[j] : T(1);
    cov = jac.asDiagonal() * cov * jac.asDiagonal();
    res.covariance = cov;
    for (int j = 0; j < p; ++j) res.standard_errors[j] = sqrt(cov(j, j));
  } else if (status == fit_status::converged) {
    status = fit_status::singular;  // the parameters are not identifiable from these data
  }
  res.status = status;
  return res;
}

}  // namespace gecko
