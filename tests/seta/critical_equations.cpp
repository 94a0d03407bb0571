// Tests of gecko/seta/critical_equations.hpp: the residual vanishes at reference states and the
// exact (dual-number) Jacobian agrees with central finite differences, on monotone states and on
// states with turning points, inextensible and extensible.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gecko/seta/critical_equations.hpp"
#include "gecko/seta/critical_line.hpp"

namespace {
void check_jacobian(const gecko::TwoLevelSeta<double>& s, const gecko::critical_state<double>& st, double dFn,
                    double dbeta, double drj, double drb) {
  // Perturbed off the solution so that the Jacobian is tested off-manifold too.
  const double x0[5] = {st.Fn + dFn, st.theta_joint + dbeta, st.theta_rate_joint + drj, st.theta_rate_base + drb, st.Ft};
  const auto at = [&](const double* x) { return gecko::critical_equations(s, x[4], x[0], x[1], x[2], x[3]); };
  const auto r0 = at(x0);
  REQUIRE(r0.valid);
  for (int j = 0; j < 5; ++j) {
    const double h = 1e-6 * std::max(1.0, std::fabs(x0[j]));
    double xp[5], xm[5];
    for (int k = 0; k < 5; ++k) xp[k] = xm[k] = x0[k];
    xp[j] += h;
    xm[j] -= h;
    const auto rp = at(xp), rm = at(xm);
    REQUIRE(rp.valid);
    REQUIRE(rm.valid);
    for (int i = 0; i < 4; ++i) {
      const double fd = (rp.F[i] - rm.F[i]) / (2 * h);
      const double an = j < 4 ? r0.J(i, j) : r0.dF_dFt[i];
      INFO("Ft " << st.Ft << " dF" << i + 1 << "/dx" << j << " analytic " << an << " fd " << fd);
      CHECK(std::fabs(fd - an) <= 1e-7 * std::max(1.0, std::fabs(an)));
    }
  }
}
}  // namespace

TEST_CASE("residual vanishes at solved states; Jacobian matches finite differences", "[seta][equations]") {
  std::vector<gecko::TwoLevelSeta<double>> designs(3);
  designs[1].EI1 = 1.63413; designs[1].EI2 = 1.15448; designs[1].l2 = 0.382758;
  designs[1].alpha1 = 0.694806; designs[1].alpha2 = 0.288542; designs[1].EA1 = 985.906; designs[1].EA2 = 461.675;
  designs[2].EI1 = 0.792828; designs[2].EI2 = 1.52271; designs[2].EA1 = 114.074; designs[2].EA2 = 93.9316;
  designs[2].l2 = 0.332596; designs[2].alpha1 = 0.224697; designs[2].alpha2 = 0.65058;
  int turning = 0;
  for (const auto& s : designs) {
    const double fm = gecko::ft_max(s);
    const auto states = gecko::critical_line_at(s, std::vector<double>{0.0, 0.2 * fm, 0.6 * fm, 0.95 * fm, -0.1 * fm});
    for (const auto& st : states) {
      REQUIRE(st.status == gecko::critical_status::converged);
      const auto r = gecko::critical_equations(s, st.Ft, st.Fn, st.theta_joint, st.theta_rate_joint, st.theta_rate_base);
      REQUIRE(r.valid);
      CHECK(r.F.lpNorm<Eigen::Infinity>() < 1e-12);
      check_jacobian(s, st, 1e-3, -2e-3, 1e-3, -1e-3);
      turning += st.turning_points_beam + st.turning_points_spatula > 0;
    }
  }
  CHECK(turning >= 3);
}
