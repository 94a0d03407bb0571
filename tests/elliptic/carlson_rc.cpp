// Tests for gecko/elliptic/carlson_rc.hpp: mpmath table (x < y, x > y, nearly equal, x = 0,
// y < 0 principal value), identities (DLMF 19.2.18-19.2.20), R_C(x, y) = R_F(x, y, y),
// domain errors, NaN/inf.
#include <gecko/elliptic/carlson_rc.hpp>
#include <gecko/elliptic/carlson_rf.hpp>

#include <cmath>
#include <limits>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

namespace {
const reference_table& rc_table() {
  static const reference_table t("elliptic_rc.csv");
  return t;
}
}  // namespace

// float: table inputs rounded to float, against double at the rounded inputs (see typed_table.hpp).
TEMPLATE_TEST_CASE("carlson_rc: mpmath table: <= 4 eps", "[carlson_rc]", float, double, long double) {
  const auto& t = rc_table();
  const auto tally = gecko_test::kernel_tally<TestType>(
      t, "carlson_rc", std::array<std::size_t, 2>{t.column("x"), t.column("y")}, t.column("rc"),
      [](auto... a) { return gecko::carlson_rc(a...); });
  CHECK(tally.overall.worst <= 4);
}

TEST_CASE("carlson_rc: special values and identities") {
  const double eps = std::numeric_limits<double>::epsilon();
  const double pi = 3.14159265358979323846;
  CHECK(gecko::carlson_rc(0.0, 1.0) == Approx(pi / 2).epsilon(eps));
  CHECK(gecko::carlson_rc(0.0, 0.25) == Approx(pi).epsilon(eps));
  CHECK(gecko::carlson_rc(2.0, 2.0) == Approx(1 / std::sqrt(2.0)).epsilon(eps));
  // R_C(1/4, 1) = 2 pi / (3 sqrt 3)?  R_C(x, y) = acos(sqrt(x/y))/sqrt(y - x): acos(1/2)/sqrt(3/4)
  CHECK(gecko::carlson_rc(0.25, 1.0) == Approx((pi / 3) / std::sqrt(0.75)).epsilon(2 * eps));
  // R_C(9/4, 2) = log 2 (DLMF 19.2.19 with x > y: acosh(sqrt(9/8))/sqrt(1/4))
  CHECK(gecko::carlson_rc(2.25, 2.0) == Approx(std::log(2.0)).epsilon(2 * eps));
  // R_C(x, y) = R_F(x, y, y), both routes
  for (double xv : {0.0, 1e-8, 0.5, 1.0, 3.0, 1e9}) {
    for (double yv : {1e-9, 0.7, 1.0, 2.0, 1e10}) {
      CHECK(gecko::carlson_rc(xv, yv) == Approx(gecko::carlson_rf(xv, yv, yv)).epsilon(4 * eps));
    }
  }
  // principal value: R_C(x, y) = sqrt(x/(x - y)) R_C(x - y, -y); and R_C(0, y < 0) = 0
  CHECK(gecko::carlson_rc(2.0, -1.0) == Approx(std::sqrt(2.0 / 3.0) * gecko::carlson_rc(3.0, 1.0)).epsilon(2 * eps));
  CHECK(gecko::carlson_rc(0.0, -1.0) == 0.0);
  // homogeneity of degree -1/2
  CHECK(gecko::carlson_rc(4e-100 * 3, 4e-100 * 5) == Approx(1e50 / 2 * gecko::carlson_rc(3.0, 5.0)).epsilon(4 * eps));
}

TEST_CASE("carlson_rc: domain errors, NaN, infinity") {
  using gecko_test::domain_error_message;
  CHECK_THAT(domain_error_message([] { gecko::carlson_rc(-1.0, 2.0); }),
             Catch::Contains("gecko::carlson_rc: x = -1 is out of range: need x >= 0 and y != 0"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rc(1.0, 0.0); }), Catch::Contains("y = 0"));
  CHECK(std::isnan(gecko::carlson_rc(1.0, 0.0, gecko::policies::nan_policy())));
  CHECK(std::isnan(gecko::carlson_rc(std::numeric_limits<double>::quiet_NaN(), 0.0)));
  CHECK(gecko::carlson_rc(1.0, std::numeric_limits<double>::infinity()) == 0.0);
  CHECK(gecko::carlson_rc(std::numeric_limits<double>::infinity(), 1.0) == 0.0);
}
