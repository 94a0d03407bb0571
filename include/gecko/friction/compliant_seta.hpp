// gecko/friction/compliant_seta.hpp — a population of spatulae at the end of a compliant seta
// (beyond paper 000: its Discussion argues that the hierarchy keeps stick-slip at the spatula
// level while "the much stiffer seta level moves smoothly"; docs/theory/frictional_adhesion.md
// "Spatulae on a compliant seta").
//
// A stage moves at speed V and drags the seta through a spring of stiffness k_s; the seta itself
// is mass-less, so at every instant the spring force balances the spatulae's lateral force,
//     k_s (u(t) - x) = sum over attached i of (f_par1_i + K_par_par_i (x - x_i)),   u = u0 + V t,
// where x is the seta's lateral position and x_i where spatula i re-stuck. Each spatula follows
// the stick-slip cycle of spatula_simulation.hpp, but its stretch is now x - x_i (the seta's
// motion, not the stage's): it detaches when the stretch reaches dd_i (A2.6, with G = G(V) at
// the stage's speed, the mean sliding rate), stays off for its re-sticking time and re-sticks
// where the seta then is. A detachment drops the force of one spatula, the seta jumps forward to
// the new balance, and every spatula within reach of its own dd detaches in the same instant:
// a slip, which the loop resolves to the end before time goes on (then the detached spatulae
// with t_off = 0 re-stick). Between events x(t) is linear in t, so the run is event by event,
// exact up to rounding, with no time step.
//
// M simulated spatulae stand for the N of sliding_params: each carries N / M times the rigidity
// and forces of its spatula (population factors as in spatula_simulation.hpp), so the collective
// stiffness N K_par_par and the mean forces are those of N spatulae, while a single detachment
// releases 1 / M of the force (the granularity of the simulation, not of the seta).
//
// Reported (over the steady part, after the first `transient` fraction of [0, T]): the mean and
// standard deviation of the spring force (the seta's lateral force) and of the normal force, the
// largest force drop in one slip, the largest number of spatulae detaching in one slip; and the
// seta's lag behind the stage (u - x - its mean) with the forces at `samples` times.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/spatula_simulation.hpp"
#include "gecko/friction/steady_sliding.hpp"

