// Minimal timing harness of the friction benchmarks: thread CPU time of whole batches, median
// over repetitions (the machines are shared; the median of CPU time is robust to preemption).
#pragma once

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace gecko_bench {

inline double thread_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Calls f() `inner` times per repetition; returns the median seconds per call.
template <class F>
double median_seconds(F&& f, int inner, int reps) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const double t0 = thread_seconds();
    for (int i = 0; i < inner; ++i) f();
    t.push_back((thread_seconds() - t0) / inner);
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

// Keeps a value alive so the optimiser cannot drop the work.
template <class T>
inline void keep(const T& v) {
  asm volatile("" : : "g"(&v) : "memory");
}

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

}  // namespace gecko_bench
