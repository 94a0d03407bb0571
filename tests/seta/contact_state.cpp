// Tests of gecko/seta/contact_state.hpp, the forward problem (paper 001 after eq 15): the contact
// length a at a given load, against an independent ODE shooting (tests/data/contact_state_reference.csv,
// made by tests/data/gen_contact_state_reference.py), against the critical line (a = l1 + l2 there),
// against the unloaded closed form (eq 6), and its statuses and input checks.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "gecko/seta/contact_state.hpp"
#include "gecko/seta/critical_line.hpp"
#include "seta/csv_table.hpp"

namespace {

struct reference_row {
  std::string label;
  gecko::TwoLevelSeta<double> seta;
  double Fn, Ft, a, theta_joint, rate_joint, rate_base;
  int turning_points;
};

std::vector<reference_row> read_reference() {
  std::vector<reference_row> rows;
  using gecko_test::parse;
  for (const auto& c : gecko_test::read_csv_table(std::string(GECKO_TEST_DATA_DIR) + "/contact_state_reference.csv").rows) {
    if (c.size() < 18) continue;
    reference_row r;
    r.label = c[0];
    r.seta.EI1 = parse(c[1]);
    r.seta.EI2 = parse(c[2]);
    r.seta.EA1 = parse(c[3]);
    r.seta.EA2 = parse(c[4]);
    r.seta.l1 = parse(c[5]);
    r.seta.l2 = parse(c[6]);
    r.seta.alpha1 = parse(c[7]);
    r.seta.alpha2 = parse(c[8]);
    r.seta.w = parse(c[9]);
    r.Fn = parse(c[10]);
    r.Ft = parse(c[11]);
    r.a = parse(c[12]);
    r.theta_joint = parse(c[13]);
    r.rate_joint = parse(c[14]);
    r.rate_base = parse(c[15]);
    r.turning_points = std::stoi(c[16]);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST_CASE("contact_state matches ODE shooting to 1e-11 in a", "[seta][contact]") {
  const auto rows = read_reference();
  REQUIRE(rows.size() >= 60);
  int exact = 0, near = 0, random = 0;
  double worst = 0;
  for (const auto& r : rows) {
    const auto st = gecko::contact_state(r.seta, r.Fn, r.Ft);
    INFO(r.label << " Fn " << r.Fn << " Ft " << r.Ft << " EI1 " << r.seta.EI1 << " EA2 " << r.seta.EA2);
    // Near (Ft)max the reference design dips below the substrate: inadmissible, values kept.
    REQUIRE((st.status == gecko::contact_status::converged || st.status == gecko::contact_status::inadmissible));
    CHECK((st.status == gecko::contact_status::inadmissible) == (st.min_z < -1e-12 * (r.seta.l1 + r.seta.l2)));
    CHECK(st.equilibria == 1);
    CHECK(std::fabs(st.a - r.a) <= 1e-11);
    CHECK(std::fabs(st.theta_joint - r.theta_joint) <= 1e-10);
    CHECK(std::fabs(st.theta_rate_joint - r.rate_joint) <= 1e-9 * (1 + std::fabs(r.rate_joint)));
    CHECK(std::fabs(st.theta_rate_base - r.rate_base) <= 1e-9 * (1 + std::fabs(r.rate_base)));
    CHECK(st.turning_points == r.turning_points);
    CHECK(std::fabs(st.contact_length - (r.seta.l1 + r.seta.l2 - st.a)) <= 1e-15);
    CHECK(std::fabs(st.energy_release_rate - r.seta.w) <= 1e-13 * r.seta.w);
    CHECK(st.a > r.seta.l1);
    CHECK(st.a <= r.seta.l1 + r.seta.l2);
    if (std::fabs(st.a - r.a) > worst) worst = std::fabs(st.a - r.a);
    exact += r.label == "exact";
    near += r.label == "near_singular";
    random += r.label == "random";
  }
  CHECK(exact >= 30);
  CHECK(near >= 8);
  CHECK(random >= 30);
  WARN("worst |a - a_ODE| = " << worst << " over " << rows.size() << " states");
}

TEST_CASE("on the critical line the forward solve returns the critical state, a = l1 + l2", "[seta][contact]") {
  std::vector<gecko::TwoLevelSeta<double>> designs(3);
  designs[1].EA2 = std::numeric_limits<double>::infinity();
  designs[2].EA1 = 100;
  designs[2].l2 = 0.2;
  for (const auto& s : designs) {
    const std::vector<double> ft = {0.0, 1.0, 3.0, 5.0, 7.0};
    std::vector<gecko::critical_state<double>> crit(ft.size());
    gecko::critical_line_at(s, ft.data(), ft.size(), crit.data(), gecko::critical_line_options<double>());
    const gecko::contact_solver<double> solve(s);
    for (std::size_t i = 0; i < ft.size(); ++i) {
      REQUIRE(crit[i].status == gecko::critical_status::converged);
      INFO("EA2 " << s.EA2 << " Ft " << ft[i] << " critical Fn " << crit[i].Fn);
      const auto r = solve(crit[i].Fn, ft[i]);
      REQUIRE(r.status == gecko::contact_status::converged);
      // The critical state is the contact state with its edge at the spatula tip.
      CHECK(std::fabs(r.a - (s.l1 + s.l2)) <= 1e-11);
      CHECK(std::fabs(r.theta_joint - crit[i].theta_joint) <= 1e-9);
      CHECK(std::fabs(r.theta_rate_base - crit[i].theta_rate_base) <= 1e-8);
      CHECK(r.turning_points_beam == crit[i].turning_points_beam);
      // Just above the line the edge moves onto the spatula by da = (da/dFn) dFn; just below, no
      // side contact.
      const auto up = solve(crit[i].Fn + 1e-7, ft[i]);
      REQUIRE(up.status == gecko::contact_status::converged);
      CHECK(up.a < s.l1 + s.l2);
      CHECK(s.l1 + s.l2 - up.a < 1e-4);
      CHECK(solve(crit[i].Fn - 1e-7, ft[i]).status == gecko::contact_status::no_contact);
    }
  }
}

TEST_CASE("no load: the closed form of eq (6), and continuity to tiny loads", "[seta][contact]") {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 4;
  s.EI2 = 1.5;  // sticky at rest (eq 22)
  const double k2 = std::sqrt(2 * s.w / s.EI2), k1 = s.EI2 / s.EI1 * k2;
  const double beta = s.alpha1 + s.alpha2 + k1 * s.l1;
  const double a = s.l1 + (1.5707963267948966 - beta) / k2;
  const auto r0 = gecko::contact_state(s, 0.0, 0.0);
  REQUIRE(r0.status == gecko::contact_status::converged);
  CHECK(std::fabs(r0.a - a) <= 1e-15);
  CHECK(std::fabs(r0.theta_joint - beta) <= 1e-15);
  for (double eps : {1e-6, 1e-9, 1e-12}) {
    for (auto [fn, ft] : {std::pair<double, double>{eps, 0.0}, {0.0, eps}, {-eps, eps}, {-eps, -eps}}) {
      const auto r = gecko::contact_state(s, fn, ft);
      INFO("Fn " << fn << " Ft " << ft);
      REQUIRE(r.status == gecko::contact_status::converged);
      CHECK(std::fabs(r.a - a) <= 10 * eps);
    }
  }
  // The reference scene is not sticky at rest: no side contact without load.
  CHECK(gecko::contact_state(gecko::TwoLevelSeta<double>(), 0.0, 0.0).status == gecko::contact_status::no_contact);
}

TEST_CASE("contact_state statuses: no contact, beyond the joint, Ft beyond -(Ft)max", "[seta][contact]") {
  const gecko::TwoLevelSeta<double> s;
  const gecko::contact_solver<double> solve(s);
  // Pulled hard: no side contact; pushed hard: the edge would move onto the beam.
  for (double ft : {0.0, 2.0, 5.0}) {
    CHECK(solve(-5.0, ft).status == gecko::contact_status::no_contact);
    const auto pushed = solve(20.0, ft);
    CHECK(pushed.status == gecko::contact_status::beyond_joint);
    CHECK(std::isnan(pushed.a));
  }
  CHECK(solve(0.0, -10.5).status == gecko::contact_status::no_contact);
  // a decreases monotonically from l1 + l2 towards l1 as Fn grows between the two lines (Ft = 2).
  double prev = s.l1 + s.l2 + 1;
  int converged = 0;
  for (double fn = -1.0; fn < 3.0; fn += 0.05) {
    const auto r = solve(fn, 2.0);
    if (r.status != gecko::contact_status::converged) continue;
    ++converged;
    CHECK(r.a < prev);
    prev = r.a;
  }
  CHECK(converged > 10);
}

TEST_CASE("contact_equilibria lists what contact_state counts", "[seta][contact]") {
  const gecko::TwoLevelSeta<double> s;
  for (double fn : {-2.0, -1.0, 0.0, 0.5, 1.0}) {
    const auto one = gecko::contact_state(s, fn, 3.0);
    const auto all = gecko::contact_equilibria(s, fn, 3.0);
    CHECK(all.status == one.status);
    CHECK(static_cast<int>(all.states.size()) == (one.status == gecko::contact_status::converged ? 1 : one.equilibria));
    if (one.status == gecko::contact_status::converged) CHECK(all.states[0].a == one.a);
  }
}

TEST_CASE("contact_state input checks", "[seta][contact]") {
  const gecko::TwoLevelSeta<double> s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(gecko::contact_state(s, nan, 1.0), std::domain_error);
  CHECK_THROWS_AS(gecko::contact_state(s, 1.0, nan), std::domain_error);
  CHECK_THROWS_AS(gecko::contact_state(s, std::numeric_limits<double>::infinity(), 1.0), std::domain_error);
  CHECK_THROWS_AS(gecko::contact_state(s, 0.0, 10.01), std::domain_error);
  try {
    gecko::contact_state(s, 0.0, 10.5);
    FAIL("no exception");
  } catch (const std::domain_error& e) {
    const std::string what = e.what();
    CHECK(what.find("Ft") != std::string::npos);
    CHECK(what.find("(Ft)max") != std::string::npos);
  }
  const auto r = gecko::contact_state(s, nan, 1.0, gecko::contact_options<double>(), gecko::policies::nan_policy());
  CHECK(r.status == gecko::contact_status::invalid_input);
  CHECK(std::isnan(r.a));
  gecko::TwoLevelSeta<double> bad;
  bad.EI1 = -1;
  CHECK_THROWS_AS(gecko::contact_state(bad, 0.0, 0.0), std::domain_error);
}

TEST_CASE("inadmissible equilibria: below the substrate or beyond the strain limit, values kept", "[seta][contact]") {
  const gecko::TwoLevelSeta<double> ref;
  const double ft = 9.0;
  gecko::critical_state<double> crit;
  gecko::critical_line_at(ref, &ft, 1, &crit, gecko::critical_line_options<double>());
  const auto r = gecko::contact_state(ref, crit.Fn + 1e-4, ft);
  REQUIRE(r.status == gecko::contact_status::converged);
  CHECK(r.max_axial_strain > 0.17);  // about Ft/EA2: the reference design strains 18 % here
  CHECK(r.min_z >= -1e-12);
  gecko::contact_options<double> limited;
  limited.strain_limit = 0.1;
  const auto l = gecko::contact_state(ref, crit.Fn + 1e-4, ft, limited);
  CHECK(l.status == gecko::contact_status::inadmissible);
  CHECK(l.a == r.a);  // the state is kept for drawing
  CHECK(l.theta_joint == r.theta_joint);
  // A soft, long spatula on a steep kink: some loads have equilibria that put the joint below the
  // substrate.
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 1.5;
  s.EI2 = 0.3;
  s.l2 = 0.5;
  s.alpha1 = 0.3;
  s.alpha2 = 0.6;
  s.EA1 = 80;
  const gecko::contact_solver<double> solve(s);
  int inadmissible = 0, several = 0;
  for (int i = 0; i < 41; ++i)
    for (int j = 0; j < 41; ++j) {
      const double fn = -5 + 8.0 * j / 40, f_t = -5 + 15.0 * i / 40;
      const auto all = solve.equilibria(fn, f_t);
      int adm = 0;
      for (const auto& e : all.states) {
        REQUIRE(std::isfinite(e.a));
        REQUIRE(std::isfinite(e.min_z));
        if (e.status == gecko::contact_status::converged) {
          ++adm;
          CHECK(e.min_z >= -1e-12 * (s.l1 + s.l2));
        } else {
          CHECK(e.status == gecko::contact_status::inadmissible);
          CHECK(e.min_z < 0);
        }
      }
      if (adm == 0 && !all.states.empty()) {
        ++inadmissible;
        CHECK(all.status == gecko::contact_status::inadmissible);
        const auto one = solve(fn, f_t);
        CHECK(one.status == gecko::contact_status::inadmissible);
        CHECK(std::isfinite(one.a));
      }
      if (adm == 1) CHECK(all.status == gecko::contact_status::converged);
      if (adm > 1) {
        ++several;
        CHECK(all.status == gecko::contact_status::several_equilibria);
      }
    }
  CHECK(inadmissible > 0);
  CHECK(several > 0);
}
