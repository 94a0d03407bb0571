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
// have a minimum before the edge where dz/ds changes sign: where theta crosses +-pi/2 (mod 2 pi),
// where the stretch 1 + T/EA vanishes (a compression of EA or more, which the equations allow but
// no rod can take: such a state is inadmissible, below), or at a segment end.
//   * Fast, exact test (almost every state): when theta stays in [-pi/2, pi/2] along both segments
//     and 1 + T/EA > 0 (T's lowest value above -EA; tension never stops it), z decreases
//     monotonically from the base to the edge, so min z = 0 at the edge. Theta's range on a
//     segment is that of its ends plus the turning angles reached inside (the solver's
//     turning-point counts; the angles from the first integral, eq (8)): without turning points
//     it costs a few comparisons and one sincos for the strain, with them one sincos and one atan2
//     in all and one asin per segment (the other angles' sines by angle addition). An inextensible
//     beam with turning points needs neither where its first integral bars theta = +-pi/2 on its
//     path (beam_first_integral_bars_level: the axial force's largest value on the way exceeds
//     the first integral's constant), nor a spatula with one turning point where its first
//     integral bars -pi/2 on its way down (spatula_first_integral_bars_level).
//   * Otherwise z is evaluated at every segment end and every point where dz/ds turns from
//     negative to positive (the candidates for its minimum; not where z has a maximum), by
//     integrating dz = -(1 + T/EA) cos(theta) dtheta / theta' over the monotone pieces of theta
//     (split at the turning points theta* where theta' = 0, eq (8)'s first integral
//     1/2 EI theta'^2 = M - N sin(psi) - N^2 sin^2(psi)/(2 EA), psi = theta - phi, gives theta' as
//     a function of theta). On a libration the path is integrated in the pendulum's variable chi
//     (sin(omega/2) = k sin(chi), omega the angle from the middle of the libration window), in
//     which ds/dchi is smooth through the turning points (height_gl_chi below) and chi runs on
//     through them, so the pieces between two candidates are one interval of chi, by adaptive
//     Gauss-Legendre: the 8-point rule where the 6-point one agrees with it, else the 16-point rule
//     where the 12-point one does, to 1e-13 of the seta's length, else bisection. On a rotation
//     each piece is mapped to t in [0, 1] by theta = theta_p + (theta_q - theta_p)(1 - cos(pi t))/2
//     and integrated by the 16/12-point pair the same way. The same quadrature integrates
//     ds, and the lengths found must reproduce l1 and the free spatula length: a check of the
//     decomposition (to 1e-9 of the seta's length). Next to a separatrix (the turning angle close to the saddle
//     psi = pi/2) the length is too sensitive to the first integral's constant M for M formed from
//     the state's rates; there the turning angle is solved from the length instead and accepted
//     when the M it implies is the state's to 1e-10 (calibrate_near_saddle); a segment tens of
//     elastic lengths long, which neither M nor the turning angle resolves, is walked past the
//     saddle (walk_past_saddle), and so is one whose M puts it at or past its separatrix in
//     rounding while the solver counts turning points on it (its turning angle is then the
//     saddle's, in theta's range too). If none closes, the check reports itself as not made
//     (min_z = NaN). A beam that stays monotone (theta in
//     [-pi/2, pi/2], stretch positive) while the spatula does not is not walked: its lowest point
//     is the joint. Each quadrature node costs one sincos (height_gl_chi, height_gl).
//     The minimum over the candidates is exact up to the quadrature tolerance: no sampling in s.
// Strain. The largest |T|/EA of each segment over theta's range (T = N sin(psi): +-N where the
// range contains psi = +-pi/2 mod 2 pi, else the ends), 0 for EA = infinity; and the lowest
// stretch 1 + T/EA the same way. A stretch <= 0 somewhere (T <= -EA) maps a piece of the rod to
// zero or negative length: the extensible elastica's linear law still solves there (the first
// integral's R(u) = M - N u - c N^2 u^2/2 has R' = -N (1 + c N u), so the stretch vanishes at the
// top of R, and the edge of the forms, f4's root, lies beyond it), but no rod is turned inside
// out, so the state is inadmissible (`inverted`) whatever the strain limit. The followed critical
// line ends at its first such state (gecko/seta/detail/line_trace.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "gecko/elliptic/first_quadrant_sincos.hpp"
#include "gecko/seta/critical_residual.hpp"
#include "gecko/seta/detail/separatrix_scales.hpp"
#include "gecko/seta/elastica_segment.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

