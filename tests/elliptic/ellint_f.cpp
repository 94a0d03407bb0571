// Tests for gecko/elliptic/ellint_f.hpp: mpmath table over the whole domain (double, long
// double, float), special values (DLMF 19.6.7-19.6.8), periodicity and oddness (DLMF 19.2.10),
// monotonicity across the reduction seams, domain errors, NaN, precision policy.
#include <gecko/elliptic/ellint_f.hpp>
#include <gecko/elliptic/ellint_k.hpp>

#include <cmath>
#include <limits>

#include "elliptic/legendre_support.hpp"
#include "elliptic/typed_table.hpp"

using gecko_test::legendre_tally;

using gecko_test::pi_d;
using gecko_test::pio2;

// float: table inputs rounded to float, against double at the rounded inputs (legendre_tally).
// m > 1 next to sin^2 phi = 1/m is included with no allowance for the conditioning in sin phi:
// Delta^2 is formed from double-word sin and cos (gecko/elliptic/edge_delta.hpp; more rows in
// edge_delta.cpp).
TEMPLATE_TEST_CASE("ellint_f: mpmath table: <= 3 eps, the m > 1 edge included", "[ellint_f]", float,
                   double, long double) {
  auto F = [](auto phi, auto m) { return gecko::ellint_f(phi, m); };
  const auto tally =
      legendre_tally<TestType>("F", "ellint_f<" + gecko_test::scalar_name<TestType>() + ">", F, true);
  CHECK(tally.overall.worst <= 3);
  if (tally.by_region.count("m_above_one_edge")) CHECK(tally.by_region.at("m_above_one_edge").worst <= 3);
}

TEST_CASE("ellint_f: special values") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double m : {-1e12, -3.0, 0.0, 0.5, 1.0, 4.0}) CHECK(gecko::ellint_f(0.0, m) == 0.0);
  for (double phi : {1e-300, 1e-8, 0.3, 1.0, pio2, 2.0, 10.0, 1e5}) {
    CHECK(gecko::ellint_f(phi, 0.0) == Approx(phi).epsilon(eps));
  }
  // F(phi|1) = atanh(sin phi) = asinh(tan phi)  (DLMF 19.6.8)
  for (double phi : {1e-10, 0.1, 0.7, 1.2, 1.5, 1.57, pio2 - 1e-9, pio2}) {
    // asinh(tan phi): no cancellation near pi/2 (atanh(sin phi) would subtract 1 - sin phi).
    const long double want = std::asinh(std::tan(static_cast<long double>(phi)));
    CHECK(gecko::ellint_f(phi, 1.0) == Approx(double(want)).epsilon(2 * eps));
    CHECK(gecko::ellint_f(-phi, 1.0) == -gecko::ellint_f(phi, 1.0));
  }
  // the pole: beyond pi/2 F(phi|1) is infinite (F(pi/2|1) = K(1) = inf)
  CHECK(gecko::ellint_f(2.0, 1.0) == std::numeric_limits<double>::infinity());
  CHECK(gecko::ellint_f(-2.0, 1.0) == -std::numeric_limits<double>::infinity());
  CHECK(gecko::ellint_f(1.0, -std::numeric_limits<double>::infinity()) == 0.0);
}

TEST_CASE("ellint_f: periodicity F(phi + n pi) = F(phi) + 2nK and oddness") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double m : {-1e6, -2.0, 0.0, 0.3, 0.9, 0.999999}) {
    const double K = gecko::ellint_k(m);
    for (double phi : {0.1, 0.8, 1.4, 1.5707, 2.9}) {
      for (int n : {1, 2, 7, 1000}) {
        // phi + n pi is rounded: the reference moves by at most half an ulp of it, i.e. by
        // (ulp / 2) / Delta_min in F with Delta_min = min(1, sqrt(1 - m)); the bound below
        // allows for that and for 3 eps of each of the three computed values.
        const double shifted = phi + n * pi_d;
        const long double exact_shift = static_cast<long double>(shifted) - phi;  // ~ n pi
        const double want = gecko::ellint_f(phi, m) + 2 * n * K +
                            double((exact_shift - n * 3.141592653589793238462643383279502884L) /
                                   std::sqrt(std::fmin(1.0, 1.0 - m * std::pow(std::sin(phi), 2))));
        const double slack = std::ldexp(1.0, std::ilogb(shifted) - 52) /
                             std::sqrt(std::fmin(1.0, 1.0 - m));
        CHECK(std::fabs(gecko::ellint_f(shifted, m) - want) <= 8 * eps * std::fabs(want) + slack);
      }
      CHECK(gecko::ellint_f(-phi, m) == -gecko::ellint_f(phi, m));
      CHECK(gecko::ellint_f(-phi - 5, m) == -gecko::ellint_f(phi + 5, m));
    }
  }
}

