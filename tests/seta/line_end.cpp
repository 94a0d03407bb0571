// Tests of the end of the critical line (gecko/seta/critical_line.hpp, the landing of
// gecko/seta/detail/continuation.hpp's follow_line on the end of its range) and of the line at
// Ft near and at (Ft)max = sqrt(2 EA2 w) (docs/theory/two_level_seta.md: the line ends there, with Fn - Fn_end
// proportional to sqrt((Ft)max - Ft)).
//
// Regressions (all found by the design optimiser's sweeps):
//  * lines that reach (Ft)max but ended with line_end::no_convergence and a flat Fn at the end
//    (10% of random designs): the landing Newton at the end demanded a scaled step of 1e-13,
//    below its rounding floor there, so every landing failed and the line crawled into the end;
//  * critical_line_at(Ft) with status 2 (later 6) just below (Ft)max, the same failure at the
//    requested end;
//  * (Ft)max's two roundings (sqrt(2 EA2 w) and sqrt(2 w / (1/EA2)) differ by an ulp in ~7% of
//    designs): the default line stopped ~1e-7 short of its end in the line parameter, labelled
//    "reached the requested end"; or Ft = ft_max(seta) had no critical state.
// Reference values: tests/data/seta_line_end.csv (mpmath, ODE route, gen_seta_line_end.py).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gecko/seta/characteristics.hpp"
#include "seta/random_designs.hpp"
#include "solved.hpp"

namespace {

struct end_case {
  gecko::TwoLevelSeta<double> seta;
  std::vector<std::pair<std::string, double>> fn;  // (Ft as written, or "ft_max"; Fn)
};

std::map<std::string, end_case> read_cases() {
  std::ifstream in(std::string(GECKO_TEST_DATA_DIR) + "/seta_line_end.csv");
  std::map<std::string, end_case> cases;
  std::string line;
  if (!std::getline(in, line)) return cases;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) c.push_back(cell);
    if (c.size() != 12) continue;
    auto num = [](const std::string& s) {
      return s == "inf" ? std::numeric_limits<double>::infinity() : std::stod(s);
    };
    auto& e = cases[c[0]];
    e.seta.EI1 = num(c[1]); e.seta.EI2 = num(c[2]); e.seta.EA1 = num(c[3]); e.seta.EA2 = num(c[4]);
    e.seta.l1 = num(c[5]); e.seta.l2 = num(c[6]); e.seta.alpha1 = num(c[7]); e.seta.alpha2 = num(c[8]);
    e.seta.w = num(c[9]);
    e.fn.emplace_back(c[10], std::stod(c[11]));
  }
  return cases;
}

}  // namespace

TEST_CASE("lines that reach (Ft)max end there, at the reference state", "[seta][line_end][regression]") {
  const auto cases = read_cases();
  REQUIRE(cases.size() == 6);
  for (const auto& [name, e] : cases) {
    const auto& s = e.seta;
    const double fm = gecko::ft_max(s);
    const auto line = gecko::critical_line(s);
    const auto c = gecko::characteristics(s);
    INFO(name << ": end " << static_cast<int>(line.end) << " after " << line.points.size() << " nodes, last Ft "
              << line.points.back().Ft << " of " << fm);
    CHECK(line.end == gecko::line_end::reached_ft_max);
    CHECK(std::fabs(line.points.back().Ft - fm) <= 4 * std::numeric_limits<double>::epsilon() * fm);
    CHECK(c.end == gecko::line_end::reached_ft_max);
    CHECK(c.min_status != gecko::minimum_status::line_incomplete);
    CHECK(c.min_status != gecko::minimum_status::not_certified);
    std::vector<double> ft;
    for (const auto& [t, fn] : e.fn) ft.push_back(t == "ft_max" ? fm : std::stod(t));
    const auto all = gecko::critical_line_at(s, ft);
    for (std::size_t k = 0; k < ft.size(); ++k) {
      // Each target alone too: then it is the requested end of the traced range.
      const auto alone = gecko::critical_line_at(s, std::vector<double>{ft[k]});
      CHECK(alone[0].status == all[k].status);
      CHECK(alone[0].Fn == Approx(all[k].Fn).margin(1e-10));
      const auto& at = alone;
      const double ref = e.fn[k].second;
      INFO("Ft " << e.fn[k].first << " = " << ft[k] << ": status " << static_cast<int>(at[0].status) << " Fn "
                 << at[0].Fn << " reference " << ref);
      CHECK(seta_test::solved(at[0].status));
      if (!seta_test::solved(at[0].status)) continue;
      if (e.fn[k].first == "ft_max") {
        // The line's end (its parameter's end, as critical_line and characteristics report it)
        // is the reference state; critical_line_at(ft_max(seta)) takes Ft literally, and where
        // ft_max = sqrt(2 EA2 w) lies an ulp below the System's sqrt(2 w / (1/EA2)) it is a state
        // an ulp of Ft before the end, ~1e-7 away in Fn (Fn ~ sqrt((Ft)max - Ft)).
        const bool same_rounding = std::sqrt(2 * s.w / (1 / s.EA2)) <= fm;
        // At the end the Newton step has a rounding floor of ~1e-10 (the spatula's turning
        // point sits on the contact edge, where rounding enters the residual as sqrt(eps));
        // the end is the line's end in its parameter, not Ft rounded (Fn ~ sqrt((Ft)max - Ft)
        // would make an ulp of Ft worth 1e-7). Measured: at most 1.1e-10 (sqrt_eps_floor).
        CHECK(std::fabs(at[0].Fn - ref) <= (same_rounding ? 1e-9 : 1e-6));
        CHECK(std::fabs(line.points.back().Fn - ref) <= 1e-9);
        CHECK(std::fabs(c.fn_at_line_end - ref) <= 1e-9);
      } else {
        // An exact double Ft below the end: full accuracy (measured 5e-13).
        CHECK(std::fabs(at[0].Fn - ref) <= 1e-11 * std::max(1.0, std::fabs(ref)));
      }
    }
  }
}

