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
// Populations (beyond paper 000, which takes all N spatulae equal): each simulated spatula may
// have its own length, stiffness and G0, given as factors on the spatula of sliding_params:
//   K_i = c_i K, c_i = stiffness_i / length_i^3   (Appendix 1: the compliance is L^3 / (2 EI)
//                                                  times a shape matrix, so K ~ EI / L^3)
//   (f_par1, f_perp1)_i = c_i (f_par1, f_perp1)   (the spatulae of a seta re-stick at one
//                                                  displacement d1 = K^-1 f1)
//   G_i(V) = G0_i G(V)                            (eqs 7 and 8 are both G0 times a function of V)
//   t_off_i = length_i^2 t_off                    (eq 4: nu_R ~ D / L^2 and t_off ~ 1 / nu_R)
// Spatula i then follows the cycle above with its own dd_i (A2.6), t_on_i and t_off_i. The result
// also carries eqs 9-10 (with the duty factor of eqs 5-6) two ways: at the mean parameters (mean
// length, stiffness and G0: one "mean spatula") and averaged over the population (every
// spatula's own eqs 9-10, averaged: what the simulation converges to), with a bound on the
// distance between the simulated mean and the population average that holds for every seed when
// re-sticking is fixed: spatula i's force is periodic (period P_i = t_on_i + t_off_i, range R_i),
// so its integral over [0, T] differs from T times its mean by at most the oscillation of its
// periodic primitive, (1/2) int_0^P_i |f_i - mean_i| dt <= P_i R_i / 2; the estimate of the
// total force is then within (N / M) sum_i P_i R_i / (2 T) of the population average.
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
#include <string>
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
  T stretch = T(0), t_on = T(0);        // dd and dd / V of a cycle (population: their means)
  std::size_t detachments = 0;          // total number of detachments in [0, T]
  std::vector<T> t, F_par, F_perp;      // F(t) at the sample times
  // Eqs 9-10 with the duty factor of eqs 5-6 (forces of N spatulae): at the mean parameters, and
  // averaged over the simulated population (the two are equal without a population).
  T mean_field_par = T(0), mean_field_perp = T(0);
  T population_par = T(0), population_perp = T(0);
  // |mean - population| <= bound for every seed with fixed re-sticking (see the header comment);
  // infinite for exponential re-sticking, where no such bound holds.
  T bound_par = T(0), bound_perp = T(0);
};

