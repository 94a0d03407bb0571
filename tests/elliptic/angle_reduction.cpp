// Tests for gecko/elliptic/angle_reduction.hpp: phi = j pi/2 + r with |r| <= pi/4, r accurate
// to a few ulps (checked against a long double / mpmath-free route: 128-bit pi/2 products in
// long double would not be exact, so the check uses an independent splitting of pi/2 into
// 26-bit pieces whose products with j < 2^26 are exact in double).
#include <gecko/elliptic/angle_reduction.hpp>

#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

TEST_CASE("angle_reduction: constants") {
  using C = gecko::detail::pi_constants<double>;
  CHECK(C::pio2_hi == 1.5707963267948966);
  CHECK(C::pio2_below <= C::pio2_hi);
  // hi + lo + lo2 agrees with pi/2 in long double to its precision
  const long double pio2 = 1.570796326794896619231321691639751442L;
  CHECK(std::fabs(static_cast<long double>(C::pio2_hi) + C::pio2_lo - pio2) <= 1e-19L);
  // long double: hi is pi/2 rounded to nearest (the literal), which lies above pi/2 (lo < 0),
  // so the largest long double below pi/2 is the one under hi.
  using L = gecko::detail::pi_constants<long double>;
  CHECK(L::pio2_hi == pio2);
  CHECK(L::pio2_lo < 0);
  CHECK(std::fabs(L::pio2_lo) <= std::ldexp(1.0L, -64));
  CHECK(L::pio2_below == std::nextafter(pio2, 0.0L));
  using F = gecko::detail::pi_constants<float>;
  CHECK(F::pio2_below < pio2);
  CHECK(std::nextafter(F::pio2_below, 2.0f) > pio2);
}

TEST_CASE("angle_reduction: remainder within pi/4 and accurate") {
  // Independent check for j < 2^26: pi/2 split into 26-bit pieces p0..p3 (exact products).
  const double p0 = 1.5707963109016418457031250;            // 26 bits of pi/2
  const double p1 = 1.5893254712295857973000658e-08;        // next 26 bits
  const double p2 = 6.1232339957367574e-17;                 // rest, to 17 digits (error ~9e-32)
  // The split is independent of the library's constants and must agree with them: p0 + p1 is
  // exactly the double nearest pi/2, and p2 is its remainder (the subtraction is exact).
  using C = gecko::detail::pi_constants<double>;
  CHECK(p0 + p1 == C::pio2_hi);
  CHECK(std::fabs(p2 - C::pio2_lo) <= 1e-31);
  std::mt19937_64 gen(42);
  std::uniform_real_distribution<double> u(0, 7.5);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a = std::pow(10.0, u(gen));  // 1 .. 3e7
    const auto q = gecko::detail::reduce_quadrant(a);
    REQUIRE(q.j == std::nearbyint(q.j));
    REQUIRE(std::fabs(q.r) <= 0.7853981633974484);
    // a - j p0 - j p1 exact in long double (64-bit significand holds 26 + 26 + ...)
    const long double r = ((static_cast<long double>(a) - q.j * static_cast<long double>(p0)) -
                           q.j * static_cast<long double>(p1)) - q.j * static_cast<long double>(p2);
    worst = std::fmax(worst, double(std::fabs(q.r - r) / std::fabs(r)));
  }
  WARN("reduce_quadrant: worst relative error of r " << worst / std::numeric_limits<double>::epsilon() << " eps");
  CHECK(worst <= 4 * std::numeric_limits<double>::epsilon());
}

TEST_CASE("angle_reduction: reduction limit and secular term") {
  CHECK(gecko::detail::reduction_limit<double>() == 0x1p52);
  CHECK(gecko::detail::reduction_limit<float>() == 0x1p23f);
  double hi, lo;
  gecko::detail::times_two_over_pi(1e300, hi, lo);
  CHECK(hi == Approx(1e300 * 0.6366197723675814));
  CHECK(std::fabs(lo) <= std::ldexp(std::fabs(hi), -52));
}
