// Tests of gecko/seta/sensitivities.hpp: dFn/d(design) by implicit differentiation against
// central finite differences of whole re-solved critical lines, for every parameter, on monotone
// and turning-point states, EA finite and infinite.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gecko/seta/sensitivities.hpp"
#include "solved.hpp"

namespace {
double& field(gecko::TwoLevelSeta<double>& s, int j) {
  double* f[9] = {&s.EI1, &s.EI2, &s.EA1, &s.EA2, &s.l1, &s.l2, &s.alpha1, &s.alpha2, &s.w};
  return *f[j];
}
}  // namespace

TEST_CASE("sensitivities match finite differences of re-solved lines", "[seta][sensitivities]") {
  std::vector<gecko::TwoLevelSeta<double>> designs(2);
  designs[1].EI1 = 1.63413; designs[1].EI2 = 1.15448; designs[1].l2 = 0.382758;
  designs[1].alpha1 = 0.694806; designs[1].alpha2 = 0.288542; designs[1].EA1 = 985.906; designs[1].EA2 = 461.675;
  int turning = 0;
  for (const auto& s : designs) {
    const std::vector<double> Ft = {0.0, 0.3 * gecko::ft_max(s), 0.7 * gecko::ft_max(s)};
    const auto sens = gecko::sensitivities(s, Ft);
    for (std::size_t k = 0; k < Ft.size(); ++k) {
      REQUIRE(seta_test::solved(sens[k].state.status));
      turning += sens[k].state.turning_points_beam + sens[k].state.turning_points_spatula > 0;
      for (int j = 0; j < 9; ++j) {
        auto sp = s, sm = s;
        if (std::isinf(field(sp, j))) {
          CHECK(sens[k].dFn[static_cast<std::size_t>(j)] == 0);
          continue;
        }
        const double h = 1e-5 * std::fabs(field(sp, j));
        field(sp, j) += h;
        field(sm, j) -= h;
        // Ft is held fixed: keep it below (Ft)max of the perturbed designs.
        const auto rp = gecko::critical_line_at(sp, std::vector<double>{Ft[k]});
        const auto rm = gecko::critical_line_at(sm, std::vector<double>{Ft[k]});
        REQUIRE(seta_test::solved(rp[0].status));
        REQUIRE(seta_test::solved(rm[0].status));
        const double fd = (rp[0].Fn - rm[0].Fn) / (2 * h);
        const double fdb = (rp[0].theta_joint - rm[0].theta_joint) / (2 * h);
        const double an = sens[k].dFn[static_cast<std::size_t>(j)];
        const double anb = sens[k].dtheta_joint[static_cast<std::size_t>(j)];
        INFO("design EI1 " << s.EI1 << " Ft " << Ft[k] << " parameter " << j << " analytic " << an << " fd " << fd);
        CHECK(std::fabs(an - fd) <= 1e-6 * std::max(1.0, std::fabs(an)));
        CHECK(std::fabs(anb - fdb) <= 1e-6 * std::max(1.0, std::fabs(anb)));
      }
    }
  }
  CHECK(turning >= 2);
}
