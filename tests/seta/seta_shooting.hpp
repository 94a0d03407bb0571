// Test helper: an independent route to the two-level seta's critical state — ODE shooting of the
// governing equations (docs/theory/two_level_seta.md, paper eqs 1-5) with classical RK4 in long double, no first
// integrals and no elliptic integrals. From the contact edge (theta2 = pi/2,
// theta2' = +sqrt(2 (w - Ft^2/(2 EA2)) / EI2)) integrate back over the spatula to the joint, apply
// the joint conditions, integrate back over the beam to the base. At a true critical state
// theta2(l1) = beta and theta1(0) = alpha1.
#pragma once

#include <cmath>
#include <limits>

#include "gecko/seta/two_level_seta.hpp"

namespace seta_test {

struct shot {
  long double theta_joint;  // theta2(l1)
  long double rate_joint;   // theta2'(l1)
  long double theta_base;   // theta1(0)
  long double rate_base;    // theta1'(0)
  int sign_changes_beam, sign_changes_spatula;
};

inline long double rhs(long double th, long double EI, long double c, long double Fn, long double Ft) {
  const long double T = Ft * std::sin(th) - Fn * std::cos(th);
  return -(Fn * std::sin(th) + Ft * std::cos(th)) * (1 + T * c) / EI;
}

// Integrate theta'' = rhs from s to s - len (backwards) with n RK4 steps; counts sign changes.
inline void integrate_back(long double& th, long double& om, long double len, long double EI, long double c,
                           long double Fn, long double Ft, int n, int& changes) {
  const long double h = -len / n;
  changes = 0;
  long double prev = om;
  for (int i = 0; i < n; ++i) {
    const long double k1t = om, k1o = rhs(th, EI, c, Fn, Ft);
    const long double k2t = om + h / 2 * k1o, k2o = rhs(th + h / 2 * k1t, EI, c, Fn, Ft);
    const long double k3t = om + h / 2 * k2o, k3o = rhs(th + h / 2 * k2t, EI, c, Fn, Ft);
    const long double k4t = om + h * k3o, k4o = rhs(th + h * k3t, EI, c, Fn, Ft);
    th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    om += h / 6 * (k1o + 2 * k2o + 2 * k3o + k4o);
    if ((om > 0) != (prev > 0) && i + 1 < n) ++changes;
    prev = om;
  }
}

inline shot shoot(const gecko::TwoLevelSeta<double>& s, long double Fn, long double Ft, int steps_per_unit = 6000) {
  const long double c1 = std::isinf(s.EA1) ? 0.0L : 1.0L / s.EA1;
  const long double c2 = std::isinf(s.EA2) ? 0.0L : 1.0L / s.EA2;
  shot r;
  long double th = 1.570796326794896619231321691639751442L;
  long double om = std::sqrt(2 * (s.w - Ft * Ft * c2 / 2) / s.EI2);
  const int n2 = std::max(200, static_cast<int>(steps_per_unit * s.l2));
  integrate_back(th, om, s.l2, s.EI2, c2, Fn, Ft, n2, r.sign_changes_spatula);
  r.theta_joint = th;
  r.rate_joint = om;
  th -= s.alpha2;
  om *= s.EI2 / s.EI1;
  const int n1 = std::max(200, static_cast<int>(steps_per_unit * s.l1));
  integrate_back(th, om, s.l1, s.EI1, c1, Fn, Ft, n1, r.sign_changes_beam);
  r.theta_base = th;
  r.rate_base = om;
  return r;
}

// Error estimate of a computed Fn: the base-angle mismatch divided by d theta1(0) / d Fn.
inline long double fn_error(const gecko::TwoLevelSeta<double>& s, double Fn, double Ft) {
  const shot a = shoot(s, Fn, Ft);
  const long double h = 1e-6L * std::max(1.0L, std::fabs(static_cast<long double>(Fn)));
  const shot b = shoot(s, Fn + h, Ft);
  const long double slope = (b.theta_base - a.theta_base) / h;
  return (a.theta_base - s.alpha1) / slope;
}

}  // namespace seta_test
