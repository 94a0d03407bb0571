// gecko/seta/detail/dual.hpp — forward-mode dual numbers for the seta Jacobians.
//
// The residual of the critical state (gecko/seta/critical_residual.hpp) is written once, templated
// on its scalar, and evaluated with dual<T, K> to get its exact first derivatives with respect to
// K chosen inputs (the Newton unknowns and Ft; or the design parameters for sensitivities). This is
// analytic differentiation, not finite differences: every operation carries the chain rule, and
// R_F carries its partial derivatives -R_D/6 (DLMF 19.18.1, gecko/elliptic/carlson_rf_gradient.hpp).
// Only the few operations the Carlson forms need are provided.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace gecko {
namespace detail {

template <class T, std::size_t K>
struct dual {
  T v{};                 // value
  std::array<T, K> d{};  // derivatives with respect to the K seeded inputs

  dual() = default;
  // Implicit from a constant: derivatives zero.
  dual(T value) : v(value) { d.fill(T(0)); }  // NOLINT(google-explicit-constructor)
  static dual variable(T value, std::size_t index) {
    dual r(value);
    r.d[index] = T(1);
    return r;
  }
};

template <class X> struct is_dual : std::false_type {};
template <class T, std::size_t K> struct is_dual<dual<T, K>> : std::true_type {};

// value_of(x): the plain value of a scalar or a dual.
template <class T> inline T value_of(T x) { return x; }
template <class T, std::size_t K> inline T value_of(const dual<T, K>& x) { return x.v; }

// Result r = a * x + b * y for the derivative parts (the common kernel of all operations).
template <class T, std::size_t K>
inline dual<T, K> dual_make(T v, T ga, const dual<T, K>& a) {
  dual<T, K> r;
  r.v = v;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = ga * a.d[i];
  return r;
}
template <class T, std::size_t K>
inline dual<T, K> dual_make(T v, T ga, const dual<T, K>& a, T gb, const dual<T, K>& b) {
  dual<T, K> r;
  r.v = v;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = ga * a.d[i] + gb * b.d[i];
  return r;
}

template <class T, std::size_t K>
inline dual<T, K> operator-(const dual<T, K>& a) { return dual_make(-a.v, T(-1), a); }
template <class T, std::size_t K>
inline dual<T, K> operator+(const dual<T, K>& a, const dual<T, K>& b) {
  dual<T, K> r;
  r.v = a.v + b.v;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <class T, std::size_t K>
inline dual<T, K> operator-(const dual<T, K>& a, const dual<T, K>& b) {
  dual<T, K> r;
  r.v = a.v - b.v;
  for (std::size_t i = 0; i < K; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <class T, std::size_t K>
inline dual<T, K> operator*(const dual<T, K>& a, const dual<T, K>& b) {
  return dual_make(a.v * b.v, b.v, a, a.v, b);
}
template <class T, std::size_t K>
inline dual<T, K> operator/(const dual<T, K>& a, const dual<T, K>& b) {
  const T q = a.v / b.v;
  const T ib = T(1) / b.v;
  return dual_make(q, ib, a, -q * ib, b);
}
// Mixed with plain constants.
template <class T, std::size_t K>
inline dual<T, K> operator+(const dual<T, K>& a, T b) { dual<T, K> r = a; r.v += b; return r; }
template <class T, std::size_t K>
inline dual<T, K> operator+(T b, const dual<T, K>& a) { return a + b; }
template <class T, std::size_t K>
inline dual<T, K> operator-(const dual<T, K>& a, T b) { dual<T, K> r = a; r.v -= b; return r; }
template <class T, std::size_t K>
inline dual<T, K> operator-(T b, const dual<T, K>& a) { return dual_make(b - a.v, T(-1), a); }
template <class T, std::size_t K>
inline dual<T, K> operator*(const dual<T, K>& a, T b) { return dual_make(a.v * b, b, a); }
template <class T, std::size_t K>
inline dual<T, K> operator*(T b, const dual<T, K>& a) { return dual_make(a.v * b, b, a); }
template <class T, std::size_t K>
inline dual<T, K> operator/(const dual<T, K>& a, T b) { const T ib = T(1) / b; return dual_make(a.v * ib, ib, a); }
template <class T, std::size_t K>
inline dual<T, K> operator/(T b, const dual<T, K>& a) {
  const T q = b / a.v;
  return dual_make(q, -q / a.v, a);
}

template <class T, std::size_t K>
inline dual<T, K> sqrt(const dual<T, K>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  return dual_make(s, T(0.5) / s, a);
}
template <class T, std::size_t K>
inline dual<T, K> sin(const dual<T, K>& a) {
  using std::cos; using std::sin;
  return dual_make(sin(a.v), cos(a.v), a);
}
template <class T, std::size_t K>
inline dual<T, K> cos(const dual<T, K>& a) {
  using std::cos; using std::sin;
  return dual_make(cos(a.v), -sin(a.v), a);
}
template <class T, std::size_t K>
inline dual<T, K> asin(const dual<T, K>& a) {
  using std::asin; using std::sqrt;
  return dual_make(asin(a.v), T(1) / sqrt((1 - a.v) * (1 + a.v)), a);
}
// atan2(y, x) and hypot(y, x): the force direction phi and magnitude N from (Fn, Ft).
template <class T, std::size_t K>
inline dual<T, K> atan2(const dual<T, K>& y, const dual<T, K>& x) {
  using std::atan2;
  const T r2 = x.v * x.v + y.v * y.v;
  return dual_make(atan2(y.v, x.v), x.v / r2, y, -y.v / r2, x);
}
template <class T, std::size_t K>
inline dual<T, K> hypot(const dual<T, K>& y, const dual<T, K>& x) {
  using std::hypot;
  const T h = hypot(y.v, x.v);
  return dual_make(h, y.v / h, y, x.v / h, x);
}

// Scalar versions with the same names, so templated code calls sqrt(x) etc. unqualified.
template <class T, std::enable_if_t<std::is_floating_point<T>::value, int> = 0>
inline T sqr(T x) { return x * x; }
template <class T, std::size_t K>
inline dual<T, K> sqr(const dual<T, K>& a) { return dual_make(a.v * a.v, 2 * a.v, a); }

}  // namespace detail
}  // namespace gecko

namespace gecko {
namespace detail {
// The plain floating-point type under a scalar or a dual.
template <class S> struct scalar_of { using type = S; };
template <class T, std::size_t K> struct scalar_of<dual<T, K>> { using type = T; };
template <class S> using scalar_of_t = typename scalar_of<S>::type;
}  // namespace detail
}  // namespace gecko
