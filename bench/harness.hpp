// bench/harness.hpp — the one timing harness of the C++ benchmarks (elliptic, seta, friction,
// scaling, tradeoff): clocks, medians over repetitions, the interleaved sweep timing of the
// elliptic kernels, errors against stored references, and the result-table writers.
//
// Why hand-rolled rather than Google Benchmark: every method must be timed on exactly the array
// whose errors are reported, in the same run, and the table joins both. Google Benchmark's model
// (one state loop per benchmark, reported by its own reporter) would still need this array loop
// inside each benchmark and a second pass to join the errors; it adds no statistic we lack here.
// What it would give — robust repetition statistics — is done below: each case sweeps the whole
// array enough passes to last >= target_ms, repeated `reps` times, and the median is reported.
// Every pass visits the array in a new order (visit_order below): a branch predictor learns the
// data-dependent branches of a sequence of inputs it has seen before, and a kernel whose branch
// pattern follows its inputs (the duplication step count of gecko::ellint_f) was timed too fast.
// Measured on the 2-core EPYC (`profile_ellint_f --learning`, bench/results/
// profile_ellint_f_learning.md): gecko::ellint_f on the uniform set took 30.8 ns in the first pass
// and 24.6 ns in passes 321-640 when every pass repeated the array's order, and 31.1-33.2 ns
// throughout with a new order per pass; Boost's ellint_1 took 58-64 ns either way. The repetitions of
// all cases are interleaved (rep 1 of every case, then rep 2, ...) with a rotating start, so a
// noisy interval on this shared machine hits all methods alike instead of one method's block.
//
// The clock is the CPU time of this thread (CLOCK_THREAD_CPUTIME_ID), not wall time: on a machine
// shared with other jobs, the intervals when the scheduler runs someone else are then not counted.
// What remains (cache and memory-bandwidth interference, frequency changes) is what the median
// over repetitions and the interleaving are for. Wall time (steady_clock) is there for the
// multithreaded batch calls, whose work is spread over threads.
//
// Also here: load_average and utc_now, the record of a run in every results file; csv_text, the
// one CSV quoting of the benchmarks that write result tables; and row/write, the
// family-method-setting-time-error table of the friction benchmarks.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <ctime>
#include <fstream>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace gecko_bench {

// ---- clocks ----------------------------------------------------------------------------------

// Seconds of CPU time of `clock` (CLOCK_THREAD_CPUTIME_ID: this thread; CLOCK_PROCESS_CPUTIME_ID:
// all threads of the process).
inline double cpu_seconds(clockid_t clock = CLOCK_THREAD_CPUTIME_ID) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
inline double thread_seconds() { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID); }
inline double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}
inline double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
inline double wall_ns() { return 1e9 * wall_seconds(); }

// The order in which one pass visits the n inputs: i_k = (start + k stride) mod n, with stride
// coprime to n (every input exactly once). The harness draws a new start and stride for every pass,
// so no pass repeats the sequence of the one before and a branch predictor cannot learn it.
// out[i] stays the result of input i, whatever the order.
struct visit_order {
  std::size_t start = 0, stride = 1;

  template <class F>
  void for_each(std::size_t n, F&& f) const {
    std::size_t i = start;
    for (std::size_t k = 0; k < n; ++k) {
      f(i);
      const std::size_t j = i + stride;
      i = j >= n ? j - n : j;  // a conditional move, not a branch (start, stride < n)
    }
  }
};

