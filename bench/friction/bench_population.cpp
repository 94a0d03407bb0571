// bench/friction/bench_population.cpp — the per-spatula cost of simulate_spatulae, built twice by
// population_cost.sh: against main's spatula_simulation.hpp (before populations) and against this
// tree's (with them). Prints one line per case: name, CPU ns per simulated spatula cycle (median
// of the repetitions), the cycles simulated and the mean force (the same in both builds: the
// check that the two time the same work).
//
//   bench_population_{main,tree} [--reps N]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "gecko/friction/spatula_simulation.hpp"
#include "gecko/friction/steady_sliding.hpp"
#include "harness.hpp"

int main(int argc, char** argv) {
  int reps = 7;
  for (int i = 1; i + 1 < argc; i += 2)
    if (!std::strcmp(argv[i], "--reps")) reps = std::atoi(argv[i + 1]);
  const auto ve = gecko::fig6_viscoelastic<double>();
  const double V = 1e-4, t_off = 1e-4;
  const auto mf = gecko::steady_sliding(ve.params, ve.law, V, t_off);
  gecko::spatula_simulation_options<double> o;
  o.spatulae = 1000;
  o.duration = 100 * (mf.t_on + t_off);  // 100 cycles per spatula
  o.t_off = t_off;
  o.samples = 200;
  auto run = [&](const char* name, gecko::resticking law, auto&& simulate) {
    o.law = law;
    double mean = 0;
    std::size_t cycles = 0;
    const double s = gecko_bench::median_seconds([&] {
      const auto r = simulate();
      mean = r.mean_par;
      cycles = r.detachments;
    }, 1, reps);
    std::printf("%s %.4f %zu %.17g\n", name, 1e9 * s / double(cycles), cycles, mean);
  };
  for (auto law : {gecko::resticking::fixed, gecko::resticking::exponential}) {
    const char* tag = law == gecko::resticking::fixed ? "fixed" : "exponential";
    char name[64];
    std::snprintf(name, sizeof name, "equal_spatulae_%s", tag);
    run(name, law, [&] { return gecko::simulate_spatulae(ve.params, ve.law, V, o); });
#ifdef GECKO_BENCH_POPULATION
    // A lognormal population (log-width 0.3 on length, stiffness and G0): per-spatula cycles.
    gecko::spatula_population<double> pop;
    for (std::size_t i = 0; i < o.spatulae; ++i) {
      const double z = std::sin(1.7 * double(i)) * 1.7;  // spread, deterministic
      pop.length.push_back(std::exp(0.1 * z));
      pop.stiffness.push_back(std::exp(0.3 * std::cos(2.3 * double(i)) * 1.7));
      pop.G0.push_back(std::exp(0.3 * z));
    }
    std::snprintf(name, sizeof name, "population_%s", tag);
    run(name, law, [&] { return gecko::simulate_spatulae(ve.params, ve.law, V, o, pop); });
#endif
  }
  return 0;
}
