// bench/seta/bench_seta.cpp — run time against error of the two-level seta critical line.
//
// Reference scene (docs/theory/two_level_seta.md), a 1000-point critical line Ft = linspace(0, 9.9, 1000):
//   * gecko::critical_line_at at several Newton tolerances (the whole call: natural state by
//     homotopy, continuation, chord steps from the traced line's nodes per point);
//   * GSL gsl_multiroot_fdfsolver_hybridsj (Powell's hybrid method with the Jacobian) driving the
//     same residual and Jacobian (gecko/seta/critical_equations.hpp's system), natural
//     continuation point to point from the previous solution, at several tolerances;
//   * the batch call (many designs x many Ft) on 1 and 2 threads, designs per second.
// The scipy peer (bench/seta/scipy_peer.py) is timed by bench/seta/peer_scipy.py in
// the same run (bench/seta/run.sh).
//
// Error: every method's Fn is checked by an independent route — RK4 shooting of the governing ODE
// in long double (6000 steps per unit length), giving |dFn| = |theta1(0) - alpha1| / |dtheta1(0)/dFn|,
// accurate to ~1e-15 — and reported as max |dFn| / max(1, |Fn|) over the 1000 points.
// Timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID; wall time for the 2-thread batch), median of
// repetitions, methods interleaved so load changes on this shared machine hit all alike.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "gecko/seta.hpp"
#include "harness.hpp"  // bench/harness.hpp: the benchmarks' one timing harness

