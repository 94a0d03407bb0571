// Vector versions of the float64 kernels F(phi|m), E(phi|m) (first quadrant, m <= 1) and
// R_F(x, y, z) (no rescaling needed), for the ufunc batch loops (elliptic_simd.hpp).
//
// Included by elliptic_simd_{sse,avx2,avx512}.cpp only, each compiled with its own ISA flags and
// -ffp-contract=off, after defining GECKO_SIMD_NS (a namespace of its own, so that no inline
// function of one ISA can stand in for another's at link time) and `pack`, a wide_pack of
// elliptic_simd_pack.hpp: vd (vector of W doubles), vi (vector of W int64 masks), W, sqrt(vd),
// any(vi), as_i / as_d (bit casts).
// No standard-library function is called here for the same reason.
//
// The arithmetic is that of the scalar kernels, operation for operation (no contraction):
//   F = s R_F(c^2, Delta^2, 1), Delta^2 = c^2 + (1 - m) s^2                     (DLMF 19.25.5)
//   E = s R_F(c^2, Delta^2, 1) - (m/3) s^3 R_D(c^2, Delta^2, 1)        (m <= 0; DLMF 19.25.9)
//   E = (1-m) s R_F(c^2, Delta^2, 1) + (m(1-m)/3) s^3 R_D(c^2, 1, Delta^2) + m s c/Delta
//                                                                  (0 < m <= 1; DLMF 19.25.10)
// with Carlson's duplication (DLMF 19.26.18, 19.26.20) and the series of
// gecko/elliptic/carlson_rf.hpp and carlson_rd.hpp; F's R_F (gecko/elliptic/ellint_f.hpp) and E's
// R_F and R_D (gecko/elliptic/legendre_rf_rd.hpp) in the scaled product form from known roots.
// Lanes converge after different numbers of duplication steps: the loop runs while any lane is
// still active, and a converged lane is frozen by a blend, so it ends with exactly its own step
// count (an extra step would change its last bits and tie its result to its neighbours).
// Domain edges stay with the scalar kernels: m > 1 (double-word Delta^2, gecko/elliptic/
// edge_delta.hpp), |phi| > pi/2 (angle reduction), NaN, infinities, R_F arguments outside the
// no-rescaling window; the caller's lane_fn recomputes those lanes.

#include "gecko/elliptic/carlson_tolerance.hpp"

