// Tests for gecko/elliptic/carlson_arguments.hpp: the rescaling exponent is even, zero in the
// comfortable range, and brings extreme arguments to order one (so R_F/R_D/R_J of huge or
// subnormal arguments are exact power-of-two rescalings of moderate ones).
#include <gecko/elliptic/carlson_arguments.hpp>
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rf.hpp>

#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

TEST_CASE("carlson_arguments: scale exponent") {
  using gecko::detail::carlson_scale_exponent;
  for (double v : {1e-290, 1e-100, 1.0, 3.0, 1e100, 1e300}) CHECK(carlson_scale_exponent(v) == 0);
  for (double v : {std::numeric_limits<double>::max(), 1e307, 1e-310, 5e-324, 1e-300}) {
    const int e = carlson_scale_exponent(v);
    INFO(v);
    CHECK(e % 2 == 0);
    CHECK(e != 0);
    const double scaled = std::ldexp(v, -e);
    CHECK(scaled >= 0.25);
    CHECK(scaled < 4);
  }
  CHECK(carlson_scale_exponent(0.0) == 0);
}

TEST_CASE("carlson_arguments: extreme arguments are exact rescalings") {
  const double eps = std::numeric_limits<double>::epsilon();
  const double a = 0.3, b = 1.7, c = 25.0;
  const double rf = gecko::carlson_rf(a, b, c), rd = gecko::carlson_rd(a, b, c);
  // 2^1000 and 2^-1060 (subnormal for the smallest argument) scale factors
  CHECK(gecko::carlson_rf(std::ldexp(a, 1000), std::ldexp(b, 1000), std::ldexp(c, 1000)) ==
        Approx(std::ldexp(rf, -500)).epsilon(3 * eps));
  CHECK(gecko::carlson_rd(std::ldexp(a, 1000), std::ldexp(b, 1000), std::ldexp(c, 1000)) ==
        Approx(std::ldexp(rd, -1500)).epsilon(8 * eps));
  CHECK(gecko::carlson_rf(std::ldexp(a, -1060), std::ldexp(b, -1060), std::ldexp(c, -1060)) ==
        Approx(std::ldexp(rf, 530)).epsilon(1e-3));  // a and b lose bits as subnormals
}
