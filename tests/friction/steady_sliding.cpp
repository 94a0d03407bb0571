// Tests of gecko/friction/steady_sliding.hpp: eqs 5, 6, 9, 10 of paper 000 (docs/theory/frictional_adhesion.md).
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "gecko/friction/force_trace.hpp"
#include "gecko/friction/steady_sliding.hpp"
#include "friction/fixtures.hpp"

TEST_CASE("Fig 6 presets satisfy the paper's fitted combinations", "[friction][steady_sliding]") {
  const auto ve = gecko::fig6_viscoelastic<double>();
  const auto& p = ve.params;
  CHECK(p.f_par1 == 0);
  CHECK(p.N * std::sqrt(p.K(0, 0) * ve.law.G0 / 2) == Approx(0.03).epsilon(1e-14));
  CHECK(ve.law.V_star == 100e-6);
  CHECK(ve.law.n == 0.45);
  CHECK(p.N * p.f_perp1 == Approx(0.02).epsilon(1e-14));
  CHECK(std::sqrt(p.K(1, 0) * p.K(1, 0) * ve.law.G0 / (2 * p.K(0, 0) * p.f_perp1 * p.f_perp1)) ==
        Approx(0.8).epsilon(1e-14));
  const auto pl = gecko::fig6_plastic<double>();
  const auto& q = pl.params;
  CHECK(q.f_perp1 == 0);
  CHECK(q.N * q.f_par1 / 2 == Approx(0.03).epsilon(1e-14));
  CHECK(2 * q.K(0, 0) * pl.law.G0 / (q.f_par1 * q.f_par1) == Approx(1.0).epsilon(1e-14));
  CHECK(pl.law.V_star == 600e-6);
  CHECK(q.N * q.K(1, 0) * q.f_par1 / (2 * q.K(0, 0)) == Approx(-0.025).epsilon(1e-14));
  // Both rigidities are valid coupled ones.
  using P = gecko::policies::default_policy;
  CHECK(gecko::detail::check_coupled_rigidity<double, P>("f", p.K));
  CHECK(gecko::detail::check_coupled_rigidity<double, P>("f", q.K));
}

TEST_CASE("steady_sliding is eqs 9-10 as printed", "[friction][steady_sliding]") {
  const auto ve = gecko::fig6_viscoelastic<double>();
  const auto pl = gecko::fig6_plastic<double>();
  auto eq9 = [](const gecko::sliding_params<double>& p, double G) {
    return p.N / 2 * (p.f_par1 + std::sqrt(p.f_par1 * p.f_par1 + 2 * p.K(0, 0) * G));
  };
  auto eq10 = [](const gecko::sliding_params<double>& p, double G) {
    return p.N * (p.f_perp1 + p.K(1, 0) / (2 * p.K(0, 0)) *
                                  (-p.f_par1 + std::sqrt(p.f_par1 * p.f_par1 + 2 * p.K(0, 0) * G)));
  };
  for (double V : {0.0, 1e-6, 1e-4, 1e-3, 1e-1}) {
    const auto a = gecko::steady_sliding(ve.params, ve.law, V);
    CHECK(a.F_par == Approx(eq9(ve.params, ve.law(V))).epsilon(1e-14));
    CHECK(a.F_perp == Approx(eq10(ve.params, ve.law(V))).epsilon(1e-13).margin(1e-18));
    const auto b = gecko::steady_sliding(pl.params, pl.law, V);
    CHECK(b.F_par == Approx(eq9(pl.params, pl.law(V))).epsilon(1e-14));
    CHECK(b.F_perp == Approx(eq10(pl.params, pl.law(V))).epsilon(1e-12).margin(1e-18));
  }
  // The Fig 6 shapes: viscoelastic F_par = 0.03 sqrt(1 + (V/V*)^n),
  // F_perp = 0.02 (1 - 0.8 sqrt(1 + (V/V*)^n)), negative (tensile) above a few um/s.
  const double V = 3e-4, g = 1 + std::pow(3.0, 0.45);
  const auto a = gecko::steady_sliding(ve.params, ve.law, V);
  CHECK(a.F_par == Approx(0.03 * std::sqrt(g)).epsilon(1e-14));
  CHECK(a.F_perp == Approx(0.02 * (1 - 0.8 * std::sqrt(g))).epsilon(1e-13));
  CHECK(gecko::steady_sliding(ve.params, ve.law, 0.0).F_perp == Approx(0.004).epsilon(1e-13));
  // Plastic: F_par = 0.03 (1 + sqrt(1 + asinh(V/V*))), F_perp = -0.025 (sqrt(1 + asinh) - 1).
  const double h = std::sqrt(1 + std::asinh(V / 6e-4));
  const auto b = gecko::steady_sliding(pl.params, pl.law, V);
  CHECK(b.F_par == Approx(0.03 * (1 + h)).epsilon(1e-14));
  CHECK(b.F_perp == Approx(-0.025 * (h - 1)).epsilon(1e-13));
}

