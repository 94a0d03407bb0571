// Tests of gecko/peel: Kendall and Rivlin lines (paper eq 17) satisfy their equations, agree in
// the inextensible limit, and report their ranges.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "gecko/peel.hpp"

TEST_CASE("Kendall and Rivlin lines satisfy eq 17", "[peel]") {
  for (double Ft : {-0.4, 0.0, 0.5, 2.0, 7.5, 9.99}) {
    const double w = 1.0, EA = 50.0;
    const double fk = gecko::kendall_fn(Ft, EA, w);
    const double N2 = fk * fk + Ft * Ft;
    CHECK(std::fabs(std::sqrt(N2) + N2 / (2 * EA) - Ft - w) < 4e-15 * (Ft + w + 1));
    CHECK(fk <= 0);
    const double fr = gecko::rivlin_fn(Ft, w);
    CHECK(std::fabs(std::hypot(fr, Ft) - Ft - w) < 4e-15 * (std::fabs(Ft) + w));
    CHECK(gecko::kendall_fn(Ft, std::numeric_limits<double>::infinity(), w) == Approx(fr).epsilon(1e-15));
    CHECK(gecko::kendall_fn(Ft, 1e14, w) == Approx(fr).epsilon(1e-12));
  }
  // Kendall's line ends at (Ft)max = sqrt(2 EA w) with Fn = 0.
  CHECK(gecko::kendall_fn(10.0, 50.0, 1.0) == Approx(0.0).margin(1e-7));
}

TEST_CASE("peel lines: bad input names the parameter", "[peel][errors]") {
  CHECK_THROWS_WITH(gecko::kendall_fn(10.5, 50.0, 1.0), Catch::Contains("Ft") && Catch::Contains("sqrt(2 EA w)"));
  CHECK_THROWS_WITH(gecko::kendall_fn(1.0, -50.0, 1.0), Catch::Contains("EA"));
  CHECK_THROWS_WITH(gecko::kendall_fn(1.0, 50.0, 0.0), Catch::Contains("w"));
  CHECK_THROWS_WITH(gecko::rivlin_fn(-0.6, 1.0), Catch::Contains("Ft") && Catch::Contains("-w/2"));
  CHECK(std::isnan(gecko::rivlin_fn(-0.6, 1.0, gecko::policies::nan_policy())));
}
