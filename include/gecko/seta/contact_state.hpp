// gecko/seta/contact_state.hpp — the forward problem of the two-level seta: the contact state at a
// given load (Fn, Ft).
//
// Paper 001, after eq (15): "if Fn and Ft are given, theta2(l1) can be solved from the second
// equation and then a from the first". At a given load the contact edge is in equilibrium when
// Griffith's condition holds there (eq 3), so the spatula's first integral is fixed,
// M2 = Ft + w (eqs 8, 12), whatever a is. A joint state (beta = theta2(l1), theta2'(l1)) lies on
// the spatula's orbit through the edge state (theta2 = pi/2, theta2' > 0), at the orbit distance
// t = a - l1 before the edge (eq 15, first equation); the beam's first integral M1 follows from the
// joint conditions (eq 4), and the beam must reach the joint state from theta1(0) = alpha1 in
// exactly l1 (eq 15, second equation, with eq 5). So every equilibrium is a root of
//     G(beta) = L_beam(beta) - l1
// along the part of the spatula orbit with 0 < t <= l2, and a = l1 + t there.
//
// The orbit part 0 <= t <= l2 is mapped to beta (monotone pieces between the spatula's turning
// points, theta2' changing sign at their ends); G is scanned on each piece for both signs of the
// base rate theta1'(0) (the beam's two branches, joined where theta1'(0) = 0), every sign change
// is refined by a bracketing solver (Brent) to full precision, and a local minimum of |G| between
// scan nodes is searched for a hidden pair of roots. Extra nodes go where G is not smooth between
// scan nodes: the joins of the two branches (found with a Lipschitz bound on R1(alpha1), no R_F),
// the beam's zero-length jump at theta1(l1) = alpha1, and the edge of a stretch without beam
// states. Both lengths are the closed-form Carlson forms of gecko/seta/elastica_segment.hpp
// (turning points included); nothing is integrated. Each equilibrium is then checked for
// admissibility (gecko/seta/admissibility.hpp: the seta above the substrate before the edge, a
// positive stretch 1 + T/EA everywhere, an optional strain limit).
//
// Where no equilibrium has 0 < t <= l2, G has one sign at both ends and says where the equilibrium
// went: beyond t = l2 (the seta would need a longer spatula: a load below the critical line, where
// the seta loses side contact: no_contact), or before t = 0 (the contact edge would pass the joint
// onto the beam, which is outside the model: beyond_joint); see the end of contact_solve. Without
// load this is eq (22): no side contact iff G(l2) > 0.
//
// Convention (as the critical solver's): each segment is measured along the shortest elastica
// path with the given end rates, so the spatula is followed back from the edge for less than one
// period of its orbit (longer orbits pass the edge's orientation theta2 = pi/2 before the edge).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/admissibility.hpp"
#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/extensibility.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

// What the forward solve found. 0 only when exactly one admissible equilibrium has its contact
// edge on the spatula (l1 < a <= l1 + l2); the numbers shared with critical_status mean the same.
enum class contact_status : int {
  converged = 0,
  not_converged = 1,       // a bracketed root could not be refined, or the scan could not decide
  no_contact = 2,          // below the critical line: the seta is not in side contact at this load
  unsupported_state = 3,   // the spatula orbit leaves the model's forms (axial load comparable to
                           // EA), or l2 exceeds one period of the spatula's orbit
  beyond_joint = 4,        // the contact edge would pass the joint onto the beam (outside the model)
  invalid_input = 5,       // bad input under nan_policy
  several_equilibria = 6,  // more than one admissible equilibrium with l1 < a <= l1 + l2 (see
                           // `equilibria`; contact_equilibria returns all of them)
  inadmissible = 7         // equilibria exist, but none is admissible: the seta crosses the substrate
                           // before the edge (joint or beam below z = 0), a segment is compressed to
                           // zero length (min_stretch <= 0), or it exceeds the strain limit; the
                           // (first) state's values are kept for drawing
};

template <class T>
struct contact_result {
  T Fn = std::numeric_limits<T>::quiet_NaN();
  T Ft = std::numeric_limits<T>::quiet_NaN();
  T a = std::numeric_limits<T>::quiet_NaN();               // non-contact length (convected s)
  T contact_length = std::numeric_limits<T>::quiet_NaN();  // l1 + l2 - a
  T theta_joint = std::numeric_limits<T>::quiet_NaN();     // beta = theta2(l1)
  T theta_rate_joint = std::numeric_limits<T>::quiet_NaN();  // theta2'(l1)
  T theta_rate_base = std::numeric_limits<T>::quiet_NaN();   // theta1'(0)
  int turning_points = -1;           // sign changes of theta' inside 0 < s < a (beam + spatula)
  int turning_points_beam = -1;
  int turning_points_spatula = -1;
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();  // max |T(theta)|/EA over 0 <= s <= a
  T min_stretch = std::numeric_limits<T>::quiet_NaN();       // min 1 + T/EA over 0 <= s <= a (<= 0: status 7)
  // Left side of eq (3) at the edge, 1/2 EI2 theta2'(a)^2 + T(pi/2)^2/(2 EA2), from the solved
  // spatula state: equal to w at every equilibrium (it is the condition that fixes a).
  T energy_release_rate = std::numeric_limits<T>::quiet_NaN();
  // Lowest height of the seta above the substrate over 0 <= s <= a (0 at the edge; < 0:
  // inadmissible), from gecko/seta/admissibility.hpp.
  T min_z = std::numeric_limits<T>::quiet_NaN();
  int equilibria = 0;  // equilibria found with l1 < a <= l1 + l2 (admissible or not)
  contact_status status = contact_status::not_converged;
};

template <class T>
struct contact_options {
  // Scan nodes per monotone piece of the spatula orbit (each piece is also searched between
  // nodes for a hidden pair of roots). More nodes: more robust, slower.
  int scan_points = 6;
  // A root within this (relative to l1 + l2) of t = l2 is the critical state itself and counts
  // as an equilibrium with a = l1 + l2 (the critical line is the boundary of contact).
  T edge_tolerance = T(1e-12);
  // Equilibria whose largest axial strain |T|/EA exceeds this are inadmissible (status 7).
  T strain_limit = std::numeric_limits<T>::infinity();
};

