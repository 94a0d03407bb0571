// Tests for gecko/elliptic/ellint_e.hpp: mpmath table over the whole domain (double, long
// double, float), special values (DLMF 19.6.9), periodicity and oddness (DLMF 19.2.10),
// monotonicity across the reduction seams, domain errors, NaN, precision policy.
#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_ek.hpp>

#include <cmath>
#include <limits>

#include "elliptic/legendre_support.hpp"
#include "elliptic/typed_table.hpp"

using gecko_test::legendre_tally;

using gecko_test::pi_d;
using gecko_test::pio2;

// float: table inputs rounded to float, against double at the rounded inputs (legendre_tally).
TEMPLATE_TEST_CASE("ellint_e: mpmath table: <= 4 eps", "[ellint_e]", float, double, long double) {
  const auto tally = legendre_tally<TestType>("E", "ellint_e<" + gecko_test::scalar_name<TestType>() + ">",
                                              [](auto phi, auto m) { return gecko::ellint_e(phi, m); });
  CHECK(tally.overall.worst <= 4);
}

TEST_CASE("ellint_e: special values") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double m : {-1e12, -3.0, 0.0, 0.5, 1.0, 4.0}) CHECK(gecko::ellint_e(0.0, m) == 0.0);
  for (double phi : {1e-300, 1e-8, 0.3, 1.0, pio2, 2.0, 10.0, 1e5}) {
    CHECK(gecko::ellint_e(phi, 0.0) == Approx(phi).epsilon(eps));
  }
  // E(phi|1) = sin phi for |phi| <= pi/2, and int_0^phi |cos| beyond (DLMF 19.6.9)
  for (double phi : {1e-10, 0.1, 0.7, 1.2, 1.5, pio2 - 1e-9, pio2}) {
    CHECK(gecko::ellint_e(phi, 1.0) == Approx(std::sin(phi)).epsilon(2 * eps));
    CHECK(gecko::ellint_e(-phi, 1.0) == -gecko::ellint_e(phi, 1.0));
  }
  CHECK(gecko::ellint_e(pi_d, 1.0) == Approx(2.0).epsilon(2 * eps));
  CHECK(gecko::ellint_e(2.0, 1.0) == Approx(2 - std::sin(2.0)).epsilon(2 * eps));
  // 3pi/2 < 5 < 2pi: three full quarter-waves, then int_{3pi/2}^5 cos = 1 + sin 5
  CHECK(gecko::ellint_e(5.0, 1.0) == Approx(4 + std::sin(5.0)).epsilon(2 * eps));
  CHECK(gecko::ellint_e(1.0, -std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
}

TEST_CASE("ellint_e: periodicity E(phi + n pi) = E(phi) + 2n E(m) and oddness") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double m : {-1e6, -2.0, 0.0, 0.3, 0.9, 0.999999, 1.0}) {
    const double Em = gecko::ellint_ek(m).E;
    for (double phi : {0.1, 0.8, 1.4, 1.5707, 2.9}) {
      for (int n : {1, 2, 7, 1000}) {
        // phi + n pi is rounded: E moves by at most |d phi| * max Delta <= |d phi| sqrt(1 - m).
        const double shifted = phi + n * pi_d;
        const long double dphi = (static_cast<long double>(shifted) - phi) -
                                 n * 3.141592653589793238462643383279502884L;
        const double want = gecko::ellint_e(phi, m) + 2 * n * Em;
        const double slack = double(std::fabs(dphi)) * std::sqrt(std::fmax(1.0, 1.0 - m));
        CHECK(std::fabs(gecko::ellint_e(shifted, m) - want) <= 8 * eps * std::fabs(want) + slack);
      }
      CHECK(gecko::ellint_e(-phi, m) == -gecko::ellint_e(phi, m));
      CHECK(gecko::ellint_e(-phi - 5, m) == -gecko::ellint_e(phi + 5, m));
    }
  }
}

TEST_CASE("ellint_e: continuous and increasing across pi/2 and the quadrant seams") {
  for (double m : {-1e12, -1.0, 0.0, 0.5, 0.99, 1 - 1e-12, 1 - 0x1p-53, 1.0}) {
    for (double seam : {pio2, 2.356194490192345, pi_d, 3.9269908169872414, 4.71238898038469,
                        1e6 * pi_d / 2, 3.0e15}) {
      double phi = seam;
      for (int k = 0; k < 6; ++k) phi = std::nextafter(phi, 0.0);
      double prev = gecko::ellint_e(phi, m);
      for (int k = 0; k < 12; ++k) {
        const double next_phi = std::nextafter(phi, 10 * seam);
        const double next = gecko::ellint_e(next_phi, m);
        INFO("m = " << m << ", phi = " << next_phi);
        REQUIRE(std::isfinite(next));
        const double ulp = std::ldexp(1.0, std::ilogb(next) - 52);
        CHECK(next >= prev - 2 * ulp);
        CHECK(next - prev <= (next_phi - phi) * std::sqrt(std::fmax(1.0, 1.0 - m)) + 4 * ulp);
        prev = next;
        phi = next_phi;
      }
    }
  }
}

TEST_CASE("ellint_e: m > 1 up to the boundary, domain errors, NaN") {
  using gecko_test::domain_error_message;
  for (double m : {1.0000001, 2.0, 10.0, 1e6}) {
    const double edge = std::asin(1 / std::sqrt(m));
    CHECK(std::isfinite(gecko::ellint_e(edge, m)));
    CHECK_THAT(domain_error_message([&] { gecko::ellint_e(edge * 1.001, m); }),
               Catch::Contains("gecko::ellint_e: m = ") && Catch::Contains("sin^2(phi) <= 1/m"));
  }
  CHECK_THAT(domain_error_message([] { gecko::ellint_e(-std::numeric_limits<double>::infinity(), 0.5); }),
             Catch::Contains("phi = -inf is out of range: need finite phi"));
  CHECK(std::isnan(gecko::ellint_e(2.0, 1.5, gecko::policies::nan_policy())));
  CHECK(std::isnan(gecko::ellint_e(std::numeric_limits<double>::quiet_NaN(), 0.5)));
  CHECK(std::isnan(gecko::ellint_e(0.5, std::numeric_limits<double>::quiet_NaN())));
}

TEST_CASE("ellint_e: precision policy") {
  const auto& t = gecko_test::legendre_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column("E");
  auto worst_with = [&](auto policy) {
    long double worst = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double r = gecko::ellint_e(t.get<double>(i, phi), t.get<double>(i, m), policy);
      worst = std::fmax(worst, std::fabs(r - t.value(i, v)) / std::fabs(t.value(i, v)));
    }
    return worst;
  };
  const long double e12 = worst_with(gecko::policies::precision<12>());
  const long double e30 = worst_with(gecko::policies::precision<30>());
  WARN("ellint_e relative error at precision<12>: " << double(e12) << ", <30>: " << double(e30));
  CHECK(e12 <= std::ldexp(1.0L, -12));
  CHECK(e30 <= std::ldexp(1.0L, -30));
  CHECK(e12 > std::ldexp(1.0L, -30));
}
