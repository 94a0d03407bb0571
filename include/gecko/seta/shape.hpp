// gecko/seta/shape.hpp — the deformed shape x(s), z(s) of a solved critical state, computed only
// when asked for (the critical line never needs it).
//
// docs/theory/two_level_seta.md governing equations (paper eqs 1-5): from the solved base state theta1(0) = alpha1,
// theta1'(0) (critical_state::theta_rate_base) the elastica is integrated along s with classical
// RK4 (state theta, theta', x, z; dx/ds = (1 + T/EA) sin theta, dz/ds = -(1 + T/EA) cos theta,
// T = Ft sin theta - Fn cos theta), through the joint (theta2 = theta1 + alpha2,
// EI2 theta2' = EI1 theta1'), to the contact edge s = a = l1 + l2. x runs along the substrate
// towards the contact, z is the height above it (the edge is put at z = 0; the base then sits at
// the height the seta spans). Error O(h^4) with h = segment length / steps; the closing error
// theta2(a) - pi/2 is returned as a check.
// (A closed form exists through R_F and R_D, the second-kind integrals of sin theta / theta';
// it is not implemented here.)
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "gecko/seta/solve_critical.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

template <class T>
struct seta_shape {
  std::vector<T> s, x, z, theta;
  T closing_error = std::numeric_limits<T>::quiet_NaN();  // theta2(a) - pi/2 of the integration
};

template <class T>
inline seta_shape<T> shape(const TwoLevelSeta<T>& seta, const critical_state<T>& state, int steps_per_segment = 200) {
  using std::cos; using std::isinf; using std::sin;
  seta_shape<T> out;
  if (state.status != critical_status::converged || steps_per_segment < 1) return out;
  const T Fn = state.Fn, Ft = state.Ft;
  struct Y { T th, om, x, z; };
  auto deriv = [&](const Y& y, T EI, T c) {
    const T st = sin(y.th), ct = cos(y.th);
    const T Tax = Ft * st - Fn * ct;
    const T stretch = 1 + Tax * c;
    return Y{y.om, -(Fn * st + Ft * ct) * stretch / EI, stretch * st, -stretch * ct};
  };
  auto step = [&](Y& y, T h, T EI, T c) {
    const Y k1 = deriv(y, EI, c);
    const Y k2 = deriv({y.th + h / 2 * k1.th, y.om + h / 2 * k1.om, y.x + h / 2 * k1.x, y.z + h / 2 * k1.z}, EI, c);
    const Y k3 = deriv({y.th + h / 2 * k2.th, y.om + h / 2 * k2.om, y.x + h / 2 * k2.x, y.z + h / 2 * k2.z}, EI, c);
    const Y k4 = deriv({y.th + h * k3.th, y.om + h * k3.om, y.x + h * k3.x, y.z + h * k3.z}, EI, c);
    y.th += h / 6 * (k1.th + 2 * k2.th + 2 * k3.th + k4.th);
    y.om += h / 6 * (k1.om + 2 * k2.om + 2 * k3.om + k4.om);
    y.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
    y.z += h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z);
  };
  auto record = [&](T s, const Y& y) {
    out.s.push_back(s);
    out.x.push_back(y.x);
    out.z.push_back(y.z);
    out.theta.push_back(y.th);
  };
  const T c1 = isinf(seta.EA1) ? T(0) : T(1) / seta.EA1;
  const T c2 = isinf(seta.EA2) ? T(0) : T(1) / seta.EA2;
  Y y{seta.alpha1, state.theta_rate_base, T(0), T(0)};
  record(T(0), y);
  const T h1 = seta.l1 / steps_per_segment;
  for (int i = 0; i < steps_per_segment; ++i) {
    step(y, h1, seta.EI1, c1);
    record(h1 * (i + 1), y);
  }
  y.th += seta.alpha2;
  y.om *= seta.EI1 / seta.EI2;
  out.theta.back() = y.th;  // theta just after the kink: the spatula's angle at the joint
  const T h2 = seta.l2 / steps_per_segment;
  for (int i = 0; i < steps_per_segment; ++i) {
    step(y, h2, seta.EI2, c2);
    record(seta.l1 + h2 * (i + 1), y);
  }
  out.closing_error = y.th - T(1.570796326794896619231321691639751442L);
  const T z_end = y.z;
  for (auto& v : out.z) v -= z_end;
  return out;
}

}  // namespace gecko
