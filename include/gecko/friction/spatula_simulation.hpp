// gecko/friction/spatula_simulation.hpp — a stochastic check of the mean field of
// steady_sliding.hpp (beyond paper 000: its eqs 5–6 and 9–10 assume N spatulae "out of phase").
//
// M independent spatulae are dragged at velocity V. Each cycles: stick with (f_par1, f_perp1),
// stretch at V for t_on = dd / V (dd from A2.6 with G = G(V)) with force f = f1 + K_col0 V s,
// detach, stay off (force 0) for a re-sticking time, re-stick. The re-sticking time is t_off
// (fixed) or exponential with mean t_off (a Poisson re-sticking process). Every spatula starts
// in the stationary state of its renewal process (a uniformly random phase for fixed t_off), so
// the estimators are unbiased at any duration. Forces are piecewise linear in time, so each
// spatula's time integral over [0, T] is exact (event by event, no time step).
//
// Reported: the total force of N spatulae estimated from the M simulated ones,
// F(t) = (N / M) sum_i f_i(t): its exact time average over [0, T] (-> steady_sliding with the
// same t_off as M T -> inf), its standard deviation over the sample times (the fluctuation of
// the force of M spatulae scaled to N), and F(t) itself at `samples` midpoints of [0, T].
//
// Random numbers: std::mt19937_64 with the given seed, turned into doubles and exponentials by
// the formulas below (not by std:: distributions, whose algorithms differ between standard
// libraries), so a seed gives the same result everywhere.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/steady_sliding.hpp"

namespace gecko {

enum class resticking { fixed, exponential };

template <class T>
struct spatula_simulation_options {
  std::size_t spatulae = 1000;  // M, number of simulated spatulae
  T duration = T(1);            // T, averaging time (s)
  T t_off = T(0);               // (mean) re-sticking time (s)
  resticking law = resticking::fixed;
  std::size_t samples = 200;    // sample times of F(t) for the trace and its fluctuation
  std::uint64_t seed = 1;
};

template <class T>
struct spatula_simulation_result {
  T mean_par = T(0), mean_perp = T(0);  // time averages of F(t) over [0, T]
  T std_par = T(0), std_perp = T(0);    // standard deviation of F(t) over the sample times
  T stretch = T(0), t_on = T(0);        // dd and dd / V of every cycle
  std::size_t detachments = 0;          // total number of detachments in [0, T]
  std::vector<T> t, F_par, F_perp;      // F(t) at the sample times
};

namespace detail {

class spatula_rng {
 public:
  explicit spatula_rng(std::uint64_t seed) : gen_(seed) {}
  // Uniform on [0, 1): the top 53 bits.
  double uniform() { return double(gen_() >> 11) * 0x1.0p-53; }
  // Exponential with the given mean; 1 - u is in (0, 1], so the log is finite.
  double exponential(double mean) { return -mean * std::log1p(-uniform()); }

