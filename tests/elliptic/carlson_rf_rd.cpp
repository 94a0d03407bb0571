// Tests for gecko/elliptic/carlson_rf_rd.hpp: the fused kernel agrees with the mpmath R_F and
// R_D tables (same bounds as the separate kernels), for double and long double, and at a low
// precision policy stays within that policy's bound.
#include <gecko/elliptic/carlson_rf_rd.hpp>

#include <cmath>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;
using gecko_test::tally_table;

namespace {
template <class T>
void check_fused(const char* table, const char* column, bool want_rf, long double bound) {
  const reference_table t(table);
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column(column);
  const auto tally = tally_table<T>(
      t, "carlson_rf_rd_imp<" + gecko_test::scalar_name<T>() + ">." + column,
      [&](std::size_t i) {
        const auto r = gecko::detail::carlson_rf_rd_imp<T>(t.get<T>(i, x), t.get<T>(i, y), t.get<T>(i, z));
        return want_rf ? r.rf : r.rd;
      },
      [&](std::size_t i) { return t.value(i, v); },
      // the unchecked kernel needs z > 0 (R_D's pole argument)
      [&](std::size_t i) { return t.get<double>(i, z) > 0; });
  CHECK(tally.overall.worst <= bound);
}
}  // namespace

TEMPLATE_TEST_CASE("carlson_rf_rd: fused kernel against the R_F and R_D tables", "[carlson_rf_rd]", double,
                   long double) {
  check_fused<TestType>("elliptic_rf.csv", "rf", true, 3);
  check_fused<TestType>("elliptic_rd.csv", "rd", false, 8);
}

TEST_CASE("carlson_rf_rd: precision policy bounds both results") {
  const reference_table t("elliptic_rd.csv");
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column("rd");
  long double worst = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto r = gecko::detail::carlson_rf_rd_imp<double, gecko::policies::precision<16>>(
        t.get<double>(i, x), t.get<double>(i, y), t.get<double>(i, z));
    worst = std::fmax(worst, std::fabs(r.rd - t.value(i, v)) / t.value(i, v));
  }
  WARN("carlson_rf_rd_imp R_D relative error at precision<16>: " << double(worst));
  CHECK(worst <= std::ldexp(1.0L, -16));
}
