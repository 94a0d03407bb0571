// Tests of gecko/seta/critical_line.hpp (and solve_critical): the critical line of the two-level
// seta against the independent references of tests/data/gen_seta_reference.py (mpmath ODE
// shooting and quadrature, 25 digits), and against an in-test RK4 shooting of eqs 1-5.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/solve_on_line.hpp"
#include "seta/csv_table.hpp"
#include "seta/seta_shooting.hpp"
#include "solved.hpp"

namespace {

using gecko_test::csv_table;
using gecko_test::design_of;
using gecko_test::parse;

const std::string reference_path = std::string(GECKO_TEST_DATA_DIR) + "/seta_reference.csv";

}  // namespace

TEST_CASE("critical line matches the independent references (mpmath ODE + quadrature)", "[seta][line][reference]") {
  const csv_table t = gecko_test::read_csv_table(reference_path);
  REQUIRE(t.rows.size() >= 300);  // the reference table must exist (tests/data/gen_seta_reference.py)
  std::map<int, std::vector<std::size_t>> by_design;
  for (std::size_t i = 0; i < t.rows.size(); ++i) by_design[std::stoi(t.rows[i][t.col("design_id")])].push_back(i);
  REQUIRE(by_design.size() >= 31);  // reference scene + at least 30 random designs
  int states = 0, matched = 0, with_turning = 0, sticky_states = 0, large_ft = 0;
  double worst = 0, worst_beta = 0;
  for (const auto& [id, rows] : by_design) {
    const auto s = design_of(t, t.rows[rows.front()]);
    std::vector<double> Ft;
    for (std::size_t i : rows) Ft.push_back(parse(t.rows[i][t.col("Ft")]));
    const auto got = gecko::critical_line_at(s, Ft);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& r = t.rows[rows[k]];
      const double Fn = parse(r[t.col("Fn")]), beta = parse(r[t.col("theta_joint")]);
      const int tp1 = std::stoi(r[t.col("turning_points_seg1")]), tp2 = std::stoi(r[t.col("turning_points_seg2")]);
      ++states;
      if (tp1 + tp2 > 0) ++with_turning;
      if (std::stoi(r[t.col("branch")]) == 0 && Ft[k] >= 0 && std::isfinite(s.EA2) && Ft[k] > 0.9 * gecko::ft_max(s)) ++large_ft;
      INFO("design " << id << " Ft " << Ft[k] << " ref Fn " << Fn << " got " << got[k].Fn << " status "
                     << static_cast<int>(got[k].status));
      // Every reference state lies on the line followed from Ft = 0 (branch 0): it must be found.
      REQUIRE(seta_test::solved(got[k].status));
      const double err = std::fabs(got[k].Fn - Fn) / std::max(1.0, std::fabs(Fn));
      worst = std::max(worst, err);
      worst_beta = std::max(worst_beta, std::fabs(got[k].theta_joint - beta));
      CHECK(err <= 1e-11);
      CHECK(std::fabs(got[k].theta_joint - beta) <= 1e-11);
      CHECK(got[k].turning_points_beam == tp1);
      CHECK(got[k].turning_points_spatula == tp2);
      if (err <= 1e-11) ++matched;
    }
    if (got.front().Fn < 0) sticky_states += static_cast<int>(rows.size());
  }
  CHECK(with_turning > 50);
  CHECK(sticky_states > 50);
  WARN("reference states " << states << ", matched " << matched << ", with turning points " << with_turning
                           << ", in sticky designs " << sticky_states << ", worst |dFn|/max(1,|Fn|) " << worst
                           << ", worst |dbeta| " << worst_beta << ", states above 0.9 (Ft)max " << large_ft);
}

