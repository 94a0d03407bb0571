// bench/seta/bench_admissibility.cpp — what the admissibility check (gecko/seta/admissibility.hpp)
// adds to a critical line.
//
// The reference line of bench_seta (Ft = linspace(0, 9.9, 1000), the paper's reference design),
// and the same line for alpha2 = 1.0 (whose states leave theta in [-pi/2, pi/2], so the check
// takes its quadrature path on part of the line): thread CPU time of critical_line_at (the whole
// call, which runs the check once per state) against the time of the check alone on the same 1000
// states: detail::admissibility_imp on the design's constants made once, as the solver calls it
// (the public admissibility_check also forms those constants, four sincos, on every call; its
// time is printed too). Median of repetitions.
//   cmake --build <build> --target bench_admissibility && <build>/bench/seta/bench_admissibility
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <vector>

#include "gecko/seta.hpp"

namespace {
double thread_cpu_ns() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 21;
  std::vector<double> ft(1000);
  for (std::size_t i = 0; i < ft.size(); ++i) ft[i] = 9.9 * static_cast<double>(i) / 999.0;
  for (double alpha2 : {0.5235987755982988, 1.0}) {
    gecko::TwoLevelSeta<double> s;
    s.alpha2 = alpha2;
    std::vector<gecko::critical_state<double>> out(ft.size());
    std::vector<double> t_line, t_check, t_public;
    const auto params = gecko::detail::make_seta_params(s);
    const double no_limit = std::numeric_limits<double>::infinity();
    double sink = 0;
    int slow = 0, bad = 0;
    for (int r = 0; r < reps; ++r) {
      double t0 = thread_cpu_ns();
      gecko::critical_line_at(s, ft.data(), ft.size(), out.data());
      double t1 = thread_cpu_ns();
      t_line.push_back(t1 - t0);
      t0 = thread_cpu_ns();
      slow = bad = 0;
      for (const auto& st : out) {
        const gecko::seta_pose<double> pose{st.Fn, st.Ft, st.theta_joint, st.theta_rate_base, st.theta_rate_joint,
                                            st.turning_points_beam, st.turning_points_spatula,
                                            std::numeric_limits<double>::quiet_NaN()};
        const auto a = gecko::detail::admissibility_imp(params, pose, no_limit);
        sink += a.min_z;
        slow += !a.exact_fast_path;
        bad += !a.admissible;
      }
      t1 = thread_cpu_ns();
      t_check.push_back(t1 - t0);
      t0 = thread_cpu_ns();
      for (const auto& st : out) sink += gecko::admissibility_check(s, st).min_z;
      t1 = thread_cpu_ns();
      t_public.push_back(t1 - t0);
    }
    const double line = median(t_line) / 1000, check = median(t_check) / 1000, pub = median(t_public) / 1000;
    std::printf("alpha2 = %.4f: line %.3f us/point (check included), check alone %.4f us/point = %.2f %% of the "
                "line (public admissibility_check %.4f us/point); quadrature path on %d of 1000 states, %d "
                "inadmissible (sink %g)\n",
                alpha2, line / 1000, check / 1000, 100 * check / line, pub / 1000, slow, bad, sink);
  }
}
