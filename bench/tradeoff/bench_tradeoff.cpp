// bench/tradeoff/bench_tradeoff.cpp — run time against error for the families that
// bench/elliptic (F, E, R_F) and bench/seta (a whole critical line) do not cover, with the peers
// in the same run. One CSV row per method and setting; bench/tradeoff/run.py merges them with
// the other benches' rows, scipy's, and draws the Pareto fronts.
//
//   R_D, R_J        gecko::carlson_rd / carlson_rj, full and precision<48/40/32/24>;
//                   boost::math::ellint_rd / ellint_rj with promote_double<false>;
//                   gsl_sf_ellint_RD / _RJ at GSL_PREC_DOUBLE / _SINGLE / _APPROX.
//                   Inputs and 40-digit mpmath references: bench/tradeoff/gen_inputs.py.
//   segment length  gecko::elastica_segment_length (docs/theory/two_level_seta.md, lengths in Carlson form), full
//                   and precision<Bits>; peers: what a researcher writes, the length integral
//                   sqrt(EI/2) * int dtheta / sqrt(R(theta)) (docs/theory/two_level_seta.md first integral) split at
//                   the turning angles, by GSL QAGS and by Boost's tanh_sinh, at several
//                   tolerances. Inputs and 40-digit mpmath references (independent quadrature):
//                   tests/data/seta_solver_segments.csv, 160 segments with 0, 1, 2 turning points.
//   solve_critical  one critical state from a guess (gecko::solve_critical, Newton tolerances)
//                   against GSL gsl_multiroot_fdfsolver_hybridsj on the same residual and
//                   Jacobian from the same starting point (test_delta tolerances); and
//                   gecko::solve_critical(seta, Ft) without a guess (follows the line from Ft = 0).
//                   States: tests/data/seta_reference.csv (mpmath, two independent routes).
//   batch           gecko::critical_line_batch, random designs x 20 Ft, 1 and 2 threads; error by
//                   the independent ODE shooting of tests/seta/seta_shooting.hpp.
//
// Errors: kernels and segment lengths, max relative error in eps = 2^-52; the seta, max
// |dFn| / max(1, |Fn|). Timing: bench/harness.hpp (thread CPU time of whole sweeps of the
// input set, median of interleaved repetitions); the batch on 2 threads needs wall time, so the
// batch rows are wall time for both thread counts.
//
// Usage: bench_tradeoff --out FILE.csv [--reps N] [--target-ms MS] [--designs N] [--quick]
#include <gecko/elliptic.hpp>
#include <gecko/seta.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/version.hpp>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_version.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "data_file.hpp"      // bench/elliptic
#include "harness.hpp"        // bench/harness.hpp
#include "seta_shooting.hpp"  // tests/seta
#include "tradeoff_config.hpp"

namespace {

using namespace gecko_bench;
using gecko::policies::precision;
using boost_policy =
    decltype(boost::math::policies::make_policy(boost::math::policies::promote_double<false>()));

// ---- one output row ---------------------------------------------------------------------------
struct result_row {
  std::string family, method, setting, input_set;
  std::size_t n = 0;
  double ns = 0, q1 = 0, q3 = 0;  // per call
  double max_err = 0, rms_err = 0;
  std::string unit;
  std::size_t failed = 0;
  std::string note;
};

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) f.push_back(cell);
  return f;
}

double parse_double(const std::string& s) {
  if (s == "inf") return std::numeric_limits<double>::infinity();
  return std::stod(s);
}

// A reference given as decimal text, split into hi + lo like the .bin files (hi the nearest
// double, lo the rest), so measure_error sees more than 53 bits of it.
void split_reference(const std::string& text, double& hi, double& lo) {
  const long double r = std::strtold(text.c_str(), nullptr);
  hi = static_cast<double>(r);
  lo = static_cast<double>(r - static_cast<long double>(hi));
}

// ---- R_D and R_J --------------------------------------------------------------------------------
struct carlson_set {
  std::vector<double> x, y, z, p;
};
template <class Policy> struct gecko_rd {
  static double eval(double x, double y, double z) {
    if constexpr (std::is_void_v<Policy>) return gecko::carlson_rd(x, y, z);
    else return gecko::carlson_rd(x, y, z, Policy());
  }
};
template <class Policy> struct gecko_rj {
  static double eval(double x, double y, double z, double p) {
    if constexpr (std::is_void_v<Policy>) return gecko::carlson_rj(x, y, z, p);
    else return gecko::carlson_rj(x, y, z, p, Policy());
  }
};
struct boost_rd {
  static double eval(double x, double y, double z) { return boost::math::ellint_rd(x, y, z, boost_policy()); }
};
struct boost_rj {
  static double eval(double x, double y, double z, double p) {
    return boost::math::ellint_rj(x, y, z, p, boost_policy());
  }
};
template <gsl_mode_t Mode> struct gsl_rd {
  static double eval(double x, double y, double z) { return gsl_sf_ellint_RD(x, y, z, Mode); }
};
template <gsl_mode_t Mode> struct gsl_rj {
  static double eval(double x, double y, double z, double p) { return gsl_sf_ellint_RJ(x, y, z, p, Mode); }
};
template <class K> void sweep3(const void* s, double* out, const visit_order& order) {
  const auto& c = *static_cast<const carlson_set*>(s);
  order.for_each(c.x.size(), [&](std::size_t i) { out[i] = K::eval(c.x[i], c.y[i], c.z[i]); });
}
template <class K> void sweep4(const void* s, double* out, const visit_order& order) {
  const auto& c = *static_cast<const carlson_set*>(s);
  order.for_each(c.x.size(), [&](std::size_t i) { out[i] = K::eval(c.x[i], c.y[i], c.z[i], c.p[i]); });
}

