// Tests of gecko/beam/castigliano.hpp against the mpmath references of
// tests/data/gen_beam_reference.py (30 digits), the Appendix-1 closed form, and closed forms of
// a straight inclined beam.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "beam/beam_reference.hpp"
#include "gecko/beam/castigliano.hpp"
#include "gecko/beam/parabolic.hpp"
#include "gecko/beam/rigidity.hpp"

using gecko_test::beam_ref;

namespace {

template <class T>
T rel(T a, long double b) { return T(std::abs((static_cast<long double>(a) - b) / b)); }

// Error relative to the largest entry: the quarter circle's C12 = B12 + A12 is exactly 0.
template <class T>
T rel_to(T a, long double b, long double scale) {
  return T(std::abs(static_cast<long double>(a) - b) / scale);
}

// Bending (B) and axial (A) parts with L = EI = EA = 1: C = B + A.
template <class T, class Shape>
void check_against_reference(const Shape& shape, const std::string& name, T tol) {
  gecko::quadrature_report<T> rep;
  gecko::quadrature_options<T> opt;
  opt.report = &rep;
  const auto B = gecko::castigliano_compliance(shape, gecko::curved_beam<T>{T(1), T(1)}, opt);
  CHECK(rep.converged);
  CHECK(rel(B(0, 0), beam_ref(name + ".B11")) <= tol);
  CHECK(rel(B(0, 1), beam_ref(name + ".B12")) <= tol);
  CHECK(rel(B(1, 1), beam_ref(name + ".B22")) <= tol);
  CHECK(B(0, 1) == B(1, 0));
  // EA = 1 as well: the axial part adds A.
  const auto C = gecko::castigliano_compliance(shape, gecko::curved_beam<T>{T(1), T(1), T(1)}, opt);
  const long double scale = std::max(beam_ref(name + ".B11") + beam_ref(name + ".A11"),
                                     beam_ref(name + ".B22") + beam_ref(name + ".A22"));
  CHECK(rel_to(C(0, 0), beam_ref(name + ".B11") + beam_ref(name + ".A11"), scale) <= tol);
  CHECK(rel_to(C(0, 1), beam_ref(name + ".B12") + beam_ref(name + ".A12"), scale) <= tol);
  CHECK(rel_to(C(1, 1), beam_ref(name + ".B22") + beam_ref(name + ".A22"), scale) <= tol);
}

}  // namespace

TEMPLATE_TEST_CASE("Castigliano quadrature matches the mpmath references", "[beam][castigliano]",
                   float, double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  auto parabola = [](auto x) { using std::sqrt; return sqrt(x) / TestType(2); };
  auto circle = [](auto x) { using std::sqrt; return sqrt(TestType(2) * x - x * x); };
  auto cubic = [](auto x) { return TestType(0.3) + x / TestType(2) + x * x * x; };
  // A few eps: the rounding of ~100 weighted terms (measured: at most 19 eps, for the cubic).
  SECTION("complex-step slopes") {
    check_against_reference<T>(parabola, "parabola", 32 * eps);
    check_against_reference<T>(circle, "quarter_circle", 32 * eps);
    check_against_reference<T>(cubic, "cubic", 32 * eps);
  }
  SECTION("explicit slopes") {
    check_against_reference<T>(gecko::parabolic_shape<T>{T(1)}, "parabola", 32 * eps);
    check_against_reference<T>(
        gecko::make_shape(circle, [](T x) { return (1 - x) / std::sqrt(2 * x - x * x); }),
        "quarter_circle", 32 * eps);
  }
}

