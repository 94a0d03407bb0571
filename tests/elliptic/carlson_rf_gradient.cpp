// Tests for gecko/elliptic/carlson_rf_gradient.hpp: R_F and its three partials from one
// duplication. The value is checked against the mpmath R_F table, and each partial against the
// mpmath R_D table through DLMF 19.18.1 (dR_F/dx_i = -R_D(x_j, x_k, x_i)/6): every row of the R_D
// table is fed in the three rotations that put its last argument in each slot, so all three R_D
// tails of the kernel are tested. Bounds are those of the separate kernels (3 eps for R_F, 5 eps
// for R_D; measured 3.6). Then the domain, zero, infinity and scaling
// paths of the public function.
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rf.hpp>
#include <gecko/elliptic/carlson_rf_gradient.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "elliptic/typed_table.hpp"

using gecko_test::reference_table;
using gecko_test::tally_table;

namespace {

template <class T>
void check_value(long double bound) {
  const reference_table t("elliptic_rf.csv");
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column("rf");
  const auto tally = tally_table<T>(
      t, "carlson_rf_gradient.rf<" + gecko_test::scalar_name<T>() + ">",
      [&](std::size_t i) { return gecko::carlson_rf_gradient(t.get<T>(i, x), t.get<T>(i, y), t.get<T>(i, z)).rf; },
      [&](std::size_t i) { return t.value(i, v); }, [](std::size_t) { return true; });
  CHECK(tally.overall.worst <= bound);
}

// slot 0, 1, 2: the R_D row's last argument z goes into x, y or z of R_F.
template <class T>
void check_partial(int slot, long double bound) {
  const reference_table t("elliptic_rd.csv");
  const auto x = t.column("x"), y = t.column("y"), z = t.column("z"), v = t.column("rd");
  const auto tally = tally_table<T>(
      t, std::string("carlson_rf_gradient.d") + "xyz"[slot] + "<" + gecko_test::scalar_name<T>() + ">",
      [&](std::size_t i) {
        const T a = t.get<T>(i, x), b = t.get<T>(i, y), c = t.get<T>(i, z);
        if (slot == 0) return -6 * gecko::carlson_rf_gradient(c, a, b).dx;  // -R_D(a, b, c)/6
        if (slot == 1) return -6 * gecko::carlson_rf_gradient(b, c, a).dy;
        return -6 * gecko::carlson_rf_gradient(a, b, c).dz;
      },
      [&](std::size_t i) { return t.value(i, v); }, [](std::size_t) { return true; });
  CHECK(tally.overall.worst <= bound);
}

}  // namespace

TEMPLATE_TEST_CASE("carlson_rf_gradient: value against the mpmath R_F table", "[carlson_rf_gradient]", double,
                   long double) {
  check_value<TestType>(3);
}

TEMPLATE_TEST_CASE("carlson_rf_gradient: each partial against the mpmath R_D table (DLMF 19.18.1)",
                   "[carlson_rf_gradient]", double, long double) {
  for (int slot = 0; slot < 3; ++slot) check_partial<TestType>(slot, 5);
}

TEST_CASE("carlson_rf_gradient: agrees with central differences at random states") {
  // Independent of the R_D route: a fourth-order difference of carlson_rf itself, in long double
  // so the difference error (~h^4 and eps/h) stays below 1e-9 relative.
  unsigned s = 12345;
  auto uniform = [&s] { s = s * 1103515245u + 12345u; return ((s >> 8) & 0xFFFF) / 65536.0L; };
  for (int n = 0; n < 200; ++n) {
    const long double v[3] = {std::pow(10.0L, 4 * uniform() - 2), std::pow(10.0L, 4 * uniform() - 2),
                              std::pow(10.0L, 4 * uniform() - 2)};
    const auto g = gecko::carlson_rf_gradient(double(v[0]), double(v[1]), double(v[2]));
    const double got[3] = {g.dx, g.dy, g.dz};
    for (int k = 0; k < 3; ++k) {
      const long double h = 1e-3L * v[k];
      auto at = [&](long double d) {
        long double w[3] = {v[0], v[1], v[2]};
        w[k] += d;
        return gecko::carlson_rf(w[0], w[1], w[2]);
      };
      const long double fd = (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h);
      CHECK(std::fabs((got[k] - fd) / fd) < 1e-9L);
    }
  }
}

