// Tests of gecko/seta/elastica_segment.hpp: segment lengths in Carlson form against 40-digit
// quadrature (tests/data/gen_seta_solver_segments.py), every case kind (libration with 0, 1, 2
// turning points, rotation, EA finite and infinite).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gecko/seta/elastica_segment.hpp"
#include "seta/csv_table.hpp"

using gecko_test::parse;

TEST_CASE("elastica segment length matches 40-digit quadrature", "[seta][segment]") {
  const auto rows = gecko_test::read_csv_table(std::string(GECKO_TEST_DATA_DIR) + "/seta_solver_segments.csv").rows;
  REQUIRE(rows.size() >= 150);
  double worst = 0;
  int kinds[4] = {0, 0, 0, 0};
  for (const auto& r : rows) {
    REQUIRE(r.size() == 11);
    const double EI = parse(r[0]), EA = parse(r[1]), M = parse(r[2]), Fn = parse(r[3]), Ft = parse(r[4]);
    const double ts = parse(r[5]), te = parse(r[6]);
    const int ss = std::stoi(r[7]), se = std::stoi(r[8]), tp = std::stoi(r[9]);
    const double ref = parse(r[10]);
    const auto got = gecko::elastica_segment(EI, EA, M, Fn, Ft, ts, te, ss, se);
    INFO("case EI=" << r[0] << " EA=" << r[1] << " M=" << r[2] << " Fn=" << r[3] << " Ft=" << r[4]
                    << " ts=" << r[5] << " te=" << r[6] << " signs " << ss << se << " ref " << r[10]
                    << " got " << got.length);
    // Relative error: the forms lose a few ulps to the half-angle sums; 64 eps covers paths up to
    // a full libration (phase differences of quarter periods).
    const double err = std::fabs(got.length - ref) / ref;
    worst = std::max(worst, err);
    CHECK(err < 64 * std::numeric_limits<double>::epsilon());
    CHECK(got.turning_points == tp);
    kinds[std::min(tp, 3)]++;
  }
  WARN("worst relative error " << worst << " (" << worst / std::numeric_limits<double>::epsilon() << " eps)");
}

TEST_CASE("elastica segment: EA = 1e12 approaches EA = infinity", "[seta][segment]") {
  const double a = gecko::elastica_segment_length(2.0, std::numeric_limits<double>::infinity(), 3.0, 0.7, 2.1, 0.4, 1.2);
  const double b = gecko::elastica_segment_length(2.0, 1e12, 3.0, 0.7, 2.1, 0.4, 1.2);
  CHECK(std::fabs(a - b) < 1e-10 * a);
  CHECK(a != b);
}

TEST_CASE("elastica segment: bad input names the parameter", "[seta][segment]") {
  CHECK_THROWS_WITH(gecko::elastica_segment_length(-1.0, 1.0, 1.0, 1.0, 1.0, 0.1, 0.2),
                    Catch::Contains("EI") && Catch::Contains("EI > 0"));
  CHECK_THROWS_WITH(gecko::elastica_segment_length(1.0, 0.0, 1.0, 1.0, 1.0, 0.1, 0.2),
                    Catch::Contains("EA"));
  CHECK_THROWS_WITH(gecko::elastica_segment_length(1.0, 1.0, 1.0, 0.0, 0.0, 0.1, 0.2),
                    Catch::Contains("Fn, Ft"));
}
