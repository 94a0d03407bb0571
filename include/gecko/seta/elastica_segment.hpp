// gecko/seta/elastica_segment.hpp — the length of one elastica segment in Carlson form.
//
// docs/theory/two_level_seta.md, "First integrals" and "Lengths" (paper eqs 8-15). A segment with bending stiffness
// EI, axial stiffness EA (c = 1/EA, c = 0 for EA = infinity), loaded by (Fn, Ft), obeys
//     1/2 EI theta'^2 = R(u) = M - N u - c N^2 u^2 / 2,   u = sin(psi),  psi = theta - phi,
// with N = |F| and phi the force direction. Its length between two states (psi, sign of theta') is
//     L = sqrt(EI/2) * int dpsi / sqrt(R(sin psi)) = sqrt(EI/2) * int du / sqrt((1-u^2) R(u)).
// R factors as f3(u) f4(u), f3 = M + b3 u, f4 = 1 + b4 u, with s = sqrt(1 + 2cM),
// b3 = -N(1+s)/2, b4 = cN/(1+s) (for c = 0: s = 1, f4 = 1, and the quartic becomes a cubic), so
// each piece is one R_F by Carlson's table (Carlson 1988, Math. Comp. 51, quartic and cubic cases):
//     int_y^x dt / sqrt(prod_{i=1..4} (a_i + b_i t)) = 2 R_F(U12^2, U13^2, U14^2).
// Three devices make the formula exact and smooth everywhere the seta goes:
//   * the factors 1 -+ u enter through signed half angles, X1 = sqrt2 cos(psi/2 + pi/4),
//     X2 = sqrt2 sin(psi/2 + pi/4) (X1 X2 = cos psi), so psi may cross +-pi/2;
//   * X3 = sqrt(f3) carries the sign of theta' (the Newton unknowns p, q of
//     gecko/seta/critical_residual.hpp are theta' scaled), so a turning point (theta' = 0) can
//     move through a segment end without a branch switch;
//   * every U is rewritten with half-angle differences (h = (psi_x - psi_y)/2), e.g.
//         U13 = P / sin h + N s sin h / (2P),   P = (X3 Y4 + Y3 X4)/2,
//     so no sines of nearby angles are subtracted and x - y never divides.
// The one-R_F ("direct") form is exact while the path is shorter than a quarter period K (then
// U14 > 0; beyond, R_F(U^2) folds back). Longer paths are measured by their phase: the distance
// of each end from its nearest special point of the libration / rotation of theta (a turning
// point, or u = -1 or u = 1), each again one R_F in a form analytic through that point, plus
// multiples of the quarter period K (a complete integral, R_F(x, y, 0)). Turning points (theta'
// changing sign inside the segment) are counted on the way.
#pragma once

#include <cmath>
#include <limits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/detail/dual.hpp"
#include "gecko/seta/detail/rf_gradient.hpp"

