// bench/friction/bench_friction.cpp — the friction kernels in C++ (docs/theory/frictional_adhesion.md): steady
// sliding over 1e6 velocities (both Fig 6 presets), the spatula simulation and the fit.
// Errors: the batch is checked against eqs 9–10 written out directly (max relative difference).
//
//   bench_friction_sliding [--out DIR] [--reps N]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_config.hpp"
#include "gecko/friction.hpp"
#include "harness.hpp"

namespace {

template <class Preset>
double eq9_error(const Preset& pr, const std::vector<double>& V, const std::vector<double>& Fp) {
  double err = 0;
  for (std::size_t i = 0; i < V.size(); i += 997) {
    const auto& p = pr.params;
    const double q = std::sqrt(p.f_par1 * p.f_par1 + 2 * p.K(0, 0) * pr.law(V[i]));
    const double ref = p.N / 2 * (p.f_par1 + q);
    err = std::max(err, std::fabs(Fp[i] - ref) / std::fabs(ref));
  }
  return err;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  int reps = 11;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--out")) out = argv[i + 1];
    if (!std::strcmp(argv[i], "--reps")) reps = std::atoi(argv[i + 1]);
  }
  std::vector<gecko_bench::row> rows;
  const std::size_t n = 1000000;
  std::vector<double> V(n), Fp(n), Fq(n);
  for (std::size_t i = 0; i < n; ++i) V[i] = 1e-7 * std::pow(1e6, double(i) / double(n - 1));

  const auto ve = gecko::fig6_viscoelastic<double>();
  const auto pl = gecko::fig6_plastic<double>();
  {
    const double s = gecko_bench::median_seconds([&] {
      gecko::steady_sliding(ve.params, ve.law, V.data(), n, Fp.data(), Fq.data());
      gecko_bench::keep(Fp);
    }, 1, reps);
    rows.push_back({"sliding", "steady_sliding, FIG6 viscoelastic", "1e6 velocities, 1 thread", s,
                    eq9_error(ve, V, Fp), "vs eq 9 as printed"});
  }
  {
    const double s = gecko_bench::median_seconds([&] {
      gecko::steady_sliding(pl.params, pl.law, V.data(), n, Fp.data(), Fq.data());
      gecko_bench::keep(Fp);
    }, 1, reps);
    rows.push_back({"sliding", "steady_sliding, FIG6 plastic (Eyring)", "1e6 velocities, 1 thread", s,
                    eq9_error(pl, V, Fp), "vs eq 9 as printed"});
  }
  {
    gecko::spatula_simulation_options<double> o;
    o.spatulae = 1000;
    o.t_off = 1e-3;
    o.law = gecko::resticking::exponential;
    const auto mf = gecko::steady_sliding(ve.params, ve.law, 1e-4, o.t_off);
    o.duration = 100 * (mf.t_on + o.t_off);
    double mean = 0;
    const double s = gecko_bench::median_seconds([&] {
      mean = gecko::simulate_spatulae(ve.params, ve.law, 1e-4, o).mean_par;
      gecko_bench::keep(mean);
    }, 1, reps);
    rows.push_back({"simulation", "simulate_spatulae", "1000 spatulae x 100 cycles, exponential t_off",
                    s, std::fabs(mean / mf.F_par - 1), "vs steady_sliding (statistical)"});
  }
  {
    std::vector<double> Vd, Fpd, Fqd;
    for (int i = 0; i < 40; ++i) {
      const double v = 1e-6 * std::pow(10.0, 4.0 * i / 39);
      const auto f = gecko::steady_sliding(ve.params, ve.law, v);
      Vd.push_back(v);
      Fpd.push_back(f.F_par * (1 + 0.01 * std::sin(7.0 * i)));
      Fqd.push_back(f.F_perp + 3e-4 * std::cos(5.0 * i));
    }
    gecko::fit_options<double> fo;
    fo.fit_f_par1 = false;
    auto gl = ve.law;
    gl.G0 *= 3;
    gl.V_star *= 0.3;
    gl.n = 0.7;
    double n_fit = 0;
    const double s = gecko_bench::median_seconds([&] {
      n_fit = gecko::fit_steady_sliding(Vd.data(), Fpd.data(), Fqd.data(), Vd.size(), ve.params, gl, fo).law.n;
      gecko_bench::keep(n_fit);
    }, 20, reps);
    rows.push_back({"fit", "fit_steady_sliding (viscoelastic, 4 parameters)", "40 points, 1% noise",
                    s, std::fabs(n_fit / ve.law.n - 1), "error of n (noise-limited)"});
  }
  gecko_bench::write(rows, out + "/friction_sliding.csv", out + "/friction_sliding.md",
                     "Friction kernels in C++. Flags: " GECKO_BENCH_CXX_FLAGS);
  for (const auto& r : rows)
    std::printf("%-50s %-46s %10.3f ms  err %.2g  %s\n", r.method.c_str(), r.setting.c_str(),
                r.seconds * 1e3, r.error, r.note.c_str());
  return 0;
}
