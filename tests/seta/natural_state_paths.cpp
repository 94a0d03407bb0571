// The natural state at Ft = 0 where the paper's homotopy path stalls
// (gecko/seta/detail/natural_state.hpp, gecko/seta/detail/homotopy_system.hpp). Designs 1072 and 362
// of the stress campaign (validation/data/stress_10000_states.npz): a soft beam under a stiff
// spatula, where the path that scales the angle deficit and sqrt(w) together runs into the edge of
// the region the beam's forms cover (its plan turns infeasible) before lambda = 1. Before, every Ft of
// these designs was status 1 (no natural state); now a path that reaches the full w first gets
// there, and the state agrees with the independent RK4 shooting of the ODE (seta_shooting.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/critical_line.hpp"
#include "seta/seta_shooting.hpp"

namespace {

gecko::TwoLevelSeta<double> design(double EI1, double EI2, double EA1, double EA2, double l2, double alpha1,
                                   double alpha2) {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = EI1; s.EI2 = EI2; s.EA1 = EA1; s.EA2 = EA2;
  s.l1 = 1.0; s.l2 = l2; s.alpha1 = alpha1; s.alpha2 = alpha2; s.w = 1.0;
  return s;
}

}  // namespace

TEST_CASE("natural state found where the first homotopy path stalls", "[seta][natural][stress]") {
  struct expect {
    gecko::TwoLevelSeta<double> s;
    // Design 362 was once status 7 only because its axial strain (4.5, in tension) exceeded 1, which
    // the admissibility check took for a stretch that reaches 0; it stays above the substrate.
    gecko::critical_status status;
  };
  const expect cases[] = {
      {design(0.80490286034451164, 353.10575466540189, 4986.756661468502, 27187449.501405418,
              0.015771499064306242, 1.0205744073106919, 0.38255092568557925),
       gecko::critical_status::converged},
      {design(0.4862557085350056, 95.663642985073622, 12.962666584858646,
              std::numeric_limits<double>::infinity(), 0.0069261819223409527, 1.196205214292706,
              0.10533172401692666),
       gecko::critical_status::converged},
  };
  for (const auto& c : cases) {
    gecko::critical_line_options<double> o;
    o.ft_end = 0.0;
    const auto line = gecko::critical_line(c.s, o);
    INFO("EI1 " << c.s.EI1 << " status " << static_cast<int>(line.natural.status) << " Fn " << line.natural.Fn);
    REQUIRE(line.natural.status == c.status);
    REQUIRE(line.points.size() == 1);
    const double Fn = line.natural.Fn;
    // Independent check: the RK4 shooting's base-angle mismatch, as an error in Fn.
    const long double err = seta_test::fn_error(c.s, Fn, 0.0);
    CHECK(std::fabs(static_cast<double>(err)) <= 1e-8 * std::max(1.0, std::fabs(Fn)));
    const auto shot = seta_test::shoot(c.s, Fn, 0.0L);
    CHECK(std::fabs(static_cast<double>(shot.theta_joint) - line.natural.theta_joint) <= 1e-8);
  }
}

TEST_CASE("a natural state past the edge of the forms is unsupported, decided in the long-double retry",
          "[seta][natural][stress]") {
  // Campaign designs whose every homotopy route failed (status 1 before; validation/README.md,
  // "Where the give-ups end, and natural states at the edge of the forms"):
  // - 88: the paper's path stalls with the beam on its separatrix; the limit system's march in
  //   lambda collapses at lambda = 0.74 and, followed on in arclength, runs into the edge of the
  //   short, stiff spatula's forms at once (|Fn| = 152 there, twice EA2 = 76);
  // - 1815: the paper's path folds back in lambda at 0.025 (Fn ~ 1.5 there already, against
  //   EA1 = 2.4); the two other paths fold and then run into the edge of the forms.
  // Double's homotopy alone gives up (status 1), so the long-double retry runs; it finds the edge
  // and gives every Ft status 3. The traced line and the characteristics ask long double too.
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here: no retry");
    return;
  }
  const gecko::TwoLevelSeta<double> designs[] = {
      {0.20860280544846005, 112.02661304011029, 94145.30914860472, 75.76908464966, 1.0, 0.026779774874249908,
       0.8212992474099053, 0.19960165499580274, 1.0},
      {18.824405697560017, 4.599697412940043, 2.3992102724048303, 2253.8829306743655, 1.0, 0.001092773692841582,
       0.3762465319084896, 0.5778420007609185, 1.0},
  };
  for (const auto& s : designs) {
    INFO("EI1 " << s.EI1);
    const gecko::detail::seta_system<double, gecko::policies::default_policy, true, true> sys(
        gecko::detail::make_seta_params(s));
    gecko::detail::seta_system<double, gecko::policies::default_policy, true, true>::vec z;
    gecko::detail::seta_plan plan;
    int its = 0;
    CHECK(gecko::detail::natural_state(sys, z, plan, its) == gecko::critical_status::not_converged);
    const gecko::TwoLevelSeta<long double> sl{s.EI1, s.EI2, s.EA1, s.EA2, s.l1, s.l2, s.alpha1, s.alpha2, s.w};
    gecko::critical_line_options<long double> ol;
    ol.ft_end = 0.0L;
    CHECK(gecko::critical_line(sl, ol).natural.status == gecko::critical_status::unsupported_state);
    const auto line = gecko::critical_line(s);
    CHECK(line.natural.status == gecko::critical_status::unsupported_state);
    CHECK(line.end == gecko::line_end::unsupported_state);
    CHECK(line.points.empty());
    CHECK(gecko::characteristics(s).end == gecko::line_end::unsupported_state);
    const double fm = gecko::ft_max(s);
    const auto got = gecko::critical_line_at(s, std::vector<double>{-0.5 * fm, 0.0, 0.3 * fm, 0.9 * fm});
    for (const auto& r : got) {
      INFO("Ft " << r.Ft << " status " << static_cast<int>(r.status));
      CHECK(r.status == gecko::critical_status::unsupported_state);
      CHECK(std::isnan(r.Fn));
    }
  }
}