TEST_CASE("reference scene: natural state, pull-off and line end", "[seta][line]") {
  const gecko::TwoLevelSeta<double> s;  // the paper's reference scene (defaults)
  const auto line = gecko::critical_line(s);
  REQUIRE(seta_test::solved(line.natural.status));
  // (Fn)0 from the scipy peer and the mpmath reference: 0.24990379377720597...
  CHECK(std::fabs(line.natural.Fn - 0.2499037937772059726562097) < 1e-13);
  CHECK(line.end == gecko::line_end::reached_ft_max);
  CHECK(line.points.back().Ft == Approx(10.0).epsilon(1e-14));
  // Fn at the end of the line, reference -0.36249408996184051...
  CHECK(std::fabs(line.points.back().Fn - -0.3624940899618405101778407) < 1e-9);
  double min_fn = 0;
  for (const auto& p : line.points) min_fn = std::min(min_fn, p.Fn);
  CHECK(min_fn == Approx(-2.80).margin(0.02));
}

TEST_CASE("states agree with an RK4 shooting of the governing ODE", "[seta][line][shooting]") {
  // Designs chosen to cover: reference scene, sticky at rest with turning points, EA finite.
  std::vector<gecko::TwoLevelSeta<double>> designs(3);
  designs[1].EI1 = 1.63413; designs[1].EI2 = 1.15448; designs[1].l2 = 0.382758;
  designs[1].alpha1 = 0.694806; designs[1].alpha2 = 0.288542; designs[1].EA1 = 985.906; designs[1].EA2 = 461.675;
  designs[2].EI1 = 0.883755; designs[2].EI2 = 0.0823395; designs[2].l2 = 0.196211;
  designs[2].alpha1 = 0.463326; designs[2].alpha2 = 0.638599; designs[2].EA2 = 100.03;
  int turning = 0;
  for (const auto& s : designs) {
    const double fm = gecko::ft_max(s);
    std::vector<double> Ft;
    for (double f : {0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, -0.1}) Ft.push_back(f * fm);
    const auto got = gecko::critical_line_at(s, Ft);
    for (const auto& st : got) {
      INFO("EI1 " << s.EI1 << " Ft " << st.Ft << " status " << static_cast<int>(st.status));
      REQUIRE(seta_test::solved(st.status));
      const auto shot = seta_test::shoot(s, st.Fn, st.Ft);
      const long double err = seta_test::fn_error(s, st.Fn, st.Ft);
      CHECK(std::fabs(static_cast<double>(err)) <= 1e-11 * std::max(1.0, std::fabs(st.Fn)));
      CHECK(std::fabs(static_cast<double>(shot.theta_joint - st.theta_joint)) < 1e-11);
      CHECK(shot.sign_changes_beam == st.turning_points_beam);
      CHECK(shot.sign_changes_spatula == st.turning_points_spatula);
      turning += st.turning_points_beam + st.turning_points_spatula > 0;
    }
  }
  CHECK(turning >= 5);
}

TEST_CASE("solve_critical from a guess and without one", "[seta][solve]") {
  const gecko::TwoLevelSeta<double> s;
  const auto a = gecko::solve_critical(s, 5.0, gecko::critical_guess<double>{-2.4, 1.49});
  REQUIRE(seta_test::solved(a.status));
  CHECK(a.iterations > 0);
  const auto b = gecko::solve_critical(s, 5.0);
  REQUIRE(seta_test::solved(b.status));
  CHECK(std::fabs(a.Fn - b.Fn) < 1e-13);
  CHECK(std::fabs(a.theta_joint - b.theta_joint) < 1e-13);
}

