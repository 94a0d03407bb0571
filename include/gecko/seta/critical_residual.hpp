// gecko/seta/critical_residual.hpp — the equations of the critical state of the two-level seta.
//
// docs/theory/two_level_seta.md ("First integrals", "Lengths", "Critical line of adhesion"; paper eqs 8-15): at
// the critical state the non-contact length is a = l1 + l2, and for a given Ft the two length
// equations fix (Fn, beta = theta2(l1)). A monotone-only formulation in (Fn, beta) has square-root
// branch points wherever theta' vanishes at a segment end (a turning point entering or leaving a
// segment), so Newton cannot cross them. The unknowns here are therefore
//     z = (Fn, beta, p, q),   p = sqrt(EI2/2) theta2'(l1),   q = sqrt(EI1/2) theta1'(0),
// the signed end rates, with the two first-integral identities as extra equations:
//     F1 = L_spatula(Fn, beta, p) - l2
//     F2 = L_beam(Fn, beta, p, q) - l1
//     F3 = p^2 - R2(beta)                            (1/2 EI2 theta2'(l1)^2 = R2)
//     F4 = q^2 - R1(alpha1)                          (1/2 EI1 theta1'(0)^2 = R1)
// with M2 = Ft + w (contact edge), M1 = (EI2/EI1) p^2 + N v + N^2 v^2/(2 EA1), v = sin(beta - alpha2
// - phi) (joint: theta1'(l1) = (EI2/EI1) theta2'(l1)), and theta2'(a) > 0 at the contact edge
// (the spatula approaches the substrate from outside). Every term is analytic in z through
// theta' = 0, so the system is smooth across turning-point changes (gecko/seta/elastica_segment.hpp).
// Written once for any scalar: plain T for values, detail::dual for exact Jacobians.
#pragma once

#include <cmath>
#include <limits>