namespace detail {

template <class T>
struct contact_root {
  T beta;
  int sp, sq;  // signs of theta2'(l1) and theta1'(0)
};

// Brent's method (R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 4)
// on [a, b] with f(a) f(b) <= 0; returns false when f fails (NaN) inside.
template <class T, class F>
inline bool brent_root(F& f, T a, T b, T fa, T fb, T& root, int max_iterations = 100) {
  using std::fabs;
  const T eps = std::numeric_limits<T>::epsilon();
  if (fa == 0) { root = a; return true; }
  if (fb == 0) { root = b; return true; }
  T c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < max_iterations; ++it) {
    if ((fb > 0) == (fc > 0)) { c = a; fc = fa; d = b - a; e = d; }
    if (fabs(fc) < fabs(fb)) { a = b; b = c; c = a; fa = fb; fb = fc; fc = fa; }
    const T tol = 2 * eps * fabs(b) + std::numeric_limits<T>::min();
    const T m = (c - b) / 2;
    if (fabs(m) <= tol || fb == 0) { root = b; return true; }
    if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
      const T s = fb / fa;
      T p, q;
      if (a == c) {
        p = 2 * m * s;
        q = 1 - s;
      } else {
        const T qq = fa / fc, r = fb / fc;
        p = s * (2 * m * qq * (qq - r) - (b - a) * (r - 1));
        q = (qq - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q; else p = -p;
      if (2 * p < 3 * m * q - fabs(tol * q) && p < fabs(e * q / 2)) { e = d; d = p / q; }
      else { d = m; e = m; }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += fabs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
    if (!(fb == fb)) return false;
  }
  root = b;
  return true;
}

// Brent's minimiser (Brent 1973, ch. 5: golden section with parabolic steps) of f on the interval
// between a and b (either order), from the interior point x with f(x) = fx. Stops as soon as
// f <= 0 (the caller only asks whether the minimum crosses zero), when the minimum is located to
// sqrt(eps) relative (f is then within rounding of its minimum), or when f fails (NaN). x, fx:
// the lowest point found. A smooth minimum takes about ten evaluations where golden section alone
// needs forty for the same decision.
template <class T, class F>
inline void brent_min(F& f, T a, T b, T& x, T& fx, int max_iterations = 40) {
  using std::fabs; using std::sqrt;
  const T gold = T(0.381966011250105151795413165634361882L);
  const T rel = sqrt(std::numeric_limits<T>::epsilon());
  if (b < a) { const T t = a; a = b; b = t; }
  T w = x, v = x, fw = fx, fv = fx, d = 0, e = 0;
  for (int it = 0; it < max_iterations && fx > 0; ++it) {
    const T m = (a + b) / 2;
    const T tol = rel * fabs(x) + T(1e-14), t2 = 2 * tol;
    if (fabs(x - m) <= t2 - (b - a) / 2) break;
    T p = 0, q = 0;
    if (fabs(e) > tol) {  // a parabola through x, w, v
      const T r = (x - w) * (fx - fv);
      q = (x - v) * (fx - fw);
      p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p; else q = -q;
    }
    const T e_prev = e;
    if (fabs(p) < fabs(q * e_prev / 2) && p > q * (a - x) && p < q * (b - x)) {
      e = d;
      d = p / q;
      const T u = x + d;
      if (u - a < t2 || b - u < t2) d = x < m ? tol : -tol;
    } else {
      e = (x < m ? b : a) - x;
      d = gold * e;
    }
    const T u = fabs(d) >= tol ? x + d : x + (d > 0 ? tol : -tol);
    const T fu = f(u);
    if (!(fu == fu)) break;
    if (fu <= fx) {
      if (u < x) b = x; else a = x;
      v = w; fv = fw; w = x; fw = fx; x = u; fx = fu;
    } else {
      if (u < x) a = u; else b = u;
      if (fu <= fw || w == x) { v = w; fv = fw; w = u; fw = fu; }
      else if (fu <= fv || v == x || v == w) { v = u; fv = fu; }
    }
  }
}

// The forward problem at one load, for one design (E1, E2: extensible beam / spatula).
template <class Policy, bool E1, bool E2, class T>
struct forward_problem {
  const seta_params<T>& d;
  T Fn, Ft, N, phi, edge, ftmax;
  segment_constants<T, E2> g2;  // the spatula: M2 = Ft + w (eqs 8, 12)
  T psi_edge;                   // pi/2 - phi
  T ratio;                      // EI2/EI1
  T cphi, sphi;                 // cos, sin phi = Ft/N, Fn/N
  T u0;                         // sin(alpha1 - phi)
  T sqrt_ratio, X3_edge;        // sqrt(EI2/EI1); X3 of the contact edge (theta2' > 0 there)
  // The spatula's end is the contact edge for every joint state: on a libration its phase and
  // the quarter period are the load's, measured once, when a phase plan first needs them (most
  // loads measure the spatula with the direct form only).
  mutable libration_end<T> edge_end;
  mutable int edge_end_state = 0;  // 0: not measured yet, 1: edge_end holds it, -1: not a libration

  forward_problem(const seta_params<T>& params, T fn, T ft) : d(params), Fn(fn), Ft(ft) {
    using std::atan2; using std::hypot; using std::sqrt;
    N = hypot(Fn, Ft);
    phi = atan2(Fn, Ft);
    ftmax = E2 ? sqrt(2 * d.w / d.c2) : std::numeric_limits<T>::infinity();
    if constexpr (E2) {
      const T r = Ft / ftmax;
      edge = sqrt((1 - r) * (1 + r));  // theta2'(a) / sqrt(2 w / EI2), eq (3)
    } else {
      edge = T(1);
    }
    g2 = make_segment<E2>(d.EI2, d.c2, Ft + d.w, N);
    psi_edge = seta_pi<T>() / 2 - phi;
    ratio = d.EI2 / d.EI1;
    cphi = N > 0 ? Ft / N : T(1);
    sphi = N > 0 ? Fn / N : T(0);
    u0 = d.s1 * cphi - d.co1 * sphi;
    sqrt_ratio = sqrt(ratio);
    // f3 at the contact edge: (w - c Ft^2/2)/f4 = w edge^2/f4(Ft/N) (as make_seta_geometry).
    X3_edge = sqrt(d.w) * edge / seg_sqrt_f4(g2, cphi);
  }
  const libration_end<T>* spatula_edge_end() const {
    if (edge_end_state == 0) edge_end_state = make_libration_end<Policy>(g2, psi_edge, X3_edge, edge_end) ? 1 : -1;
    return edge_end_state > 0 ? &edge_end : nullptr;
  }

  // sin(beta - phi) and sin(beta - alpha2 - phi) from one sincos(beta), by angle addition.
  void joint_sines(T beta, T& ub, T& v) const {
    using std::cos; using std::sin;
    joint_sines_half(sin(beta / 2), cos(beta / 2), ub, v);
  }
  // sin and cos of beta - phi, from sb, cb = sin, cos(beta/2).
  void joint_sine_cos_half(T sb, T cb, T& ub, T& cu) const {
    const T sinb = 2 * sb * cb, cosb = (cb - sb) * (cb + sb);
    ub = sinb * cphi - cosb * sphi;
    cu = cosb * cphi + sinb * sphi;
  }
  void joint_sines_half(T sb, T cb, T& ub, T& v) const {
    const T sinb = 2 * sb * cb, cosb = (cb - sb) * (cb + sb);
    ub = sinb * cphi - cosb * sphi;
    const T sj = sinb * d.co2 - cosb * d.s2, cj = cosb * d.co2 + sinb * d.s2;
    v = sj * cphi - cj * sphi;
  }
  // R2 = 1/2 EI2 theta2'^2 at the joint (eq 12 with M2 = Ft + w), u = sin(beta - phi).
  T R2u(T u) const { return g2.M - N * u - d.c2 * N * N * u * u / 2; }
  // R1(alpha1) = 1/2 EI1 theta1'(0)^2 with M1 from the joint conditions (eqs 4, 12).
  T R1v(T v, T p) const {
    T r = ratio * p * p + N * (v - u0);
    if constexpr (E1) r += d.c1 * N * N * (v - u0) * (v + u0) / 2;
    return r;
  }
  // sign * sqrt(r); at a turning point (r <= 0 by rounding) the smallest normal number keeps
  // the sign, which the Carlson forms read (X3 >= 0 or < 0) to know the branch.
  static T signed_sqrt(T r, int sign) {
    const T s = r > 0 ? std::sqrt(r) : std::numeric_limits<T>::min();
    return sign >= 0 ? s : -s;
  }
  T R2(T beta) const {
    T ub, v;
    joint_sines(beta, ub, v);
    return R2u(ub);
  }
  T p_of(T beta, int sp) const { return signed_sqrt(R2(beta), sp); }
  T R1(T beta, T p) const {
    T ub, v;
    joint_sines(beta, ub, v);
    return R1v(v, p);
  }
  // R1(alpha1) along the orbit branch sp (the join of the two base-rate branches where it is 0).
  T R1_on(T beta, int sp) const {
    T ub, v;
    joint_sines(beta, ub, v);
    return R1v(v, signed_sqrt(R2u(ub), sp));
  }

  struct eval_out {
    T G = std::numeric_limits<T>::quiet_NaN();
    T L2 = std::numeric_limits<T>::quiet_NaN();
    T p = 0, q = 0;
    segment_plan beam_plan, spatula_plan;
    bool unsupported = false;
  };

  // One segment's length: the direct form when it applies (one R_F), else the planned phase forms.
  template <bool E>
  static bool seg_len(const segment_constants<T, E>& g, T psi_s, T X3s, T psi_e, T X3e, const direct_trig<T>& trig,
                      T h, T& L, segment_plan& plan, bool& unsupported, const forward_problem* edge_of = nullptr) {
    if constexpr (E) {
      if (!(g.b4 < 1)) { unsupported = true; return false; }
    }
    // The direct form is exact on a path shorter than a quarter period, where U14 > 0; paths
    // sweeping more than pi/2 in theta go to the planner, which measures them (as the critical
    // solver does) before choosing a form.
    if (std::fabs(h) < seta_pi<T>() / 4 && direct_orientation_ok(g, h, X3s, X3e)) {
      T u14 = 0;
      plan = segment_plan();
      plan.direct = true;
      L = length_direct<Policy>(g, trig, X3s, X3e, &u14);
      if (u14 > 0 && L == L) {
        plan.libration = g.up < 1;
        return true;
      }
    }
    // The planner measures a phase plan's path as it chooses it: that length is the result (no
    // second pass through the same phase forms).
    T planned = std::numeric_limits<T>::quiet_NaN();
    // The spatula (edge_of given) ends at the contact edge, measured once per load.
    const libration_end<T>* end = edge_of ? edge_of->spatula_edge_end() : nullptr;
    plan = plan_segment<Policy>(g, psi_s, X3s, psi_e, X3e, T(0.75), &planned, end);
    if (plan.state == segment_state::unsupported) { unsupported = true; return false; }
    if (plan.state != segment_state::ok) return false;
    L = plan.direct ? segment_length<Policy>(g, plan, psi_s, X3s, psi_e, X3e) : planned;
    return L == L;
  }

  // G = L_beam - l1 (eq 15, second) at the joint angle beta, spatula rate sign sp, base rate sign
  // sq; with_spatula adds L2 = a - l1 (eq 15, first).
  bool eval(T beta, int sp, int sq, eval_out& o, bool with_beam, bool with_spatula) const {
    using std::cos; using std::sin;
    // One sincos(beta/2) gives every sine the two direct forms need (as make_seta_geometry of
    // gecko/seta/critical_residual.hpp does for the critical state), the spatula's constants
    // are the load's.
    return eval_half(beta, sin(beta / 2), cos(beta / 2), sp, sq, o, with_beam, with_spatula);
  }
  // As eval, with sb, cb = sin, cos(beta/2) from the caller.
  bool eval_half(T beta, T sb, T cb, int sp, int sq, eval_out& o, bool with_beam, bool with_spatula) const {
    T ub, v;
    joint_sines_half(sb, cb, ub, v);
    o.p = signed_sqrt(R2u(ub), sp);
    if (with_spatula) {
      const T r2 = seta_sqrt2<T>();
      const T sh2 = (cb - sb) / r2, ch2 = (cb + sb) / r2;
      const direct_trig<T> trig2{cphi, ub, sh2, ch2, ch2 * cphi - sh2 * sphi};
      const T X3s = o.p / seg_sqrt_f4(g2, ub);
      if (!seg_len(g2, beta - phi, X3s, psi_edge, X3_edge, trig2, (seta_pi<T>() / 2 - beta) / 2, o.L2,
                   o.spatula_plan, o.unsupported, this))
        return false;
    }
    return !with_beam || eval_beam(beta, sb, cb, v, sq, o);
  }
  // The beam part of eval_half: G at the joint state (beta, o.p) with v = sin(beta - alpha2 - phi)
  // (the scan's nodes have them already).
  bool eval_beam(T beta, T sb, T cb, T v, int sq, eval_out& o) const {
    const T r1 = R1v(v, o.p);
    // R1 = 0 (theta1'(0) = 0, where the two base-rate branches join) rounds either way.
    const T r1_tol = 64 * std::numeric_limits<T>::epsilon() * (ratio * o.p * o.p + 2 * N);
    if (!(r1 >= -r1_tol)) return false;
    o.q = signed_sqrt(r1, sq);
    T M1 = ratio * o.p * o.p + N * v;
    if constexpr (E1) M1 += d.c1 * N * N * v * v / 2;
    const auto g1 = make_segment<E1>(d.EI1, d.c1, M1, N);
    const T sh1 = sb * d.cA - cb * d.sA, ch1 = cb * d.cA + sb * d.sA;
    const T sm1 = sb * d.cB + cb * d.sB, cm1 = cb * d.cB - sb * d.sB;
    const direct_trig<T> trig1{v, u0, sh1, ch1, sm1 * cphi - cm1 * sphi};
    const T X3s = o.q / seg_sqrt_f4(g1, u0);
    const T X3e = sqrt_ratio * o.p / seg_sqrt_f4(g1, v);
    T L1 = 0;
    if (!seg_len(g1, d.alpha1 - phi, X3s, beta - d.alpha2 - phi, X3e, trig1, (beta - d.alpha2 - d.alpha1) / 2, L1,
                 o.beam_plan, o.unsupported))
      return false;
    o.G = L1 - d.l1;
    return true;
  }

  T G(T beta, int sp, int sq) const {
    eval_out o;
    if (!eval(beta, sp, sq, o, true, false)) return std::numeric_limits<T>::quiet_NaN();
    return o.G;
  }
  T L2(T beta, int sp, bool* unsupported = nullptr) const {
    return L2_half(beta, std::sin(beta / 2), std::cos(beta / 2), sp, unsupported);
  }
  // As L2, with sb, cb = sin, cos(beta/2) from the caller.
  T L2_half(T beta, T sb, T cb, int sp, bool* unsupported = nullptr) const {
    eval_out o;
    if (!eval_half(beta, sb, cb, sp, 1, o, false, true)) {
      if (unsupported && o.unsupported) *unsupported = true;
      return std::numeric_limits<T>::quiet_NaN();
    }
    return o.L2;
  }
};

// A monotone piece of the spatula orbit in beta: from beta_from (orbit distance t_from) to
// beta_to, with the joint rate sign sp.
template <class T>
struct orbit_piece {
  T beta_from, beta_to;
  int sp;
};

// Solves L2(beta, sp) = target for beta between lo and hi (L2 monotone there; f_lo: the sign of
// L2 - target at lo): Halley's method on the orbit, dt/dbeta = -sqrt(EI2/2)/p (eq 10) and its
// derivative from p^2 = R2(sin(beta - phi)) (eq 12), safeguarded by bisection. Cubic convergence
// from the Taylor guess saves one length per load over Newton's method. False when no beta there has |L2 - target| within rounding (the target lies
// outside the piece).
template <class FP, class T>
inline bool invert_spatula(const FP& fp, int sp, T lo, T hi, T f_lo, T target, T guess, T& beta) {
  using std::fabs; using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  T x = (guess > (lo < hi ? lo : hi) && guess < (lo < hi ? hi : lo)) ? guess : (lo + hi) / 2;
  const T scale = sqrt(fp.d.EI2 / 2);
  const T ftol = 64 * eps * (1 + target);
  for (int it = 0; it < 100; ++it) {
    // one sincos(x/2) for the length and for the Halley step's sines
    const T sb = std::sin(x / 2), cb = std::cos(x / 2);
    const T L = fp.L2_half(x, sb, cb, sp);
    if (!(L == L)) return false;
    const T f = L - target;
    if (fabs(f) <= eps * target) { beta = x; return true; }
    if ((f > 0) == (f_lo > 0)) lo = x; else hi = x;
    T ub, cu;
    fp.joint_sine_cos_half(sb, cb, ub, cu);
    const T p = fp.signed_sqrt(fp.R2u(ub), sp);
    T xn = (lo + hi) / 2;
    if (p != 0) {
      const T newton = f / (-scale / p);
      // f f'' / (2 f'^2) with f'' = sqrt(EI2/2) R2'(u) cos(beta - phi) / (2 p^3).
      const T dR2 = -fp.N - fp.d.c2 * fp.N * fp.N * ub;
      const T corr = 1 - f * dR2 * cu / (4 * scale * p);
      xn = x - (corr > T(0.5) && corr < T(2) ? newton / corr : newton);
    }
    const T tol = 4 * eps * (1 + fabs(x));
    if (fabs(xn - x) <= tol || fabs(hi - lo) <= tol) {
      // Converged in beta: a root when the residual is rounding (near a turning point t moves
      // by |dt/dbeta| ulp(beta), large there), not the end of a piece the target lies beyond.
      beta = x;
      return fabs(f) <= ftol || fabs(f) <= sqrt(eps) * (1 + target) * T(1e-3);
    }
    if (!((xn - lo) * (xn - hi) < 0)) xn = (lo + hi) / 2;
    x = xn;
  }
  beta = x;
  const T L = fp.L2(x, sp);
  return fabs(L - target) <= ftol;
}

// The pieces of the orbit with 0 <= t <= l2 (at most one period). Returns false with
// *unsupported set when the orbit leaves the forms or is shorter than l2 (see the header comment).
template <class FP, class T>
inline bool orbit_pieces(const FP& fp, orbit_piece<T> pieces[3], int& count, bool& unsupported) {
  using std::asin; using std::floor;
  const T pi = seta_pi<T>(), two_pi = 2 * pi, half_pi = pi / 2;
  const T l2 = fp.d.l2;
  const auto& g = fp.g2;
  count = 0;
  unsupported = false;
  if (!(g.N > 0)) return false;
  // Guess of the joint angle at t = l2: the Taylor series of theta2 back from the edge, where
  // theta2 = pi/2, theta2' = rate_edge, and eq (2) gives EI2 theta2'' = -Fn (1 + Ft/EA2) and,
  // differentiated once more, EI2 theta2''' = (Ft (1 + Ft/EA2) - Fn^2/EA2) theta2'.
  const T rate_edge = fp.p_of(half_pi, 1) * std::sqrt(2 / fp.d.EI2);
  const T c2 = fp.d.c2;
  const T dd = -fp.Fn * (1 + c2 * fp.Ft) / fp.d.EI2;
  const T ddd = (fp.Ft * (1 + c2 * fp.Ft) - c2 * fp.Fn * fp.Fn) / fp.d.EI2 * rate_edge;
  const T guess1 = half_pi - l2 * rate_edge + dd * l2 * l2 / 2 - ddd * l2 * l2 * l2 / 6;
  if (!(g.up < 1)) {
    // Rotation: theta2' > 0 along the whole orbit; beta decreases with t, less than a turn.
    const T lo = half_pi - two_pi;
    T beta = 0;
    if (invert_spatula(fp, 1, lo, half_pi, T(1), l2, guess1, beta)) {
      pieces[count++] = {half_pi, beta, 1};
      return true;
    }
    const T L_lo = fp.L2(lo + 64 * std::numeric_limits<T>::epsilon(), 1, &unsupported);
    if (L_lo == L_lo && L_lo <= l2) unsupported = true;  // l2 longer than a full turn
    return false;
  }
  // Past a turning point theta2 - theta_turn ~ |theta2''|/2 t^2 (eq 2): the first guess there.
  auto turn = [&](T beta) {
    const T u = std::sin(beta - fp.phi);
    return std::fabs(fp.N * std::cos(beta - fp.phi) * (1 + fp.d.c2 * fp.N * u)) / (2 * fp.d.EI2);
  };
  // Libration: psi in [-pi - a*, a*] (mod 2 pi) with a* = asin(u+), the window holding the edge.
  const T astar = asin(g.up);
  const T shift = floor((fp.psi_edge + pi + astar) / two_pi);
  const T beta_min = fp.phi - pi - astar + shift * two_pi;
  const T beta_max = fp.phi + astar + shift * two_pi;
  // Piece 1: theta2'(l1) > 0, beta from pi/2 down to the lower turning point. Most loads end
  // there (t = l2 before the turning point): when a lower bound of the piece's length says so,
  // invert without measuring the piece. The bound: t1 >= (pi/2 - beta_min) / max theta2', with
  // theta2'^2 = 2 R2(u)/EI2 largest at u = -1 (R2 concave, vertex at u = -1/(c2 N) when inside).
  {
    T R2max = g.M + fp.N - fp.d.c2 * fp.N * fp.N / 2;
    if (fp.d.c2 * fp.N > 1) R2max = g.M + 1 / (2 * fp.d.c2);
    const T t1_low = R2max > 0 ? (half_pi - beta_min) / std::sqrt(2 * R2max / fp.d.EI2) : T(0);
    T beta = 0;
    if (t1_low > l2 && invert_spatula(fp, 1, beta_min, half_pi, T(1), l2, guess1, beta)) {
      pieces[count++] = {half_pi, beta, 1};
      return true;
    }
  }
  const T t1 = fp.L2(beta_min, 1, &unsupported);
  if (unsupported) return false;
  if (!(t1 == t1)) return false;
  if (l2 <= t1) {
    T beta = 0;
    if (!invert_spatula(fp, 1, beta_min, half_pi, t1 - l2, l2, guess1, beta)) beta = beta_min;
    pieces[count++] = {half_pi, beta, 1};
    return true;
  }
  pieces[count++] = {half_pi, beta_min, 1};
  // Piece 2: theta2'(l1) < 0, beta from the lower to the upper turning point (half a period).
  const T t2 = fp.L2(beta_max, -1, &unsupported);
  if (unsupported || !(t2 == t2)) return false;
  if (l2 <= t2) {
    T beta = 0;
    if (!invert_spatula(fp, -1, beta_min, beta_max, t1 - l2, l2, beta_min + turn(beta_min) * (l2 - t1) * (l2 - t1), beta))
      return false;
    pieces[count++] = {beta_min, beta, -1};
    return true;
  }
  pieces[count++] = {beta_min, beta_max, -1};
  // Piece 3: theta2'(l1) > 0 again, beta from the upper turning point down to pi/2 (a period).
  const T t3 = fp.L2(half_pi + 64 * std::numeric_limits<T>::epsilon() * (1 + half_pi), 1, &unsupported);
  if (unsupported || !(t3 == t3)) return false;
  if (!(l2 < t3)) { unsupported = true; return false; }
  T beta = 0;
  if (!invert_spatula(fp, 1, beta_max, half_pi, t2 - l2, l2, beta_max - turn(beta_max) * (l2 - t2) * (l2 - t2), beta))
    return false;
  pieces[count++] = {beta_max, beta, 1};
  return true;
}

// Max |sin psi| over the interval [lo, hi] of psi = theta - phi.
template <class T>
inline T max_abs_sin(T lo, T hi) {
  using std::ceil; using std::fabs; using std::sin;
  const T pi = seta_pi<T>();
  if (hi - lo >= pi) return T(1);
  // a peak pi/2 + k pi inside?
  const T k = ceil((lo - pi / 2) / pi);
  if (pi / 2 + k * pi <= hi) return T(1);
  const T a = fabs(sin(lo)), b = fabs(sin(hi));
  return a > b ? a : b;
}

// The range of psi one segment sweeps (its ends and the turning points it passes), for the axial
// strain T/EA = N sin(psi)/EA (eq 1).
template <class T, bool E>
inline T segment_max_abs_sin(const segment_constants<T, E>& g, T psi_s, T X3s, T psi_e, T X3e, int turning_points) {
  using std::asin; using std::floor;
  const T pi = seta_pi<T>();
  T lo = psi_s < psi_e ? psi_s : psi_e, hi = psi_s < psi_e ? psi_e : psi_s;
  if (turning_points > 0 && g.up < 1) {
    const T astar = asin(g.up);
    const T shift = floor((psi_s + pi + astar) / (2 * pi)) * 2 * pi;
    const T top = astar + shift, bottom = -pi - astar + shift;
    const bool ss = X3s >= 0, se = X3e >= 0;
    if (turning_points >= 2 || (ss && !se)) hi = hi > top ? hi : top;
    if (turning_points >= 2 || (!ss && se)) lo = lo < bottom ? lo : bottom;
  }
  return max_abs_sin(lo, hi);
}

constexpr int max_contact_equilibria = 16;

// The forward solve at one load. Writes up to max_contact_equilibria equilibria into eq[] (their
// count into n_eq) and returns the summary status (see contact_status).
template <class Policy, bool E1, bool E2, class T>
inline contact_status contact_solve(const seta_params<T>& d, T Fn, T Ft, const contact_options<T>& opt,
                                    contact_result<T>* eq, int& n_eq) {
  using std::fabs; using std::sqrt;
  using FP = forward_problem<Policy, E1, E2, T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T half_pi = seta_pi<T>() / 2;
  n_eq = 0;
  const T L = d.l1 + d.l2;
  const T edge_tol = opt.edge_tolerance * L;
  auto base_result = [&]() {
    contact_result<T> r;
    r.Fn = Fn;
    r.Ft = Ft;
    return r;
  };
  if (!(Fn != 0 || Ft != 0)) {
    // No load (N = 0): pure bending at constant moment Meq = sqrt(2 EI2 w), eq (6).
    const T k2 = sqrt(2 * d.w / d.EI2), k1 = d.EI2 / d.EI1 * k2;
    const T beta = d.alpha1 + d.alpha2 + k1 * d.l1;
    const T t = (half_pi - beta) / k2;
    if (!(t > 0)) return contact_status::beyond_joint;
    if (t > d.l2 + edge_tol) return contact_status::no_contact;
    contact_result<T> r = base_result();
    r.a = d.l1 + (t < d.l2 ? t : d.l2);
    r.contact_length = L - r.a;
    r.theta_joint = beta;
    r.theta_rate_joint = k2;
    r.theta_rate_base = k1;
    r.turning_points = r.turning_points_beam = r.turning_points_spatula = 0;
    r.max_axial_strain = 0;
    r.min_stretch = 1;
    r.min_z = 0;  // theta rises monotonically from alpha1 to pi/2: z falls to the edge
    r.energy_release_rate = d.w;
    r.equilibria = 1;
    r.status = contact_status::converged;
    eq[n_eq++] = r;
    return contact_status::converged;
  }
  if constexpr (E2) {
    // |Ft| > (Ft)max: Griffith's condition (eq 3) cannot hold at any edge (Ft > (Ft)max is refused
    // by the caller's input check).
    if (Ft < -sqrt(2 * d.w / d.c2)) return contact_status::no_contact;
  }
  const FP fp(d, Fn, Ft);
  orbit_piece<T> pieces[3];
  int n_pieces = 0;
  bool unsupported = false;
  if (!orbit_pieces(fp, pieces, n_pieces, unsupported))
    return unsupported ? contact_status::unsupported_state : contact_status::not_converged;

  // ---- scan: nodes along the pieces, G on both base-rate branches (q > 0: index 0, q < 0: 1) ----
  const int n_scan = opt.scan_points < 3 ? 3 : (opt.scan_points > 64 ? 64 : opt.scan_points);
  constexpr int max_nodes = 3 * 64 + 3 * 2 * 64;
  struct node {
    T beta;
    int sp;      // joint rate sign on the interval from the previous node to this one
    T G[2];      // NaN: no state on this branch; +inf: known positive (not evaluated)
    bool join;   // a point where theta1'(0) = 0 (the two branches meet)
    T r1;        // R1(alpha1) = 1/2 EI1 theta1'(0)^2 there (< 0: no beam reaches this joint state)
  };
  node nodes[max_nodes];
  int nn = 0;
  const T inf = std::numeric_limits<T>::infinity();
  // sb, cb: sin and cos of x.beta / 2 (the scan's nodes pass them from a rotation, the others
  // compute them).
  auto fill_sc = [&](node& x, T sb, T cb) {
    typename FP::eval_out o;
    // The shorter beam path leaves alpha1 in the direction of the joint end (sign of h1); the
    // other is longer by twice the distance from alpha1 to a turning point, so G >= 0 there
    // whenever G >= 0 on the shorter one.
    T ub, vj;
    fp.joint_sines_half(sb, cb, ub, vj);
    const T p = FP::signed_sqrt(fp.R2u(ub), x.sp);
    const T r1 = fp.R1v(vj, p);
    x.r1 = r1;
    x.G[0] = x.G[1] = nan;
    if (!(r1 >= 0)) return;
    const int s_short = (x.beta - d.alpha2 - d.alpha1 >= 0) ? 1 : -1;
    const int i_short = s_short > 0 ? 0 : 1;
    o.p = p;  // the joint state is the node's: only the beam is measured
    if (fp.eval_beam(x.beta, sb, cb, vj, s_short, o)) x.G[i_short] = o.G;
    else if (o.unsupported) unsupported = true;
    if (x.G[i_short] == x.G[i_short]) {
      // The longer path adds twice the distance d from alpha1 to the turning point behind it;
      // d >= |psi_turn - psi(alpha1)| / max theta1', and theta1'^2 = 2 R1(u)/EI1 is largest at
      // u = -1 (R1 is concave in u with its vertex at u <= -1). So G_long > 0 needs no R_F when
      // G_short + 2 d_low > 0 (the common case).
      T d_low = 0;
      if (x.G[i_short] < 0) {
        using std::asin;
        T M1 = fp.ratio * p * p + fp.N * vj;
        if constexpr (E1) M1 += d.c1 * fp.N * fp.N * vj * vj / 2;
        const auto g1 = make_segment<E1>(d.EI1, d.c1, M1, fp.N);
        if (g1.up < 1) {
          const T astar = asin(g1.up), pi = seta_pi<T>();
          const T ps = d.alpha1 - fp.phi;
          const T shift = std::floor((ps + pi + astar) / (2 * pi)) * 2 * pi;
          const T dpsi = s_short > 0 ? ps - (-pi - astar + shift) : astar + shift - ps;
          T Rmax = M1 + fp.N;
          if constexpr (E1) Rmax = d.c1 * fp.N > 1 ? M1 + 1 / (2 * d.c1) : Rmax - d.c1 * fp.N * fp.N / 2;
          if (dpsi > 0 && Rmax > 0) d_low = dpsi / sqrt(2 * Rmax / d.EI1);
        }
      }
      if (x.G[i_short] + 2 * d_low > 0) {
        x.G[1 - i_short] = inf;  // known positive if it exists; evaluated when bracketed
        return;
      }
    }
    if (fp.eval_beam(x.beta, sb, cb, vj, -s_short, o)) x.G[1 - i_short] = o.G;
    else if (o.unsupported) unsupported = true;
  };
  auto fill = [&](node& x) { fill_sc(x, std::sin(x.beta / 2), std::cos(x.beta / 2)); };
  // At theta1(l1) = alpha1 (beta = alpha1 + alpha2) the beam's path with theta1'(0) of the joint
  // rate's sign shrinks to nothing on one side (G -> -l1) and jumps to a whole period on the other:
  // nodes on both sides of it keep the roots next to that jump bracketed.
  const T beta_jump = d.alpha1 + d.alpha2;
  const T jump_gap = T(1e-9) * (1 + fabs(beta_jump));
  for (int k = 0; k < n_pieces; ++k) {
    const auto& pc = pieces[k];
    // sin and cos of beta/2 along the piece's equally spaced nodes by rotation (within a few ulp
    // after the few steps, far below what a sign of G at a node depends on): three sincos per
    // piece (its start, the step, its end) instead of one per node.
    const T half_step = (pc.beta_to - pc.beta_from) / T(2 * (n_scan - 1));
    const T rs = std::sin(half_step), rc = std::cos(half_step);
    T sj = std::sin(pc.beta_from / 2), cj = std::cos(pc.beta_from / 2);
    for (int j = 0; j < n_scan; ++j) {
      if (j > 0) {
        const T s_next = sj * rc + cj * rs;
        cj = cj * rc - sj * rs;
        sj = s_next;
      }
      if (j == 0 && k > 0) continue;  // the previous piece's last node
      node x;
      x.beta = j == n_scan - 1 ? pc.beta_to : pc.beta_from + (pc.beta_to - pc.beta_from) * T(j) / T(n_scan - 1);
      x.sp = pc.sp;
      x.join = false;
      if (nn > 0 && (nodes[nn - 1].beta - beta_jump) * (x.beta - beta_jump) < 0) {
        const T dir = x.beta > nodes[nn - 1].beta ? T(1) : T(-1);
        for (const T side : {-dir, dir}) {
          node y = x;
          y.beta = beta_jump + side * jump_gap;
          fill(y);
          nodes[nn++] = y;
        }
      }
      // the piece's last node is its end exactly: there the sines are computed, not rotated
      if (j == n_scan - 1) fill(x);
      else fill_sc(x, sj, cj);
      nodes[nn++] = x;
    }
  }
  // A branch without a beam state beyond some beta (the beam's orbit turning from libration to
  // rotation, where its period diverges and G with it): bisect towards that boundary so that the
  // last defined stretch has a node (a few evaluations, only where it happens).
  {
    node more[max_nodes];
    int nm = 0;
    for (int i = 0; i < nn; ++i) {
      if (i > 0 && nm + 2 < max_nodes) {  // the interval belongs to node i's piece (its sp)
        for (int b = 0; b < 2; ++b) {
          const bool d0 = nodes[i - 1].G[b] == nodes[i - 1].G[b], d1 = nodes[i].G[b] == nodes[i].G[b];
          if (d0 == d1 || !(nodes[i - 1].r1 > 0) || !(nodes[i].r1 > 0)) continue;
          T lo = d0 ? nodes[i - 1].beta : nodes[i].beta, hi = d0 ? nodes[i].beta : nodes[i - 1].beta;
          node last;
          bool have = false;
          for (int it = 0; it < 6; ++it) {
            node y;
            y.beta = (lo + hi) / 2;
            y.sp = nodes[i].sp;
            y.join = false;
            fill(y);
            if (y.G[b] == y.G[b]) { lo = y.beta; last = y; have = true; }
            else hi = y.beta;
          }
          if (have) more[nm++] = last;  // between nodes i - 1 and i
          break;
        }
      }
      more[nm++] = nodes[i];
    }
    for (int i = 0; i < nm; ++i) nodes[i] = more[i];
    nn = nm;
  }
  // The actual value of a known-positive entry.
  auto resolve = [&](int i, int b) {
    node& x = nodes[i];
    if (x.G[b] == inf) {
      typename FP::eval_out o;
      x.G[b] = fp.eval(x.beta, x.sp, b == 0 ? 1 : -1, o, true, false) ? o.G : nan;
    }
    return x.G[b];
  };
  const T tolG = T(1e-8) * L;
  contact_root<T> roots[max_contact_equilibria * 2];
  int n_roots = 0;
  bool refine_failed = false;
  auto add_root = [&](T beta, int sp, int sq) {
    for (int i = 0; i < n_roots; ++i)
      if (roots[i].sp == sp && fabs(roots[i].beta - beta) <= T(1e-9) * (1 + fabs(beta))) return;
    if (n_roots < max_contact_equilibria * 2) roots[n_roots++] = {beta, sp, sq};
  };
  auto refine = [&](T b0, T g0, T b1, T g1, int sp, int b) {
    const int sq = b == 0 ? 1 : -1;
    auto f = [&](T beta) { return fp.G(beta, sp, sq); };
    T root = 0;
    if (!brent_root(f, b0, b1, g0, g1, root)) { refine_failed = true; return; }
    const T gr = f(root);
    if (!(fabs(gr) <= tolG)) return;  // a jump of the shortest-path convention, not a root
    add_root(root, sp, sq);
  };
  // Joins: where R1(alpha1) changes sign between nodes, theta1'(0) = 0 and the two base-rate
  // branches meet; a beam state exists only where R1 >= 0. R1(beta) on the orbit is a
  // trigonometric polynomial with |dR1/dbeta| <= K = (EI2/EI1)(N + N^2/(2 EA2)) + N + N^2/(2 EA1)
  // (eqs 4, 12), so an interval whose end values satisfy |R1_l| + |R1_r| > K h has no sign change
  // inside unless the ends differ in sign; otherwise it is bisected (R1 costs one sincos, no R_F).
  // Each sign change becomes a join node, and each defined stretch between two of them gets a
  // node of its own: no root next to a region without beam states is lost.
  {
    const T K = fp.ratio * (fp.N + d.c2 * fp.N * fp.N / 2) + fp.N + d.c1 * fp.N * fp.N / 2;
    node merged[max_nodes];
    int nm = 0;
    T changes[32];
    int nc = 0;
    auto R1_at = [&](T beta) { return fp.R1_on(beta, 1); };
    auto collect = [&](auto&& self, T b0, T r0, T b1, T r1v, int depth) -> void {
      if (nc >= 32 || !(r0 == r0) || !(r1v == r1v)) return;
      if ((r0 >= 0) != (r1v >= 0)) {
        T bj = 0;
        auto f = [&](T beta) { return R1_at(beta); };
        if (brent_root(f, b0, b1, r0, r1v, bj)) changes[nc++] = bj;
        return;
      }
      if (depth >= 12 || fabs(r0) + fabs(r1v) > K * fabs(b1 - b0)) return;
      const T bm = (b0 + b1) / 2, rm = R1_at(bm);
      self(self, b0, r0, bm, rm, depth + 1);
      self(self, bm, rm, b1, r1v, depth + 1);
    };
    auto join_node = [&](T bj, int sp) {
      node x;
      x.beta = bj;
      x.sp = sp;
      x.join = true;
      x.r1 = 0;
      typename FP::eval_out o;
      // At the join q = 0: one state, on both branches.
      const T g = fp.eval(bj, sp, 1, o, true, false) ? o.G : nan;
      x.G[0] = x.G[1] = g;
      return x;
    };
    for (int i = 0; i < nn; ++i) {
      if (i > 0 && nm + 8 < max_nodes) {
        nc = 0;
        collect(collect, nodes[i - 1].beta, nodes[i - 1].r1, nodes[i].beta, nodes[i].r1, 0);
        const int sp = nodes[i].sp;
        T prev_b = nodes[i - 1].beta;
        bool prev_def = nodes[i - 1].r1 >= 0;
        for (int k = 0; k < nc && nm + 3 < max_nodes; ++k) {
          if (k > 0 && prev_def) {  // a defined stretch between two joins: a node inside
            node x;
            x.beta = (prev_b + changes[k]) / 2;
            x.sp = sp;
            x.join = false;
            fill(x);
            merged[nm++] = x;
          }
          merged[nm++] = join_node(changes[k], sp);
          prev_b = changes[k];
          prev_def = !prev_def;
        }
      }
      merged[nm++] = nodes[i];
    }
    for (int i = 0; i < nm; ++i) nodes[i] = merged[i];
    nn = nm;
  }
  // Sign changes on each branch.
  for (int b = 0; b < 2; ++b) {
    for (int i = 0; i + 1 < nn; ++i) {
      T g0 = nodes[i].G[b], g1 = nodes[i + 1].G[b];
      if (!(g0 == g0) || !(g1 == g1)) continue;
      if (g0 == inf && g1 == inf) continue;
      if (g0 == inf || g1 == inf) {
        const T other = g0 == inf ? g1 : g0;
        if (!(other <= 0)) continue;
        g0 = resolve(i, b);
        g1 = resolve(i + 1, b);
        if (!(g0 == g0) || !(g1 == g1)) continue;
      }
      if (g0 == 0) add_root(nodes[i].beta, nodes[i + 1].sp, b == 0 ? 1 : -1);
      if ((g0 < 0 && g1 > 0) || (g0 > 0 && g1 < 0))
        refine(nodes[i].beta, g0, nodes[i + 1].beta, g1, nodes[i + 1].sp, b);
    }
    if (nn > 0 && nodes[nn - 1].G[b] == 0) add_root(nodes[nn - 1].beta, nodes[nn - 1].sp, b == 0 ? 1 : -1);
    // A local minimum of |G| between nodes may hide a pair of roots (a fold of the equilibria
    // in the load): minimise sign * G there (Brent's minimiser) and bracket both roots if it crosses.
    for (int i = 1; i + 1 < nn; ++i) {
      const T gl = nodes[i - 1].G[b], gm = nodes[i].G[b], gr = nodes[i + 1].G[b];
      if (!(gl == gl && gm == gm && gr == gr) || gl == inf || gm == inf || gr == inf) continue;
      if (nodes[i - 1].sp != nodes[i].sp || nodes[i].sp != nodes[i + 1].sp) continue;
      const T sg = gm > 0 ? T(1) : T(-1);
      if (!(sg * gl > sg * gm && sg * gr > sg * gm && sg * gl > 0 && sg * gr > 0)) continue;
      const int sp = nodes[i].sp, sq = b == 0 ? 1 : -1;
      auto h = [&](T beta) { return sg * fp.G(beta, sp, sq); };
      T best = nodes[i].beta, hbest = sg * gm;
      brent_min(h, nodes[i - 1].beta, nodes[i + 1].beta, best, hbest);
      if (hbest <= 0) {
        const T gb = sg * hbest;
        if (gb == 0) { add_root(best, sp, sq); continue; }
        refine(nodes[i - 1].beta, gl, best, gb, sp, b);
        refine(best, gb, nodes[i + 1].beta, gr, sp, b);
      }
    }
  }
  // The critical state itself: G ~ 0 at t = l2 (within the edge tolerance) is a root there.
  const node& last = nodes[nn - 1];
  for (int b = 0; b < 2; ++b)
    if (last.G[b] == last.G[b] && last.G[b] != inf && fabs(last.G[b]) <= edge_tol)
      add_root(last.beta, last.sp, b == 0 ? 1 : -1);

  // ---- the equilibria ------------------------------------------------------------------------
  const T rate2 = sqrt(2 / d.EI2), rate1 = sqrt(2 / d.EI1);
  for (int i = 0; i < n_roots && n_eq < max_contact_equilibria; ++i) {
    const auto& rt = roots[i];
    typename FP::eval_out o;
    if (!fp.eval(rt.beta, rt.sp, rt.sq, o, true, true)) {
      if (o.unsupported) unsupported = true;
      else refine_failed = true;
      continue;
    }
    // The root found at the end node is the state at t = l2 by construction.
    const bool at_end = rt.beta == last.beta && rt.sp == last.sp;
    const T t = at_end ? d.l2 : o.L2;
    if (!(t > 0) || !(t <= d.l2 + edge_tol)) continue;  // contact on the beam / not on this spatula
    contact_result<T> r = base_result();
    r.a = d.l1 + (t < d.l2 ? t : d.l2);
    r.contact_length = L - r.a;
    r.theta_joint = rt.beta;
    r.theta_rate_joint = o.p * rate2;
    r.theta_rate_base = o.q * rate1;
    const auto g = make_seta_geometry<E1, E2>(d, Fn, rt.beta, o.p, o.q, Ft, fp.edge, false);
    const T ps1 = d.alpha1 - fp.phi, pe1 = rt.beta - d.alpha2 - fp.phi, ps2 = rt.beta - fp.phi;
    r.turning_points_beam = segment_turning_points<Policy>(g.beam, o.beam_plan, ps1, g.X3_s1, pe1, g.X3_e1, g.h1);
    r.turning_points_spatula =
        segment_turning_points<Policy>(g.spatula, o.spatula_plan, ps2, g.X3_s2, fp.psi_edge, g.X3_e2, g.h2);
    r.turning_points = r.turning_points_beam + r.turning_points_spatula;
    T strain = 0;
    if constexpr (E1)
      strain = d.c1 * fp.N * segment_max_abs_sin(g.beam, ps1, g.X3_s1, pe1, g.X3_e1, r.turning_points_beam);
    if constexpr (E2) {
      const T s2 = d.c2 * fp.N * segment_max_abs_sin(g.spatula, ps2, g.X3_s2, fp.psi_edge, g.X3_e2,
                                                     r.turning_points_spatula);
      if (s2 > strain) strain = s2;
    }
    r.max_axial_strain = strain;
    // Eq (3), left side: 1/2 EI2 theta2'(a)^2 = R2(pi/2) (eq 12), T(pi/2) = N cos(phi) = Ft.
    r.energy_release_rate = fp.R2(half_pi) + d.c2 * Ft * Ft / 2;
    // Admissibility (gecko/seta/admissibility.hpp): the seta must stay on its side of the
    // substrate before the edge, with a positive stretch (and within the caller's strain limit);
    // else status 7, with the state's values kept for drawing.
    seta_pose<T> pose{Fn, Ft, r.theta_joint, r.theta_rate_base, r.theta_rate_joint, r.turning_points_beam,
                      r.turning_points_spatula, r.a - d.l1};
    const auto adm = admissibility_imp(d, pose, opt.strain_limit);
    r.min_z = adm.min_z;
    if (adm.max_axial_strain == adm.max_axial_strain) r.max_axial_strain = adm.max_axial_strain;
    r.min_stretch = adm.min_stretch;
    r.status = adm.admissible ? contact_status::converged : contact_status::inadmissible;
    eq[n_eq++] = r;
  }
  int n_adm = 0, first_adm = -1;
  for (int i = 0; i < n_eq; ++i) {
    eq[i].equilibria = n_eq;
    if (eq[i].status == contact_status::converged && n_adm++ == 0) first_adm = i;
  }
  if (n_adm == 1) {  // the one admissible equilibrium first
    const contact_result<T> keep = eq[first_adm];
    for (int i = first_adm; i > 0; --i) eq[i] = eq[i - 1];
    eq[0] = keep;
    return contact_status::converged;
  }
  if (n_adm > 1) return contact_status::several_equilibria;
  if (n_eq > 0) return contact_status::inadmissible;
  if (unsupported) return contact_status::unsupported_state;
  if (refine_failed) return contact_status::not_converged;
  // No equilibrium on the spatula: why (header comment). G at the ends (t = 0: the edge at the
  // joint; t = l2: the edge at the spatula tip) extrapolated linearly to its root says where the
  // equilibrium went when that root is near (within l2 of an end): beyond the tip (no contact)
  // or beyond the joint (contact on the beam); this follows the equilibria of nearby loads
  // continuously across both boundary lines. With no root near, the sign of G decides: the beam
  // falls short for every contact length (G > 0: no contact) or is too long for all of them
  // (G < 0: the edge is pushed onto the beam). No beam state anywhere on the orbit
  // (R1(alpha1) < 0: a pull the beam cannot carry into contact) is no contact.
  auto end_value = [&](int i) {
    T m = nan;
    for (int b = 0; b < 2; ++b) {
      const T v = nodes[i].G[b];
      if (v == v && v != inf && !(fabs(m) <= fabs(v))) m = v;
    }
    return m;
  };
  const T g0 = end_value(0), g1 = end_value(nn - 1);
  if (g0 == g0 && g1 == g1) {
    if (g0 != g1) {
      const T tstar = -g0 / (g1 - g0);  // in units of l2
      if (tstar > 1 && tstar <= 2) return contact_status::no_contact;
      if (tstar < 0 && tstar >= -1) return contact_status::beyond_joint;
    }
    return g1 > 0 ? contact_status::no_contact : contact_status::beyond_joint;
  }
  if (g0 == g0) return g0 > 0 ? contact_status::no_contact : contact_status::beyond_joint;
  if (g1 == g1) return g1 > 0 ? contact_status::no_contact : contact_status::beyond_joint;
  return contact_status::no_contact;
}

template <class T>
inline bool check_load(T Fn, T Ft) {
  return std::isfinite(Fn) && std::isfinite(Ft);
}

}  // namespace detail

// The forward solver for one design: checks the design once, then solves any number of loads.
//   contact_solver<double> solve(seta);
//   auto r = solve(Fn, Ft);                        // contact_result (status, a, ...)
//   auto all = solve.equilibria(Fn, Ft);           // every equilibrium with l1 < a <= l1 + l2
// Bad input (NaN or infinite loads, Ft > (Ft)max) raises std::domain_error under the default
// policy, or gives status invalid_input under nan_policy.
template <class T = double, class Policy = policies::default_policy>
class contact_solver {
 public:
  explicit contact_solver(const TwoLevelSeta<T>& seta, const contact_options<T>& options = contact_options<T>())
      : seta_(seta), opt_(options) {
    valid_ = detail::check_seta<T, Policy>(seta, "gecko::contact_state");
    d_ = detail::make_seta_params(seta);
    e1_ = detail::is_extensible(seta.EA1);
    e2_ = detail::is_extensible(seta.EA2);
    ftmax_ = ft_max(seta);
  }

