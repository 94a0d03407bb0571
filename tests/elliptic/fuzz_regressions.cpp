// Regression tests for the inputs the elliptic fuzzers found (fuzz/fuzz_carlson.cpp,
// fuzz/fuzz_legendre.cpp; fuzz/README.md lists the findings), against the mpmath references of
// tests/data/gen_fuzz_regressions.py (tests/data/fuzz_regressions.csv, inputs as exact hex floats).
// Bounds as the unit tests of each function: R_F 3 eps, R_C 4 eps, R_D 4 eps, R_J 4 eps (times
// the cancellation factor of DLMF 19.20.14 for principal values), E 4 eps, F 3 eps, the partials
// of carlson_rf_gradient 8 eps; a reference below
// DBL_MIN (exact result subnormal or underflowing) is met within DBL_MIN absolute.
// Rows marked "fixed" must pass. Rows marked "open" are known findings not fixed yet; they run
// as [!mayfail] (reported, not failing) so that the fix shows up as "passed" here -- then move
// the row to "fixed" in gen_fuzz_regressions.py.
#include <gecko/elliptic.hpp>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

namespace {

struct fuzz_case {
  std::string id, status, function;
  double a[4];
  long double reference;
  double cancellation;
};

std::vector<fuzz_case> load_cases() {
  std::ifstream in(std::string(GECKO_TEST_DATA_DIR) + "/fuzz_regressions.csv");
  REQUIRE(in.good());
  std::string line;
  std::getline(in, line);  // header
  std::vector<fuzz_case> cases;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cell;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cell.push_back(c);
    REQUIRE(cell.size() == 9);
    fuzz_case fc;
    fc.id = cell[0];
    fc.status = cell[1];
    fc.function = cell[2];
    for (int i = 0; i < 4; ++i) fc.a[i] = std::strtod(cell[3 + i].c_str(), nullptr);  // hex floats: exact
    fc.reference = std::strtold(cell[7].c_str(), nullptr);
    fc.cancellation = std::strtod(cell[8].c_str(), nullptr);
    cases.push_back(fc);
  }
  REQUIRE(cases.size() >= 10);
  return cases;
}

double evaluate(const fuzz_case& c, double& bound_eps) {
  using gecko::policies::nan_policy;
  const double* a = c.a;
  if (c.function == "rf") { bound_eps = 3; return gecko::carlson_rf(a[0], a[1], a[2], nan_policy()); }
  if (c.function == "rc") { bound_eps = 4; return gecko::carlson_rc(a[0], a[1], nan_policy()); }
  if (c.function == "rd") { bound_eps = 4; return gecko::carlson_rd(a[0], a[1], a[2], nan_policy()); }
  if (c.function == "rj") {
    bound_eps = 4 * c.cancellation;
    return gecko::carlson_rj(a[0], a[1], a[2], a[3], nan_policy());
  }
  if (c.function == "e") { bound_eps = 4; return gecko::ellint_e(a[0], a[1], nan_policy()); }
  if (c.function == "f") { bound_eps = 3; return gecko::ellint_f(a[0], a[1], nan_policy()); }
  // partials of R_F from carlson_rf_gradient, at R_D's bound (they are -R_D/6)
  if (c.function == "rfg_dz") { bound_eps = 8; return gecko::carlson_rf_gradient(a[0], a[1], a[2], nan_policy()).dz; }
  if (c.function == "rfg_dx") { bound_eps = 8; return gecko::carlson_rf_gradient(a[0], a[1], a[2], nan_policy()).dx; }
  FAIL("unknown function " << c.function);
  return 0;
}

void check_case(const fuzz_case& c) {
  double bound_eps = 0;
  const double got = evaluate(c, bound_eps);
  const long double ref = c.reference;
  INFO(c.id << ": " << c.function << "(" << c.a[0] << ", " << c.a[1] << ", " << c.a[2] << ", " << c.a[3]
            << ") = " << got << ", mpmath " << static_cast<double>(ref));
  // Where the bound exceeds the value itself (an R_J principal value at a near-zero of its
  // formula's sum) a finite result may stand for a reference beyond DBL_MAX.
  if (bound_eps * DBL_EPSILON < 1) CHECK(std::isfinite(got) == (std::fabs(ref) <= DBL_MAX));
  if (std::isnan(got)) return;
  if (std::isinf(got)) {  // the reference beyond DBL_MAX (checked above): the sign must agree
    CHECK(std::signbit(got) == (ref < 0));
    return;
  }
  const long double err = std::fabs(static_cast<long double>(got) - ref);
  if (std::fabs(ref) < DBL_MIN) {
    CHECK(err <= DBL_MIN);
  } else {
    const long double err_eps = err / (std::fabs(ref) * DBL_EPSILON);
    INFO("error " << static_cast<double>(err_eps) << " eps, bound " << bound_eps << " eps");
    CHECK(err_eps <= bound_eps);
  }
}

}  // namespace

TEST_CASE("fuzz regressions: fixed findings stay fixed") {
  int n = 0;
  for (const auto& c : load_cases()) {
    if (c.status != "fixed") continue;
    ++n;
    check_case(c);
  }
  CHECK(n >= 30);
}

TEST_CASE("fuzz regressions: open findings (known failures, fuzz/README.md)", "[!mayfail]") {
  for (const auto& c : load_cases()) {
    if (c.status != "open") continue;
    check_case(c);
  }
}
