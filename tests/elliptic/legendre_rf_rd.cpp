// Tests for gecko/elliptic/legendre_rf_rd.hpp: R_F and R_D from known roots, in both argument
// orders the Legendre E uses, (c^2, Delta^2, 1) for m <= 0 and (c^2, 1, Delta^2) for 0 < m <= 1,
// against the general fused kernel carlson_rf_rd_imp evaluated one precision higher at the same
// rounded arguments (long double for double, double for float): at random points, next to the
// singular corner c -> 0, Delta -> 0 (m -> 1, phi -> pi/2), at Delta^2 up to 1/eps (m -> -inf),
// and at the exact point c = Delta = 1, where both are 1 and the loop must not run.
#include <gecko/elliptic/carlson_rf_rd.hpp>
#include <gecko/elliptic/legendre_rf_rd.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

namespace {

template <class T>
struct wider {
  using type = long double;
};
template <>
struct wider<float> {
  using type = double;
};

struct legendre_rf_rd_worst {
  long double rf = 0, rd = 0;
};

// One point: c = cos phi, d = Delta, both in (0, ...); neg selects the m <= 0 order.
template <class T>
void check_point(T c, T d, bool neg, legendre_rf_rd_worst& w) {
  using W = typename wider<T>::type;
  const T x = c * c, d2 = d * d;
  const T y = neg ? d2 : T(1), z = neg ? T(1) : d2;
  const T ry = neg ? d : T(1), rz = neg ? T(1) : d;
  const auto got = gecko::detail::legendre_rf_rd_imp<T>(x, y, z, c, ry, rz);
  const auto ref = gecko::detail::carlson_rf_rd_imp<W>(W(x), W(y), W(z));
  const long double eps = std::numeric_limits<T>::epsilon();
  const long double erf = std::fabs((static_cast<long double>(got.rf) - ref.rf) / ref.rf) / eps;
  const long double erd = std::fabs((static_cast<long double>(got.rd) - ref.rd) / ref.rd) / eps;
  if (erf > w.rf || erd > w.rd) {
    std::ostringstream where;
    where.precision(std::numeric_limits<T>::max_digits10);
    where << "c = " << c << ", Delta = " << d << (neg ? " (order c^2, Delta^2, 1)" : " (order c^2, 1, Delta^2)");
    INFO(where.str());
    // the roots are those of the rounded squares only to within half an ulp, which moves R_F by
    // a quarter and R_D by three quarters of an ulp at most (degrees -1/2 and -3/2); the kernels'
    // own bounds are 3 eps (R_F) and 4 eps (R_D) (gecko/elliptic/carlson_tolerance.hpp)
    CHECK(erf <= 3);
    CHECK(erd <= 4);
  }
  w.rf = std::fmax(w.rf, erf);
  w.rd = std::fmax(w.rd, erd);
}

template <class T>
void report(const legendre_rf_rd_worst& w, const char* where) {
  WARN("legendre_rf_rd_imp<" << (sizeof(T) == sizeof(float) ? "float" : "double") << ">, " << where
                             << ": worst R_F " << double(w.rf) << " eps, R_D " << double(w.rd) << " eps");
}

}  // namespace

TEMPLATE_TEST_CASE("legendre_rf_rd: known-root kernel against the general fused kernel one precision up",
                   "[legendre_rf_rd]", float, double) {
  using T = TestType;
  std::mt19937_64 gen(20261129);
  std::uniform_real_distribution<double> u(0, 1);
  legendre_rf_rd_worst w;
  SECTION("random phi in (0, pi/2), m in (-10, 1]") {
    for (int i = 0; i < 20000; ++i) {
      const double phi = 1.5707963 * u(gen), m = 1 - 11 * u(gen);
      const T c = static_cast<T>(std::cos(phi)), s = static_cast<T>(std::sin(phi));
      const T d = std::sqrt(c * c + static_cast<T>(1 - m) * (s * s));
      check_point<T>(c, d, m <= 0, w);
    }
    report<T>(w, "random");
  }
  SECTION("near the singular corner: c and Delta from 1 down to 1e-15") {
    for (int i = 0; i < 5000; ++i) {
      const T c = static_cast<T>(std::pow(10.0, -15 * u(gen)));
      const T d = static_cast<T>(std::pow(10.0, -15 * u(gen)));
      check_point<T>(std::fmax(c, std::numeric_limits<T>::min()), std::fmax(d, c), false, w);
    }
    report<T>(w, "singular corner");
  }
  SECTION("m -> -inf: Delta^2 up to 1/eps") {
    const double top = std::log10(1 / static_cast<double>(std::numeric_limits<T>::epsilon()));
    for (int i = 0; i < 5000; ++i) {
      const T d = static_cast<T>(std::sqrt(std::pow(10.0, top * u(gen)) * 0.999));
      check_point<T>(static_cast<T>(u(gen)), std::fmax(d, T(1)), true, w);
    }
    report<T>(w, "m -> -inf");
  }
  SECTION("exact point: R_F(1, 1, 1) = R_D(1, 1, 1) = 1") {
    const auto r = gecko::detail::legendre_rf_rd_imp<T>(T(1), T(1), T(1), T(1), T(1), T(1));
    CHECK(r.rf == T(1));
    CHECK(r.rd == T(1));
  }
}