  contact_result<T> operator()(T Fn, T Ft) const {
    contact_result<T> eq[detail::max_contact_equilibria];
    int n = 0;
    const contact_status st = solve(Fn, Ft, eq, n);
    if (st == contact_status::converged || st == contact_status::inadmissible) {
      eq[0].status = st;
      return eq[0];
    }
    contact_result<T> r;
    r.Fn = Fn;
    r.Ft = Ft;
    r.status = st;
    r.equilibria = n;
    return r;
  }

  struct all_result {
    contact_status status;             // as operator() would report
    std::vector<contact_result<T>> states;  // every equilibrium found (each with its own status)
  };
  all_result equilibria(T Fn, T Ft) const {
    contact_result<T> eq[detail::max_contact_equilibria];
    int n = 0;
    all_result r;
    r.status = solve(Fn, Ft, eq, n);
    r.states.assign(eq, eq + n);
    return r;
  }

 private:
  contact_status solve(T Fn, T Ft, contact_result<T>* eq, int& n) const {
    constexpr const char* fn = "gecko::contact_state";
    n = 0;
    if (!valid_) return contact_status::invalid_input;
    if (!(Fn == Fn) || !std::isfinite(Fn)) {
      raise_domain_error<T, Policy>(fn, "Fn", Fn, "a finite normal force");
      return contact_status::invalid_input;
    }
    if (!detail::check_ft<T, Policy>(Ft, ftmax_, fn)) return contact_status::invalid_input;
    return detail::visit_extensibility(e1_, e2_, [&](auto E1, auto E2) {
      return detail::contact_solve<Policy, decltype(E1)::value, decltype(E2)::value>(d_, Fn, Ft, opt_, eq, n);
    });
  }

  TwoLevelSeta<T> seta_;
  contact_options<T> opt_;
  detail::seta_params<T> d_;
  bool valid_ = false, e1_ = false, e2_ = false;
  T ftmax_;
};

// The contact state at the load (Fn, Ft): one equilibrium (status 0) or the reason there is none
// (or several: status several_equilibria with their count in `equilibria`).
template <class T, class Policy = policies::default_policy>
inline contact_result<T> contact_state(const TwoLevelSeta<T>& seta, T Fn, T Ft,
                                       const contact_options<T>& options = contact_options<T>(),
                                       const Policy& = Policy()) {
  return contact_solver<T, Policy>(seta, options)(Fn, Ft);
}

// Every equilibrium at the load with l1 < a <= l1 + l2, and the status contact_state reports.
template <class T, class Policy = policies::default_policy>
inline typename contact_solver<T, Policy>::all_result contact_equilibria(
    const TwoLevelSeta<T>& seta, T Fn, T Ft, const contact_options<T>& options = contact_options<T>(),
    const Policy& = Policy()) {
  return contact_solver<T, Policy>(seta, options).equilibria(Fn, Ft);
}

}  // namespace gecko