namespace {

using gecko_bench::median;
using gecko_bench::thread_cpu_ns;
using gecko_bench::wall_ns;

// ---- independent check: RK4 shooting (as tests/seta/seta_shooting.hpp) ----------------------
long double rhs(long double th, long double EI, long double c, long double Fn, long double Ft) {
  const long double T = Ft * std::sin(th) - Fn * std::cos(th);
  return -(Fn * std::sin(th) + Ft * std::cos(th)) * (1 + T * c) / EI;
}
void back(long double& th, long double& om, long double len, long double EI, long double c, long double Fn,
          long double Ft, int n) {
  const long double h = -len / n;
  for (int i = 0; i < n; ++i) {
    const long double k1t = om, k1o = rhs(th, EI, c, Fn, Ft);
    const long double k2t = om + h / 2 * k1o, k2o = rhs(th + h / 2 * k1t, EI, c, Fn, Ft);
    const long double k3t = om + h / 2 * k2o, k3o = rhs(th + h / 2 * k2t, EI, c, Fn, Ft);
    const long double k4t = om + h * k3o, k4o = rhs(th + h * k3t, EI, c, Fn, Ft);
    th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    om += h / 6 * (k1o + 2 * k2o + 2 * k3o + k4o);
  }
}
long double base_angle(const gecko::TwoLevelSeta<double>& s, long double Fn, long double Ft) {
  const long double c1 = std::isinf(s.EA1) ? 0.0L : 1.0L / s.EA1, c2 = std::isinf(s.EA2) ? 0.0L : 1.0L / s.EA2;
  long double th = 1.570796326794896619231321691639751442L;
  long double om = std::sqrt(2 * (s.w - Ft * Ft * c2 / 2) / s.EI2);
  back(th, om, s.l2, s.EI2, c2, Fn, Ft, std::max(200, static_cast<int>(6000 * s.l2)));
  th -= s.alpha2;
  om *= s.EI2 / s.EI1;
  back(th, om, s.l1, s.EI1, c1, Fn, Ft, static_cast<int>(6000 * s.l1));
  return th;
}
double fn_error(const gecko::TwoLevelSeta<double>& s, double Fn, double Ft) {
  const long double a = base_angle(s, Fn, Ft);
  const long double h = 1e-6L * std::max(1.0L, std::fabs(static_cast<long double>(Fn)));
  const long double b = base_angle(s, Fn + h, Ft);
  return static_cast<double>((a - s.alpha1) / ((b - a) / h));
}

// ---- GSL hybridsj on the same residual -------------------------------------------------------
using System = gecko::detail::seta_system<double, gecko::policies::default_policy, false, true>;
struct gsl_ctx {
  const System* sys;
  double mu;
  System::plan_type plan;
};
int gsl_f(const gsl_vector* x, void* p, gsl_vector* f) {
  auto* c = static_cast<gsl_ctx*>(p);
  System::vec z, F;
  for (int i = 0; i < 4; ++i) z[i] = gsl_vector_get(x, i);
  if (!c->sys->residual(z, c->mu, c->plan, F)) return GSL_EDOM;
  for (int i = 0; i < 4; ++i) gsl_vector_set(f, i, F[i]);
  return GSL_SUCCESS;
}
int gsl_fdf(const gsl_vector* x, void* p, gsl_vector* f, gsl_matrix* J) {
  auto* c = static_cast<gsl_ctx*>(p);
  System::vec z, F;
  System::mat Jz;
  double u14[2];
  for (int i = 0; i < 4; ++i) z[i] = gsl_vector_get(x, i);
  if (!c->sys->eval(z, c->mu, c->plan, F, Jz, nullptr, u14)) return GSL_EDOM;
  for (int i = 0; i < 4; ++i) {
    gsl_vector_set(f, i, F[i]);
    for (int j = 0; j < 4; ++j) gsl_matrix_set(J, i, j, Jz(i, j));
  }
  return GSL_SUCCESS;
}
int gsl_df(const gsl_vector* x, void* p, gsl_matrix* J) {
  gsl_vector* f = gsl_vector_alloc(4);
  const int r = gsl_fdf(x, p, f, J);
  gsl_vector_free(f);
  return r;
}

// The GSL peer: natural continuation, previous solution as the guess, plan refreshed per point.
void gsl_line(const gecko::TwoLevelSeta<double>& s, const std::vector<double>& Ft, double tol,
              std::vector<double>& Fn, long& evaluations) {
  const System sys(gecko::detail::make_seta_params(s));
  // Start from the library's natural state (the GSL peer has no homotopy of its own).
  const auto start = gecko::solve_critical(s, 0.0);
  System::vec z = sys.from_guess(start.Fn, start.theta_joint, start.theta_rate_joint, start.theta_rate_base, 0.0);
  gsl_multiroot_fdfsolver* solver = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 4);
  gsl_vector* x = gsl_vector_alloc(4);
  Fn.assign(Ft.size(), std::nan(""));
  evaluations = 0;
  for (std::size_t k = 0; k < Ft.size(); ++k) {
    gsl_ctx ctx{&sys, sys.mu_of(Ft[k]), {}};
    ctx.plan = sys.plan(z, ctx.mu);
    gsl_multiroot_function_fdf fdf{&gsl_f, &gsl_df, &gsl_fdf, 4, &ctx};
    for (int i = 0; i < 4; ++i) gsl_vector_set(x, i, z[i]);
    gsl_multiroot_fdfsolver_set(solver, &fdf, x);
    int status = GSL_CONTINUE;
    for (int it = 0; it < 100 && status == GSL_CONTINUE; ++it) {
      if (gsl_multiroot_fdfsolver_iterate(solver)) break;
      status = gsl_multiroot_test_delta(solver->dx, solver->x, 0.0, tol);
    }
    evaluations += static_cast<long>(solver->state ? 0 : 0);
    for (int i = 0; i < 4; ++i) z[i] = gsl_vector_get(solver->x, i);
    if (status == GSL_SUCCESS) Fn[k] = z[0];
  }
  gsl_vector_free(x);
  gsl_multiroot_fdfsolver_free(solver);
}

