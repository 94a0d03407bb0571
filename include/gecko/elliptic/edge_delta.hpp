// gecko/elliptic/edge_delta.hpp — Delta^2 = 1 - m sin^2 phi without cancellation, for m > 1.
//
// For m > 1 the Legendre integrals live on 0 <= phi <= arcsin(1/sqrt m) (DLMF 19.2.4 with
// 19.7.4), and next to that edge Delta^2 = 1 - m sin^2 phi is the difference of two nearly equal
// numbers. Formed from a correctly rounded sin phi it carries an absolute error of an ulp of 1,
// which is a relative error of eps / Delta^2 in Delta^2 and moves F(phi|m) by about eps / Delta:
// 10.6 eps at m = 1.46e5, m sin^2 phi = 0.9993, and without bound closer to the edge. But the
// integrals themselves are well conditioned in the exact inputs phi and m (as functions of
// Delta^2 they change by a relative dDelta^2 / Delta^2 times Delta at most): only the rounding of
// sin phi hurts. So sin phi and cos phi are computed here in double-word arithmetic (a pair
// hi + lo of T, about 2 digits(T) bits; Dekker 1971, error-free products by fma) and
//   m > 2:      Delta^2 = 1 - m s^2            (one cancellation, of the exact m s^2),
//   1 < m <= 2: Delta^2 = c^2 - (m - 1) s^2    (m - 1 exact by Sterbenz; when m -> 1 and
//                                              phi -> pi/2, c^2 is small and the form 1 - m s^2
//                                              would lose c^2's digits),
// each to within a few units of 2^(-2 digits) relative to its larger term, i.e. Delta^2 to full
// relative accuracy unless Delta^2 / (m s^2) is below 2^-digits, which double inputs on the
// real domain do not reach in practice (the closest a double phi comes to the edge).
// sin and cos of the double-word argument come from their Taylor series (DLMF 4.19.1) in
// Horner form, 15 terms: for |x| <= pi/4 the first omitted term is below 2^-120 relative; the
// 8 smallest are summed in T alone (see dw_taylor_horner).
#pragma once

#include <cmath>

#include "gecko/elliptic/angle_reduction.hpp"

