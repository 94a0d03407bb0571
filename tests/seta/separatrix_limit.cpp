// Tests for gecko/seta/detail/separatrix_limit.hpp (states past a followed line's stall, on a
// segment's separatrix) and the admissibility check's walk past the saddle
// (gecko/seta/admissibility.hpp, walk_past_saddle).
// Reference values: tests/data/seta_separatrix_reference.csv (mpmath, the quadrature route with
// the separatrix distances as unknowns and, up to 40 elastic lengths, joint-matching Taylor
// shooting; for design 8038, an extensible beam ending next to its saddle, the bracketing
// backward shot; gen_seta_separatrix_reference.py).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "gecko/seta/admissibility.hpp"
#include "gecko/seta/critical_line.hpp"
#include "gecko/seta/sensitivities.hpp"
#include "seta/csv_table.hpp"

namespace {

using gecko_test::design_of;
using gecko_test::parse;
using gecko_test::read_csv_table;

// A design of the reference table, read from the rows of its case (one source with the generator).
gecko::TwoLevelSeta<double> reference_design(const std::string& name) {
  const auto t = read_csv_table(std::string(GECKO_TEST_DATA_DIR) + "/seta_separatrix_reference.csv");
  for (const auto& r : t.rows)
    if (r[t.col("case")] == name) return design_of(t, r);
  FAIL("no " << name << " rows in seta_separatrix_reference.csv");
  return {};
}
// Campaign design 27 (validation/data/stress_10000_states.npz): its followed line stalls at
// Ft = 145 with the spatula 23 and the beam 17 elastic lengths long, both next to their separatrices.
gecko::TwoLevelSeta<double> design_27() { return reference_design("design_27"); }

}  // namespace

