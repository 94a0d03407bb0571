// Tests of gecko/beam/rigidity.hpp: K = C^-1 and the checks on a rigidity matrix.
#include <catch2/catch.hpp>

#include <cmath>

#include "gecko/beam/rigidity.hpp"

TEST_CASE("rigidity inverts a symmetric positive definite compliance", "[beam][rigidity]") {
  Eigen::Matrix2d C;
  C << 2.0, 0.5, 0.5, 1.0;
  const auto K = gecko::rigidity(C);
  CHECK(K(0, 1) == K(1, 0));
  CHECK((K * C - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= 4e-16);
  // Ill-conditioned (cond ~ 1e8): the compensated determinant keeps the inverse accurate.
  Eigen::Matrix2d D;
  D << 1.0, 1.0 - 1e-8, 1.0 - 1e-8, 1.0;
  const auto KD = gecko::rigidity(D);
  const double det = 2e-8 - 1e-16;  // exactly 1 - (1 - 1e-8)^2 up to the rounding of 1e-8
  CHECK(KD(0, 0) == Approx(1.0 / det).epsilon(1e-7));
  CHECK((KD * D - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= 1e-7);
}

TEST_CASE("det2 has one rounding error", "[beam][rigidity]") {
  // (1 + 2^-30)^2 - 1 * (1 + 2^-29): naive evaluation gives 0, the exact value is 2^-60.
  const double a = 1.0 + std::ldexp(1.0, -30);
  const double b = 1.0 + std::ldexp(1.0, -29);
  CHECK(gecko::detail::det2(a, b, 1.0, a) == std::ldexp(1.0, -60));
}

TEST_CASE("rigidity and the coupled-rigidity check reject bad matrices", "[beam][rigidity][errors]") {
  Eigen::Matrix2d nonsym, nonpd, negdiag, ok, uncoupled;
  nonsym << 5, -3, -2.9, 2;
  nonpd << 1, 2, 2, 1;
  negdiag << -1, 0, 0, 1;
  ok << 5, -3, -3, 2;
  uncoupled << 5, 1, 1, 2;
  CHECK_THROWS_WITH(gecko::rigidity(nonsym), Catch::Contains("C =") && Catch::Contains("symmetric"));
  CHECK_THROWS_WITH(gecko::rigidity(nonpd), Catch::Contains("positive definite"));
  CHECK_THROWS_WITH(gecko::rigidity(negdiag), Catch::Contains("positive definite"));
  Eigen::Matrix2d nan = ok;
  nan(1, 1) = std::nan("");
  CHECK_THROWS_WITH(gecko::rigidity(nan), Catch::Contains("finite"));
  using P = gecko::policies::default_policy;
  CHECK(gecko::detail::check_coupled_rigidity<double, P>("f", ok));
  CHECK_THROWS_WITH((gecko::detail::check_coupled_rigidity<double, P>("f", uncoupled)),
                    Catch::Contains("K = 1") && Catch::Contains("K_par_perp < 0"));
  CHECK_THROWS_WITH((gecko::detail::check_coupled_rigidity<double, P>("f", nonsym)),
                    Catch::Contains("K ="));
  CHECK(std::isnan(gecko::rigidity(nonpd, gecko::policies::nan_policy())(0, 0)));
}
