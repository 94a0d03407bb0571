// gecko/seta/two_level_seta.hpp — the two-level seta design and its admissible range.
//
// docs/theory/two_level_seta.md, "Geometry and unknowns": a beam (level 1: EI1, EA1, length l1, clamped at
// theta1(0) = alpha1) carrying a spatula (level 2: EI2, EA2, length l2, kinked by alpha2 at the
// joint) in side contact with a rigid substrate, work of adhesion w. Defaults: the paper's
// reference scene (non-dimensional, w = 1, l1 = 1): EI1 = 5, EI2 = 2, EA1 = inf, EA2 = 50,
// l2 = 0.1, alpha1 = alpha2 = pi/6.
#pragma once

#include <array>
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
  return sqrt(2 * s.EA2 * s.w);  // paper 001 eq (3) needs w - Ft^2/(2 EA2) >= 0
}

// The design fields in their canonical order (the order of every flat design array: the bindings,
// sensitivities' columns, sweeps), each with its admissible range: lower < v (or lower <= v where
// lower_inclusive), v < upper (or v = infinity where infinity_allowed: EA = inf is inextensible).
// The joint condition alpha1 + alpha2 < pi/2 couples two fields and is checked after them.
template <class T>
struct seta_design_field {
  const char* name;
  T TwoLevelSeta<T>::*member;
  T lower;
  T upper;
  bool lower_inclusive;
  bool infinity_allowed;
  const char* range;        // the allowed range as the error message states it
  const char* description;  // what the field is (for help texts and scene files)

  bool admissible(T v) const {
    const bool lo = lower_inclusive ? v >= lower : v > lower;  // NaN fails both
    return lo && (v < upper || (infinity_allowed && v == std::numeric_limits<T>::infinity()));
  }
};

template <class T>
inline const std::array<seta_design_field<T>, 9>& seta_design_fields() {
  const T inf = std::numeric_limits<T>::infinity();
  const T half_pi = T(1.570796326794896619231321691639751442L);
  using S = TwoLevelSeta<T>;
  static const std::array<seta_design_field<T>, 9> fields{{
      {"EI1", &S::EI1, T(0), inf, false, false, "0 < EI1 < infinity",
       "bending stiffness of the beam (level 1)"},
      {"EI2", &S::EI2, T(0), inf, false, false, "0 < EI2 < infinity",
       "bending stiffness of the spatula (level 2)"},
      {"EA1", &S::EA1, T(0), inf, false, true, "EA1 > 0 (infinity allowed: inextensible)",
       "axial stiffness of the beam (inf: inextensible)"},
      {"EA2", &S::EA2, T(0), inf, false, true, "EA2 > 0 (infinity allowed: inextensible)",
       "axial stiffness of the spatula (inf: inextensible)"},
      {"l1", &S::l1, T(0), inf, false, false, "0 < l1 < infinity", "length of the beam"},
      {"l2", &S::l2, T(0), inf, false, false, "0 < l2 < infinity", "length of the spatula"},
      {"alpha1", &S::alpha1, T(0), half_pi, false, false, "0 < alpha1 < pi/2",
       "base angle of the beam from the substrate normal"},
      {"alpha2", &S::alpha2, T(0), half_pi, true, false, "0 <= alpha2 and alpha1 + alpha2 < pi/2",
       "kink of the spatula at the joint (alpha1 + alpha2 < pi/2)"},
      {"w", &S::w, T(0), inf, false, false, "0 < w < infinity", "work of adhesion per unit length"},
  }};
  return fields;
}

namespace detail {

// Checks every design parameter against its admissible range (seta_design_fields: one table for
// this check, the error messages and the bindings); returns false (after raise_domain_error,
// which throws under the default policy) when one is out of range.
template <class T, class Policy>
inline bool check_seta(const TwoLevelSeta<T>& s, const char* function) {
  for (const auto& f : seta_design_fields<T>()) {
    if (!f.admissible(s.*(f.member))) {
      raise_domain_error<T, Policy>(function, f.name, s.*(f.member), f.range);
      return false;
    }
  }
  const T half_pi = T(1.570796326794896619231321691639751442L);
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
