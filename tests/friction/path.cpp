// Tests of gecko/friction/path.hpp: the paper's paths and their checks.
#include <catch2/catch.hpp>

#include <cmath>

#include "gecko/friction/path.hpp"

using P = gecko::policies::default_policy;

TEST_CASE("paper paths and rigidity are eqs 2, 3, 12, 13", "[friction][path]") {
  const auto K = gecko::paper_rigidity<double>();
  CHECK(K(0, 0) == 5);
  CHECK(K(0, 1) == -3);
  CHECK(K(1, 0) == -3);
  CHECK(K(1, 1) == 2);
  const auto f4 = gecko::fig4_spatula_path<double>();
  CHECK(f4.t == std::vector<double>{0, 0.5, 2});
  CHECK(f4.d_par == std::vector<double>{0, 0, 3});
  CHECK(f4.d_perp == std::vector<double>{0, 1, 1});
  const auto f8 = gecko::fig8_seta_path<double>();
  CHECK(f8.d_par == std::vector<double>{0, 4, 6, 0});
  CHECK(f8.d_perp == std::vector<double>{0, 7, 7, 0});
  CHECK(gecko::detail::check_path<double, P>("f", f4));
  CHECK(gecko::detail::check_path<double, P>("f", f8));
}

TEST_CASE("path_at interpolates linearly and hits vertices exactly", "[friction][path]") {
  const auto p = gecko::fig4_spatula_path<double>();
  CHECK(gecko::detail::path_at(p, 0.0) == Eigen::Vector2d(0, 0));
  CHECK(gecko::detail::path_at(p, 0.5) == Eigen::Vector2d(0, 1));
  CHECK(gecko::detail::path_at(p, 2.0) == Eigen::Vector2d(3, 1));
  CHECK(gecko::detail::path_at(p, 0.25)(1) == Approx(0.5).epsilon(1e-15));
  CHECK(gecko::detail::path_at(p, 1.25)(0) == Approx(1.5).epsilon(1e-15));
}

TEST_CASE("check_path: bad paths name the argument", "[friction][path][errors]") {
  gecko::displacement_path<double> p{{0, 1, 1}, {0, 1, 2}, {0, 0, 0}};
  CHECK_THROWS_WITH((gecko::detail::check_path<double, P>("gecko::force_trace", p)),
                    Catch::Contains("gecko::force_trace: t = 1") &&
                        Catch::Contains("strictly increasing"));
  p.t = {0, 2, 1};
  CHECK_THROWS_WITH((gecko::detail::check_path<double, P>("f", p)), Catch::Contains("t = 1"));
  p.t = {0, 1, 2};
  p.d_perp = {0, 0};
  CHECK_THROWS_WITH((gecko::detail::check_path<double, P>("f", p)), Catch::Contains("equal length"));
  p.d_perp = {0, std::nan(""), 0};
  CHECK_THROWS_WITH((gecko::detail::check_path<double, P>("f", p)), Catch::Contains("d_perp = nan"));
  gecko::displacement_path<double> one{{0}, {0}, {0}};
  CHECK_THROWS_WITH((gecko::detail::check_path<double, P>("f", one)), Catch::Contains("at least 2"));
  CHECK_FALSE((gecko::detail::check_path<double, gecko::policies::nan_policy>("f", one)));
}
