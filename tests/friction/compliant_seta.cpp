// Tests of gecko/friction/compliant_seta.hpp: spatulae at the end of a seta dragged through a
// spring (the hierarchy of paper 000's Discussion).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "gecko/friction/compliant_seta.hpp"
#include "gecko/friction/spatula_simulation.hpp"
#include "gecko/friction/steady_sliding.hpp"
#include "friction/fixtures.hpp"

namespace {

// Unit spatulae: K_par_par = 1, f_par1 = 0, G = 1/2 (so dd = 1), V = 1 (t_on = 1).
struct unit {
  gecko::sliding_params<double> p = friction_test::spatula(200, 1, -0.6, 0.5, 0, 0.1);
  double V = 1;
  static double G(double) { return 0.5; }
};

gecko::compliant_seta_options<double> options(double ratio, double t_off, double periods) {
  gecko::compliant_seta_options<double> o;
  o.spatulae = 200;
  o.spring = ratio * 200.0;  // ratio to the collective stiffness N K_par_par = 200
  o.t_off = t_off;
  // Long enough for several loading periods of the spring, ~ (t_on + t_off) / ratio.
  o.duration = periods * (1 + t_off) * (ratio < 1 ? 1 / ratio : 1.0);
  o.samples = 4000;
  o.seed = 3;
  return o;
}

}  // namespace

TEST_CASE("compliant seta: a stiff spring is the rigid drive", "[friction][seta_compliance]") {
  const unit u;
  for (double t_off : {0.0, 0.3}) {
    auto o = options(1e6, t_off, 40);
    o.transient = 0;
    const auto r = gecko::simulate_compliant_seta(u.p, unit::G, u.V, o);
    // Rigid drive, same phases (the same draws from the same seed).
    gecko::spatula_simulation_options<double> q;
    q.spatulae = o.spatulae;
    q.duration = o.duration;
    q.t_off = t_off;
    q.samples = o.samples;
    q.seed = o.seed;
    const auto rigid = gecko::simulate_spatulae(u.p, unit::G, u.V, q);
    CHECK(r.collective_stiffness == Approx(200.0));
    CHECK(r.stretch == Approx(1.0));
    // The seta lags the stage by F / k_s ~ 1e-6 dd: every detachment is one spatula alone.
    CHECK(r.max_slip_size == 1);
    // Sample by sample the force is the rigid drive's, but for a detachment that the lag moves
    // across a sample time (one spatula's force, N/M K dd = 1, at most).
    std::size_t differ = 0;
    for (std::size_t k = 0; k < o.samples; ++k) {
      CHECK(r.t[k] == rigid.t[k]);
      const double d = std::abs(r.F_par[k] - rigid.F_par[k]);
      CHECK(d <= 1.0 + 1e-6);
      if (d > 1e-3) ++differ;
    }
    CHECK(differ <= o.samples / 100);
    CHECK(r.mean_par == Approx(rigid.mean_par).epsilon(1e-3));
    const auto mf = gecko::steady_sliding(u.p, unit::G, u.V, t_off);
    CHECK(r.mean_par == Approx(mf.F_par).epsilon(0.02));
    CHECK(r.mean_perp == Approx(mf.F_perp).margin(0.02 * std::abs(mf.F_par)));
  }
}

TEST_CASE("compliant seta: a soft spring with re-sticking delay slips at the seta level",
          "[friction][seta_compliance]") {
  const unit u;
  // Spatulae that detach together re-stick together after t_off, at one seta position, and so
  // detach together again: with a soft spring the jumps gather the whole population.
  const auto r = gecko::simulate_compliant_seta(u.p, unit::G, u.V, options(0.01, 0.3, 10));
  CHECK(r.max_slip_size == 200);
  // The spring force falls from its peak (all spatulae at dd: N K dd = 200) to ~0 in one slip.
  CHECK(r.max_drop > 0.9 * 200);
  CHECK(r.std_par > 0.2 * r.mean_par);
}

TEST_CASE("compliant seta: reproducible, and bad input", "[friction][seta_compliance][errors]") {
  const unit u;
  auto o = options(1.0, 0.1, 5);
  o.law = gecko::resticking::exponential;
  const auto a = gecko::simulate_compliant_seta(u.p, unit::G, u.V, o);
  const auto b = gecko::simulate_compliant_seta(u.p, unit::G, u.V, o);
  CHECK(a.F_par == b.F_par);
  CHECK(a.detachments == b.detachments);
  CHECK(a.detachments > 0);
  o.spring = 0;
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o), Catch::Contains("spring = 0"));
  o.spring = 1;
  o.transient = 1;
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o), Catch::Contains("transient = 1"));
  o.transient = 0.5;
  o.samples = 1;
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o), Catch::Contains("samples = 1"));
  o.samples = 10;
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, -1.0, o), Catch::Contains("V = -1"));
  gecko::spatula_population<double> pop;
  pop.G0 = {1.0};
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o, pop),
                    Catch::Contains("population.G0.size() = 1"));
  o.duration = 1e9;  // ~1e11 cycles
  CHECK_THROWS_WITH(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o), Catch::Contains("duration"));
  CHECK(std::isnan(gecko::simulate_compliant_seta(u.p, unit::G, u.V, o, {},
                                                  gecko::policies::nan_policy()).mean_par));
}