// A pseudo-random order of n inputs from a 64-bit state (splitmix64), deterministic for a seed.
inline visit_order next_visit_order(std::size_t n, std::uint64_t& state) {
  auto next = [&] {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  visit_order o;
  if (n <= 1) return visit_order{0, 0};
  o.start = static_cast<std::size_t>(next() % n);
  // strides away from 1 and n - 1, which would keep neighbours together
  const std::size_t lo = n >= 16 ? n / 8 : 1, span = n >= 16 ? n - 2 * lo : n - 1;
  o.stride = lo + static_cast<std::size_t>(next() % span);
  while (std::gcd(o.stride, n) != 1) o.stride = o.stride + 1 < n ? o.stride + 1 : 1;
  return o;
}

// One timed thing: a function that evaluates a kernel over the whole input array into `out`, in
// the given order (visit_order::for_each). Results go to memory that is read afterwards (errors,
// checksum), so the compiler cannot drop the evaluations; the kernel itself is inlined into the
// loop (a function pointer is followed once per pass, not per evaluation).
using sweep_fn = void (*)(const void* inputs, double* out, const visit_order& order);

struct timing {
  double median_ns = 0, q1_ns = 0, q3_ns = 0, min_ns = 0;  // per evaluation
};

struct error_stats {
  double max_eps = 0, rms_eps = 0;  // relative error in units of DBL_EPSILON = 2^-52
  std::size_t worst = 0;            // row of the largest error
  std::size_t nonfinite = 0;        // rows where the method returned NaN or +-inf
};

inline double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(pos);
  const auto hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

// The median of repetitions (the mean of the middle two for an even count).
inline double median(const std::vector<double>& v) { return quantile(v, 0.5); }

// Calls f() `inner` times per repetition; returns the median thread CPU seconds per call.
template <class F>
double median_seconds(F&& f, int inner, int reps) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const double t0 = thread_seconds();
    for (int i = 0; i < inner; ++i) f();
    t.push_back((thread_seconds() - t0) / inner);
  }
  return median(t);
}

// Keeps a value alive so the optimiser cannot drop the work.
template <class T>
inline void keep(const T& v) {
  asm volatile("" : : "g"(&v) : "memory");
}

// Relative error of got[i] against ref = hi[i] + lo[i] (+ delta[i] when given: the reference
// moved to the input a peer actually received). got - hi is formed first, in long double, so the
// sub-ulp tail lo is not lost to rounding.
inline error_stats measure_error(const std::vector<double>& got, const std::vector<double>& hi,
                                 const std::vector<double>& lo, const std::vector<double>* delta) {
  error_stats s;
  long double sum_sq = 0;
  std::size_t finite = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!std::isfinite(got[i])) {
      ++s.nonfinite;
      continue;
    }
    long double tail = static_cast<long double>(lo[i]);
    if (delta) tail += static_cast<long double>((*delta)[i]);
    const long double ref = static_cast<long double>(hi[i]) + tail;
    const long double diff = (static_cast<long double>(got[i]) - hi[i]) - tail;
    const double e = static_cast<double>(std::fabs(diff / ref)) / std::numeric_limits<double>::epsilon();
    if (e > s.max_eps) {
      s.max_eps = e;
      s.worst = i;
    }
    sum_sq += static_cast<long double>(e) * e;
    ++finite;
  }
  s.rms_eps = finite ? static_cast<double>(std::sqrt(sum_sq / static_cast<long double>(finite))) : 0.0;
  if (s.nonfinite) s.max_eps = std::numeric_limits<double>::infinity();
  return s;
}

struct timed_case {
  sweep_fn sweep;
  const void* inputs;
  std::size_t n;
  std::vector<double> out;  // the values of the last pass
  std::size_t passes = 1;   // per repetition, calibrated
  std::vector<double> samples_ns;
  timing result;
};

