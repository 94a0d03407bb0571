// bench/friction/bench_beam.cpp — rigidity of a curved beam by Castigliano (docs/theory/frictional_adhesion.md):
// run time and error of gecko's tanh-sinh quadrature (explicit slope, complex-step slope, a few
// tolerances), the Appendix-1 closed form, and GSL's adaptive QAGS (the peer) on the same
// integrals in the original variable x. Errors against tests/data/beam_reference.csv (mpmath).
//
//   bench_friction_beam [--out DIR] [--reps N]
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_config.hpp"  // defines GECKO_TEST_DATA_DIR for the reader below
#include "beam_reference.hpp"
#include "gecko/beam.hpp"
#include "harness.hpp"

namespace {

double max_rel(const Eigen::Matrix2d& M, long double r11, long double r12, long double r22) {
  auto rel = [](double a, long double b) { return double(std::fabs((a - b) / b)); };
  return std::max({rel(M(0, 0), r11), rel(M(0, 1), r12), rel(M(1, 1), r22)});
}

// GSL peer: the three bending integrals of the parabola (L = 1) in x, QAGS at epsrel.
struct gsl_peer {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  ~gsl_peer() { gsl_integration_workspace_free(w); }
  static double f(double x, void* p) {
    const int k = *static_cast<int*>(p);
    const double z = std::sqrt(x) / 2, ds = std::sqrt(1 + 1 / (16 * x));
    return (k == 0 ? z * z : k == 1 ? z * x : x * x) * ds;
  }
  Eigen::Matrix2d compliance(double epsrel) {
    double v[3];
    for (int k = 0; k < 3; ++k) {
      gsl_function F{&f, &k};
      double err;
      gsl_integration_qags(&F, 0, 1, 0, epsrel, 1000, w, &v[k], &err);
    }
    Eigen::Matrix2d C;
    C << v[0], v[1], v[1], v[2];
    return C;
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  int reps = 15;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--out")) out = argv[i + 1];
    if (!std::strcmp(argv[i], "--reps")) reps = std::atoi(argv[i + 1]);
  }
  gsl_set_error_handler_off();
  // The same reader as the tests (tests/beam/beam_reference.hpp): one parser of the mpmath table.
  const auto& ref = gecko_test::beam_reference();
  const long double K11 = ref.at("parabola_closed_form.K11_unit"),
                    K12 = ref.at("parabola_closed_form.K12_unit"),
                    K22 = ref.at("parabola_closed_form.K22_unit");
  std::vector<gecko_bench::row> rows;
  const gecko::curved_beam<double> beam{1.0, 1.0};
  const int inner = 2000;

  // gecko, explicit slope (parabolic_shape), at several tolerances.
  for (double tol : {1e-2, 1e-4, 1e-8, 1e-10, 0.0}) {
    gecko::quadrature_options<double> opt;
    opt.tol = tol;
    gecko::quadrature_report<double> rep;
    Eigen::Matrix2d K;
    const double s = gecko_bench::median_seconds([&] {
      K = gecko::rigidity(gecko::castigliano_compliance(gecko::parabolic_shape<double>{1.0}, beam, opt));
      gecko_bench::keep(K);
    }, inner, reps);
    opt.report = &rep;
    gecko::castigliano_compliance(gecko::parabolic_shape<double>{1.0}, beam, opt);
    char setting[64], note[96];
    if (tol == 0) std::snprintf(setting, sizeof setting, "tol=default (eps^2/3)");
    else std::snprintf(setting, sizeof setting, "tol=%g", tol);
    std::snprintf(note, sizeof note, "%d evaluations, %d levels", rep.evaluations, rep.levels);
    rows.push_back({"beam", "gecko castigliano + rigidity, explicit slope", setting, s,
                    max_rel(K, K11, K12, K22), note});
  }
  // gecko, complex-step slope of a generic lambda (the 'general curved beam' of the issue).
  {
    Eigen::Matrix2d K;
    auto z = [](auto x) { using std::sqrt; return sqrt(x) / 2.0; };
    const double s = gecko_bench::median_seconds([&] {
      K = gecko::rigidity(gecko::castigliano_compliance(z, beam));
      gecko_bench::keep(K);
    }, inner, reps);
    rows.push_back({"beam", "gecko castigliano + rigidity, complex-step slope", "tol=default", s,
                    max_rel(K, K11, K12, K22), "general shape: z(x) only"});
  }
  // gecko, quarter circle with the axial term (EA = 1), complex step; error against mpmath.
  {
    Eigen::Matrix2d C;
    auto z = [](auto x) { using std::sqrt; return sqrt(2.0 * x - x * x); };
    const gecko::curved_beam<double> b{1.0, 1.0, 1.0};
    const double s = gecko_bench::median_seconds([&] {
      C = gecko::castigliano_compliance(z, b);
      gecko_bench::keep(C);
    }, inner, reps);
    const long double c11 = ref.at("quarter_circle.B11") + ref.at("quarter_circle.A11");
    const long double c22 = ref.at("quarter_circle.B22") + ref.at("quarter_circle.A22");
    const double err = std::max(double(std::fabs((C(0, 0) - c11) / c11)),
                                double(std::fabs((C(1, 1) - c22) / c22)));
    rows.push_back({"beam", "gecko castigliano (compliance), quarter circle + axial", "tol=default",
                    s, err, "C12 = 0 exactly; error of C11, C22"});
  }
  // Closed form.
  {
    Eigen::Matrix2d K;
    volatile double L = 1.0;  // not a compile-time constant: no folding of the closed form
    const double s = gecko_bench::median_seconds([&] {
      K = gecko::parabolic_beam_rigidity(double(L), 1.0);
      gecko_bench::keep(K);
    }, 20 * inner, reps);
    rows.push_back({"beam", "gecko parabolic_beam_rigidity (closed form)", "-", s,
                    max_rel(K, K11, K12, K22), "Appendix 1"});
  }
  // Peer: GSL QAGS in x (singular endpoint handled by extrapolation).
  {
    gsl_peer peer;
    for (double epsrel : {1e-8, 1e-10, 1e-13}) {
      Eigen::Matrix2d K;
      const double s = gecko_bench::median_seconds([&] {
        K = gecko::rigidity(peer.compliance(epsrel));
        gecko_bench::keep(K);
      }, inner / 10, reps);
      char setting[64];
      std::snprintf(setting, sizeof setting, "epsrel=%g", epsrel);
      rows.push_back({"beam", "GSL qags (3 integrals in x) + rigidity", setting, s,
                      max_rel(K, K11, K12, K22), "peer"});
    }
  }
  gecko_bench::write(rows, out + "/friction_beam.csv", out + "/friction_beam.md",
                     "Rigidity of the parabolic beam (L = EI = 1), error against mpmath (30 digits). "
                     "Flags: " GECKO_BENCH_CXX_FLAGS);
  for (const auto& r : rows)
    std::printf("%-58s %-26s %10.3f us  err %.2g  %s\n", r.method.c_str(), r.setting.c_str(),
                r.seconds * 1e6, r.error, r.note.c_str());
  return 0;
}
