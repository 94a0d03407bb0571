// gecko/seta/two_level_seta.hpp — the two-level seta design and its admissible range.
//
// docs/theory/two_level_seta.md, "Geometry and unknowns": a beam (level 1: EI1, EA1, length l1, clamped at
// theta1(0) = alpha1) carrying a spatula (level 2: EI2, EA2, length l2, kinked by alpha2 at the
// joint) in side contact with a rigid substrate, work of adhesion w. Defaults: the paper's
// reference scene (non-dimensional, w = 1, l1 = 1): EI1 = 5, EI2 = 2, EA1 = inf, EA2 = 50,
// l2 = 0.1, alpha1 = alpha2 = pi/6.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {

template <class T = double>
struct TwoLevelSeta {
  T EI1 = T(5);
  T EI2 = T(2);
  T EA1 = std::numeric_limits<T>::infinity();
  T EA2 = T(50);
  T l1 = T(1);
  T l2 = T(0.1);
  T alpha1 = T(0.523598775598298873077107230546583814L);  // pi/6
  T alpha2 = T(0.523598775598298873077107230546583814L);  // pi/6
  T w = T(1);
};

// (Ft)max = sqrt(2 EA2 w): beyond it the contact edge cannot satisfy Griffith's condition
// 1/2 EI2 theta2'(a)^2 + Ft^2/(2 EA2) = w (docs/theory/two_level_seta.md, "Critical line of adhesion").
template <class T>
inline T ft_max(const TwoLevelSeta<T>& s) {
  using std::sqrt;
  return sqrt(2 * s.EA2 * s.w);
}

namespace detail {

// Checks every design parameter; returns false (after raise_domain_error, which throws under
// the default policy) when one is out of range.
template <class T, class Policy>
inline bool check_seta(const TwoLevelSeta<T>& s, const char* function) {
  using std::isfinite;
  const T half_pi = T(1.570796326794896619231321691639751442L);
  auto positive = [&](T v, const char* name, const char* range) {
    if (v > 0 && isfinite(v)) return true;
    raise_domain_error<T, Policy>(function, name, v, range);
    return false;
  };
  auto positive_or_inf = [&](T v, const char* name, const char* range) {
    if (v > 0) return true;  // NaN fails here too
    raise_domain_error<T, Policy>(function, name, v, range);
    return false;
  };
  if (!positive(s.EI1, "EI1", "0 < EI1 < infinity")) return false;
  if (!positive(s.EI2, "EI2", "0 < EI2 < infinity")) return false;
  if (!positive_or_inf(s.EA1, "EA1", "EA1 > 0 (infinity allowed: inextensible)")) return false;
  if (!positive_or_inf(s.EA2, "EA2", "EA2 > 0 (infinity allowed: inextensible)")) return false;
  if (!positive(s.l1, "l1", "0 < l1 < infinity")) return false;
  if (!positive(s.l2, "l2", "0 < l2 < infinity")) return false;
  if (!positive(s.w, "w", "0 < w < infinity")) return false;
  if (!(s.alpha1 > 0 && s.alpha1 < half_pi)) {
    raise_domain_error<T, Policy>(function, "alpha1", s.alpha1, "0 < alpha1 < pi/2");
    return false;
  }
  if (!(s.alpha2 >= 0 && s.alpha2 < half_pi)) {
    raise_domain_error<T, Policy>(function, "alpha2", s.alpha2, "0 <= alpha2 and alpha1 + alpha2 < pi/2");
    return false;
  }
  if (!(s.alpha1 + s.alpha2 < half_pi)) {
    raise_domain_error<T, Policy>(function, "alpha1 + alpha2", s.alpha1 + s.alpha2,
                                  "alpha1 + alpha2 < pi/2 (the spatula must bend to reach the substrate)");
    return false;
  }
  return true;
}

// Ft must be finite and at most (Ft)max; negative Ft (shear against the gripping direction) is
// valid input.
template <class T, class Policy>
inline bool check_ft(T Ft, T ftmax, const char* function) {
  if (!(Ft == Ft) || !(Ft > -std::numeric_limits<T>::infinity())) {
    raise_domain_error<T, Policy>(function, "Ft", Ft, "a finite shear force, Ft <= (Ft)max = sqrt(2 EA2 w)");
    return false;
  }
  if (!(Ft <= ftmax)) {
    const std::string range = "Ft <= (Ft)max = sqrt(2 EA2 w) = " + format_value(ftmax);
    raise_domain_error<T, Policy>(function, "Ft", Ft, range.c_str());
    return false;
  }
  return true;
}

}  // namespace detail
}  // namespace gecko