namespace gecko {
namespace bindings {
namespace GECKO_SIMD_NS {

using vd = pack::vd;
using vi = pack::vi;
constexpr int W = pack::W;

inline vd splat(double x) {
  vd v;
  for (int i = 0; i < W; ++i) v[i] = x;
  return v;
}
inline vi splat_i(long long x) {
  vi v;
  for (int i = 0; i < W; ++i) v[i] = x;
  return v;
}
inline vi as_i(vd x) { return pack::as_i(x); }
inline vd as_d(vi m) { return pack::as_d(m); }
inline vd select(vi mask, vd a, vd b) { return as_d((mask & as_i(a)) | (~mask & as_i(b))); }
inline vd vabs(vd x) { return as_d(as_i(x) & splat_i(0x7fffffffffffffffLL)); }
inline vd vcopysign(vd mag, vd sgn) {
  return as_d((as_i(mag) & splat_i(0x7fffffffffffffffLL)) | (as_i(sgn) & splat_i(-0x7fffffffffffffffLL - 1)));
}
inline vd vmax(vd a, vd b) { return select(a < b, b, a); }  // max_of of carlson_arguments.hpp

constexpr double tol_rf = gecko::detail::carlson_tolerance<double, 0>::rf;
constexpr double tol_rd = gecko::detail::carlson_tolerance<double, 0>::rd;
constexpr int max_steps = gecko::detail::carlson_max_steps<double>;

// sin and cos of 0 <= a <= pi/2 (gecko/elliptic/first_quadrant_sincos.hpp, same polynomials).
inline void sincos_kernel(vd x, vd& s, vd& c) {
  const vd z = x * x;
  const vd z2 = z * z;
  const vd p = (-0.16666666666666666 + z * 0.0083333333333333315) +
               z2 * ((-0.00019841269841265065 + z * 2.7557319219339167e-06) +
                     z2 * ((-2.5052106232447578e-08 + z * 1.6058531618986147e-10) +
                           z2 * -7.5866971177069183e-13));
  const vd q = (0.041666666666666664 + z * -0.0013888888888887398) +
               z2 * ((2.4801587298765689e-05 + z * -2.7557317271729793e-07) +
                     z2 * (2.0876146268403199e-09 + z * -1.1382632425521717e-11));
  s = x + (x * z) * p;
  const vd hz = 0.5 * z;
  const vd w = 1.0 - hz;
  c = w + (((1.0 - w) - hz) + z2 * q);
}

inline void first_quadrant_sincos(vd a, vd& s, vd& c) {
  constexpr double pio2_hi = 0x1.921fb54442d18p+0, pio2_lo = 0x1.1a62633145c07p-54;
  const vi reflect = a > 0.78539816339744828;
  const vd x = select(reflect, (pio2_hi - a) + pio2_lo, a);  // pi/2 - a: the difference is exact
  vd s0, c0;
  sincos_kernel(x, s0, c0);
  s = select(reflect, c0, s0);
  c = select(reflect, s0, c0);
}

// The degree-15 series of R_F minus 1 (carlson_rf_series_tail).
inline vd rf_series_tail(vd X, vd Y) {
  const vd Z = -(X + Y);
  const vd E2 = X * Y - Z * Z;
  const vd E3 = X * Y * Z;
  const vd e4 = E2 * E2;
  const vd e8 = e4 * e4;
  const vd p0 = E2 * ((-1.0 / 10 + E2 * (1.0 / 24)) + e4 * (-5.0 / 208 + E2 * (35.0 / 2176)) +
                      e8 * ((-3.0 / 256 + E2 * (231.0 / 25600)) + e4 * (-429.0 / 59392)));
  const vd p1 = (1.0 / 14 + E2 * (-3.0 / 44)) + e4 * (1.0 / 16 + E2 * (-35.0 / 608)) +
                e8 * ((315.0 / 5888 + E2 * (-77.0 / 1536)) + e4 * (3003.0 / 63488));
  const vd p2 = (3.0 / 104 + E2 * (-15.0 / 272)) + e4 * (5.0 / 64 + E2 * (-63.0 / 640)) + e8 * (3465.0 / 29696);
  const vd p3 = (5.0 / 304 + E2 * (-35.0 / 736)) + e4 * (35.0 / 384 + E2 * (-1155.0 / 7936));
  const vd p4 = 7.0 / 640 + E2 * (-315.0 / 7424);
  const vd p5 = splat(63.0 / 7936);
  const vd t2 = E3 * E3;
  const vd t4 = t2 * t2;
  return (p0 + E3 * p1) + t2 * (p2 + E3 * p3) + t4 * (p4 + E3 * p5);
}

inline vd rf_finish(vd dx, vd dy, vd A, vd f) {
  const vd s = f / A;
  const vd root = pack::sqrt(A);
  return (1.0 + rf_series_tail(dx * s, dy * s)) / root;
}

// R_D's series (carlson_rd_series): f A^(-3/2) (1 + tail).
inline vd rd_series(vd X, vd Y, vd A, vd f) {
  const vd S = X + Y;
  const vd P = X * Y;
  const vd S2 = S * S;
  const vd S4 = S2 * S2;
  const vd S8 = S4 * S4;
  const vd q0 = ((S2 * ((1.0 / 7) + S * (4.0 / 81)) + S4 * (((5.0 / 99) + S * (4.0 / 117)) + S2 * ((7.0 / 243) + S * (32.0 / 1377)))) + S8 * (((91.0 / 4617) + S * (2320.0 / 137781)) + S2 * ((737.0 / 50301) + S * (1268.0 / 98415))));
  const vd q1 = (((((-3.0 / 14) + S * (-1.0 / 6)) + S2 * ((-2.0 / 11) + S * (-20.0 / 117))) + S4 * (((-1.0 / 6) + S * (-49.0 / 306)) + S2 * ((-238.0 / 1539) + S * (-254.0 / 1701)))) + S8 * ((-1615.0 / 11178) + S * (-1837.0 / 13122)));
  const vd q2 = ((((9.0 / 88) + S * (9.0 / 52)) + S2 * ((1.0 / 4) + S * (65.0 / 204))) + S4 * (((175.0 / 456) + S * (4.0 / 9)) + S2 * ((623.0 / 1242) + S * (5.0 / 9))));
  const vd q3 = ((((-1.0 / 16) + S * (-45.0 / 272)) + S2 * ((-5.0 / 16) + S * (-215.0 / 432))) + S4 * ((-595.0 / 828) + S * (-35.0 / 36)));
  const vd q4 = (((105.0 / 2432) + S * (5.0 / 32)) + S2 * ((1085.0 / 2944) + S * (203.0 / 288)));
  const vd q5 = ((-189.0 / 5888) + S * (-189.0 / 1280));
  const vd P2 = P * P;
  const vd tail = (q0 + P * q1) + P2 * (q2 + P * q3) + (P2 * P2) * (q4 + P * q5);
  return f * (1.0 + tail) / (A * pack::sqrt(A));
}

// The degree-11 series of R_F minus 1 (carlson_rf_series11_tail), for the Legendre F.
inline vd rf_series11_tail(vd X, vd Y) {
  const vd Z = -(X + Y);
  const vd XY = X * Y;
  const vd E2 = XY - Z * Z;
  const vd E3 = XY * Z;
  const vd e2 = E2 * E2;
  const vd e4 = e2 * e2;
  const vd q0 = E2 * (((-1.0 / 10 + E2 * (1.0 / 24)) + e2 * (-5.0 / 208 + E2 * (35.0 / 2176))) + e4 * (-3.0 / 256));
  const vd q1 = ((1.0 / 14 + E2 * (-3.0 / 44)) + e2 * (1.0 / 16 + E2 * (-35.0 / 608))) + e4 * (315.0 / 5888);
  const vd q2 = (3.0 / 104 + E2 * (-15.0 / 272)) + e2 * (5.0 / 64);
  const vd q3 = 5.0 / 304 + E2 * (-35.0 / 736);
  return q0 + E3 * (q1 + E3 * (q2 + E3 * q3));
}

constexpr double tol_rf11 = gecko::detail::carlson_tolerance<double, 0>::rf11;

// s R_F(c^2, d2, 1) by the duplication in scaled product form (legendre_rf_imp of
// gecko/elliptic/ellint_f.hpp, same operations): d2 < 1/eps.
inline vd legendre_rf(vd s, vd c, vd d2) {
  const vd x = c * c;
  const vd A0 = (x + d2 + 1.0) * (1.0 / 3);
  const vd dx = A0 - x;
  const vd dy = A0 - d2;
  const vd D = vmax(vmax(vabs(dx), vabs(dy)), vabs(A0 - 1.0));
  const vd d = pack::sqrt(d2);
  const vd cd = c + d, c1 = c + 1.0, d1 = d + 1.0;
  vd X = cd * c1, Y = cd * d1, Z = c1 * d1;
  vd g = splat(2.0);
  const vd lim = D * (3 / tol_rf11);
  vi active = X + Y + Z <= lim;
  for (int step = 1; step < max_steps && pack::any(active); ++step) {
    const vd rx = pack::sqrt(X), ry = pack::sqrt(Y), rz = pack::sqrt(Z);
    const vd xy = rx + ry, xz = rx + rz, yz = ry + rz;
    X = select(active, xy * xz, X);
    Y = select(active, xy * yz, Y);
    Z = select(active, xz * yz, Z);
    g = select(active, g * 2.0, g);
    active &= X + Y + Z <= lim;
  }
  const vd A = (X + Y + Z) * (1.0 / 3);
  const vd r = 1.0 / A;
  const vd w = (s * g) / pack::sqrt(A);
  return w + w * rf_series11_tail(dx * r, dy * r);
}

// R_F without known roots (carlson_rf_imp).
inline vd rf_plain(vd x, vd y, vd z) {
  vd A = (x + y + z) * (1.0 / 3);
  const vd dx = A - x, dy = A - y, dz = A - z;
  const vd D = vmax(vmax(vabs(dx), vabs(dy)), vabs(dz));
  vd f = splat(1.0);
  vi active = f * D >= tol_rf * A;
  for (int step = 0; step < max_steps && pack::any(active); ++step) {
    const vd sx = pack::sqrt(x), sy = pack::sqrt(y), sz = pack::sqrt(z);
    const vd lambda = sx * (sy + sz) + sy * sz;
    x = select(active, (x + lambda) * 0.25, x);
    y = select(active, (y + lambda) * 0.25, y);
    z = select(active, (z + lambda) * 0.25, z);
    A = select(active, (A + lambda) * 0.25, A);
    f = select(active, f * 0.25, f);
    active &= f * D >= tol_rf * A;
  }
  return rf_finish(dx, dy, A, f);
}

// R_F and R_D of the Legendre E from known roots (legendre_rf_rd_imp of
// gecko/elliptic/legendre_rf_rd.hpp, same operations): every argument below 1/eps.
inline void legendre_rf_rd(vd x, vd y, vd z, vd rx, vd ry, vd rz, vd& rf, vd& rd) {
  vd AF = (x + y + z) * (1.0 / 3);
  vd AD = (x + y + 3.0 * z) * (1.0 / 5);
  const vd fx = AF - x, fy = AF - y;
  const vd dx = AD - x, dy = AD - y;
  const vd DF = vmax(vmax(vabs(fx), vabs(fy)), vabs(AF - z));
  const vd DD = vmax(vmax(vabs(dx), vabs(dy)), vabs(AD - z));
  const vd limF = DF * (1 / tol_rf11);
  const vd limD = DD * (1 / tol_rd);
  vd xy = rx + ry, xz = rx + rz, yz = ry + rz;
  const vd L0 = rx * yz + ry * rz;
  vd sum = 1.0 / (rz * (z + L0));
  AF = AF + L0;
  AD = AD + L0;
  vd X = xy * xz, Y = xy * yz, Z = xz * yz;
  vd g = splat(2.0);
  vi active = (AF <= limF) | (AD <= limD);
  for (int step = 1; step < max_steps && pack::any(active); ++step) {
    const vd sx = pack::sqrt(X), sy = pack::sqrt(Y), sz = pack::sqrt(Z);
    xy = sx + sy;
    xz = sx + sz;
    yz = sy + sz;
    const vd L = sx * yz + sy * sz;
    sum = select(active, sum + g / (sz * (Z + L)), sum);
    AF = select(active, AF + L, AF);
    AD = select(active, AD + L, AD);
    X = select(active, xy * xz, X);
    Y = select(active, xy * yz, Y);
    Z = select(active, xz * yz, Z);
    g = select(active, g * 2.0, g);
    active &= (AF <= limF) | (AD <= limD);
  }
  const vd q = 1.0 / (AF * AD);
  const vd rA = AD * q, rB = AF * q;
  const vd w = g / pack::sqrt(AF);
  rf = w + w * rf_series11_tail(fx * rA, fy * rA);
  rd = rd_series(dx * rB, dy * rB, AD, g) + 3.0 * sum;
}

constexpr double pio2_below = 0x1.921fb54442d18p+0;
constexpr double dbl_max = 0x1.fffffffffffffp+1023;

// Lanes that are not NaN, and their arguments with NaN replaced by `benign`: the relational
// compares (<, <=) signal invalid on NaN, and numpy would warn where the scalar kernels, which
// test isnan first, stay quiet; == is a quiet compare.
inline vi not_nan(vd x) { return x == x; }
inline vd quiet(vd x, double benign) { return select(not_nan(x), x, splat(benign)); }

// Legendre lanes on the vector path: |phi| <= pi/2 (finite), -DBL_MAX <= m <= 1 (not NaN).
inline vi legendre_ok(vd phi, vd m) {
  const vd p = quiet(phi, 0.5), q = quiet(m, 0.5);
  return not_nan(phi) & not_nan(m) & (vabs(p) <= pio2_below) & (q <= 1.0) & (q >= -dbl_max);
}

// The Legendre lanes shared by F and E: ok marks the lanes on the vector path; the others get a
// benign phi = m = 1/2 (an infinite m would keep the duplication loop going) and are recomputed by
// the scalar kernel. s, c: sin and cos of |phi|.
struct legendre_lanes {
  vd phi, m, s, c;
  // always inlined: an out-of-line call passes the four vectors through memory (measured slower for E)
  __attribute__((always_inline)) legendre_lanes(const vd* a, vi& ok) {
    ok = legendre_ok(a[0], a[1]);
    phi = select(ok, a[0], splat(0.5));
    m = select(ok, a[1], splat(0.5));
    first_quadrant_sincos(vabs(phi), s, c);
  }
};

struct kernel_f {
  static constexpr int nin = 2;
  static constexpr double pad[2] = {0.5, 0.5};
  static vd eval(const vd* a, vi& ok) {
    const legendre_lanes l(a, ok);
    const vd d2 = l.c * l.c + (1.0 - l.m) * (l.s * l.s);
    ok &= d2 < 0x1p52;  // d2 >= 1/eps (m -> -inf): the scalar kernel's unscaled duplication
    return vcopysign(legendre_rf(l.s, l.c, select(ok, d2, splat(1.0))), l.phi);
  }
};

struct kernel_e {
  static constexpr int nin = 2;
  static constexpr double pad[2] = {0.5, 0.5};
  static vd eval(const vd* a, vi& ok) {
    const legendre_lanes l(a, ok);
    const vd s = l.s, c = l.c;
    const vd c2 = c * c;
    const vd s2 = s * s;
    // Delta^2 >= 1/eps (m -> -inf) goes to the scalar kernel's unscaled duplication (ellint_e_sc);
    // such lanes continue with m = 1/2 and Delta^2 = 1. The e_pos products of lanes with m <= 0
    // use m = 1/2 as well (m (1 - m) would overflow for m < -1e154 and raise the flag, though the
    // lane takes e_neg).
    const vd d2_in = c2 + (1.0 - l.m) * s2;
    ok &= d2_in < 0x1p52;
    const vd m = select(ok, l.m, splat(0.5));
    const vd d2 = select(ok, d2_in, splat(1.0));
    const vd d = pack::sqrt(d2);
    const vi neg = m <= 0.0;
    const vd mp = select(neg, splat(0.5), m), kp = 1.0 - mp;
    // m <= 0: R(c^2, Delta^2, 1); 0 < m <= 1: R(c^2, 1, Delta^2) (the scalar kernel's orders)
    const vd one = splat(1.0);
    vd rf, rd;
    legendre_rf_rd(c2, select(neg, d2, one), select(neg, one, d2), c, select(neg, d, one), select(neg, one, d), rf, rd);
    const vd e_neg = s * (rf - (m / 3.0) * s2 * rd);
    const vd e_pos = s * (kp * rf + (mp * kp / 3.0) * s2 * rd + mp * c / d);
    return vcopysign(select(neg, e_neg, e_pos), l.phi);
  }
};

struct kernel_rf {
  static constexpr int nin = 3;
  static constexpr double pad[3] = {1.0, 2.0, 0.5};
  static vd eval(const vd* a, vi& ok) {
    const vi num = not_nan(a[0]) & not_nan(a[1]) & not_nan(a[2]);
    const vd x = quiet(a[0], 1.0), y = quiet(a[1], 1.0), z = quiet(a[2], 1.0);
    const vd big = vmax(vmax(x, y), z);
    const vi zeros = (x == 0.0) + (y == 0.0) + (z == 0.0);  // -1 per zero
    // not NaN, x, y, z >= 0, at most one zero, and the largest in the window where
    // gecko::carlson_rf does not rescale: 2^-967 <= largest < 2^1016 (carlson_scale_exponent)
    ok = num & (x >= 0.0) & (y >= 0.0) & (z >= 0.0) & (zeros >= -1) & (big >= 0x1p-967) & (big < 0x1p+1016);
    const vd one = splat(1.0);
    return rf_plain(select(ok, x, one), select(ok, y, one), select(ok, z, one));
  }
};

// out[i] = K(in[0][i], ...) for i < n: full vectors straight from memory, the tail padded with
// K::pad, lanes outside K's vector region from the scalar kernel.
template <class K>
void batch(const double* const* in, double* out, std::size_t n, simd::lane_fn fallback) {
  vd a[K::nin];
  std::size_t i = 0;
  for (; i < n; i += W) {
    const std::size_t count = n - i < static_cast<std::size_t>(W) ? n - i : static_cast<std::size_t>(W);
    for (int k = 0; k < K::nin; ++k) {
      if (count == static_cast<std::size_t>(W)) {
        __builtin_memcpy(&a[k], in[k] + i, sizeof(vd));
      } else {
        a[k] = splat(K::pad[k]);
        for (std::size_t l = 0; l < count; ++l) a[k][l] = in[k][i + l];
      }
    }
    vi ok;
    vd r = K::eval(a, ok);
    if (pack::any(~ok)) {
      for (std::size_t l = 0; l < count; ++l) {
        if (ok[l]) continue;
        double args[K::nin];
        for (int k = 0; k < K::nin; ++k) args[k] = a[k][l];
        r[l] = fallback(args);
      }
    }
    // stored after every read of this vector's inputs: out may be one of them (out=phi)
    if (count == static_cast<std::size_t>(W)) {
      __builtin_memcpy(out + i, &r, sizeof(vd));
    } else {
      for (std::size_t l = 0; l < count; ++l) out[i + l] = r[l];
    }
  }
}

inline const simd::kernels* table() {
  static const simd::kernels t = {&batch<kernel_f>, &batch<kernel_e>, &batch<kernel_rf>, W};
  return &t;
}

}  // namespace GECKO_SIMD_NS
}  // namespace bindings
}  // namespace gecko
