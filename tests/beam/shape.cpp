// Tests of gecko/beam/shape.hpp: the slope of a shape, explicit or by the complex step.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "gecko/beam/shape.hpp"

namespace {
template <class T>
T rel_error(T a, T b) { return std::abs(a - b) / std::abs(b); }
}  // namespace

TEMPLATE_TEST_CASE("complex-step slope is exact to rounding", "[beam][shape]", float, double,
                   long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  // Near the tip singularity of the parabola, in the middle and at the clamp.
  auto z = [](auto x) { using std::sqrt; return sqrt(x * TestType(3)) / TestType(2); };
  const gecko::parabolic_shape<T> para{T(3)};
  for (T x : {T(1e-20), T(1e-6), T(0.25), T(1), T(3)}) {
    const T exact = para.slope(x);
    CHECK(rel_error(gecko::detail::shape_slope<T>(z, x), exact) <= 4 * eps);
    CHECK(rel_error(gecko::detail::shape_slope<T>(para, x), exact) <= 4 * eps);  // explicit member
  }
  // An oscillating shape: the relative step h = eps x stays far below its scale.
  auto wave = [](auto x) { using std::sin; return sin(TestType(40) * x) + x * x * x; };
  for (T x : {T(0.01), T(0.3), T(0.9)}) {
    const T exact = T(40) * std::cos(T(40) * x) + T(3) * x * x;
    CHECK(std::abs(gecko::detail::shape_slope<T>(wave, x) - exact) <= 64 * eps);
  }
}

TEST_CASE("make_shape uses the given slope, not the complex step", "[beam][shape]") {
  // A deliberately 'wrong' slope proves which route is taken.
  auto s = gecko::make_shape([](double x) { return x * x; }, [](double) { return 42.0; });
  CHECK(s(3.0) == 9.0);
  CHECK(gecko::detail::shape_slope<double>(s, 3.0) == 42.0);
  STATIC_REQUIRE(gecko::detail::has_slope<decltype(s), double>::value);
  auto plain = [](auto x) { return x * x; };
  STATIC_REQUIRE_FALSE(gecko::detail::has_slope<decltype(plain), double>::value);
  STATIC_REQUIRE(gecko::detail::accepts_complex<decltype(plain), double>::value);
}

TEST_CASE("parabolic_shape is z = sqrt(L x)/2", "[beam][shape]") {
  const gecko::parabolic_shape<double> p{2.0};
  CHECK(p(0.0) == 0.0);
  CHECK(p(2.0) == 1.0);
  CHECK(p(0.5) == 0.5);
  CHECK(p.slope(0.5) == Approx(std::sqrt(2.0) / (4 * std::sqrt(0.5))).epsilon(1e-15));
}
