// bench/elliptic/harness.hpp — the measuring half of the elliptic benchmark: run time of a kernel
// over a whole input array, and its error against the stored mpmath references.
//
// Why hand-rolled rather than Google Benchmark: every method must be timed on exactly the array
// whose errors are reported, in the same run, and the table joins both. Google Benchmark's model
// (one state loop per benchmark, reported by its own reporter) would still need this array loop
// inside each benchmark and a second pass to join the errors; it adds no statistic we lack here.
// What it would give — robust repetition statistics — is done below: each case sweeps the whole
// array (20000 independent inputs, so branch predictors cannot learn one point) enough passes
// to last >= target_ms, repeated `reps` times, and the median is reported. The repetitions of
// all cases are interleaved (rep 1 of every case, then rep 2, ...) with a rotating start, so a
// noisy interval on this shared machine hits all methods alike instead of one method's block.
//
// The clock is the CPU time of this thread (CLOCK_THREAD_CPUTIME_ID), not wall time: on a machine
// shared with other jobs, the intervals when the scheduler runs someone else are then not counted.
// What remains (cache and memory-bandwidth interference, frequency changes) is what the median
// over repetitions and the interleaving are for.
//
// Also here: csv_text, the one CSV quoting of the benchmarks that write result tables
// (bench_elliptic, bench/tradeoff/bench_tradeoff.cpp).
#pragma once

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace gecko_bench {

// One timed thing: a function that evaluates a kernel over the whole input array into `out`.
// Results go to memory that is read afterwards (errors, checksum), so the compiler cannot drop
// the evaluations; the kernel itself is inlined into the loop (a function pointer is followed
// once per pass, not per evaluation).
using sweep_fn = void (*)(const void* inputs, double* out);

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
  auto now_ns = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
  };
  auto run = [&](timed_case& c) {
    const double t0 = now_ns();
    for (std::size_t p = 0; p < c.passes; ++p) c.sweep(c.inputs, c.out.data());
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

}  // namespace gecko_bench
