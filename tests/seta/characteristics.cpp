// Tests of gecko/seta/characteristics.hpp against the per-design characteristics of the
// reference generator (tests/data/seta_reference_designs.csv, mpmath, 25 digits), a max-pull-off
// regression (tests/data/seta_min_regression.csv, mpmath) and 200 random designs against a dense
// sample of the line refined independently (run time ~2 s Release).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/sensitivities.hpp"
#include "seta/csv_table.hpp"
#include "seta/random_designs.hpp"
#include "solved.hpp"

using gecko_test::design_of;
using gecko_test::parse;
using gecko_test::split_csv_line;

TEST_CASE("characteristics match the reference designs", "[seta][characteristics][reference]") {
  const auto t = gecko_test::read_csv_table(std::string(GECKO_TEST_DATA_DIR) + "/seta_reference_designs.csv");
  REQUIRE(!t.rows.empty());
  auto col = [&](const char* name) { return t.col(name); };
  int designs = 0, sticky = 0;
  for (const auto& r : t.rows) {
    const gecko::TwoLevelSeta<double> s = design_of(t, r);
    gecko::critical_line_options<double> opt;
    opt.ft_end = parse(r[col("F_scale")]);
    const auto c = gecko::characteristics(s, opt);
    INFO("design " << r[0] << " end " << static_cast<int>(c.end));
    ++designs;
    const double fn0 = parse(r[col("Fn0")]);
    CHECK(std::fabs(c.fn0 - fn0) <= 1e-11 * std::max(1.0, std::fabs(fn0)));
    CHECK(c.sticky_at_rest == (r[col("sticky_at_rest")] == "1"));
    sticky += c.sticky_at_rest;
    const std::string kind = r[col("min_kind")];
    const double min_fn = parse(r[col("min_Fn")]), ft_min = parse(r[col("Ft_at_min")]);
    if (kind == "interior") {
      CHECK(c.min_fn_interior);
      CHECK(c.min_status == gecko::minimum_status::stationary);
      // The value at a minimum is insensitive to its location: full accuracy.
      CHECK(std::fabs(c.min_fn - min_fn) <= 1e-11 * std::max(1.0, std::fabs(min_fn)));
      CHECK(std::fabs(c.ft_at_min_fn - ft_min) <= 1e-6 * std::max(1.0, std::fabs(ft_min)));
      CHECK(c.max_pull_off == Approx(std::max(0.0, -min_fn)).epsilon(1e-11));
    }
    if (kind == "range_end") {  // at the end of the requested range (EA2 = inf): Fn there
      CHECK(c.min_status == gecko::minimum_status::range_end);
      CHECK_FALSE(c.min_fn_interior);
      CHECK(c.ft_at_min_fn == Approx(ft_min).epsilon(1e-15));
      CHECK(std::fabs(c.min_fn - min_fn) <= 1e-11 * std::max(1.0, std::fabs(min_fn)));
    }
    if (std::isfinite(s.EA2)) {
      CHECK(c.end == gecko::line_end::reached_ft_max);
      CHECK(c.ft_max == Approx(parse(r[col("Ft_max")])).epsilon(1e-15));
      // At (Ft)max the line has a vertical tangent (Fn ~ sqrt((Ft)max - Ft)): Fn there is only
      // as good as the square root of the rounding of Ft near the end.
      CHECK(std::fabs(c.fn_at_line_end - parse(r[col("Fn_at_Ftmax")])) <= 1e-6);
    }
    CHECK(static_cast<int>(c.folds.size()) == static_cast<int>(parse(r[col("n_folds")])));
  }
  CHECK(designs >= 31);
  CHECK(sticky >= 10);
}

TEST_CASE("small-deformation formulas at the reference scene", "[seta][characteristics]") {
  const gecko::TwoLevelSeta<double> s;
  const auto c = gecko::characteristics(s);
  // docs/theory/two_level_seta.md: the linear theory gives (Fn)0 ~ 0.34 against the exact ~0.25.
  CHECK(c.small.fn0 == Approx(0.3397).margin(2e-3));
  CHECK(c.fn0 == Approx(0.24990379377720597).epsilon(1e-13));
  CHECK(c.small.non_sticky);
  CHECK_FALSE(c.sticky_at_rest);
  // Both slopes are negative (shear makes the seta stick) and of the same size.
  CHECK(c.slope_k < 0);
  CHECK(c.small.slope_k < 0);
  CHECK(c.slope_k == Approx(c.small.slope_k).epsilon(0.5));
  CHECK(c.max_pull_off == Approx(2.8024125576053010746).epsilon(1e-12));
  CHECK(c.ft_at_min_fn == Approx(7.123205952979077).epsilon(1e-7));
}

