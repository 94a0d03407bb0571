// gecko/seta/shape.hpp — the deformed shape x(s), z(s) of a solved critical state, computed only
// when asked for (the critical line never needs it).
//
// Governing equations, paper 001 eqs (1)-(2): from the solved base state theta1(0) = alpha1,
// theta1'(0) (critical_state::theta_rate_base) the elastica is integrated along the convected
// coordinate s (state theta, theta', x, z; dx/ds = (1 + T/EA) sin theta, dz/ds = -(1 + T/EA) cos
// theta, T = Ft sin theta - Fn cos theta), through the joint (eq (4): theta2 = theta1 + alpha2,
// EI2 theta2' = EI1 theta1'), to the contact edge s = a = l1 + l2. x runs along the substrate
// towards the contact, z is the height above it (the edge is put at z = 0; the base then sits at
// the height the seta spans).
//
// Accuracy. Between the requested output points the integration is adaptive: classical RK4 with
// step doubling (the two half steps, extrapolated, are fifth order; their difference from the full
// step, /15, estimates the local error), each step accepted when its error is below
// shape_tolerance * h / (l1 + l2) (plus a rounding floor of 16 eps), so the summed local errors
// stay below shape_tolerance (1e-12 by default) plus rounding at any sampling. The result carries
//   * error_estimate: the sum of the accepted steps' error estimates (a global bound of the
//     truncation error, barring amplification by the ODE);
//   * closing_error: theta2(a) - pi/2, and max_closing_error: the largest mismatch of the
//     integrated solution against what the solved state fixes independently: theta2 and theta2'
//     at the joint (beta, theta2'(l1) of the state), theta2(a) = pi/2, and the Griffith edge rate
//     theta2'(a) = sqrt(2 (w - Ft^2/(2 EA2)) / EI2) (eq (3)). These measure the integration and
//     the state together;
//   * status: 0 when error_estimate and max_closing_error are both within 1e-10 (scaled by
//     max(1, |rate|) for the rates), 1 when not (the numbers are still returned), 2 when the step
//     size collapsed or the step budget ran out, 3 for no state (not converged / inadmissible are
//     both drawn: an inadmissible state, status 7, keeps its values so that it can be drawn).
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
  T closing_error = std::numeric_limits<T>::quiet_NaN();      // theta2(a) - pi/2 of the integration
  T max_closing_error = std::numeric_limits<T>::quiet_NaN();  // see the header comment
  T error_estimate = std::numeric_limits<T>::quiet_NaN();     // summed local error estimates
  int status = 3;                                             // 0 accurate to 1e-10; see above
  int steps = 0;                                              // accepted RK4 (doubled) steps
};

