// gecko/peel/rivlin.hpp — Rivlin's peel line of an inextensible film (docs/theory/two_level_seta.md, paper eq 17):
//     sqrt(Fn^2 + Ft^2) - Ft - w = 0   =>   Fn = -sqrt(w^2 + 2 w Ft)   (tensile root),
// defined for Ft >= -w/2.
#pragma once

#include <cmath>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {

template <class T, class Policy = policies::default_policy>
inline T rivlin_fn(T Ft, T w, const Policy& = Policy()) {
  using std::isinf; using std::sqrt;
  constexpr const char* fn = "gecko::rivlin_fn";
  if (!(w > 0) || isinf(w)) return raise_domain_error<T, Policy>(fn, "w", w, "0 < w < infinity");
  if (!(Ft >= -w / 2) || isinf(Ft)) return raise_domain_error<T, Policy>(fn, "Ft", Ft, "-w/2 <= Ft < infinity");
  return -sqrt(w * (w + 2 * Ft));  // Rivlin's line, paper 001 eq (17): sqrt(Fn^2 + Ft^2) = Ft + w
}

}  // namespace gecko