// ---- one elastica segment ------------------------------------------------------------------------
struct segment_case {
  double EI, EA, M, Fn, Ft, ts, te;
  int ss, se;
};
struct segment_set {
  std::vector<segment_case> c;
  std::vector<double> hi, lo;
};
template <class Policy> struct gecko_segment {
  static double eval(const segment_case& s) {
    if constexpr (std::is_void_v<Policy>)
      return gecko::elastica_segment_length(s.EI, s.EA, s.M, s.Fn, s.Ft, s.ts, s.te, s.ss, s.se);
    else
      return gecko::elastica_segment_length(s.EI, s.EA, s.M, s.Fn, s.Ft, s.ts, s.te, s.ss, s.se, Policy());
  }
};

// The peer's set-up, done inside every call (it is part of the method): the first integral
// R(theta) = M - N u - c N^2 u^2 / 2, u = sin(theta - phi), and the path from theta_start to
// theta_end with the signs of theta' at both ends, split at the turning angles (R = 0) it passes.
struct segment_path {
  double M, N, c, phi, scale;
  double pts[6];
  int count;
};
segment_path make_path(const segment_case& s) {
  segment_path p{};
  p.c = std::isinf(s.EA) ? 0.0 : 1.0 / s.EA;
  p.M = s.M;
  p.N = std::hypot(s.Fn, s.Ft);
  p.phi = std::atan2(s.Fn, s.Ft);
  p.scale = std::sqrt(s.EI / 2);
  const double root = std::sqrt(1 + 2 * p.c * s.M);
  const double up = 2 * s.M / (p.N * (1 + root));  // sin(theta - phi) at the turning angles
  p.pts[0] = s.ts;
  p.count = 1;
  if (!(up > -1 && up < 1)) {  // rotation: theta' never vanishes
    p.pts[p.count++] = s.te;
    return p;
  }
  const double tmax = p.phi + std::asin(up), tmin = p.phi - M_PI - std::asin(up);
  double cur = s.ts;
  int sg = s.ss;
  while (p.count < 5) {
    if (sg == s.se && ((sg > 0 && s.te >= cur) || (sg < 0 && s.te <= cur))) {
      p.pts[p.count++] = s.te;
      break;
    }
    cur = sg > 0 ? tmax : tmin;
    p.pts[p.count++] = cur;
    sg = -sg;
  }
  return p;
}
double inv_sqrt_r(double theta, const segment_path& p) {
  const double u = std::sin(theta - p.phi);
  return 1 / std::sqrt(std::fabs(p.M - p.N * u - p.c * p.N * p.N * u * u / 2));
}

struct gsl_quad_state {
  double epsrel;
  gsl_integration_workspace* ws;
};
double gsl_integrand(double t, void* p) { return inv_sqrt_r(t, *static_cast<const segment_path*>(p)); }
template <int Setting> struct gsl_segment {
  static gsl_quad_state& state();
  static double eval(const segment_case& s) {
    segment_path p = make_path(s);
    gsl_function f{&gsl_integrand, &p};
    double total = 0;
    for (int k = 0; k + 1 < p.count; ++k) {
      const double a = std::min(p.pts[k], p.pts[k + 1]), b = std::max(p.pts[k], p.pts[k + 1]);
      double r = 0, err = 0;
      gsl_integration_qags(&f, a, b, 0.0, state().epsrel, 1000, state().ws, &r, &err);
      total += r;
    }
    return p.scale * total;
  }
};
// Settings are template parameters so that each sweep is its own function (sweep_fn has no
// context); the workspace is allocated once per setting, outside the timing.
constexpr double gsl_quad_tols[] = {1e-6, 1e-10, 1e-13};
template <int Setting> gsl_quad_state& gsl_segment<Setting>::state() {
  static gsl_quad_state s{gsl_quad_tols[Setting], gsl_integration_workspace_alloc(1000)};
  return s;
}