TEST_CASE("carlson_rf_gradient: zero, infinite and extreme arguments, and the domain") {
  // A zero argument: finite partials for the others (R_D with a finite last argument), -inf for
  // its own; the value equals carlson_rf whichever slot holds the zero.
  const double a = 0.7, b = 2.5;
  const auto gz = gecko::carlson_rf_gradient(a, b, 0.0);
  const auto gx = gecko::carlson_rf_gradient(0.0, a, b);
  const auto gy = gecko::carlson_rf_gradient(b, 0.0, a);
  const double rf = gecko::carlson_rf(a, b, 0.0);
  for (double r : {gz.rf, gx.rf, gy.rf}) CHECK(std::fabs(r - rf) <= 2 * std::numeric_limits<double>::epsilon() * rf);
  CHECK(std::isinf(gz.dz));
  CHECK(gz.dz < 0);
  CHECK(std::isinf(gx.dx));
  CHECK(std::isinf(gy.dy));
  const double rd_ab0 = gecko::carlson_rd(b, 0.0, a);  // dR_F(a, b, 0)/da = -R_D(b, 0, a)/6
  CHECK(std::fabs(-6 * gz.dx - rd_ab0) <= 16 * std::numeric_limits<double>::epsilon() * rd_ab0);
  CHECK(std::fabs(gx.dy - gz.dx) <= 16 * std::numeric_limits<double>::epsilon() * std::fabs(gz.dx));
  CHECK(std::fabs(gy.dz - gz.dx) <= 16 * std::numeric_limits<double>::epsilon() * std::fabs(gz.dx));

  // Exact rescaling: arguments near the top and bottom of the range give the scaled answer.
  const auto g1 = gecko::carlson_rf_gradient(1.0, 2.0, 3.0);
  const double big = std::ldexp(1.0, 1000), small = std::ldexp(1.0, -1000);
  const auto gb = gecko::carlson_rf_gradient(big, 2 * big, 3 * big);
  const auto gs = gecko::carlson_rf_gradient(small, 2 * small, 3 * small);
  CHECK(gb.rf == std::ldexp(g1.rf, -500));
  CHECK(gb.dy == std::ldexp(g1.dy, -1500));
  CHECK(gs.rf == std::ldexp(g1.rf, 500));
  CHECK(gs.dz == std::ldexp(g1.dz, 1500));

  const auto gi = gecko::carlson_rf_gradient(1.0, std::numeric_limits<double>::infinity(), 2.0);
  CHECK(gi.rf == 0);
  CHECK(gi.dx == 0);
  CHECK(std::isnan(gecko::carlson_rf_gradient(std::nan(""), 1.0, 2.0).dz));

  CHECK_THROWS_AS(gecko::carlson_rf_gradient(-1.0, 1.0, 1.0), std::domain_error);
  CHECK_THROWS_AS(gecko::carlson_rf_gradient(0.0, 0.0, 1.0), std::domain_error);
  CHECK_THROWS_WITH(gecko::carlson_rf_gradient(1.0, 1.0, -2.0),
                    Catch::Contains("carlson_rf_gradient") && Catch::Contains("z"));
  const auto gn = gecko::carlson_rf_gradient(1.0, -1.0, 1.0, gecko::policies::nan_policy());
  CHECK(std::isnan(gn.rf));
  CHECK(std::isnan(gn.dx));

  // The unchecked kernel with two zeros (a degenerate continuation state) ends with NaN.
  const auto deg = gecko::detail::carlson_rf_gradient_imp<double>(0.0, 0.0, 1.0);
  CHECK(std::isnan(deg.rf));
}
