// bench/seta/long_double_probe.cpp — one critical state in double and in long double (the solver
// is templated on the scalar), to tell rounding amplified by the formulation from the problem's own
// conditioning (README, "Known limits": a large-tension state whose double Fn is 1.09e-9 from the
// 60-digit root while the problem's condition number is 2.3).
//
//   g++ -O2 -std=c++17 -Wall -Wextra -Iinclude -I/usr/include/eigen3 bench/seta/long_double_probe.cpp -o /tmp/ldprobe
//   /tmp/ldprobe EI1 EI2 EA1 EA2 l1 l2 alpha1 alpha2 w Ft        (EA = inf allowed)
//
// Without arguments: the state of bench/results/traced_nodes.json "worst_state".
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gecko/seta/critical_line.hpp"

template <class T>
static void solve(const double* v, double ft, const char* name) {
  gecko::TwoLevelSeta<T> s;
  s.EI1 = T(v[0]);
  s.EI2 = T(v[1]);
  s.EA1 = T(v[2]);
  s.EA2 = T(v[3]);
  s.l1 = T(v[4]);
  s.l2 = T(v[5]);
  s.alpha1 = T(v[6]);
  s.alpha2 = T(v[7]);
  s.w = T(v[8]);
  const auto r = gecko::critical_line_at(s, std::vector<T>{T(ft)});
  std::printf("%-12s Fn = %.20Lg  theta_joint = %.20Lg  status %d\n", name, static_cast<long double>(r[0].Fn),
              static_cast<long double>(r[0].theta_joint), static_cast<int>(r[0].status));
}

int main(int argc, char** argv) {
  double v[10] = {2.534082475936204, 0.3372537410847821, 3505990.196635402, 3671641.159721389, 1.0,
                  0.0020648469809357176, 0.22830270849729953, 0.596286916822679, 1.0, 571.133896323054};
  if (argc == 11)
    for (int k = 0; k < 10; ++k) v[k] = std::strtod(argv[k + 1], nullptr);
  else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [EI1 EI2 EA1 EA2 l1 l2 alpha1 alpha2 w Ft]\n", argv[0]);
    return 2;
  }
  solve<double>(v, v[9], "double");
  solve<long double>(v, v[9], "long double");
  return 0;
}
