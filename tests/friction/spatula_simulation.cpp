// Tests of gecko/friction/spatula_simulation.hpp: the stochastic check of eqs 5, 6, 9, 10.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "gecko/friction/spatula_simulation.hpp"
#include "gecko/friction/steady_sliding.hpp"
#include "friction/fixtures.hpp"

namespace {

// A spatula whose attached and detached times are comparable.
struct scene {
  gecko::sliding_params<double> p = friction_test::spatula(1000, 5, -3, 2, 0.2, 0.5);
  gecko::viscoelastic_detachment<double> law{2.0, 1.0, 0.5};
  double V = 0.5;  // t_on = dd(V) / V = 2.26 s, comparable to t_off: the duty factor matters
  double t_off = 0.5;
};

struct rms_errors {
  double par, perp, bias_par, se_par;
};

rms_errors errors(const scene& s, gecko::resticking law, std::size_t M, double T, int R) {
  const auto mf = gecko::steady_sliding(s.p, s.law, s.V, s.t_off);
  double e2p = 0, e2q = 0, sum = 0;
  for (int seed = 1; seed <= R; ++seed) {
    gecko::spatula_simulation_options<double> o;
    o.spatulae = M;
    o.duration = T;
    o.t_off = s.t_off;
    o.law = law;
    o.seed = std::uint64_t(seed) * 7919 + M * 31 + std::uint64_t(T * 1000);  // distinct streams
    o.samples = 8;
    const auto r = gecko::simulate_spatulae(s.p, s.law, s.V, o);
    const double ep = r.mean_par - mf.F_par, eq = r.mean_perp - mf.F_perp;
    e2p += ep * ep;
    e2q += eq * eq;
    sum += ep;
  }
  const double rms = std::sqrt(e2p / R);
  return {rms, std::sqrt(e2q / R), sum / R, rms / std::sqrt(double(R))};
}

}  // namespace

TEST_CASE("simulate_spatulae is reproducible from its seed", "[friction][simulation]") {
  const scene s;
  gecko::spatula_simulation_options<double> o;
  o.spatulae = 50;
  o.duration = 20;
  o.t_off = 0.5;
  o.law = gecko::resticking::exponential;
  o.seed = 42;
  const auto a = gecko::simulate_spatulae(s.p, s.law, s.V, o);
  const auto b = gecko::simulate_spatulae(s.p, s.law, s.V, o);
  CHECK(a.mean_par == b.mean_par);
  CHECK(a.F_perp == b.F_perp);
  CHECK(a.detachments == b.detachments);
  o.seed = 43;
  const auto c = gecko::simulate_spatulae(s.p, s.law, s.V, o);
  CHECK(c.mean_par != a.mean_par);
  REQUIRE(a.t.size() == o.samples);
  CHECK(a.t.front() == Approx(0.5 * 20 / 200.0));
}

TEST_CASE("simulate_spatulae converges to the mean field with t_off (eqs 5-6, 9-10)",
          "[friction][simulation]") {
  const scene s;
  const auto mf = gecko::steady_sliding(s.p, s.law, s.V, s.t_off);
  const double P = mf.t_on + s.t_off;
  const int R = 100;
  SECTION("exponential re-sticking: error ~ (M T)^-1/2") {
    const auto base = errors(s, gecko::resticking::exponential, 50, 20 * P, R);
    const auto moreM = errors(s, gecko::resticking::exponential, 200, 20 * P, R);
    const auto moreT = errors(s, gecko::resticking::exponential, 50, 80 * P, R);
    // Unbiased: the mean error is within 4 standard errors of 0.
    CHECK(std::abs(base.bias_par) <= 4 * base.se_par);
    // 4x the spatulae or 4x the time halves the RMS error (the RMS over 100 seeds is itself
    // uncertain by ~7%, a ratio of two by ~10%: accept 1.5 .. 2.5).
    CHECK(base.par / moreM.par == Approx(2.0).margin(0.5));
    CHECK(base.par / moreT.par == Approx(2.0).margin(0.5));
    CHECK(base.perp / moreT.perp == Approx(2.0).margin(0.5));
    // And it is small: 1% of the force already at 50 spatulae x 20 periods.
    CHECK(base.par < 0.01 * mf.F_par);
  }
  SECTION("fixed re-sticking time, random phase: error ~ M^-1/2 T^-1") {
    // Whole periods would average exactly; the half period left over is what is random.
    const auto base = errors(s, gecko::resticking::fixed, 50, 10.5 * P, R);
    const auto moreM = errors(s, gecko::resticking::fixed, 200, 10.5 * P, R);
    const auto moreT = errors(s, gecko::resticking::fixed, 50, 42.5 * P, R);
    CHECK(std::abs(base.bias_par) <= 4 * base.se_par);
    CHECK(base.par / moreM.par == Approx(2.0).margin(0.5));
    CHECK(base.par / moreT.par == Approx(4.05).margin(1.0));
  }
}