TEST_CASE("a line that ends exactly at the requested Ft is solved from its end node", "[seta][line]") {
  // The traced line ends at the largest requested Ft; the Hermite guess used to discard that end
  // node (its cubic rounded to the wrong sign at s = 1) and Newton restarted from the previous
  // node, 0.18 away, outside this design's narrow basin: status 1 alone, status 0 with a larger
  // Ft beside it (found by bench/scaling, 2 of 2e6 states).
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 0.890109313591035;
  s.EI2 = 0.3647603514851164;
  s.EA2 = 91.42353211686735;
  s.l2 = 0.04332596620695156;
  s.alpha1 = 0.7443924728216106;
  s.alpha2 = 0.6647447504166255;
  const auto alone = gecko::critical_line_at(s, std::vector<double>{4.427});
  const auto pair = gecko::critical_line_at(s, std::vector<double>{4.427, 4.5});
  REQUIRE(seta_test::solved(alone[0].status));
  REQUIRE(seta_test::solved(pair[0].status));
  CHECK(std::fabs(alone[0].Fn - pair[0].Fn) <= 1e-12 * std::fabs(pair[0].Fn));
  const long double err = seta_test::fn_error(s, alone[0].Fn, 4.427);
  CHECK(std::fabs(static_cast<double>(err)) <= 1e-11 * std::max(1.0, std::fabs(alone[0].Fn)));
  for (double ft : {4.45, 4.427}) {
    CHECK(seta_test::solved(gecko::critical_line_at(s, std::vector<double>{ft})[0].status));
  }
}

TEST_CASE("traced nodes are re-solved to the state tolerance, or say they are not", "[seta][line][nodes]") {
  // Reference scene: every node re-solved, and nodes spread along the line agree with the RK4
  // shooting (an independent route) to the states' 1e-11.
  {
    const gecko::TwoLevelSeta<double> s;
    const auto line = gecko::critical_line(s);
    REQUIRE(line.points.size() > 20);
    for (const auto& p : line.points) REQUIRE(seta_test::solved(p.status));
    for (std::size_t i = 0; i < line.points.size(); i += line.points.size() / 10) {
      const auto& p = line.points[i];
      INFO("node " << i << " Ft " << p.Ft);
      const long double err = seta_test::fn_error(s, p.Fn, p.Ft);
      CHECK(std::fabs(static_cast<double>(err)) <= 1e-11 * std::max(1.0, std::fabs(p.Fn)));
    }
  }
  // A line that runs along a form boundary until it stalls (stress box, bench/stress/traced_nodes.py):
  // its raw continuation nodes, accepted at the line tolerance where the Jacobian is
  // ill-conditioned, are off by up to 4e-9. Each re-solved node must be a converged state: Newton
  // started from it (a fresh solve, plan included) does not move it by more than 1e-12 (scaled).
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 109.03561709410768;
  s.EI2 = 10445.851940246343;
  s.EA1 = 4.8534128346462735;
  s.EA2 = 4438510.754279062;
  s.l2 = 0.06765687857959017;
  s.alpha1 = 0.4202264003740614;
  s.alpha2 = 0.5224316334220043;
  const auto line = gecko::critical_line(s);
  gecko::critical_line_options<double> raw_options;
  raw_options.resolve_nodes = false;
  const auto raw = gecko::critical_line(s, raw_options);
  CHECK(line.end == gecko::line_end::stalled);
  REQUIRE(line.points.size() == raw.points.size());
  REQUIRE(line.points.size() > 100);
  CHECK(seta_test::solved(raw.points[0].status));  // the natural state (7: it crosses the substrate)
  double worst_raw = 0, worst = 0;
  int resolved = 0;
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    const auto& p = line.points[i];
    if (i > 0) CHECK(raw.points[i].status == gecko::critical_status::not_converged);
    if (!seta_test::solved(p.status)) continue;
    ++resolved;
    const auto q = gecko::solve_critical(s, p.Ft, gecko::critical_guess<double>{p.Fn, p.theta_joint, p.theta_rate_joint,
                                                                                 p.theta_rate_base});
    REQUIRE(seta_test::solved(q.status));
    const double scale = std::max(1.0, std::fabs(q.Fn));
    worst = std::max(worst, std::fabs(p.Fn - q.Fn) / scale);
    if (raw.points[i].Ft == p.Ft) worst_raw = std::max(worst_raw, std::fabs(raw.points[i].Fn - q.Fn) / scale);
  }
  CHECK(resolved == static_cast<int>(line.points.size()));
  CHECK(worst <= 1e-12);
  CHECK(worst_raw > 1e-9);  // what the re-solve removes
}