#include "gecko/core/policy.hpp"
#include "gecko/seta/detail/dual.hpp"
#include "gecko/seta/elastica_segment.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {
namespace detail {

// The design with 1/EA in place of EA (0 for infinity), in any scalar D (a dual for
// sensitivities), and the sines and cosines of its angles (computed once, not per evaluation).
template <class D>
struct seta_params {
  D EI1, EI2, c1, c2, l1, l2, alpha1, alpha2, w;
  D s1, co1;  // sin, cos alpha1
  D s2, co2;  // sin, cos alpha2
  D sA, cA;   // sin, cos (alpha1 + alpha2)/2
  D sB, cB;   // sin, cos (alpha1 - alpha2)/2
};

template <class D>
inline void set_seta_angles(seta_params<D>& d) {
  using std::cos; using std::sin;
  using T = scalar_of_t<D>;
  d.s1 = sin(d.alpha1);
  d.co1 = cos(d.alpha1);
  d.s2 = sin(d.alpha2);
  d.co2 = cos(d.alpha2);
  const D A = (d.alpha1 + d.alpha2) * T(0.5), B = (d.alpha1 - d.alpha2) * T(0.5);
  d.sA = sin(A);
  d.cA = cos(A);
  d.sB = sin(B);
  d.cB = cos(B);
}

template <class T>
inline seta_params<T> make_seta_params(const TwoLevelSeta<T>& s) {
  using std::isinf;
  seta_params<T> d;
  d.EI1 = s.EI1;
  d.EI2 = s.EI2;
  d.c1 = isinf(s.EA1) ? T(0) : T(1) / s.EA1;
  d.c2 = isinf(s.EA2) ? T(0) : T(1) / s.EA2;
  d.l1 = s.l1;
  d.l2 = s.l2;
  d.alpha1 = s.alpha1;
  d.alpha2 = s.alpha2;
  d.w = s.w;
  set_seta_angles(d);
  return d;
}

// Segment ends and constants of both segments at a state: everything but the R_F's.
template <bool E1, bool E2, class S>
struct seta_geometry {
  segment_constants<S, E1> beam;
  segment_constants<S, E2> spatula;
  S X3_s1, X3_e1;                  // beam: base (s = 0) -> joint (s = l1)
  S X3_s2, X3_e2;                  // spatula: joint -> contact edge (s = a)
  direct_trig<S> trig1, trig2;     // the direct forms' trigonometry
  S psi_s1, psi_e1, psi_s2, psi_e2;  // psi = theta - phi at the ends (only with angles = true)
  scalar_of_t<S> h1, h2;           // (theta_end - theta_start)/2 of each segment
  S F3, F4;                        // first-integral identities at the joint and the base
};

// edge = cos(tau/(Ft)max) for an extensible spatula, where Ft = (Ft)max sin(tau/(Ft)max): the
// contact-edge rate theta2'(a) = sqrt(2 (w - Ft^2/(2 EA2))/EI2) is then analytic in tau through the
// end of the line at Ft = (Ft)max (it vanishes there like sqrt((Ft)max - Ft) in Ft). For EA2 =
// infinity, edge = 1 and tau = Ft.
// All sines of psi = theta - phi come from one sincos(beta/2) by angle addition, with
// cos phi = Ft/N and sin phi = Fn/N (no atan2 on the hot path); angles = true adds the psi
// themselves, which only the phase forms need.
template <bool E1, bool E2, class S, class D>
inline seta_geometry<E1, E2, S> make_seta_geometry(const seta_params<D>& d, const S& Fn, const S& beta,
                                                   const S& p, const S& q, const S& Ft, const S& edge,
                                                   bool angles) {
  using std::atan2; using std::cos; using std::sin; using std::sqrt;
  using T = scalar_of_t<S>;
  seta_geometry<E1, E2, S> g;
  const T r2 = seta_sqrt2<T>();
  const S N = sqrt(Fn * Fn + Ft * Ft);
  const S cphi = Ft / N, sphi = Fn / N;
  const S half = beta * T(0.5);
  const S sb = sin(half), cb = cos(half);
  const S sinb = T(2) * sb * cb, cosb = (cb - sb) * (cb + sb);
  // Spatula: theta from beta to pi/2; h2 = pi/4 - beta/2, mean pi/4 + beta/2.
  const S ub = sinb * cphi - cosb * sphi;  // sin(beta - phi)
  const S sh2 = (cb - sb) / r2, ch2 = (cb + sb) / r2;
  g.trig2 = {cphi, ub, sh2, ch2, ch2 * cphi - sh2 * sphi};
  // Beam: theta from alpha1 to beta - alpha2; h1 = beta/2 - A, mean beta/2 + B.
  const S sj = sinb * d.co2 - cosb * d.s2, cj = cosb * d.co2 + sinb * d.s2;  // beta - alpha2
  const S v = sj * cphi - cj * sphi;                                         // sin(beta - alpha2 - phi)
  const S u0 = d.s1 * cphi - d.co1 * sphi;                                   // sin(alpha1 - phi)
  const S sh1 = sb * d.cA - cb * d.sA, ch1 = cb * d.cA + sb * d.sA;
  const S sm1 = sb * d.cB + cb * d.sB, cm1 = cb * d.cB - sb * d.sB;
  g.trig1 = {v, u0, sh1, ch1, sm1 * cphi - cm1 * sphi};
  g.h2 = (seta_pi<T>() / 2 - value_of(beta)) / 2;
  g.h1 = (value_of(beta) - value_of(d.alpha2) - value_of(d.alpha1)) / 2;
  // Spatula: M2 = Ft + w, paper 001 eq (9); R2 = 1/2 EI2 theta2'^2 at the joint, paper 001 eq (8).
  const S M2 = Ft + d.w;
  S R2 = M2 - N * ub;
  if constexpr (E2) R2 = R2 - d.c2 * N * N * ub * ub * T(0.5);
  g.spatula = make_segment<E2>(S(d.EI2), S(d.c2), M2, N);
  g.X3_s2 = p / seg_sqrt_f4(g.spatula, ub);
  // f3 at the contact edge: (w - c Ft^2/2) / f4 = w edge^2 / f4(Ft/N), no cancellation
  // (Griffith's condition there, paper 001 eq (3)).
  if constexpr (E2) g.X3_e2 = sqrt(S(d.w)) * edge / seg_sqrt_f4(g.spatula, cphi);
  else g.X3_e2 = sqrt(S(d.w)) * edge;
  // Beam: M1 from the joint conditions, paper 001 eq (12) (joint moment balance, eq (4)).
  const S ratio = S(d.EI2 / d.EI1);
  S M1 = ratio * p * p + N * v;
  if constexpr (E1) M1 = M1 + d.c1 * N * N * v * v * T(0.5);
  g.beam = make_segment<E1>(S(d.EI1), S(d.c1), M1, N);
  S R1 = M1 - N * u0;  // R1 at the base, paper 001 eq (8)
  if constexpr (E1) R1 = R1 - d.c1 * N * N * u0 * u0 * T(0.5);
  g.X3_s1 = q / seg_sqrt_f4(g.beam, u0);
  g.X3_e1 = sqrt(ratio) * p / seg_sqrt_f4(g.beam, v);
  // First integrals, paper 001 eq (8): p^2 = R2(u_beta), q^2 = R1(u0).
  g.F3 = p * p - R2;
  g.F4 = q * q - R1;
  if (angles) {
    const S phi = atan2(Fn, Ft);
    g.psi_s2 = beta - phi;
    g.psi_e2 = T(seta_pi<T>() / 2) - phi;
    g.psi_s1 = d.alpha1 - phi;
    g.psi_e1 = beta - d.alpha2 - phi;
  } else {
    g.psi_s1 = g.psi_e1 = g.psi_s2 = g.psi_e2 = S(T(0));
  }
  return g;
}

struct seta_plan {
  segment_plan beam, spatula;
};

inline bool operator==(const seta_plan& a, const seta_plan& b) {
  return a.beam == b.beam && a.spatula == b.spatula;
}

// The residual (F1..F4) under a plan; u14[0], u14[1]: the direct forms' U14 (beam, spatula).
template <class Policy, bool E1, bool E2, class S, class D>
inline void seta_residual(const seta_params<D>& d, const S& Fn, const S& beta, const S& p, const S& q,
                          const S& Ft, const S& edge, const seta_plan& plan, S F[4],
                          scalar_of_t<S>* u14 = nullptr) {
  const bool angles = !plan.beam.direct || !plan.spatula.direct;
  const auto g = make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, angles);
  scalar_of_t<S> u[2] = {1, 1};
  // The two length equations, paper 001 eq (15) (eq (10) the spatula's, eq (13) the beam's).
  F[0] = segment_length<Policy>(g.spatula, plan.spatula, g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, &u[1], &g.trig2) - d.l2;
  F[1] = segment_length<Policy>(g.beam, plan.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, &u[0], &g.trig1) - d.l1;
  F[2] = g.F3;
  F[3] = g.F4;
  if (u14) {
    u14[0] = u[0];
    u14[1] = u[1];
  }
}