TEST_CASE("the line reaches (Ft)max for random designs, and is solved there", "[seta][line_end][random]") {
  // The box of the design optimiser's sweeps (as tests/seta/characteristics.cpp, another seed):
  // EI1 in [1, 20], EI2 in [0.1, 5] (log-uniform), EA2 in [50, 500], l2 in [0.05, 0.5], alpha1
  // in [0.3, 1.2], alpha2 in [0.05, min(1, pi/2 - alpha1 - 0.05)]. Before the fix 10% of such
  // lines ended in no_convergence and 3.6% as reached_ft_end, and critical_line_at(ft_max)
  // failed for 13%.
  std::uint64_t rng = 7;
  int n = 0;
  for (int k = 0; k < 200; ++k) {
    const auto s = seta_test::sweep_box_design(rng);
    const double fm = gecko::ft_max(s);
    const auto line = gecko::critical_line(s);
    INFO("design " << k << ": EI1 " << s.EI1 << " EI2 " << s.EI2 << " EA2 " << s.EA2 << " l2 " << s.l2 << " alpha1 "
                   << s.alpha1 << " alpha2 " << s.alpha2 << "; end " << static_cast<int>(line.end) << " at Ft "
                   << line.points.back().Ft);
    CHECK(line.end == gecko::line_end::reached_ft_max);
    // The same end, asked for explicitly.
    gecko::critical_line_options<double> opt;
    opt.ft_end = fm;
    CHECK(gecko::critical_line(s, opt).end == gecko::line_end::reached_ft_max);
    const auto at = gecko::critical_line_at(s, std::vector<double>{fm * (1 - 1e-6), fm});
    CHECK(seta_test::solved(at[0].status));
    CHECK(seta_test::solved(at[1].status));
    // The landed end node and this state: the same line parameter, unless ft_max lies an ulp
    // below the System's (Ft)max (then an ulp of Ft before the end, see above).
    const bool same_rounding = std::sqrt(2 * s.w / (1 / s.EA2)) <= fm;
    if (seta_test::solved(at[1].status))
      CHECK(std::fabs(at[1].Fn - line.points.back().Fn) <= (same_rounding ? 1e-9 : 1e-6));
    n += line.end == gecko::line_end::reached_ft_max;
  }
  WARN(n << " of 200 lines reached (Ft)max");
  CHECK(n == 200);
}