TEST_CASE("quadrature against the Appendix-1 closed form to 1e-13", "[beam][castigliano]") {
  for (double L : {1e-6, 0.3, 1.0, 7.0}) {
    for (double EI : {1e-20, 1.0, 250.0}) {
      const auto Cq = gecko::castigliano_compliance(gecko::parabolic_shape<double>{L},
                                                    gecko::curved_beam<double>{L, EI});
      const auto Cc = gecko::parabolic_beam_compliance(L, EI);
      CHECK(((Cq - Cc).cwiseAbs().array() / Cc.cwiseAbs().array()).maxCoeff() <= 1e-13);
      // Rigidity, the ill-conditioned inverse, too.
      const auto Kq = gecko::rigidity(Cq);
      const auto Kc = gecko::parabolic_beam_rigidity(L, EI);
      CHECK(((Kq - Kc).cwiseAbs().array() / Kc.cwiseAbs().array()).maxCoeff() <= 1e-13);
    }
  }
}

TEST_CASE("rigidity of the parabola to 1e-13 against mpmath", "[beam][castigliano]") {
  const auto K = gecko::rigidity(gecko::castigliano_compliance(
      [](auto x) { using std::sqrt; return sqrt(x) / 2.0; }, gecko::curved_beam<double>{1.0, 1.0}));
  CHECK(rel(K(0, 0), beam_ref("parabola_closed_form.K11_unit")) <= 1e-13);
  CHECK(rel(K(0, 1), beam_ref("parabola_closed_form.K12_unit")) <= 1e-13);
  CHECK(rel(K(1, 1), beam_ref("parabola_closed_form.K22_unit")) <= 1e-13);
}

TEST_CASE("straight inclined beam: bending and axial closed forms", "[beam][castigliano]") {
  // z = c x: ds = sqrt(1 + c^2) dx, m = (c x, x), a = (1, -c) / sqrt(1 + c^2).
  const double c = 0.7, L = 2.0, EI = 3.0, EA = 50.0;
  const double s = std::sqrt(1 + c * c);
  const auto C = gecko::castigliano_compliance([c](auto x) { return c * x; },
                                               gecko::curved_beam<double>{L, EI, EA});
  const double b = s * L * L * L / (3 * EI), a = L / (EA * s);
  CHECK(C(0, 0) == Approx(c * c * b + a).epsilon(4e-16));
  CHECK(C(0, 1) == Approx(c * b - c * a).epsilon(4e-16));
  CHECK(C(1, 1) == Approx(b + c * c * a).epsilon(4e-16));
  // The force along the beam, (1, -c) in (F_par, F_perp), only stretches it: D = a (1+c^2) F.
  Eigen::Vector2d F(1.0, -c);
  const Eigen::Vector2d D = C * F;
  CHECK(D(0) == Approx(a * (1 + c * c)).epsilon(1e-14));
  CHECK(D(1) == Approx(-c * a * (1 + c * c)).epsilon(1e-14));
}

TEST_CASE("compliance scales as L^3/EI", "[beam][castigliano]") {
  auto shape = [](double L) {
    return [L](auto x) { using std::sqrt; return sqrt(L * x) / 2.0 + 0.1 * x * x / L; };
  };
  const auto C1 = gecko::castigliano_compliance(shape(1.0), gecko::curved_beam<double>{1.0, 1.0});
  const double L = 3.5, EI = 0.02;
  const auto C2 = gecko::castigliano_compliance(shape(L), gecko::curved_beam<double>{L, EI});
  const Eigen::Matrix2d ratio = C2.cwiseQuotient(C1) * (EI / (L * L * L));
  CHECK((ratio.array() - 1.0).abs().maxCoeff() <= 1e-14);
}

