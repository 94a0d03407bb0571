// Tests for gecko/elliptic/carlson_rf.hpp: mpmath table (double, long double, float),
// identities (DLMF 19.20.1, 19.18.1), domain errors, NaN/inf handling, precision policy.
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rf.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;

namespace {
const reference_table& rf_table() {
  static const reference_table t("elliptic_rf.csv");
  return t;
}
constexpr long double pi_l = 3.141592653589793238462643383279502884L;
}  // namespace

// float: table inputs rounded to float, against double at the rounded inputs (see typed_table.hpp).
TEMPLATE_TEST_CASE("carlson_rf: mpmath table: <= 3 eps", "[carlson_rf]", float, double, long double) {
  const auto& t = rf_table();
  const auto tally = gecko_test::kernel_tally<TestType>(
      t, "carlson_rf", std::array<std::size_t, 3>{t.column("x"), t.column("y"), t.column("z")},
      t.column("rf"), [](auto... a) { return gecko::carlson_rf(a...); });
  CHECK(tally.overall.worst <= 3);
}

TEST_CASE("carlson_rf: special values and identities") {
  const double eps = std::numeric_limits<double>::epsilon();
  // R_F(x, x, x) = x^(-1/2)  (DLMF 19.20.1)
  for (double xv : {1e-300, 1e-10, 0.25, 1.0, 3.0, 7e11, 1e300}) {
    CHECK(gecko::carlson_rf(xv, xv, xv) == Approx(1 / std::sqrt(xv)).epsilon(2 * eps));
  }
  // R_F(0, y, y) = pi / (2 sqrt y)
  for (double yv : {1e-200, 1e-6, 1.0, 2.0, 5e9, 1e200}) {
    CHECK(gecko::carlson_rf(0.0, yv, yv) == Approx(double(pi_l / 2) / std::sqrt(yv)).epsilon(3 * eps));
    CHECK(gecko::carlson_rf(yv, 0.0, yv) == Approx(double(pi_l / 2) / std::sqrt(yv)).epsilon(3 * eps));
  }
  // R_F(0, 1, 2) (lemniscate constant / 2... DLMF 19.20.2: R_F(0,1,2) = Gamma(1/4)^2/(4 sqrt(2 pi)))
  CHECK(gecko::carlson_rf(0.0, 1.0, 2.0) ==
        Approx(1.311028777146059905232419794945559706841377475715811581408410851900395L).epsilon(2 * eps));
  // Symmetry and homogeneity R_F(l x, l y, l z) = l^(-1/2) R_F(x, y, z) with l = 4^k (exact).
  const double a = 0.3, b = 1.7, c = 25.0;
  const double r = gecko::carlson_rf(a, b, c);
  CHECK(gecko::carlson_rf(b, c, a) == Approx(r).epsilon(3 * eps));
  CHECK(gecko::carlson_rf(c, a, b) == Approx(r).epsilon(3 * eps));
  for (int k : {-400, -60, -3, 5, 60, 400}) {
    const double l = std::ldexp(1.0, 2 * k);
    CHECK(gecko::carlson_rf(l * a, l * b, l * c) == Approx(std::ldexp(r, -k)).epsilon(3 * eps));
  }
  // Arguments at the very top of the range: the public layer rescales instead of overflowing.
  const double big = std::numeric_limits<double>::max();
  CHECK(gecko::carlson_rf(big, big, big) == Approx(1 / std::sqrt(big)).epsilon(2 * eps));
  CHECK(std::isfinite(gecko::carlson_rf(big, big / 3, 0.0)));
}

TEST_CASE("carlson_rf: domain errors name the argument, nan_policy returns NaN") {
  auto message = [](auto f) {
    try {
      f();
    } catch (const std::domain_error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK_THAT(message([] { gecko::carlson_rf(1.0, 2.0, -1.0); }),
             Catch::Contains("gecko::carlson_rf: z = -1 is out of range") &&
                 Catch::Contains("at most one of them zero"));
  CHECK_THAT(message([] { gecko::carlson_rf(-1.0, 2.0, 1.0); }), Catch::Contains("x = -1"));
  CHECK_THAT(message([] { gecko::carlson_rf(1.0, -2.0, 1.0); }), Catch::Contains("y = -2"));
  CHECK_THAT(message([] { gecko::carlson_rf(0.0, 0.0, 1.0); }), Catch::Contains("y = 0"));
  CHECK_THAT(message([] { gecko::carlson_rf(0.0, 1.0, 0.0); }), Catch::Contains("z = 0"));
  CHECK(std::isnan(gecko::carlson_rf(-1.0, 1.0, 1.0, gecko::policies::nan_policy())));
  CHECK(std::isnan(gecko::carlson_rf(0.0f, 0.0f, 1.0f, gecko::policies::nan_policy())));
}

TEST_CASE("carlson_rf: NaN propagates quietly, infinity gives the limit 0") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(std::isnan(gecko::carlson_rf(nan, 1.0, 1.0)));
  CHECK(std::isnan(gecko::carlson_rf(1.0, nan, -1.0)));  // NaN wins over a domain error
  CHECK(std::isnan(gecko::carlson_rf(1.0, 1.0, nan)));
  CHECK(gecko::carlson_rf(1.0, 2.0, inf) == 0.0);
  CHECK(gecko::carlson_rf(0.0, inf, 2.0) == 0.0);
}

TEST_CASE("carlson_rf: precision policy trades error for fewer steps, error stays bounded") {
  const auto& t = rf_table();
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column("rf");
  auto worst_with = [&](auto policy) {
    long double worst = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      const double r = gecko::carlson_rf(t.get<double>(i, x), t.get<double>(i, y),
                                         t.get<double>(i, z), policy);
      const long double want = t.value(i, v);
      worst = std::fmax(worst, std::fabs(r - want) / want);
    }
    return worst;
  };
  const long double e10 = worst_with(gecko::policies::precision<10>());
  const long double e24 = worst_with(gecko::policies::precision<24>());
  const long double e40 = worst_with(gecko::policies::precision<40>());
  WARN("carlson_rf relative error at precision<10>: " << double(e10) << ", <24>: " << double(e24)
                                                      << ", <40>: " << double(e40));
  CHECK(e10 <= std::ldexp(1.0L, -10));
  CHECK(e24 <= std::ldexp(1.0L, -24));
  CHECK(e40 <= std::ldexp(1.0L, -40));
  CHECK(e40 <= e24);
  CHECK(e24 <= e10);
  // ... and a lower precision does have a visible effect (the policy is not ignored). Below
  // about 20 bits the threshold is capped (carlson_tolerance.hpp), so 10 and 12 bits coincide.
  CHECK(e24 > std::ldexp(1.0L, -40));
}

// Regression (seta stress campaign): the unchecked kernels are called from hot loops without
// argument checks; two zero arguments used to keep the duplication test true forever. They must
// now stop (bounded by detail::carlson_max_steps) and answer with a non-finite value.
TEMPLATE_TEST_CASE("carlson unchecked kernels terminate on two zero arguments", "[carlson_rf][regression]",
                   float, double, long double) {
  using T = TestType;
  using gecko::policies::default_policy;
  const T zero = 0, a = T(0.2);
  CHECK_FALSE(std::isfinite(gecko::detail::carlson_rf_imp<T, default_policy>(zero, a, zero)));
  CHECK_FALSE(std::isfinite(
      gecko::detail::carlson_rf_roots_imp<T, default_policy>(zero, a, zero, zero, std::sqrt(a), zero)));
  CHECK_FALSE(std::isfinite(gecko::detail::carlson_rd_imp<T, default_policy>(zero, zero, a)));
}