struct row {
  std::string method, setting;
  double us_per_point;
  double max_err;
  int failed;
};

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "bench/results";
  int reps = 7;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) out_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
  }
  gsl_set_error_handler_off();
  const gecko::TwoLevelSeta<double> s;
  const int n = 1000;
  std::vector<double> Ft(n);
  for (int i = 0; i < n; ++i) Ft[i] = 9.9 * i / (n - 1);

  const std::vector<double> gecko_tols = {1e-3, 1e-5, 1e-7, 1e-9, 1e-12, 1e-14};
  const std::vector<double> gsl_tols = {1e-6, 1e-9, 1e-12};
  struct method {
    std::string name, setting;
    std::function<void(std::vector<double>&)> run;
  };
  std::vector<method> methods;
  for (double tol : gecko_tols) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "tolerance %.0e", tol);
    methods.push_back({"gecko::critical_line_at", buf, [&, tol](std::vector<double>& fn) {
      gecko::critical_line_options<double> o;
      o.tolerance = tol;
      const auto r = gecko::critical_line_at(s, Ft, o);
      fn.resize(r.size());
      for (std::size_t i = 0; i < r.size(); ++i) fn[i] = r[i].status == gecko::critical_status::converged ? r[i].Fn : std::nan("");
    }});
  }
  for (double tol : gsl_tols) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "test_delta %.0e", tol);
    methods.push_back({"GSL hybridsj, same residual", buf, [&, tol](std::vector<double>& fn) {
      long ev = 0;
      gsl_line(s, Ft, tol, fn, ev);
    }});
  }
  std::vector<std::vector<double>> times(methods.size());
  std::vector<std::vector<double>> results(methods.size());
  for (int r = 0; r < reps; ++r) {
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const std::size_t m = (k + static_cast<std::size_t>(r)) % methods.size();
      const double t0 = thread_cpu_ns();
      methods[m].run(results[m]);
      times[m].push_back((thread_cpu_ns() - t0) / n / 1000.0);
    }
  }
  std::vector<row> rows;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    double worst = 0;
    int failed = 0;
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(results[m][i])) {
        ++failed;
        continue;
      }
      const double e = std::fabs(fn_error(s, results[m][i], Ft[i])) / std::max(1.0, std::fabs(results[m][i]));
      worst = std::max(worst, e);
    }
    rows.push_back({methods[m].name, methods[m].setting, median(times[m]), worst, failed});
    std::printf("%-30s %-20s %9.3f us/point  max err %.2e  failed %d\n", methods[m].name.c_str(),
                methods[m].setting.c_str(), median(times[m]), worst, failed);
  }

  // Batch: random designs (the distribution of tests/data/gen_seta_reference.py), 20 Ft each.
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<double> designs;
  const int nd = 200;
  for (int k = 0; k < nd; ++k) {
    const double EI1 = std::exp(std::log(0.5) + U(rng) * std::log(100.0));
    const double EI2 = EI1 * std::exp(std::log(0.05) + U(rng) * std::log(40.0));
    const double l2 = 0.02 + 0.48 * U(rng);
    const double a1 = M_PI / 18 + U(rng) * (M_PI / 3 - M_PI / 18);
    const double a2 = U(rng) * (M_PI / 2 - 0.15 - a1);
    const double EA2 = std::exp(std::log(10.0) + U(rng) * std::log(100.0));
    designs.insert(designs.end(), {EI1, EI2, std::numeric_limits<double>::infinity(), EA2, 1.0, l2, a1, a2, 1.0});
  }
  auto batch = [&](int threads) {
    std::vector<double> fn(static_cast<std::size_t>(nd) * 20);
    auto work = [&](int t) {
      for (int k = t; k < nd; k += threads) {
        gecko::TwoLevelSeta<double> d;
        const double* p = &designs[static_cast<std::size_t>(9 * k)];
        d.EI1 = p[0]; d.EI2 = p[1]; d.EA1 = p[2]; d.EA2 = p[3]; d.l1 = p[4]; d.l2 = p[5];
        d.alpha1 = p[6]; d.alpha2 = p[7]; d.w = p[8];
        std::vector<double> ft(20);
        for (int j = 0; j < 20; ++j) ft[static_cast<std::size_t>(j)] = 0.99 * gecko::ft_max(d) * j / 19.0;
        const auto r = gecko::critical_line_at(d, ft);
        for (int j = 0; j < 20; ++j) fn[static_cast<std::size_t>(20 * k + j)] = r[static_cast<std::size_t>(j)].Fn;
      }
    };
    const double t0 = wall_ns();
    if (threads == 1) work(0);
    else {
      std::vector<std::thread> pool;
      for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
      for (auto& th : pool) th.join();
    }
    return std::make_pair((wall_ns() - t0) * 1e-9, fn);
  };
  std::vector<double> t1, t2;
  std::vector<double> fn1, fn2;
  for (int r = 0; r < 3; ++r) {
    auto a = batch(1);
    auto b = batch(2);
    t1.push_back(a.first);
    t2.push_back(b.first);
    fn1 = a.second;
    fn2 = b.second;
  }
  const bool identical = std::memcmp(fn1.data(), fn2.data(), fn1.size() * sizeof(double)) == 0;
  const double dps1 = nd / median(t1), dps2 = nd / median(t2);
  std::printf("batch: %d designs x 20 Ft: %.0f designs/s (1 thread), %.0f designs/s (2 threads), identical %d\n",
              nd, dps1, dps2, identical);

  const std::string load = gecko_bench::load_average();  // for the record
  std::ofstream csv(out_dir + "/seta.csv");
  csv << "method,setting,us_per_point,max_rel_err_Fn,failed_points\n";
  for (const auto& r : rows) csv << r.method << "," << r.setting << "," << r.us_per_point << "," << r.max_err << "," << r.failed << "\n";
  csv << "batch 200 designs x 20 Ft,1 thread," << 1e6 / (dps1 * 20) << ",,\n";
  csv << "batch 200 designs x 20 Ft,2 threads," << 1e6 / (dps2 * 20) << ",,\n";
  std::ofstream md(out_dir + "/seta.md");
  md << "# Two-level seta critical line: run time and error (bench/seta)\n\n";
  md << "Generated by `bench/seta/run.sh` (binary `bench_seta`). Reference scene (docs/theory/two_level_seta.md), "
        "1000-point line Ft = linspace(0, 9.9, 1000), natural state and continuation included in every gecko call.\n\n";
  md << "- Load average at the end: " << load << " (shared 2-core machine; compare ratios within one run).\n";
  md << "- Error: max |dFn| / max(1, |Fn|) over the 1000 points, measured by an independent RK4 shooting of the "
        "governing ODE in long double (not by gecko itself).\n";
  md << "- Timing: thread CPU time per point, median of " << reps << " repetitions, methods interleaved.\n";
  md << "- What the gecko tolerance changes: each point starts from the cubic Hermite guess of the traced line "
        "(accurate to ~1e-7) and takes chord steps, residuals without a Jacobian, with the Jacobian interpolated "
        "between the two nodes around it (gecko/seta/detail/line_output.hpp); a step is the last one when it is "
        "below the tolerance and at most a quarter of the step before it. Every setting so takes at least two "
        "residuals per point (the second step is already ~1e-12 or below), the tight settings a third where it "
        "is not below them; Newton from the guess where the chord steps do not settle a point.\n\n";
  md << "| method | setting | us/point | max rel. error of Fn | failed points |\n|---|---|---:|---:|---:|\n";
  for (const auto& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "| %s | %s | %.3f | %.1e | %d |\n", r.method.c_str(), r.setting.c_str(),
                  r.us_per_point, r.max_err, r.failed);
    md << buf;
  }
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "\nBatch (%d random designs x 20 Ft up to 0.99 (Ft)max, wall time): %.0f designs/s on 1 thread, "
                "%.0f designs/s on 2 threads; results bitwise identical: %s.\n",
                nd, dps1, dps2, identical ? "yes" : "NO");
  md << buf;
  return 0;
}
