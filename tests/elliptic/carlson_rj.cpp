// Tests for gecko/elliptic/carlson_rj.hpp: mpmath table (p > 0 and the Cauchy principal value
// p < 0), identities (R_J(x,y,z,z) = R_D(x,y,z), DLMF 19.20.5; R_J(x,x,x,x) = x^-3/2),
// domain errors, NaN/inf, precision policy.
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rj.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

namespace {
const reference_table& rj_table() {
  static const reference_table t("elliptic_rj.csv");
  return t;
}
}  // namespace

// The principal value (p < 0) goes through DLMF 19.20.14, a sum of three terms of mixed sign;
// its rows carry the cancellation factor (sum of |terms|) / |sum| of that formula, and are held
// to 4 eps times it (the formula's own conditioning), all other rows to 4 eps.
template <class T>
void check_rj(const char* what) {
  const auto& t = rj_table();
  const auto cancel = t.column("pv_cancel"), region = t.column("region");
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), p = t.column("p"),
             v = t.column("rj");
  long double worst_plain = 0, worst_pv_ratio = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const long double err = gecko_test::error_in_eps<T>(
        gecko::carlson_rj(t.get<T>(i, x), t.get<T>(i, y), t.get<T>(i, z), t.get<T>(i, p)), t.value(i, v));
    if (t.text(i, region) == "pv") {
      worst_pv_ratio = std::fmax(worst_pv_ratio, err / (4 * t.value(i, cancel)));
    } else {
      worst_plain = std::fmax(worst_plain, err);
    }
  }
  WARN(what << ": p > 0 worst " << double(worst_plain) << " eps; p < 0 worst err / (4 cancel) = "
            << double(worst_pv_ratio));
  CHECK(worst_plain <= 4);
  CHECK(worst_pv_ratio <= 1);
}

// float: table inputs rounded to float, p > 0 only, against double at the rounded inputs (see
// typed_table.hpp), <= 4 eps(float).
TEMPLATE_TEST_CASE("carlson_rj: mpmath table: <= 4 eps (p.v.: 4 eps x cancellation)", "[carlson_rj]", float,
                   double, long double) {
  const std::string what = "carlson_rj<" + gecko_test::scalar_name<TestType>() + ">";
  if constexpr (std::is_same<TestType, float>::value) {
    const auto& t = rj_table();
    const auto p = t.column("p");
    const auto tally = gecko_test::kernel_tally<float>(
        t, "carlson_rj", std::array<std::size_t, 4>{t.column("x"), t.column("y"), t.column("z"), p},
        t.column("rj"), [](auto... a) { return gecko::carlson_rj(a...); },
        [&](std::size_t i, const auto& ref) {
          return t.get<double>(i, p) > 0 && gecko_test::float_representable(ref());
        });
    CHECK(tally.overall.worst <= 4);
  } else {
    check_rj<TestType>(what.c_str());
  }
}

TEST_CASE("carlson_rj: special values and identities") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (double xv : {1e-100, 0.25, 1.0, 7e11}) {
    CHECK(gecko::carlson_rj(xv, xv, xv, xv) == Approx(1 / (xv * std::sqrt(xv))).epsilon(3 * eps));
  }
  const double a = 0.3, b = 1.7, c = 25.0;
  CHECK(gecko::carlson_rj(a, b, c, c) == Approx(gecko::carlson_rd(a, b, c)).epsilon(8 * eps));
  CHECK(gecko::carlson_rj(0.0, b, c, c) == Approx(gecko::carlson_rd(0.0, b, c)).epsilon(8 * eps));
  // symmetric in x, y, z
  const double r = gecko::carlson_rj(a, b, c, 2.0);
  CHECK(gecko::carlson_rj(c, a, b, 2.0) == Approx(r).epsilon(4 * eps));
  // principal value symmetric too (the implementation sorts)
  const double q = gecko::carlson_rj(a, b, c, -2.0);
  CHECK(gecko::carlson_rj(c, b, a, -2.0) == Approx(q).epsilon(4 * eps));
}

TEST_CASE("carlson_rj: domain errors, NaN, infinity") {
  using gecko_test::domain_error_message;
  CHECK_THAT(domain_error_message([] { gecko::carlson_rj(1.0, 2.0, 3.0, 0.0); }),
             Catch::Contains("gecko::carlson_rj: p = 0 is out of range") && Catch::Contains("p != 0"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rj(1.0, 2.0, -3.0, 1.0); }), Catch::Contains("z = -3"));
  CHECK_THAT(domain_error_message([] { gecko::carlson_rj(0.0, 0.0, 3.0, 1.0); }), Catch::Contains("y = 0"));
  CHECK(std::isnan(gecko::carlson_rj(1.0, 1.0, 1.0, 0.0, gecko::policies::nan_policy())));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(gecko::carlson_rj(1.0, 1.0, 1.0, nan)));
  CHECK(gecko::carlson_rj(1.0, 2.0, 3.0, std::numeric_limits<double>::infinity()) == 0.0);
}

TEST_CASE("carlson_rj: precision policy") {
  const auto& t = rj_table();
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), p = t.column("p"),
             v = t.column("rj");
  auto worst_with = [&](auto policy) {
    long double worst = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.get<double>(i, p) < 0) continue;
      const double r = gecko::carlson_rj(t.get<double>(i, x), t.get<double>(i, y),
                                         t.get<double>(i, z), t.get<double>(i, p), policy);
      worst = std::fmax(worst, std::fabs(r - t.value(i, v)) / t.value(i, v));
    }
    return worst;
  };
  const long double e12 = worst_with(gecko::policies::precision<12>());
  const long double e30 = worst_with(gecko::policies::precision<30>());
  WARN("carlson_rj relative error at precision<12>: " << double(e12) << ", <30>: " << double(e30));
  CHECK(e12 <= std::ldexp(1.0L, -12));
  CHECK(e30 <= std::ldexp(1.0L, -30));
  CHECK(e12 > std::ldexp(1.0L, -30));
}
