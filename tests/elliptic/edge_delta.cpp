// m > 1 next to the edge sin^2 phi = 1/m, and m -> 1 from above (gecko/elliptic/edge_delta.hpp):
// F and E against the mpmath table elliptic_legendre_edge.csv (tests/data/gen_elliptic.py edge),
// the exact values at the given double inputs, with no allowance for the conditioning in sin phi:
// F <= 3 eps, E <= 4 eps. Also the double-word sin and cos and Delta^2 themselves.
#include <gecko/elliptic/edge_delta.hpp>
#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_f.hpp>

#include <cmath>
#include <limits>

#include "elliptic/reference_table.hpp"

namespace {

const gecko_test::reference_table& edge_table() {
  static const gecko_test::reference_table t("elliptic_legendre_edge.csv");
  return t;
}

template <class T, class Fn>
gecko_test::error_tally edge_tally(const char* which, const char* what, Fn fn) {
  const auto& t = edge_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column(which);
  return gecko_test::tally_table<T>(
      t, what, [&](std::size_t i) { return fn(t.get<T>(i, phi), t.get<T>(i, m)); },
      [&](std::size_t i) { return t.value(i, v); }, [](std::size_t) { return true; });
}

}  // namespace

TEST_CASE("ellint_f, ellint_e for m > 1 at the edge: F <= 3 eps, E <= 4 eps (double)", "[elliptic][edge]") {
  const auto f = edge_tally<double>("F", "ellint_f<double>, m > 1 at the edge",
                                    [](double p, double m) { return gecko::ellint_f(p, m); });
  CHECK(f.overall.worst <= 3);
  CHECK(f.overall.count > 600);
  const auto e = edge_tally<double>("E", "ellint_e<double>, m > 1 at the edge",
                                    [](double p, double m) { return gecko::ellint_e(p, m); });
  CHECK(e.overall.worst <= 4);
  // the nan policy takes the same route
  const auto fn = edge_tally<double>("F", "ellint_f<double, nan_policy>, m > 1 at the edge", [](double p, double m) {
    return gecko::ellint_f(p, m, gecko::policies::nan_policy());
  });
  CHECK(fn.overall.worst <= 3);
}

TEST_CASE("ellint_f, ellint_e for m > 1 at the edge: F <= 3 eps, E <= 4 eps (long double)", "[elliptic][edge]") {
  // the table's inputs are doubles, so these are long double problems with the same exact values
  const auto f = edge_tally<long double>("F", "ellint_f<long double>, m > 1 at the edge",
                                         [](long double p, long double m) { return gecko::ellint_f(p, m); });
  CHECK(f.overall.worst <= 3);
  const auto e = edge_tally<long double>("E", "ellint_e<long double>, m > 1 at the edge",
                                         [](long double p, long double m) { return gecko::ellint_e(p, m); });
  CHECK(e.overall.worst <= 4);
}

TEST_CASE("double-word sin and cos of the first quadrant", "[elliptic][edge]") {
  // Against long double sinl/cosl (64 bits): the double-word result must agree to within a few
  // units of 2^-64, far beyond double's 2^-53 (a plain double sin would fail this).
  const long double tol = std::ldexp(4.0L, -64);
  for (int i = 0; i <= 2000; ++i) {
    const double a = 1.5707963267948966 * i / 2000;
    gecko::detail::dword<double> s, c;
    gecko::detail::dw_first_quadrant_sincos(a, s, c);
    const long double ws = std::sin(static_cast<long double>(a)), wc = std::cos(static_cast<long double>(a));
    INFO("a = " << a);
    CHECK(std::fabs((static_cast<long double>(s.hi) + s.lo) - ws) <= tol * std::fabs(ws) + 1e-300L);
    // cos near pi/2: relative to cos itself (the reflection keeps it)
    if (std::numeric_limits<long double>::digits >= 64)
      CHECK(std::fabs((static_cast<long double>(c.hi) + c.lo) - wc) <= tol * std::fabs(wc) + std::ldexp(1.0L, -120));
  }
}

TEST_CASE("Delta^2 for m > 1: full relative accuracy next to the edge", "[elliptic][edge]") {
  // m = 3, phi the last double with 3 sin^2 phi <= 1: Delta^2 is of order eps, and the rounded
  // sin would give it with no correct digit. long double sinl has 11 bits more than double,
  // enough to confirm the sign and the first few digits.
  const double m = 3.0;
  double phi = std::asin(1 / std::sqrt(m));
  while (static_cast<long double>(m) * std::pow(std::sin(static_cast<long double>(phi)), 2) > 1)
    phi = std::nextafter(phi, 0.0);
  const auto e = gecko::detail::m_above_one_arguments(phi, m);
  const long double s = std::sin(static_cast<long double>(phi));
  const long double want = 1 - m * s * s;
  CHECK(e.d2 >= 0);
  CHECK(e.d2 < 1e-14);
  if (std::numeric_limits<long double>::digits >= 64) CHECK(std::fabs(e.d2 - want) <= 0.02L * std::fabs(want) + 1e-19L);
}