// ---------------------------------------------------------------------------------------------
// The max pull-off is the true minimum of Fn along the line.
//
// Regression: for this design characteristics() returned the traced node Fn = -6.589516 at
// Ft = 9.62 (dFn/dFt = 0.016 there) instead of the minimum -6.591953 at Ft = 9.31: the beam's
// turning point leaves and re-enters the segment between the nodes around the minimum, the
// refinement used the middle node's Carlson plan across the whole bracket, failed at its first
// evaluation and silently kept the node. Reference: tests/data/seta_min_regression.csv (mpmath,
// ODE route, independent of the C++ forms; gen_seta_min_regression.py), good to ~1e-25.

namespace {

gecko::TwoLevelSeta<double> turning_point_design() {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 16.248074011412644; s.EI2 = 2.073266411055929; s.EA2 = 158.40954057083513;
  s.l2 = 0.2956123183806999; s.alpha1 = 0.9518127924448841; s.alpha2 = 0.5104088538263943;
  return s;
}

// dFn/dFt at a converged state on the line from the exact design sensitivities (an independent
// route to the slope: the equations are homogeneous in force units, so by Euler's theorem
// Ft dFn/dFt = Fn - sum over EI1, EI2, EA1, EA2, w of p dFn/dp).
double euler_slope(const gecko::TwoLevelSeta<double>& s, double ft, double& fn, gecko::critical_status& st) {
  const auto sens = gecko::sensitivities(s, std::vector<double>{ft});
  st = sens[0].state.status;
  fn = sens[0].state.Fn;
  const double p[9] = {s.EI1, s.EI2, s.EA1, s.EA2, s.l1, s.l2, s.alpha1, s.alpha2, s.w};
  double acc = fn;
  for (int j : {0, 1, 2, 3, 8})
    if (std::isfinite(p[j])) acc -= p[j] * sens[0].dFn[static_cast<std::size_t>(j)];
  return acc / ft;
}

// Minimum of Fn(Ft) on [a, b] from Fn values only (Brent's golden-section + parabolic search),
// each Fn a Newton solve from the guess of a nearby dense state: independent of the continuation
// and of characteristics(). Returns false if a solve fails.
bool brent_min_fn(const gecko::TwoLevelSeta<double>& s, double a, double b, const gecko::critical_state<double>& near,
                  double& ft_min, double& fn_min) {
  gecko::critical_guess<double> g{near.Fn, near.theta_joint, near.theta_rate_joint, near.theta_rate_base};
  bool ok = true;
  auto f = [&](double ft) {
    gecko::solve_options<double> o;
    o.tolerance = 1e-13;
    const auto r = gecko::solve_critical(s, ft, g, o);
    if (!seta_test::solved(r.status)) {
      ok = false;
      return std::numeric_limits<double>::infinity();
    }
    return r.Fn;
  };
  const double cg = 0.3819660112501051;
  double x = a + cg * (b - a), w = x, v = x, fx = f(x), fw = fx, fv = fx, d = 0, e = 0;
  for (int it = 0; it < 200 && ok; ++it) {
    const double m = (a + b) / 2, tol = 1e-9 * std::fabs(x) + 1e-12, t2 = 2 * tol;
    if (std::fabs(x - m) <= t2 - (b - a) / 2) break;
    double u;
    bool golden = true;
    if (std::fabs(e) > tol) {
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), pp = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) pp = -pp;
      q = std::fabs(q);
      if (std::fabs(pp) < std::fabs(0.5 * q * e) && pp > q * (a - x) && pp < q * (b - x)) {
        e = d;
        d = pp / q;
        golden = false;
      }
    }
    if (golden) {
      e = (x < m ? b : a) - x;
      d = cg * e;
    }
    u = x + (std::fabs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w; fv = fw; w = x; fw = fx; x = u; fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) { v = w; fv = fw; w = u; fw = fu; }
      else if (fu <= fv || v == x || v == w) { v = u; fv = fu; }
    }
  }
  ft_min = x;
  fn_min = fx;
  return ok;
}

}  // namespace

