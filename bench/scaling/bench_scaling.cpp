// bench/scaling/bench_scaling.cpp — throughput and scaling of the two-level seta critical line
// (issue 6 item 2), through the batch call gecko::critical_line_batch (gecko/seta/batch.hpp).
//
//   * lines/s for the reference scene (docs/theory/two_level_seta.md defaults) and for random designs (the box of
//     bench/seta/bench_seta.cpp), 1 and 2 threads, results compared bitwise between thread counts;
//   * time against points per line (reference scene, one design) and against designs per batch
//     (random designs, 20 points each), with a least-squares fit of log t against log n (slope 1:
//     linear) and of t = a + b n (b: the per-point / per-design cost, a: the fixed cost);
//   * memory per design: peak RSS (VmHWM of /proc/self/status) of a freshly exec'd copy of this
//     program before and after one batch of N designs, against the analytic bytes of the input and output arrays.
// Timing: lines/s from the wall time (steady_clock) of the whole batch call (the process CPU time
// beside it); the scaling runs (1 thread) in CPU time of the calling thread, which the other jobs
// on this shared machine disturb far less than wall time. Medians of repetitions; the sizes are
// interleaved across repetitions so that load changes hit all sizes alike.
// Output: one CSV line per measurement on stdout (parsed by bench/scaling/report.py).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "gecko/seta/batch.hpp"
#include "harness.hpp"  // bench/harness.hpp: the benchmarks' one timing harness

