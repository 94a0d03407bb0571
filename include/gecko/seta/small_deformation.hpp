// gecko/seta/small_deformation.hpp — the small-deformation (linear) theory of the two-level seta
// (docs/theory/two_level_seta.md, "Small-deformation approximations", paper eqs 6-7 and 18-22). Qualitative by the
// paper's own account (reference scene: (Fn)0 = 0.34 here against the exact 0.2499); the exact
// counterparts are in gecko/seta/characteristics.hpp.
//   Meq = sqrt(2 EI2 w), Delta = pi/2 - (alpha1 + alpha2)
//   eq 7:  Meq l1/EI1 + Meq (l2 - lc)/EI2 = Delta                (contact length lc at rest)
//   eq 22: non-sticky at rest iff Meq (l1/EI1 + l2/EI2) <= Delta
//   eq 18: P l2^2/(2EI2) + Meq l2/EI2 + Q l1^2/(2EI1) + (P l2 + Meq) l1/EI1 = Delta,
//          P = Ft cos(a1+a2) + Fn sin(a1+a2), Q = Ft cos a1 + Fn sin a1: linear in (Fn, Ft), so
//          Fn = (Fn)0 + k Ft with (Fn)0 (eqs 19-20) and k (eq 21) below.
#pragma once

#include <cmath>

#include "gecko/core/policy.hpp"
#include "gecko/seta/two_level_seta.hpp"

namespace gecko {

template <class T>
struct small_deformation_line {
  T fn0;              // (Fn)0, eqs 19-20
  T slope_k;          // k, eq 21
  T contact_length;   // lc at rest, eq 7 (may fall outside [0, l2]: then no contact at rest)
  bool non_sticky;    // eq 22
};

template <class T, class Policy = policies::default_policy>
inline small_deformation_line<T> small_deformation(const TwoLevelSeta<T>& s, const Policy& = Policy()) {
  using std::cos; using std::sin; using std::sqrt;
  small_deformation_line<T> r{};
  if (!detail::check_seta<T, Policy>(s, "gecko::small_deformation")) {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    return {nan, nan, nan, false};
  }
  const T a12 = s.alpha1 + s.alpha2;
  const T Delta = T(1.570796326794896619231321691639751442L) - a12;
  const T Meq = sqrt(2 * s.EI2 * s.w);  // the adhesive moment at the contact edge, paper 001 eq (6)
  const T cP = s.l2 * s.l2 / (2 * s.EI2) + s.l1 * s.l2 / s.EI1;  // coefficient of P in eq 18
  const T cQ = s.l1 * s.l1 / (2 * s.EI1);                       // coefficient of Q
  const T An = cP * sin(a12) + cQ * sin(s.alpha1);
  const T At = cP * cos(a12) + cQ * cos(s.alpha1);
  const T rhs = Delta - Meq * (s.l2 / s.EI2 + s.l1 / s.EI1);
  r.fn0 = rhs / An;                                                      // paper 001 eqs (19)-(20)
  r.slope_k = -At / An;                                                  // paper 001 eq (21)
  r.contact_length = s.l2 - (Delta - Meq * s.l1 / s.EI1) * s.EI2 / Meq;  // paper 001 eq (7)
  r.non_sticky = Meq * (s.l1 / s.EI1 + s.l2 / s.EI2) <= Delta;           // paper 001 eq (22)
  return r;
}

// Fn on the linear critical line (eq 18) at shear Ft.
template <class T, class Policy = policies::default_policy>
inline T small_deformation_fn(const TwoLevelSeta<T>& s, T Ft, const Policy& pol = Policy()) {
  const auto r = small_deformation(s, pol);
  return r.fn0 + r.slope_k * Ft;  // paper 001 eq (18), solved for Fn
}

}  // namespace gecko
