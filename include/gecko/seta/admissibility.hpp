// gecko/seta/admissibility.hpp — is a solved state of the two-level seta physically possible?
//
// The equations of the seta (paper 001 eqs (1)-(5)) know nothing of the substrate except at the
// contact edge: a state can solve them and still put the joint or the beam below the substrate
// (z < 0), which a real seta cannot do. admissibility_check says whether the deformed seta stays
// on its side of the substrate everywhere before the contact edge (min z >= 0 over s in [0, a]),
// where its lowest point is, and its largest axial strain |T|/EA, T = Ft sin(theta) - Fn cos(theta)
// (the axial force of eqs (1)-(2)).
//
// Height. With x along the substrate towards the contact and z the height above it (the edge at
// z = 0), dz/ds = -(1 + T/EA) cos(theta) (the convected coordinate s of eqs (1)-(2)). So z can only
// have a minimum before the edge where cos(theta) changes sign, i.e. where theta crosses +-pi/2 (mod
// 2 pi), or at a segment end.
//   * Fast, exact test (almost every state): when theta stays in [-pi/2, pi/2] along both segments
//     (and 1 + T/EA > 0), z decreases monotonically from the base to the edge, so min z = 0 at the
//     edge. Theta's range on a segment is that of its ends plus the turning angles reached inside
//     (the solver's turning-point counts; the angles from the first integral, eq (8)): without
//     turning points it costs a few comparisons and one sincos for the strain, with them an atan2
//     and an asin.
//   * Otherwise z is evaluated at every segment end and every crossing of theta = pi/2 + k pi, by
//     integrating dz = -(1 + T/EA) cos(theta) dtheta / theta' over the monotone pieces of theta
//     (split at the turning points theta* where theta' = 0, eq (8)'s first integral
//     1/2 EI theta'^2 = M - N sin(psi) - N^2 sin^2(psi)/(2 EA), psi = theta - phi, gives theta' as
//     a function of theta). Each piece is mapped to t in [0, 1] by theta = theta_p + (theta_q -
//     theta_p)(1 - cos(pi t))/2, which removes the inverse square-root singularity of 1/theta' at a
//     turning point, and integrated by adaptive 16-point Gauss-Legendre (bisection until two
//     levels agree to 1e-13 of the seta's length). The same quadrature integrates ds, and the
//     lengths found must reproduce l1 and the free spatula length: a check of the decomposition
//     (to 1e-9 of the seta's length; else the check reports itself as not made, min_z = NaN).
//     The minimum over the candidates is exact up to the quadrature tolerance: no sampling in s.
// Strain. The largest |T|/EA of each segment over theta's range (T = N sin(psi): N where the range
// contains psi = pi/2 mod 2 pi, else the larger end), 0 for EA = infinity.
#pragma once

#include <cmath>
#include <limits>

#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/elastica_segment.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

// The verdict on one state.
template <class T>
struct admissibility_result {
  // true: min_z >= -1e-12 (l1 + l2) and (with a strain limit) max_axial_strain <= strain_limit.
  bool admissible = false;
  bool crosses_substrate = false;  // min_z < -1e-12 (l1 + l2): part of the seta below the substrate
  bool strain_exceeded = false;    // max_axial_strain > strain_limit
  T min_z = std::numeric_limits<T>::quiet_NaN();  // lowest height over [0, a] (0 at the edge itself)
  T where = std::numeric_limits<T>::quiet_NaN();  // arc length s of that point (a: the edge)
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();  // max over s of |T(s)|/EA(s)
  bool exact_fast_path = false;  // theta stayed within [-pi/2, pi/2]: no quadrature was needed
};

// A deformed state in the solvers' terms (critical_state, or a forward-problem state whose contact
// edge is at s = a < l1 + l2): the forces, beta = theta2(l1), the end rates theta1'(0) and
// theta2'(l1), and the turning points (sign changes of theta') inside each segment.
template <class T>
struct seta_pose {
  T Fn, Ft, theta_joint, theta_rate_base, theta_rate_joint;
  int turning_points_beam, turning_points_spatula;
  T free_spatula_length = std::numeric_limits<T>::quiet_NaN();  // a - l1; NaN: l2 (critical state)
};

