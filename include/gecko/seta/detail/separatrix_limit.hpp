// gecko/seta/detail/separatrix_limit.hpp — critical states past a followed line's stall, where a
// segment lies on its separatrix to double precision.
//
// docs/theory/two_level_seta.md, "Long segments". A tensioned segment many elastic lengths
// l / tau long (tau = sqrt(EI / (N (1 + c N))), the time constant of its saddle) is straight and
// aligned with the force except in boundary layers at its ends; its first integral (paper 001
// eq (8)) passes the saddle u = sin(theta - phi) = 1 at the distance
//     delta = R(1) = M - N - c N^2/2,
// which shrinks like exp(-l / tau). The length equation of such a segment (eq (10) for the
// spatula, eq (13) for the beam) is logarithmic in delta and, with delta formed from the state by
// cancellation, cannot be solved beyond about 30 elastic lengths: the followed line stalls there
// (validation/README.md, "Where the followed line gives up"). Its limit is not singular, though:
// replacing that equation by delta = 0 gives a smooth system in the same unknowns (Fn, beta, p, q)
// whose solution differs from the exact state by O(delta). For the spatula, whose M2 = Ft + w is
// fixed, delta2 = 0 fixes N (inextensible: N = Ft + w, Fn^2 = w (2 Ft + w)); for the beam it fixes
// M1, i.e. the joint rate p through eq (12).
//
// A state of the limit system is corrected to the exact one: near the saddle the segment's length
// obeys L(delta) = L(delta_b) + slope log(delta_b / delta) to O(delta log delta), the slope a whole
// number of passages times the saddle's time constant; the exact Carlson forms
// (gecko/seta/elastica_segment.hpp) measure the segment, from the same ends with the same rate
// signs, at two distances they resolve, L(delta) = l gives the exact state's delta, and the limit
// state moves by the limit system's Jacobian times it. Accepted only where the segment is already
// shorter than l at delta_b, exactly one side of the separatrix fits the ends, the slope is a
// whole number of passages, the turning points are within one of the followed line's (see
// separatrix_state_exact), the correction's uncertainty is below a quarter of the tolerance, and
// a segment left to its own length equation resolves its separatrix distance
// (measured_segments_resolved). Failing that, smaller limit systems and last the full system are
// solved from the law's estimate, under measured_segments_resolved (separatrix_target_state).
// Elsewhere the state stays not reached.
// Used past a followed line's stall (detail/separatrix_extend.hpp, the march in Ft) and past a
// natural-state homotopy's stall (detail/natural_state.hpp, the march in lambda).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "gecko/seta/critical_line_types.hpp"
#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/detail/dual.hpp"
#include "gecko/seta/detail/newton.hpp"
#include "gecko/seta/detail/separatrix_scales.hpp"
#include "gecko/seta/detail/seta_system.hpp"
#include "gecko/seta/solve_critical.hpp"

namespace gecko {
namespace detail {

// Which segments the limit system takes on their separatrix.
constexpr int limit_beam = 1, limit_spatula = 2;

// R(1) = M - N - c N^2/2 of a segment: its signed distance from the separatrix (> 0: rotation).
template <bool E, class S>
inline S separatrix_gap(const segment_constants<S, E>& g) {
  using T = scalar_of_t<S>;
  if constexpr (E) return g.M - g.N - g.c * g.N * g.N * T(0.5);
  else return g.M - g.N;
}

// The critical-state equations with the length equation of each segment in `mask` replaced by
// its separatrix condition delta = 0 (scaled to a length: l delta / (|M| + N)). A System for
// newton_fixed_ft and for the arclength corrector; the plans of the limit segments are ignored.
template <class T, class Policy, bool E1, bool E2>
struct separatrix_system {
  using base_type = seta_system<T, Policy, E1, E2>;
  static constexpr int n = 4;
  using value_type = T;
  using vec = typename base_type::vec;
  using mat = typename base_type::mat;
  using plan_type = seta_plan;

  const base_type& base;
  int mask;

