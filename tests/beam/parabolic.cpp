// Tests of gecko/beam/parabolic.hpp: the Appendix-1 closed form (docs/theory/frictional_adhesion.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "beam/beam_reference.hpp"
#include "gecko/beam/castigliano.hpp"
#include "gecko/beam/parabolic.hpp"

using gecko_test::beam_ref;

TEMPLATE_TEST_CASE("closed form against its 30-digit evaluation and the energy integral",
                   "[beam][parabolic]", float, double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  const auto C = gecko::parabolic_beam_compliance<T>(T(1), T(2));  // L^3/2EI = 1/4
  auto rel = [](T a, long double b) { return T(std::abs((a - b) / b)); };
  CHECK(rel(4 * C(0, 0), beam_ref("parabola_closed_form.a11")) <= 4 * eps);
  CHECK(rel(4 * C(0, 1), beam_ref("parabola_closed_form.a12")) <= 4 * eps);
  CHECK(rel(4 * C(1, 1), beam_ref("parabola_closed_form.a22")) <= 4 * eps);
  // The closed form is itself right: against mpmath's quadrature of the energy integral, a = 2 B,
  // which does not go through the closed form (this is where the OCR's "+" in a11 fails: it
  // would be off by ln(4+sqrt17)/1024). The two references agree to 1e-25, far below eps.
  CHECK(rel(4 * C(0, 0), 2 * beam_ref("parabola.B11")) <= 4 * eps);
  CHECK(rel(4 * C(0, 1), 2 * beam_ref("parabola.B12")) <= 4 * eps);
  CHECK(rel(4 * C(1, 1), 2 * beam_ref("parabola.B22")) <= 4 * eps);
}

TEST_CASE("parabolic rigidity: symmetric, positive definite, coupled, ~[[5,-3],[-3,2]]",
          "[beam][parabolic]") {
  const auto K = gecko::parabolic_beam_rigidity(1.0, 1.0);
  CHECK(K(0, 1) == K(1, 0));
  CHECK(K(0, 0) > 0);
  CHECK(K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0) > 0);
  CHECK(K(0, 1) < 0);  // friction couples to adhesion
  const Eigen::Matrix2d Kn = K * (5.0 / K(0, 0));
  CHECK(Kn(0, 1) == Approx(double(beam_ref("parabola_closed_form.K12_norm5"))).epsilon(1e-14));
  CHECK(Kn(1, 1) == Approx(double(beam_ref("parabola_closed_form.K22_norm5"))).epsilon(1e-14));
  // The paper's rounded illustration (eq 2).
  CHECK(Kn(0, 1) == Approx(-3.0).margin(0.02));
  CHECK(Kn(1, 1) == Approx(2.0).margin(0.11));
  CHECK((K * gecko::parabolic_beam_compliance(1.0, 1.0) - Eigen::Matrix2d::Identity())
            .cwiseAbs()
            .maxCoeff() <= 1e-13);
}

TEST_CASE("parabolic compliance scales exactly as L^3/EI", "[beam][parabolic]") {
  const auto C1 = gecko::parabolic_beam_compliance(1.0, 1.0);
  for (double L : {0.5, 2.0, 10.0})
    for (double EI : {0.25, 3.0}) {
      const auto C = gecko::parabolic_beam_compliance(L, EI);
      CHECK((C * (EI / (L * L * L)) - C1).cwiseAbs().maxCoeff() <= 4e-16);
      const auto K = gecko::parabolic_beam_rigidity(L, EI);
      CHECK(((K * (L * L * L / EI) - gecko::parabolic_beam_rigidity(1.0, 1.0)).array() /
             gecko::parabolic_beam_rigidity(1.0, 1.0).array())
                .abs()
                .maxCoeff() <= 4e-16);
    }
}

TEST_CASE("parabolic_beam_compliance: bad input", "[beam][parabolic][errors]") {
  CHECK_THROWS_WITH(gecko::parabolic_beam_compliance(-1.0, 1.0), Catch::Contains("L = -1"));
  CHECK_THROWS_WITH(gecko::parabolic_beam_rigidity(1.0, 0.0), Catch::Contains("EI = 0"));
  CHECK(std::isnan(gecko::parabolic_beam_rigidity(1.0, 0.0, gecko::policies::nan_policy())(0, 0)));
}