namespace detail {

// 16-point Gauss-Legendre nodes and weights on [0, 1] (Newton on P_16, computed once).
template <class T>
struct gauss_legendre16 {
  T x[16], w[16];
  gauss_legendre16() {
    using std::cos; using std::fabs;
    const int n = 16;
    for (int i = 0; i < n; ++i) {
      T z = cos(seta_pi<T>() * (i + T(0.75)) / (n + T(0.5)));
      T dp = 1;
      for (int it = 0; it < 100; ++it) {
        T p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const T p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const T dz = p1 / dp;
        z -= dz;
        if (fabs(dz) < 4 * std::numeric_limits<T>::epsilon()) break;
      }
      x[i] = (1 - z) / 2;
      w[i] = 1 / ((1 - z * z) * dp * dp);  // 2/((1-z^2) P'^2), halved for [0, 1]
    }
  }
  static const gauss_legendre16& get() {
    static const gauss_legendre16 g;
    return g;
  }
};

// One segment for the quadrature: 1/2 EI theta'^2 = R(u) = M - N u - c N^2 u^2/2, u = sin(theta -
// phi) (paper 001 eqs (8), (12)).
template <class T>
struct height_segment {
  T EI, c, M, N, phi;
  T up;        // root of f3 (turning points at sin(psi) = up); > 1: rotation, no turning point
  T b3, b4;    // R = f3 f4, f3 = M + b3 u = -b3 (up - u), f4 = 1 + b4 u
  T psi_top;   // asin(up) for a libration
};

template <class T>
inline height_segment<T> make_height_segment(T EI, T c, T M, T N, T phi) {
  using std::asin; using std::sqrt;
  height_segment<T> g{EI, c, M, N, phi, 0, 0, 0, 0};
  const T s = sqrt(1 + 2 * c * M);
  g.b3 = -N * (1 + s) / 2;
  g.b4 = c * N / (1 + s);
  g.up = 2 * M / (N * (1 + s));
  g.psi_top = g.up < 1 ? asin(g.up) : seta_pi<T>() / 2;
  return g;
}

// |theta'| at theta, from the first integral. In a libration f3 = -b3 (up - sin psi) is written
// with a turning angle theta_t (sin(theta_t - phi) = up) and delta = theta_t - theta as
// 2 cos(theta_t - phi - delta/2) sin(delta/2): no cancellation as theta -> theta_t when the caller
// gives delta exactly (the quadrature maps t to the distance from a turning end directly).
template <class T>
inline T height_rate(const height_segment<T>& g, T theta, T theta_t, T delta) {
  using std::cos; using std::sin; using std::sqrt;
  const T u = sin(theta - g.phi);
  const T f3 = g.up < 1 ? -g.b3 * 2 * cos(theta_t - g.phi - delta / 2) * sin(delta / 2) : g.M + g.b3 * u;
  const T f4 = 1 + g.b4 * u;
  const T R = f3 * f4;
  return R > 0 ? sqrt(2 * R / g.EI) : T(0);
}

// The turning angle of the libration window around theta nearest to it.
template <class T>
inline T nearest_turning(const height_segment<T>& g, T theta) {
  using std::floor;
  const T pi = seta_pi<T>();
  const T psi = theta - g.phi;
  const T k = floor((psi + pi / 2) / (2 * pi) + T(0.5));
  const T pr = psi - k * 2 * pi;  // in the window [-pi - a, a] around -pi/2
  return (pr > -pi / 2 ? g.psi_top : -pi - g.psi_top) + g.phi + k * 2 * pi;
}

// ds and dz over theta from a to b (theta monotone there) for t in [t0, t1] of the map
// theta = a + (b - a) sin^2(pi t/2) = b - (b - a) cos^2(pi t/2), by 16-point Gauss-Legendre.
// turn_a, turn_b: the end is a turning point (theta' = 0 there).
template <class T>
inline void height_gl(const height_segment<T>& g, T a, T b, bool turn_a, bool turn_b, T t0, T t1, T& ds, T& dz) {
  using std::cos; using std::sin;
  const auto& q = gauss_legendre16<T>::get();
  const T pi = seta_pi<T>();
  const T span = b - a;
  const T sgn = span >= 0 ? T(1) : T(-1);
  ds = 0;
  dz = 0;
  for (int i = 0; i < 16; ++i) {
    const T t = t0 + (t1 - t0) * q.x[i];
    const T sh = sin(pi * t / 2), ch = cos(pi * t / 2);
    const T th = t < T(0.5) ? a + span * sh * sh : b - span * ch * ch;
    const T dth = span * pi * sh * ch;  // dtheta/dt
    T rate;
    if (g.up < 1) {
      if (turn_b && (t >= T(0.5) || !turn_a)) rate = height_rate(g, th, b, span * ch * ch);
      else if (turn_a) rate = height_rate(g, th, a, -span * sh * sh);
      else {
        const T tt = nearest_turning(g, th);
        rate = height_rate(g, th, tt, tt - th);
      }
    } else {
      rate = height_rate(g, th, th, T(0));
    }
    if (!(rate > 0)) continue;  // only at a turning point itself, where dtheta/dt vanishes too
    const T w = q.w[i] * (t1 - t0) * dth * sgn / rate;  // ds
    ds += w;
    dz -= w * (1 + g.c * g.N * sin(th - g.phi)) * cos(th);
  }
}

// Adaptive bisection: an interval is accepted when its two halves agree with the whole to tol
// (16-point Gauss-Legendre converges geometrically, so the accepted values are far better than
// tol); budget caps the number of intervals (false when it runs out or depth 30 is reached).
template <class T>
inline bool height_adaptive(const height_segment<T>& g, T a, T b, bool turn_a, bool turn_b, T t0, T t1, T ds_whole,
                            T dz_whole, T tol, int depth, int& budget, T& ds, T& dz) {
  using std::fabs;
  const T tm = (t0 + t1) / 2;
  T dsl, dzl, dsr, dzr;
  height_gl(g, a, b, turn_a, turn_b, t0, tm, dsl, dzl);
  height_gl(g, a, b, turn_a, turn_b, tm, t1, dsr, dzr);
  budget -= 2;
  const T es = fabs(dsl + dsr - ds_whole), ez = fabs(dzl + dzr - dz_whole);
  if ((es <= tol && ez <= tol) || depth >= 30 || budget <= 0) {
    ds += dsl + dsr;
    dz += dzl + dzr;
    return es <= tol && ez <= tol;
  }
  const bool ok_l = height_adaptive(g, a, b, turn_a, turn_b, t0, tm, dsl, dzl, tol, depth + 1, budget, ds, dz);
  const bool ok_r = height_adaptive(g, a, b, turn_a, turn_b, tm, t1, dsr, dzr, tol, depth + 1, budget, ds, dz);
  return ok_l && ok_r;
}

// Walks one segment from (theta_s, sign of theta'_s) through its turning points to theta_e,
// splitting at theta = pi/2 + k pi; calls visit(s, z) at every end and split point. s, z: running
// arc length and height on entry, updated. False when the pieces do not fit together.
template <class T, class Visit>
inline bool height_walk(const height_segment<T>& g, T theta_s, T rate_s, T theta_e, int turning, T tol, T& s,
                        T& z, Visit&& visit) {
  using std::ceil; using std::fabs; using std::floor;
  const T pi = seta_pi<T>();
  const T two_pi = 2 * pi;
  const T psi_s = theta_s - g.phi;
  const T k = floor((psi_s + pi / 2) / two_pi + T(0.5));
  const T th_max = g.phi + g.psi_top + k * two_pi;
  const T th_min = g.phi - pi - g.psi_top + k * two_pi;
  if (turning < 0) return false;
  if (turning > 0 && !(g.up < 1)) return false;
  T dir;
  if (rate_s > 0) dir = 1;
  else if (rate_s < 0) dir = -1;
  else if (turning == 0) dir = theta_e >= theta_s ? T(1) : T(-1);
  else dir = fabs(theta_s - th_max) <= fabs(theta_s - th_min) ? T(-1) : T(1);
  T th = theta_s;
  bool ok = true;
  auto piece = [&](T a, T b, bool turn_a, bool turn_b) {
    // split at pi/2 + j pi strictly inside (a, b)
    const T lo = a < b ? a : b, hi = a < b ? b : a;
    T first = ceil((lo - pi / 2) / pi) * pi + pi / 2;
    if (!(first > lo)) first += pi;
    T cur = a;
    auto sub = [&](T from, T to) {
      if (from == to) return;
      const bool ta = turn_a && from == a, tb = turn_b && to == b;
      T ds0, dz0, ds = 0, dz = 0;
      height_gl(g, from, to, ta, tb, T(0), T(1), ds0, dz0);
      int budget = 2000;
      if (!height_adaptive(g, from, to, ta, tb, T(0), T(1), ds0, dz0, tol, 0, budget, ds, dz)) ok = false;
      s += ds;
      z += dz;
      visit(s, z);
    };
    if (a < b) {
      for (T c = first; c < hi; c += pi) { sub(cur, c); cur = c; }
    } else {
      T c = floor((hi - pi / 2) / pi) * pi + pi / 2;
      if (!(c < hi)) c -= pi;
      for (; c > lo; c -= pi) { sub(cur, c); cur = c; }
    }
    sub(cur, b);
  };
  for (int i = 0; i < turning; ++i) {
    const T next = dir > 0 ? th_max : th_min;
    if ((next - th) * dir < -tol) return false;
    piece(th, next, i > 0, true);
    th = next;
    dir = -dir;
  }
  if ((theta_e - th) * dir < -1e-9) return false;  // the last piece runs against theta'
  piece(th, theta_e, turning > 0, false);
  return ok;
}

// Largest |T|/EA over theta in [lo, hi] on one segment, T = N sin(theta - phi).
template <class T>
inline T segment_max_strain(T c, T N, T phi, T lo, T hi) {
  using std::ceil; using std::fabs; using std::sin;
  if (!(c > 0)) return 0;
  const T pi = seta_pi<T>();
  // |sin psi| = 1 at psi = pi/2 + j pi inside?
  const T first = ceil((lo - phi - pi / 2) / pi) * pi + pi / 2 + phi;
  if (first <= hi) return c * N;
  const T a = fabs(sin(lo - phi)), b = fabs(sin(hi - phi));
  return c * N * (a > b ? a : b);
}

// The check on design parameters d (1/EA as c1, c2) and a pose; strain_limit: +inf for none.
template <class T>
inline admissibility_result<T> admissibility_imp(const seta_params<T>& d, const seta_pose<T>& st, T strain_limit) {
  using std::atan2; using std::cos; using std::fabs; using std::sin; using std::sqrt;
  admissibility_result<T> r;
  const T half_pi = seta_pi<T>() / 2;
  const T L = d.l1 + d.l2;
  const T free2 = st.free_spatula_length == st.free_spatula_length ? st.free_spatula_length : d.l2;
  const T a_edge = d.l1 + free2;
  const T Fn = st.Fn, Ft = st.Ft, beta = st.theta_joint;
  if (!(Fn == Fn) || !(Ft == Ft) || !(beta == beta)) return r;
  const T th_j1 = beta - d.alpha2;  // theta1(l1)
  const int n1 = st.turning_points_beam, n2 = st.turning_points_spatula;
  const T z_tol = T(1e-12) * L;
  auto finish = [&](T strain) {
    r.max_axial_strain = strain;
    r.crosses_substrate = r.min_z < -z_tol;
    r.strain_exceeded = strain > strain_limit;
    r.admissible = !r.crosses_substrate && !r.strain_exceeded && r.min_z == r.min_z;
    return r;
  };
  if (n1 == 0 && n2 == 0) {
    // theta monotone on each segment: its range is that of the ends.
    const T lo1 = d.alpha1 < th_j1 ? d.alpha1 : th_j1, hi1 = d.alpha1 < th_j1 ? th_j1 : d.alpha1;
    const T lo2 = beta < half_pi ? beta : half_pi, hi2 = beta < half_pi ? half_pi : beta;
    if (lo1 >= -half_pi && hi1 <= half_pi && lo2 >= -half_pi && hi2 <= half_pi) {
      // Strain from T at the ends and T' = Ft cos + Fn sin (T = N sin(psi), T' = N cos(psi)):
      // an interior extremum of T where T' changes sign (the ranges are shorter than pi).
      const T N = sqrt(Fn * Fn + Ft * Ft);
      auto seg_strain = [&](T c, T sl, T cl, T sh, T ch) {
        if (!(c > 0)) return T(0);
        const T Tl = Ft * sl - Fn * cl, Th = Ft * sh - Fn * ch;
        const T dl = Ft * cl + Fn * sl, dh = Ft * ch + Fn * sh;
        T m = fabs(Tl) > fabs(Th) ? fabs(Tl) : fabs(Th);
        if ((dl > 0 && dh < 0) || (dl < 0 && dh > 0)) m = N;
        return c * m;
      };
      T strain = 0;
      T sb = 0, cb = 0;
      if (d.c1 > 0 || d.c2 > 0) {
        sb = sin(beta);
        cb = cos(beta);
      }
      if (d.c1 > 0) {
        const T sj = sb * d.co2 - cb * d.s2, cj = cb * d.co2 + sb * d.s2;
        strain = seg_strain(d.c1, d.s1, d.co1, sj, cj);
      }
      if (d.c2 > 0) {
        const T s2 = seg_strain(d.c2, sb, cb, T(1), T(0));
        if (s2 > strain) strain = s2;
      }
      // z decreases along s only while the stretch 1 + T/EA is positive.
      if (strain < 1) {
        r.min_z = 0;
        r.where = a_edge;
        r.exact_fast_path = true;
        return finish(strain);
      }
    }
  }
  // General path: quadrature of z over the monotone pieces.
  const T N = sqrt(Fn * Fn + Ft * Ft);
  if (!(N > 0)) return r;
  const T phi = atan2(Fn, Ft);
  const T p = st.theta_rate_joint, q = st.theta_rate_base;
  const T ub = sin(beta - phi), v = sin(th_j1 - phi);
  // First integrals (eq (8)): M2 from the joint state, M1 from the beam's end at the joint
  // (EI1 theta1'(l1) = EI2 theta2'(l1), eq (4)).
  const T M2 = d.EI2 * p * p / 2 + N * ub + d.c2 * N * N * ub * ub / 2;
  const T rate_j1 = d.EI2 / d.EI1 * p;
  const T M1 = d.EI1 * rate_j1 * rate_j1 / 2 + N * v + d.c1 * N * N * v * v / 2;
  const auto g1 = make_height_segment(d.EI1, d.c1, M1, N, phi);
  const auto g2 = make_height_segment(d.EI2, d.c2, M2, N, phi);
  // theta's range on each segment: its ends and the turning angles reached (n >= 2 turning points
  // reach both ends of the libration window, one the one theta' runs into first).
  T lo1 = d.alpha1, hi1 = d.alpha1, lo2 = beta, hi2 = beta;
  auto track = [&](T& lo, T& hi, T th) {
    if (th < lo) lo = th;
    if (th > hi) hi = th;
  };
  track(lo1, hi1, th_j1);
  track(lo2, hi2, half_pi);
  auto turning_range = [&](const height_segment<T>& g, T th_s, T rate_s, int n, T& lo, T& hi) {
    using std::floor;
    if (n <= 0 || !(g.up < 1)) return;
    const T pi = seta_pi<T>();
    const T k = floor((th_s - g.phi + pi / 2) / (2 * pi) + T(0.5));
    const T tmax = g.phi + g.psi_top + k * 2 * pi, tmin = g.phi - pi - g.psi_top + k * 2 * pi;
    if (n >= 2) {
      track(lo, hi, tmax);
      track(lo, hi, tmin);
    } else {
      track(lo, hi, rate_s > 0 ? tmax : tmin);
    }
  };
  turning_range(g1, d.alpha1, q, n1, lo1, hi1);
  turning_range(g2, beta, p, n2, lo2, hi2);
  T strain = segment_max_strain(d.c1, N, phi, lo1, hi1);
  const T s2 = segment_max_strain(d.c2, N, phi, lo2, hi2);
  if (s2 > strain) strain = s2;
  if (strain < 1 && lo1 >= -half_pi && hi1 <= half_pi && lo2 >= -half_pi && hi2 <= half_pi) {
    // Turning points, but theta stays within [-pi/2, pi/2]: z is monotone all the same.
    r.min_z = 0;
    r.where = a_edge;
    r.exact_fast_path = true;
    return finish(strain);
  }
  const T tol = T(1e-13) * L;
  T s = 0, z = 0;
  T zmin = 0, smin = 0;  // the base, at z = 0 before the shift
  auto visit = [&](T ss, T zz) {
    if (zz < zmin) {
      zmin = zz;
      smin = ss;
    }
  };
  bool ok = true;
  {
    T s_prev = s;
    ok = height_walk(g1, d.alpha1, q, th_j1, n1, tol, s, z, visit) && ok;
    if (fabs(s - s_prev - d.l1) > T(1e-9) * L) ok = false;
  }
  {
    T s_prev = s;
    ok = height_walk(g2, beta, p, half_pi, n2, tol, s, z, visit) && ok;
    if (fabs(s - s_prev - free2) > T(1e-9) * L) ok = false;
  }
  if (!ok || !(strain < 1)) {
    // The decomposition did not close, or the stretch 1 + T/EA reaches 0: no verdict on z.
    r.max_axial_strain = strain;
    r.strain_exceeded = strain > strain_limit;
    return r;
  }
  // Shift so that the contact edge is at z = 0 (its z after the walk is z).
  r.min_z = zmin - z;
  r.where = smin;
  if (!(r.min_z < 0)) {  // the edge itself is the lowest point
    r.min_z = 0;
    r.where = a_edge;
  }
  return finish(strain);
}

}  // namespace detail

// The check for a state of the design (status converged or inadmissible: a solved state); a state
// without a solution gives admissible = false and NaN values. strain_limit: states whose largest
// axial strain exceeds it are inadmissible too (default: no limit).
template <class T>
inline admissibility_result<T> admissibility_check(const TwoLevelSeta<T>& seta, const seta_pose<T>& pose,
                                                   T strain_limit = std::numeric_limits<T>::infinity()) {
  return detail::admissibility_imp(detail::make_seta_params(seta), pose, strain_limit);
}

}  // namespace gecko
