// Tests of gecko/peel: Kendall and Rivlin lines (paper eq 17) satisfy their equations, agree in
// the inextensible limit, and report their ranges.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "gecko/peel.hpp"
#include "gecko/peel/small_deformation.hpp"  // the deprecated forwarding header, tested below

TEMPLATE_TEST_CASE("Kendall and Rivlin lines satisfy eq 17", "[peel]", float, double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  for (T Ft : {T(-0.4), T(0.0), T(0.5), T(2.0), T(7.5), T(9.99)}) {
    const T w = 1, EA = 50;
    const T fk = gecko::kendall_fn(Ft, EA, w);
    const T N2 = fk * fk + Ft * Ft;
    CHECK(std::fabs(std::sqrt(N2) + N2 / (2 * EA) - Ft - w) < 18 * eps * (Ft + w + 1));
    CHECK(fk <= 0);
    const T fr = gecko::rivlin_fn(Ft, w);
    CHECK(std::fabs(std::hypot(fr, Ft) - Ft - w) < 18 * eps * (std::fabs(Ft) + w));
    CHECK(gecko::kendall_fn(Ft, std::numeric_limits<T>::infinity(), w) == Approx(fr).epsilon(4.5 * eps));
    // the line moves by O(w / EA) = 1e-14 relative: below eps(float), so float gets its rounding
    CHECK(gecko::kendall_fn(Ft, T(1e14), w) == Approx(fr).epsilon(std::max<double>(1e-12, 8 * eps)));
  }
  // Kendall's line ends at (Ft)max = sqrt(2 EA w) with Fn = 0; Fn ~ sqrt(rounding) there.
  CHECK(gecko::kendall_fn(T(10), T(50), T(1)) == Approx(0.0).margin(6 * std::sqrt(eps)));
}

TEST_CASE("peel lines: bad input names the parameter", "[peel][errors]") {
  CHECK_THROWS_WITH(gecko::kendall_fn(10.5, 50.0, 1.0), Catch::Contains("Ft") && Catch::Contains("sqrt(2 EA w)"));
  CHECK_THROWS_WITH(gecko::kendall_fn(1.0, -50.0, 1.0), Catch::Contains("EA"));
  CHECK_THROWS_WITH(gecko::kendall_fn(1.0, 50.0, 0.0), Catch::Contains("w"));
  CHECK_THROWS_WITH(gecko::rivlin_fn(-0.6, 1.0), Catch::Contains("Ft") && Catch::Contains("-w/2"));
  CHECK(std::isnan(gecko::rivlin_fn(-0.6, 1.0, gecko::policies::nan_policy())));
}

// The small-deformation formulas moved to gecko/seta/small_deformation.hpp (they are the seta's,
// paper eqs 7 and 18-22); code written against gecko 0.1 includes the old peel path or
// gecko/peel.hpp and must still compile and get the same functions.
TEST_CASE("deprecated peel path still provides the small-deformation formulas", "[peel][small_deformation]") {
  const gecko::TwoLevelSeta<double> s;
  const auto r = gecko::small_deformation(s);
  CHECK(gecko::small_deformation_fn(s, 2.0) == r.fn0 + r.slope_k * 2.0);
}
