// Tests of gecko/friction/force_trace.hpp: Figs 4 and 8 of paper 000 (docs/theory/frictional_adhesion.md).
#include <catch2/catch.hpp>

#include <cmath>

#include "gecko/friction/force_trace.hpp"

TEST_CASE("Fig 4: the spatula's normal force turns from +2 to -7", "[friction][force_trace]") {
  const auto r = gecko::force_trace(gecko::paper_rigidity<double>(),
                                    gecko::fig4_spatula_path<double>(), 10);
  REQUIRE(r.t.size() == 21);
  CHECK(r.t.front() == 0);
  CHECK(r.t.back() == 2);
  // Corners exactly: after loading f = (-3, 2) (compressive), after dragging (12, -7) (tensile).
  CHECK(r.f_par[10] == -3);
  CHECK(r.f_perp[10] == 2);
  CHECK(r.f_par.back() == 12);
  CHECK(r.f_perp.back() == -7);
  // In between, f = K d with d on the straight legs.
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const double d_par = r.t[i] <= 0.5 ? 0.0 : 3.0 * (r.t[i] - 0.5) / 1.5;
    const double d_perp = r.t[i] <= 0.5 ? r.t[i] / 0.5 : 1.0;
    CHECK(r.d_par[i] == Approx(d_par).margin(1e-15));
    CHECK(r.d_perp[i] == Approx(d_perp).margin(1e-15));
    CHECK(r.f_par[i] == Approx(5 * d_par - 3 * d_perp).margin(1e-14));
    CHECK(r.f_perp[i] == Approx(-3 * d_par + 2 * d_perp).margin(1e-14));
  }
  // The sign change (frictional adhesion) happens during the drag at d_par = 2/3.
  const auto at = gecko::force_trace(gecko::paper_rigidity<double>(),
                                     gecko::fig4_spatula_path<double>(), std::vector<double>{0.5 + 1.5 * 2.0 / 9.0});
  CHECK(at.f_perp[0] == Approx(0.0).margin(1e-15));
}

TEST_CASE("Fig 8: the seta loop visits (-1,2), (9,-4), (0,0)", "[friction][force_trace]") {
  const auto r = gecko::force_trace(gecko::paper_rigidity<double>(), gecko::fig8_seta_path<double>(),
                                    std::vector<double>{0, 1, 2, 3, 2.5});
  CHECK(r.f_par == std::vector<double>{0, -1, 9, 0, 4.5});
  CHECK(r.f_perp == std::vector<double>{0, 2, -4, 0, -2});
}

TEST_CASE("force_trace: bad input", "[friction][force_trace][errors]") {
  const auto path = gecko::fig4_spatula_path<double>();
  Eigen::Matrix2d nonsym, nonpd;
  nonsym << 5, -3, -3.1, 2;
  nonpd << 5, -4, -4, 2;
  CHECK_THROWS_WITH(gecko::force_trace(nonsym, path), Catch::Contains("K =") && Catch::Contains("symmetric"));
  CHECK_THROWS_WITH(gecko::force_trace(nonpd, path), Catch::Contains("K =") && Catch::Contains("positive definite"));
  CHECK_THROWS_WITH(gecko::force_trace(gecko::paper_rigidity<double>(), path, std::vector<double>{2.5}),
                    Catch::Contains("times = 2.5"));
  CHECK_THROWS_WITH(gecko::force_trace(gecko::paper_rigidity<double>(), path, 0),
                    Catch::Contains("samples_per_segment = 0"));
  auto bad = path;
  bad.t[1] = 0.0;
  CHECK_THROWS_WITH(gecko::force_trace(gecko::paper_rigidity<double>(), bad), Catch::Contains("t = 0"));
  // nan_policy: NaN for a time outside the path, the others computed.
  const auto r = gecko::force_trace(gecko::paper_rigidity<double>(), path, std::vector<double>{-1, 2},
                                    gecko::policies::nan_policy());
  CHECK(std::isnan(r.f_par[0]));
  CHECK(r.f_perp[1] == -7);
}
