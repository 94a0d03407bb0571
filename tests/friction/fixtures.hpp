// Test helper: the spatula of sliding_params (paper 000 eqs 9-10: N spatulae of rigidity K and
// re-sticking forces f_par1, f_perp1), written in one line by the friction tests' fixtures.
#pragma once

#include "gecko/friction/steady_sliding.hpp"

namespace friction_test {
inline gecko::sliding_params<double> spatula(double N, double K_par_par, double K_par_perp, double K_perp_perp,
                                             double f_par1, double f_perp1) {
  gecko::sliding_params<double> p;
  p.N = N;
  p.K << K_par_par, K_par_perp, K_par_perp, K_perp_perp;
  p.f_par1 = f_par1;
  p.f_perp1 = f_perp1;
  return p;
}
}  // namespace friction_test
