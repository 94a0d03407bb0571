// The corner phi -> pi/2, m -> 1 of F(phi|m) and E(phi|m) (gecko/elliptic/ellint_f.hpp,
// ellint_e.hpp): the last doubles below pi/2, the first above it (the quadrant seam of the angle
// reduction), m within one ulp of 1, and the diagonal phi = pi/2 - d/2, m = 1 - d, against the
// mpmath table of tests/data/gen_elliptic_near_singular.py (what elliptic_legendre.csv does not
// sample: it stops at phi = pi/2 - 1e-12). Same bound as the main table: 3 eps, double and long
// double. The kernel keeps full relative accuracy here because Delta^2 = cos^2 phi + (1 - m)
// sin^2 phi is a sum of non-negative terms (no cancellation), with 1 - m exact.
#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_f.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "elliptic/typed_table.hpp"

namespace {

const gecko_test::reference_table& corner_table() {
  static const gecko_test::reference_table t("elliptic_near_singular.csv");
  return t;
}

template <class T, class Fn>
gecko_test::error_tally corner_tally(const char* which, const char* what, Fn fn) {
  const auto& t = corner_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column(which);
  return gecko_test::tally_table<T>(
      t, what, [&](std::size_t i) { return fn(t.get<T>(i, phi), t.get<T>(i, m)); },
      [&](std::size_t i) { return t.value(i, v); }, [](std::size_t) { return true; });
}

}  // namespace

// float is left out: the table's inputs sit within ulps(double) of the corner, which float
// rounding would move onto the seam or the pole.
TEMPLATE_TEST_CASE("ellint_f, ellint_e at phi -> pi/2, m -> 1: <= 3 eps against mpmath", "[elliptic][near_singular]",
                   double, long double) {
  const std::string type = "<" + gecko_test::scalar_name<TestType>() + "> near (pi/2, 1)";
  const auto f = corner_tally<TestType>("F", ("ellint_f" + type).c_str(),
                                        [](auto p, auto m) { return gecko::ellint_f(p, m); });
  CHECK(f.overall.worst <= 3);
  CHECK(f.overall.count > 1300);
  const auto e = corner_tally<TestType>("E", ("ellint_e" + type).c_str(),
                                        [](auto p, auto m) { return gecko::ellint_e(p, m); });
  CHECK(e.overall.worst <= 3);
}

TEST_CASE("F(phi|1) jumps to infinity across pi/2; F(phi|1 - 1ulp) stays finite and increasing", "[elliptic][near_singular]") {
  const double below = 1.5707963267948966;  // the double nearest pi/2 (below it)
  const double above = std::nextafter(below, 4.0);
  CHECK(std::isfinite(gecko::ellint_f(below, 1.0)));
  CHECK(std::isinf(gecko::ellint_f(above, 1.0)));
  CHECK(gecko::ellint_e(above, 1.0) == Approx(2.0 - std::sin(above)).epsilon(1e-15));  // E(phi|1) = 2 - sin phi on [pi/2, pi]
  const double m = 1.0 - std::numeric_limits<double>::epsilon() / 2;  // 1 - 2^-53
  double prev = 0;
  double phi = below;
  for (int i = 0; i < 6; ++i) phi = std::nextafter(phi, 0.0);
  for (int i = 0; i < 12; ++i) {  // six ulps below pi/2 to six above: finite, strictly increasing
    const double F = gecko::ellint_f(phi, m);
    INFO("phi " << phi << " F " << F);
    CHECK(std::isfinite(F));
    CHECK(F > prev);
    prev = F;
    phi = std::nextafter(phi, 4.0);
  }
}