TEST_CASE("max pull-off where the turning points change inside the bracket", "[seta][characteristics][regression]") {
  std::ifstream in(std::string(GECKO_TEST_DATA_DIR) + "/seta_min_regression.csv");
  std::string line;
  REQUIRE(std::getline(in, line));
  REQUIRE(std::getline(in, line));
  const auto r = split_csv_line(line);
  const auto s = turning_point_design();
  REQUIRE(parse(r[1]) == s.EI1);
  REQUIRE(parse(r[6]) == s.l2);
  const double ref_fn = parse(r[10]), ref_ft = parse(r[11]);
  const auto c = gecko::characteristics(s);
  INFO("min_fn " << c.min_fn << " at Ft " << c.ft_at_min_fn << " status " << static_cast<int>(c.min_status));
  REQUIRE(c.end == gecko::line_end::reached_ft_max);
  REQUIRE(c.min_status == gecko::minimum_status::stationary);
  CHECK(c.min_fn_interior);
  // Measured: 1.4e-16 relative; the bound allows for the states' solve accuracy (a scaled Newton
  // step of 1e-13 on the refinement's states).
  CHECK(std::fabs(c.min_fn - ref_fn) <= 1e-13 * std::fabs(ref_fn));
  CHECK(c.max_pull_off == -c.min_fn);
  // The minimiser is located to ~(state accuracy) / Fn'': measured 7e-13 absolute.
  CHECK(std::fabs(c.ft_at_min_fn - ref_ft) <= 1e-9 * ref_ft);
  // The slope there, by characteristics itself and by the Euler identity.
  CHECK(std::fabs(c.slope_at_min_fn) <= 1e-10);
  double fn;
  gecko::critical_status st;
  const double slope = euler_slope(s, c.ft_at_min_fn, fn, st);
  REQUIRE(seta_test::solved(st));
  CHECK(std::fabs(slope) <= 1e-10);
  CHECK(std::fabs(fn - c.min_fn) <= 1e-13 * std::fabs(fn));
}

