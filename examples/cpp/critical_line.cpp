// The reference seta's critical line from C++: the same numbers as gecko.TwoLevelSeta().critical_line.
// Build: see examples/cpp/CMakeLists.txt (find_package(gecko)), or
//   c++ -std=c++17 -O2 -I include $(pkg-config --cflags eigen3) examples/cpp/critical_line.cpp
#include <gecko/gecko.hpp>

#include <cstdio>
#include <vector>

int main() {
  gecko::TwoLevelSeta<double> seta;  // the paper's reference scene: EI1 = 5, EI2 = 2, EA2 = 50, ...
  seta.alpha2 = 0.5;                 // any field can be changed

  std::vector<double> Ft;
  for (int i = 0; i <= 8; ++i) Ft.push_back(1.2 * i);
  // Followed from Ft = 0 through folds; every state carries a status (0 = converged).
  const auto line = gecko::critical_line_at(seta, Ft);
  for (const auto& s : line)
    std::printf("Ft = %5.2f  Fn = %+.12f  theta_joint = %.12f  status %d\n", s.Ft, s.Fn, s.theta_joint,
                static_cast<int>(s.status));

  const auto c = gecko::characteristics(seta);
  std::printf("(Fn)0 = %.12f, max pull-off = %.12f\n", c.fn0, c.max_pull_off);
  return line.front().status == gecko::critical_status::converged ? 0 : 1;
}
