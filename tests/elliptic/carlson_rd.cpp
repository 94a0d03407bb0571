// Tests for gecko/elliptic/carlson_rd.hpp: mpmath table (double, long double, float),
// identities (DLMF 19.20.18-19.20.20, 19.18.1), domain errors, NaN/inf, precision policy.
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rf.hpp>

#include <cmath>
#include <limits>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

namespace {
const reference_table& rd_table() {
  static const reference_table t("elliptic_rd.csv");
  return t;
}
}  // namespace

// float: table inputs rounded to float, against double at the rounded inputs (see
// typed_table.hpp); float R_D ~ z^(-3/2) must itself stay a normal float.
TEMPLATE_TEST_CASE("carlson_rd: mpmath table: <= 4 eps", "[carlson_rd]", float, double, long double) {
  const auto& t = rd_table();
  const auto tally = gecko_test::kernel_tally<TestType>(
      t, "carlson_rd", std::array<std::size_t, 3>{t.column("x"), t.column("y"), t.column("z")},
      t.column("rd"), [](auto... a) { return gecko::carlson_rd(a...); },
      [](std::size_t, const auto& ref) { return gecko_test::float_representable(ref()); });
  CHECK(tally.overall.worst <= 4);
}

TEST_CASE("carlson_rd: special values and identities") {
  const double eps = std::numeric_limits<double>::epsilon();
  // R_D(x, x, x) = x^(-3/2)
  for (double xv : {1e-200, 1e-10, 0.25, 1.0, 3.0, 7e11, 1e200}) {
    CHECK(gecko::carlson_rd(xv, xv, xv) == Approx(1 / (xv * std::sqrt(xv))).epsilon(3 * eps));
  }
  // R_D(0, y, y) = 3 pi / (4 y^(3/2))  (DLMF 19.20.18)
  for (double yv : {1e-6, 1.0, 2.0, 5e9}) {
    CHECK(gecko::carlson_rd(0.0, yv, yv) ==
          Approx(3 * 3.14159265358979323846 / (4 * yv * std::sqrt(yv))).epsilon(4 * eps));
  }
  // Sum rule DLMF 19.21.10: R_D(x,y,z) + R_D(y,z,x) + R_D(z,x,y) = 3 / sqrt(xyz)
  const double a = 0.3, b = 1.7, c = 25.0;
  const double sum = gecko::carlson_rd(a, b, c) + gecko::carlson_rd(b, c, a) + gecko::carlson_rd(c, a, b);
  CHECK(sum == Approx(3 / std::sqrt(a * b * c)).epsilon(8 * eps));
  // Symmetric in x and y; homogeneity of degree -3/2 (l = 4^k, exact).
  const double r = gecko::carlson_rd(a, b, c);
  CHECK(gecko::carlson_rd(b, a, c) == Approx(r).epsilon(2 * eps));
  for (int k : {-300, -20, 7, 300}) {
    const double l = std::ldexp(1.0, 2 * k);
    CHECK(gecko::carlson_rd(l * a, l * b, l * c) == Approx(std::ldexp(r, -3 * k)).epsilon(4 * eps));
  }
}

TEST_CASE("carlson_rd: domain errors, NaN, infinity") {
  using gecko_test::domain_error_message;
  CHECK_THAT(domain_error_message([] { gecko::carlson_rd(1.0, 2.0, 0.0); }),
             Catch::Contains("gecko::carlson_rd: z = 0 is out of range") && Catch::Contains("z > 0"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rd(-1.0, 2.0, 1.0); }), Catch::Contains("x = -1"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rd(1.0, -2.0, 1.0); }), Catch::Contains("y = -2"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rd(0.0, 0.0, 1.0); }), Catch::Contains("y = 0"));
  CHECK(std::isnan(gecko::carlson_rd(1.0, 1.0, -1.0, gecko::policies::nan_policy())));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(gecko::carlson_rd(nan, 1.0, 1.0)));
  CHECK(std::isnan(gecko::carlson_rd(1.0, 1.0, nan)));
  CHECK(gecko::carlson_rd(1.0, 2.0, std::numeric_limits<double>::infinity()) == 0.0);
}

TEST_CASE("carlson_rd: precision policy") {
  const auto& t = rd_table();
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column("rd");
  auto worst_with = [&](auto policy) {
    long double worst = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double r = gecko::carlson_rd(t.get<double>(i, x), t.get<double>(i, y),
                                         t.get<double>(i, z), policy);
      worst = std::fmax(worst, std::fabs(r - t.value(i, v)) / t.value(i, v));
    }
    return worst;
  };
  const long double e12 = worst_with(gecko::policies::precision<12>());
  const long double e30 = worst_with(gecko::policies::precision<30>());
  WARN("carlson_rd relative error at precision<12>: " << double(e12) << ", <30>: " << double(e30));
  CHECK(e12 <= std::ldexp(1.0L, -12));
  CHECK(e30 <= std::ldexp(1.0L, -30));
  CHECK(e12 > std::ldexp(1.0L, -30));
}