TEST_CASE("EA = 1e12 is continuous with EA = infinity", "[seta][line]") {
  gecko::TwoLevelSeta<double> a, b;
  a.EA2 = std::numeric_limits<double>::infinity();
  b.EA2 = 1e12;
  a.EA1 = std::numeric_limits<double>::infinity();
  b.EA1 = 1e12;
  const std::vector<double> Ft = {0.0, 2.0, 5.0, 8.0};
  const auto ra = gecko::critical_line_at(a, Ft);
  const auto rb = gecko::critical_line_at(b, Ft);
  for (std::size_t i = 0; i < Ft.size(); ++i) {
    REQUIRE(seta_test::solved(ra[i].status));
    REQUIRE(seta_test::solved(rb[i].status));
    // O(1/EA) difference: Fn ~ 10 => ~1e-11
    CHECK(std::fabs(ra[i].Fn - rb[i].Fn) < 1e-9);
  }
}

TEST_CASE("no critical state is reported in status, never as a number", "[seta][status]") {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 1.63413; s.EI2 = 1.15448; s.l2 = 0.382758; s.alpha1 = 0.694806; s.alpha2 = 0.288542;
  s.EA1 = 985.906; s.EA2 = 461.675;
  // This line folds back near Ft = -8.6: no critical state further left.
  const std::vector<double> Ft = {-9.5, -20.0, -40.0};
  const auto r = gecko::critical_line_at(s, Ft);
  for (const auto& x : r) {
    CHECK(x.status == gecko::critical_status::no_critical_state);
    CHECK(std::isnan(x.Fn));
    CHECK(std::isnan(x.theta_joint));
  }
  const auto line = gecko::critical_line(s, gecko::critical_line_options<double>{-9.5});
  CHECK(line.end == gecko::line_end::turned_back);
  REQUIRE(line.folds.size() == 1);
  CHECK(line.folds[0] == Approx(-8.6).margin(0.05));
  // The line is followed around the fold: the nodes after it (branch 1) are genuine states too
  // (corrector tolerance 1e-10 along the traced line; checked by the RK4 shooting).
  int after = 0;
  for (const auto& p : line.points) {
    if (p.branch != 1) continue;
    ++after;
    INFO("branch 1 node Ft " << p.Ft << " Fn " << p.Fn);
    CHECK(std::fabs(static_cast<double>(seta_test::fn_error(s, p.Fn, p.Ft))) <= 1e-9 * std::max(1.0, std::fabs(p.Fn)));
  }
  CHECK(after >= 5);
}

TEST_CASE("bad input names the parameter and its range", "[seta][errors]") {
  using gecko::TwoLevelSeta;
  auto throws_with = [](TwoLevelSeta<double> s, const char* name) {
    CHECK_THROWS_WITH(gecko::solve_critical(s, 1.0), Catch::Contains(name) && Catch::Contains("need"));
  };
  TwoLevelSeta<double> s;
  s.EI1 = -1; throws_with(s, "EI1"); s = {};
  s.EI2 = 0; throws_with(s, "EI2"); s = {};
  s.EA1 = 0; throws_with(s, "EA1"); s = {};
  s.EA2 = -5; throws_with(s, "EA2"); s = {};
  s.l1 = 0; throws_with(s, "l1"); s = {};
  s.l2 = std::numeric_limits<double>::quiet_NaN(); throws_with(s, "l2"); s = {};
  s.w = -1; throws_with(s, "w"); s = {};
  s.alpha1 = 0; throws_with(s, "alpha1"); s = {};
  s.alpha1 = 1.6; throws_with(s, "alpha1"); s = {};
  s.alpha2 = -0.1; throws_with(s, "alpha2"); s = {};
  s.alpha1 = 0.8; s.alpha2 = 0.8; throws_with(s, "alpha1 + alpha2"); s = {};
  CHECK_THROWS_WITH(gecko::solve_critical(s, 10.5), Catch::Contains("Ft") && Catch::Contains("(Ft)max"));
  CHECK_THROWS_WITH(gecko::solve_critical(s, std::numeric_limits<double>::quiet_NaN()), Catch::Contains("Ft"));
  // NaN policy: the bad element is reported in status, the others are solved.
  std::vector<double> Ft = {1.0, 11.0, 2.0};
  std::vector<gecko::critical_state<double>> out(3);
  gecko::critical_line_at(s, Ft.data(), Ft.size(), out.data(), gecko::critical_line_options<double>(),
                          gecko::policies::nan_policy());
  CHECK(seta_test::solved(out[0].status));
  CHECK(out[1].status == gecko::critical_status::invalid_input);
  CHECK(std::isnan(out[1].Fn));
  CHECK(seta_test::solved(out[2].status));
}