// solved: the state solves the equations (a node of a followed line), so the segments' lengths
// are l1 and l2 there, which fixes each libration's period count (plan_segment's target).
template <class Policy, bool E1, bool E2, class T>
inline seta_plan plan_seta(const seta_params<T>& d, T Fn, T beta, T p, T q, T Ft, T edge, bool solved = false) {
  const auto g = make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, true);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  T* const no_length = nullptr;
  const libration_end<T>* const no_end = nullptr;
  return {plan_segment<Policy>(g.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, T(0.75), no_length, no_end,
                               solved ? d.l1 : nan),
          plan_segment<Policy>(g.spatula, g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, T(0.75), no_length, no_end,
                               solved ? d.l2 : nan)};
}

// The plan check and the turning-point count on a state's geometry (the public forms below build
// it; a state read off the line needs both and builds it once).
template <bool E1, bool E2, class S>
inline bool geometry_plan_valid(const seta_geometry<E1, E2, S>& g, const seta_plan& plan, const S u14[2]) {
  return segment_plan_valid(g.beam, plan.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, u14[0], g.h1) &&
         segment_plan_valid(g.spatula, plan.spatula, g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, u14[1], g.h2);
}
template <class Policy, bool E1, bool E2, class S>
inline void geometry_turning_points(const seta_geometry<E1, E2, S>& g, const seta_plan& plan, int& beam,
                                    int& spatula) {
  beam = segment_turning_points<Policy>(g.beam, plan.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, g.h1);
  spatula = segment_turning_points<Policy>(g.spatula, plan.spatula, g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, g.h2);
}

template <bool E1, bool E2, class T>
inline bool seta_plan_valid(const seta_params<T>& d, const seta_plan& plan, T Fn, T beta, T p, T q, T Ft,
                            T edge, const T u14[2]) {
  const bool angles = !plan.beam.direct || !plan.spatula.direct;
  return geometry_plan_valid(make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, angles), plan, u14);
}

// seta_plan_valid and, where the plan is valid, seta_turning_points on one geometry (a state read
// off the line needs both at the same point).
template <class Policy, bool E1, bool E2, class T>
inline bool seta_plan_valid_turning_points(const seta_params<T>& d, const seta_plan& plan, T Fn, T beta, T p, T q,
                                           T Ft, T edge, const T u14[2], int& beam, int& spatula) {
  // The angles whenever either needs them: the plan check for a phase plan, the count for one
  // with added periods (a subset).
  const bool angles = !plan.beam.direct || !plan.spatula.direct;
  const auto g = make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, angles);
  if (!geometry_plan_valid(g, plan, u14)) return false;
  geometry_turning_points<Policy>(g, plan, beam, spatula);
  return true;
}

template <class Policy, bool E1, bool E2, class T>
inline void seta_turning_points(const seta_params<T>& d, const seta_plan& plan, T Fn, T beta, T p, T q, T Ft,
                                T edge, int& beam, int& spatula) {
  const bool angles = plan.beam.periods != 0 || plan.spatula.periods != 0;  // see segment_turning_points
  geometry_turning_points<Policy>(make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, angles), plan, beam,
                                  spatula);
}

}  // namespace detail
}  // namespace gecko
