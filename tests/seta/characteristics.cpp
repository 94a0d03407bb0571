// Tests of gecko/seta/characteristics.hpp against the per-design characteristics of the
// reference generator (tests/data/seta_reference_designs.csv, mpmath, 25 digits).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gecko/seta/characteristics.hpp"

namespace {
double parse(const std::string& s) {
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(s);
}
std::vector<std::string> split(const std::string& l) {
  std::vector<std::string> cells;
  std::stringstream ss(l);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!l.empty() && l.back() == ',') cells.push_back("");
  return cells;
}
}  // namespace

TEST_CASE("characteristics match the reference designs", "[seta][characteristics][reference]") {
  std::ifstream in(std::string(GECKO_TEST_DATA_DIR) + "/seta_reference_designs.csv");
  std::string line;
  REQUIRE(std::getline(in, line));
  const auto header = split(line);
  auto col = [&](const char* name) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    FAIL("missing column " << name);
    return std::size_t(0);
  };
  int designs = 0, sticky = 0;
  while (std::getline(in, line)) {
    const auto r = split(line);
    gecko::TwoLevelSeta<double> s;
    s.EI1 = parse(r[col("EI1")]); s.EI2 = parse(r[col("EI2")]);
    s.EA1 = parse(r[col("EA1")]); s.EA2 = parse(r[col("EA2")]);
    s.l1 = parse(r[col("l1")]); s.l2 = parse(r[col("l2")]);
    s.alpha1 = parse(r[col("alpha1")]); s.alpha2 = parse(r[col("alpha2")]);
    s.w = parse(r[col("w")]);
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
      // The value at a minimum is insensitive to its location: full accuracy.
      CHECK(std::fabs(c.min_fn - min_fn) <= 1e-11 * std::max(1.0, std::fabs(min_fn)));
      CHECK(std::fabs(c.ft_at_min_fn - ft_min) <= 1e-6 * std::max(1.0, std::fabs(ft_min)));
      CHECK(c.max_pull_off == Approx(std::max(0.0, -min_fn)).epsilon(1e-11));
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
  // models.md: the linear theory gives (Fn)0 ~ 0.34 against the exact ~0.25.
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