TEST_CASE("steady_sliding with finite t_off against eqs 5-6 integrated along the path",
          "[friction][steady_sliding]") {
  // Independent route: realise (f_par1, f_perp1) by a tip displacement d1, drag it by the
  // stretch, integrate f = K d along the path with force_trace (trapezoid, exact for linear),
  // and check that the stretch stores exactly G = U(d2) - U(d1) (A2.4-A2.5).
  for (double f1 : {-0.4, 0.0, 0.7}) {
    const gecko::sliding_params<double> p = friction_test::spatula(300, 5, -3, 2.2, f1, 0.3);
    const gecko::viscoelastic_detachment<double> law{0.8, 2.0, 0.5};
    for (double V : {0.1, 3.0})
      for (double t_off : {0.0, 0.05, 2.0}) {
        const auto r = gecko::steady_sliding(p, law, V, t_off);
        const Eigen::Vector2d d1 = p.K.inverse() * Eigen::Vector2d(p.f_par1, p.f_perp1);
        const Eigen::Vector2d d2 = d1 + Eigen::Vector2d(r.stretch, 0);
        CHECK(0.5 * d2.dot(p.K * d2) - 0.5 * d1.dot(p.K * d1) == Approx(law(V)).epsilon(1e-13));
        CHECK(r.t_on == Approx(r.stretch / V).epsilon(1e-15));
        gecko::displacement_path<double> path{{0, r.t_on}, {d1(0), d2(0)}, {d1(1), d2(1)}};
        const auto tr = gecko::force_trace(p.K, path, 64);
        double I_par = 0, I_perp = 0;
        for (std::size_t i = 1; i < tr.t.size(); ++i) {
          const double dt = tr.t[i] - tr.t[i - 1];
          I_par += dt * (tr.f_par[i] + tr.f_par[i - 1]) / 2;
          I_perp += dt * (tr.f_perp[i] + tr.f_perp[i - 1]) / 2;
        }
        CHECK(r.F_par == Approx(p.N * I_par / (r.t_on + t_off)).epsilon(1e-12));
        CHECK(r.F_perp == Approx(p.N * I_perp / (r.t_on + t_off)).epsilon(1e-12));
      }
  }
}

TEST_CASE("steady_sliding takes any callable law, and a batch", "[friction][steady_sliding]") {
  const auto ve = gecko::fig6_viscoelastic<double>();
  auto twice = [&](double V) { return 2 * ve.law(V); };
  const auto r = gecko::steady_sliding(ve.params, twice, 1e-4);
  CHECK(r.F_par == Approx(std::sqrt(2.0) * gecko::steady_sliding(ve.params, ve.law, 1e-4).F_par));
  const auto e = gecko::steady_sliding_from_energy(ve.params, 1e-4, 2 * ve.law(1e-4));
  CHECK(e.F_par == r.F_par);
  CHECK(e.F_perp == r.F_perp);
  std::vector<double> V{0.0, 1e-5, -1.0, 1e-3}, Fp(4), Fq(4), dd(4), ton(4);
  gecko::steady_sliding(ve.params, ve.law, V.data(), V.size(), Fp.data(), Fq.data(), dd.data(),
                        ton.data(), 0.0, gecko::policies::nan_policy());
  CHECK(std::isnan(Fp[2]));
  CHECK(std::isnan(Fq[2]));
  CHECK(Fp[3] == gecko::steady_sliding(ve.params, ve.law, 1e-3).F_par);
  CHECK(std::isinf(ton[0]));
  CHECK_THROWS_WITH(gecko::steady_sliding(ve.params, ve.law, V.data(), V.size(), Fp.data(), Fq.data()),
                    Catch::Contains("V = -1"));
}

TEST_CASE("steady_sliding: bad input names the argument", "[friction][steady_sliding][errors]") {
  auto ve = gecko::fig6_viscoelastic<double>();
  auto p = ve.params;
  p.K(0, 1) = p.K(1, 0) = 5.0;  // K_par_perp >= 0 is allowed, but K must be positive definite
  CHECK_THROWS_WITH(gecko::steady_sliding(p, ve.law, 1e-4), Catch::Contains("positive definite"));
  p = ve.params;
  p.K(0, 1) = -3.0;  // non-symmetric
  CHECK_THROWS_WITH(gecko::steady_sliding(p, ve.law, 1e-4), Catch::Contains("symmetric"));
  p = ve.params;
  p.K(1, 1) = 1.0;  // det = 6 - 10.24 < 0
  CHECK_THROWS_WITH(gecko::steady_sliding(p, ve.law, 1e-4), Catch::Contains("positive definite"));
  p = ve.params;
  p.N = 0;
  CHECK_THROWS_WITH(gecko::steady_sliding(p, ve.law, 1e-4), Catch::Contains("N = 0"));
  CHECK_THROWS_WITH(gecko::steady_sliding(ve.params, ve.law, -1e-4), Catch::Contains("V = -0.0001"));
  CHECK_THROWS_WITH(gecko::steady_sliding(ve.params, ve.law, 1e-4, -1.0), Catch::Contains("t_off = -1"));
  CHECK_THROWS_WITH(gecko::steady_sliding(ve.params, [](double) { return -1.0; }, 1e-4),
                    Catch::Contains("G = -1"));
  CHECK_THROWS_WITH(gecko::steady_sliding(ve.params, [](double) { return std::nan(""); }, 1e-4),
                    Catch::Contains("G = nan"));
  // t_off > 0 with a law that does not stretch at V = 0 (Eyring, f_par1 > 0): t_on = 0/0.
  const auto pl = gecko::fig6_plastic<double>();
  CHECK_THROWS_WITH(gecko::steady_sliding(pl.params, pl.law, 0.0, 1e-6), Catch::Contains("V = 0"));
  CHECK(std::isnan(gecko::steady_sliding(pl.params, pl.law, 0.0, 1e-6, gecko::policies::nan_policy()).F_par));
}

