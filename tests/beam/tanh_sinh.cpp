// Tests of gecko/beam/tanh_sinh.hpp: the double-exponential rule on (0, 1).
#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "gecko/beam/tanh_sinh.hpp"

namespace {
template <class T, class F>
T integrate1(F f, T tol, gecko::quadrature_report<T>& rep) {
  using V1 = Eigen::Matrix<T, 1, 1>;
  return gecko::detail::tanh_sinh_unit<T, V1>([&](T t) { return V1(f(t)); }, tol, 3, 9, rep)(0);
}
}  // namespace

TEMPLATE_TEST_CASE("tanh-sinh integrates smooth and tip-singular integrands", "[beam][quadrature]",
                   float, double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  const T tol = std::pow(eps, T(2) / T(3));
  gecko::quadrature_report<T> rep;
  // Smooth.
  CHECK(std::abs(integrate1<T>([](T t) { return t * t; }, tol, rep) - T(1) / T(3)) <= 8 * eps);
  CHECK(rep.converged);
  CHECK(std::abs(integrate1<T>([](T t) { return std::exp(t); }, tol, rep) - (std::exp(T(1)) - 1)) <=
        8 * eps);
  // Integrable singularities at t = 0: 1/sqrt(t), -ln t, t^-1/3 (what a tip with z' ~ x^-2/3
  // leaves after x = L t^2). The rule stops at t = eps^2, so t^-a loses 2 eps^(2(1-a)) / (1-a).
  CHECK(std::abs(integrate1<T>([](T t) { return 1 / std::sqrt(t); }, tol, rep) - T(2)) <= 16 * eps);
  CHECK(rep.converged);
  CHECK(std::abs(integrate1<T>([](T t) { return -std::log(t); }, tol, rep) - T(1)) <= 16 * eps);
  CHECK(std::abs(integrate1<T>([](T t) { return std::pow(t, T(-1) / T(3)); }, tol, rep) - T(1.5)) <=
        16 * eps);
}

TEST_CASE("tanh-sinh nodes stay inside (0, 1) and reuse earlier levels", "[beam][quadrature]") {
  const auto& levels = gecko::detail::tanh_sinh_table<double>::levels();
  std::size_t total = 0;
  double wsum = 0;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    for (const auto& nd : levels[k]) {
      CHECK(nd.t > 0.0);
      CHECK(nd.t < 1.0);
      CHECK(nd.w > 0.0);
      if (k == 0) wsum += nd.w;
    }
    total += levels[k].size();
  }
  // The level-0 rule (h = 1, 8 nodes) already integrates the constant 1 to 2%.
  CHECK(wsum == Approx(1.0).margin(0.02));
  CHECK(total > 1000);
}

TEST_CASE("tanh-sinh reports non-convergence", "[beam][quadrature]") {
  using V1 = Eigen::Matrix<double, 1, 1>;
  gecko::quadrature_report<double> rep;
  // A wildly oscillating integrand cannot converge within 2 levels at tol 1e-15.
  gecko::detail::tanh_sinh_unit<double, V1>([](double t) { return V1(std::sin(1e4 * t)); }, 1e-15,
                                            1, 2, rep);
  CHECK_FALSE(rep.converged);
  CHECK(rep.levels == 2);
  CHECK(rep.error_estimate > 0);
}