 private:
  std::mt19937_64 gen_;
};

}  // namespace detail

template <class T, class Law, class Policy = policies::default_policy>
spatula_simulation_result<T> simulate_spatulae(const sliding_params<T>& p, const Law& law, T V,
                                               const spatula_simulation_options<T>& opt,
                                               const Policy& = Policy()) {
  using std::isfinite;
  using std::sqrt;
  static const char* function = "gecko::simulate_spatulae";
  spatula_simulation_result<T> r;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  auto fail = [&]() {
    r.mean_par = r.mean_perp = r.std_par = r.std_perp = r.stretch = r.t_on = nan;
    return r;
  };
  if (!detail::check_sliding_params<T, Policy>(function, p)) return fail();
  if (!detail::check_positive<T, Policy>(function, "V", V, "0 < V < inf (drag velocity)"))
    return fail();
  if (!detail::check_t_off<T, Policy>(function, opt.t_off)) return fail();
  if (!detail::check_positive<T, Policy>(function, "duration", opt.duration, "0 < duration < inf"))
    return fail();
  if (opt.spatulae < 1) {
    raise_domain_error<T, Policy>(function, "spatulae", T(opt.spatulae), "spatulae >= 1");
    return fail();
  }
  if (opt.samples < 1) {
    raise_domain_error<T, Policy>(function, "samples", T(opt.samples), "samples >= 1");
    return fail();
  }
  const T G = static_cast<T>(law(V));
  if (!(G > T(0)) || !isfinite(G)) {
    raise_domain_error<T, Policy>(function, "G", G,
                                  "0 < G(V) < inf (a spatula must stretch before it detaches)");
    return fail();
  }
  const T Kpp = p.K(0, 0), Kqp = p.K(1, 0);
  const T f1 = p.f_par1, f2 = p.f_perp1;
  const T dd = detachment_stretch<T>(Kpp, f1, G, Policy());
  const T t_on = dd / V;
  const T t_off = opt.t_off;
  const T T_end = opt.duration;
  const std::size_t M = opt.spatulae, S = opt.samples;
  // Event-driven cost is M T / (t_on + t_off) cycles; refuse what would not finish (or would
  // stall when t_on is below the resolution of the clock at T).
  const T cycles = T(M) * (T_end / (t_on + t_off) + T(2));
  if (!(cycles <= T(1e10)) || !(T_end + t_on > T_end)) {
    raise_domain_error<T, Policy>(function, "duration", T_end,
                                  "spatulae * duration / (t_on + t_off) <= 1e10 cycles");
    return fail();
  }
  const T rate_par = Kpp * V, rate_perp = Kqp * V;  // df/dt while attached
  const bool exponential = opt.law == resticking::exponential && t_off > T(0);
  r.stretch = dd;
  r.t_on = t_on;

  std::vector<T> sum_par(S, T(0)), sum_perp(S, T(0));
  const T dt_sample = T_end / T(S);
  T integral_par = T(0), integral_perp = T(0);
  detail::spatula_rng rng(opt.seed);

  for (std::size_t i = 0; i < M; ++i) {
    // Stationary initial state: attached with probability t_on / (t_on + t_off) (for either
    // re-sticking law: the mean off time is t_off), at a uniform point of the stretch; else
    // detached with the residual off time (uniform for fixed, exponential — memoryless — else).
    bool on;
    T s0;         // attached: time since re-sticking at the segment start
    T seg_start = T(0), seg_end;
    const T u = T(rng.uniform()) * (t_on + t_off);
    if (u < t_on) {
      on = true;
      s0 = u;
      seg_end = t_on - u;
    } else {
      on = false;
      s0 = T(0);
      seg_end = exponential ? T(rng.exponential(double(t_off))) : (t_on + t_off - u);
    }
    std::size_t k = 0;  // next sample index
    while (seg_start < T_end) {
      const T b = seg_end < T_end ? seg_end : T_end;
      if (on) {
        // Exact integral of the linear force over [seg_start, b).
        const T len = b - seg_start;
        const T s_mid = s0 + len / T(2);
        integral_par += len * (f1 + rate_par * s_mid);
        integral_perp += len * (f2 + rate_perp * s_mid);
        for (; k < S; ++k) {
          const T tk = (T(k) + T(0.5)) * dt_sample;
          if (!(tk < b)) break;
          const T s = s0 + (tk - seg_start);
          sum_par[k] += f1 + rate_par * s;
          sum_perp[k] += f2 + rate_perp * s;
        }
      } else {
        for (; k < S; ++k) {
          if (!((T(k) + T(0.5)) * dt_sample < b)) break;
        }
      }
      if (seg_end >= T_end) break;
      // Next segment.
      seg_start = seg_end;
      if (on) {
        ++r.detachments;
        if (t_off > T(0)) {
          on = false;
          seg_end = seg_start + (exponential ? T(rng.exponential(double(t_off))) : t_off);
        } else {
          s0 = T(0);
          seg_end = seg_start + t_on;
        }
      } else {
        on = true;
        s0 = T(0);
        seg_end = seg_start + t_on;
      }
    }
  }

  const T scale = p.N / T(M);
  r.mean_par = scale * integral_par / T_end;
  r.mean_perp = scale * integral_perp / T_end;
  r.t.resize(S);
  r.F_par.resize(S);
  r.F_perp.resize(S);
  T m_par = T(0), m_perp = T(0);
  for (std::size_t k = 0; k < S; ++k) {
    r.t[k] = (T(k) + T(0.5)) * dt_sample;
    r.F_par[k] = scale * sum_par[k];
    r.F_perp[k] = scale * sum_perp[k];
    m_par += r.F_par[k];
    m_perp += r.F_perp[k];
  }
  m_par /= T(S);
  m_perp /= T(S);
  T v_par = T(0), v_perp = T(0);
  for (std::size_t k = 0; k < S; ++k) {
    v_par += (r.F_par[k] - m_par) * (r.F_par[k] - m_par);
    v_perp += (r.F_perp[k] - m_perp) * (r.F_perp[k] - m_perp);
  }
  r.std_par = S > 1 ? sqrt(v_par / T(S - 1)) : T(0);
  r.std_perp = S > 1 ? sqrt(v_perp / T(S - 1)) : T(0);
  return r;
}

}  // namespace gecko
