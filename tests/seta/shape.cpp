// Tests of gecko/seta/shape.hpp: the integrated shape closes at the contact edge (theta2(a) = pi/2,
// the Griffith edge rate, z(a) = 0), the joint matches the solved theta_joint and rate, every
// sampling gives the same points (the adaptive integration is accurate to 1e-12 between them), and
// the closing error stays below 1e-10 over 1,000 random critical states.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/shape.hpp"
#include "random_designs.hpp"

TEST_CASE("deformed shape of solved states", "[seta][shape]") {
  gecko::TwoLevelSeta<double> s;
  const auto states = gecko::critical_line_at(s, std::vector<double>{0.0, 5.0, 9.0});
  for (const auto& st : states) {
    REQUIRE(st.status == gecko::critical_status::converged);
    const auto a = gecko::shape(s, st, 100);
    const auto b = gecko::shape(s, st, 200);
    const auto c = gecko::shape(s, st, 3);
    REQUIRE(a.s.size() == 201);
    CHECK(a.status == 0);
    CHECK(b.status == 0);
    CHECK(c.status == 0);
    CHECK(std::fabs(b.closing_error) < 1e-10);
    CHECK(b.max_closing_error < 1e-10);
    CHECK(b.error_estimate < 1e-10);
    // Any sampling, the same curve: a's point i is b's point 2i.
    for (std::size_t i = 0; i < a.s.size(); ++i) {
      CHECK(std::fabs(a.x[i] - b.x[2 * i]) < 1e-11);
      CHECK(std::fabs(a.z[i] - b.z[2 * i]) < 1e-11);
      CHECK(std::fabs(a.theta[i] - b.theta[2 * i]) < 1e-11);
    }
    CHECK(std::fabs(c.z[3] - b.z[200]) < 1e-11);  // the joint with 3 points per segment
    CHECK(b.z.back() == 0.0);
    CHECK(b.z.front() > 0);  // the base sits above the substrate
    CHECK(std::fabs(b.theta[200] - st.theta_joint) < 1e-10);  // spatula angle at the joint
    CHECK(b.s.back() == s.l1 + s.l2);
  }
  gecko::critical_state<double> bad;
  CHECK(gecko::shape(s, bad).s.empty());
  CHECK(gecko::shape(s, bad).status == 3);
}

TEST_CASE("an inadmissible state is drawn, below the substrate where the check says", "[seta][shape]") {
  gecko::TwoLevelSeta<double> s;
  s.alpha2 = 1.0;
  const auto st = gecko::critical_line_at(s, std::vector<double>{9.999})[0];
  REQUIRE(st.status == gecko::critical_status::inadmissible);
  const auto sh = gecko::shape(s, st, 400);
  REQUIRE(sh.status == 0);
  double zmin = 0;
  for (double z : sh.z) zmin = std::min(zmin, z);
  // the lowest point is the joint (s = l1, a sample point): the same value as the check's
  CHECK(std::fabs(zmin - st.min_z) < 1e-10);
  CHECK(std::fabs(sh.z[400] - st.min_z) < 1e-10);
}

TEST_CASE("shape closes to 1e-10 over 1,000 random critical states", "[seta][shape][random]") {
  std::uint64_t seed = 0x5a4e0013ULL;
  int states = 0, worst_status = 0;
  double worst = 0;
  for (int i = 0; i < 250 && states < 1000; ++i) {
    const auto s = seta_test::sweep_box_design(seed);
    const double fm = gecko::ft_max(s);
    std::vector<double> ft;
    for (int k = 0; k < 5; ++k) ft.push_back(fm * (0.19 * k + 0.1 * seta_test::uniform01(seed)));
    for (const auto& st : gecko::critical_line_at(s, ft)) {
      if (st.status != gecko::critical_status::converged && st.status != gecko::critical_status::inadmissible) continue;
      const auto sh = gecko::shape(s, st, 20);
      INFO("design " << i << " Ft " << st.Ft << " closing " << sh.max_closing_error << " estimate " << sh.error_estimate);
      CHECK(sh.status == 0);
      CHECK(sh.max_closing_error <= 1e-10);
      worst = std::max(worst, sh.max_closing_error);
      worst_status = std::max(worst_status, sh.status);
      ++states;
    }
  }
  INFO("worst closing error " << worst);
  CHECK(states >= 1000);
}