// The verdict on one state.
template <class T>
struct admissibility_result {
  // true: min_z >= -1e-12 (l1 + l2), min_stretch > 0 and (with a strain limit) max_axial_strain <=
  // strain_limit.
  bool admissible = false;
  bool crosses_substrate = false;  // min_z < -1e-12 (l1 + l2): part of the seta below the substrate
  bool strain_exceeded = false;    // max_axial_strain > strain_limit
  // min_stretch <= 0: a segment compressed to zero length or beyond somewhere (T <= -EA). The
  // linear law 1 + T/EA then gives a negative stretch, a rod turned inside out, which no seta can
  // be: inadmissible whatever the strain limit.
  bool inverted = false;
  T min_z = std::numeric_limits<T>::quiet_NaN();  // lowest height over [0, a] (0 at the edge itself)
  T where = std::numeric_limits<T>::quiet_NaN();  // arc length s of that point (a: the edge)
  T max_axial_strain = std::numeric_limits<T>::quiet_NaN();  // max over s of |T(s)|/EA(s)
  T min_stretch = std::numeric_limits<T>::quiet_NaN();       // min over s of 1 + T(s)/EA(s)
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

// n-point Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n, computed once).
template <class T, int n>
struct gauss_legendre {
  T x[n], w[n];
  gauss_legendre() {
    using std::cos; using std::fabs;
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
  static const gauss_legendre& get() {
    static const gauss_legendre g;
    return g;
  }
};

template <class T>
using gauss_legendre16 = gauss_legendre<T, 16>;

// One segment for the quadrature: 1/2 EI theta'^2 = R(u) = M - N u - c N^2 u^2/2, u = sin(theta -
// phi) (paper 001 eqs (8), (12)).
template <class T>
struct height_segment {
  T EI, c, M, N, phi;
  T up;        // root of f3 (turning points at sin(psi) = up); > 1: rotation, no turning point
  T b3, b4;    // R = f3 f4, f3 = M + b3 u = -b3 (up - u), f4 = 1 + b4 u
  T psi_top;   // asin(up) for a libration
  T cos_top;   // cos(psi_top) (0 for a rotation): the turning angles' psi are psi_top and -pi - psi_top
  T sin_phi, cos_phi;
};

// psi_top = asin(up) of a libration (pi/2 for a rotation); NaN until set.
template <class T>
inline void set_turning_angle(height_segment<T>& g) {
  using std::asin;
  if (!(g.psi_top == g.psi_top)) g.psi_top = g.up < 1 ? asin(g.up) : seta_pi<T>() / 2;
}

// sin_phi, cos_phi: of the force direction phi (Fn/N and Ft/N, exact to rounding without trigonometry).
// turning_angle: set psi_top now (else NaN: set_turning_angle before the segment is walked; a
// segment without turning points whose theta stays within [-pi/2, pi/2] never needs it).
template <class T>
inline height_segment<T> make_height_segment(T EI, T c, T M, T N, T phi, T sin_phi, T cos_phi,
                                             bool turning_angle = true) {
  using std::sqrt;
  height_segment<T> g{EI, c, M, N, phi, 0, 0, 0, 0, 0, sin_phi, cos_phi};
  const T s = sqrt(1 + 2 * c * M);
  g.b3 = -N * (1 + s) / 2;
  g.b4 = c * N / (1 + s);
  g.up = 2 * M / (N * (1 + s));
  g.psi_top = std::numeric_limits<T>::quiet_NaN();
  if (turning_angle) set_turning_angle(g);
  g.cos_top = g.up < 1 ? sqrt((1 - g.up) * (1 + g.up)) : T(0);
  return g;
}

// sin and cos of pi w x/2 and of pi w (1 - x)/2 at the n nodes x on [0, 1], for the widths
// w = 2^-depth of the adaptive quadrature's intervals: the map's sin(pi t/2) and cos(pi t/2) =
// sin(pi (1 - t)/2) at the nodes of [t0, t0 + w] then follow by the addition theorem from one
// sincos at each end of the interval, without cancellation (both terms are >= 0).
template <class T, int n>
struct gauss_legendre_map {
  static constexpr int depths = 31;
  T sx[depths][n], cx[depths][n], s1x[depths][n], c1x[depths][n];
  gauss_legendre_map() {
    using std::cos; using std::ldexp; using std::sin;
    const auto& q = gauss_legendre<T, n>::get();
    for (int d = 0; d < depths; ++d) {
      const T h = seta_pi<T>() / 2 * ldexp(T(1), -d);
      for (int i = 0; i < n; ++i) {
        sx[d][i] = sin(h * q.x[i]);
        cx[d][i] = cos(h * q.x[i]);
        s1x[d][i] = sin(h * (1 - q.x[i]));
        c1x[d][i] = cos(h * (1 - q.x[i]));
      }
    }
  }
  static const gauss_legendre_map& get() {
    static const gauss_legendre_map m;
    return m;
  }
};

// The map's sines and cosines at the ends of an interval [t0, t0 + 2^-depth]: sin, cos of pi t0/2
// and of pi (1 - t1)/2, both angles in [0, pi/2] (formed once for the two rules of an interval).
template <class T>
struct interval_ends {
  T s0, c0, s1, c1;
};

template <class T>
inline interval_ends<T> make_interval_ends(T t0, int depth) {
  const T pi = seta_pi<T>();
  const T t1 = t0 + std::ldexp(T(1), -depth);
  interval_ends<T> e;
  first_quadrant_sincos(pi * t0 / 2, e.s0, e.c0);
  first_quadrant_sincos(pi * (1 - t1) / 2, e.s1, e.c1);
  return e;
}

// ds and dz over theta from a to b on a rotation (theta monotone, theta' never zero) for t in
// [t0, t1] = [t0, t0 + 2^-depth] of the map theta = a + (b - a) sin^2(pi t/2) = b - (b - a)
// cos^2(pi t/2), by n-point Gauss-Legendre (librations: height_gl_chi below).
template <int n, class T>
inline void height_gl(const height_segment<T>& g, T a, T b, T t0, int depth, const interval_ends<T>& ends, T& ds,
                      T& dz) {
  using std::cos; using std::sin; using std::sqrt;
  const auto& q = gauss_legendre<T, n>::get();
  const auto& m = gauss_legendre_map<T, n>::get();
  const T pi = seta_pi<T>();
  const T w = std::ldexp(T(1), -depth);
  const T s0 = ends.s0, c0 = ends.c0, s1 = ends.s1, c1 = ends.c1;
  const T span = b - a;
  const T sgn = span >= 0 ? T(1) : T(-1);
  const T two_over_EI = 2 / g.EI, cN = g.c * g.N;
  // Local sums (the outputs are references: accumulating into them directly would store and
  // reload them at every node).
  T sum_ds = 0, sum_dz = 0;
  for (int i = 0; i < n; ++i) {
    const T t = t0 + w * q.x[i];
    const T sh = s0 * m.cx[depth][i] + c0 * m.sx[depth][i];   // sin(pi t/2)
    const T ch = s1 * m.c1x[depth][i] + c1 * m.s1x[depth][i];  // cos(pi t/2)
    const T th = t < T(0.5) ? a + span * sh * sh : b - span * ch * ch;
    const T dth = span * pi * sh * ch;  // dtheta/dt
    const T sn = sin(th), cs = cos(th);
    const T u = sn * g.cos_phi - cs * g.sin_phi;
    const T R = (g.M + g.b3 * u) * (1 + g.b4 * u);
    if (!(R > 0)) continue;  // not on a rotation of a solved state
    const T rate = sqrt(R * two_over_EI);
    const T wt = q.w[i] * w * dth * sgn / rate;  // ds
    sum_ds += wt;
    sum_dz -= wt * (1 + cN * u) * cs;
  }
  ds = sum_ds;
  dz = sum_dz;
}

// Adaptive Gauss-Legendre on a rotation: an interval's 16-point value is accepted when the
// 12-point rule agrees with it to tol (both converge geometrically, the 16-point rule faster, so
// the 12-point rule's error bounds the accepted value's), else the interval is halved; budget caps
// the number of intervals (false when it runs out or depth 30 is reached).
template <class T>
inline bool height_adaptive(const height_segment<T>& g, T a, T b, T t0, T tol, int depth, int& budget, T& ds,
                            T& dz) {
  using std::fabs;
  T ds16, dz16, ds12, dz12;
  const interval_ends<T> ends = make_interval_ends(t0, depth);
  height_gl<16>(g, a, b, t0, depth, ends, ds16, dz16);
  height_gl<12>(g, a, b, t0, depth, ends, ds12, dz12);
  --budget;
  const bool agree = fabs(ds16 - ds12) <= tol && fabs(dz16 - dz12) <= tol;
  if (agree || depth >= 30 || budget <= 0) {
    ds += ds16;
    dz += dz16;
    return agree;
  }
  const T tm = t0 + std::ldexp(T(1), -depth - 1);
  const bool ok_l = height_adaptive(g, a, b, t0, tol, depth + 1, budget, ds, dz);
  const bool ok_r = height_adaptive(g, a, b, tm, tol, depth + 1, budget, ds, dz);
  return ok_l && ok_r;
}

// Libration pieces in the pendulum's variable chi. In a libration window, psi = theta - phi runs
// between the turning angles -pi - psi_top and psi_top; with omega = psi + pi/2 (mod 2 pi), the
// distance from the window's centre, and h = psi_top + pi/2 its half-width, u = sin(psi) =
// -cos(omega), up = -cos(h) and f3 = -b3 (up - u) = -b3 (cos(omega) - cos(h)) vanishes at both
// turning angles. The pendulum's substitution sin(omega/2) = k sin(chi), k = sin(h/2)
// (DLMF 22.19(i)), gives cos(omega) - cos(h) = 2 k^2 cos^2(chi) and d omega = 2 k cos(chi) d chi /
// Delta with Delta = cos(omega/2) = sqrt(cos^2 chi + k'^2 sin^2 chi), so that
//   ds = d theta / |theta'| = sqrt(EI/(-b3)) d chi / (Delta sqrt(f4))            (eq (8), R = f3 f4)
// is smooth over the whole window: the turning angles are chi = +-pi/2, ordinary points, so a
// piece that ends at or near one needs no special map (the integrand's nearest singularities are
// at sin^2 chi = 1/k^2 and at f4 = 0, off the real interval; they close in on chi = +-pi/2 only
// near a separatrix, k' -> 0). For an inextensible segment (f4 = 1) the length is
// sqrt(EI/(-b3)) F(chi|k^2) (DLMF 19.2.4). k^2 = (1 + up)/2 and k'^2 = (1 - up)/2 =
// cos_top^2/(2 (1 + up)) keep their relative accuracy near the separatrix (cos_top is formed from
// the distance to it). Then u = 2 k^2 sin^2 chi - 1, cos(psi) = sin(omega) = 2 sin(omega/2) Delta
// and cos(theta) = sin(omega) cos(phi) - u sin(phi): one sincos and two square roots per node.
template <class T>
struct libration_frame {
  T k, kc2, scale;  // k = sin(h/2), k'^2 = cos^2(h/2), sqrt(EI/(-b3))
};

template <class T>
inline libration_frame<T> make_libration_frame(const height_segment<T>& g) {
  using std::sqrt;
  return {sqrt((1 + g.up) / 2), g.cos_top * g.cos_top / (2 * (1 + g.up)), sqrt(g.EI / -g.b3)};
}

// chi of theta in the libration window around theta_mid: sin(chi) = sin(omega/2)/k and
// k cos(chi) = sqrt(sin((h - omega)/2) sin((h + omega)/2)), from theta's distances to the window's
// turning angles (exact differences to rounding, so chi stays accurate next to a turning angle).
template <class T>
inline T libration_chi(const height_segment<T>& g, T theta, T theta_mid) {
  using std::atan2; using std::floor; using std::sin; using std::sqrt;
  const T pi = seta_pi<T>();
  const T kw = floor((theta_mid - g.phi + pi / 2) / (2 * pi) + T(0.5));
  const T to_top = g.phi + g.psi_top + kw * 2 * pi - theta;           // h - omega
  const T from_bottom = theta - (g.phi - pi - g.psi_top + kw * 2 * pi);  // h + omega
  T p = sin(to_top / 2) * sin(from_bottom / 2);
  if (!(p > 0)) p = 0;  // on (or, by rounding, beyond) a turning angle
  return atan2(sin((from_bottom - to_top) / 4), sqrt(p));
}

// ds and dz over chi in [x0, x1] of a libration by n-point Gauss-Legendre. chi may leave
// [-pi/2, pi/2]: a path through a turning angle continues in chi (height_walk), and the integrand,
// a function of sin(chi) and cos^2(chi), is reduced to [-pi/2, pi/2] by chi = r + j pi,
// sin(chi) = (-1)^j sin(r).
template <int n, class T>
inline void height_gl_chi(const height_segment<T>& g, const libration_frame<T>& f, T x0, T x1, T& ds, T& dz) {
  using std::fabs; using std::nearbyint; using std::sqrt;
  const auto& q = gauss_legendre<T, n>::get();
  const T h = x1 - x0, cN = g.c * g.N;
  const T pi = seta_pi<T>();
  const bool reduce = fabs(x0) > pi / 2 || fabs(x1) > pi / 2;
  T sum_ds = 0, sum_dz = 0;
  for (int i = 0; i < n; ++i) {
    T chi = x0 + h * q.x[i];
    T flip = 1;
    if (reduce && fabs(chi) > pi / 2) {
      const T j = nearbyint(chi / pi);
      chi -= j * pi;
      if (std::fmod(j, T(2)) != 0) flip = -1;
    }
    T sc, cc;
    first_quadrant_sincos(fabs(chi), sc, cc);
    sc = std::copysign(sc, chi) * flip;
    const T sw = f.k * sc;                      // sin(omega/2)
    const T d2 = cc * cc + f.kc2 * (sc * sc);   // Delta^2 = cos^2(omega/2)
    const T u = 2 * sw * sw - 1;                // sin(psi) = -cos(omega)
    const T f4 = 1 + g.b4 * u;
    if (!(f4 > 0)) continue;  // theta' vanishes there too: not reached by a solved state
    const T cos_th = 2 * sw * sqrt(d2) * g.cos_phi - u * g.sin_phi;
    const T wt = q.w[i] / sqrt(d2 * f4);
    sum_ds += wt;
    sum_dz -= wt * (1 + cN * u) * cos_th;
  }
  const T len = fabs(h) * f.scale;
  ds = sum_ds * len;
  dz = sum_dz * len;
}

// Adaptive Gauss-Legendre in chi, in two stages per interval: the 8-point value is accepted when
// the 6-point rule agrees with it to tol, else the 16-point value when the 12-point rule does, else
// the interval is halved (the lower rule of a pair bounds the error of the higher one, as in
// height_adaptive). The first pair settles the short pieces next to a turning angle that most
// non-monotone states have (in chi the integrand is smooth there); the second, near-separatrix
// pieces whose integrand peaks at chi = +-pi/2 with a width of order k'.
template <class T>
inline bool height_adaptive_chi(const height_segment<T>& g, const libration_frame<T>& f, T x0, T x1, T tol,
                                int depth, int& budget, T& ds, T& dz) {
  using std::fabs;
  T ds_hi, dz_hi, ds_lo, dz_lo;
  height_gl_chi<8>(g, f, x0, x1, ds_hi, dz_hi);
  height_gl_chi<6>(g, f, x0, x1, ds_lo, dz_lo);
  bool agree = fabs(ds_hi - ds_lo) <= tol && fabs(dz_hi - dz_lo) <= tol;
  if (!agree) {
    height_gl_chi<16>(g, f, x0, x1, ds_hi, dz_hi);
    height_gl_chi<12>(g, f, x0, x1, ds_lo, dz_lo);
    agree = fabs(ds_hi - ds_lo) <= tol && fabs(dz_hi - dz_lo) <= tol;
  }
  --budget;
  if (agree || depth >= 30 || budget <= 0) {
    ds += ds_hi;
    dz += dz_hi;
    return agree;
  }
  const T xm = x0 + (x1 - x0) / 2;
  const bool ok_l = height_adaptive_chi(g, f, x0, xm, tol, depth + 1, budget, ds, dz);
  const bool ok_r = height_adaptive_chi(g, f, xm, x1, tol, depth + 1, budget, ds, dz);
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
  // z can only turn where dz/ds = -(1 + T/EA) cos(theta) changes sign: at theta = pi/2 + j pi, and
  // where the stretch 1 + c N sin(theta - phi) vanishes (a compression of EA or more; c N > 1):
  // theta = phi - asin(1/(c N)) + 2 j pi and phi + pi + asin(1/(c N)) + 2 j pi. With a positive
  // stretch only the crossings where z turns from falling to rising are candidates for its
  // minimum: theta rising through pi/2 (mod 2 pi) or falling through -pi/2 (mod 2 pi); at the
  // others z has a maximum and the piece is not split there (its integrand is smooth across).
  const bool stretch_zeros = g.c * g.N > 1;
  const T w0 = stretch_zeros ? std::asin(1 / (g.c * g.N)) : T(0);
  auto next_split = [&](T x, bool up) {  // the nearest split point strictly beyond x
    auto member = [&](T offset, T period) {
      T c = up ? offset + period * (floor((x - offset) / period) + 1)
               : offset + period * (ceil((x - offset) / period) - 1);
      if (up ? !(c > x) : !(c < x)) c += up ? period : -period;  // x itself a member, to rounding
      return c;
    };
    T best = stretch_zeros ? member(pi / 2, pi) : member(up ? pi / 2 : -pi / 2, two_pi);
    if (stretch_zeros) {
      for (const T o : {g.phi - w0, g.phi + pi + w0}) {
        const T c = member(o, two_pi);
        if (up ? c < best : c > best) best = c;
      }
    }
    return best;
  };
  const bool libration = g.up < 1;
  const libration_frame<T> lf = libration ? make_libration_frame(g) : libration_frame<T>{};
  // On a libration the path is integrated in chi, which runs on through a turning angle (chi =
  // +-pi/2; theta turns back, chi does not: sin(chi) retraces itself), so the pieces on either
  // side of a turning point are one interval of chi: [cx0, cx1], open until a split point (a
  // candidate for the minimum of z) or the segment's end. A turning point is no such candidate
  // (theta does not cross +-pi/2 there).
  auto advance = [&](bool done, T ds, T dz) {  // one integrated interval: s, z at its end
    if (!done) ok = false;
    s += ds;
    z += dz;
    visit(s, z);
  };
  bool open = false;
  T cx0 = 0, cx1 = 0;
  auto flush = [&]() {
    if (!open) return;
    T ds = 0, dz = 0;
    int budget = 1000;
    const bool done = height_adaptive_chi(g, lf, cx0, cx1, tol, 0, budget, ds, dz);
    advance(done, ds, dz);
    open = false;
  };
  auto piece = [&](T a, T b, bool turn_a, bool turn_b, bool upper_a, bool upper_b) {
    auto sub = [&](T from, T to) {
      if (from == to) return;
      const bool ta = turn_a && from == a, tb = turn_b && to == b;
      if (libration) {
        const T mid = from + (to - from) / 2;
        const T xa = ta ? (upper_a ? pi / 2 : -pi / 2) : libration_chi(g, from, mid);
        const T xb = tb ? (upper_b ? pi / 2 : -pi / 2) : libration_chi(g, to, mid);
        if (open) {
          // Continues from the turning point that ended the open interval (xa = +-pi/2 there):
          // chi goes on in the interval's direction by this piece's extent.
          cx1 += (cx1 >= cx0 ? T(1) : T(-1)) * fabs(xb - xa);
        } else {
          cx0 = xa;
          cx1 = xb;
          open = true;
        }
        return;
      }
      T ds = 0, dz = 0;
      int budget = 1000;
      const bool done = height_adaptive(g, from, to, T(0), tol, 0, budget, ds, dz);
      advance(done, ds, dz);
    };
    const bool up = a < b;
    T cur = a;
    for (T c = next_split(a, up); up ? c < b : c > b; c = next_split(c, up)) {
      sub(cur, c);
      flush();
      cur = c;
    }
    sub(cur, b);
  };
  bool upper = false;  // the turning point just passed is the window's top (theta = th_max)
  for (int i = 0; i < turning; ++i) {
    const T next = dir > 0 ? th_max : th_min;
    if ((next - th) * dir < -tol) return false;
    piece(th, next, i > 0, true, upper, dir > 0);
    upper = dir > 0;
    th = next;
    dir = -dir;
  }
  if ((theta_e - th) * dir < -1e-9) return false;  // the last piece runs against theta'
  piece(th, theta_e, turning > 0, false, upper, false);
  flush();
  return ok;
}

// One segment's walk, relative to its start: its length, the change of z, and its lowest point.
template <class T>
struct segment_walk {
  bool ok = false;
  T length = 0, dz = 0, zmin = 0, smin = 0;
};

template <class T>
inline segment_walk<T> walk_segment(const height_segment<T>& g, T theta_s, T rate_s, T theta_e, int turning, T tol) {
  segment_walk<T> w;
  T s = 0, z = 0;
  w.ok = height_walk(g, theta_s, rate_s, theta_e, turning, tol, s, z, [&](T ss, T zz) {
    if (zz < w.zmin) {
      w.zmin = zz;
      w.smin = ss;
    }
  });
  w.length = s;
  w.dz = z;
  return w;
}

// A libration whose turning angle lies eta short of the saddle psi = pi/2: up = cos(eta) and, from
// R(up) = 0, M = N up (1 + c N up/2), f3 = N (1 + c N up/2)(up - u), f4 = 1 + c N u/(2 + c N up).
// psi_top = pi/2 - eta is exact to rounding of pi/2, where asin(up) would lose half the digits
// of eta, and cos(psi_top) = sin(eta) keeps all of them.
template <class T>
inline height_segment<T> height_segment_near_saddle(T EI, T c, T N, T phi, T eta) {
  using std::cos;
  const T up = cos(eta);
  const T h = 1 + c * N * up / 2;
  const T psi_top = seta_pi<T>() / 2 - eta;
  return height_segment<T>{EI, c, N * up * h, N, phi, up, -N * h, c * N / (2 * h), psi_top, std::sin(eta),
                           std::sin(phi), std::cos(phi)};
}

// Near a separatrix (1 - up small) a libration's length grows like log(1/eta)/omega, and the
// constant M of the first integral, formed from the rates at the segment's end, carries a rounding
// error of order eps (EI theta'^2 + N) that is not small against N (1 - up): the walk's length then
// misses the segment's. The length pins the state instead: eta is solved (secant in log eta) so
// that the walk reproduces `length` (to len_tol/100, or to len_tol where eta's rounding stops the
// secant), and the result is accepted only when the M it implies agrees with the one formed from
// the state to m_tol (the state is then the given one within its own accuracy). False when the
// walk fails or the secant does not converge.
template <class T>
inline bool calibrate_near_saddle(const height_segment<T>& g0, T theta_s, T rate_s, T theta_e, int turning,
                                  T length, T tol, T len_tol, T m_tol, segment_walk<T>& w) {
  using std::exp; using std::fabs; using std::log; using std::sqrt; using std::asin;
  if (!(g0.up < 1) || turning < 1 || !(g0.up > 0)) return false;
  auto miss = [&](T x, segment_walk<T>& out) {
    out = walk_segment(height_segment_near_saddle(g0.EI, g0.c, g0.N, g0.phi, exp(x)), theta_s, rate_s, theta_e,
                       turning, tol);
    return out.ok ? out.length - length : std::numeric_limits<T>::quiet_NaN();
  };
  T x0 = log(2 * asin(sqrt((1 - g0.up) / 2)));  // eta of the given state
  segment_walk<T> w1;
  T f0 = miss(x0, w1);
  T x1 = x0 + (f0 > 0 ? T(0.05) : T(-0.05));  // longer than the segment: move away from the saddle
  T f1 = miss(x1, w1);
  for (int it = 0; it < 40 && f0 == f0 && f1 == f1; ++it) {
    // Converged to len_tol/100, or to len_tol where the secant can go no further (eta's rounding).
    if (fabs(f1) <= len_tol / 100 || ((f1 == f0 || x1 == x0) && fabs(f1) <= len_tol)) {
      const height_segment<T> g = height_segment_near_saddle(g0.EI, g0.c, g0.N, g0.phi, exp(x1));
      if (!(fabs(g.M - g0.M) <= m_tol)) return false;
      w = w1;
      return true;
    }
    if (f1 == f0) return false;
    T x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    if (x2 > x1 + 2) x2 = x1 + 2;  // log eta: steps of at most e^2 in eta
    if (x2 < x1 - 2) x2 = x1 - 2;
    if (!(x2 < T(0.45))) x2 = T(0.45);  // eta < pi/2
    x0 = x1;
    f0 = f1;
    x1 = x2;
    f1 = miss(x1, w1);
  }
  return false;
}

// A libration so close to its separatrix that neither the state's M nor eta resolves it (a
// segment tens of elastic lengths long, gecko/seta/detail/separatrix_limit.hpp): at each turning
// point it dwells next to the saddle, straight and aligned with the force, for a time that grows
// like log(1/eta) and is the same at every turning point of the path (the orbit is symmetric about
// each). The segment is then the libration at eta_p (resolved: its shape differs from the exact
// one by O(eta_p^2) relative) walked turning point to turning point, with the length it misses,
// length - L(eta_p), shared equally among the turning points as straight pieces along the force
// direction (dz/ds = -(1 + c N) cos(phi + pi/2) there). Valid where L(eta_p) < length: the exact
// eta is then smaller still. False otherwise, or where a piece's walk fails.
template <class T>
inline bool walk_past_saddle(const height_segment<T>& g0, T theta_s, T rate_s, T theta_e, int turning, T length,
                             T tol, segment_walk<T>& w) {
  using std::floor; using std::sqrt;
  if (turning < 1 || !(g0.N > 0)) return false;
  const T pi = seta_pi<T>();
  const T delta_p = std::ldexp(std::fabs(g0.M) + g0.N, separatrix_resolved_exponent);
  const T eta_p = sqrt(2 * delta_p / (g0.N * (1 + g0.c * g0.N)));
  const height_segment<T> g = height_segment_near_saddle(g0.EI, g0.c, g0.N, g0.phi, eta_p);
  const T k = floor((theta_s - g.phi + pi / 2) / (2 * pi) + T(0.5));
  const T th_max = g.phi + g.psi_top + k * 2 * pi, th_min = g.phi - pi - g.psi_top + k * 2 * pi;
  // The pieces between turning points, each walked on its own (none has a turning point inside).
  // At most this many turning points (the plans count up to 8): a path with more is refused,
  // and its state's admissibility stays undecided.
  constexpr int max_turning = 6;
  if (turning > max_turning) return false;
  T ends[max_turning];
  T dir = rate_s > 0 ? T(1) : (rate_s < 0 ? T(-1) : (std::fabs(theta_s - th_max) <= std::fabs(theta_s - th_min) ? T(-1) : T(1)));
  for (int i = 0; i < turning; ++i) {
    ends[i] = dir > 0 ? th_max : th_min;
    dir = -dir;
  }
  segment_walk<T> pieces[max_turning + 1];
  T walked = 0;
  for (int i = 0; i <= turning; ++i) {
    const T a = i == 0 ? theta_s : ends[i - 1], b = i == turning ? theta_e : ends[i];
    pieces[i] = walk_segment(g, a, i == 0 ? rate_s : T(0), b, 0, tol);
    if (!pieces[i].ok) return false;
    walked += pieces[i].length;
  }
  if (!(walked < length)) return false;
  const T dwell = (length - walked) / turning;
  const T slope = (1 + g.c * g.N) * g.sin_phi;
  T s = 0, z = 0;
  w = segment_walk<T>();
  auto lowest = [&](T zz, T ss) {
    if (zz < w.zmin) {
      w.zmin = zz;
      w.smin = ss;
    }
  };
  for (int i = 0; i <= turning; ++i) {
    lowest(z + pieces[i].zmin, s + pieces[i].smin);
    z += pieces[i].dz;
    s += pieces[i].length;
    if (i < turning) {  // the straight dwell: linear in s, lowest at an end
      z += slope * dwell;
      s += dwell;
      lowest(z, s);
    }
  }
  w.ok = true;
  w.length = s;
  w.dz = z;
  return true;
}

// theta's range [lo, hi] on one segment, with u = sin(theta - phi) at both ends (the ends of the
// range are segment ends or turning angles, where u is known without trigonometry).
template <class T>
struct theta_range {
  T lo, hi, u_lo, u_hi;
  void track(T th, T u) {
    if (th < lo) {
      lo = th;
      u_lo = u;
    }
    if (th > hi) {
      hi = th;
      u_hi = u;
    }
  }
};

// The range of the axial force T = N sin(theta - phi) over theta's range on one segment: +-N
// where the range contains psi = +-pi/2 (mod 2 pi), else the ends.
template <class T>
inline void segment_force_range(T N, T phi, const theta_range<T>& r, T& t_min, T& t_max) {
  using std::ceil;
  const T pi = seta_pi<T>();
  const T a = N * r.u_lo, b = N * r.u_hi;
  t_min = a < b ? a : b;
  t_max = a < b ? b : a;
  if (ceil((r.lo - phi - pi / 2) / (2 * pi)) * 2 * pi + pi / 2 + phi <= r.hi) t_max = N;
  if (ceil((r.lo - phi + pi / 2) / (2 * pi)) * 2 * pi - pi / 2 + phi <= r.hi) t_min = -N;
}

// The range of T/EA over the seta, one segment at a time: lo and hi start at 0 (for the largest
// |T|/EA), least is the lowest T/EA itself (0 on an inextensible segment, whose stretch is 1).
template <class T>
struct strain_extremes {
  T lo = 0, hi = 0;
  T least = std::numeric_limits<T>::infinity();
  // One segment with 1/EA = c and T between t_lo and t_hi.
  void add(T c, T t_lo, T t_hi) {
    if (!(c > 0)) {
      if (least > 0) least = 0;
      return;
    }
    if (c * t_lo < lo) lo = c * t_lo;
    if (c * t_hi > hi) hi = c * t_hi;
    if (c * t_lo < least) least = c * t_lo;
  }
};

// The strain part of the verdict, from the range of T/EA over the seta: the largest |T|/EA, the
// lowest stretch 1 + T/EA, and whether either rules the state out.
template <class T>
inline void set_strain_verdict(admissibility_result<T>& r, const strain_extremes<T>& e, T strain_limit) {
  r.max_axial_strain = e.hi > -e.lo ? e.hi : -e.lo;
  r.min_stretch = 1 + e.least;
  r.strain_exceeded = r.max_axial_strain > strain_limit;
  r.inverted = r.min_stretch <= 0;  // NaN (theta's range unknown): not decided here
}

// The verdict from a known lowest height r.min_z (NaN: not known) and the range of T/EA.
template <class T>
inline admissibility_result<T> finish_admissibility(admissibility_result<T> r, const strain_extremes<T>& e, T z_tol,
                                                    T strain_limit) {
  set_strain_verdict(r, e, strain_limit);
  r.crosses_substrate = r.min_z < -z_tol;
  r.admissible = !r.crosses_substrate && !r.strain_exceeded && !r.inverted && r.min_z == r.min_z;
  return r;
}

// What both paths of the check read from a pose (lengths, the edge, the angles at the joint).
template <class T>
struct pose_frame {
  T L, free2, a_edge;  // l1 + l2, the free spatula length, the edge's s
  T Fn, Ft, beta, th_j1;  // th_j1 = theta1(l1) = beta - alpha2
  int n1, n2;             // turning points of the beam and of the spatula
  T z_tol;                // heights below -z_tol cross the substrate
};

template <class T>
inline pose_frame<T> make_pose_frame(const seta_params<T>& d, const seta_pose<T>& st) {
  pose_frame<T> f;
  f.L = d.l1 + d.l2;
  f.free2 = st.free_spatula_length == st.free_spatula_length ? st.free_spatula_length : d.l2;
  f.a_edge = d.l1 + f.free2;
  f.Fn = st.Fn;
  f.Ft = st.Ft;
  f.beta = st.theta_joint;
  f.th_j1 = f.beta - d.alpha2;
  f.n1 = st.turning_points_beam;
  f.n2 = st.turning_points_spatula;
  f.z_tol = T(1e-12) * f.L;
  return f;
}

// A segment's first-integral constant (eq (8)), M = EI rate^2/2 + N u + c N^2 u^2/2 at a point with
// u = sin(theta - phi), and in *scale the sum of its terms' magnitudes (N included), the scale of
// its rounding.
template <class T>
inline T first_integral_constant(T EI, T c, T N, T rate, T u, T& scale) {
  using std::fabs;
  const T bend = EI * rate * rate / 2, axial = c * N * N * u * u / 2;
  scale = bend + N * fabs(u) + axial + N;
  return bend + N * u + axial;
}

// The general path of admissibility_imp (turning points, or theta leaving [-pi/2, pi/2]): kept
// apart so that admissibility_imp, the common case (theta monotone and within [-pi/2, pi/2]),
// stays a small function. f: the pose's frame (forces and beta not NaN). strain_only: the strain
// and stretch alone (theta's ranges, no quadrature of the height; min_z stays NaN).
template <class T>
inline admissibility_result<T> admissibility_general(const seta_params<T>& d, const seta_pose<T>& st,
                                                     const pose_frame<T>& f, T strain_limit,
                                                     bool strain_only = false) {
  using std::atan2; using std::cos; using std::fabs; using std::sin; using std::sqrt;
  admissibility_result<T> r;
  const T half_pi = seta_pi<T>() / 2;
  const T L = f.L, free2 = f.free2, a_edge = f.a_edge, Fn = f.Fn, Ft = f.Ft, beta = f.beta, th_j1 = f.th_j1;
  const int n1 = f.n1, n2 = f.n2;
  auto finish = [&](const strain_extremes<T>& e) { return finish_admissibility(r, e, f.z_tol, strain_limit); };
  // General path: quadrature of z over the monotone pieces. The sines and cosines of the angles
  // relative to the force direction phi come from those of beta, alpha1, alpha2 and phi (sin phi =
  // Fn/N, cos phi = Ft/N) by angle addition: one sincos and one atan2 (phi itself, for the 2 pi
  // windows of the turning angles) instead of one call per angle.
  const T N = sqrt(Fn * Fn + Ft * Ft);
  if (!(N > 0)) return r;
  const T phi = atan2(Fn, Ft);
  const T sphi = Fn / N, cphi = Ft / N;
  const T sb = sin(beta), cb = cos(beta);
  const T sj = sb * d.co2 - cb * d.s2, cj = cb * d.co2 + sb * d.s2;  // of theta1(l1) = beta - alpha2
  const T ub = sb * cphi - cb * sphi;                                // sin(beta - phi)
  const T v = sj * cphi - cj * sphi;                                 // sin(theta1(l1) - phi)
  const T u_base = d.s1 * cphi - d.co1 * sphi;                       // sin(alpha1 - phi)
  const T p = st.theta_rate_joint, q = st.theta_rate_base;
  // First integrals (eq (8)): M2 from the joint state, M1 from the beam's end at the joint
  // (EI1 theta1'(l1) = EI2 theta2'(l1), eq (4)), each with the sum of its terms' magnitudes (N
  // included), the scale of its rounding.
  T scale1, scale2;
  const T M2 = first_integral_constant(d.EI2, d.c2, N, p, ub, scale2);
  const T M1 = first_integral_constant(d.EI1, d.c1, N, d.EI2 / d.EI1 * p, v, scale1);
  // The turning angles (an asin each) only where theta turns; the walks below set the others.
  auto g1 = make_height_segment(d.EI1, d.c1, M1, N, phi, sphi, cphi, n1 > 0);
  auto g2 = make_height_segment(d.EI2, d.c2, M2, N, phi, sphi, cphi, n2 > 0);
  // theta's range on each segment: its ends and the turning angles reached (n >= 2 turning points
  // reach both ends of the libration window, one the one theta' runs into first); u = up at both
  // turning angles (psi_top and -pi - psi_top), cos(phi) at the contact edge (theta = pi/2).
  theta_range<T> r1{d.alpha1, d.alpha1, u_base, u_base}, r2{beta, beta, ub, ub};
  r1.track(th_j1, v);
  r2.track(half_pi, cphi);
  // A segment whose M, formed from the state's rates, puts it at or past its separatrix (up >= 1 in
  // rounding) while the solver counts turning points on it lies on the separatrix within the
  // state's accuracy: its turning angle is the saddle (psi_top = pi/2, set_turning_angle), which it
  // approaches as closely as a segment tens of elastic lengths long does (walk_past_saddle). Leaving
  // the angle out instead made the range that of the ends, and the verdict flip between 0 and
  // -0.4 l1 with the state's last bits (design 9557 of the 10,000-design re-run; tests/seta/
  // admissibility.cpp). Without a first integral (up NaN) the range is unknown: the walk decides,
  // and fails.
  auto turning_range = [&](const height_segment<T>& g, T th_s, T rate_s, int n, theta_range<T>& rg) {
    using std::floor;
    if (n <= 0) return;
    if (!(g.up == g.up)) {
      rg.track(-std::numeric_limits<T>::infinity(), g.up);
      rg.track(std::numeric_limits<T>::infinity(), g.up);
      return;
    }
    const T up = g.up < 1 ? g.up : T(1);
    const T pi = seta_pi<T>();
    const T k = floor((th_s - g.phi + pi / 2) / (2 * pi) + T(0.5));
    const T tmax = g.phi + g.psi_top + k * 2 * pi, tmin = g.phi - pi - g.psi_top + k * 2 * pi;
    if (n >= 2) {
      rg.track(tmax, up);
      rg.track(tmin, up);
    } else {
      rg.track(rate_s > 0 ? tmax : tmin, up);
    }
  };
  turning_range(g1, d.alpha1, q, n1, r1);
  turning_range(g2, beta, p, n2, r2);
  const T lo1 = r1.lo, hi1 = r1.hi, lo2 = r2.lo, hi2 = r2.hi;
  // The axial strain T/EA over both segments: its largest magnitude is reported; its lowest value
  // (the largest compression) decides whether the stretch 1 + T/EA stays positive.
  strain_extremes<T> e;
  auto strain_range = [&](T c, const theta_range<T>& rg) {
    T a = 0, b = 0;
    if (c > 0) segment_force_range(N, phi, rg, a, b);
    e.add(c, a, b);
  };
  // A segment whose theta stays in [-pi/2, pi/2] with a positive stretch has z decreasing along it.
  strain_range(d.c1, r1);
  const bool beam_monotone = e.lo > -1 && lo1 >= -half_pi && hi1 <= half_pi;
  strain_range(d.c2, r2);
  if (strain_only) {
    set_strain_verdict(r, e, strain_limit);
    return r;
  }
  if (beam_monotone && e.lo > -1 && lo2 >= -half_pi && hi2 <= half_pi) {  // the spatula too
    // Turning points, but theta stays within [-pi/2, pi/2]: z is monotone all the same.
    r.min_z = 0;
    r.where = a_edge;
    r.exact_fast_path = true;
    return finish(e);
  }
  const T tol = T(1e-13) * L;
  const T len_tol = T(1e-9) * L;
  // The M of each segment to the accuracy of the state: its terms' magnitudes times 1e-10.
  const T m_tol1 = T(1e-10) * scale1, m_tol2 = T(1e-10) * scale2;
  auto walk = [&](const height_segment<T>& g, T th_s, T rate_s, T th_e, int n, T length, T m_tol) {
    segment_walk<T> w = walk_segment(g, th_s, rate_s, th_e, n, tol);
    if (w.ok && fabs(w.length - length) <= len_tol) return w;
    segment_walk<T> c;
    if (calibrate_near_saddle(g, th_s, rate_s, th_e, n, length, tol, len_tol, m_tol, c)) return c;
    if (walk_past_saddle(g, th_s, rate_s, th_e, n, length, tol, c)) return c;
    w.ok = false;
    return w;
  };
  // A monotone beam's lowest point is the joint, where the spatula's walk starts, so it is not
  // walked (its record puts the origin of z at the joint).
  segment_walk<T> w1;
  if (beam_monotone) {
    w1.ok = true;
    w1.length = d.l1;
  } else {
    set_turning_angle(g1);
    w1 = walk(g1, d.alpha1, q, th_j1, n1, d.l1, m_tol1);
  }
  set_turning_angle(g2);
  const segment_walk<T> w2 = walk(g2, beta, p, half_pi, n2, free2, m_tol2);
  const bool ok = w1.ok && w2.ok;
  if (!ok) {
    // The decomposition did not close: no verdict on z (the strain's is known).
    set_strain_verdict(r, e, strain_limit);
    return r;
  }
  // The base (or the joint, for a beam not walked) at z = 0, then shift so that the contact edge is
  // at z = 0.
  T zmin = 0, smin = beam_monotone ? d.l1 : T(0);
  if (w1.zmin < zmin) {
    zmin = w1.zmin;
    smin = w1.smin;
  }
  if (w1.dz + w2.zmin < zmin) {
    zmin = w1.dz + w2.zmin;
    smin = w1.length + w2.smin;
  }
  const T z = w1.dz + w2.dz;
  r.min_z = zmin - z;
  r.where = smin;
  if (!(r.min_z < 0)) {  // the edge itself is the lowest point
    r.min_z = 0;
    r.where = a_edge;
  }
  return finish(e);
}

// The range [lo, hi] of the axial force T(theta) = Ft sin(theta) - Fn cos(theta) over an interval
// [a, b] shorter than pi, from T and T' = Ft cos(theta) + Fn sin(theta) at its ends (T = N sin(psi),
// T' = N cos(psi)): an interior maximum N where T' falls through 0, a minimum -N where it rises.
template <class T>
inline void axial_force_range(T Ta, T da, T Tb, T db, T N, T& lo, T& hi) {
  lo = Ta < Tb ? Ta : Tb;
  hi = Ta < Tb ? Tb : Ta;
  if (da > 0 && db < 0) hi = N;
  if (da < 0 && db > 0) lo = -N;
}

// An inextensible beam (c1 = 0) with turning points whose ends lie within [-pi/2, pi/2] stays
// inside when its first integral (eq (8)) bars its path from theta = +-pi/2:
// 1/2 EI1 theta'^2 = R(theta) = M1 - T(theta), with the axial force T = Ft sin(theta) -
// Fn cos(theta) (= N sin(theta - phi)), and theta cannot pass where T > M1. theta is continuous
// along the beam and monotone between turning points: with one turning point and theta'(0) > 0 it
// rises from alpha1 to its turning angle and falls to theta1(l1), so it leaves [-pi/2, pi/2] only
// if it rises through pi/2, which a point of [alpha1, pi/2] with T > M1 bars (theta'(0) < 0: a
// point of [-pi/2, alpha1]); with two or more turning points both are needed. The largest T over
// an interval shorter than pi comes from T and T' = Ft cos + Fn sin at its ends: N where T' falls
// through 0 inside, else the larger end value. Then z is monotone along the beam (its stretch is
// 1): no atan2, asin or quadrature is needed. M1 is formed at the base from theta1'(0); the test
// demands a margin of 1e-9 of the terms' magnitudes (more than the state's own accuracy), so a
// state next to the boundary takes the general path.
template <class T>
inline bool beam_first_integral_bars_level(const seta_params<T>& d, const seta_pose<T>& st, const pose_frame<T>& f,
                                           T N) {
  using std::fabs;
  const T Ft = f.Ft, Fn = f.Fn, q = st.theta_rate_base;
  const T bend = d.EI1 * q * q / 2;
  const T t_base = Ft * d.s1 - Fn * d.co1, slope_base = Ft * d.co1 + Fn * d.s1;  // T, T' at alpha1
  const T M1 = bend + t_base;
  const T margin = T(1e-9) * (bend + fabs(t_base) + N);
  // [alpha1, pi/2]: T(pi/2) = Ft, T'(pi/2) = Fn; [-pi/2, alpha1]: T(-pi/2) = -Ft, T'(-pi/2) = -Fn.
  T lo, top, bottom;
  axial_force_range(t_base, slope_base, Ft, Fn, N, lo, top);
  axial_force_range(-Ft, -Fn, t_base, slope_base, N, lo, bottom);
  const bool bars_top = top - M1 > margin, bars_bottom = bottom - M1 > margin;
  if (f.n1 == 1) return q > 0 ? bars_top : (q < 0 ? bars_bottom : false);
  return bars_top && bars_bottom;
}

// A spatula with one turning point and beta <= pi/2 stays inside [-pi/2, pi/2] when its first
// integral (eq (8)) bars theta = -pi/2 on its way down. With one turning point theta'(l1) < 0: theta
// falls from beta to its turning angle theta_min and rises into the contact edge at pi/2 (where
// theta' > 0, eq (3)), so its range is [theta_min, pi/2]. With the axial force T = Ft sin(theta) -
// Fn cos(theta), 1/2 EI2 theta'^2 = R = M2 - T - c2 T^2/2 is negative where T exceeds
// T+ = 2 M2 / (1 + sqrt(1 + 2 c2 M2)) (= N u+, gecko/seta/elastica_segment.hpp), so a point of
// [-pi/2, beta] with T > T+ stops the fall before -pi/2 (R(beta) = EI2 theta'(l1)^2/2 > 0). Then
// T's range over [theta_min, pi/2], for the strain, follows from its ends without the turning angle
// itself: T = T+ and T' = -N cos(psi_top) <= 0 at theta_min (T falls from T+ as theta rises from
// there), Ft and Fn at pi/2. M2 is formed from the joint's rate as on the general path; the test
// demands a margin of 1e-9 of its terms' magnitudes, so a state next to the boundary takes the
// general path. sb, cb: sin and cos of beta. False: not shown inside (lo, hi unset).
template <class T>
inline bool spatula_first_integral_bars_level(const seta_params<T>& d, const seta_pose<T>& st, const pose_frame<T>& f,
                                              T N, T sb, T cb, T& lo, T& hi) {
  using std::sqrt;
  const T Ft = f.Ft, Fn = f.Fn, p = st.theta_rate_joint;
  if (f.n2 != 1 || !(p < 0) || !(N > 0) || !(f.beta <= seta_pi<T>() / 2)) return false;
  const T t_beta = Ft * sb - Fn * cb, slope_beta = Ft * cb + Fn * sb;  // T, T' at beta
  T scale;
  const T M2 = first_integral_constant(d.EI2, d.c2, N, p, t_beta / N, scale);  // u = sin(beta - phi)
  const T margin = T(1e-9) * scale;
  const T root = 1 + 2 * d.c2 * M2;
  if (!(root > 0)) return false;
  const T t_plus = 2 * M2 / (1 + sqrt(root));
  const T up = t_plus / N;
  if (!(up < 1 && up > -1)) return false;  // no libration: one turning point is not this orbit
  // [-pi/2, beta]: T(-pi/2) = -Ft, T'(-pi/2) = -Fn.
  T low, top;
  axial_force_range(-Ft, -Fn, t_beta, slope_beta, N, low, top);
  if (!(top - t_plus > margin)) return false;
  axial_force_range(t_plus, -N * sqrt((1 - up) * (1 + up)), Ft, Fn, N, lo, hi);
  return true;
}

// The check on design parameters d (1/EA as c1, c2) and a pose; strain_limit: +inf for none.
// strain_only: the strain and the stretch alone (max_axial_strain, min_stretch, strain_exceeded,
// inverted), without the height: what the followed line checks at each node (line_trace.hpp).
template <class T>
inline admissibility_result<T> admissibility_imp(const seta_params<T>& d, const seta_pose<T>& st, T strain_limit,
                                                 bool strain_only = false) {
  using std::cos; using std::sin; using std::sqrt;
  admissibility_result<T> r;
  const pose_frame<T> f = make_pose_frame(d, st);
  if (!(f.Fn == f.Fn) || !(f.Ft == f.Ft) || !(f.beta == f.beta)) return r;
  const T half_pi = seta_pi<T>() / 2;
  const T Fn = f.Fn, Ft = f.Ft, beta = f.beta, th_j1 = f.th_j1;
  auto finish = [&](const strain_extremes<T>& e) { return finish_admissibility(r, e, f.z_tol, strain_limit); };
  // theta's range on each segment is that of its ends when it has no turning point; on an
  // inextensible beam with turning points, the ends bound it too where the first integral forbids
  // theta = +-pi/2 (beam_first_integral_bars_level): then the beam stays strictly between.
  // A spatula with one turning point is inside where its first integral bars -pi/2
  // (spatula_first_integral_bars_level); more turning points take it past pi/2 (a libration
  // window that holds the edge's pi/2 inside, left and re-entered).
  const bool spatula_candidate = f.n2 == 0 || (f.n2 == 1 && st.theta_rate_joint < 0);
  const T N = sqrt(Fn * Fn + Ft * Ft);
  bool beam_by_ends = f.n1 == 0;
  if (f.n1 > 0 && spatula_candidate && !(d.c1 > 0)) beam_by_ends = beam_first_integral_bars_level(d, st, f, N);
  if (beam_by_ends && spatula_candidate) {
    const T lo1 = d.alpha1 < th_j1 ? d.alpha1 : th_j1, hi1 = d.alpha1 < th_j1 ? th_j1 : d.alpha1;
    const T lo2 = beta < half_pi ? beta : half_pi, hi2 = beta < half_pi ? half_pi : beta;
    if (lo1 >= -half_pi && hi1 <= half_pi && lo2 >= -half_pi && hi2 <= half_pi) {
      // T's range from T and T' at the ends (the ranges are shorter than pi): axial_force_range.
      strain_extremes<T> e;  // T/EA over the segments
      auto add_range = [&](T c, T lo, T hi) { e.add(c, lo, hi); };
      auto seg_range = [&](T c, T th_a, T sa, T ca, T th_b, T sb, T cb) {
        if (!(c > 0)) {
          e.add(c, T(0), T(0));
          return;
        }
        if (th_b < th_a) {
          std::swap(sa, sb);
          std::swap(ca, cb);
        }
        T lo, hi;
        axial_force_range(Ft * sa - Fn * ca, Ft * ca + Fn * sa, Ft * sb - Fn * cb, Ft * cb + Fn * sb, N, lo, hi);
        add_range(c, lo, hi);
      };
      T sb = 0, cb = 0;
      if (d.c1 > 0 || d.c2 > 0 || f.n2 > 0) {
        sb = sin(beta);
        cb = cos(beta);
      }
      T lo_s = 0, hi_s = 0;  // T's range on a turning spatula
      if (f.n2 > 0 && !spatula_first_integral_bars_level(d, st, f, N, sb, cb, lo_s, hi_s))
        return admissibility_general(d, st, f, strain_limit, strain_only);
      if (d.c1 > 0) {
        const T sj = sb * d.co2 - cb * d.s2, cj = cb * d.co2 + sb * d.s2;
        seg_range(d.c1, d.alpha1, d.s1, d.co1, th_j1, sj, cj);
      } else {
        e.add(d.c1, T(0), T(0));
      }
      if (f.n2 == 0) seg_range(d.c2, beta, sb, cb, half_pi, T(1), T(0));
      else add_range(d.c2, lo_s, hi_s);
      // z decreases along s only while the stretch 1 + T/EA is positive (tension, T > 0, never
      // stops it; a compression of EA or more would).
      if (e.lo > -1) {
        r.min_z = 0;
        r.where = f.a_edge;
        r.exact_fast_path = true;
        return finish(e);
      }
    }
  }
  return admissibility_general(d, st, f, strain_limit, strain_only);
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