  template <class S>
  void residual_of(const S& Fn, const S& beta, const S& p, const S& q, const S& Ft, const S& edge,
                   const seta_plan& plan, S F[4], T u14[2]) const {
    using std::fabs;
    const auto& d = base.d;
    const bool beam_long = (mask & limit_beam) != 0, spatula_long = (mask & limit_spatula) != 0;
    const bool angles = (!beam_long && !plan.beam.direct) || (!spatula_long && !plan.spatula.direct);
    const auto g = make_seta_geometry<E1, E2>(d, Fn, beta, p, q, Ft, edge, angles);
    u14[0] = u14[1] = 1;
    if (spatula_long)
      F[0] = separatrix_gap(g.spatula) *
             (value_of(d.l2) / (fabs(value_of(g.spatula.M)) + value_of(g.spatula.N)));
    else
      F[0] = segment_length<Policy>(g.spatula, plan.spatula, g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, &u14[1],
                                    &g.trig2) - d.l2;
    if (beam_long)
      F[1] = separatrix_gap(g.beam) * (value_of(d.l1) / (fabs(value_of(g.beam.M)) + value_of(g.beam.N)));
    else
      F[1] = segment_length<Policy>(g.beam, plan.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, &u14[0],
                                    &g.trig1) - d.l1;
    F[2] = g.F3;
    F[3] = g.F4;
  }

  // F, dF/dz and (if dF_dmu) dF/dmu at (z, mu): the derivative in mu for the march in arclength
  // (detail/separatrix_arclength.hpp).
  bool eval(const vec& z, T mu, const plan_type& plan, vec& F, mat& J, vec* dF_dmu, T u14[2]) const {
    if (dF_dmu) {
      using S = dual<T, 5>;
      S r[4], Ft, edge;
      base.forces(S::variable(mu, 4), Ft, edge);
      residual_of<S>(S::variable(z[0], 0), S::variable(z[1], 1), S::variable(z[2], 2), S::variable(z[3], 3), Ft,
                     edge, plan, r, u14);
      for (int i = 0; i < 4; ++i) {
        F[i] = r[i].v;
        for (int j = 0; j < 4; ++j) J(i, j) = r[i].d[j];
        (*dF_dmu)[i] = r[i].d[4];
      }
      return F.allFinite() && J.allFinite() && dF_dmu->allFinite();
    }
    using S = dual<T, 4>;
    S r[4];
    T Ft, edge;
    base.forces(mu, Ft, edge);
    residual_of<S>(S::variable(z[0], 0), S::variable(z[1], 1), S::variable(z[2], 2), S::variable(z[3], 3), S(Ft),
                   S(edge), plan, r, u14);
    for (int i = 0; i < 4; ++i) {
      F[i] = r[i].v;
      for (int j = 0; j < 4; ++j) J(i, j) = r[i].d[j];
    }
    return F.allFinite() && J.allFinite();
  }

  T step_norm(const vec& dz, const vec& z) const { return base.step_norm(dz, z); }

  // The base plan with the limit segments' plans blanked (their length is not measured).
  plan_type plan(const vec& z, T mu) const {
    auto p = plan_at_solution(base, z, mu);
    if (mask & limit_beam) p.beam = segment_plan();
    if (mask & limit_spatula) p.spatula = segment_plan();
    return p;
  }