constexpr double boost_quad_tols[] = {1e-6, 1e-10, 1e-14};
template <int Setting> struct boost_segment {
  static double eval(const segment_case& s) {
    static boost::math::quadrature::tanh_sinh<double> integrator;  // abscissas: built once
    const segment_path p = make_path(s);
    double total = 0;
    for (int k = 0; k + 1 < p.count; ++k) {
      const double a = std::min(p.pts[k], p.pts[k + 1]), b = std::max(p.pts[k], p.pts[k + 1]);
      if (!(b > a)) continue;
      total += integrator.integrate([&p](double t) { return inv_sqrt_r(t, p); }, a, b, boost_quad_tols[Setting]);
    }
    return p.scale * total;
  }
};
template <class K> void sweep_segment(const void* s, double* out, const visit_order& order) {
  const auto& set = *static_cast<const segment_set*>(s);
  order.for_each(set.c.size(), [&](std::size_t i) {
    try {
      out[i] = K::eval(set.c[i]);
    } catch (const std::exception&) {  // Boost's quadrature throws where the integrand blows up
      out[i] = std::numeric_limits<double>::quiet_NaN();
    }
  });
}

// ---- solve_critical at one Ft ------------------------------------------------------------------
struct seta_case {
  gecko::TwoLevelSeta<double> s;
  double Ft;
  long double Fn_ref;
  int branch;
  gecko::critical_guess<double> guess;
};
struct seta_set {
  std::vector<seta_case> c;
  double tol = 1e-12;  // the setting being swept
};

// GSL hybridsj on gecko's residual and exact Jacobian (gecko/seta/detail/seta_system.hpp), as in
// bench/seta/bench_seta.cpp, for one state; the plan (Carlson forms) is fixed at the guess.
template <class System>
struct gsl_ctx {
  const System* sys;
  double mu;
  typename System::plan_type plan;
};
template <class System>
int gsl_fdf(const gsl_vector* x, void* p, gsl_vector* f, gsl_matrix* J) {
  auto* c = static_cast<gsl_ctx<System>*>(p);
  typename System::vec z, F;
  typename System::mat Jz;
  double u14[2];
  for (int i = 0; i < 4; ++i) z[i] = gsl_vector_get(x, static_cast<std::size_t>(i));
  if (!c->sys->eval(z, c->mu, c->plan, F, Jz, nullptr, u14)) return GSL_EDOM;
  for (int i = 0; i < 4; ++i) {
    gsl_vector_set(f, static_cast<std::size_t>(i), F[i]);
    for (int j = 0; j < 4; ++j) gsl_matrix_set(J, static_cast<std::size_t>(i), static_cast<std::size_t>(j), Jz(i, j));
  }
  return GSL_SUCCESS;
}
template <class System>
int gsl_f(const gsl_vector* x, void* p, gsl_vector* f) {
  auto* c = static_cast<gsl_ctx<System>*>(p);
  typename System::vec z, F;
  for (int i = 0; i < 4; ++i) z[i] = gsl_vector_get(x, static_cast<std::size_t>(i));
  if (!c->sys->residual(z, c->mu, c->plan, F)) return GSL_EDOM;
  for (int i = 0; i < 4; ++i) gsl_vector_set(f, static_cast<std::size_t>(i), F[i]);
  return GSL_SUCCESS;
}
template <class System>
int gsl_df(const gsl_vector* x, void* p, gsl_matrix* J) {
  double buf[4];
  gsl_vector_view f = gsl_vector_view_array(buf, 4);
  return gsl_fdf<System>(x, p, &f.vector, J);
}
template <class System>
double gsl_solve(const seta_case& k, double tol) {
  const System sys(gecko::detail::make_seta_params(k.s));
  const auto& g = k.guess;
  const typename System::vec z0 = sys.from_guess(g.Fn, g.theta_joint, g.theta_rate_joint, g.theta_rate_base, k.Ft);
  gsl_ctx<System> ctx{&sys, sys.mu_of(k.Ft), {}};
  ctx.plan = sys.plan(z0, ctx.mu);
  gsl_multiroot_function_fdf fdf{&gsl_f<System>, &gsl_df<System>, &gsl_fdf<System>, 4, &ctx};
  static gsl_multiroot_fdfsolver* solver = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 4);
  double xb[4];
  for (int i = 0; i < 4; ++i) xb[i] = z0[i];
  gsl_vector_view x = gsl_vector_view_array(xb, 4);
  if (gsl_multiroot_fdfsolver_set(solver, &fdf, &x.vector)) return std::nan("");
  int status = GSL_CONTINUE;
  for (int it = 0; it < 100 && status == GSL_CONTINUE; ++it) {
    if (gsl_multiroot_fdfsolver_iterate(solver)) break;
    status = gsl_multiroot_test_delta(solver->dx, solver->x, 0.0, tol);
  }
  return status == GSL_SUCCESS ? gsl_vector_get(solver->x, 0) : std::nan("");
}
template <bool E1, bool E2>
using system_t = gecko::detail::seta_system<double, gecko::policies::default_policy, E1, E2>;

