// Tests of the admissible part of the line, the bound of an unbounded maximum and the paper's k in
// gecko/seta/characteristics.hpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/characteristics.hpp"
#include "gecko/seta/characteristics_batch.hpp"

namespace {
gecko::critical_state<double> at(const gecko::TwoLevelSeta<double>& s, double ft) {
  return gecko::critical_line_at(s, std::vector<double>{ft})[0];
}
}  // namespace

TEST_CASE("the admissible part of the line ends where the seta first crosses the substrate",
          "[seta][characteristics][admissibility]") {
  for (double a2 : {0.5235987755982988, 1.0}) {
    gecko::TwoLevelSeta<double> s;
    s.alpha2 = a2;
    const auto c = gecko::characteristics(s);
    INFO("alpha2 " << a2 << " admissible end " << c.admissible_end_ft);
    REQUIRE_FALSE(c.admissible_to_end);
    REQUIRE(c.admissible_end_ft > 9.5);
    REQUIRE(c.admissible_end_ft < gecko::ft_max(s));
    // admissible just before, not just after (the boundary is refined to ~1e-10 of the arclength)
    CHECK(at(s, c.admissible_end_ft - 1e-6).status == gecko::critical_status::converged);
    CHECK(at(s, c.admissible_end_ft + 1e-6).status == gecko::critical_status::inadmissible);
    CHECK(std::fabs(at(s, c.admissible_end_ft).Fn - c.admissible_end_fn) < 1e-8);
    // the max pull-off is an interior stationary minimum, inside the admissible part
    CHECK(c.min_status == gecko::minimum_status::stationary);
    CHECK(c.ft_at_min_fn < c.admissible_end_ft);
  }
  gecko::TwoLevelSeta<double> s;
  const auto c = gecko::characteristics(s);
  CHECK(c.max_pull_off == Approx(2.8024125).margin(1e-6));
  // The batch carries the same values, bitwise.
  const auto b = gecko::characteristics_to_depth(s, gecko::characteristics_depth::whole_line);
  CHECK(b.admissible_end_ft == c.admissible_end_ft);
  CHECK(b.paper_k == c.paper_k);
}

TEST_CASE("a strain limit moves the admissible end and the max pull-off with it", "[seta][characteristics][admissibility]") {
  gecko::TwoLevelSeta<double> s;
  gecko::critical_line_options<double> o;
  o.strain_limit = 0.1;  // T = Ft at the edge: Ft <= 5 on the reference spatula (EA2 = 50)
  const auto c = gecko::characteristics(s, o);
  REQUIRE_FALSE(c.admissible_to_end);
  CHECK(c.admissible_end_ft <= 5.0 + 1e-9);
  CHECK(c.admissible_end_ft > 4.0);
  CHECK(c.min_status == gecko::minimum_status::admissible_end);
  CHECK(c.min_fn == c.admissible_end_fn);
  CHECK(c.max_pull_off == -c.admissible_end_fn);
}

TEST_CASE("a maximum at the end of an arbitrary followed range is a bound, flagged",
          "[seta][characteristics][unbounded]") {
  gecko::TwoLevelSeta<double> s;
  s.EA2 = std::numeric_limits<double>::infinity();  // no (Ft)max: the line keeps falling
  const auto c = gecko::characteristics(s);
  CHECK(c.min_status == gecko::minimum_status::range_end);
  CHECK(std::isnan(c.max_pull_off));
  CHECK(c.max_pull_off_is_bound);
  CHECK(c.max_pull_off_bound == -c.min_fn);
  s.EA2 = 1e300;
  const auto d = gecko::characteristics(s);
  CHECK(std::isnan(d.max_pull_off));
  CHECK(d.max_pull_off_is_bound);
  const auto b = gecko::characteristics_to_depth(s, gecko::characteristics_depth::whole_line);
  CHECK(std::isnan(b.max_pull_off));
}

TEST_CASE("the paper's k: least-squares slope through (Fn)0 over the lower part", "[seta][characteristics][k]") {
  gecko::TwoLevelSeta<double> s;
  const auto c = gecko::characteristics(s);
  CHECK(c.slope_k == c.slope_at_zero);
  // Independent: composite Simpson on 2001 states of critical_line_at.
  const int n = 2000;
  std::vector<double> ft(n + 1);
  for (int i = 0; i <= n; ++i) ft[static_cast<std::size_t>(i)] = c.ft_at_min_fn * i / n;
  const auto st = gecko::critical_line_at(s, ft);
  double num = 0;
  for (int i = 0; i <= n; ++i) {
    const auto& x = st[static_cast<std::size_t>(i)];
    REQUIRE(x.status == gecko::critical_status::converged);
    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    num += w * x.Ft * (x.Fn - c.fn0);
  }
  num *= c.ft_at_min_fn / n / 3;
  const double k = num / (c.ft_at_min_fn * c.ft_at_min_fn * c.ft_at_min_fn / 3);
  CHECK(c.paper_k == Approx(k).margin(1e-9));
  // The lower part is not straight: the tangent at 0 is steeper than the fitted slope.
  CHECK(c.slope_at_zero < c.paper_k);
  CHECK(c.paper_k < 0);
}
