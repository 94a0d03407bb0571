// Tests for gecko/elliptic/first_quadrant_sincos.hpp: the inline double kernel against long
// double sinl/cosl on [0, pi/2], including the neighbourhood of pi/2 where cos must keep its
// relative accuracy, and the float route.
#include <gecko/elliptic/first_quadrant_sincos.hpp>

#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

TEST_CASE("first_quadrant_sincos: double within about an ulp of sinl/cosl") {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(0, 1.5707963267948966);
  std::uniform_real_distribution<double> e(0, 17);
  double worst_s = 0, worst_c = 0;
  auto check = [&](double a) {
    double s, c;
    gecko::detail::first_quadrant_sincos(a, s, c);
    const long double S = std::sin(static_cast<long double>(a));
    const long double C = std::cos(static_cast<long double>(a));
    worst_s = std::fmax(worst_s, double(std::fabs(s - S) / S));
    worst_c = std::fmax(worst_c, double(std::fabs(c - C) / C));
  };
  for (int i = 0; i < 200000; ++i) check(u(gen));
  for (int i = 0; i < 20000; ++i) check(1.5707963267948966 - std::pow(10.0, -e(gen)));  // near pi/2
  for (int i = 0; i < 2000; ++i) check(std::pow(10.0, -20 * e(gen)));                  // tiny
  check(0.78539816339744828);
  check(std::nextafter(0.78539816339744828, 1.0));
  check(1.5707963267948966);
  const double eps = std::numeric_limits<double>::epsilon();
  WARN("first_quadrant_sincos: worst relative error sin " << worst_s / eps << " eps, cos "
                                                          << worst_c / eps << " eps");
  CHECK(worst_s <= 1.0 * eps);
  CHECK(worst_c <= 1.0 * eps);
  double s, c;
  gecko::detail::first_quadrant_sincos(0.0, s, c);
  CHECK(s == 0.0);
  CHECK(c == 1.0);
}

TEST_CASE("first_quadrant_sincos: float is the rounded double result") {
  float s, c;
  gecko::detail::first_quadrant_sincos(1.2f, s, c);
  CHECK(s == static_cast<float>(std::sin(1.2f * 1.0)));
  CHECK(c == static_cast<float>(std::cos(1.2f * 1.0)));
}
