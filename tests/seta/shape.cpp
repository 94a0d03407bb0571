// Tests of gecko/seta/shape.hpp: the integrated shape closes at the contact edge (theta2(a) = pi/2,
// z(a) = 0), the joint angle matches the solved theta_joint, and the RK4 error falls like h^4.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/shape.hpp"

TEST_CASE("deformed shape of solved states", "[seta][shape]") {
  gecko::TwoLevelSeta<double> s;
  const auto states = gecko::critical_line_at(s, std::vector<double>{0.0, 5.0, 9.0});
  for (const auto& st : states) {
    REQUIRE(st.status == gecko::critical_status::converged);
    const auto a = gecko::shape(s, st, 100);
    const auto b = gecko::shape(s, st, 200);
    REQUIRE(a.s.size() == 201);
    CHECK(std::fabs(b.closing_error) < 1e-10);
    // h^4: halving h shrinks the closing error ~16x (or it is already at rounding level)
    CHECK((std::fabs(b.closing_error) < 1e-13 || std::fabs(a.closing_error) > 8 * std::fabs(b.closing_error)));
    CHECK(b.z.back() == 0.0);
    CHECK(b.z.front() > 0);  // the base sits above the substrate
    CHECK(std::fabs(b.theta[200] - st.theta_joint) < 1e-10);  // spatula angle at the joint
    CHECK(b.s.back() == Approx(s.l1 + s.l2).epsilon(1e-15));
  }
  gecko::critical_state<double> bad;
  CHECK(gecko::shape(s, bad).s.empty());
}