TEMPLATE_TEST_CASE("steady_sliding in every scalar type", "[friction][steady_sliding]", float,
                   double, long double) {
  using T = TestType;
  const auto ve = gecko::fig6_viscoelastic<T>();
  const auto pl = gecko::fig6_plastic<T>();
  const long double V = 3e-4L;
  const long double g = 1 + std::pow(3.0L, 0.45L);
  const long double h = std::sqrt(1 + std::asinh(V / 6e-4L));
  const T eps = std::numeric_limits<T>::epsilon();
  const auto a = gecko::steady_sliding(ve.params, ve.law, T(V));
  CHECK(std::abs(a.F_par / (0.03L * std::sqrt(g)) - 1) <= 16 * eps);
  CHECK(std::abs(a.F_perp / (0.02L * (1 - 0.8L * std::sqrt(g))) - 1) <= 64 * eps);
  const auto b = gecko::steady_sliding(pl.params, pl.law, T(V));
  CHECK(std::abs(b.F_par / (0.03L * (1 + h)) - 1) <= 16 * eps);
  CHECK(std::abs(b.F_perp / (-0.025L * (h - 1)) - 1) <= 64 * eps);
}

// K_par_perp >= 0 (issue 14): eq 9 does not involve K_perp_par; eq 10 is linear in it, so the
// straight pillar (0) keeps F_perp = N f_perp1 and the mirror image (dragging against the
// curvature, +K_perp_par) gives F_perp(+k) + F_perp(-k) = 2 N f_perp1, compressive and growing.
TEST_CASE("steady_sliding: straight pillar and dragging against the curvature",
          "[friction][steady_sliding]") {
  const auto ve = gecko::fig6_viscoelastic<double>();
  auto pillar = ve.params, against = ve.params;
  pillar.K(0, 1) = pillar.K(1, 0) = 0.0;
  against.K(0, 1) = against.K(1, 0) = -ve.params.K(0, 1);
  double last = 0;
  for (double V : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2}) {
    const auto c = gecko::steady_sliding(ve.params, ve.law, V);
    const auto s = gecko::steady_sliding(pillar, ve.law, V);
    const auto a = gecko::steady_sliding(against, ve.law, V);
    CHECK(s.F_par == c.F_par);
    CHECK(a.F_par == c.F_par);
    CHECK(s.F_perp == Approx(ve.params.N * ve.params.f_perp1).epsilon(1e-15));
    CHECK(a.F_perp + c.F_perp == Approx(2 * ve.params.N * ve.params.f_perp1).epsilon(1e-13));
    CHECK(a.F_perp > last);
    last = a.F_perp;
  }
}

// Plastic (Eyring) law at V = 0: G(0) = 0 and f_par1 > 0 give dd = 2G/(f1 + q) ~ G/f1, so
// t_on = dd/V -> G'(0)/f1 = G0/(V* f1) (finite), not inf; the viscoelastic G(0) = G0 > 0
// keeps t_on = inf (a spatula never detaches without sliding).
TEST_CASE("steady_sliding: plastic t_on at V = 0 is its limit", "[friction][steady_sliding]") {
  const auto pl = gecko::fig6_plastic<double>();
  const double limit = pl.law.G0 / (pl.law.V_star * pl.params.f_par1);
  const auto r0 = gecko::steady_sliding(pl.params, pl.law, 0.0);
  CHECK(r0.t_on == Approx(limit).epsilon(1e-15));
  const auto r1 = gecko::steady_sliding(pl.params, pl.law, 1e-12);
  CHECK(r1.t_on == Approx(limit).epsilon(1e-6));
  double V[2] = {0.0, 1e-12}, Fp[2], Fq[2], dd[2], ton[2];
  gecko::steady_sliding(pl.params, pl.law, V, 2, Fp, Fq, dd, ton);
  CHECK(ton[0] == Approx(limit).epsilon(1e-15));
  const auto ve = gecko::fig6_viscoelastic<double>();
  CHECK(std::isinf(gecko::steady_sliding(ve.params, ve.law, 0.0).t_on));
}