// Times every case `reps` times, interleaved; returns a checksum of all outputs (printed by the
// caller, which is what finally keeps every evaluation observable).
inline double time_cases(std::vector<timed_case>& cases, int reps, double target_ms) {
  auto now_ns = [] { return thread_cpu_ns(); };
  std::uint64_t order_state = 0x5EEDull;  // fixed seed: a rerun visits in the same orders
  std::vector<visit_order> orders;
  auto run = [&](timed_case& c) {
    orders.resize(c.passes);  // drawn before the clock starts
    for (auto& o : orders) o = next_visit_order(c.n, order_state);
    const double t0 = now_ns();
    for (std::size_t p = 0; p < c.passes; ++p) c.sweep(c.inputs, c.out.data(), orders[p]);
    return now_ns() - t0;
  };
  for (auto& c : cases) {  // warm-up (page in, caches, lazy init) and calibration
    c.out.assign(c.n, 0.0);
    c.passes = 1;
    run(c);
    const double one = std::max(run(c), 1.0);
    c.passes = static_cast<std::size_t>(std::max(1.0, std::ceil(target_ms * 1e6 / one)));
    c.samples_ns.clear();
  }
  double checksum = 0;
  for (int r = 0; r < reps; ++r) {
    for (std::size_t j = 0; j < cases.size(); ++j) {
      auto& c = cases[(j + static_cast<std::size_t>(r) * 7) % cases.size()];
      const double ns = run(c);
      c.samples_ns.push_back(ns / static_cast<double>(c.passes * c.n));
      checksum += c.out[static_cast<std::size_t>(r) % c.n];
    }
  }
  for (auto& c : cases) {
    c.result.median_ns = quantile(c.samples_ns, 0.5);
    c.result.q1_ns = quantile(c.samples_ns, 0.25);
    c.result.q3_ns = quantile(c.samples_ns, 0.75);
    c.result.min_ns = *std::min_element(c.samples_ns.begin(), c.samples_ns.end());
  }
  return checksum;
}

// ---- the record of a run -----------------------------------------------------------------------

// The arguments of a benchmark that writes a results file: `[reps] [--out DIR]` (repetitions,
// and the folder of the results, bench/results by default).
struct run_args {
  int reps;
  std::string out_dir = "bench/results";
};
inline run_args parse_run_args(int argc, char** argv, int default_reps) {
  run_args a{default_reps};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) a.out_dir = argv[++i];
    else a.reps = std::atoi(argv[i]);
  }
  return a;
}

// The 1, 5 and 15 minute load averages ("unknown" where /proc/loadavg cannot be read): results
// files note them because the machines are shared.
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  if (!(in >> a >> b >> c)) return "unknown";
  return a + " " + b + " " + c;
}

// The current time as "YYYY-MM-DD HH:MM UTC".
inline std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buf;
}

// A CSV text field: always quoted (R_F(x,y,z) and the input-set names contain commas), a quote
// inside doubled (RFC 4180).
inline std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

// ---- the family / method / setting / time / error table (friction benchmarks) ---------------

struct row {
  std::string family, method, setting;
  double seconds;
  double error;  // relative, NaN when not applicable
  std::string note;
};

inline void write(const std::vector<row>& rows, const std::string& csv, const std::string& md,
                  const std::string& title) {
  if (FILE* f = std::fopen(csv.c_str(), "w")) {
    std::fprintf(f, "family,method,setting,seconds,rel_error,note\n");
    for (const auto& r : rows)
      std::fprintf(f, "%s,%s,%s,%.6g,%.3g,%s\n", r.family.c_str(), r.method.c_str(),
                   r.setting.c_str(), r.seconds, r.error, r.note.c_str());
    std::fclose(f);
  }
  if (FILE* f = std::fopen(md.c_str(), "w")) {
    std::fprintf(f, "%s\n\n| family | method | setting | time | max rel. error | note |\n"
                    "|---|---|---|---|---|---|\n", title.c_str());
    for (const auto& r : rows) {
      char t[64];
      if (r.seconds < 1e-3) std::snprintf(t, sizeof t, "%.3g us", r.seconds * 1e6);
      else std::snprintf(t, sizeof t, "%.3g ms", r.seconds * 1e3);
      char e[64];
      if (r.error == r.error) std::snprintf(e, sizeof e, "%.2g", r.error);
      else std::snprintf(e, sizeof e, "-");
      std::fprintf(f, "| %s | %s | %s | %s | %s | %s |\n", r.family.c_str(), r.method.c_str(),
                   r.setting.c_str(), t, e, r.note.c_str());
    }
    std::fclose(f);
  }
}

// main() of a benchmark: run(argc, argv), with an exception (missing data, unwritable output, a
// kernel that threw) printed as "<name>: <what>" and exit status 1.
inline int guarded_main(const char* name, int (*run)(int, char**), int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace gecko_bench