// Per-spatula factors on the spatula of sliding_params (see the header comment): each vector is
// empty (every factor 1) or has one entry per simulated spatula.
template <class T>
struct spatula_population {
  std::vector<T> length;     // L_i / L: K_i ~ L_i^-3, t_off_i ~ L_i^2
  std::vector<T> stiffness;  // a further factor on K_i (and on the re-sticking forces)
  std::vector<T> G0;         // factor on the detachment energy G(V)
  bool empty() const { return length.empty() && stiffness.empty() && G0.empty(); }
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

// One spatula's cycle: the forces just after re-sticking, their rates while attached (K V),
// the attached time dd / V and the (mean) re-sticking time.
template <class T>
struct spatula_cycle {
  T f1, f2, rate_par, rate_perp, t_on, t_off;
};

template <class T, class Policy>
bool check_population_factors(const char* function, const char* name, const std::vector<T>& v,
                              std::size_t M) {
  using std::isfinite;
  if (v.empty()) return true;
  if (v.size() != M) {
    const std::string arg = std::string("population.") + name + ".size()";
    raise_domain_error<T, Policy>(function, arg.c_str(), T(v.size()),
                                  "0 (every factor 1) or spatulae (one factor per spatula)");
    return false;
  }
  for (std::size_t i = 0; i < M; ++i) {
    if (!(v[i] > T(0)) || !isfinite(v[i])) {
      const std::string arg = std::string("population.") + name + "[" + std::to_string(i) + "]";
      raise_domain_error<T, Policy>(function, arg.c_str(), v[i], "0 < factor < inf");
      return false;
    }
  }
  return true;
}

template <class T, class Policy>
bool check_population(const char* function, const spatula_population<T>& pop, std::size_t M) {
  return check_population_factors<T, Policy>(function, "length", pop.length, M) &&
         check_population_factors<T, Policy>(function, "stiffness", pop.stiffness, M) &&
         check_population_factors<T, Policy>(function, "G0", pop.G0, M);
}

// The checks of a run of M spatulae (simulate_spatulae, simulate_compliant_seta), in order; the
// law is called last, with a checked V, and gives G = G(V).
template <class T, class Policy, class Law>
bool check_run(const char* function, const sliding_params<T>& p, const Law& law, T V, T t_off,
               T duration, std::size_t spatulae, std::size_t samples, std::size_t min_samples,
               T& G) {
  using std::isfinite;
  if (!check_sliding_params<T, Policy>(function, p)) return false;
  if (!check_positive<T, Policy>(function, "V", V, "0 < V < inf (drag velocity)")) return false;
  if (!check_t_off<T, Policy>(function, t_off)) return false;
  if (!check_positive<T, Policy>(function, "duration", duration, "0 < duration < inf"))
    return false;
  if (spatulae < 1) {
    raise_domain_error<T, Policy>(function, "spatulae", T(spatulae), "spatulae >= 1");
    return false;
  }
  if (samples < min_samples) {
    raise_domain_error<T, Policy>(function, "samples", T(samples),
                                  min_samples == 1 ? "samples >= 1" : "samples >= 2");
    return false;
  }
  G = static_cast<T>(law(V));
  if (!(G > T(0)) || !isfinite(G)) {
    raise_domain_error<T, Policy>(function, "G", G,
                                  "0 < G(V) < inf (a spatula must stretch before it detaches)");
    return false;
  }
  return true;
}

template <class T>
T factor_or_one(const std::vector<T>& v, std::size_t i) { return v.empty() ? T(1) : v[i]; }

template <class T>
T mean_or_one(const std::vector<T>& v) {
  if (v.empty()) return T(1);
  T s = T(0);
  for (const T& x : v) s += x;
  return s / T(v.size());
}

// A spatula's force range over one period: attached from f1 to f_end, 0 while detached.
template <class T>
T force_range(T f1, T f_end, bool has_off) {
  T lo = f1 < f_end ? f1 : f_end, hi = f1 < f_end ? f_end : f1;
  if (has_off) {
    lo = lo < T(0) ? lo : T(0);
    hi = hi > T(0) ? hi : T(0);
  }
  return hi - lo;
}

// The event loop over M spatulae; cycle(i) gives spatula i's cycle. Apart from the setup, so
// that a population costs the same per spatula as equal spatulae.
template <class T, class Cycle>
void run_spatulae(std::size_t M, const Cycle& cycle, T T_end, std::size_t S, bool exponential,
                  std::uint64_t seed, std::vector<T>& sum_par, std::vector<T>& sum_perp,
                  T& integral_par_out, T& integral_perp_out, std::size_t& detachments_out) {
  // Local accumulators: through the references the compiler would have to assume that the
  // stores to sum_par / sum_perp may change them, and keep them in memory (half as fast again).
  T integral_par = T(0), integral_perp = T(0);
  std::size_t detachments = 0;
  const T dt_sample = T_end / T(S);
  spatula_rng rng(seed);
  for (std::size_t i = 0; i < M; ++i) {
    const spatula_cycle<T>& c = cycle(i);
    const T f1 = c.f1, f2 = c.f2, rate_par = c.rate_par, rate_perp = c.rate_perp;
    const T t_on = c.t_on, t_off = c.t_off;
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
        ++detachments;
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
  integral_par_out += integral_par;
  integral_perp_out += integral_perp;
  detachments_out += detachments;
}

template <class T, class Policy, class Law>
spatula_simulation_result<T> simulate_spatulae_imp(const char* function,
                                                   const sliding_params<T>& p, const Law& law, T V,
                                                   const spatula_simulation_options<T>& opt,
                                                   const spatula_population<T>* pop) {
  using std::sqrt;
  spatula_simulation_result<T> r;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  auto fail = [&]() {
    r.mean_par = r.mean_perp = r.std_par = r.std_perp = r.stretch = r.t_on = nan;
    r.mean_field_par = r.mean_field_perp = r.population_par = r.population_perp = nan;
    r.bound_par = r.bound_perp = nan;
    return r;
  };
  T G;
  if (!check_run<T, Policy>(function, p, law, V, opt.t_off, opt.duration, opt.spatulae,
                            opt.samples, 1, G))
    return fail();
  const std::size_t M = opt.spatulae, S = opt.samples;
  const bool population = pop != nullptr && !pop->empty();
  if (population && !check_population<T, Policy>(function, *pop, M)) return fail();
  const T t_off = opt.t_off;
  const T T_end = opt.duration;
  const bool exponential = opt.law == resticking::exponential && t_off > T(0);

  // Spatula cycle with stiffness factor c, energy factor g and length factor l: its stretch from
  // A2.6 with its own K, f_par1 and G; its eqs 9-10 and its term of the bound accumulated.
  T cycles = T(0), sum_dd = T(0), sum_on = T(0);
  T pop_par = T(0), pop_perp = T(0), bnd_par = T(0), bnd_perp = T(0);
  bool too_short = false;
  auto make_cycle = [&](T c, T g, T l, spatula_cycle<T>& out) {
    sliding_params<T> one = p;
    one.N = T(1);
    one.K = c * p.K;
    one.f_par1 = c * p.f_par1;
    one.f_perp1 = c * p.f_perp1;
    const T G_i = g * G, t_off_i = l * l * t_off;
    const T Kpp = one.K(0, 0), Kqp = one.K(1, 0), f1 = one.f_par1, f2 = one.f_perp1;
    const T dd = detachment_stretch<T>(Kpp, f1, G_i, Policy());
    out = {f1, f2, Kpp * V, Kqp * V, dd / V, t_off_i};
    const sliding_force<T> m = steady_sliding_imp<T, Policy>(function, one, V, G_i, t_off_i);
    const T P = out.t_on + t_off_i;
    cycles += T_end / P + T(2);
    too_short = too_short || !(T_end + out.t_on > T_end);
    sum_dd += dd;
    sum_on += out.t_on;
    pop_par += m.F_par;
    pop_perp += m.F_perp;
    bnd_par += P * force_range(f1, f1 + Kpp * dd, t_off_i > T(0));
    bnd_perp += P * force_range(f2, f2 + Kqp * dd, t_off_i > T(0));
  };
  // Event-driven cost is M T / (t_on + t_off) cycles; refuse what would not finish (or would
  // stall when t_on is below the resolution of the clock at T).
  auto refused = [&]() {
    if (cycles <= T(1e10) && !too_short) return false;
    raise_domain_error<T, Policy>(function, "duration", T_end,
                                  "spatulae * duration / (t_on + t_off) <= 1e10 cycles");
    return true;
  };

  std::vector<T> sum_par(S, T(0)), sum_perp(S, T(0));
  T integral_par = T(0), integral_perp = T(0);
  const T scale = p.N / T(M);
  if (!population) {
    spatula_cycle<T> c;
    make_cycle(T(1), T(1), T(1), c);
    cycles *= T(M);
    if (refused()) return fail();
    r.stretch = sum_dd;
    r.t_on = sum_on;
    r.population_par = r.mean_field_par = p.N * pop_par;
    r.population_perp = r.mean_field_perp = p.N * pop_perp;
    r.bound_par = p.N * bnd_par / (T(2) * T_end);
    r.bound_perp = p.N * bnd_perp / (T(2) * T_end);
    run_spatulae<T>(M, [&c](std::size_t) -> const spatula_cycle<T>& { return c; }, T_end, S,
                    exponential, opt.seed, sum_par, sum_perp, integral_par, integral_perp,
                    r.detachments);
  } else {
    std::vector<spatula_cycle<T>> cyc(M);
    for (std::size_t i = 0; i < M; ++i) {
      const T l = factor_or_one(pop->length, i);
      make_cycle(factor_or_one(pop->stiffness, i) / (l * l * l), factor_or_one(pop->G0, i), l,
                 cyc[i]);
    }
    if (refused()) return fail();
    r.stretch = sum_dd / T(M);
    r.t_on = sum_on / T(M);
    r.population_par = scale * pop_par;
    r.population_perp = scale * pop_perp;
    r.bound_par = scale * bnd_par / (T(2) * T_end);
    r.bound_perp = scale * bnd_perp / (T(2) * T_end);
    // Eqs 9-10 for N spatulae of the mean length, stiffness and G0.
    const T l = mean_or_one(pop->length), c = mean_or_one(pop->stiffness) / (l * l * l);
    sliding_params<T> mean = p;
    mean.K = c * p.K;
    mean.f_par1 = c * p.f_par1;
    mean.f_perp1 = c * p.f_perp1;
    const sliding_force<T> m = steady_sliding_imp<T, Policy>(
        function, mean, V, mean_or_one(pop->G0) * G, l * l * t_off);
    r.mean_field_par = m.F_par;
    r.mean_field_perp = m.F_perp;
    run_spatulae<T>(M, [&cyc](std::size_t i) -> const spatula_cycle<T>& { return cyc[i]; },
                    T_end, S, exponential, opt.seed, sum_par, sum_perp, integral_par,
                    integral_perp, r.detachments);
  }
  if (exponential) r.bound_par = r.bound_perp = std::numeric_limits<T>::infinity();

  r.mean_par = scale * integral_par / T_end;
  r.mean_perp = scale * integral_perp / T_end;
  r.t.resize(S);
  r.F_par.resize(S);
  r.F_perp.resize(S);
  const T dt_sample = T_end / T(S);
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

}  // namespace detail

template <class T, class Law, class Policy = policies::default_policy>
spatula_simulation_result<T> simulate_spatulae(const sliding_params<T>& p, const Law& law, T V,
                                               const spatula_simulation_options<T>& opt,
                                               const Policy& = Policy()) {
  return detail::simulate_spatulae_imp<T, Policy>("gecko::simulate_spatulae", p, law, V, opt,
                                                  nullptr);
}

// A population of different spatulae (factors on length, stiffness and G0, spatula_population).
template <class T, class Law, class Policy = policies::default_policy>
spatula_simulation_result<T> simulate_spatulae(const sliding_params<T>& p, const Law& law, T V,
                                               const spatula_simulation_options<T>& opt,
                                               const spatula_population<T>& population,
                                               const Policy& = Policy()) {
  return detail::simulate_spatulae_imp<T, Policy>("gecko::simulate_spatulae", p, law, V, opt,
                                                  &population);
}

}  // namespace gecko
