// Regression tests from the stress campaign (bench/stress, bench/results/stress.md) for
// gecko/seta/critical_line.hpp and gecko/seta/detail/continuation.hpp: designs whose followed
// line crawls (the step collapses near the edge of the region where the forms exist). Before the
// stall test such a line took 10^5 nodes (seconds; timeouts in the campaign) and reported every
// Ft it had not reached as "no critical state" (status 2) although the line had not ended.
// Now: the line ends early as line_end::stalled, the unreached states are critical_status::
// not_reached, and the states that are returned agree with the RK4 shooting of the ODE.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gecko/seta/critical_line.hpp"
#include "seta/seta_shooting.hpp"

namespace {

struct crawl_case {
  double EI1, EI2, EA1, EA2, l2, alpha1, alpha2;
  std::vector<double> Ft;
};

gecko::TwoLevelSeta<double> design(const crawl_case& c) {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = c.EI1; s.EI2 = c.EI2; s.EA1 = c.EA1; s.EA2 = c.EA2;
  s.l1 = 1.0; s.l2 = c.l2; s.alpha1 = c.alpha1; s.alpha2 = c.alpha2; s.w = 1.0;
  return s;
}

// Campaign designs 104, 233 and 81 of bench/stress/stress_2000.npz (timeouts there).
const std::vector<crawl_case> crawl_cases = {
    {121.23012666200682, 181.93170240108034, 62.13120636995391, 65147751.416489564, 0.0011560084510717048,
     0.7523599362194637, 0.7361350194761096, {0.0, 3434.570189643642, 4847.250251725305, 10273.234996568175}},
    {0.4846134249746898, 0.03688888357900377, 6.638700748633841, 14424.77246656048, 0.003637933262510324,
     0.6253527450948849, 0.1192875572913307, {0.0, 146.93093892249553, 134.8672506791768, 169.68168638011485}},
    {10.925496115802561, 1447.2560672430527, 12758778.242423614, 60395409.89601219, 0.22048726230309484,
     1.209227157850754, 0.2526114036724534, {0.0, 2000.0, 8018.03784429737, 10979.497208126613}},
};

}  // namespace

TEST_CASE("a crawling line ends as stalled, with a bounded number of nodes", "[seta][line][stress]") {
  for (const auto& c : crawl_cases) {
    const auto s = design(c);
    const auto line = gecko::critical_line(s);
    INFO("EI1 " << s.EI1 << " nodes " << line.points.size() << " end " << static_cast<int>(line.end));
    CHECK(line.end == gecko::line_end::stalled);
    // The default stall test (1000 attempts, 1 % of the scale) stops these well before the
    // 10^5-node budget that they used to exhaust.
    CHECK(line.points.size() < 20000);
    // Not checked here: the traced nodes themselves. In the crawl they are off by up to ~1e-6
    // (relative, RK4 shooting and bench/stress/verify.py agree) although the corrector accepted
    // them: the corrector converges only linearly there. States at requested Ft are re-solved by
    // Newton and verified (next test case; bench/results/stress.md).
  }
}

TEST_CASE("states beyond a given-up line are 'not reached', never 'no critical state'", "[seta][status][stress]") {
  for (const auto& c : crawl_cases) {
    const auto s = design(c);
    const double reached = gecko::critical_line(s).points.back().Ft;
    const auto got = gecko::critical_line_at(s, c.Ft);
    int solved = 0, unreached = 0;
    for (const auto& st : got) {
      INFO("EI1 " << s.EI1 << " Ft " << st.Ft << " status " << static_cast<int>(st.status) << " reached " << reached);
      if (st.status == gecko::critical_status::converged) {
        ++solved;
        const long double err = seta_test::fn_error(s, st.Fn, st.Ft);
        CHECK(std::fabs(static_cast<double>(err)) <= 1e-8 * std::max(1.0, std::fabs(st.Fn)));
      } else {
        CHECK(st.status == gecko::critical_status::not_reached);
        CHECK(st.Ft > reached);
        CHECK(std::isnan(st.Fn));
        CHECK(std::isnan(st.theta_joint));
        ++unreached;
      }
    }
    CHECK(solved >= 1);     // the natural state at least
    CHECK(unreached >= 2);  // (Ft)max end not reached in any of them
  }
}