namespace gecko {

template <class T>
struct compliant_seta_options {
  std::size_t spatulae = 200;  // M, simulated spatulae (each standing for N / M)
  T spring = T(1);             // k_s, stage-to-seta stiffness (N/m)
  T duration = T(1);           // T (s)
  T t_off = T(0);              // (mean) re-sticking time (s)
  resticking law = resticking::fixed;
  T transient = T(0.5);        // fraction of [0, T] left out of the statistics
  std::size_t samples = 1000;  // sample times of the trace
  std::uint64_t seed = 1;
};

template <class T>
struct compliant_seta_result {
  T mean_par = T(0), mean_perp = T(0);  // time averages over the steady part
  T std_par = T(0), std_perp = T(0);    // standard deviations over the steady sample times
  T max_drop = T(0);                    // largest drop of the lateral force in one slip (steady)
  std::size_t max_slip_size = 0;        // most spatulae (of M) detaching in one slip (steady)
  std::size_t detachments = 0, slips = 0;  // over [0, T]
  T collective_stiffness = T(0);        // N * mean K_par_par of the spatulae
  T stretch = T(0), t_on = T(0);        // mean dd and dd / V
  std::vector<T> t, lag, F_par, F_perp;  // at the sample times; lag = u - x minus its mean
};

namespace detail {

// A simulated spatula: rigidity and re-sticking forces times N / M, stretch at detachment,
// re-sticking time; x0 is where it re-stuck.
template <class T>
struct seta_spatula {
  T Kpp, Kqp, f1, f2, dd, t_off, x0;
};

}  // namespace detail

template <class T, class Law, class Policy = policies::default_policy>
compliant_seta_result<T> simulate_compliant_seta(const sliding_params<T>& p, const Law& law, T V,
                                                 const compliant_seta_options<T>& opt,
                                                 const spatula_population<T>& pop = {},
                                                 const Policy& = Policy()) {
  using std::sqrt;
  static const char* function = "gecko::simulate_compliant_seta";
  compliant_seta_result<T> r;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  auto fail = [&]() {
    r.mean_par = r.mean_perp = r.std_par = r.std_perp = r.max_drop = nan;
    r.collective_stiffness = r.stretch = r.t_on = nan;
    return r;
  };
  if (!detail::check_positive<T, Policy>(function, "spring", opt.spring,
                                         "0 < spring < inf (stage-to-seta stiffness)"))
    return fail();
  if (!(opt.transient >= T(0) && opt.transient < T(1))) {
    raise_domain_error<T, Policy>(function, "transient", opt.transient, "0 <= transient < 1");
    return fail();
  }
  T G;
  if (!detail::check_run<T, Policy>(function, p, law, V, opt.t_off, opt.duration, opt.spatulae,
                                    opt.samples, 2, G))
    return fail();
  const std::size_t M = opt.spatulae, S = opt.samples;
  if (!detail::check_population<T, Policy>(function, pop, M)) return fail();
  const T w = p.N / T(M), ks = opt.spring, T_end = opt.duration;
  const bool exponential = opt.law == resticking::exponential && opt.t_off > T(0);

  // The spatulae (population factors as in spatula_simulation.hpp), weighted by N / M.
  std::vector<detail::seta_spatula<T>> sp(M);
  T cycles = T(0), sum_K = T(0), sum_dd = T(0);
  for (std::size_t i = 0; i < M; ++i) {
    const T l = detail::factor_or_one(pop.length, i);
    const T c = detail::factor_or_one(pop.stiffness, i) / (l * l * l);
    const T g = detail::factor_or_one(pop.G0, i);
    const T Kpp = c * p.K(0, 0), f1 = c * p.f_par1;
    const T dd = detachment_stretch<T>(Kpp, f1, g * G, Policy());
    sp[i] = {w * Kpp, w * c * p.K(1, 0), w * f1, w * c * p.f_perp1, dd, l * l * opt.t_off, T(0)};
    cycles += T_end / (dd / V + sp[i].t_off) + T(2);
    sum_K += Kpp;
    sum_dd += dd;
  }
  r.collective_stiffness = p.N * sum_K / T(M);
  r.stretch = sum_dd / T(M);
  r.t_on = r.stretch / V;
  // The seta travels V T on average: about M V T / (dd + V t_off) detachments, each a few heap
  // operations. Refuse what would not finish.
  if (!(cycles <= T(2e8))) {
    raise_domain_error<T, Policy>(function, "duration", T_end,
                                  "spatulae * duration / (t_on + t_off) <= 2e8 cycles");
    return fail();
  }

  // Attached spatulae keyed by the seta position where they detach (x0 + dd); detached ones by
  // the time they re-stick. Both min-heaps.
  using entry = std::pair<T, std::size_t>;
  std::priority_queue<entry, std::vector<entry>, std::greater<entry>> attached, detached;
  detail::spatula_rng rng(opt.seed);
  // Sums over the attached spatulae: lateral force F_a + K_a x, normal force P_a + Q_a x.
  T F_a = T(0), K_a = T(0), P_a = T(0), Q_a = T(0);
  auto attach = [&](std::size_t i, T x0) {
    detail::seta_spatula<T>& s = sp[i];
    s.x0 = x0;
    F_a += s.f1 - s.Kpp * x0;
    K_a += s.Kpp;
    P_a += s.f2 - s.Kqp * x0;
    Q_a += s.Kqp;
    attached.push({x0 + s.dd, i});
  };
  // Stationary start as for a rigid drive: spatula i attached with probability t_on / (t_on +
  // t_off) at a uniform stretch (x0 = -stretch with the seta at 0), else off for its residual
  // re-sticking time.
  std::vector<char> on(M, 0);
  for (std::size_t i = 0; i < M; ++i) {
    const T t_on = sp[i].dd / V, t_off = sp[i].t_off;
    const T u = T(rng.uniform()) * (t_on + t_off);
    if (u < t_on) {
      on[i] = 1;
      attach(i, -u * V);
    } else {
      detached.push({exponential ? T(rng.exponential(double(t_off))) : t_on + t_off - u, i});
    }
  }
  // Sums recomputed from scratch every M events (the running sums lose digits as x grows).
  auto resum = [&]() {
    F_a = K_a = P_a = Q_a = T(0);
    for (std::size_t i = 0; i < M; ++i)
      if (on[i]) {
        F_a += sp[i].f1 - sp[i].Kpp * sp[i].x0;
        K_a += sp[i].Kpp;
        P_a += sp[i].f2 - sp[i].Kqp * sp[i].x0;
        Q_a += sp[i].Kqp;
      }
  };
  const T u0 = F_a / ks;  // the spring balances the initial force with the seta at x = 0
  auto position = [&](T t) { return (ks * (u0 + V * t) - F_a) / (ks + K_a); };

  r.t.resize(S);
  r.lag.resize(S);
  r.F_par.resize(S);
  r.F_perp.resize(S);
  const T dt_sample = T_end / T(S);
  std::size_t k = 0, events = 0;
  const T t_steady = opt.transient * T_end;
  auto sample_until = [&](T t_next) {  // samples in [.., t_next) with the current sums
    for (; k < S; ++k) {
      const T tk = (T(k) + T(0.5)) * dt_sample;
      if (!(tk < t_next)) break;
      const T x = position(tk);
      r.t[k] = tk;
      r.lag[k] = u0 + V * tk - x;
      r.F_par[k] = ks * r.lag[k];
      r.F_perp[k] = P_a + Q_a * x;
    }
  };
  T t = T(0);
  while (true) {
    // Next detachment: the seta reaches the smallest x0 + dd (it moves at k_s V / (k_s + K_a)).
    T t_det = std::numeric_limits<T>::infinity();
    if (!attached.empty())
      t_det = ((ks + K_a) * attached.top().first + F_a) / ks;
    if (!attached.empty()) t_det = (t_det - u0) / V;
    if (t_det < t) t_det = t;  // rounding: already due
    const T t_re = detached.empty() ? std::numeric_limits<T>::infinity() : detached.top().first;
    const T t_next = t_det < t_re ? t_det : t_re;
    sample_until(t_next < T_end ? t_next : T_end);
    if (!(t_next < T_end)) break;
    t = t_next;
    if (t_det <= t_re) {
      // A slip: detach the first, then every spatula the jump takes past its dd.
      const T F_before = ks * (u0 + V * t - position(t));
      std::size_t size = 0;
      auto detach_first = [&]() {
        const std::size_t i = attached.top().second;
        attached.pop();
        const detail::seta_spatula<T>& s = sp[i];
        F_a -= s.f1 - s.Kpp * s.x0;
        K_a -= s.Kpp;
        P_a -= s.f2 - s.Kqp * s.x0;
        Q_a -= s.Kqp;
        on[i] = 0;
        ++size;
        detached.push({t + (exponential ? T(rng.exponential(double(s.t_off))) : s.t_off), i});
      };
      while (!attached.empty() && attached.top().first <= position(t)) detach_first();
      // Rounding can leave x a hair short of the threshold that was due: take that one.
      if (size == 0) detach_first();
      if (attached.empty()) F_a = K_a = P_a = Q_a = T(0);  // no rounding left when all are off
      r.detachments += size;
      ++r.slips;
      if (t >= t_steady) {
        const T drop = F_before - ks * (u0 + V * t - position(t));
        if (drop > r.max_drop) r.max_drop = drop;
        if (size > r.max_slip_size) r.max_slip_size = size;
      }
      events += size;
    } else {
      // Re-sticking at the seta's present position, for everyone due now.
      while (!detached.empty() && detached.top().first <= t) {
        const std::size_t i = detached.top().second;
        detached.pop();
        on[i] = 1;
        attach(i, position(t));
        ++events;
      }
    }
    if (events >= M) {
      resum();
      events = 0;
    }
  }
  // Statistics over the steady sample times.
  std::size_t n = 0;
  T m_par = T(0), m_perp = T(0), m_lag = T(0);
  for (std::size_t j = 0; j < S; ++j) {
    m_lag += r.lag[j];
    if (r.t[j] < t_steady) continue;
    m_par += r.F_par[j];
    m_perp += r.F_perp[j];
    ++n;
  }
  m_lag /= T(S);
  for (std::size_t j = 0; j < S; ++j) r.lag[j] -= m_lag;
  if (n == 0) {
    raise_domain_error<T, Policy>(function, "samples", T(S),
                                  "at least one sample time after the transient");
    return fail();
  }
  m_par /= T(n);
  m_perp /= T(n);
  T v_par = T(0), v_perp = T(0);
  for (std::size_t j = 0; j < S; ++j) {
    if (r.t[j] < t_steady) continue;
    v_par += (r.F_par[j] - m_par) * (r.F_par[j] - m_par);
    v_perp += (r.F_perp[j] - m_perp) * (r.F_perp[j] - m_perp);
  }
  r.mean_par = m_par;
  r.mean_perp = m_perp;
  r.std_par = n > 1 ? sqrt(v_par / T(n - 1)) : T(0);
  r.std_perp = n > 1 ? sqrt(v_perp / T(n - 1)) : T(0);
  return r;
}

}  // namespace gecko