TEST_CASE("states recovered on a separatrix agree with arbitrary-precision references", "[seta][separatrix]") {
  const auto t = read_csv_table(std::string(GECKO_TEST_DATA_DIR) + "/seta_separatrix_reference.csv");
  REQUIRE(t.rows.size() >= 5);
  double deepest = 0;
  // The rows of one case are asked for together, as the generator asked gecko for them (the traced
  // line, and so where it stalls, depends on the requested range and count).
  std::size_t i = 0;
  while (i < t.rows.size()) {
    std::size_t j = i;
    std::vector<double> Ft;
    while (j < t.rows.size() && t.rows[j][t.col("case")] == t.rows[i][t.col("case")])
      Ft.push_back(parse(t.rows[j++][t.col("Ft")]));
    const auto s = design_of(t, t.rows[i]);
    const auto got = gecko::critical_line_at(s, Ft);
    for (std::size_t k = i; k < j; ++k) {
      const auto& r = t.rows[k];
      const auto& st = got[k - i];
      const double Fn = parse(r[t.col("Fn")]), beta = parse(r[t.col("theta_joint")]);
      deepest = std::max({deepest, parse(r[t.col("elastic_beam")]), parse(r[t.col("elastic_spatula")])});
      INFO(r[t.col("case")] << " Ft " << st.Ft << " status " << static_cast<int>(st.status));
      REQUIRE((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
      CHECK(std::fabs(st.Fn - Fn) <= 1e-11 * std::max(1.0, std::fabs(Fn)));
      CHECK(std::fabs(st.theta_joint - beta) <= 1e-11);
      CHECK(std::isfinite(st.min_z));  // its admissibility decided
    }
    i = j;
  }
  CHECK(deepest > 100);  // the table reaches segments beyond 100 elastic lengths
}

TEST_CASE("the followed line stalls where the recovered states begin", "[seta][separatrix]") {
  // Without the separatrix limit every state past the stall was status 6 (not reached).
  const auto s = design_27();
  const auto line = gecko::critical_line(s, [] {
    gecko::critical_line_options<double> o;
    o.ft_end = 1000;
    return o;
  }());
  CHECK(line.end == gecko::line_end::stalled);
  CHECK(line.points.back().Ft < 200);
  const auto got = gecko::critical_line_at(s, std::vector<double>{100.0, 200.0, 1000.0});
  for (const auto& st : got) {
    INFO("Ft " << st.Ft);
    CHECK(st.status == gecko::critical_status::converged);
    CHECK(st.turning_points_beam == 1);
    CHECK(st.turning_points_spatula == 1);
  }
}

TEST_CASE("a line that never leaves its natural state is marched from it", "[seta][separatrix]") {
  // Campaign design 3664: the natural state's beam is 43 elastic lengths long, on its separatrix,
  // and the continuation fails at its first step. Before the march started from such a one-node
  // line, every Ft > 0 of this design was status 6; the state itself is checked against its
  // reference by the first test case (single_3664).
  const auto s = reference_design("single_3664");
  const auto line = gecko::critical_line(s, [] {
    gecko::critical_line_options<double> o;
    o.ft_end = 8;  // (Ft)max = sqrt(2 EA2 w) = 8.64
    return o;
  }());
  CHECK(line.end == gecko::line_end::no_convergence);
  CHECK(line.points.size() == 1);
  const auto got = gecko::critical_line_at(s, std::vector<double>{2.0, 8.635534569003983});
  for (const auto& st : got) {
    INFO("Ft " << st.Ft << " status " << static_cast<int>(st.status));
    CHECK((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
  }
}

TEST_CASE("states given up in double are solved along the same line in long double", "[seta][separatrix]") {
  // Campaign design 1005: in double its line and the separatrix march stop before all four Ft
  // (status not_reached, the limit system's Newton at a rounding floor); critical_line_at retries
  // them in long double (gecko/seta/critical_line.hpp, retry_in_long_double). The states are
  // checked against their references by the first test case (long_double_1005); here, that the
  // double call returns the long-double states rounded, and that a state double solves is its own.
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here: no retry");
    return;
  }
  const auto s = reference_design("long_double_1005");
  const std::vector<double> Ft{0.0, 164.2456444511225, 210.259320846518, 377.08184261870156, 418.5608453067587};
  const auto got = gecko::critical_line_at(s, Ft);
  const gecko::TwoLevelSeta<long double> sl{s.EI1, s.EI2, s.EA1, s.EA2, s.l1, s.l2, s.alpha1, s.alpha2, s.w};
  const auto wide = gecko::critical_line_at(sl, std::vector<long double>(Ft.begin(), Ft.end()));
  for (std::size_t k = 1; k < Ft.size(); ++k) {
    INFO("Ft " << Ft[k] << " status " << static_cast<int>(got[k].status));
    CHECK((got[k].status == gecko::critical_status::converged || got[k].status == gecko::critical_status::inadmissible));
    CHECK(got[k].status == wide[k].status);
    CHECK(got[k].Fn == static_cast<double>(wide[k].Fn));
    CHECK(got[k].theta_joint == static_cast<double>(wide[k].theta_joint));
    CHECK(got[k].turning_points_beam == wide[k].turning_points_beam);
  }
  // The natural state (Ft = 0) is solved in double and kept as double computed it, within the
  // tolerance of the long-double state.
  REQUIRE(got[0].status == gecko::critical_status::converged);
  CHECK(std::fabs(got[0].Fn - static_cast<double>(wide[0].Fn)) <= 1e-12 * std::fabs(got[0].Fn));
}

TEST_CASE("a wider type measures its limit segments as many binades deeper as its extra digits", "[seta][separatrix]") {
  // gecko/seta/detail/separatrix_scales.hpp: double's scales unchanged (the states solved in double
  // are bit for bit those before), long double's deeper by its extra digits, where its rounding
  // leaves delta as many bits as double's does at 2^-36. Campaign design 809's three states past
  // its stall, refused by the retry at double's scales, are solved at these (rows ld_exponents_809
  // of the reference table: the first test case checks them).
  using namespace gecko::detail;
  STATIC_REQUIRE(separatrix_resolved_exponent_of<double>() == separatrix_resolved_exponent);
  STATIC_REQUIRE(separatrix_unresolved_exponent_of<double>() == separatrix_unresolved_exponent);
  STATIC_REQUIRE(separatrix_resolved_exponent_of<float>() == separatrix_resolved_exponent);
  constexpr int extra = std::numeric_limits<long double>::digits - std::numeric_limits<double>::digits;
  STATIC_REQUIRE(separatrix_resolved_exponent_of<long double>() == separatrix_resolved_exponent - extra);
  STATIC_REQUIRE(separatrix_unresolved_exponent_of<long double>() == separatrix_unresolved_exponent - extra);
}

TEST_CASE("the walk past the saddle agrees with the walk calibrated to the length", "[seta][separatrix][admissibility]") {
  // At Ft = 145 the spatula's separatrix distance (~1e-12 of |M| + N) is still resolved, so the
  // calibrated walk (eta solved from the length) measures it; the walk past the saddle (the
  // libration at a larger eta with the missing length as a straight dwell) must give the same
  // heights.
  const auto s = design_27();
  const double Ft = 145.0;
  const auto st = gecko::critical_line_at(s, std::vector<double>{Ft})[0];
  REQUIRE(st.status == gecko::critical_status::converged);
  REQUIRE(st.turning_points_spatula == 1);
  using namespace gecko::detail;
  const double N = std::hypot(st.Fn, Ft), phi = std::atan2(st.Fn, Ft);
  const double c2 = 1 / s.EA2;
  // The spatula's first integral: M2 = Ft + w (paper 001 eq (9)).
  auto g = make_height_segment(s.EI2, c2, Ft + s.w, N, phi, st.Fn / N, Ft / N, true);
  const double L = s.l1 + s.l2, tol = 1e-13 * L;
  segment_walk<double> calibrated, past;
  const double half_pi = std::acos(-1.0) / 2;
  REQUIRE(calibrate_near_saddle(g, st.theta_joint, st.theta_rate_joint, half_pi, 1, s.l2, tol, 1e-9 * L,
                                1e-10 * (Ft + s.w + N), calibrated));
  REQUIRE(walk_past_saddle(g, st.theta_joint, st.theta_rate_joint, half_pi, 1, s.l2, tol, past));
  CHECK(std::fabs(past.length - s.l2) <= 1e-12 * L);
  CHECK(std::fabs(past.dz - calibrated.dz) <= 1e-9 * L);
  CHECK(std::fabs(past.zmin - calibrated.zmin) <= 1e-9 * L);
  // Injected: a segment shorter than the libration at the walk's eta is refused (no dwell to add).
  segment_walk<double> refused;
  CHECK_FALSE(walk_past_saddle(g, st.theta_joint, st.theta_rate_joint, half_pi, 1, 0.5 * s.l2, tol, refused));
  CHECK_FALSE(walk_past_saddle(g, st.theta_joint, st.theta_rate_joint, half_pi, 0, s.l2, tol, refused));
}

TEST_CASE("the separatrix correction refuses a state it cannot certify", "[seta][separatrix]") {
  // Injected failures at a recovered state: turning points two away from the line's, and a limit
  // segment that is not yet long enough (the beam at Ft = 150, 17 elastic lengths: its length at
  // delta_b exceeds l1).
  const auto s = design_27();
  using System = gecko::detail::seta_system<double, gecko::policies::default_policy, false, true>;
  const System sys(gecko::detail::make_seta_params(s));
  struct probe {
    double Ft;
    int mask;
    bool certain;
  };
  const int spatula = gecko::detail::limit_spatula, both = gecko::detail::limit_beam | gecko::detail::limit_spatula;
  for (const probe& pr : {probe{150.0, spatula, true}, probe{150.0, both, false}, probe{1000.0, both, true}}) {
    const auto st = gecko::critical_line_at(s, std::vector<double>{pr.Ft})[0];
    REQUIRE(st.status == gecko::critical_status::converged);
    const double mu = sys.mu_of(pr.Ft);
    auto z = sys.from_guess(st.Fn, st.theta_joint, st.theta_rate_joint, st.theta_rate_base, pr.Ft);
    gecko::detail::separatrix_system<double, gecko::policies::default_policy, false, true> lim{sys, pr.mask};
    auto plan = lim.plan(z, mu);
    int its = 0;
    INFO("Ft " << pr.Ft << " mask " << pr.mask);
    REQUIRE(gecko::detail::solve_separatrix(lim, z, mu, plan, 1e-12, its));
    // The limit segments' turning points come from the side of the separatrix that fits the ends.
    // Expected within one of them (an end through the saddle's orientation); two away is a path
    // with a loop more, refused.
    const int expected[2] = {0, 2}, wrong[2] = {1, 3};
    int turning[2] = {(pr.mask & gecko::detail::limit_beam) ? -1 : st.turning_points_beam,
                      (pr.mask & gecko::detail::limit_spatula) ? -1 : st.turning_points_spatula};
    auto zc = z;
    CHECK(gecko::detail::separatrix_state_exact(lim, zc, mu, plan, 1e-12, expected, turning) == pr.certain);
    if (pr.certain) {  // the corrected state is the recovered one, with its turning points
      CHECK(std::fabs(zc[0] - st.Fn) <= 1e-11 * std::max(1.0, std::fabs(st.Fn)));
      CHECK(std::fabs(zc[1] - st.theta_joint) <= 1e-11);
      CHECK(turning[0] == st.turning_points_beam);
      CHECK(turning[1] == st.turning_points_spatula);
    }
    zc = z;
    CHECK_FALSE(gecko::detail::separatrix_state_exact(lim, zc, mu, plan, 1e-12, wrong, turning));
  }
}

TEST_CASE("the march keeps to the limit state whose ends a path joins", "[seta][separatrix]") {
  // Campaign design 4 (mirror_4 of the reference table): past its stall the beam's joint end lies
  // 1.4e-3 to 1.6e-3 rad short of the saddle's orientation. The limit system sees the joint only
  // through sin(psi), even about the saddle, so it also has a mirror solution with the joint as far
  // past it. The march had jumped onto the mirror at Ft = 1484.6, and every target beyond was
  // refused (status 6). Both solve the limit system; only the followed one has a path joining its
  // ends. (The table has no rows of these states: the bracketing shot's root agrees with them in
  // Fn to 3.4e-13 but counts 3 beam turning points where gecko has 1, along the beam's dwell.)
  const auto s = reference_design("mirror_4");
  using System = gecko::detail::seta_system<double, gecko::policies::default_policy, true, true>;
  using Limit = gecko::detail::separatrix_system<double, gecko::policies::default_policy, true, true>;
  const System sys(gecko::detail::make_seta_params(s));
  const std::vector<double> Ft{0.0, 2973.778736877619, 3242.789375309997, 3439.8812489588895, 3818.268186344367};
  const auto got = gecko::critical_line_at(s, Ft);
  const double half_pi = std::acos(-1.0) / 2;
  for (std::size_t k = 1; k < Ft.size(); ++k) {
    const auto& st = got[k];
    INFO("Ft " << Ft[k] << " status " << static_cast<int>(st.status));
    REQUIRE((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
    const double mu = sys.mu_of(Ft[k]);
    const Limit lim{sys, gecko::detail::limit_beam | gecko::detail::limit_spatula};
    // The joint end's angle from the beam's saddle, psi = pi/2.
    auto joint_from_saddle = [&](const System::vec& z) {
      double FtS, edge;
      sys.forces(mu, FtS, edge);
      const auto g = gecko::detail::make_seta_geometry<true, true>(sys.d, z[0], z[1], z[2], z[3], FtS, edge, true);
      return g.psi_e1 - half_pi;
    };
    // Both limit states solved to 1e-10 (the long-double march's tolerance): from the exact state at
    // Ft = 3818.27 the limit system's Newton in double does not reach 1e-12.
    auto z = sys.from_guess(st.Fn, st.theta_joint, st.theta_rate_joint, st.theta_rate_base, Ft[k]);
    auto plan = lim.plan(z, mu);
    int its = 0;
    REQUIRE(gecko::detail::solve_separatrix(lim, z, mu, plan, 1e-10, its));
    const double x = joint_from_saddle(z);
    CHECK(x < -1e-3);
    CHECK(x > -2e-3);
    CHECK(gecko::detail::limit_ends_joined(lim, z, mu));
    // The mirror: beta moved by -2x puts the joint end as far past the saddle.
    auto zm = z;
    zm[1] -= 2 * x;
    auto plan_m = lim.plan(zm, mu);
    REQUIRE(gecko::detail::solve_separatrix(lim, zm, mu, plan_m, 1e-10, its));
    const double xm = joint_from_saddle(zm);
    CHECK(xm > 0.5 * std::fabs(x));
    CHECK(xm < 2 * std::fabs(x));
    CHECK(std::fabs(zm[1] - z[1]) > std::fabs(x));
    CHECK(zm[2] * z[2] > 0);  // the joint rate keeps its sign: the mirror is no passage of the saddle
    CHECK_FALSE(gecko::detail::limit_ends_joined(lim, zm, mu));
    int expected[2] = {st.turning_points_beam, st.turning_points_spatula}, turning[2];
    CHECK_FALSE(gecko::detail::separatrix_state_exact(lim, zm, mu, plan_m, 1e-12, expected, turning));
  }
}

TEST_CASE("the march keeps a free rate's sign through its end's saddle, as the traced line does", "[seta][separatrix]") {
  // Campaign design 161 (keep_sign_161 of the reference table): in double the followed line stalls
  // at Ft = 1398.4 with the beam's base just short of its saddle's orientation and theta1'(0) < 0.
  // The limit system leaves theta1'(0) free in sign (it enters squared); the march had landed on
  // the other sign at its first step (another path, a loop apart), and at the base's saddle
  // carried it through zero to ends that no path joins, reaching states with theta1'(0) < 0 and 2
  // beam turning points at Ft = 5485.91 and 6089.36. The same line traced in long double, by the
  // full system alone, passes the saddle with theta1'(0) going from negative to positive and keeps
  // it positive to where it ends; the march now does too (keep_ends_joined). The first test case
  // checks those states against their references.
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here: no traced line to compare with");
    return;
  }
  const auto s = reference_design("keep_sign_161");
  const gecko::TwoLevelSeta<long double> sl{s.EI1, s.EI2, s.EA1, s.EA2, s.l1, s.l2, s.alpha1, s.alpha2, s.w};
  gecko::critical_line_options<long double> o;
  o.ft_end = 6090;  // below (Ft)max = 6095.46
  const auto traced = gecko::critical_line(sl, o);
  REQUIRE(traced.points.size() > 2);
  const auto& last = traced.points.back();
  CHECK(last.Ft > 3000);  // well past the base's saddle (Ft = 1398.6)
  for (const auto& pt : traced.points) {
    INFO("traced Ft " << static_cast<double>(pt.Ft));
    if (pt.Ft < 1390) CHECK(pt.theta_rate_base < 0);
    if (pt.Ft > 1410) CHECK(pt.theta_rate_base > 0);
  }
  // In double, at the traced line's last Ft (the retry in long double, or the march) and beyond (the march).
  const auto got = gecko::critical_line_at(
      s, std::vector<double>{static_cast<double>(last.Ft), 5485.909656607731, 6089.359718834582});
  for (const auto& st : got) {
    INFO("Ft " << st.Ft << " status " << static_cast<int>(st.status));
    REQUIRE((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
    CHECK(st.theta_rate_base > 0);
  }
  CHECK(std::fabs(got[0].Fn - static_cast<double>(last.Fn)) <= 1e-11 * std::fabs(got[0].Fn));
  CHECK(got[0].turning_points_beam == last.turning_points_beam);
}

TEST_CASE("the march goes on in arclength where its steps in Ft collapse", "[seta][separatrix]") {
  // Campaign design 1298 (arclength_1298 of the reference table, whose values the first test case
  // checks): the followed line stalls at Ft = 2480.5 with the beam on its separatrix; the march in
  // Ft on the limit system collapsed at Ft = 2588.6, where Newton in Ft no longer converges, in
  // double and in the long-double retry, and the three targets beyond were status 6. The retry's
  // march now goes on in arclength from there.
  const auto s = reference_design("arclength_1298");
  const std::vector<double> Ft{0.0, 2766.188288194081, 3681.7744044388473, 4086.7695889271204};
  gecko::critical_line_options<double> o;
  o.ft_end = Ft.back();
  const auto line = gecko::critical_line(s, o);
  CHECK(line.end == gecko::line_end::stalled);
  CHECK(line.points.back().Ft < 2500);
  const auto got = gecko::critical_line_at(s, Ft);
  for (const auto& st : got) {
    INFO("Ft " << st.Ft << " status " << static_cast<int>(st.status));
    CHECK((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
  }
}

TEST_CASE("the joining test looks no farther from the separatrix than the nearer end's own f3", "[seta][separatrix]") {
  // joining_distance (gecko/seta/detail/separatrix_limit.hpp): double keeps the fixed distance
  // 2^-36 of the scale; a wider type starts from its own deeper one and shrinks it to a quarter of
  // the nearer end's X3^2, down to a floor four bits above its rounding of the scale.
  using gecko::detail::joining_distance;
  CHECK(joining_distance(100.0, 1e-9, 3.0) == std::ldexp(100.0, -36));
  CHECK(joining_distance(100.0, 5.0, 3.0) == std::ldexp(100.0, -36));
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here");
    return;
  }
  const long double scale = 100, fixed = std::ldexp(scale, gecko::detail::separatrix_resolved_exponent_of<long double>());
  const long double floor = std::ldexp(scale, 4 - std::numeric_limits<long double>::digits);
  CHECK(joining_distance<long double>(scale, 5, 3) == fixed);  // ends far from their saddle
  const long double rate = 1e-7L, quarter = rate * rate / 4;  // the joint rate 1e-7: f3 = 1e-14
  CHECK(joining_distance<long double>(scale, 3, rate) == quarter);
  CHECK(joining_distance<long double>(scale, -rate, 3) == quarter);  // the sign does not matter
  CHECK(joining_distance<long double>(scale, 0, 3) == floor);  // a turning point at an end
  CHECK(quarter < fixed);
}

TEST_CASE("the march passes an end rate's zero that the fixed joining distance refused", "[seta][separatrix]") {
  // Campaign design 3281 with the campaign's six Ft (the march's steps, and so where it stalls,
  // depend on the requested targets): the long-double retry's march in arclength stalled at
  // Ft = 998.1 with the beam's joint rate theta1'(l1) about 1e-9. At the fixed joining distance
  // (2^-47 of the scale in long double) no libration reaches an end whose f3 lies below it, and
  // every step was refused, so the three targets beyond were status 6. The joining test now looks
  // no farther than a quarter of the nearer end's f3 (joining_distance). Their states are
  // confirmed by the bracketing shot in arbitrary precision with gecko's path (Fn within 5e-17,
  // validation/results/separatrix_joining_sample.json). Campaign design 2840 (joining_2840 of the
  // reference table, whose values the first test case checks): the march in Ft reached
  // Ft = 39.96 and its state was refused.
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here: no retry");
    return;
  }
  const gecko::TwoLevelSeta<double> s{48.148305992400786, 275.5524734909576, 32.39310507140628, 3745258.5838821772,
                                      1.0, 0.09388918383797486, 1.1806949938740248, 0.22773892826447034, 1.0};
  const std::vector<double> Ft{-2599.382431668891, 0.0, 941.1104576715811, 2308.615177535424, 2463.1928275896566,
                               2734.1440386245185};
  gecko::critical_line_options<double> o;
  o.ft_end = Ft.back();
  const auto line = gecko::critical_line(s, o);
  CHECK(line.points.back().Ft < 998);  // the followed line stops before the march's stall
  const auto got = gecko::critical_line_at(s, Ft);
  for (std::size_t k = 3; k < Ft.size(); ++k) {
    INFO("3281 Ft " << got[k].Ft << " status " << static_cast<int>(got[k].status));
    CHECK((got[k].status == gecko::critical_status::converged || got[k].status == gecko::critical_status::inadmissible));
  }
  const auto g2 = gecko::critical_line_at(reference_design("joining_2840"), std::vector<double>{39.95570367291479});
  INFO("2840 status " << static_cast<int>(g2[0].status));
  CHECK(g2[0].status == gecko::critical_status::converged);
}

TEST_CASE("where the limit system does not converge at the line's last node, the march starts before it",
          "[seta][separatrix]") {
  // Campaign design 9080 (back_9080 of the reference table, whose values the first test case
  // checks): the followed line ends at Ft = 63.76 (no convergence) with the beam on its
  // separatrix, and the limit system does not converge at that last node, so Ft = 66.99 was
  // status 6. The long-double retry starts the march from a node before it on the same branch
  // (gecko/seta/detail/separatrix_extend.hpp).
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) {
    WARN("long double is no wider than double here: no retry");
    return;
  }
  const auto s = reference_design("back_9080");
  gecko::critical_line_options<double> o;
  o.ft_end = 66.99401309319731;
  const auto line = gecko::critical_line(s, o);
  CHECK(line.end == gecko::line_end::no_convergence);
  CHECK(line.points.back().Ft < 64);
  const auto got = gecko::critical_line_at(s, std::vector<double>{66.99401309319731});
  INFO("status " << static_cast<int>(got[0].status));
  CHECK(got[0].status == gecko::critical_status::converged);
}

TEST_CASE("the march in arclength passes folds of the line in Ft", "[seta][separatrix]") {
  // Campaign design 3486 (arclength_fold_3486 of the reference table, whose values the first test
  // case checks): towards negative Ft the march in Ft collapsed at a fold of the line, Ft = -35.06
  // (Fn = 15.2 there); in arclength (the long-double retry) the line turns back to Ft = -24.8
  // (Fn = 313 there), folds again, and then first crosses Ft = -35.1 and -42.44, both status 6
  // before. Their states lie past the second fold, not next to the first.
  const auto s = reference_design("arclength_fold_3486");
  const auto got = gecko::critical_line_at(s, std::vector<double>{-30.0, -35.1, -42.44250662834663});
  for (const auto& st : got) {
    INFO("Ft " << st.Ft << " status " << static_cast<int>(st.status));
    REQUIRE((st.status == gecko::critical_status::converged || st.status == gecko::critical_status::inadmissible));
  }
  CHECK(got[0].Fn < 15.2);  // before the first fold, on the first branch
  CHECK(got[1].Fn > 313);
  CHECK(got[2].Fn > got[1].Fn);
}

TEST_CASE("a march that comes back over the line's start after a fold has turned back: no critical state beyond",
          "[seta][separatrix]") {
  // Campaign design 146 towards negative Ft: the march on the beam's separatrix meets a fold at
  // Ft = -131.93155 and, in arclength (the long-double retry), comes back over Ft = 0. The forces
  // beyond the fold have no critical state on the line (status 2), as beyond a followed line that
  // turns back; before this they stayed not reached (status 6). The fold is checked in arbitrary
  // precision by validation/folds.py --parabola (validation/README.md, "Targets past a
  // turned-back march"; validation/results/folds_parabola_sample.json): the line's states short of
  // it follow the square-root law, and the shot finds the partner root on their path where that
  // law puts it. Short of the fold the state is the march's in Ft. (Design 148 held this case
  // until the line's first state compressed to zero length ended it, before that fold: status 3.)
  const gecko::TwoLevelSeta<double> s{0.15977275855014858, 47.77421877194483, 4511.554739042326, 50773.842822281484,
                                      1.0, 0.008311236730929763, 0.9525727277960906, 0.5054364768402785, 1.0};
  const auto got = gecko::critical_line_at(s, std::vector<double>{-131.93, -131.94, -144.3074971951446});
  INFO("statuses " << static_cast<int>(got[0].status) << " " << static_cast<int>(got[1].status) << " "
                   << static_cast<int>(got[2].status));
  CHECK((got[0].status == gecko::critical_status::converged || got[0].status == gecko::critical_status::inadmissible));
  CHECK(got[1].status == gecko::critical_status::no_critical_state);
  CHECK(got[2].status == gecko::critical_status::no_critical_state);
  CHECK(std::isnan(got[1].Fn));
  CHECK(std::isnan(got[2].Fn));
}

TEST_CASE("a line that stopped inside what it covered after a fold goes on in arclength from where it stopped",
          "[seta][separatrix]") {
  // The followed line towards negative Ft folds, heads back towards Ft = 0 and stalls there, inside
  // the range it covered: the targets beyond its fold were status 6. The long-double retry marches
  // from the stall along the line's own tangent on the separatrix limit: design 4165's march comes
  // back over Ft = 0 (turned back: status 2 beyond its fold at Ft = -36.45), design 5337's folds
  // again and first crosses its target beyond the reach (solved). validation/README.md, "Lines
  // stopped inside what they covered" (validation/results/folds_parabola_inside.json: 4165's fold
  // confirmed in arbitrary precision). Design 3681 held the first case until its line's first
  // state compressed to zero length ended it (status 3).
  const gecko::TwoLevelSeta<double> back{0.1693707417976444, 2.8705002184822246, 102991.50250920083, 908725.7286198998,
                                         1.0, 0.6226536725921479, 0.04239728296999268, 1.2450321716546784, 1.0};
  const auto b = gecko::critical_line_at(back, std::vector<double>{-519.0255191611686, 0.0, 411.3077377948683});
  CHECK(b[0].status == gecko::critical_status::no_critical_state);
  CHECK(b[1].status == gecko::critical_status::converged);
  CHECK(b[2].status == gecko::critical_status::converged);
  const gecko::TwoLevelSeta<double> again{0.18077370510251417, 8.717498902956999, 60597545.05091903,
                                          1021098.9831846402, 1.0, 0.028367338862926743, 1.243719999639823,
                                          0.2886957547132285, 1.0};
  const auto a = gecko::critical_line_at(again, std::vector<double>{-848.8259027544344, 0.0});
  INFO("status " << static_cast<int>(a[0].status) << " Fn " << a[0].Fn);
  CHECK((a[0].status == gecko::critical_status::converged || a[0].status == gecko::critical_status::inadmissible));
  CHECK(a[1].status == gecko::critical_status::converged);
}

TEST_CASE("no design derivatives where the state does not resolve its separatrix distance", "[seta][separatrix]") {
  const auto s = design_27();
  const auto d = gecko::sensitivities(s, std::vector<double>{100.0, 1000.0});
  REQUIRE(d[0].state.status == gecko::critical_status::converged);
  REQUIRE(d[1].state.status == gecko::critical_status::converged);
  for (int j = 0; j < 9; ++j) {
    if (j == 2) continue;  // EA1 = infinity: 0 by definition
    CHECK(std::isfinite(d[0].dFn[static_cast<std::size_t>(j)]));
    CHECK(std::isnan(d[1].dFn[static_cast<std::size_t>(j)]));
  }
}

TEST_CASE("a smaller limit system's state is refused where a measured segment is unresolved", "[seta][separatrix]") {
  // separatrix_target_state tries the limit system with a subset of the limit segments, the others
  // measured by their own length equations. Such a state is kept only where each measured segment
  // resolves its separatrix distance and, if it was a limit segment, keeps the line's turning
  // points within one. Injected at design 27's recovered states: Ft = 1000 (a segment beyond what
  // its digits resolve), Ft = 150 (both resolved).
  const auto s = design_27();
  using System = gecko::detail::seta_system<double, gecko::policies::default_policy, false, true>;
  const System sys(gecko::detail::make_seta_params(s));
  const int beam = gecko::detail::limit_beam, spatula = gecko::detail::limit_spatula, both = beam | spatula;
  const int bits[2] = {beam, spatula};
  const auto got = gecko::critical_line_at(s, std::vector<double>{150.0, 1000.0});
  for (const auto& st : got) {
    REQUIRE(st.status == gecko::critical_status::converged);
    const double mu = sys.mu_of(st.Ft);
    const auto z = sys.from_guess(st.Fn, st.theta_joint, st.theta_rate_joint, st.theta_rate_base, st.Ft);
    double lengths[2], gaps[2];
    gecko::detail::separatrix_measures(sys, z, mu, lengths, gaps);
    const int turning[2] = {st.turning_points_beam, st.turning_points_spatula};
    INFO("Ft " << st.Ft << " elastic lengths " << lengths[0] << ", " << lengths[1] << " gaps " << gaps[0] << ", "
               << gaps[1]);
    int unresolved = 0;
    for (int i = 0; i < 2; ++i) {
      const bool u = gecko::detail::separatrix_unresolved(lengths, gaps, i);
      unresolved += u;
      // Measured by its own length equation (the other segment in the limit): refused exactly
      // where unresolved.
      CHECK(gecko::detail::measured_segments_resolved(sys, z, mu, both & ~bits[i], both, turning, turning) == !u);
    }
    // Both in the limit: nothing is measured by a length equation.
    CHECK(gecko::detail::measured_segments_resolved(sys, z, mu, both, both, turning, turning));
    if (st.Ft == 1000.0) {
      CHECK(unresolved >= 1);
      continue;
    }
    CHECK(unresolved == 0);
    // Resolved, but the measured segment's turning points two away from the line's: another path.
    for (int i = 0; i < 2; ++i) {
      int one[2] = {turning[0], turning[1]}, two[2] = {turning[0], turning[1]};
      one[i] += 1;
      two[i] += 2;
      CHECK(gecko::detail::measured_segments_resolved(sys, z, mu, both & ~bits[i], both, one, turning));
      CHECK_FALSE(gecko::detail::measured_segments_resolved(sys, z, mu, both & ~bits[i], both, two, turning));
      // A segment that was never a limit segment keeps whatever turning points the line gives it.
      CHECK(gecko::detail::measured_segments_resolved(sys, z, mu, both & ~bits[i], both & ~bits[i], two, turning));
    }
  }
}