TEST_CASE("simulate_spatulae: force fluctuations are N sigma_f / sqrt(M)", "[friction][simulation]") {
  const scene s;
  const auto mf = gecko::steady_sliding(s.p, s.law, s.V, s.t_off);
  // One spatula: attached a fraction p of the time, force uniform on [f1, f1 + K dd] then.
  const double p = mf.t_on / (mf.t_on + s.t_off);
  const double a = s.p.f_par1, b = s.p.f_par1 + s.p.K(0, 0) * mf.stretch;
  const double m1 = p * (a + b) / 2, m2 = p * (a * a + a * b + b * b) / 3;
  const double sigma = std::sqrt(m2 - m1 * m1);
  const std::size_t M = 400;
  double v = 0;
  const int R = 20;
  for (int seed = 1; seed <= R; ++seed) {
    gecko::spatula_simulation_options<double> o;
    o.spatulae = M;
    o.duration = 200 * (mf.t_on + s.t_off);
    o.t_off = s.t_off;
    o.law = gecko::resticking::exponential;
    o.samples = 400;
    o.seed = std::uint64_t(seed);
    const auto r = gecko::simulate_spatulae(s.p, s.law, s.V, o);
    v += r.std_par * r.std_par;
    // The time series' mean is the time average, to the sampling of the midpoint rule.
    double m = 0;
    for (double f : r.F_par) m += f;
    CHECK(m / double(r.F_par.size()) == Approx(r.mean_par).epsilon(0.02));
  }
  CHECK(std::sqrt(v / R) == Approx(s.p.N * sigma / std::sqrt(double(M))).epsilon(0.08));
}

TEST_CASE("simulate_spatulae: bad input", "[friction][simulation][errors]") {
  const scene s;
  gecko::spatula_simulation_options<double> o;
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, 0.0, o), Catch::Contains("V = 0"));
  o.duration = -1;
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o), Catch::Contains("duration = -1"));
  o.duration = 1;
  o.t_off = -0.1;
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o), Catch::Contains("t_off = -0.1"));
  o.t_off = 0;
  o.spatulae = 0;
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o), Catch::Contains("spatulae = 0"));
  o.spatulae = 10;
  o.duration = 1e12;  // 1e13 cycles: refused rather than run for days
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o), Catch::Contains("duration = 1000000000000"));
  o.duration = 1;
  auto p = s.p;
  p.K(0, 1) = p.K(1, 0) = 100.0;  // not positive definite (K_par_perp >= 0 alone is allowed)
  CHECK_THROWS_WITH(gecko::simulate_spatulae(p, s.law, s.V, o), Catch::Contains("positive definite"));
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, [](double) { return 0.0; }, s.V, o),
                    Catch::Contains("G = 0"));
  CHECK(std::isnan(gecko::simulate_spatulae(s.p, s.law, -1.0, o, gecko::policies::nan_policy()).mean_par));
}

// ---- populations: each spatula its own length, stiffness and G0 --------------------------------