void sweep_gsl_solve(const void* p, double* out, const visit_order& order) {
  const auto& set = *static_cast<const seta_set*>(p);
  order.for_each(set.c.size(), [&](std::size_t i) {
    const auto& k = set.c[i];
    const bool e1 = !std::isinf(k.s.EA1), e2 = !std::isinf(k.s.EA2);
    out[i] = e1 ? (e2 ? gsl_solve<system_t<true, true>>(k, set.tol) : gsl_solve<system_t<true, false>>(k, set.tol))
                : (e2 ? gsl_solve<system_t<false, true>>(k, set.tol) : gsl_solve<system_t<false, false>>(k, set.tol));
  });
}
void sweep_gecko_solve(const void* p, double* out, const visit_order& order) {
  const auto& set = *static_cast<const seta_set*>(p);
  gecko::solve_options<double> opt;
  opt.tolerance = set.tol;
  order.for_each(set.c.size(), [&](std::size_t i) {
    const auto& k = set.c[i];
    const auto r = gecko::solve_critical(k.s, k.Ft, k.guess, opt);
    out[i] = r.status == gecko::critical_status::converged ? r.Fn : std::nan("");
  });
}
void sweep_gecko_solve_noguess(const void* p, double* out, const visit_order& order) {
  const auto& set = *static_cast<const seta_set*>(p);
  order.for_each(set.c.size(), [&](std::size_t i) {
    const auto r = gecko::solve_critical(set.c[i].s, set.c[i].Ft);
    out[i] = r.status == gecko::critical_status::converged ? r.Fn : std::nan("");
  });
}

seta_set load_seta_states(const std::string& path, double perturbation) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);
  seta_set set;
  while (std::getline(in, line)) {
    const auto f = split_csv_line(line);
    if (f.size() < 17) continue;
    seta_case k;
    k.s.EI1 = parse_double(f[1]); k.s.EI2 = parse_double(f[2]); k.s.EA1 = parse_double(f[3]);
    k.s.EA2 = parse_double(f[4]); k.s.l1 = parse_double(f[5]); k.s.l2 = parse_double(f[6]);
    k.s.alpha1 = parse_double(f[7]); k.s.alpha2 = parse_double(f[8]); k.s.w = parse_double(f[9]);
    k.Ft = parse_double(f[10]);
    k.Fn_ref = std::strtold(f[11].c_str(), nullptr);
    const double beta = parse_double(f[12]), rate_base = parse_double(f[13]);
    const int tp_spatula = std::stoi(f[15]);
    k.branch = std::stoi(f[16]);
    // The starting point: the reference state moved by `perturbation` (relative in Fn and the
    // base rate, absolute in beta), the joint rate from the spatula's first integral at the
    // moved state with the reference sign (the spatula arrives at the contact edge with
    // theta' > 0, so an odd number of turning points inside means theta' < 0 at the joint).
    const double Fn = static_cast<double>(k.Fn_ref) + perturbation * std::max(1.0, std::fabs(static_cast<double>(k.Fn_ref)));
    const double b = beta + perturbation;
    const double N = std::hypot(Fn, k.Ft), phi = std::atan2(Fn, k.Ft), u = std::sin(b - phi);
    const double c2 = std::isinf(k.s.EA2) ? 0.0 : 1.0 / k.s.EA2;
    const double R2 = std::max(0.0, k.Ft + k.s.w - N * u - c2 * N * N * u * u / 2);
    const double rate_joint = (tp_spatula % 2 ? -1.0 : 1.0) * std::sqrt(2 * R2 / k.s.EI2);
    k.guess = gecko::critical_guess<double>{Fn, b, rate_joint, rate_base * (1 + perturbation)};
    set.c.push_back(k);
  }
  return set;
}

// "status: 379 converged, 24 not_converged" from counts indexed by gecko::critical_status.
std::string status_text(const int (&counts)[6]) {
  const char* names[6] = {"converged", "not_converged", "no_critical_state", "unsupported_state", "singular",
                          "invalid_input"};
  std::string s = "status: " + std::to_string(counts[0]) + " converged";
  for (int k = 1; k < 6; ++k)
    if (counts[k]) s += ", " + std::to_string(counts[k]) + " " + names[k];
  return s;
}

struct seta_err {
  double max = 0, rms = 0;
  std::size_t failed = 0;
};
seta_err seta_errors(const std::vector<double>& got, const std::vector<long double>& ref) {
  seta_err e;
  long double sum = 0;
  std::size_t ok = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!std::isfinite(got[i])) {
      ++e.failed;
      continue;
    }
    const long double d = std::fabs(static_cast<long double>(got[i]) - ref[i]) / std::max(1.0L, std::fabs(ref[i]));
    e.max = std::max(e.max, static_cast<double>(d));
    sum += d * d;
    ++ok;
  }
  e.rms = ok ? static_cast<double>(std::sqrt(sum / static_cast<long double>(ok))) : 0.0;
  return e;
}

// ---- batch ------------------------------------------------------------------------------------
// Random designs: the distribution of tests/data/gen_seta_reference.py, as bench/seta's batch.
std::vector<gecko::TwoLevelSeta<double>> random_designs(int nd) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<gecko::TwoLevelSeta<double>> out;
  for (int k = 0; k < nd; ++k) {
    gecko::TwoLevelSeta<double> d;
    d.EI1 = std::exp(std::log(0.5) + U(rng) * std::log(100.0));
    d.EI2 = d.EI1 * std::exp(std::log(0.05) + U(rng) * std::log(40.0));
    d.EA1 = std::numeric_limits<double>::infinity();
    d.l1 = 1.0;
    d.l2 = 0.02 + 0.48 * U(rng);
    d.alpha1 = M_PI / 18 + U(rng) * (M_PI / 3 - M_PI / 18);
    d.alpha2 = U(rng) * (M_PI / 2 - 0.15 - d.alpha1);
    d.EA2 = std::exp(std::log(10.0) + U(rng) * std::log(100.0));
    d.w = 1.0;
    out.push_back(d);
  }
  return out;
}

