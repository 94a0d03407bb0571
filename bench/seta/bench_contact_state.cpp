// bench/seta/bench_contact_state.cpp — the forward problem (gecko/seta/contact_state.hpp) on rows of
// a contour of a in force space: microseconds per point on 1000-point rows (Fn from -4 to 2 at
// fixed Ft) of the reference design, single thread, with the status histogram of each row (loads
// without contact cost less than loads with one). Timing only; accuracy is tested in
// tests/seta/contact_state.cpp. Reports process CPU time (std::clock) per point, best of the
// repeats, and wall time beside it: on a shared machine the wall time includes preemption.
//
//   c++ -O3 -march=native -std=c++17 -Iinclude -I/usr/include/eigen3 bench/seta/bench_contact_state.cpp -o /tmp/bcs && /tmp/bcs
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <vector>

#include "gecko/seta/contact_state.hpp"

int main() {
  const gecko::TwoLevelSeta<double> seta;  // the paper's reference design
  const gecko::contact_solver<double> solve(seta);
  const int n = 1000, repeats = 7;
  std::vector<double> Fn(n);
  for (int i = 0; i < n; ++i) Fn[i] = -4.0 + 6.0 * i / (n - 1);
  std::printf("# reference design, 1000-point rows Fn in [-4, 2], best of %d runs\n", repeats);
  std::printf("%8s %12s %12s   status histogram (0 converged, 2 no contact, 4 beyond joint, other)\n", "Ft",
              "cpu us/pt", "wall us/pt");
  double total = 0;
  int rows = 0;
  volatile double sink = 0;
  for (double Ft : {0.0, 2.0, 5.0, 7.0, 9.0, 9.9}) {
    double best = 1e300, best_wall = 1e300;
    int hist[8] = {0};
    for (int r = 0; r < repeats; ++r) {
      std::fill(hist, hist + 8, 0);
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      for (int i = 0; i < n; ++i) {
        const auto s = solve(Fn[i], Ft);
        ++hist[static_cast<int>(s.status)];
        sink = sink + (s.a == s.a ? s.a : 0.0);
      }
      const double cpu = 1e6 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / n;
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / n;
      best = std::min(best, cpu);
      best_wall = std::min(best_wall, us);
    }
    total += best;
    ++rows;
    std::printf("%8.2f %12.3f %12.3f   %d / %d / %d / %d\n", Ft, best, best_wall, hist[0], hist[2], hist[4],
                n - hist[0] - hist[2] - hist[4]);
  }
  std::printf("mean over rows: %.3f cpu us/point\n", total / rows);
  return 0;
}
