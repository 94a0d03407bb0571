// Tests for gecko/elliptic/ellint_k.hpp: mpmath table (double, long double, float), special
// values K(0) = pi/2, K(1) = inf, K(-inf) = 0, domain errors, NaN.
#include <gecko/elliptic/ellint_k.hpp>

#include <cmath>
#include <limits>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

using gecko_test::complete_table;

// float: table inputs rounded to float (and still below 1), against double at the rounded
// inputs (see typed_table.hpp).
TEMPLATE_TEST_CASE("ellint_k: mpmath table: <= 3 eps", "[ellint_k]", float, double, long double) {
  const auto& t = complete_table();
  const auto m = t.column("m");
  CHECK(gecko_test::kernel_tally<TestType>(
            t, "ellint_k", std::array<std::size_t, 1>{m}, t.column("K"),
            [](auto mm) { return gecko::ellint_k(mm); },
            [&](std::size_t i, const auto&) { return t.get<float>(i, m) < 1; })
            .overall.worst <= 3);
}

TEST_CASE("ellint_k: special values, domain, NaN") {
  const double pi = 3.14159265358979323846;
  CHECK(gecko::ellint_k(0.0) == Approx(pi / 2).epsilon(1e-16));
  CHECK(gecko::ellint_k(1.0) == std::numeric_limits<double>::infinity());
  CHECK(gecko::ellint_k(1.0f) == std::numeric_limits<float>::infinity());
  CHECK(gecko::ellint_k(-std::numeric_limits<double>::infinity()) == 0.0);
  // K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi))  (DLMF 19.20.2 via K = R_F(0, 1/2, 1))
  CHECK(gecko::ellint_k(0.5) == Approx(1.854074677301371918433850347195260046217598823521766905586).epsilon(2.3e-16));
  CHECK_THAT(gecko_test::domain_error_message([] { gecko::ellint_k(1.5); }),
             Catch::Contains("gecko::ellint_k: m = 1.5 is out of range: need m <= 1"));
  CHECK(std::isnan(gecko::ellint_k(1.5, gecko::policies::nan_policy())));
  CHECK(std::isnan(gecko::ellint_k(std::numeric_limits<double>::quiet_NaN())));
}
