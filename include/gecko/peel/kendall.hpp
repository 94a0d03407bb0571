// gecko/peel/kendall.hpp — Kendall's peel line of an extensible film (docs/theory/two_level_seta.md, "Classical
// peel lines", paper eq 17):
//     sqrt(Fn^2 + Ft^2) + (Fn^2 + Ft^2)/(2 EA) - Ft - w = 0.
// Solved for the (tensile, Fn <= 0) normal force at a given shear Ft: with N = |F|,
// N + N^2/(2EA) = Ft + w gives N = 2 (Ft + w) / (1 + sqrt(1 + 2 (Ft + w)/EA)) (no cancellation),
// and Fn = -sqrt((N - Ft)(N + Ft)). The line exists where N >= |Ft|, i.e. up to
// Ft = sqrt(2 EA w) = (Ft)max; EA = infinity gives Rivlin's line (gecko/peel/rivlin.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {

template <class T, class Policy = policies::default_policy>
inline T kendall_fn(T Ft, T EA, T w, const Policy& = Policy()) {
  using std::isinf; using std::sqrt;
  constexpr const char* fn = "gecko::kendall_fn";
  if (!(EA > 0)) return raise_domain_error<T, Policy>(fn, "EA", EA, "EA > 0 (infinity allowed)");
  if (!(w > 0) || isinf(w)) return raise_domain_error<T, Policy>(fn, "w", w, "0 < w < infinity");
  if (!(Ft == Ft) || isinf(Ft)) return raise_domain_error<T, Policy>(fn, "Ft", Ft, "a finite shear force");
  // The line's ends: N = -Ft at Ft = -2w / (2 + sqrt(4 + 2w/EA)) and N = Ft at sqrt(2 EA w).
  const T lo = isinf(EA) ? -w / 2 : -2 * w / (2 + sqrt(4 + 2 * w / EA));
  const T hi = isinf(EA) ? std::numeric_limits<T>::infinity() : sqrt(2 * EA * w);
  if (!(Ft >= lo && Ft <= hi)) {
    const std::string range = "-2w/(2 + sqrt(4 + 2w/EA)) = " + detail::format_value(lo) +
                              " <= Ft <= sqrt(2 EA w) = " + detail::format_value(hi);
    return raise_domain_error<T, Policy>(fn, "Ft", Ft, range.c_str());
  }
  // Kendall's line, paper 001 eq (17): N + N^2/(2 EA) = Ft + w, solved for N = sqrt(Fn^2 + Ft^2).
  const T M = Ft + w;
  const T N = isinf(EA) ? M : 2 * M / (1 + sqrt(1 + 2 * M / EA));
  const T d = (N - Ft) * (N + Ft);
  return d > 0 ? -sqrt(d) : T(0);
}

}  // namespace gecko