TEST_CASE("ellint_f: continuous and increasing across pi/2 and the quadrant seams") {
  // Near-singular states: exactly at, just below and just above the seams of the argument
  // reduction (pi/2, 3pi/4, pi, ...), for m at 0, near 1 and far negative.
  for (double m : {-1e12, -1.0, 0.0, 0.5, 0.99, 1 - 1e-12, 1 - 0x1p-53}) {
    for (double seam : {pio2, 2.356194490192345, pi_d, 3.9269908169872414, 4.71238898038469,
                        1e6 * pi_d / 2, 3.0e15}) {
      double phi = seam;
      for (int k = 0; k < 6; ++k) phi = std::nextafter(phi, 0.0);
      double prev = gecko::ellint_f(phi, m);
      for (int k = 0; k < 12; ++k) {
        const double next_phi = std::nextafter(phi, 10 * seam);
        const double next = gecko::ellint_f(next_phi, m);
        INFO("m = " << m << ", phi = " << next_phi);
        REQUIRE(std::isfinite(next));
        // F increases with slope 1/Delta <= 1/sqrt(1 - m) (m < 1); one rounding step of the
        // result is tolerated.
        const double ulp = std::ldexp(1.0, std::ilogb(next) - 52);
        CHECK(next >= prev - 2 * ulp);
        CHECK(next - prev <= (next_phi - phi) / std::sqrt(std::fmin(1.0, 1.0 - m)) + 4 * ulp);
        prev = next;
        phi = next_phi;
      }
    }
  }
}

TEST_CASE("ellint_f: m > 1 up to the boundary sin^2(phi) = 1/m, domain errors") {
  using gecko_test::domain_error_message;
  // At the boundary (phi = arcsin(1/sqrt m) rounded) the result is finite.
  for (double m : {1.0000001, 2.0, 10.0, 1e6}) {
    const double edge = std::asin(1 / std::sqrt(m));
    CHECK(std::isfinite(gecko::ellint_f(edge, m)));
    CHECK(std::isfinite(gecko::ellint_f(-edge, m)));
    CHECK_THAT(domain_error_message([&] { gecko::ellint_f(edge * 1.001, m); }),
               Catch::Contains("gecko::ellint_f: m = ") && Catch::Contains("sin^2(phi) <= 1/m"));
  }
  CHECK_THAT(domain_error_message([] { gecko::ellint_f(2.0, 1.5); }),
             Catch::Contains("m = 1.5 is out of range: need m <= 1"));
  CHECK_THAT(domain_error_message([] { gecko::ellint_f(std::numeric_limits<double>::infinity(), 0.5); }),
             Catch::Contains("phi = inf is out of range: need finite phi"));
  CHECK_THAT(domain_error_message([] { gecko::ellint_f(0.1, std::numeric_limits<double>::infinity()); }),
             Catch::Contains("m = inf"));
  CHECK(std::isnan(gecko::ellint_f(2.0, 1.5, gecko::policies::nan_policy())));
  CHECK(std::isnan(gecko::ellint_f(std::numeric_limits<double>::quiet_NaN(), 0.5)));
  CHECK(std::isnan(gecko::ellint_f(0.5, std::numeric_limits<double>::quiet_NaN())));
  CHECK(std::isnan(gecko::ellint_f(std::numeric_limits<float>::quiet_NaN(), 5.0f)));
}

TEST_CASE("ellint_f: precision policy") {
  const auto& t = gecko_test::legendre_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column("F");
  auto worst_with = [&](auto policy) {
    long double worst = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double r = gecko::ellint_f(t.get<double>(i, phi), t.get<double>(i, m), policy);
      worst = std::fmax(worst, std::fabs(r - t.value(i, v)) / std::fabs(t.value(i, v)));
    }
    return worst;
  };
  const long double e10 = worst_with(gecko::policies::precision<10>());
  const long double e26 = worst_with(gecko::policies::precision<26>());
  WARN("ellint_f relative error at precision<10>: " << double(e10) << ", <26>: " << double(e26));
  CHECK(e10 <= std::ldexp(1.0L, -10));
  CHECK(e26 <= std::ldexp(1.0L, -26));
  CHECK(e10 > std::ldexp(1.0L, -26));
}