double wall_ns() {
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int run(int argc, char** argv) {
  std::string out_path, data_dir = GECKO_TRADEOFF_DATA_DIR, tests_dir = GECKO_TESTS_DATA_DIR;
  int reps = 11, designs = 200;
  double target_ms = 20;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    if (a == "--out") out_path = next();
    else if (a == "--reps") reps = std::stoi(next());
    else if (a == "--target-ms") target_ms = std::stod(next());
    else if (a == "--designs") designs = std::stoi(next());
    else if (a == "--quick") quick = true;
    else {
      std::cerr << "usage: " << argv[0] << " --out FILE.csv [--reps N] [--target-ms MS] [--designs N] [--quick]\n";
      return 2;
    }
  }
  if (quick) {
    reps = std::min(reps, 3);
    target_ms = std::min(target_ms, 3.0);
    designs = std::min(designs, 20);
  }
  if (out_path.empty() || reps < 1 || target_ms <= 0 || designs < 1) {
    std::cerr << "need --out FILE.csv, --reps >= 1, --target-ms > 0, --designs >= 1\n";
    return 2;
  }
  gsl_set_error_handler_off();

  std::vector<timed_case> cases;
  struct pending {
    result_row row;
    std::size_t index;
    const std::vector<double>* hi;  // kernel reference (eps errors); null for the seta
    const std::vector<double>* lo;
  };
  std::vector<pending> rows;
  auto add = [&](result_row r, sweep_fn fn, const void* inputs, std::size_t n, const std::vector<double>* hi,
                 const std::vector<double>* lo) {
    r.n = n;
    rows.push_back({r, cases.size(), hi, lo});
    cases.push_back(timed_case{fn, inputs, n, {}, 1, {}, {}});
  };
  auto row = [](const std::string& family, const std::string& method, const std::string& setting,
                const std::string& input_set, const std::string& unit) {
    result_row r;
    r.family = family; r.method = method; r.setting = setting; r.input_set = input_set; r.unit = unit;
    return r;
  };

  // R_D, R_J
  const column_file rd(data_dir + "/carlson_rd.bin"), rj(data_dir + "/carlson_rj.bin");
  const carlson_set rd_set{rd["x"], rd["y"], rd["z"], {}};
  const carlson_set rj_set{rj["x"], rj["y"], rj["z"], rj["p"]};
  const std::string rd_name = "x,y,z log-U(1e-6,1e6), 5% x or y zero";
  const std::string rj_name = "x,y,z,p log-U(1e-6,1e6), 5% one of x,y,z zero";
  {
    const auto n = rd_set.x.size();
    const auto *hi = &rd["RD"], *lo = &rd["RD_lo"];
    auto R = [&](const std::string& m, const std::string& s) { return row("R_D", m, s, rd_name, "eps"); };
    add(R("gecko::carlson_rd", "full"), sweep3<gecko_rd<void>>, &rd_set, n, hi, lo);
    add(R("gecko::carlson_rd", "precision<48>"), sweep3<gecko_rd<precision<48>>>, &rd_set, n, hi, lo);
    add(R("gecko::carlson_rd", "precision<40>"), sweep3<gecko_rd<precision<40>>>, &rd_set, n, hi, lo);
    add(R("gecko::carlson_rd", "precision<32>"), sweep3<gecko_rd<precision<32>>>, &rd_set, n, hi, lo);
    add(R("gecko::carlson_rd", "precision<24>"), sweep3<gecko_rd<precision<24>>>, &rd_set, n, hi, lo);
    add(R("boost::math::ellint_rd", "promote_double<false>"), sweep3<boost_rd>, &rd_set, n, hi, lo);
    add(R("gsl_sf_ellint_RD", "GSL_PREC_DOUBLE"), sweep3<gsl_rd<GSL_PREC_DOUBLE>>, &rd_set, n, hi, lo);
    add(R("gsl_sf_ellint_RD", "GSL_PREC_SINGLE"), sweep3<gsl_rd<GSL_PREC_SINGLE>>, &rd_set, n, hi, lo);
    add(R("gsl_sf_ellint_RD", "GSL_PREC_APPROX"), sweep3<gsl_rd<GSL_PREC_APPROX>>, &rd_set, n, hi, lo);
  }
  {
    const auto n = rj_set.x.size();
    const auto *hi = &rj["RJ"], *lo = &rj["RJ_lo"];
    auto R = [&](const std::string& m, const std::string& s) { return row("R_J", m, s, rj_name, "eps"); };
    add(R("gecko::carlson_rj", "full"), sweep4<gecko_rj<void>>, &rj_set, n, hi, lo);
    add(R("gecko::carlson_rj", "precision<48>"), sweep4<gecko_rj<precision<48>>>, &rj_set, n, hi, lo);
    add(R("gecko::carlson_rj", "precision<40>"), sweep4<gecko_rj<precision<40>>>, &rj_set, n, hi, lo);
    add(R("gecko::carlson_rj", "precision<32>"), sweep4<gecko_rj<precision<32>>>, &rj_set, n, hi, lo);
    add(R("gecko::carlson_rj", "precision<24>"), sweep4<gecko_rj<precision<24>>>, &rj_set, n, hi, lo);
    add(R("boost::math::ellint_rj", "promote_double<false>"), sweep4<boost_rj>, &rj_set, n, hi, lo);
    add(R("gsl_sf_ellint_RJ", "GSL_PREC_DOUBLE"), sweep4<gsl_rj<GSL_PREC_DOUBLE>>, &rj_set, n, hi, lo);
    add(R("gsl_sf_ellint_RJ", "GSL_PREC_SINGLE"), sweep4<gsl_rj<GSL_PREC_SINGLE>>, &rj_set, n, hi, lo);
    add(R("gsl_sf_ellint_RJ", "GSL_PREC_APPROX"), sweep4<gsl_rj<GSL_PREC_APPROX>>, &rj_set, n, hi, lo);
  }

  // Segment lengths: all 160 test segments, and the 73 without a turning point inside (where the
  // quadrature peers integrate a smooth function: their best case).
  segment_set seg_all, seg_mono;
  {
    const std::string path = tests_dir + "/seta_solver_segments.csv";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      const auto f = split_csv_line(line);
      if (f.size() < 11) continue;
      const segment_case c{parse_double(f[0]), parse_double(f[1]), parse_double(f[2]), parse_double(f[3]),
                           parse_double(f[4]), parse_double(f[5]), parse_double(f[6]), std::stoi(f[7]), std::stoi(f[8])};
      double hi, lo;
      split_reference(f[10], hi, lo);
      for (segment_set* set : {&seg_all, &seg_mono}) {
        if (set == &seg_mono && std::stoi(f[9]) != 0) continue;
        set->c.push_back(c);
        set->hi.push_back(hi);
        set->lo.push_back(lo);
      }
    }
  }
  for (const segment_set* set : {&seg_all, &seg_mono}) {
    const std::string set_name = set == &seg_all
        ? "tests/data/seta_solver_segments.csv, all " + std::to_string(set->c.size()) + " (0-2 turning points)"
        : "tests/data/seta_solver_segments.csv, the " + std::to_string(set->c.size()) + " without turning points";
    const auto n = set->c.size();
    const auto *hi = &set->hi, *lo = &set->lo;
    auto R = [&](const std::string& m, const std::string& s) { return row("segment length", m, s, set_name, "eps"); };
    const std::string g = "gecko::elastica_segment_length";
    add(R(g, "full"), sweep_segment<gecko_segment<void>>, set, n, hi, lo);
    add(R(g, "precision<48>"), sweep_segment<gecko_segment<precision<48>>>, set, n, hi, lo);
    add(R(g, "precision<40>"), sweep_segment<gecko_segment<precision<40>>>, set, n, hi, lo);
    add(R(g, "precision<32>"), sweep_segment<gecko_segment<precision<32>>>, set, n, hi, lo);
    add(R(g, "precision<24>"), sweep_segment<gecko_segment<precision<24>>>, set, n, hi, lo);
    const std::string gq = "GSL QAGS of the first integral";
    add(R(gq, "epsrel 1e-06"), sweep_segment<gsl_segment<0>>, set, n, hi, lo);
    add(R(gq, "epsrel 1e-10"), sweep_segment<gsl_segment<1>>, set, n, hi, lo);
    add(R(gq, "epsrel 1e-13"), sweep_segment<gsl_segment<2>>, set, n, hi, lo);
    const std::string bq = "Boost tanh_sinh of the first integral";
    add(R(bq, "tol 1e-06"), sweep_segment<boost_segment<0>>, set, n, hi, lo);
    add(R(bq, "tol 1e-10"), sweep_segment<boost_segment<1>>, set, n, hi, lo);
    add(R(bq, "tol 1e-14"), sweep_segment<boost_segment<2>>, set, n, hi, lo);
  }

  // solve_critical from a guess 1e-2 away (relative), and without a guess.
  const double perturbation = 1e-2;
  const seta_set states = load_seta_states(tests_dir + "/seta_reference.csv", perturbation);
  std::vector<long double> fn_ref;
  for (const auto& k : states.c) fn_ref.push_back(k.Fn_ref);
  const std::vector<double> gecko_tols = {1e-3, 1e-6, 1e-9, 1e-12, 1e-14};
  const std::vector<double> gsl_tols = {1e-4, 1e-6, 1e-9, 1e-12};
  std::vector<seta_set> solve_sets;  // one copy per setting (the tolerance travels with the inputs)
  solve_sets.reserve(gecko_tols.size() + gsl_tols.size() + 1);
  const std::string states_name = "tests/data/seta_reference.csv (" + std::to_string(states.c.size()) + " states)";
  auto tol_text = [](const char* prefix, double t) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s %.0e", prefix, t);
    return std::string(buf);
  };
  for (double t : gecko_tols) {
    solve_sets.push_back(states);
    solve_sets.back().tol = t;
    add(row("solve_critical", "gecko::solve_critical, guess 1e-2 off", tol_text("tolerance", t), states_name, "rel"),
        sweep_gecko_solve, &solve_sets.back(), states.c.size(), nullptr, nullptr);
  }
  for (double t : gsl_tols) {
    solve_sets.push_back(states);
    solve_sets.back().tol = t;
    add(row("solve_critical", "GSL hybridsj, same residual, guess 1e-2 off", tol_text("test_delta", t), states_name,
            "rel"),
        sweep_gsl_solve, &solve_sets.back(), states.c.size(), nullptr, nullptr);
  }
  // Without a guess: follows the line from Ft = 0; only the states on the first crossing (branch 0).
  seta_set branch0;
  std::vector<long double> fn_ref0;
  for (const auto& k : states.c)
    if (k.branch == 0) {
      branch0.c.push_back(k);
      fn_ref0.push_back(k.Fn_ref);
    }
  const std::string branch0_name = branch0.c.size() == states.c.size()
      ? states_name : "tests/data/seta_reference.csv, " + std::to_string(branch0.c.size()) + " first-crossing states";
  add(row("solve_critical", "gecko::solve_critical, no guess (line from Ft=0)", "tolerance 1e-12", branch0_name, "rel"),
      sweep_gecko_solve_noguess, &branch0, branch0.c.size(), nullptr, nullptr);

  std::cerr << "timing " << cases.size() << " cases x " << reps << " repetitions of >= " << target_ms << " ms\n";
  const double checksum = time_cases(cases, reps, target_ms);

  std::vector<result_row> out;
  for (auto& p : rows) {
    const auto& c = cases[p.index];
    result_row r = p.row;
    r.ns = c.result.median_ns;
    r.q1 = c.result.q1_ns;
    r.q3 = c.result.q3_ns;
    if (p.hi) {
      // Kernels: the max over the finite results, failures (NaN/inf) counted apart.
      const error_stats e = measure_error(c.out, *p.hi, *p.lo, nullptr);
      std::vector<double> finite_got, fhi, flo;
      for (std::size_t i = 0; i < c.out.size(); ++i)
        if (std::isfinite(c.out[i])) {
          finite_got.push_back(c.out[i]);
          fhi.push_back((*p.hi)[i]);
          flo.push_back((*p.lo)[i]);
        }
      const error_stats ef = measure_error(finite_got, fhi, flo, nullptr);
      r.max_err = ef.max_eps;
      r.rms_err = ef.rms_eps;
      r.failed = e.nonfinite;
    } else {
      const auto& ref = c.inputs == &branch0 ? fn_ref0 : fn_ref;
      const seta_err e = seta_errors(c.out, ref);
      r.max_err = e.max;
      r.rms_err = e.rms;
      r.failed = e.failed;
      if (p.row.method == "gecko::solve_critical, guess 1e-2 off") {
        // Why states failed: gecko says so in its status (re-solved here, untimed).
        const auto* set = static_cast<const seta_set*>(c.inputs);
        gecko::solve_options<double> opt;
        opt.tolerance = set->tol;
        int counts[6] = {0, 0, 0, 0, 0, 0};
        for (const auto& k : set->c) ++counts[static_cast<int>(gecko::solve_critical(k.s, k.Ft, k.guess, opt).status)];
        r.note = status_text(counts);
      }
      if (p.row.method.rfind("GSL hybridsj", 0) == 0) {
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < c.out.size(); ++i)
          if (std::isfinite(c.out[i]) &&
              std::fabs(static_cast<long double>(c.out[i]) - ref[i]) > 1e-3L * std::max(1.0L, std::fabs(ref[i])))
            ++wrong;
        r.note = std::to_string(wrong) + " reported converged but wrong (|dFn| > 1e-3 max(1,|Fn|))";
      }
    }
    out.push_back(r);
  }

  // Batch: wall time (2 threads), median of the repetitions; errors by ODE shooting.
  {
    const auto ds = random_designs(designs);
    const int nft = 20;
    const int breps = quick ? 1 : 5;
    const int check_every = quick ? 1 : 4;
    std::vector<double> ft(nft);
    std::vector<gecko::critical_state<double>> res(ds.size() * nft);
    // Ft shared by all designs (critical_line_batch's contract): up to 0.99 of the smallest (Ft)max.
    double ftm = std::numeric_limits<double>::infinity();
    for (const auto& d : ds) ftm = std::min(ftm, gecko::ft_max(d));
    for (int j = 0; j < nft; ++j) ft[static_cast<std::size_t>(j)] = 0.99 * ftm * j / (nft - 1);
    for (double tol : {1e-6, 1e-12}) {
      gecko::critical_line_options<double> opt;
      opt.tolerance = tol;
      std::vector<double> times[2];
      std::vector<double> fn[2];
      // Warm-up (page-in, thread start-up paths), not timed.
      gecko::critical_line_batch(ds.data(), ds.size(), ft.data(), ft.size(), res.data(), 2u, opt);
      for (int r = 0; r < breps; ++r)
        for (unsigned th : {1u, 2u}) {
          const double t0 = wall_ns();
          gecko::critical_line_batch(ds.data(), ds.size(), ft.data(), ft.size(), res.data(), th, opt);
          times[th - 1].push_back(wall_ns() - t0);
          fn[th - 1].resize(res.size());
          for (std::size_t i = 0; i < res.size(); ++i)
            fn[th - 1][i] = res[i].status == gecko::critical_status::converged ? res[i].Fn : std::nan("");
        }
      // Error against the long-double ODE shooting (independent of gecko): every state of every
      // `check_every`-th design (the shooting costs ~1 ms a state; all designs in --quick).
      double worst = 0;
      long double sum = 0;
      std::size_t failed = 0, ok = 0;
      int counts[6] = {0, 0, 0, 0, 0, 0};
      for (const auto& st : res) ++counts[static_cast<int>(st.status)];
      for (std::size_t i = 0; i < res.size(); ++i) {
        const double v = fn[0][i];
        if (!std::isfinite(v)) {
          ++failed;
          continue;
        }
        if ((i / nft) % static_cast<std::size_t>(check_every) != 0) continue;
        const long double e = std::fabs(seta_test::fn_error(ds[i / nft], v, ft[i % nft])) / std::max(1.0, std::fabs(v));
        worst = std::max(worst, static_cast<double>(e));
        sum += e * e;
        ++ok;
      }
      const bool identical = fn[0].size() == fn[1].size() &&
                             std::equal(fn[0].begin(), fn[0].end(), fn[1].begin(),
                                        [](double a, double b) { return a == b || (a != a && b != b); });
      for (unsigned th : {1u, 2u}) {
        result_row r;
        r.family = "batch";
        r.method = "gecko::critical_line_batch, " + std::to_string(th) + (th == 1 ? " thread" : " threads");
        r.setting = tol_text("tolerance", tol);
        r.input_set = std::to_string(designs) + " random designs x 20 Ft up to 0.99 min (Ft)max";
        r.n = ds.size();
        r.ns = quantile(times[th - 1], 0.5) / static_cast<double>(ds.size());  // per design (20 states)
        r.q1 = quantile(times[th - 1], 0.25) / static_cast<double>(ds.size());
        r.q3 = quantile(times[th - 1], 0.75) / static_cast<double>(ds.size());
        r.max_err = worst;
        r.rms_err = ok ? static_cast<double>(std::sqrt(sum / static_cast<long double>(ok))) : 0.0;
        r.unit = "rel";
        r.failed = failed;
        char buf[160];
        std::snprintf(buf, sizeof buf, "%.0f designs/s (wall, median of %d); %zu states checked by shooting; ",
                      1e9 / r.ns, breps, ok);
        r.note = std::string(buf) + status_text(counts) + "; threads bitwise identical: " + (identical ? "yes" : "NO");
        out.push_back(r);
      }
    }
  }

  std::ofstream csv(out_path);
  csv << "family,method,setting,input_set,n,time_per_call_ns,time_q1_ns,time_q3_ns,max_err,rms_err,unit,failed,"
         "source,note\n";
  for (const auto& r : out) {
    char nums[256];
    std::snprintf(nums, sizeof nums, "%zu,%.6g,%.6g,%.6g,%.6g,%.6g", r.n, r.ns, r.q1, r.q3, r.max_err, r.rms_err);
    csv << csv_text(r.family) << "," << csv_text(r.method) << "," << csv_text(r.setting) << ","
        << csv_text(r.input_set) << "," << nums << "," << r.unit << "," << r.failed << ",bench_tradeoff,"
        << csv_text(r.note) << "\n";
    std::fprintf(stderr, "%-15s %-48s %-22s %12.1f ns  max err %-10.3g %s  failed %zu\n", r.family.c_str(),
                 r.method.c_str(), r.setting.c_str(), r.ns, r.max_err, r.unit.c_str(), r.failed);
  }
  if (!csv) throw std::runtime_error("cannot write " + out_path);
  std::cerr << "compiler g++ " << __VERSION__ << ", flags " << GECKO_TRADEOFF_CXX_FLAGS << ", Boost "
            << BOOST_LIB_VERSION << ", GSL " << GSL_VERSION << "; checksum " << checksum << "\n";
  // Machine-readable build facts for run.py (one line, key=value).
  std::cout << "\nBUILD compiler=g++ " << __VERSION__ << "|flags=" << GECKO_TRADEOFF_CXX_FLAGS
            << "|boost=" << BOOST_LIB_VERSION << "|gsl=" << GSL_VERSION << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gecko_bench::guarded_main("bench_tradeoff", run, argc, argv); }