  bool plan_valid(const plan_type& p, const vec& z, T mu, const T u14[2]) const {
    T Ft, edge;
    base.forces(mu, Ft, edge);
    const bool angles = !p.beam.direct || !p.spatula.direct;
    const auto g = make_seta_geometry<E1, E2>(base.d, z[0], z[1], z[2], z[3], Ft, edge, angles);
    const bool beam_ok = (mask & limit_beam) ||
                         segment_plan_valid(g.beam, p.beam, g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, u14[0], g.h1);
    const bool spatula_ok = (mask & limit_spatula) || segment_plan_valid(g.spatula, p.spatula, g.psi_s2, g.X3_s2,
                                                                         g.psi_e2, g.X3_e2, u14[1], g.h2);
    return beam_ok && spatula_ok;
  }
};

// Newton on the limit system with plan refresh (as solve_with_plans for the full system).
template <class T, class Policy, bool E1, bool E2>
inline bool solve_separatrix(const separatrix_system<T, Policy, E1, E2>& sys, typename seta_system<T, Policy, E1, E2>::vec& z,
                             T mu, seta_plan& plan, T tol, int& iterations) {
  for (int round = 0; round < 4; ++round) {
    if (seta_system<T, Policy, E1, E2>::plan_state(plan) != segment_state::ok) return false;
    int its = 0;
    T u14[2] = {1, 1};
    const newton_code code = newton_fixed_ft(sys, z, mu, plan, tol, 40, its, u14);
    iterations += its;
    if (code != newton_code::converged) return false;
    if (sys.plan_valid(plan, z, mu, u14)) return true;
    plan = sys.plan(z, mu);
  }
  return false;
}

// One segment as the exact forms measure it with R(1) = side * gap_t (side +1: rotation, -1:
// libration), from ends psi_s, psi_e (psi = theta - phi) with the given rate signs. False where no
// such segment exists (f3 < 0 at an end, or no consistent path).
template <class Policy, bool E, class T>
inline bool segment_beside_separatrix(T EI, T c, T N, T psi_s, T sign_s, T psi_e, T sign_e, T gap_t, T& length,
                                      int& turning) {
  using std::sin; using std::sqrt;
  const T M = N + (E ? c * N * N / 2 : T(0)) + gap_t;
  const auto g = make_segment<E>(EI, c, M, N);
  const T f3s = seg_f3(g, sin(psi_s)), f3e = seg_f3(g, sin(psi_e));
  if (!(f3s >= 0) || !(f3e >= 0)) return false;
  const T X3s = sign_s * sqrt(f3s), X3e = sign_e * sqrt(f3e);
  T L = std::numeric_limits<T>::quiet_NaN();
  const segment_plan plan = plan_segment<Policy>(g, psi_s, X3s, psi_e, X3e, T(0.75), &L);
  if (plan.state != segment_state::ok) return false;
  if (plan.direct) L = segment_length<Policy>(g, plan, psi_s, X3s, psi_e, X3e);
  if (!(L > 0)) return false;
  length = L;
  turning = plan.turning_points;
  return true;
}

// The distance from the separatrix at which limit_ends_joined looks for a path: the first measuring
// distance 2^resolved of the scale |M| + N, but in a type wider than double no more than a quarter
// of the nearer end's own f3 = X3^2 (its squared rate over f4, in M's units; a floor four bits above
// the type's rounding of M). A libration at the distance d from the separatrix has f3 - d at the
// ends, so it cannot reach an end whose f3 is below d, and the test judged the ends of an orbit the
// end does not lie on. Where the march carried an end rate towards zero, it refused the steps
// there: the long-double retry's march in arclength stalled at the 10,000-design re-run's 24 lines
// with the joint rate near zero (6 pass now) and 33 with the base rate near zero (these now stop
// closer, where the base reaches its saddle's orientation); and the march in Ft went on a way whose
// targets' states were refused (17 targets solved now; validation/README.md, "End rates through
// zero in the march"). Double keeps the fixed distance, so no state solved in double changes.
template <class T>
inline T joining_distance(T scale, T X3s, T X3e) {
  T d = std::ldexp(scale, separatrix_resolved_exponent_of<T>());
  if constexpr (wider_than_double<T>()) {
    const T near = std::min(X3s * X3s, X3e * X3e) / 4;
    if (near < d) d = std::max(near, std::ldexp(scale, 4 - std::numeric_limits<T>::digits));
  }
  return d;
}

// Whether every limit segment of `lim` at the state z has a path next to its separatrix, on
// either side, that joins the state's ends with their rate signs (segment_beside_separatrix at
// joining_distance). The limit system sees a beam's joint end only through v = sin(psi)
// at the joint, even about the saddle psi = pi/2 (and its rate only squared), so next to the saddle
// it has a mirror solution, the joint end as far past the saddle as it was short of it, beta moved
// by about twice that, and the other equations nearly unchanged; no path joins the mirror's ends
// (a libration cannot pass the saddle and come back, a rotation keeps its rate's sign). A march
// step to such a state is the march jumping to the mirror, not the line: campaign design 4, marched
// in Ft from the stall at 621.4, jumped at Ft = 1484.6 from the joint 2.4e-3 rad short of the saddle
// to 2.2e-3 past it, with theta1'(l1) < 0 on both sides, and every target beyond was refused
// (validation/README.md, "The march's mirror jump, and free rate signs through a saddle").
template <class T, class Policy, bool E1, bool E2>
inline bool limit_ends_joined(const separatrix_system<T, Policy, E1, E2>& lim,
                              const typename seta_system<T, Policy, E1, E2>::vec& z, T mu) {
  const auto& d = lim.base.d;
  T Ft, edge;
  lim.base.forces(mu, Ft, edge);
  const auto g = make_seta_geometry<E1, E2>(d, z[0], z[1], z[2], z[3], Ft, edge, true);
  auto joined = [&](const auto& c, auto E, T EI, T cc, T ps, T X3s, T pe, T X3e) {
    constexpr bool Ext = decltype(E)::value;
    const T da = joining_distance(std::fabs(c.M) + c.N, X3s, X3e);
    const T ss = X3s >= 0 ? T(1) : T(-1), se = X3e >= 0 ? T(1) : T(-1);
    for (T side : {T(1), T(-1)}) {
      T length;
      int turning;
      if (segment_beside_separatrix<Policy, Ext>(EI, cc, c.N, ps, ss, pe, se, side * da, length, turning)) return true;
    }
    return false;
  };
  if ((lim.mask & limit_beam) && !joined(g.beam, std::integral_constant<bool, E1>(), d.EI1, d.c1, g.psi_s1,
                                         g.X3_s1, g.psi_e1, g.X3_e1))
    return false;
  if ((lim.mask & limit_spatula) && !joined(g.spatula, std::integral_constant<bool, E2>(), d.EI2, d.c2, g.psi_s2,
                                            g.X3_s2, g.psi_e2, g.X3_e2))
    return false;
  return true;
}

// A march step of the limit system from z (ends joined) to zt at mu: true, with zt possibly
// changed, where zt's ends are joined (limit_ends_joined). The limit system leaves the sign of a
// rate free where it enters only squared: the base rate q with the beam a limit segment (F4 =
// q^2 - R1; its sign served only the beam's length equation), and the joint rate p as well with
// both segments limit segments. The two signs are two paths, a loop apart, with Fn and beta the
// same to O(delta). Where the rate's end passes its saddle's orientation the smooth continuation
// carries such a rate through zero with the end's angle, and on one of the two paths that leads
// to ends no path joins; a free rate that changed sign over the step is then given back its sign,
// which joins them. (Campaign design 161: the march's first step from the stall had landed on the
// other sign of theta1'(0) than the line's last node, and at the base's saddle, Ft = 1398.6, it
// carried theta1'(0) through zero to ends that nothing joins, and on to states with 2 beam turning
// points. Given back its sign, it is the line traced in long double by the full system alone:
// theta1'(0) > 0 past the saddle.) Keeping a free rate's sign at every step where the ends allow
// it was tried and not kept: it lost 68 states of the campaign re-run and moved 72
// (validation/README.md, "The march's mirror jump, and free rate signs through a saddle").
// False where no sign joins the ends: the step has jumped to the limit system's mirror
// (limit_ends_joined), and the march retries it shorter.
template <class T, class Policy, bool E1, bool E2>
inline bool keep_ends_joined(const separatrix_system<T, Policy, E1, E2>& lim,
                             const typename seta_system<T, Policy, E1, E2>::vec& z,
                             typename seta_system<T, Policy, E1, E2>::vec& zt, T mu) {
  if (limit_ends_joined(lim, zt, mu)) return true;
  const bool q_free = (lim.mask & limit_beam) != 0, p_free = lim.mask == (limit_beam | limit_spatula);
  const bool q_changed = q_free && z[3] * zt[3] < 0, p_changed = p_free && z[2] * zt[2] < 0;
  for (int restore = 1; restore < 4; ++restore) {  // q, p, both given back their sign
    if (((restore & 1) && !q_changed) || ((restore & 2) && !p_changed)) continue;
    auto zf = zt;
    if (restore & 1) zf[3] = -zf[3];
    if (restore & 2) zf[2] = -zf[2];
    if (limit_ends_joined(lim, zf, mu)) {
      zt = zf;
      return true;
    }
  }
  return false;
}

// The length in units of the saddle's time constant, l / tau = l sqrt(N (1 + c N) / EI), and the
// relative separatrix distance R(1)/(|M| + N) of both segments at a state of the full system.
// The time constant, not sqrt(EI/N): delta shrinks like exp(-l / tau), and for an extensible
// segment far into tension (c N up to thousands in the stress box) sqrt(EI/N) counted a beam on
// its separatrix to double precision as five lengths, below separatrix_long_segment, and its line
// stayed stalled (validation/README.md, "Extensible beams stalled on their separatrix").
template <class T, class Policy, bool E1, bool E2>
inline void separatrix_measures(const seta_system<T, Policy, E1, E2>& sys, const typename seta_system<T, Policy, E1, E2>::vec& z,
                                T mu, T lengths[2], T gaps[2]) {
  using std::fabs; using std::sqrt;
  T Ft, edge;
  sys.forces(mu, Ft, edge);
  const auto g = make_seta_geometry<E1, E2>(sys.d, z[0], z[1], z[2], z[3], Ft, edge, false);
  lengths[0] = sys.d.l1 * sqrt(g.beam.N * (1 + sys.d.c1 * g.beam.N) / sys.d.EI1);
  lengths[1] = sys.d.l2 * sqrt(g.spatula.N * (1 + sys.d.c2 * g.spatula.N) / sys.d.EI2);
  gaps[0] = separatrix_gap(g.beam) / (fabs(g.beam.M) + g.beam.N);
  gaps[1] = separatrix_gap(g.spatula) / (fabs(g.spatula.M) + g.spatula.N);
}

// Segments that a line stalled next to: long (separatrix_long_segment elastic lengths or more) and
// within separatrix_stall_gap of the separatrix.
template <class T>
inline int separatrix_mask(const T lengths[2], const T gaps[2]) {
  using std::fabs;
  auto stalled = [&](int i) {
    return lengths[i] >= T(separatrix_long_segment) && fabs(gaps[i]) <= T(separatrix_stall_gap);
  };
  int mask = 0;
  if (stalled(0)) mask |= limit_beam;
  if (stalled(1)) mask |= limit_spatula;
  return mask;
}

// A march's step: a segment that has come next to its separatrix on the way (lengths, gaps:
// separatrix_measures at (z, mu)) joins the limit ones. The limit system is then planned and
// solved again there and whether a path joins its ends is checked afresh; otherwise a march not
// yet joined is checked, and one joined stays so (keep_ends_joined kept it). Shared by the marches
// in Ft (detail/separatrix_extend.hpp) and in arclength (detail/separatrix_arclength.hpp).
// Returns -1 where the new solve fails, 1 where the mask grew, else 0.
template <class T, class Policy, bool E1, bool E2>
inline int grow_limit_segments(separatrix_system<T, Policy, E1, E2>& lim, const T lengths[2], const T gaps[2],
                               typename seta_system<T, Policy, E1, E2>::vec& z, T mu, seta_plan& plan, T tol,
                               int& iterations, bool& joined) {
  const int grown = lim.mask | separatrix_mask(lengths, gaps);
  if (grown != lim.mask) {
    lim.mask = grown;
    plan = lim.plan(z, mu);
    if (!solve_separatrix(lim, z, mu, plan, tol, iterations)) return -1;
    joined = limit_ends_joined(lim, z, mu);
    return 1;
  }
  if (!joined) joined = limit_ends_joined(lim, z, mu);
  return 0;
}

// Whether segment i (0 beam, 1 spatula) is long and its separatrix distance below what a state's
// digits resolve (separatrix_unresolved_exponent): its length equation, logarithmic in a distance
// formed by cancellation, then holds for rounding noise rather than for the state.
template <class T>
inline bool separatrix_unresolved(const T lengths[2], const T gaps[2], int i) {
  return lengths[i] >= T(separatrix_long_segment) &&
         std::fabs(gaps[i]) < std::ldexp(T(1), separatrix_unresolved_exponent_of<T>());
}

// Whether a segment's turning points at a state past the stall can be the followed line's: within
// one of the count at the stall (see separatrix_state_exact for why one, and not two).
inline bool turning_points_follow_line(int turning, int at_stall) { return std::abs(turning - at_stall) <= 1; }

// The exact state from the limit state z at mu (see the header comment): each limit segment's
// separatrix distance delta from its length, and z corrected to first order in it. True, with z
// the exact state, where the correction is certain to tol; turning[]: the limit segments'
// turning points, those of the one side of the separatrix that fits the ends, which must be
// within one of expected[] (the followed line's at its stall).
//   One, because along the line an end can come through the saddle's orientation: near the
// saddle the angle from it is x = A e^(s/tau) + B e^(-s/tau), smooth in the ends, and as the end
// passes, the end rate and the energy (-A B, the sign of delta) change sign at nearby points, so
// the segment goes from a rotation that approaches the saddle to a libration that turns there,
// or back: one turning point more or less. Not two: a segment this long also has paths with
// whole loops more or fewer (each a turning point pair and one more dwell), with Fn and beta the
// same to O(delta); the forms measure the shortest, and a count two away from the line's is
// such another path, not the followed one.
template <class T, class Policy, bool E1, bool E2>
inline bool separatrix_state_exact(const separatrix_system<T, Policy, E1, E2>& lim, typename seta_system<T, Policy, E1, E2>::vec& z,
                                   T mu, const seta_plan& plan, T tol, const int expected[2], int turning[2]) {
  using std::exp; using std::fabs; using std::log;
  using vec = typename seta_system<T, Policy, E1, E2>::vec;
  using mat = typename seta_system<T, Policy, E1, E2>::mat;
  const auto& d = lim.base.d;
  vec F;
  mat J;
  T u14[2];
  if (!lim.eval(z, mu, plan, F, J, nullptr, u14)) return false;
  const Eigen::PartialPivLU<mat> lu(J);
  T Ft, edge;
  lim.base.forces(mu, Ft, edge);
  const auto g = make_seta_geometry<E1, E2>(d, z[0], z[1], z[2], z[3], Ft, edge, true);
  vec shift = vec::Zero();
  T uncertainty = 0;
  bool certain = true;
  // One limit segment: c its constants, row its residual row, ends (psi, X3) as in the geometry.
  auto delta_of = [&](const auto& c, auto E, int row, T EI, T cc, T len, T ps, T X3s, T pe, T X3e, int seg) {
    constexpr bool Ext = decltype(E)::value;
    const T scale = fabs(c.M) + c.N;
    // Lengths at two distances the forms resolve (separatrix_scales.hpp: 2^-36 and 2^-38 of the
    // scale keep delta to about 1e-4), then L(delta) = L_b + slope log(delta_b / delta), exact to
    // O(delta log delta): the dwell at the saddle, slope = passages x tau, with tau =
    // sqrt(EI / (N (1 + c N))) the inverse of the saddle's rate.
    const T da = std::ldexp(scale, separatrix_resolved_exponent_of<T>()),
            db = std::ldexp(scale, separatrix_resolved_exponent_of<T>() - 2);
    const T ss = X3s >= 0 ? T(1) : T(-1), se = X3e >= 0 ? T(1) : T(-1);
    const T tau = std::sqrt(EI / (c.N * (1 + cc * c.N)));
    int sides = 0;
    vec move = vec::Zero();
    T unc = 0;
    for (T side : {T(1), T(-1)}) {
      T La, Lb;
      int ta, tb;
      if (!segment_beside_separatrix<Policy, Ext>(EI, cc, c.N, ps, ss, pe, se, side * da, La, ta) ||
          !segment_beside_separatrix<Policy, Ext>(EI, cc, c.N, ps, ss, pe, se, side * db, Lb, tb))
        continue;  // no segment with these ends on this side of the separatrix
      const T slope = (Lb - La) / log(da / db);
      const T passages = slope / tau;
      if (ta != tb || !turning_points_follow_line(tb, expected[seg]) || !(passages > T(0.5)) ||
          !(fabs(passages - std::round(passages)) < T(1e-3)))
        return false;
      // Longer than the segment already at delta_b: the exact |delta| is larger, and the law
      // (good while delta is small) gives a start for the segment's own length equation, not
      // the state.
      if (!(Lb < len)) certain = false;
      ++sides;
      const T delta = side * db * exp(-(len - Lb) / slope);
      turning[seg] = tb;
      // The correction's relative uncertainty: the slope's (two lengths each good to ~1e-4 tau)
      // over the extrapolated logarithm, and delta_b's own.
      const T rel = T(2e-4) * (1 + (len - Lb) / slope);
      vec e = vec::Zero();
      e[row] = len / scale;  // the limit row is l delta / scale
      move = lu.solve(e) * delta;
      unc = lim.step_norm(move, z) * rel;
    }
    // Exactly one side: the ends' rate signs must tell libration from rotation.
    if (sides != 1) return false;
    shift += move;
    uncertainty += unc;
    return true;
  };
  if ((lim.mask & limit_beam) && !delta_of(g.beam, std::integral_constant<bool, E1>(), 1, d.EI1, d.c1, d.l1,
                                           g.psi_s1, g.X3_s1, g.psi_e1, g.X3_e1, 0))
    return false;
  if ((lim.mask & limit_spatula) && !delta_of(g.spatula, std::integral_constant<bool, E2>(), 0, d.EI2, d.c2, d.l2,
                                              g.psi_s2, g.X3_s2, g.psi_e2, g.X3_e2, 1))
    return false;
  z += shift;
  return certain && uncertainty <= tol / 4;
}

// Whether the segments outside `mask` (measured by their own length equations) are resolved at the
// state z, and those of them in `limit_mask` (limit segments of the march) have turning points
// within one of expected[].
template <class T, class Policy, bool E1, bool E2>
inline bool measured_segments_resolved(const seta_system<T, Policy, E1, E2>& sys, const typename seta_system<T, Policy, E1, E2>::vec& z,
                                       T mu, int mask, int limit_mask, const int expected[2], const int turning[2]) {
  T lengths[2], gaps[2];
  separatrix_measures(sys, z, mu, lengths, gaps);
  const int bits[2] = {limit_beam, limit_spatula};
  for (int i = 0; i < 2; ++i) {
    if (mask & bits[i]) continue;
    if (separatrix_unresolved(lengths, gaps, i)) return false;
    if ((limit_mask & bits[i]) && !turning_points_follow_line(turning[i], expected[i])) return false;
  }
  return true;
}

// The state at a target mu from the marched limit state z: the limit system with every nonempty
// subset of the limit segments (largest first: a segment not yet long enough for its limit to be
// certified is measured by its length equation again, started from the law's estimate), and last
// the full system, every segment measured, from that estimate. That last one serves the targets
// where the law says the segment is not deep enough yet (longer than l at delta_b: the exact
// |delta| is above 2^-38 of the scale, which its own length equation resolves). Any state with a
// measured segment is kept only under measured_segments_resolved: without that guard the full
// system, re-planned next to a separatrix, had converged to states 1e-7 to 1e-5 off in Fn in the
// campaign re-run (distances below the digits, or a path with loops more). True with r set where
// a state is certified and its admissibility decided (and *z_out, where given, its unknowns).
template <class T, class Policy, bool E1, bool E2>
inline bool separatrix_target_state(const separatrix_system<T, Policy, E1, E2>& lim, const typename seta_system<T, Policy, E1, E2>::vec& z,
                                    T mu, T Ft, T tol, const int expected[2], int iterations, critical_state<T>& r,
                                    typename seta_system<T, Policy, E1, E2>::vec* z_out = nullptr) {
  using vec = typename seta_system<T, Policy, E1, E2>::vec;
  const auto& sys = lim.base;
  int masks[4] = {lim.mask, 0, 0, 0};
  int count = 1;
  if (lim.mask == (limit_beam | limit_spatula)) {
    masks[count++] = limit_spatula;
    masks[count++] = limit_beam;
  }
  masks[count++] = 0;  // the full system
  vec start = z;  // the limit state corrected to first order in delta where the law gives it
  for (int m = 0; m < count; ++m) {
    const int mask = masks[m];
    vec zs = start;
    int its = iterations;
    int turning[2];
    const separatrix_system<T, Policy, E1, E2> sub{sys, mask};
    seta_plan plan = sub.plan(zs, mu);
    if (!solve_separatrix(sub, zs, mu, plan, tol, its)) continue;
    sys.turning_points(plan, zs, mu, turning[0], turning[1]);
    if (!separatrix_state_exact(sub, zs, mu, plan, tol, expected, turning)) {
      if (m == 0) start = zs;
      continue;
    }
    // A segment this system measures by its own length equation must be resolved by it, and,
    // where it was a limit segment of the march, keep the followed line's turning points within
    // one (separatrix_state_exact's rule): else the smaller system has solved that equation for
    // rounding noise (a spatula 92 elastic lengths long gave Fn right and beta 3.5e-7 off in the
    // campaign re-run) or taken a path with a loop more.
    if (!measured_segments_resolved(sys, zs, mu, mask, lim.mask, expected, turning)) continue;
    if (z_out) *z_out = zs;
    r = critical_state<T>();
    r.Ft = Ft;
    r.status = critical_status::converged;
    r.iterations = its;
    r.Fn = zs[0];
    r.theta_joint = sys.theta_joint(zs);
    r.theta_rate_joint = sys.rate_joint(zs);
    r.theta_rate_base = sys.rate_base(zs);
    r.turning_points_beam = turning[0];
    r.turning_points_spatula = turning[1];
    apply_admissibility(sys, r);
    // A state whose admissibility could not be decided stays unknown (a strain beyond the limit or
    // a stretch <= 0 decides it without the height).
    if (r.status == critical_status::inadmissible && !(r.min_z == r.min_z) &&
        !(r.max_axial_strain > sys.strain_limit) && !(r.min_stretch <= 0))
      return false;
    return true;
  }
  return false;
}

}  // namespace detail
}  // namespace gecko
