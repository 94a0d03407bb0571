// Tests for gecko/elliptic/carlson_tolerance.hpp: the constexpr thresholds equal the pow()
// values they stand for and order as expected with the precision target.
#include <gecko/elliptic/carlson_tolerance.hpp>

#include <cmath>

#include <catch2/catch.hpp>

namespace {
// R_F threshold for the degree-15 series: sqrt((160 r)^(1/8) / 1.5), capped at 1/2.
double rf_threshold(long double r) {
  return double(std::fmin(std::sqrt(std::pow(160 * r, 1.0L / 8) / 1.5L), 0.5L));
}
}  // namespace

TEST_CASE("carlson_tolerance: constexpr roots match pow") {
  using gecko::detail::carlson_tolerance;
  const long double r53 = std::ldexp(1.0L, -53);
  CHECK(carlson_tolerance<double, 0>::rf == Approx(rf_threshold(r53)).epsilon(1e-15));
  CHECK(carlson_tolerance<double, 40>::rf == Approx(rf_threshold(std::ldexp(1.0L, -40))).epsilon(1e-15));
  CHECK(carlson_tolerance<double, 12>::rf == 0.5);  // capped
  CHECK(carlson_tolerance<double, 20>::rf == Approx(rf_threshold(std::ldexp(1.0L, -20))).epsilon(1e-15));
  // R_D threshold for the degree-11 series: (r / (2 C_12))^(1/12), C_12 = 0.0530524..., cap 1/2
  CHECK(carlson_tolerance<double, 0>::rd ==
        Approx(double(std::pow(r53 / (2 * 0.05305240792088293L), 1.0L / 12))).epsilon(1e-15));
  CHECK(carlson_tolerance<double, 12>::rd == 0.5);
  // R_F threshold for the degree-11 series of the Legendre F kernel: (r / (2 C12))^(1/12),
  // C12 = 0.1235894775390625 (degree-12 terms at |E2| <= 1.5 t^2, |E3| <= t^3/4), cap 1/2
  CHECK(carlson_tolerance<double, 0>::rf11 ==
        Approx(double(std::pow(r53 / (2 * 0.12358947753906249L), 1.0L / 12))).epsilon(1e-15));
  CHECK(carlson_tolerance<double, 0>::rf11 == Approx(0.0526).epsilon(1e-3));
  CHECK(carlson_tolerance<double, 12>::rf11 == 0.5);
  CHECK(carlson_tolerance<double, 10>::rf11 > carlson_tolerance<double, 30>::rf11);
  // R_J keeps Carlson's degree-5 series: (r/4)^(1/6)
  CHECK(carlson_tolerance<double, 0>::rj == Approx(double(std::pow(r53 / 4, 1.0L / 6))).epsilon(1e-15));
  CHECK(carlson_tolerance<double, 0>::agm == Approx(double(2 * std::sqrt(r53))).epsilon(1e-15));
  CHECK(carlson_tolerance<long double, 0>::rf == Approx(rf_threshold(std::ldexp(1.0L, -64))).epsilon(1e-15));
  // Bits beyond the type's precision mean full precision
  CHECK(carlson_tolerance<float, 100>::rf == carlson_tolerance<float, 0>::rf);
  // coarser targets stop earlier (larger thresholds)
  CHECK(carlson_tolerance<double, 10>::rf >= carlson_tolerance<double, 30>::rf);
  CHECK(carlson_tolerance<double, 30>::rf > carlson_tolerance<double, 0>::rf);
  CHECK(carlson_tolerance<double, 10>::rd > carlson_tolerance<double, 30>::rd);
  CHECK(carlson_tolerance<double, 10>::rj > carlson_tolerance<double, 30>::rj);
  CHECK(carlson_tolerance<long double, 0>::rf < carlson_tolerance<double, 0>::rf);
  static_assert(carlson_tolerance<double, 0>::rf > 0 && carlson_tolerance<double, 0>::rf < 1, "constexpr");
}