namespace gecko {
namespace detail {

template <class T> constexpr T seta_pi() { return T(3.141592653589793238462643383279502884L); }
template <class T> constexpr T seta_sqrt2() { return T(1.414213562373095048801688724209698079L); }

// ---- one segment's constants ---------------------------------------------------------------
template <class S, bool Extensible>
struct segment_constants {
  S M, N, c;   // first-integral constant, |F|, 1/EA (unused when inextensible)
  S s;         // sqrt(1 + 2 c M)
  S b3, b4;    // f3(u) = M + b3 u, f4(u) = 1 + b4 u
  S up;        // u+ = -M/b3, the root of f3: theta' = 0 there (turning points)
  S scale;     // sqrt(2 EI): lengths are scale * R_F(...)
};

template <bool Extensible, class S>
inline segment_constants<S, Extensible> make_segment(const S& EI, const S& c, const S& M, const S& N) {
  using std::sqrt;
  using T = scalar_of_t<S>;
  segment_constants<S, Extensible> g;
  g.M = M;
  g.N = N;
  g.c = c;
  if constexpr (Extensible) {
    // R(u) = M - N u - c N^2 u^2/2 (paper 001 eq (8)) factored as f3(u) f4(u).
    g.s = sqrt(T(1) + T(2) * c * M);
    const S one_s = T(1) + g.s;
    g.b3 = -(N * one_s) * T(0.5);
    g.b4 = c * N / one_s;
    g.up = T(2) * M / (N * one_s);
  } else {
    g.s = S(T(1));
    g.b3 = -N;
    g.b4 = S(T(0));
    g.up = M / N;
  }
  g.scale = sqrt(T(2) * EI);
  return g;
}

template <class S, bool E>
inline S seg_f3(const segment_constants<S, E>& g, const S& u) { return g.M + g.b3 * u; }
template <class S, bool E>
inline S seg_sqrt_f4(const segment_constants<S, E>& g, const S& u) {
  using std::sqrt;
  using T = scalar_of_t<S>;
  if constexpr (E) return sqrt(T(1) + g.b4 * u);
  else return S(T(1));
}
// a3 b4 + a4 b3 + b3 b4 (x + y) = -(N + c N^2 (x + y)/2): the coefficient in U12.
template <class S, bool E>
inline S seg_g12(const segment_constants<S, E>& g, const S& x, const S& y) {
  using T = scalar_of_t<S>;
  if constexpr (E) return g.N + g.c * g.N * g.N * (x + y) * T(0.5);
  else return g.N;
}
// d34 = a3 b4 - a4 b3 = N s.
template <class S, bool E>
inline S seg_d34(const segment_constants<S, E>& g) {
  if constexpr (E) return g.N * g.s;
  else return g.N;
}

// ---- the Carlson forms -----------------------------------------------------------------------
// Trigonometry of the direct form for a path from psi_y to psi_x: x = sin psi_x, y = sin psi_y,
// sin and cos of h = (psi_x - psi_y)/2, sin of sigma = (psi_x + psi_y)/2. The seta computes these
// from one sincos by angle addition (gecko/seta/critical_residual.hpp).
template <class S>
struct direct_trig {
  S x, y, sh, ch, ssg;
};

template <class S>
inline direct_trig<S> make_direct_trig(const S& psi_y, const S& psi_x) {
  using std::cos; using std::sin;
  using T = scalar_of_t<S>;
  const S h = (psi_x - psi_y) * T(0.5);
  return {sin(psi_x), sin(psi_y), sin(h), cos(h), sin((psi_x + psi_y) * T(0.5))};
}

// Direct form: the path from (psi_y, Y3) to (psi_x, X3), valid while it is shorter than a quarter
// period (then U14 > 0, returned in *u14, oriented, for the caller's check).
template <class Policy, class S, bool E>
inline S length_direct(const segment_constants<S, E>& g, const direct_trig<S>& t, const S& Y3, const S& X3,
                       scalar_of_t<S>* u14 = nullptr) {
  using T = scalar_of_t<S>;
  const S X4 = seg_sqrt_f4(g, t.x), Y4 = seg_sqrt_f4(g, t.y);
  S P, Q;
  if constexpr (E) {
    P = (X3 * Y4 + Y3 * X4) * T(0.5);
    Q = (X3 * X4 + Y3 * Y4) * T(0.5);
  } else {
    P = (X3 + Y3) * T(0.5);
    Q = P;
  }
  const S U12 = Q * t.ch / t.sh - t.ssg * t.sh * seg_g12(g, t.x, t.y) / (T(2) * Q);
  const S a = P / t.sh;
  const S b = seg_d34(g) * t.sh / (T(2) * P);
  const S U13 = a + b;
  const S U14 = a - b;
  if (u14) *u14 = value_of(U14) * (value_of(P) > 0 ? T(1) : T(-1)) * (value_of(t.sh) > 0 ? T(1) : T(-1));
  // One segment's length, paper 001 eq (15), as one Carlson R_F of the quartic R(u) (1 - u^2).
  return g.scale * carlson_rf_ad<Policy>(U12 * U12, U13 * U13, U14 * U14);
}

template <class Policy, class S, bool E>
inline S length_direct(const segment_constants<S, E>& g, const S& psi_y, const S& Y3, const S& psi_x,
                       const S& X3, scalar_of_t<S>* u14 = nullptr) {
  return length_direct<Policy>(g, make_direct_trig(psi_y, psi_x), Y3, X3, u14);
}

// Signed distance from (psi_e, X3) to the turning point psi* = a = asin(u+) above it (theta'
// positive on the way): sqrt(2EI) X3 R_F(V^2) with V = X3 U. Replacing X3^2 by
// f3(sin psi_e) = -2 b3 cos(sigma) sin(h) removes the 0/0 at the turning point, so the form is
// analytic in X3 through 0 (the end passing the turning point). Valid for psi_e in (-pi/2, a].
template <class Policy, class S, bool E>
inline S length_to_turning(const segment_constants<S, E>& g, const S& a, const S& X4top,
                           const S& psi_e, const S& X3) {
  using std::cos; using std::sin;
  using T = scalar_of_t<S>;
  const S h = (a - psi_e) * T(0.5);
  const S sg = (a + psi_e) * T(0.5);
  const S y = sin(psi_e);
  const S Y4 = seg_sqrt_f4(g, y);
  const S sh = sin(h);
  const S A = -g.b3 * cos(sg);
  const S d = seg_d34(g) * sh / X4top;
  const S V13 = A * X4top + d;
  const S V14 = A * X4top - d;
  const S V12 = A * Y4 * cos(h) - sin(sg) * sh * seg_g12(g, g.up, y) / Y4;
  return g.scale * X3 * carlson_rf_ad<Policy>(V12 * V12, V13 * V13, V14 * V14);
}

// Signed distance from u = -1 (psi = -pi/2) to psi_e, positive for psi_e > -pi/2:
// sqrt(2EI) X2 R_F(W^2), W = X2 U (y = -1 makes Y2 = 0 and x - y = X2^2). |X3| of the end.
template <class Policy, class S, bool E>
inline S length_from_bottom(const segment_constants<S, E>& g, const S& psi_e, const S& X3abs) {
  using std::cos; using std::sin; using std::sqrt;
  using T = scalar_of_t<S>;
  const T r2 = seta_sqrt2<T>();
  const S A = psi_e * T(0.5) + seta_pi<T>() / 4;
  const S X1 = r2 * cos(A), X2 = r2 * sin(A);
  const S Y3b = sqrt(g.M - g.b3);
  const S Y4b = seg_sqrt_f4(g, S(T(-1)));
  const S X4 = seg_sqrt_f4(g, sin(psi_e));
  const S W12 = X1 * Y3b * Y4b;
  const S W13 = r2 * Y3b * X4;
  const S W14 = r2 * Y4b * X3abs;
  return g.scale * X2 * carlson_rf_ad<Policy>(W12 * W12, W13 * W13, W14 * W14);
}

// Signed distance from psi_e to u = +1 (psi = pi/2), positive for psi_e < pi/2 (rotation only,
// where f3 > 0 on [-1, 1]).
template <class Policy, class S, bool E>
inline S length_to_top(const segment_constants<S, E>& g, const S& psi_e, const S& X3abs) {
  using std::cos; using std::sin; using std::sqrt;
  using T = scalar_of_t<S>;
  const T r2 = seta_sqrt2<T>();
  const S A = psi_e * T(0.5) + seta_pi<T>() / 4;
  const S Y1 = r2 * cos(A), Y2 = r2 * sin(A);
  const S X3t = sqrt(g.M + g.b3);
  const S X4t = seg_sqrt_f4(g, S(T(1)));
  const S Y4 = seg_sqrt_f4(g, sin(psi_e));
  const S W12 = Y2 * X3t * X4t;
  const S W13 = r2 * X3abs * X4t;
  const S W14 = r2 * Y4 * X3t;
  return g.scale * Y1 * carlson_rf_ad<Policy>(W12 * W12, W13 * W13, W14 * W14);
}

// Quarter period of a libration (u+ < 1): the length from u = -1 to the turning point.
template <class Policy, class S, bool E>
inline S quarter_libration(const segment_constants<S, E>& g, const S& X4top) {
  using std::sqrt;
  using T = scalar_of_t<S>;
  const S X1 = sqrt(T(1) - g.up), X2 = sqrt(T(1) + g.up);
  const S Y3b = sqrt(g.M - g.b3);
  const S Y4b = seg_sqrt_f4(g, S(T(-1)));
  const S U12 = X1 * Y3b * Y4b / X2;
  const S U13 = seta_sqrt2<T>() * Y3b * X4top / X2;
  return g.scale * carlson_rf0_ad<Policy>(U12 * U12, U13 * U13);
}

// Half period of a rotation (u+ > 1): the length from u = -1 to u = +1.
template <class Policy, class S, bool E>
inline S half_rotation(const segment_constants<S, E>& g) {
  using std::sqrt;
  using T = scalar_of_t<S>;
  const S U13 = sqrt(g.M - g.b3) * seg_sqrt_f4(g, S(T(1)));
  const S U14 = seg_sqrt_f4(g, S(T(-1))) * sqrt(g.M + g.b3);
  return g.scale * carlson_rf0_ad<Policy>(U13 * U13, U14 * U14);
}

// ---- plans: which form measures a segment ---------------------------------------------------
// A plan is chosen from a state estimate and kept fixed during one Newton solve (the residual
// must be one smooth function there); at the converged state it is checked again
// (segment_plan_valid) and the solve repeated with a fresh plan if it no longer applies.
enum class segment_rep : unsigned char {
  turning_max,   // near the turning point above (theta max), libration
  turning_min,   // near the turning point below (theta min), libration
  bottom_up,     // near u = -1, theta' > 0, libration
  bottom_down,   // near u = -1, theta' < 0, libration
  rot_bottom,    // near u = -1, rotation
  rot_top        // near u = +1, rotation
};

enum class segment_state : unsigned char {
  ok = 0,
  infeasible,    // R < 0 somewhere it must not be, or the ends disagree (not a state at all)
  unsupported    // outside what the Carlson forms here cover (f4 root reachable: |T| ~ EA)
};

struct segment_plan {
  bool direct = true;
  bool libration = false;
  segment_rep rep_s = segment_rep::turning_max, rep_e = segment_rep::turning_max;
  int shift_s = 0, shift_e = 0;  // 2 pi shifts of the ends when planned (informative only: the
                                 // forms recompute them, see phase_shift)
  int periods = 0;               // 4K added to unwrap the phase difference (libration)
  int turning_points = 0;        // sign changes of theta' strictly inside, at the planned state
  segment_state state = segment_state::ok;
};

inline bool operator==(const segment_plan& a, const segment_plan& b) {
  return a.direct == b.direct && a.libration == b.libration && a.rep_s == b.rep_s &&
         a.rep_e == b.rep_e &&
         a.periods == b.periods && a.state == b.state;
}

// The 2 pi shift that brings psi next to the centre of its form: -pi/2 (the libration window,
// the bottom of a rotation) or pi/2 (the top of a rotation). Recomputed at every evaluation, so a
// 2 pi jump of phi = atan2(Fn, Ft) (Fn crossing 0 with Ft < 0) changes nothing; the forms are
// used within less than pi of their centre, far from the rounding boundary.
template <class T>
inline int phase_shift(segment_rep rep, T psi) {
  using std::floor;
  const T pi = seta_pi<T>();
  const T centre = rep == segment_rep::rot_top ? pi / 2 : -pi / 2;
  return static_cast<int>(floor((psi - centre) / (2 * pi) + T(0.5)));
}

// Phase of one end on the libration cycle (T_min at 0, bottom (up) at K, T_max at 2K, bottom
// (down) at 3K, period 4K), from the form of rep; psi is already reduced to the window.
template <class Policy, class S, bool E>
inline S libration_phase(const segment_constants<S, E>& g, const S& a, const S& X4top, const S& K,
                         segment_rep rep, const S& psi, const S& X3) {
  using T = scalar_of_t<S>;
  switch (rep) {
    case segment_rep::turning_max:
      return T(2) * K - length_to_turning<Policy>(g, a, X4top, psi, X3);
    case segment_rep::turning_min:  // mirror psi -> -pi - psi maps T_min onto T_max
      return length_to_turning<Policy>(g, a, X4top, S(-seta_pi<T>()) - psi, X3);
    case segment_rep::bottom_up:
      return K + length_from_bottom<Policy>(g, psi, X3);
    default:  // bottom_down
      return T(3) * K - length_from_bottom<Policy>(g, psi, -X3);
  }
}

template <class Policy, class S, bool E>
inline S rotation_phase(const segment_constants<S, E>& g, const S& Kr, segment_rep rep,
                        const S& psi, const S& X3abs) {
  if (rep == segment_rep::rot_bottom) return length_from_bottom<Policy>(g, psi, X3abs);
  return Kr - length_to_top<Policy>(g, psi, X3abs);
}

// The segment length under a given plan (paper 001 eq (15), split at turning points); psi_s, X3s
// at the start (s small), psi_e, X3e at the end. X3 = sign(theta') sqrt(f3).
// trig: the direct form's trigonometry when the caller has it (else computed from the angles).
template <class Policy, class S, bool E>
inline S segment_length(const segment_constants<S, E>& g, const segment_plan& plan, const S& psi_s,
                        const S& X3s, const S& psi_e, const S& X3e,
                        scalar_of_t<S>* u14 = nullptr, const direct_trig<S>* trig = nullptr) {
  using std::asin; using std::fabs;
  using T = scalar_of_t<S>;
  if (plan.direct) {
    if (trig) return length_direct<Policy>(g, *trig, X3s, X3e, u14);
    return length_direct<Policy>(g, psi_s, X3s, psi_e, X3e, u14);
  }
  const T two_pi = 2 * seta_pi<T>();
  const int shift_s = phase_shift(plan.rep_s, value_of(psi_s));
  const int shift_e = phase_shift(plan.rep_e, value_of(psi_e));
  const S ps = psi_s - T(shift_s) * two_pi;
  const S pe = psi_e - T(shift_e) * two_pi;
  if (plan.libration) {
    const S a = asin(g.up);
    const S X4top = seg_sqrt_f4(g, g.up);
    // K cancels between the ends when both use the same form and no period is added.
    const bool need_K = plan.rep_s != plan.rep_e || plan.periods != 0;
    const S K = need_K ? quarter_libration<Policy>(g, X4top) : S(T(0));
    const S ts = libration_phase<Policy>(g, a, X4top, K, plan.rep_s, ps, X3s);
    const S te = libration_phase<Policy>(g, a, X4top, K, plan.rep_e, pe, X3e);
    return te - ts + T(4 * plan.periods) * K;
  }
  const S Kr = half_rotation<Policy>(g);
  const T sign = value_of(X3s) >= 0 ? T(1) : T(-1);
  const S X3sa = X3s * sign, X3ea = X3e * sign;
  const S ts = rotation_phase<Policy>(g, Kr, plan.rep_s, ps, X3sa) + T(2 * shift_s) * Kr;
  const S te = rotation_phase<Policy>(g, Kr, plan.rep_e, pe, X3ea) + T(2 * shift_e) * Kr;
  return (te - ts) * sign;
}

// The direct form measures the short path between the two ends; it is the physical one when
// theta' has one sign at both ends, theta moves in the direction of that sign, and |h| < pi
// (and the path is shorter than a quarter period: U14 > 0, checked by the caller).
template <class T, bool E>
inline bool direct_orientation_ok(const segment_constants<T, E>& g, T h, T X3s, T X3e) {
  using std::fabs;
  const T pi = seta_pi<T>();
  if (!(fabs(h) < pi)) return false;
  const bool ps = X3s >= 0, pe = X3e >= 0;
  (void)g;
  // Opposite signs (a turning point inside) are left to the phase forms: with the ends level
  // on both sides of the turning point, P = (X3 Y4 + Y3 X4)/2 and sin h both vanish and the
  // direct form would lose digits to cancellation.
  if (ps != pe) return false;
  return ps ? h > 0 : h < 0;
}

// The phase form a libration end uses: near a turning point (sin psi above the midpoint of u+
// and -1) the turning-point form of that side, else the bottom form of theta's direction.
template <class T, bool E>
inline segment_rep libration_rep(const segment_constants<T, E>& g, T psi, T X3) {
  using std::cos; using std::sin;
  if (sin(psi) > (g.up - 1) / 2) return cos(psi) > 0 ? segment_rep::turning_max : segment_rep::turning_min;
  return X3 >= 0 ? segment_rep::bottom_up : segment_rep::bottom_down;
}

// One end of a libration segment that stays fixed while the other moves (the spatula's contact
// edge in the forward problem), with the segment's libration constants: plan_segment reads them
// instead of measuring the end again (one R_F per length instead of three).
template <class T>
struct libration_end {
  T a = 0, X4top = 0, K = 0;  // asin(u+), sqrt(f4(u+)), the quarter period
  T phase = 0;                // the end's phase on the cycle (libration_phase)
  segment_rep rep = segment_rep::turning_max;
  int shift = 0;
};

// False (nothing set) unless g is a libration the phase forms cover.
template <class Policy, class T, bool E>
inline bool make_libration_end(const segment_constants<T, E>& g, T psi_e, T X3e, libration_end<T>& end) {
  using std::asin;
  if (!(g.N > 0) || !(g.s > 0) || !(g.scale > 0) || !(g.up > -1) || !(g.up < 1)) return false;
  if constexpr (E) {
    if (!(g.b4 < 1)) return false;
  }
  end.a = asin(g.up);
  end.X4top = seg_sqrt_f4(g, g.up);
  end.K = quarter_libration<Policy>(g, end.X4top);
  end.shift = phase_shift(segment_rep::bottom_up, psi_e);
  const T pe = psi_e - end.shift * 2 * seta_pi<T>();
  end.rep = libration_rep(g, pe, X3e);
  end.phase = libration_phase<Policy>(g, end.a, end.X4top, end.K, end.rep, pe, X3e);
  return end.phase == end.phase;
}

// Choose the plan for a state (plain values). direct_limit: largest path, in quarter periods,
// measured with the direct form (< 1; margin for the Newton iterates around the state).
// length: where given, receives the path length the plan was made from (phases and quarter
// periods, as segment_length would measure it; only for a phase plan: a direct plan's length is
// the direct form's). end_e: where given, the end (psi_e, X3e) measured before
// (make_libration_end with the same g and end), used on a libration.
// target: where given (not NaN), the segment's length at the state, which is then a solved state
// (a node of a followed line): see the period choice below.
// The most libration periods a plan adds to a segment's phase difference (plan_segment): far more
// than a segment of the stress box reaches (a beam 1,000 elastic lengths long has ~160).
constexpr int max_libration_periods = 4096;

template <class Policy, class T, bool E>
inline segment_plan plan_segment(const segment_constants<T, E>& g, T psi_s, T X3s, T psi_e, T X3e,
                                 T direct_limit = T(0.75), T* length = nullptr,
                                 const libration_end<T>* end_e = nullptr,
                                 T target = std::numeric_limits<T>::quiet_NaN()) {
  using std::asin; using std::cos; using std::fabs; using std::floor; using std::sin;
  const T pi = seta_pi<T>();
  const T two_pi = 2 * pi;
  segment_plan plan;
  if (!(g.N > 0) || !(value_of(g.s) > 0) || !(g.scale > 0)) {
    plan.state = segment_state::infeasible;
    return plan;
  }
  if constexpr (E) {
    // f4 must stay positive on [-1, 1]: its root u- = -1/b4 < -1, i.e. b4 < 1.
    if (!(g.b4 < 1)) {
      plan.state = segment_state::unsupported;
      return plan;
    }
  }
  if (!(g.up > -1)) {  // f3 < 0 on all of [-1, 1]: no real state
    plan.state = segment_state::infeasible;
    return plan;
  }
  const T sgn_s = X3s >= 0 ? T(1) : T(-1);
  const T sgn_e = X3e >= 0 ? T(1) : T(-1);
  plan.libration = g.up < 1;
  T L = 0, quarter = 0;
  if (plan.libration) {
    const T a = end_e ? end_e->a : asin(g.up);
    const T X4top = end_e ? end_e->X4top : seg_sqrt_f4(g, g.up);
    const T K = end_e ? end_e->K : quarter_libration<Policy>(g, X4top);
    // Window [-pi - a, a) + 2 pi j: the ends must lie in one (theta oscillates inside it).
    plan.shift_s = phase_shift(segment_rep::bottom_up, psi_s);
    plan.shift_e = end_e ? end_e->shift : phase_shift(segment_rep::bottom_up, psi_e);
    if (plan.shift_s != plan.shift_e) {
      plan.state = segment_state::infeasible;
      return plan;
    }
    const T ps = psi_s - plan.shift_s * two_pi, pe = psi_e - plan.shift_e * two_pi;
    plan.rep_s = libration_rep(g, ps, X3s);
    plan.rep_e = end_e ? end_e->rep : libration_rep(g, pe, X3e);
    const T ts = libration_phase<Policy>(g, a, X4top, K, plan.rep_s, ps, X3s);
    const T te = end_e ? end_e->phase : libration_phase<Policy>(g, a, X4top, K, plan.rep_e, pe, X3e);
    plan.periods = te - ts > 0 ? 0 : 1;
    // The phases are defined modulo the period 4K (and the forms of the two sides of a turning
    // point name one point by phases 4K apart), so they alone cannot tell a path of te - ts from
    // one a period longer: where the ends' phases coincide (a segment about one libration long,
    // paper 001 eq (15) with l = 4K), the rule above drops a period as soon as te passes ts, and
    // the length jumps by 4K between two states of one line (the continuation then never
    // converges past them). At a solved state the length is known, and the period count is the
    // one that gives it. Lines towards negative Ft put the segments in compression, where they
    // wave with a libration period of about 2 pi elastic lengths (EI/N)^(1/2), their count
    // growing as the square root of the force: a count held below 4 dropped the periods of a beam 20
    // elastic lengths long, and the line ended as no_convergence there (campaign design 3621).
    // max_libration_periods only keeps the count an int.
    if (target == target) {
      const T n = floor((target - (te - ts)) / (4 * K) + T(0.5));
      if (n > plan.periods && n <= max_libration_periods) plan.periods = static_cast<int>(n);
    }
    L = te - ts + 4 * plan.periods * K;
    quarter = K;
    // Turning points: phases 0 and 2K (mod 4K) strictly inside (ts, ts + L).
    const T p0 = ts - 4 * K * floor(ts / (4 * K));
    const T p1 = p0 + L;
    int count = 0;
    for (int k = 0; k <= 2 * max_libration_periods + 4; ++k) {
      const T tp = 2 * K * k;
      if (!(tp < p1)) break;
      if (tp > p0) ++count;
    }
    plan.turning_points = count;
  } else {
    if (sgn_s != sgn_e) {  // rotation: theta' cannot vanish, the signs must agree
      plan.state = segment_state::infeasible;
      return plan;
    }
    const T Kr = half_rotation<Policy>(g);
    auto choose = [&](T psi, int& shift) {
      const segment_rep rep = sin(psi) <= 0 ? segment_rep::rot_bottom : segment_rep::rot_top;
      shift = phase_shift(rep, psi);
      return rep;
    };
    plan.rep_s = choose(psi_s, plan.shift_s);
    plan.rep_e = choose(psi_e, plan.shift_e);
    const T ts = rotation_phase<Policy>(g, Kr, plan.rep_s, psi_s - plan.shift_s * two_pi, fabs(X3s)) +
                 2 * plan.shift_s * Kr;
    const T te = rotation_phase<Policy>(g, Kr, plan.rep_e, psi_e - plan.shift_e * two_pi, fabs(X3e)) +
                 2 * plan.shift_e * Kr;
    L = (te - ts) * sgn_s;
    if (!(L > 0)) {
      plan.state = segment_state::infeasible;
      return plan;
    }
    quarter = Kr;
    plan.turning_points = 0;
  }
  if (!(L > 0) || !(L == L)) {
    plan.state = segment_state::infeasible;
    return plan;
  }
  // The direct form covers the short paths; it needs the orientation that makes the short path
  // the physical one (checked again at the solution by direct_plan_valid).
  const bool short_path = L < direct_limit * quarter;
  plan.direct = short_path && direct_orientation_ok(g, (psi_e - psi_s) / 2, X3s, X3e);
  if (plan.direct) {
    plan.shift_s = plan.shift_e = 0;
    plan.periods = 0;
  } else if (length) {
    *length = L;
  }
  return plan;
}

// Turning points inside a segment at a state measured with `plan` (the plan's own count is that
// of the state it was made for; a plan stays valid while an end's rate changes sign). On a path
// shorter than a full libration (4K) the end signs decide: opposite signs give one, equal signs
// with theta moving against them two. A libration plan that added a period (made where the end
// phase te was behind the start phase ts) stays valid when the Newton iterates carry te past ts:
// the path is then te - ts + 4K, a full period more, and passes both turning points of that
// period. The stress campaign found such states (bench/results/stress.md: a spatula and a beam
// whose ends lie 0.001-0.002 rad apart on a path of one period; the end signs alone said 0, the
// ODE 2), so there the phases decide. psi_s, psi_e are only read for such plans.
template <class Policy, class T, bool E>
inline int segment_turning_points(const segment_constants<T, E>& g, const segment_plan& plan, T psi_s, T X3s,
                                  T psi_e, T X3e, T h) {
  if (!plan.direct && !plan.libration) return 0;  // rotation: theta' keeps its sign
  const bool ps = X3s >= 0, pe = X3e >= 0;
  const int within_period = ps != pe ? 1 : ((ps ? h > 0 : h < 0) ? 0 : 2);
  if (plan.direct || plan.periods == 0) return within_period;
  using std::asin;
  const T two_pi = 2 * seta_pi<T>();
  const T a = asin(g.up);
  const T X4top = seg_sqrt_f4(g, g.up);
  const T K = quarter_libration<Policy>(g, X4top);
  const T ts = libration_phase<Policy>(g, a, X4top, K, plan.rep_s, psi_s - phase_shift(plan.rep_s, psi_s) * two_pi, X3s);
  const T te = libration_phase<Policy>(g, a, X4top, K, plan.rep_e, psi_e - phase_shift(plan.rep_e, psi_e) * two_pi, X3e);
  // te - ts + 4K periods: with te > ts every added period passes two turning points, with te < ts
  // the first added period only closes the path.
  return te > ts ? within_period + 2 * plan.periods : within_period + 2 * (plan.periods - 1);
}

// Is a plan still right at a (converged) state? u14: the direct form's U14 there.
// h = (theta_end - theta_start)/2 (psi_s, psi_e are only needed, and only set, for phase plans).
template <class T, bool E>
inline bool segment_plan_valid(const segment_constants<T, E>& g, const segment_plan& plan, T psi_s,
                               T X3s, T psi_e, T X3e, T u14, T h) {
  using std::asin; using std::cos; using std::fabs; using std::sin;
  const T pi = seta_pi<T>();
  const T two_pi = 2 * pi;
  if (plan.state != segment_state::ok) return false;
  if constexpr (E) {
    if (!(g.b4 < 1)) return false;
  }
  if (plan.direct) return u14 > 0 && direct_orientation_ok(g, h, X3s, X3e);
  if (plan.libration != (g.up < 1)) return false;
  if (plan.libration) {
    const T a = asin(g.up);
    // An end exactly at a turning point (the contact edge at (Ft)max) may round just outside.
    const T tol = 64 * std::numeric_limits<T>::epsilon() * (1 + fabs(psi_s) + fabs(psi_e));
    const int shift_s = phase_shift(plan.rep_s, psi_s), shift_e = phase_shift(plan.rep_e, psi_e);
    if (shift_s != shift_e) return false;
    auto in_window = [&](T psi, int shift) {
      const T pr = psi - shift * two_pi;
      return pr > -pi - a - tol && pr < a + tol;
    };
    auto rep_ok = [&](segment_rep rep, T psi, int shift, T X3) {
      const T pr = psi - shift * two_pi;
      switch (rep) {
        case segment_rep::turning_max: return cos(pr) > 0;
        case segment_rep::turning_min: return cos(pr) < 0;
        case segment_rep::bottom_up: return X3 > 0;
        case segment_rep::bottom_down: return X3 < 0;
        default: return false;
      }
    };
    return in_window(psi_s, shift_s) && in_window(psi_e, shift_e) && rep_ok(plan.rep_s, psi_s, shift_s, X3s) &&
           rep_ok(plan.rep_e, psi_e, shift_e, X3e);
  }
  if ((X3s >= 0) != (X3e >= 0)) return false;
  auto rot_ok = [&](segment_rep rep, T psi, int shift) {
    const T pr = psi - shift * two_pi;
    if (rep == segment_rep::rot_bottom) return pr > -3 * pi / 2 && pr < pi / 2;
    if (rep == segment_rep::rot_top) return pr > -pi / 2 && pr < 3 * pi / 2;
    return false;
  };
  return rot_ok(plan.rep_s, psi_s, phase_shift(plan.rep_s, psi_s)) &&
         rot_ok(plan.rep_e, psi_e, phase_shift(plan.rep_e, psi_e));
}

}  // namespace detail

// ---- public: one segment -----------------------------------------------------------------------
// The shortest elastica path that leaves theta_start with theta' of sign sign_start and arrives
// at theta_end with sign sign_end (turning points in between where needed). EA = infinity selects
// the inextensible (cubic) forms at compile time.
template <class T>
struct elastica_segment_result {
  T length;
  int turning_points;
};

namespace detail {
template <bool E, class T, class Policy>
inline elastica_segment_result<T> elastica_segment_imp(T EI, T EA, T M, T Fn, T Ft, T theta_start,
                                                       T theta_end, int sign_start, int sign_end) {
  using std::atan2; using std::hypot; using std::sin; using std::sqrt;
  constexpr const char* fn = "gecko::elastica_segment";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T c = E ? T(1) / EA : T(0);
  const T N = hypot(Fn, Ft);
  if (!(N > 0)) return {raise_domain_error<T, Policy>(fn, "hypot(Fn, Ft)", N, "a nonzero force"), -1};
  const T phi = atan2(Fn, Ft);
  const auto g = make_segment<E>(EI, c, M, N);
  const T ps = theta_start - phi, pe = theta_end - phi;
  const T f3s = seg_f3(g, sin(ps)), f3e = seg_f3(g, sin(pe));
  if (!(f3s >= 0))
    return {raise_domain_error<T, Policy>(fn, "theta_start", theta_start,
                                          "an angle where the elastica can be (R(theta) >= 0)"), -1};
  if (!(f3e >= 0))
    return {raise_domain_error<T, Policy>(fn, "theta_end", theta_end,
                                          "an angle where the elastica can be (R(theta) >= 0)"), -1};
  const T X3s = sign_start >= 0 ? sqrt(f3s) : -sqrt(f3s);
  const T X3e = sign_end >= 0 ? sqrt(f3e) : -sqrt(f3e);
  const segment_plan plan = plan_segment<Policy>(g, ps, X3s, pe, X3e);
  if (plan.state == segment_state::unsupported)
    return {raise_domain_error<T, Policy>(fn, "N/EA", N * c,
                                          "an axial load below the range where f4 vanishes on the path"), -1};
  if (plan.state != segment_state::ok) return {nan, -1};
  return {segment_length<Policy>(g, plan, ps, X3s, pe, X3e), plan.turning_points};
}
}  // namespace detail

template <class T, class Policy = policies::default_policy>
inline elastica_segment_result<T> elastica_segment(T EI, T EA, T M, T Fn, T Ft, T theta_start,
                                                   T theta_end, int sign_start, int sign_end,
                                                   const Policy& = Policy()) {
  using std::isinf;
  constexpr const char* fn = "gecko::elastica_segment";
  if (!(EI > 0)) return {raise_domain_error<T, Policy>(fn, "EI", EI, "EI > 0"), -1};
  if (!(EA > 0)) return {raise_domain_error<T, Policy>(fn, "EA", EA, "EA > 0 (infinity allowed)"), -1};
  if (isinf(EA))
    return detail::elastica_segment_imp<false, T, Policy>(EI, EA, M, Fn, Ft, theta_start, theta_end,
                                                          sign_start, sign_end);
  return detail::elastica_segment_imp<true, T, Policy>(EI, EA, M, Fn, Ft, theta_start, theta_end,
                                                       sign_start, sign_end);
}

template <class T, class Policy = policies::default_policy>
inline T elastica_segment_length(T EI, T EA, T M, T Fn, T Ft, T theta_start, T theta_end,
                                 int sign_start = 1, int sign_end = 1, const Policy& pol = Policy()) {
  return elastica_segment(EI, EA, M, Fn, Ft, theta_start, theta_end, sign_start, sign_end, pol).length;
}

}  // namespace gecko