TEST_CASE("max pull-off against a dense sample of the line, random designs", "[seta][characteristics][random]") {
  // 200 designs: EI1 in [1, 20], EI2 in [0.1, 5] (log-uniform), EA2 in [50, 500], l2 in
  // [0.05, 0.5], alpha1 in [0.3, 1.2], alpha2 in [0.05, min(1, pi/2 - alpha1 - 0.05)];
  // EA1 = inf, l1 = w = 1. Each line is sampled at 2001 Ft in [0, (Ft)max] (critical_line_at,
  // the first crossing) and the sample's minimum refined by Brent on Fn(Ft) values.
  std::uint64_t rng = 20261121;
  const int designs = 200, samples = 2000;
  int interior = 0, checked_two_sided = 0, turning = 0, incomplete = 0;
  double worst_gap = 0, worst_slope = 0;
  for (int k = 0; k < designs; ++k) {
    const auto s = seta_test::sweep_box_design(rng);
    const auto c = gecko::characteristics(s);
    INFO("design " << k << ": EI1 " << s.EI1 << " EI2 " << s.EI2 << " EA2 " << s.EA2 << " l2 " << s.l2
         << " alpha1 " << s.alpha1 << " alpha2 " << s.alpha2 << "; min_fn " << c.min_fn << " at Ft "
         << c.ft_at_min_fn << " status " << static_cast<int>(c.min_status) << " end " << static_cast<int>(c.end));
    REQUIRE(c.min_status != gecko::minimum_status::not_certified);
    // The default range ends at (Ft)max; the trace may label reaching it either way (the two
    // roundings of (Ft)max, sqrt(2 EA2 w) and sqrt(2 w / (1/EA2)), can differ by an ulp).
    const bool complete = c.end == gecko::line_end::reached_ft_max ||
                          (c.end == gecko::line_end::reached_ft_end && c.ft_at_line_end >= c.ft_max * (1 - 1e-12));
    if (!complete) {
      CHECK(c.min_status == gecko::minimum_status::line_incomplete);
      ++incomplete;
      continue;
    }
    std::vector<double> ft(samples + 1);
    for (int j = 0; j <= samples; ++j) ft[static_cast<std::size_t>(j)] = c.ft_max * (static_cast<double>(j) / samples);
    const auto dense = gecko::critical_line_at(s, ft);
    std::size_t jmin = 0;
    bool all = true;
    // The max pull-off is taken over the admissible part of the line (up to admissible_end_ft):
    // the dense sample's minimum over the admissible states before it.
    const double adm_end = c.admissible_to_end ? c.ft_max : c.admissible_end_ft;
    for (std::size_t j = 0; j < dense.size(); ++j) {
      all = all && seta_test::solved(dense[j].status);
      turning += seta_test::solved(dense[j].status) &&
                 dense[j].turning_points_beam + dense[j].turning_points_spatula > 0 &&
                 j + 1 < dense.size() &&
                 dense[j + 1].turning_points_beam + dense[j + 1].turning_points_spatula !=
                     dense[j].turning_points_beam + dense[j].turning_points_spatula;
      if (dense[j].status == gecko::critical_status::converged && ft[j] <= adm_end && dense[j].Fn < dense[jmin].Fn)
        jmin = j;
    }
    double ref = dense[jmin].Fn;
    if (!c.admissible_to_end && c.admissible_end_fn < ref) ref = c.admissible_end_fn;
    if (jmin > 0 && jmin + 1 < dense.size() && ft[jmin + 1] <= adm_end) {
      double ft_b = 0, fn_b = 0;
      REQUIRE(brent_min_fn(s, ft[jmin - 1], ft[jmin + 1], dense[jmin], ft_b, fn_b));
      ref = std::min(ref, fn_b);
    }
    const double tol = 1e-10 * std::max(1.0, std::fabs(ref));
    // Never less pull-off than any state of the line found independently ...
    CHECK(c.min_fn <= ref + tol);
    worst_gap = std::max(worst_gap, (c.min_fn - ref) / std::max(1.0, std::fabs(ref)));
    // ... and, where the dense sample covers the whole line (no fold), not more either.
    if (all && c.folds.empty()) {
      CHECK(c.min_fn >= ref - tol);
      ++checked_two_sided;
    }
    if (c.min_status == gecko::minimum_status::stationary) {
      ++interior;
      double fn;
      gecko::critical_status st;
      const double slope = euler_slope(s, c.ft_at_min_fn, fn, st);
      REQUIRE(seta_test::solved(st));
      CHECK(std::fabs(fn - c.min_fn) <= 1e-12 * std::max(1.0, std::fabs(fn)));
      // A stationary point: |dFn/dFt| far below the slopes of the line (O(1)).
      CHECK(std::fabs(slope) <= 1e-9 * std::max(1.0, std::fabs(fn)) / c.ft_at_min_fn);
      CHECK(std::fabs(c.slope_at_min_fn) <= 1e-9 * std::max(1.0, std::fabs(fn)) / c.ft_at_min_fn);
      worst_slope = std::max(worst_slope, std::fabs(slope) * c.ft_at_min_fn / std::max(1.0, std::fabs(fn)));
    } else if (c.min_status == gecko::minimum_status::range_start) {
      CHECK(c.ft_at_min_fn == 0);
      CHECK(c.slope_at_min_fn >= 0);
    } else if (c.min_status == gecko::minimum_status::admissible_end) {
      CHECK(c.ft_at_min_fn == c.admissible_end_ft);
    } else {
      CHECK(c.min_status == gecko::minimum_status::range_end);
      CHECK(c.ft_at_min_fn == c.ft_at_line_end);
    }
  }
  WARN("lines not followed to (Ft)max " << incomplete << ", interior minima " << interior << "/" << designs << ", two-sided checks " << checked_two_sided
       << ", turning-point changes in the samples " << turning << ", worst (min_fn - dense)/max(1,|Fn|) "
       << worst_gap << ", worst |Ft dFn/dFt|/max(1,|Fn|) " << worst_slope);
  CHECK(interior >= designs / 2);
  CHECK(turning > 0);
}
