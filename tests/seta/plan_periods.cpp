// The libration period count of a refreshed plan (gecko/seta/elastica_segment.hpp plan_segment,
// gecko/seta/detail/continuation.hpp follow_line). Campaign designs 413, 437 and 528 of the stress
// campaign (validation/data/stress_10000_states.npz), each at its negative Ft: a segment of the
// line followed towards negative Ft is about one libration long (paper 001 eq (15) with l = 4K),
// its ends' phases coincide, and the plan refreshed after a node chose its period count from the
// phases alone. It dropped the period as the end phase passed the start phase (or as an end moved
// to the form of the other side of a turning point, which names the same point by a phase 4K
// apart), the length residual jumped by 4K from one node to the next, and the line ended as
// no_convergence: these states were status 6 (not reached). Now the refreshed plan takes its
// period count from the segment's length at the node, and the states agree with the RK4 shooting
// of the ODE (seta_shooting.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/critical_line.hpp"
#include "seta/seta_shooting.hpp"

namespace {

struct period_case {
  double EI1, EI2, EA1, EA2, l2, alpha1, alpha2, Ft;
};

// The state at c.Ft on the critical line, with the expected status (converged, or inadmissible:
// it solves paper 001 eq (15) as well), checked against the RK4 shooting of the ODE; returned for
// checks of its own.
gecko::critical_state<double> check_state(const period_case& c, gecko::critical_status expected) {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = c.EI1; s.EI2 = c.EI2; s.EA1 = c.EA1; s.EA2 = c.EA2;
  s.l1 = 1.0; s.l2 = c.l2; s.alpha1 = c.alpha1; s.alpha2 = c.alpha2; s.w = 1.0;
  const auto st = gecko::critical_line_at(s, std::vector<double>{c.Ft})[0];
  INFO("EI1 " << s.EI1 << " Ft " << c.Ft << " status " << static_cast<int>(st.status) << " Fn " << st.Fn);
  REQUIRE(st.status == expected);
  // Independent check: the RK4 shooting's base-angle mismatch, as an error in Fn.
  const long double err = seta_test::fn_error(s, st.Fn, c.Ft);
  CHECK(std::fabs(static_cast<double>(err)) <= 1e-8 * std::max(1.0, std::fabs(st.Fn)));
  const auto shot = seta_test::shoot(s, st.Fn, c.Ft);
  CHECK(std::fabs(static_cast<double>(shot.theta_joint) - st.theta_joint) <= 1e-8);
  CHECK(shot.sign_changes_beam == st.turning_points_beam);
  CHECK(shot.sign_changes_spatula == st.turning_points_spatula);
  return st;
}

}  // namespace

TEST_CASE("a line whose segment is one libration long keeps its period count", "[seta][line][stress]") {
  const period_case cases[] = {
      {26.49198234895262, 0.2482999324116493, 12502.835171187016, 3652577.6559803374, 0.02827686290340751,
       1.1636933363048867, 0.12714903335425107, -1449.6527083579476},
      {2.1304496130947532, 0.00408939279640268, 1335.5722906500189, 687.9960275331455, 0.07992537431484655,
       1.2091877915657692, 0.2557590570667968, -35.97813592169937},
      {4.016807922700496, 0.3797143314374259, 11771325.138693243, 4978.413142805896, 0.5852586607649094,
       1.0796046787514415, 0.22435793941112436, -54.87132672250153},
  };
  for (const auto& c : cases) check_state(c, gecko::critical_status::converged);
}

// Campaign designs 971 and 394 (validation/data/stress_10000_states.npz), each at its negative Ft.
// Where the corrector converged to a state its plan no longer applied to, follow_line re-planned
// there from the phases alone (in a step, and in the landing on the end of the range), which can
// drop the period of a segment about one libration long, as the refresh between steps did above;
// these lines ended as no_convergence before reaching Ft (status 6). The re-plan now takes the
// period counts from the lengths at the converged state (detail::plan_at_solution).
// Design 394 solves eq (15) but its seta crosses the substrate (inadmissible, status 7).
TEST_CASE("a re-plan at a converged state keeps the libration period count", "[seta][line][stress]") {
  check_state({41.075667553956144, 0.0932552034397584, 174.60163716341123, 5615.080522039161,
               0.35704620912901713, 1.2599461916860546, 0.25820678549186615, -63.314157628291134},
              gecko::critical_status::converged);
  check_state({79.22094127969113, 0.2962867518683177, 928.9707463831139, std::numeric_limits<double>::infinity(),
               0.9644286252595868, 1.5464121652466718, 0.010191580584372783, -24.795400365954627},
              gecko::critical_status::inadmissible);
}

// Campaign design 3621 (validation/data/stress_10000_states.npz) at its negative Ft. Towards
// negative Ft the beam is in compression and waves with a libration period of about 2 pi elastic
// lengths (EI1/N)^(1/2); at Ft = -323 it is 20 elastic lengths long and passes a fourth period.
// The refreshed plan's count was held below 4, so the plan dropped the periods there, the length
// residual at the node was off by 4K (0.95 in the beam's length equation) and the line ended as
// no_convergence, in double and in the long-double retry: the state was status 6 (not reached).
// The count now has no such bound (gecko/seta/elastica_segment.hpp, max_libration_periods); the
// state has 9 turning points on the beam, as many as the RK4 shot counts.
TEST_CASE("a segment more than four librations long keeps its period count", "[seta][line][stress]") {
  const period_case c{0.814886315391265, 0.09132366430478034, 4250640.435207513, 2287661.8090719273,
                      0.027683694945233053, 1.3248813045970413, 0.2049004680303356, -576.3987285628448};
  const auto st = check_state(c, gecko::critical_status::converged);
  CHECK(st.turning_points_beam == 9);  // past four periods (two turning points each)
}