namespace {

// n standard normal quantiles at the midpoints of n equal-probability cells, in a scrambled
// order (so that neighbouring spatulae differ): a deterministic stand-in for a normal sample.
std::vector<double> normal_scores(std::size_t n) {
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double q = (double((i * 7919) % n) + 0.5) / double(n);
    // Inverse of the normal CDF by bisection on erfc (plenty for test data).
    double lo = -10, hi = 10;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (0.5 * std::erfc(-mid / std::sqrt(2.0)) < q ? lo : hi) = mid;
    }
    z[i] = 0.5 * (lo + hi);
  }
  return z;
}

// Lognormal factors of mean 1 and log-width sigma from the scores z.
std::vector<double> lognormal(const std::vector<double>& z, double sigma, std::size_t shift) {
  std::vector<double> v(z.size());
  for (std::size_t i = 0; i < z.size(); ++i)
    v[i] = std::exp(sigma * z[(i + shift) % z.size()] - sigma * sigma / 2);
  return v;
}

}  // namespace

TEST_CASE("simulate_spatulae: a degenerate population is the single population exactly",
          "[friction][simulation][population]") {
  const scene s;
  gecko::spatula_simulation_options<double> o;
  o.spatulae = 300;
  o.duration = 40;
  o.t_off = s.t_off;
  o.samples = 50;
  for (auto law : {gecko::resticking::fixed, gecko::resticking::exponential}) {
    o.law = law;
    const auto ref = gecko::simulate_spatulae(s.p, s.law, s.V, o);
    gecko::spatula_population<double> ones;
    ones.length.assign(o.spatulae, 1.0);
    ones.stiffness.assign(o.spatulae, 1.0);
    ones.G0.assign(o.spatulae, 1.0);
    const auto r = gecko::simulate_spatulae(s.p, s.law, s.V, o, ones);
    CHECK(r.mean_par == ref.mean_par);
    CHECK(r.mean_perp == ref.mean_perp);
    CHECK(r.std_par == ref.std_par);
    CHECK(r.F_par == ref.F_par);
    CHECK(r.F_perp == ref.F_perp);
    CHECK(r.detachments == ref.detachments);
    CHECK(r.mean_field_par == Approx(ref.mean_field_par).epsilon(1e-14));
    CHECK(r.population_perp == Approx(ref.population_perp).epsilon(1e-14));
    // Equal factors other than 1 (powers of 2 and a 3 that both sides apply the same way) are
    // the single population with K, f, G and t_off scaled as the header says.
    gecko::spatula_population<double> eq;
    eq.length.assign(o.spatulae, 2.0);     // K / 8, t_off * 4
    eq.stiffness.assign(o.spatulae, 4.0);  // K * 4: K / 2 in all
    eq.G0.assign(o.spatulae, 3.0);
    auto p2 = s.p;
    p2.K = 0.5 * s.p.K;
    p2.f_par1 = 0.5 * s.p.f_par1;
    p2.f_perp1 = 0.5 * s.p.f_perp1;
    auto o2 = o;
    o2.t_off = 4 * o.t_off;
    const auto law3 = [&s](double V) { return 3.0 * s.law(V); };
    const auto a = gecko::simulate_spatulae(s.p, s.law, s.V, o, eq);
    const auto b = gecko::simulate_spatulae(p2, law3, s.V, o2);
    CHECK(a.mean_par == b.mean_par);
    CHECK(a.F_perp == b.F_perp);
    CHECK(a.detachments == b.detachments);
    // With every spatula equal, the mean field at the mean parameters is the population's.
    CHECK(a.mean_field_par == Approx(a.population_par).epsilon(1e-13));
  }
}

