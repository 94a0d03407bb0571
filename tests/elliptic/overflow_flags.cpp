// Valid arguments at the far end of the range raise no floating-point overflow flag: m -> -inf
// in E(m), K(m) and E(phi|m), and R_D, R_J with arguments near 1e300 (numpy reports a raised flag
// as a RuntimeWarning on the ufuncs; the values themselves were right). The sites were the R_D
// sum term sqrt(z)(z + lambda) and the series' A^(3/2) on unscaled arguments
// (gecko/elliptic/carlson_rd.hpp) and R_J's spread test lo * 2^409 (carlson_rj.hpp). Values are
// checked against mpmath in the tables (elliptic_complete.csv reaches m = -DBL_MAX).
#include <gecko/elliptic/carlson_rd.hpp>
#include <gecko/elliptic/carlson_rj.hpp>
#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_ek.hpp>
#include <gecko/elliptic/ellint_f.hpp>
#include <gecko/elliptic/ellint_k.hpp>

#include <cfenv>
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

namespace {
// true when f() leaves the overflow flag clear and returns a finite value
template <class F>
bool no_overflow(F f) {
  std::feclearexcept(FE_ALL_EXCEPT);
  volatile double v = f();
  return std::fetestexcept(FE_OVERFLOW) == 0 && std::isfinite(v);
}
}  // namespace

TEST_CASE("elliptic: no spurious overflow flag for m -> -inf and arguments near 1e300") {
  const double big = std::numeric_limits<double>::max();
  for (double m : {-1e160, -1e200, -1e250, -1e300, -1e305, -big}) {
    INFO("m = " << m);
    CHECK(no_overflow([m] { return gecko::ellint_ek(m).E; }));
    CHECK(no_overflow([m] { return gecko::ellint_ek(m).K; }));
    CHECK(no_overflow([m] { return gecko::ellint_k(m); }));
    for (double phi : {1e-80, 1e-20, 1.0, 1.5, 1.6, 3.0, -7.5}) {
      INFO("phi = " << phi);
      CHECK(no_overflow([phi, m] { return gecko::ellint_e(phi, m); }));
      CHECK(no_overflow([phi, m] { return gecko::ellint_f(phi, m); }));
    }
  }
  for (double y : {1e200, 1e300, big}) {
    INFO("y = " << y);
    CHECK(no_overflow([y] { return gecko::carlson_rd(0.0, y, 1.0); }));
    CHECK(no_overflow([y] { return gecko::carlson_rj(0.0, y, 1.0, 2.0); }));
    CHECK(no_overflow([y] { return gecko::carlson_rj(1.0, y, y, 2.0); }));
  }
}