namespace {

using seta = gecko::TwoLevelSeta<double>;
using state = gecko::critical_state<double>;

using gecko_bench::median;
double now_s() { return gecko_bench::wall_seconds(); }

// The random-design box of bench/seta/bench_seta.cpp (and tests/data/gen_seta_reference.py).
std::vector<seta> random_designs(std::size_t n, unsigned long long seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<seta> out(n);
  for (auto& d : out) {
    d.EI1 = std::exp(std::log(0.5) + U(rng) * std::log(100.0));
    d.EI2 = d.EI1 * std::exp(std::log(0.05) + U(rng) * std::log(40.0));
    d.l2 = 0.02 + 0.48 * U(rng);
    d.alpha1 = M_PI / 18 + U(rng) * (M_PI / 3 - M_PI / 18);
    d.alpha2 = U(rng) * (M_PI / 2 - 0.15 - d.alpha1);
    d.EA2 = std::exp(std::log(10.0) + U(rng) * std::log(100.0));
    d.EA1 = std::numeric_limits<double>::infinity();
    d.l1 = 1;
    d.w = 1;
  }
  return out;
}

// The batch call shares one Ft grid among designs; for random designs it goes up to 0.99 of the
// smallest (Ft)max of the box, sqrt(2 * 10 * 1) (every design's line reaches it).
std::vector<double> grid(double hi, std::size_t n) {
  std::vector<double> ft(n);
  for (std::size_t i = 0; i < n; ++i) ft[i] = n > 1 ? hi * static_cast<double>(i) / static_cast<double>(n - 1) : 0;
  return ft;
}
const double random_ft_hi = 0.99 * std::sqrt(20.0);

double cpu_s(clockid_t clock) { return gecko_bench::cpu_seconds(clock); }

// Seconds of one batch call: wall, CPU of the calling thread (with threads = 1 the batch runs in
// it: the work itself, not the time other jobs held the core), CPU of the process (all threads).
struct timing {
  double wall, thread_cpu, process_cpu;
};

timing run_batch(const std::vector<seta>& d, const std::vector<double>& ft, unsigned threads, std::vector<state>& out) {
  out.assign(d.size() * ft.size(), state());
  const double w0 = now_s(), t0 = cpu_s(CLOCK_THREAD_CPUTIME_ID), p0 = cpu_s(CLOCK_PROCESS_CPUTIME_ID);
  gecko::critical_line_batch(d.data(), d.size(), ft.data(), ft.size(), out.data(), threads);
  return {now_s() - w0, cpu_s(CLOCK_THREAD_CPUTIME_ID) - t0, cpu_s(CLOCK_PROCESS_CPUTIME_ID) - p0};
}

bool same_bits(const std::vector<state>& a, const std::vector<state>& b, std::size_t& converged) {
  if (a.size() != b.size()) return false;
  converged = 0;
  auto eq = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (std::size_t i = 0; i < a.size(); ++i) {
    const state &x = a[i], &y = b[i];
    if (!(eq(x.Ft, y.Ft) && eq(x.Fn, y.Fn) && eq(x.theta_joint, y.theta_joint) && x.status == y.status &&
          x.iterations == y.iterations && eq(x.theta_rate_joint, y.theta_rate_joint) &&
          eq(x.theta_rate_base, y.theta_rate_base) && x.turning_points_beam == y.turning_points_beam &&
          x.turning_points_spatula == y.turning_points_spatula))
      return false;
    converged += x.status == gecko::critical_status::converged;
  }
  return true;
}

long status_kib(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t k = std::strlen(key);
  while (std::getline(in, line))
    if (line.compare(0, k, key) == 0) return std::atol(line.c_str() + k + 1);
  return -1;
}

// Peak RSS growth of one batch of n designs x p points, measured in the child (--memory-child).
void memory_child(std::size_t n, std::size_t p) {
  const long before = status_kib("VmHWM:");
  {
    const auto d = random_designs(n, 7);
    std::vector<state> out;
    run_batch(d, grid(random_ft_hi, p), 1, out);
    volatile double sink = out.back().Fn;
    (void)sink;
  }
  const long after = status_kib("VmHWM:");
  std::printf("%.0f\n", 1024.0 * static_cast<double>(after - before));
}

// Runs the measurement in a freshly exec'd copy of this program: a forked child would inherit
// the parent's high-water mark (VmHWM), which hides the batch's own peak. Returns bytes, or -1.
double peak_rss_delta(std::size_t n, std::size_t p) {
  char self[4096];
  const ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
  if (len <= 0) return -1;
  self[len] = 0;
  const std::string cmd = "'" + std::string(self) + "' --memory-child " + std::to_string(n) + " " + std::to_string(p);
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return -1;
  double delta = -1;
  if (std::fscanf(f, "%lf", &delta) != 1) delta = -1;
  pclose(f);
  return delta;
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--memory-child") && i + 2 < argc) {
      memory_child(std::strtoul(argv[i + 1], nullptr, 10), std::strtoul(argv[i + 2], nullptr, 10));
      return 0;
    }
  }
  std::printf("kind,case,threads,n,points,designs,median_s,min_s,reps,extra\n");
  std::vector<state> out1, out2;

  // 1. lines/s, 1 and 2 threads, reference scene (200 copies) and 200 random designs.
  for (std::size_t pts : {std::size_t(20), std::size_t(1000)}) {
    for (int kind = 0; kind < 2; ++kind) {
      const std::size_t nd = quick ? 40 : 200;
      const auto d = kind == 0 ? std::vector<seta>(nd) : random_designs(nd, 20261121);
      const auto ft = grid(kind == 0 ? 9.9 : random_ft_hi, pts);
      std::vector<double> t1, t2, c1, c2;
      bool identical = true;
      std::size_t conv = 0;
      for (int r = 0; r < reps; ++r) {
        const timing a = run_batch(d, ft, 1, out1);
        const timing b = run_batch(d, ft, 2, out2);
        t1.push_back(a.wall); c1.push_back(a.process_cpu);
        t2.push_back(b.wall); c2.push_back(b.process_cpu);
        identical = identical && same_bits(out1, out2, conv);
      }
      const char* name = kind == 0 ? "reference" : "random";
      std::printf("throughput,%s,1,%zu,%zu,%zu,%.6g,%.6g,%d,converged=%zu;process_cpu_s=%.6g\n", name, nd, pts, nd,
                  median(t1), *std::min_element(t1.begin(), t1.end()), reps, conv, median(c1));
      std::printf("throughput,%s,2,%zu,%zu,%zu,%.6g,%.6g,%d,bitwise_identical_1_vs_2=%d;process_cpu_s=%.6g\n", name, nd,
                  pts, nd, median(t2), *std::min_element(t2.begin(), t2.end()), reps, identical ? 1 : 0, median(c2));
      std::fflush(stdout);
    }
  }

  // 2. time against points per line: the reference scene, one design, Ft = linspace(0, 9.9, n).
  {
    std::vector<std::size_t> ns;
    const int top = quick ? 4 : 5;
    for (int k = 2; k <= 2 * top; ++k) ns.push_back(static_cast<std::size_t>(std::lround(std::pow(10.0, k / 2.0))));
    const std::vector<seta> d(1);
    std::vector<std::vector<double>> t(ns.size());
    for (int r = 0; r < reps; ++r)
      for (std::size_t k = 0; k < ns.size(); ++k) {
        const std::size_t i = (k + static_cast<std::size_t>(r)) % ns.size();
        // small n: repeat the call to get above the clock's noise, report per call
        const int inner = ns[i] < 1000 ? 20 : 1;
        const auto ft = grid(9.9, ns[i]);
        double s = 0;
        for (int j = 0; j < inner; ++j) s += run_batch(d, ft, 1, out1).thread_cpu;
        t[i].push_back(s / inner);
      }
    for (std::size_t i = 0; i < ns.size(); ++i) {
      std::size_t conv = 0;
      const auto ft = grid(9.9, ns[i]);
      run_batch(d, ft, 1, out1);
      for (const auto& x : out1) conv += x.status == gecko::critical_status::converged;
      std::printf("points,reference,1,%zu,%zu,1,%.6g,%.6g,%d,converged=%zu\n", ns[i], ns[i], median(t[i]),
                  *std::min_element(t[i].begin(), t[i].end()), reps, conv);
    }
    std::fflush(stdout);
  }

  // 3. time against designs per batch: the first n random designs, 20 points each, 1 thread.
  {
    std::vector<std::size_t> ns;
    const int top = quick ? 3 : 5;
    for (int k = 2; k <= 2 * top; ++k) ns.push_back(static_cast<std::size_t>(std::lround(std::pow(10.0, k / 2.0))));
    const auto all = random_designs(ns.back(), 99);
    const auto ft = grid(random_ft_hi, 20);
    std::vector<std::vector<double>> t(ns.size());
    const int r_designs = std::max(1, std::min(reps, 3));  // the 1e5-design batch takes ~30 s CPU
    for (int r = 0; r < r_designs; ++r)
      for (std::size_t k = 0; k < ns.size(); ++k) {
        const std::size_t i = (k + static_cast<std::size_t>(r)) % ns.size();
        if (r > 0 && ns[i] > 20000) continue;  // the largest batches once (CPU time: little noise)
        const std::vector<seta> d(all.begin(), all.begin() + static_cast<long>(ns[i]));
        t[i].push_back(run_batch(d, ft, 1, out1).thread_cpu);
      }
    for (std::size_t i = 0; i < ns.size(); ++i)
      std::printf("designs,random,1,%zu,20,%zu,%.6g,%.6g,%zu,\n", ns[i], ns[i], median(t[i]),
                  *std::min_element(t[i].begin(), t[i].end()), t[i].size());
    std::fflush(stdout);
  }

  // 4. memory: peak RSS growth of one batch, against the analytic bytes of designs + results.
  for (std::size_t p : {std::size_t(20), std::size_t(1000)}) {
    for (std::size_t n : {std::size_t(1000), std::size_t(10000), std::size_t(100000)}) {
      if (quick && n * p > 1000000) continue;
      if (n * p > 20000000) continue;  // keep the child below ~1.2 GB
      const double analytic = static_cast<double>(n) * (sizeof(seta) + p * sizeof(state));
      const double delta = peak_rss_delta(n, p);
      std::printf("memory,random,1,%zu,%zu,%zu,%.6g,%.6g,1,analytic_bytes=%.0f;sizeof_design=%zu;sizeof_state=%zu\n", n,
                  p, n, delta, delta, analytic, sizeof(seta), sizeof(state));
      std::fflush(stdout);
    }
  }
  return 0;
}