TEST_CASE("states read off a line by chord steps: Newton's states, and Newton where the steps do not contract",
          "[seta][line][chord]") {
  // The dense output (gecko/seta/detail/line_output.hpp) reads each state off the traced line by
  // chord steps: residuals alone, with the nodes' Jacobians. On the reference line every state so
  // read must be the state full Newton finds from the same guess, and a chord whose steps do not
  // contract must say so and leave its guess untouched (the caller then runs Newton).
  using Policy = gecko::policies::default_policy;
  using System = gecko::detail::seta_system<double, Policy, false, true>;
  const gecko::TwoLevelSeta<double> s;
  const System sys(gecko::detail::make_seta_params(s));
  gecko::critical_line_options<double> opt;
  gecko::detail::traced_line<System> line;
  System::vec z0;
  System::plan_type plan0;
  gecko::critical_state<double> natural;
  REQUIRE(gecko::detail::trace(sys, 9.9, 9.9, opt, 1000, z0, plan0, natural, line));
  REQUIRE(line.jacobians.size() == line.nodes.size());
  REQUIRE(line.nodes.size() > 20);
  int states = 0, evaluations = 0;
  double worst = 0;
  for (std::size_t i = 0; i + 1 < line.nodes.size(); ++i) {
    const auto& a = line.nodes[i];
    const auto& b = line.nodes[i + 1];
    for (const double f : {0.25, 0.5, 0.75}) {
      const double mu = a.Ft + f * (b.Ft - a.Ft);
      System::vec guess;
      REQUIRE(gecko::detail::hermite_guess(a, b, mu, guess));
      const std::size_t near = f <= 0.5 ? i : i + 1, other = near == i ? i + 1 : i;
      const double w = (mu - line.nodes[near].Ft) / (line.nodes[other].Ft - line.nodes[near].Ft);
      const System::mat E = w * (line.jacobians[other] - line.jacobians[near]);
      const System::mat Jinv = line.jacobians[near].partialPivLu().inverse();
      System::vec z = guess;
      double u14[2];
      int its = 0;
      INFO("node " << i << " fraction " << f);
      REQUIRE(gecko::detail::chord_solve(sys, Jinv, E, z, mu, line.plans[near], 1e-12, its, u14));
      CHECK(sys.plan_valid(line.plans[near], z, mu, u14));
      CHECK(its <= 4);
      auto plan = line.plans[near];
      System::vec zn = guess;
      int newton_its = 0;
      REQUIRE(gecko::detail::solve_with_plans(sys, zn, mu, plan, 1e-14, 40, newton_its) ==
              gecko::critical_status::converged);
      worst = std::max(worst, sys.step_norm(z - zn, zn));
      ++states;
      evaluations += its;
      // E = -0.9 J: the first-order inverse is 1.9 J^-1, steps 1.9 times Newton's, which overshoot
      // and contract by ~0.9, not by the quarter the chord asks for.
      System::vec zb = guess;
      int bad_its = 0;
      CHECK_FALSE(gecko::detail::chord_solve(sys, Jinv, System::mat(-0.9 * line.jacobians[near]), zb, mu,
                                              line.plans[near], 1e-12, bad_its, u14));
      CHECK(zb == guess);
    }
  }
  INFO(states << " states, " << evaluations << " residuals");
  CHECK(worst <= 1e-12);
  CHECK(evaluations <= 3 * states);  // two or three residuals per state (measured: mostly two)
}