template <class T>
inline seta_shape<T> shape(const TwoLevelSeta<T>& seta, const critical_state<T>& state, int steps_per_segment = 200,
                           T shape_tolerance = T(1e-12)) {
  using std::cos; using std::fabs; using std::isinf; using std::pow; using std::sin; using std::sqrt;
  seta_shape<T> out;
  const bool solved = state.status == critical_status::converged || state.status == critical_status::inadmissible;
  if (!solved || steps_per_segment < 1 || !(shape_tolerance > 0)) return out;
  const T Fn = state.Fn, Ft = state.Ft;
  struct Y { T th, om, x, z; };
  auto deriv = [&](const Y& y, T EI, T c) {
    const T st = sin(y.th), ct = cos(y.th);
    const T Tax = Ft * st - Fn * ct;  // the axial force T(theta), paper 001 eqs (1)-(2)
    const T stretch = 1 + Tax * c;
    // EI theta'' = -(Fn sin theta + Ft cos theta)(1 + T/EA), paper 001 eq (1); x, z along the
    // stretched arc (dz/ds = -(1 + T/EA) cos theta).
    return Y{y.om, -(Fn * st + Ft * ct) * stretch / EI, stretch * st, -stretch * ct};
  };
  auto axpy = [](const Y& y, T h, const Y& k) { return Y{y.th + h * k.th, y.om + h * k.om, y.x + h * k.x, y.z + h * k.z}; };
  auto rk4 = [&](const Y& y, T h, T EI, T c) {
    const Y k1 = deriv(y, EI, c);
    const Y k2 = deriv(axpy(y, h / 2, k1), EI, c);
    const Y k3 = deriv(axpy(y, h / 2, k2), EI, c);
    const Y k4 = deriv(axpy(y, h, k3), EI, c);
    return Y{y.th + h / 6 * (k1.th + 2 * k2.th + 2 * k3.th + k4.th), y.om + h / 6 * (k1.om + 2 * k2.om + 2 * k3.om + k4.om),
             y.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x), y.z + h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
  };
  const T L = seta.l1 + seta.l2;
  T err_sum = 0;
  bool failed = false;
  T h_try = L / 64;
  // Integrate y over [0, len] adaptively (step doubling), landing exactly on len.
  auto advance = [&](Y& y, T len, T EI, T c) {
    T done = 0;
    int budget = 200000;
    while (done < len && !failed) {
      T h = h_try < len - done ? h_try : len - done;
      const bool last = h == len - done;
      const Y full = rk4(y, h, EI, c);
      const Y half = rk4(rk4(y, h / 2, EI, c), h / 2, EI, c);
      // Error of the half steps: (half - full)/15, scaled: theta, x, z by 1, theta' by max(1, |theta'|).
      const T sc = fabs(y.om) > 1 ? fabs(y.om) : T(1);
      T e = fabs(half.th - full.th);
      e = fabs(half.x - full.x) > e ? fabs(half.x - full.x) : e;
      e = fabs(half.z - full.z) > e ? fabs(half.z - full.z) : e;
      e = fabs(half.om - full.om) / sc > e ? fabs(half.om - full.om) / sc : e;
      e /= 15;
      // per unit length, plus a rounding floor (the differences of O(1) values cannot go below it)
      const T allowed = shape_tolerance * h / L + 16 * std::numeric_limits<T>::epsilon();
      if (e <= allowed || h <= 64 * std::numeric_limits<T>::epsilon() * L) {
        if (!(e <= allowed)) failed = true;  // step collapsed
        // local extrapolation (fifth order)
        y = Y{half.th + (half.th - full.th) / 15, half.om + (half.om - full.om) / 15, half.x + (half.x - full.x) / 15,
              half.z + (half.z - full.z) / 15};
        done = last ? len : done + h;
        err_sum += e;
        ++out.steps;
        const T grow = e > 0 ? T(0.9) * pow(allowed / e, T(0.2)) : T(4);
        if (!last) h_try = h * (grow < 4 ? (grow > T(0.2) ? grow : T(0.2)) : T(4));
      } else {
        const T shrink = T(0.9) * pow(allowed / e, T(0.2));
        h_try = h * (shrink > T(0.1) ? shrink : T(0.1));
      }
      if (--budget <= 0) failed = true;
    }
  };
  auto record = [&](T s, const Y& y) {
    out.s.push_back(s);
    out.x.push_back(y.x);
    out.z.push_back(y.z);
    out.theta.push_back(y.th);
  };
  const std::size_t n = static_cast<std::size_t>(steps_per_segment);
  out.s.reserve(2 * n + 1);
  out.x.reserve(2 * n + 1);
  out.z.reserve(2 * n + 1);
  out.theta.reserve(2 * n + 1);
  const T c1 = isinf(seta.EA1) ? T(0) : T(1) / seta.EA1;
  const T c2 = isinf(seta.EA2) ? T(0) : T(1) / seta.EA2;
  Y y{seta.alpha1, state.theta_rate_base, T(0), T(0)};
  record(T(0), y);
  const T h1 = seta.l1 / steps_per_segment;
  for (int i = 0; i < steps_per_segment; ++i) {
    advance(y, h1, seta.EI1, c1);
    record(i + 1 == steps_per_segment ? seta.l1 : h1 * (i + 1), y);
  }
  y.th += seta.alpha2;           // the kink at the joint, paper 001 eq (4)
  y.om *= seta.EI1 / seta.EI2;   // moment balance there, paper 001 eq (4)
  out.theta.back() = y.th;  // theta just after the kink: the spatula's angle at the joint
  const T rs = fabs(state.theta_rate_joint) > 1 ? fabs(state.theta_rate_joint) : T(1);
  T mismatch = fabs(y.th - state.theta_joint);
  mismatch = fabs(y.om - state.theta_rate_joint) / rs > mismatch ? fabs(y.om - state.theta_rate_joint) / rs : mismatch;
  const T h2 = seta.l2 / steps_per_segment;
  for (int i = 0; i < steps_per_segment; ++i) {
    advance(y, h2, seta.EI2, c2);
    record(i + 1 == steps_per_segment ? L : seta.l1 + h2 * (i + 1), y);
  }
  const T half_pi = T(1.570796326794896619231321691639751442L);
  out.closing_error = y.th - half_pi;
  // Griffith at the edge (paper 001 eq (3)): 1/2 EI2 theta2'(a)^2 + Ft^2/(2 EA2) = w.
  const T g = 2 * (seta.w - Ft * Ft * c2 / 2) / seta.EI2;
  const T edge_rate = g > 0 ? sqrt(g) : T(0);
  const T re = fabs(edge_rate) > 1 ? fabs(edge_rate) : T(1);
  if (fabs(out.closing_error) > mismatch) mismatch = fabs(out.closing_error);
  if (fabs(y.om - edge_rate) / re > mismatch) mismatch = fabs(y.om - edge_rate) / re;
  out.max_closing_error = mismatch;
  out.error_estimate = err_sum;
  const T z_end = y.z;
  for (auto& v : out.z) v -= z_end;
  if (failed) out.status = 2;
  else out.status = (err_sum <= T(1e-10) && mismatch <= T(1e-10)) ? 0 : 1;
  return out;
}

}  // namespace gecko