TEST_CASE("simulate_spatulae: a population converges to its averaged mean field",
          "[friction][simulation][population]") {
  const scene s;
  const std::size_t M = 256;
  const auto z = normal_scores(M);
  gecko::spatula_population<double> pop;
  pop.length = lognormal(z, 0.05, 0);
  pop.stiffness = lognormal(z, 0.10, 85);
  pop.G0 = lognormal(z, 0.10, 170);
  // The population average, independently: eqs 9-10 with t_off (steady_sliding) per spatula.
  double pp = 0, pq = 0;
  for (std::size_t i = 0; i < M; ++i) {
    const double l = pop.length[i], c = pop.stiffness[i] / (l * l * l);
    auto p = s.p;
    p.N = s.p.N / double(M);
    p.K = c * s.p.K;
    p.f_par1 = c * s.p.f_par1;
    p.f_perp1 = c * s.p.f_perp1;
    const double g = pop.G0[i];
    const auto f = gecko::steady_sliding(p, [&](double V) { return g * s.law(V); }, s.V,
                                         l * l * s.t_off);
    pp += f.F_par;
    pq += f.F_perp;
  }
  gecko::spatula_simulation_options<double> o;
  o.spatulae = M;
  o.t_off = s.t_off;
  o.samples = 8;
  const auto mf = gecko::steady_sliding(s.p, s.law, s.V, s.t_off);
  const double P = mf.t_on + s.t_off;
  double last_bound = 0;
  for (double periods : {10.3, 103.7}) {
    o.duration = periods * P;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      o.seed = seed;
      const auto r = gecko::simulate_spatulae(s.p, s.law, s.V, o, pop);
      CHECK(r.population_par == Approx(pp).epsilon(1e-13));
      CHECK(r.population_perp == Approx(pq).epsilon(1e-13));
      // The bound of the header comment holds for every seed (plus rounding of the sums).
      CHECK(std::abs(r.mean_par - r.population_par) <= r.bound_par + 1e-12 * std::abs(pp));
      CHECK(std::abs(r.mean_perp - r.population_perp) <= r.bound_perp + 1e-12 * std::abs(pq));
      // It is the range of one spatula over twice the number of periods: ~ 1 / duration.
      CHECK(r.bound_par < 2.0 / periods * pp);
      last_bound = r.bound_par;
    }
  }
  CHECK(last_bound < 0.02 * pp);
}

TEST_CASE("simulate_spatulae: the mean field at the mean parameters is off by O(sigma^2)",
          "[friction][simulation][population]") {
  // Eqs 9-10 are nonlinear in K and G (F ~ sqrt(K G) at f_par1 = 0), so averaging over the
  // population is not evaluating at the mean: the gap is second order in the width.
  const scene s;
  const std::size_t M = 400;
  const auto z = normal_scores(M);
  gecko::spatula_simulation_options<double> o;
  o.spatulae = M;
  o.t_off = s.t_off;
  o.duration = 1;
  o.samples = 1;
  double gap[2];
  for (int k = 0; k < 2; ++k) {
    const double sigma = k == 0 ? 0.1 : 0.05;
    gecko::spatula_population<double> pop;
    pop.stiffness = lognormal(z, sigma, 0);
    pop.G0 = lognormal(z, sigma, 131);
    const auto r = gecko::simulate_spatulae(s.p, s.law, s.V, o, pop);
    gap[k] = r.population_par - r.mean_field_par;
    CHECK(std::abs(gap[k]) < 4 * sigma * sigma * r.mean_field_par);
  }
  CHECK(gap[0] / gap[1] == Approx(4.0).epsilon(0.05));
}

TEST_CASE("simulate_spatulae: bad population", "[friction][simulation][population][errors]") {
  const scene s;
  gecko::spatula_simulation_options<double> o;
  o.spatulae = 4;
  gecko::spatula_population<double> pop;
  pop.G0 = {1, 1, 1};
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o, pop),
                    Catch::Contains("population.G0.size() = 3"));
  pop.G0.clear();
  pop.stiffness = {1, 1, -1, 1};
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o, pop),
                    Catch::Contains("population.stiffness[2] = -1") &&
                        Catch::Contains("0 < factor < inf"));
  pop.stiffness.clear();
  pop.length = {1, 1, 1, std::numeric_limits<double>::infinity()};
  CHECK_THROWS_WITH(gecko::simulate_spatulae(s.p, s.law, s.V, o, pop),
                    Catch::Contains("population.length[3] = inf"));
  CHECK(std::isnan(
      gecko::simulate_spatulae(s.p, s.law, s.V, o, pop, gecko::policies::nan_policy()).mean_par));
}
