// Tests of gecko/seta/single_fiber.hpp: the single-level fiber's critical states satisfy the
// governing ODE (RK4 shooting in long double, independent of the Carlson forms), through turning
// points and for EA finite and infinite; bad input is named.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/single_fiber.hpp"

namespace {
long double rhs(long double th, long double EI, long double c, long double Fn, long double Ft) {
  const long double T = Ft * std::sin(th) - Fn * std::cos(th);
  return -(Fn * std::sin(th) + Ft * std::cos(th)) * (1 + T * c) / EI;
}
// theta(0) from the contact edge backwards, and the number of sign changes of theta'.
long double shoot(const gecko::SingleFiber<double>& f, long double Fn, long double Ft, int& changes) {
  const long double c = std::isinf(f.EA) ? 0.0L : 1.0L / f.EA;
  long double th = 1.570796326794896619231321691639751442L, om = std::sqrt(2 * (f.w - Ft * Ft * c / 2) / f.EI);
  const int n = 8000;
  const long double h = -f.l / n;
  changes = 0;
  long double prev = om;
  for (int i = 0; i < n; ++i) {
    const long double k1t = om, k1o = rhs(th, f.EI, c, Fn, Ft);
    const long double k2t = om + h / 2 * k1o, k2o = rhs(th + h / 2 * k1t, f.EI, c, Fn, Ft);
    const long double k3t = om + h / 2 * k2o, k3o = rhs(th + h / 2 * k2t, f.EI, c, Fn, Ft);
    const long double k4t = om + h * k3o, k4o = rhs(th + h * k3t, f.EI, c, Fn, Ft);
    th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    om += h / 6 * (k1o + 2 * k2o + 2 * k3o + k4o);
    if ((om > 0) != (prev > 0) && i + 1 < n) ++changes;
    prev = om;
  }
  return th;
}
}  // namespace

TEST_CASE("single fiber critical states satisfy the governing ODE", "[seta][fiber]") {
  std::vector<gecko::SingleFiber<double>> fibers(3);
  fibers[1].EA = std::numeric_limits<double>::infinity();
  fibers[2].EI = 2.0;
  fibers[2].alpha = 0.4;
  fibers[2].EA = 120.0;
  int turning = 0;
  for (const auto& f : fibers) {
    const double scale = std::isinf(f.EA) ? 3.0 : gecko::ft_max(f);
    std::vector<double> Ft;
    for (double x : {0.0, 0.1, 0.3, 0.5, 0.8, 0.95, -0.1}) Ft.push_back(x * scale);
    const auto r = gecko::critical_line_at(f, Ft);
    for (const auto& st : r) {
      INFO("EI " << f.EI << " EA " << f.EA << " Ft " << st.Ft);
      REQUIRE(st.status == gecko::critical_status::converged);
      CHECK(std::isnan(st.theta_joint));
      int changes = 0, c2 = 0;
      const long double th = shoot(f, st.Fn, st.Ft, changes);
      const long double h = 1e-6L * std::max(1.0, std::fabs(st.Fn));
      const long double slope = (shoot(f, st.Fn + h, st.Ft, c2) - th) / h;
      CHECK(std::fabs(static_cast<double>((th - f.alpha) / slope)) <= 1e-11 * std::max(1.0, std::fabs(st.Fn)));
      CHECK(changes == st.turning_points_beam);
      turning += st.turning_points_beam > 0;
    }
  }
  CHECK(turning >= 2);
}

TEST_CASE("single fiber: bad input names the parameter", "[seta][fiber][errors]") {
  gecko::SingleFiber<double> f;
  f.alpha = 1.7;
  CHECK_THROWS_WITH(gecko::critical_line_at(f, std::vector<double>{1.0}), Catch::Contains("alpha"));
  f = {};
  f.EI = 0;
  CHECK_THROWS_WITH(gecko::critical_line_at(f, std::vector<double>{1.0}), Catch::Contains("EI"));
  f = {};
  CHECK_THROWS_WITH(gecko::critical_line_at(f, std::vector<double>{10.5}), Catch::Contains("Ft"));
}