namespace gecko {
namespace detail {

template <class T>
struct dword {
  T hi, lo;
};

// a + b exactly as hi + lo, |a| >= |b| or a = 0 (Dekker's fast two-sum).
template <class T>
inline dword<T> fast_two_sum(T a, T b) {
  const T s = a + b;
  return {s, b - (s - a)};
}

// a + b exactly as hi + lo, any order (Knuth's two-sum).
template <class T>
inline dword<T> two_sum(T a, T b) {
  const T s = a + b;
  const T bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

template <class T>
inline dword<T> dw_add(dword<T> x, dword<T> y) {
  const dword<T> s = two_sum(x.hi, y.hi);
  const dword<T> t = two_sum(x.lo, y.lo);
  dword<T> u = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(u.hi, u.lo + t.lo);
}

template <class T>
inline dword<T> dw_neg(dword<T> x) { return {-x.hi, -x.lo}; }

template <class T>
inline dword<T> dw_mul(dword<T> x, dword<T> y) {
  using std::fma;
  const T p = x.hi * y.hi;
  const T e = fma(x.hi, y.hi, -p);
  return fast_two_sum(p, e + (x.hi * y.lo + x.lo * y.hi));
}

template <class T>
inline dword<T> dw_mul(dword<T> x, T y) {
  using std::fma;
  const T p = x.hi * y;
  const T e = fma(x.hi, y, -p);
  return fast_two_sum(p, fma(x.lo, y, e));
}

// x / n for an integer-valued n that T holds exactly.
template <class T>
inline dword<T> dw_div(dword<T> x, T n) {
  using std::fma;
  const T q = x.hi / n;
  const T r = fma(-q, n, x.hi) + x.lo;  // the first remainder is exact
  return fast_two_sum(q, r / n);
}

// 1 - x^2/((k)(k+1)) (1 - x^2/((k+2)(k+3)) (1 - ...)): the Taylor series of sin x / x (first = 2)
// or of cos x (first = 1), x2 = x^2, |x| <= pi/4. The innermost levels j > 7 are summed in T
// alone: their rounding is scaled by x^14/14! < 2^-44 on its way out, so the result keeps about
// digits + 44 bits (2^-97 for double), the double-word levels j <= 7 carry it.
constexpr int taylor_terms = 15;

// 1/(k(k+1)) for k = 1 .. 2 taylor_terms as double-words (divisions once, not on every call).
template <class T>
struct taylor_reciprocals {
  dword<T> r[2 * taylor_terms + 1];
};

template <class T>
inline const taylor_reciprocals<T>& reciprocals() {
  static const taylor_reciprocals<T> table = [] {
    taylor_reciprocals<T> t{};
    for (int k = 1; k <= 2 * taylor_terms; ++k) t.r[k] = dw_div(dword<T>{T(1), T(0)}, T(k) * T(k + 1));
    return t;
  }();
  return table;
}

template <class T>
inline dword<T> dw_taylor_horner(dword<T> x2, int first) {
  constexpr int dw_terms = 7;
  const dword<T>* inv = reciprocals<T>().r;
  T tt = 1;
  for (int j = taylor_terms; j > dw_terms; --j) {
    const int k = 2 * j - 2 + first;  // (k)(k+1) = (2j)(2j+1) for sin, (2j-1)(2j) for cos
    tt = 1 - tt * x2.hi * inv[k].hi;
  }
  dword<T> t{tt, T(0)};
  for (int j = dw_terms; j >= 1; --j) {
    const int k = 2 * j - 2 + first;
    t = dw_mul(dw_mul(t, x2), inv[k]);
    const dword<T> u = fast_two_sum(T(1), -t.hi);  // 1 - t, |t| <= 1/4
    t = fast_two_sum(u.hi, u.lo - t.lo);
  }
  return t;
}

// sin a and cos a for 0 <= a <= pi/2 (a exact), each as a double-word.
template <class T>
inline void dw_first_quadrant_sincos(T a, dword<T>& s, dword<T>& c) {
  using C = pi_constants<T>;
  const bool reflect = a > C::pio2_hi * T(0.5);
  dword<T> x{a, T(0)};
  if (reflect) {
    // pi/2 - a: the first difference is exact (Sterbenz, pi/4 <= a <= pi/2)
    x = two_sum(C::pio2_hi - a, C::pio2_lo);
    x = fast_two_sum(x.hi, x.lo + C::pio2_lo2);
  }
  const dword<T> x2 = dw_mul(x, x);
  const dword<T> sx = dw_mul(dw_taylor_horner(x2, 2), x);
  const dword<T> cx = dw_taylor_horner(x2, 1);
  s = reflect ? cx : sx;
  c = reflect ? sx : cx;
}

// For m > 1 and 0 <= a <= pi/2: s = sin a, c = cos a (rounded to T) and Delta^2 = 1 - m sin^2 a
// to full relative accuracy (may be slightly negative when a is beyond the edge by rounding).
template <class T>
struct edge_arguments {
  T s, c, d2;
};

template <class T>
inline edge_arguments<T> m_above_one_arguments(T a, T m) {
  dword<T> s, c;
  dw_first_quadrant_sincos(a, s, c);
  dword<T> d2;
  if (m <= 2) {
    d2 = dw_add(dw_mul(c, c), dw_neg(dw_mul(dw_mul(s, s), m - 1)));
  } else {
    // (m s) s, not m s^2: for m near the largest T, s^2 and its low part would underflow
    d2 = dw_add(dword<T>{T(1), T(0)}, dw_neg(dw_mul(dw_mul(s, m), s)));
  }
  return {s.hi + s.lo, c.hi + c.lo, d2.hi + d2.lo};
}

}  // namespace detail
}  // namespace gecko