TEST_CASE("castigliano_compliance: bad input names the argument", "[beam][castigliano][errors]") {
  auto ok = [](auto x) { using std::sqrt; return sqrt(x); };
  using B = gecko::curved_beam<double>;
  auto msg = [&](auto&& f) {
    try { f(); } catch (const std::domain_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  CHECK_THAT(msg([&] { gecko::castigliano_compliance(ok, B{0.0, 1.0}); }),
             Catch::Contains("L = 0") && Catch::Contains("castigliano_compliance"));
  CHECK_THAT(msg([&] { gecko::castigliano_compliance(ok, B{1.0, -1.0}); }), Catch::Contains("EI = -1"));
  CHECK_THAT(msg([&] { gecko::castigliano_compliance(ok, B{1.0, 1.0, 0.0}); }), Catch::Contains("EA = 0"));
  CHECK_THAT(msg([&] { gecko::castigliano_compliance(ok, B{std::nan(""), 1.0}); }), Catch::Contains("L = nan"));
  // A shape with no finite value at the tip, and one that is NaN inside (0, L).
  CHECK_THAT(msg([&] { gecko::castigliano_compliance([](auto x) { using std::log; return log(x); }, B{1.0, 1.0}); }),
             Catch::Contains("shape") && Catch::Contains("z(0)"));
  CHECK_THAT(msg([&] {
               gecko::castigliano_compliance(
                   gecko::make_shape([](double x) { return x; },
                                     [](double x) { return x > 0.5 ? std::nan("") : 1.0; }),
                   B{1.0, 1.0});
             }),
             Catch::Contains("shape") && Catch::Contains("finite z(x) and dz/dx"));
  // Under nan_policy: NaN, no throw.
  const auto C = gecko::castigliano_compliance(ok, B{-1.0, 1.0}, {}, gecko::policies::nan_policy());
  CHECK(std::isnan(C(0, 0)));
}

TEST_CASE("castigliano_compliance says when the quadrature does not converge",
          "[beam][castigliano][errors]") {
  gecko::quadrature_options<double> opt;
  opt.max_levels = 3;
  opt.tol = 1e-15;
  auto wiggly = [](auto x) { using std::sin; return sin(500.0 * x); };
  CHECK_THROWS_AS(gecko::castigliano_compliance(wiggly, gecko::curved_beam<double>{1.0, 1.0}, opt),
                  std::runtime_error);
  const auto C = gecko::castigliano_compliance(wiggly, gecko::curved_beam<double>{1.0, 1.0}, opt,
                                               gecko::policies::nan_policy());
  CHECK(std::isnan(C(0, 1)));
}

// Quarter circle of radius R as a graph with a vertical tangent at the clamp,
// z = R - sqrt(R^2 - x^2), 0 <= x <= R: with x = R sin p, z = R (1 - cos p), ds = R dp,
// C = R^3 [[int (1 - cos p)^2, int (1 - cos p) sin p], [., int sin^2 p]] over [0, pi/2]
//   = R^3 [[3 pi/4 - 2, 1/2], [1/2, pi/4]] (EI = 1). Converges at the default tolerance.
TEST_CASE("quarter circle graph with a vertical tangent at the clamp", "[beam][castigliano]") {
  const double R = 0.7, pi = 3.141592653589793;
  gecko::quadrature_report<double> rep;
  gecko::quadrature_options<double> opt;
  opt.report = &rep;
  const auto C = gecko::castigliano_compliance(
      [R](auto x) { using std::sqrt; return R - sqrt(R * R - x * x); },
      gecko::curved_beam<double>{R, 1.0}, opt);
  CHECK(rep.converged);
  const double R3 = R * R * R;
  CHECK(C(0, 0) == Approx(R3 * (3 * pi / 4 - 2)).epsilon(2e-12));
  CHECK(C(0, 1) == Approx(R3 / 2).epsilon(2e-12));
  CHECK(C(1, 1) == Approx(R3 * pi / 4).epsilon(2e-12));
}

TEST_CASE("castigliano_compliance refuses out-of-range options", "[beam][castigliano][errors]") {
  gecko::quadrature_options<double> opt;
  opt.max_levels = 10;
  const auto line = [](auto x) { return x; };
  CHECK_THROWS_WITH(gecko::castigliano_compliance(line, gecko::curved_beam<double>{}, opt),
                    Catch::Contains("max_levels = 10"));
  opt.max_levels = 0;
  CHECK_THROWS_WITH(gecko::castigliano_compliance(line, gecko::curved_beam<double>{}, opt),
                    Catch::Contains("max_levels = 0"));
  opt.max_levels = 9;
  opt.tol = -1;
  CHECK_THROWS_WITH(gecko::castigliano_compliance(line, gecko::curved_beam<double>{}, opt),
                    Catch::Contains("tol = -1"));
}