// A line that runs into the edge of the model's forms: followed towards negative Ft, the beam's
// compression grows until f4 = 1 + b4 u of its first integral (paper 001 eq (8), c N^2 u^2/2 in
// R) vanishes at u = -1 (b4 = 1, an axial load comparable to EA1). Past that the forms do not
// exist, the corrector's plan evaluates to NaN at every predictor, and the step collapsed: the
// line ended as no_convergence and its states beyond as not_reached (status 6, "unknown").
// The continuation (detail::follow_line) ends it as unsupported_state at that edge. Before the
// edge, the stretch 1 + T/EA1 of the beam passes zero (it vanishes at u = -1/(c N), f4's root lies
// at u = -(1 + sqrt(1 + 2 c M))/(c N)), and the critical line now ends there, at its first node
// compressed to zero length (line_trace.hpp's end_at_inverted_state): the targets beyond are
// unsupported (status 3) all the same. Design 982 of the stress campaign
// (validation/data/stress_10000_states.npz).
TEST_CASE("a line that reaches the edge of the forms ends as unsupported, not as a failure",
          "[seta][line_end][regression]") {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 0x1.d18b126d6817cp+1;
  s.EI2 = 0x1.9c904de46d0ddp-7;
  s.EA1 = 0x1.541473f9e15adp+4;
  s.EA2 = 0x1.9735c8b3f3a1fp+21;
  s.l1 = 1;
  s.l2 = 0x1.7c097c9b3b924p-5;
  s.alpha1 = 0x1.9ade7b9964e08p-1;
  s.alpha2 = 0x1.648694b7485b6p-1;
  s.w = 1;
  const double Ft = -0x1.9bb0923a6fbd9p+10;
  // b4 = c N / (1 + sqrt(1 + 2 c M1)) with c = 1/EA1 at a state; the beam's M1 follows from the
  // base (R1 = EI1 theta1'(0)^2 / 2 = M1 - N u0 - c N^2 u0^2 / 2, u0 = sin(alpha1 - phi)).
  auto b4_of = [&](double Fn, double Fta, double rate_base) {
    const double N = std::hypot(Fn, Fta), c = 1 / s.EA1;
    const double u0 = std::sin(s.alpha1 - std::atan2(Fn, Fta));
    const double M1 = s.EI1 * rate_base * rate_base / 2 + N * u0 + c * N * N * u0 * u0 / 2;
    return c * N / (1 + std::sqrt(1 + 2 * c * M1));
  };
  {  // The continuation alone, from the natural state, runs on to the edge of the forms.
    using System = gecko::detail::seta_system<double, gecko::policies::default_policy, true, true>;
    const System sys(gecko::detail::make_seta_params(s));
    System::vec z0;
    System::plan_type plan0;
    gecko::critical_state<double> natural;
    REQUIRE(gecko::detail::start_line(sys, z0, plan0, natural));
    gecko::detail::continuation_options<double> copt;
    copt.ft_max = sys.mu_limit();
    copt.ft_stop = gecko::detail::line_parameter(sys, Ft);
    copt.scale = std::max(std::fabs(Ft), std::sqrt(s.EI1 * s.w) / s.l1);
    copt.tolerance = 1e-10;
    const auto raw = gecko::detail::follow_line(sys, z0, 0.0, plan0, -1, copt);
    CHECK(raw.end == gecko::line_end::unsupported_state);
    REQUIRE(!raw.nodes.empty());
    const auto& e = raw.nodes.back();
    const double b4 = b4_of(e.z[0], sys.ft_of(e.Ft), sys.rate_base(e.z));
    INFO("last raw node Ft " << sys.ft_of(e.Ft) << " b4 " << b4);
    CHECK(std::fabs(b4 - 1) < 1e-3);
  }
  gecko::critical_line_options<double> opt;
  opt.ft_end = Ft;
  const auto line = gecko::critical_line(s, opt);
  CHECK(line.end == gecko::line_end::unsupported_state);
  REQUIRE(line.points.size() >= 2);
  const auto& last = line.points.back();
  // Re-solved (the seta crosses the substrate there: inadmissible, a solved state all the same),
  // compressed to zero length, the node before it not; short of the edge of the forms.
  CHECK(last.status == gecko::critical_status::inadmissible);
  CHECK(last.min_stretch <= 0);
  CHECK(line.points[line.points.size() - 2].min_stretch > 0);
  const double b4 = b4_of(last.Fn, last.Ft, last.theta_rate_base);
  INFO("last node Ft " << last.Ft << " b4 " << b4);
  CHECK(b4 < 1);
  const auto at = gecko::critical_line_at(s, std::vector<double>{Ft});
  CHECK(at[0].status == gecko::critical_status::unsupported_state);
}
