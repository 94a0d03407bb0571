// Tests for gecko/elliptic/ellint_ek.hpp: E(m) and K(m) from one call against the mpmath table,
// K agreeing with ellint_k, Legendre's relation E K' + E' K - K K' = pi/2 (DLMF 19.7.1),
// special values, domain errors, NaN.
#include <gecko/elliptic/ellint_ek.hpp>
#include <gecko/elliptic/ellint_k.hpp>

#include <cmath>
#include <limits>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

using gecko_test::complete_table;

// float: table inputs rounded to float (and still below 1), against double at the rounded
// inputs (see typed_table.hpp).
TEMPLATE_TEST_CASE("ellint_ek: mpmath table: E <= 4 eps, K <= 3 eps", "[ellint_ek]", float, double, long double) {
  const auto& t = complete_table();
  const auto m = t.column("m");
  auto below_one = [&](std::size_t i, const auto&) { return t.get<float>(i, m) < 1; };
  CHECK(gecko_test::kernel_tally<TestType>(
            t, "ellint_ek.E", std::array<std::size_t, 1>{m}, t.column("E"),
            [](auto mm) { return gecko::ellint_ek(mm).E; }, below_one)
            .overall.worst <= 4);
  CHECK(gecko_test::kernel_tally<TestType>(
            t, "ellint_ek.K", std::array<std::size_t, 1>{m}, t.column("K"),
            [](auto mm) { return gecko::ellint_ek(mm).K; }, below_one)
            .overall.worst <= 3);
}

TEST_CASE("ellint_ek: Legendre's relation E K' + E' K - K K' = pi/2") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double m : {1e-6, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999}) {
    const auto a = gecko::ellint_ek(m);
    const auto b = gecko::ellint_ek(1 - m);  // 1 - m is exact for m >= 1/2; else one rounding
    const double lhs = a.E * b.K + b.E * a.K - a.K * b.K;
    INFO("m = " << m);
    // terms are as large as K K' ~ log(16/m) pi/2; allow 8 eps of the largest term.
    CHECK(std::fabs(lhs - 1.5707963267948966) <= 8 * eps * a.K * b.K + std::fabs(b.K * (m - (1 - (1 - m)))));
  }
}

TEST_CASE("ellint_ek: agrees with ellint_k, special values, domain, NaN") {
  for (double m : {-1e12, -1.0, 0.0, 0.3, 0.9, 1 - 1e-15}) {
    CHECK(gecko::ellint_ek(m).K == Approx(gecko::ellint_k(m)).epsilon(3e-16));
  }
  CHECK(gecko::ellint_ek(0.0).E == Approx(1.5707963267948966).epsilon(1e-16));
  CHECK(gecko::ellint_ek(1.0).E == 1.0);
  CHECK(gecko::ellint_ek(1.0).K == std::numeric_limits<double>::infinity());
  CHECK(gecko::ellint_ek(-std::numeric_limits<double>::infinity()).K == 0.0);
  CHECK_THAT(gecko_test::domain_error_message([] { gecko::ellint_ek(2.0); }),
             Catch::Contains("gecko::ellint_ek: m = 2 is out of range: need m <= 1"));
  const auto n = gecko::ellint_ek(2.0, gecko::policies::nan_policy());
  CHECK(std::isnan(n.E));
  CHECK(std::isnan(n.K));
  CHECK(std::isnan(gecko::ellint_ek(std::numeric_limits<double>::quiet_NaN()).E));
}
