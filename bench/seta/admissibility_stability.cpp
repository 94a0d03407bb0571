// bench/seta/admissibility_stability.cpp — is the admissibility verdict of every solved state a
// property of the state, or of its last bits? Each solved state (status 0 or 7) with turning
// points (the states that can take the general path of gecko/seta/admissibility.hpp) is checked
// again with beta and theta2'(l1) perturbed by k 1e-15 (k = -2, -1, 1, 2): a state whose
// perturbations give both verdicts (crossing and not) is printed as FLIP, one whose lowest height
// moves by more than 1e-9 (l1 + l2) as MOVED, one whose check is not made for some perturbation
// (min_z NaN) as NAN. A check that left a beam's turning angle out of theta's range when its first
// integral put it past its separatrix in rounding had 32 states of the 10,000-design re-run
// reported admissible that cross the substrate (validation/README.md, "Beams on their separatrix
// in rounding: admissibility"); this probe looks for others of the kind.
//
//   g++ -O2 -std=c++17 -Wall -Wextra -Iinclude -I/usr/include/eigen3 bench/seta/admissibility_stability.cpp -o /tmp/admstab
//   python3 -c "import numpy as np; z = np.load('validation/data/stress_10000_states.npz'); [print(i, *map(repr, map(float, p)), *map(repr, map(float, f))) for i, (p, f) in enumerate(zip(z['P'], z['FT']))]" > /tmp/designs.txt
//   split -n l/2 -d /tmp/designs.txt /tmp/designs_part && (/tmp/admstab /tmp/designs_part00 & /tmp/admstab /tmp/designs_part01; wait)
//
// Each input line: design index, EI1 EI2 EA1 EA2 l1 l2 alpha1 alpha2 w (inf allowed), six Ft.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gecko/seta/critical_line.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s designs.txt\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1]);
  std::string line, tok;
  long checked = 0, flips = 0, moved = 0, unmade = 0;
  while (std::getline(in, line)) {
    std::istringstream is(line);
    int id = 0;
    double p[9];
    std::vector<double> ft(6);
    is >> id;
    for (double& x : p) {
      is >> tok;
      x = std::strtod(tok.c_str(), nullptr);  // strtod reads "inf", operator>> does not
    }
    for (double& x : ft) {
      is >> tok;
      x = std::strtod(tok.c_str(), nullptr);
    }
    const gecko::TwoLevelSeta<double> s{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8]};
    const auto states = gecko::critical_line_at(s, ft, gecko::critical_line_options<double>(), gecko::policies::nan_policy());
    const double L = p[4] + p[5];
    for (std::size_t c = 0; c < states.size(); ++c) {
      const auto& st = states[c];
      if (st.status != gecko::critical_status::converged && st.status != gecko::critical_status::inadmissible) continue;
      if (st.turning_points_beam + st.turning_points_spatula == 0) continue;
      ++checked;
      const auto base = gecko::admissibility_check(s, st);
      double lo = base.min_z, hi = base.min_z;
      bool crossing = base.crosses_substrate, above = !base.crosses_substrate, nan = !(base.min_z == base.min_z);
      for (int k : {-2, -1, 1, 2}) {
        for (int which = 0; which < 2; ++which) {
          auto q = st;
          (which == 0 ? q.theta_joint : q.theta_rate_joint) *= 1 + k * 1e-15;
          const auto a = gecko::admissibility_check(s, q);
          if (!(a.min_z == a.min_z)) {
            nan = true;
            continue;
          }
          lo = std::fmin(lo, a.min_z);
          hi = std::fmax(hi, a.min_z);
          crossing |= a.crosses_substrate;
          above |= !a.crosses_substrate;
        }
      }
      const bool flip = crossing && above, mv = hi - lo > 1e-9 * L;
      flips += flip;
      moved += mv;
      unmade += nan;
      if (flip || mv || nan)
        std::printf("%s design %d column %zu Ft %.17g status %d turning %d %d min_z %.17g over perturbations %.17g to %.17g\n",
                    flip ? "FLIP" : (mv ? "MOVED" : "NAN"), id, c, st.Ft, static_cast<int>(st.status),
                    st.turning_points_beam, st.turning_points_spatula, base.min_z, lo, hi);
    }
  }
  std::printf("SUMMARY %s: %ld states with turning points checked, %ld verdicts flip, %ld lowest heights move by > 1e-9 (l1 + l2), %ld checks not made\n",
              argv[1], checked, flips, moved, unmade);
  return 0;
}
