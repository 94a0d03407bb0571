// Tests of gecko/friction/fit.hpp: round trips on synthetic Fig-6-like data.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gecko/friction/fit.hpp"
#include "gecko/friction/steady_sliding.hpp"

namespace {

// Reproducible normal deviates (Box-Muller on the top 53 bits of mt19937_64).
struct normal_rng {
  std::mt19937_64 gen;
  explicit normal_rng(std::uint64_t seed) : gen(seed) {}
  double uniform() { return (double(gen() >> 11) + 0.5) * 0x1.0p-53; }
  double operator()() {
    return std::sqrt(-2 * std::log(uniform())) * std::cos(6.283185307179586 * uniform());
  }
};

template <class Law>
struct dataset {
  std::vector<double> V, F_par, F_perp;
};

template <class Law>
dataset<Law> synthesise(const gecko::sliding_params<double>& p, const Law& law, double noise,
                        std::uint64_t seed, int n = 40) {
  dataset<Law> d;
  normal_rng rng(seed);
  for (int i = 0; i < n; ++i) {
    const double V = 1e-6 * std::pow(10.0, 4.0 * i / (n - 1));  // 1 um/s .. 10 mm/s
    const auto f = gecko::steady_sliding(p, law, V);
    d.V.push_back(V);
    d.F_par.push_back(f.F_par + noise * rng());
    d.F_perp.push_back(f.F_perp + noise * rng());
  }
  return d;
}

}  // namespace

TEST_CASE("fit: noise-free viscoelastic data are recovered exactly", "[friction][fit]") {
  const auto truth = gecko::fig6_viscoelastic<double>();
  const auto d = synthesise(truth.params, truth.law, 0.0, 1);
  auto guess = truth.params;
  guess.f_perp1 *= 1.6;
  const gecko::viscoelastic_detachment<double> guess_law{3 * truth.law.G0, 0.3 * truth.law.V_star, 0.8};
  gecko::fit_options<double> opt;
  opt.fit_f_par1 = false;  // the paper's fit: f_par1 = 0
  const auto r = gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), d.V.size(),
                                           guess, guess_law, opt);
  CHECK(r.status == gecko::fit_status::converged);
  CHECK(r.names == std::vector<std::string>{"G0", "V_star", "n", "f_perp1"});
  CHECK(r.law.G0 == Approx(truth.law.G0).epsilon(1e-8));
  CHECK(r.law.V_star == Approx(truth.law.V_star).epsilon(1e-8));
  CHECK(r.law.n == Approx(truth.law.n).epsilon(1e-8));
  CHECK(r.params.f_perp1 == Approx(truth.params.f_perp1).epsilon(1e-8));
  CHECK(r.rss < 1e-25);
}

TEST_CASE("fit: noisy data, estimates within their standard errors, errors calibrated",
          "[friction][fit]") {
  const auto truth = gecko::fig6_viscoelastic<double>();
  const double noise = 3e-4;  // 1% of the lateral force
  gecko::fit_options<double> opt;
  opt.fit_f_par1 = false;
  const int R = 40;
  std::vector<double> sum(4, 0), sum2(4, 0), se(4, 0);
  int within = 0;
  for (int k = 0; k < R; ++k) {
    const auto d = synthesise(truth.params, truth.law, noise, 100 + k);
    const auto r = gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(),
                                             d.V.size(), truth.params,
                                             gecko::viscoelastic_detachment<double>{1e-14, 3e-4, 0.6}, opt);
    REQUIRE(r.status == gecko::fit_status::converged);
    const double tv[4] = {truth.law.G0, truth.law.V_star, truth.law.n, truth.params.f_perp1};
    bool all = true;
    for (int j = 0; j < 4; ++j) {
      sum[j] += r.values[j];
      sum2[j] += r.values[j] * r.values[j];
      se[j] += r.standard_errors[j] / R;
      if (std::abs(r.values[j] - tv[j]) > 3 * r.standard_errors[j]) all = false;
    }
    within += all;
    // The residual variance estimates the noise.
    CHECK(std::sqrt(r.rss / (2 * d.V.size() - 4)) == Approx(noise).epsilon(0.3));
  }
  // Nearly every fit has all four parameters within 3 standard errors.
  CHECK(within >= R - 3);
  // Reported standard errors match the spread over the 40 noise realisations (to ~25%).
  for (int j = 0; j < 4; ++j) {
    const double mean = sum[j] / R;
    const double sd = std::sqrt((sum2[j] - R * mean * mean) / (R - 1));
    CHECK(se[j] == Approx(sd).epsilon(0.3));
  }
}

TEST_CASE("fit: Eyring law with f_par1 and the coupling free", "[friction][fit]") {
  const auto truth = gecko::fig6_plastic<double>();
  const auto d = synthesise(truth.params, truth.law, 2e-4, 7);
  auto guess = truth.params;
  guess.f_par1 *= 0.7;
  guess.K(0, 1) = guess.K(1, 0) = -3.0;
  gecko::fit_options<double> opt;
  opt.fit_coupling = true;
  const auto r = gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), d.V.size(),
                                           guess, gecko::eyring_detachment<double>{1e-13, 1e-3}, opt);
  CHECK(r.status == gecko::fit_status::converged);
  CHECK(r.names == std::vector<std::string>{"G0", "V_star", "f_par1", "f_perp1", "K_perp_par"});
  const double tv[5] = {truth.law.G0, truth.law.V_star, truth.params.f_par1, truth.params.f_perp1,
                        truth.params.K(1, 0)};
  for (int j = 0; j < 5; ++j) {
    CHECK(std::abs(r.values[j] - tv[j]) <= 4 * r.standard_errors[j]);
    CHECK(r.standard_errors[j] > 0);
  }
  CHECK(r.params.K(0, 1) == r.params.K(1, 0));
  CHECK(r.covariance.rows() == 5);
}

TEST_CASE("fit: bad input", "[friction][fit][errors]") {
  const auto t = gecko::fig6_viscoelastic<double>();
  auto d = synthesise(t.params, t.law, 0.0, 1, 3);
  // 6 data, 5 parameters: fine; 2 data, 5 parameters: refused.
  CHECK_THROWS_WITH(gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), 2,
                                              t.params, t.law),
                    Catch::Contains("len(V) = 2") && Catch::Contains("more data than parameters"));
  d.V[1] = -1;
  CHECK_THROWS_WITH(gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), 3,
                                              t.params, t.law),
                    Catch::Contains("V = -1"));
  d.V[1] = 1e-4;
  d.F_perp[2] = std::nan("");
  CHECK_THROWS_WITH(gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), 3,
                                              t.params, t.law),
                    Catch::Contains("F_perp = nan"));
  CHECK_THROWS_WITH(gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), 3,
                                              t.params, gecko::viscoelastic_detachment<double>{-1.0, 1.0, 1.0}),
                    Catch::Contains("G0 = -1"));
  auto p = t.params;
  p.K(0, 1) = p.K(1, 0) = 0.1;
  CHECK_THROWS_WITH(gecko::fit_steady_sliding(d.V.data(), d.F_par.data(), d.F_perp.data(), 3, p, t.law),
                    Catch::Contains("K = 0.1"));
}
