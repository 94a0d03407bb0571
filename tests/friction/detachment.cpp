// Tests of gecko/friction/detachment.hpp: eqs 4, 7, 8 and A2.6 of paper 000.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "gecko/friction/detachment.hpp"

TEST_CASE("detachment laws are eqs 7 and 8", "[friction][detachment]") {
  const gecko::viscoelastic_detachment<double> ve{2.0, 1e-4, 0.45};
  const gecko::eyring_detachment<double> ey{2.0, 6e-4};
  for (double V : {0.0, 1e-6, 1e-4, 3e-3}) {
    CHECK(ve(V) == Approx(2.0 * (1 + std::pow(V / 1e-4, 0.45))).epsilon(4e-16));
    CHECK(ey(V) == Approx(2.0 * std::asinh(V / 6e-4)).epsilon(4e-16).margin(1e-300));
  }
  CHECK(ve(0.0) == 2.0);  // G0 is the low-rate limit
  CHECK(ey(0.0) == 0.0);
  // Eyring is logarithmic at high rate: G ~ G0 ln(2 V / V*).
  CHECK(ey(6e4) == Approx(2.0 * std::log(2e8)).epsilon(1e-15));
}

TEMPLATE_TEST_CASE("detachment_stretch solves the energy balance A2.4-A2.6", "[friction][detachment]",
                   float, double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  for (T K : {T(0.5), T(6)})
    for (T f1 : {T(-2e-1), T(0), T(3e-1), T(7)})
      for (T G : {T(1e-12), T(1e-3), T(0.4), T(50)}) {
        const T dd = gecko::detachment_stretch(K, f1, G);
        CHECK(dd >= 0);
        // K dd^2 / 2 + f1 dd = G, to rounding (the terms are all >= 0 for f1 >= 0).
        const T lhs = K * dd * dd / 2 + f1 * dd;
        const T scale = K * dd * dd / 2 + std::abs(f1 * dd) + G;
        CHECK(std::abs(lhs - G) <= 8 * eps * scale);
      }
  // f1 > 0, tiny G: the naive (-f1 + sqrt(f1^2 + 2 K G)) / K would give 0 here.
  const T dd = gecko::detachment_stretch(T(6), T(1), T(1e-30));
  CHECK(dd == Approx(T(1e-30)).epsilon(10 * eps));
  CHECK(gecko::detachment_stretch(T(2), T(0), T(1)) == Approx(T(1)).epsilon(2 * eps));
}

TEST_CASE("resonant frequency (eq 4): 17.1 MHz, half the paper's printed 34.3 MHz",
          "[friction][detachment]") {
  const double nu = gecko::resonant_frequency(100e-9, 1e-6, 1.5e9, 1000.0);
  CHECK(nu == Approx(0.14 * 1e5 * std::sqrt(1.5e6)).epsilon(1e-15));
  CHECK(nu == Approx(17.146e6).epsilon(1e-4));
  CHECK(2 * nu == Approx(34.3e6).epsilon(2e-3));  // what the paper printed
  CHECK(1 / nu == Approx(5.83e-8).epsilon(1e-3));  // t_off ~ 0.06 us, not 0.03 us
}

TEST_CASE("detachment: bad input names the argument", "[friction][detachment][errors]") {
  CHECK_THROWS_WITH((gecko::viscoelastic_detachment<double>{0.0, 1.0, 0.5}(1.0)),
                    Catch::Contains("viscoelastic_detachment: G0 = 0"));
  CHECK_THROWS_WITH((gecko::viscoelastic_detachment<double>{1.0, -1.0, 0.5}(1.0)),
                    Catch::Contains("V_star = -1"));
  CHECK_THROWS_WITH((gecko::viscoelastic_detachment<double>{1.0, 1.0, 0.0}(1.0)),
                    Catch::Contains("n = 0"));
  CHECK_THROWS_WITH((gecko::viscoelastic_detachment<double>{1.0, 1.0, 0.5}(-1e-3)),
                    Catch::Contains("V = -0.001"));
  CHECK_THROWS_WITH((gecko::eyring_detachment<double>{-2.0, 1.0}(1.0)), Catch::Contains("G0 = -2"));
  CHECK_THROWS_WITH((gecko::eyring_detachment<double>{1.0, 0.0}(1.0)), Catch::Contains("V_star = 0"));
  CHECK_THROWS_WITH((gecko::eyring_detachment<double>{1.0, 1.0}(std::nan(""))), Catch::Contains("V = nan"));
  CHECK_THROWS_WITH(gecko::detachment_stretch(0.0, 0.0, 1.0), Catch::Contains("K_par_par = 0"));
  CHECK_THROWS_WITH(gecko::detachment_stretch(1.0, 0.0, -1.0), Catch::Contains("G = -1"));
  CHECK_THROWS_WITH(gecko::resonant_frequency(1.0, 1.0, 1.0, 0.0), Catch::Contains("rho = 0"));
  CHECK(std::isnan((gecko::viscoelastic_detachment<double, gecko::policies::nan_policy>{1.0, 1.0, -1.0}(1.0))));
}
