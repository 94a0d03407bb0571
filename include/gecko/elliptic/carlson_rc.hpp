// gecko/elliptic/carlson_rc.hpp — Carlson's degenerate integral
//   R_C(x, y) = R_F(x, y, y) = 1/2 int_0^inf dt / ((t + y) sqrt(t + x))   (DLMF 19.2.17)
//
// Closed forms (DLMF 19.2.18-19.2.19), written so that no subtraction cancels:
//   x < y:  R_C = atan(sqrt((y - x)/x)) / sqrt(y - x)                  (= acos(sqrt(x/y))/sqrt(y-x))
//   x > y:  R_C = log1p(((x - y)/(sqrt x + sqrt y) + sqrt(x - y)) / sqrt y) / sqrt(x - y)
//           (= acosh(sqrt(x/y))/sqrt(x-y), with sqrt(x) - sqrt(y) = (x-y)/(sqrt x + sqrt y)),
//   x = y:  R_C = x^(-1/2).
// y < 0: the Cauchy principal value, DLMF 19.2.20: R_C(x, y) = sqrt(x/(x - y)) R_C(x - y, -y).
//
// Domain: x >= 0, y != 0. +inf in either argument gives 0. NaN gives NaN quietly.
// The closed forms need no duplication, so the precision policy does not change the cost.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {
namespace detail {

// Unchecked kernel: x >= 0 and y > 0, both finite.
template <class T, class Policy = policies::default_policy>
inline T carlson_rc_imp(T x, T y) {
  using std::atan;
  using std::log;
  using std::log1p;
  using std::sqrt;
  if (x < y) {
    const T d = y - x;
    if (x == 0) return T(1.570796326794896619231321691639751442L) / sqrt(y);
    return atan(sqrt(d / x)) / sqrt(d);
  }
  if (x > y) {
    const T d = x - y;
    const T sd = sqrt(d);
    const T sy = sqrt(y);
    const T num = d / (sqrt(x) + sy) + sd;
    const T t = num / sy;
    // x/y beyond the overflow threshold (x = 1e300, y subnormal) makes t = +inf while log t is
    // about 710: take the logarithms apart there (both are far from zero, of opposite signs,
    // so nothing cancels). Found by fuzz/fuzz_carlson.cpp.
    if (!(t <= std::numeric_limits<T>::max())) return (log(num) - log(sy)) / sd;
    return log1p(t) / sd;
  }
  return 1 / sqrt(x);
}

// Principal value for y < 0 (DLMF 19.2.20); x >= 0, y < 0, finite.
template <class T, class Policy = policies::default_policy>
inline T carlson_rc_pv_imp(T x, T y) {
  using std::sqrt;
  if (x == 0) return T(0);
  const T d = x - y;
  // x - y overflows only when x and -y are both above 2^(max_exponent - 54): quarter them
  // (exact there) and use R_C(x/4, y/4) = 2 R_C(x, y) (found by fuzz/fuzz_carlson.cpp:
  // R_C(DBL_MAX, -1.2e300) gave NaN).
  if (!(d <= std::numeric_limits<T>::max()))
    return carlson_rc_pv_imp<T, Policy>(x * T(0.25), y * T(0.25)) * T(0.5);
  const T ratio = x / d;
  // x/d below the normal range (x subnormal, |y| large) loses its bits or flushes to zero: take
  // the roots apart there (found by fuzz/fuzz_carlson.cpp: R_C(4.9e-324, -50) gave 0).
  const T factor = ratio >= std::numeric_limits<T>::min() ? sqrt(ratio) : sqrt(x) / sqrt(d);
  return factor * carlson_rc_imp<T, Policy>(d, -y);
}

}  // namespace detail

template <class T, class Policy>
inline T carlson_rc(T x, T y, const Policy&) {
  static_assert(std::is_floating_point<T>::value, "gecko::carlson_rc: T must be a floating-point type");
  using std::isinf;
  using std::isnan;
  constexpr const char* function = "gecko::carlson_rc";
  if (isnan(x) || isnan(y)) return std::numeric_limits<T>::quiet_NaN();
  if (x < 0) return raise_domain_error<T, Policy>(function, "x", x, "x >= 0 and y != 0");
  if (y == 0) return raise_domain_error<T, Policy>(function, "y", y, "x >= 0 and y != 0");
  if (isinf(x) || isinf(y)) return T(0);
  if (y < 0) return detail::carlson_rc_pv_imp<T, Policy>(x, y);
  return detail::carlson_rc_imp<T, Policy>(x, y);
}

template <class T>
inline T carlson_rc(T x, T y) {
  return carlson_rc(x, y, policies::default_policy());
}

}  // namespace gecko
