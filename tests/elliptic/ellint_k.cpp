// Tests for gecko/elliptic/ellint_k.hpp: mpmath table (double, long double, float), special
// values K(0) = pi/2, K(1) = inf, K(-inf) = 0, domain errors, NaN.
#include <gecko/elliptic/ellint_k.hpp>

#include <cmath>
#include <limits>

#include "elliptic/reference_table.hpp"

using gecko_test::reference_table;
using gecko_test::tally_table;

namespace {
const reference_table& complete_table() {
  static const reference_table t("elliptic_complete.csv");
  return t;
}
}  // namespace

TEST_CASE("ellint_k: mpmath table: <= 3 eps (double, long double, float)") {
  const auto& t = complete_table();
  const auto m = t.column("m"), v = t.column("K");
  auto all = [](std::size_t) { return true; };
  CHECK(tally_table<double>(t, "ellint_k<double>",
                            [&](std::size_t i) { return gecko::ellint_k(t.get<double>(i, m)); },
                            [&](std::size_t i) { return t.value(i, v); }, all)
            .overall.worst <= 3);
  CHECK(tally_table<long double>(t, "ellint_k<long double>",
                                 [&](std::size_t i) { return gecko::ellint_k(t.get<long double>(i, m)); },
                                 [&](std::size_t i) { return t.value(i, v); }, all)
            .overall.worst <= 3);
  CHECK(tally_table<float>(
            t, "ellint_k<float>", [&](std::size_t i) { return gecko::ellint_k(t.get<float>(i, m)); },
            [&](std::size_t i) { return static_cast<long double>(gecko::ellint_k<double>(t.get<float>(i, m))); },
            [&](std::size_t i) {
              return gecko_test::float_representable(t.get<double>(i, m)) && t.get<float>(i, m) < 1;
            })
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
