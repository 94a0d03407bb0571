// gecko/seta/detail/separatrix_scales.hpp — the scales that decide when a segment is treated in
// its separatrix limit, shared by the limit continuation (detail/separatrix_limit.hpp), the
// admissibility walk past the saddle (admissibility.hpp) and the design derivatives
// (sensitivities.hpp).
//
// docs/theory/two_level_seta.md, "Long segments": a tensioned segment l / tau elastic lengths
// long passes its saddle at the distance delta = M - N - c N^2/2 (paper 001 eq (8)), which shrinks
// like exp(-l / tau), tau = sqrt(EI / (N (1 + c N))) the time constant of its saddle; delta is
// formed from the state by cancellation against |M| + N.
#pragma once

#include <limits>

namespace gecko {
namespace detail {

// A segment this many elastic lengths long or longer is "long": its separatrix distance is below
// about e^-10 of the scale, and the limit treatment applies to it.
constexpr double separatrix_long_segment = 10;

// A line stalled next to a long segment's separatrix when the relative distance
// delta / (|M| + N) is at most this.
constexpr double separatrix_stall_gap = 1e-6;

// The smallest relative distance the Carlson forms resolve (to about 1e-4 in delta: M is rounded
// to eps of the scale and the forms form M + b3 from it again): 2^-36. The limit's length law
// is sampled there and two binades below, and the admissibility walk takes its proxy orbit there.
constexpr int separatrix_resolved_exponent = -36;

// Below 2^-40 of the scale a state's digits no longer resolve its separatrix distance: the length
// equations, whose derivatives go like 1/delta, cannot be differentiated there.
constexpr int separatrix_unresolved_exponent = -40;

// The two exponents above for a type T: they are double's, set by its rounding (eps = 2^-52 of the
// scale against 2^-36 leaves delta 2^-16 relative), so a wider type resolves as many binades deeper
// as it has more digits (long double on x86: 11, to 2^-47 and 2^-51), with delta again 2^-16
// relative there. The long-double retry of give-ups (critical_line.hpp) measures its limit segments
// there: the law's extrapolation from the measured lengths to the segment's is that much shorter.
// A type no wider than double keeps double's.
template <class T>
constexpr int separatrix_extra_digits() {
  constexpr int extra = std::numeric_limits<T>::digits - std::numeric_limits<double>::digits;
  return extra > 0 ? extra : 0;
}
// Is T wider than double? What only the long-double retry of give-ups does (critical_line.hpp) asks
// this: the separatrix march at the line's tolerance, from a node before the line's last, and in
// arclength past a collapse of its steps; the natural state's march in lambda past a collapse, and
// its verdict at the edge of the forms. So no state solved in double changes.
template <class T>
constexpr bool wider_than_double() {
  return separatrix_extra_digits<T>() > 0;
}
template <class T>
constexpr int separatrix_resolved_exponent_of() {
  return separatrix_resolved_exponent - separatrix_extra_digits<T>();
}
template <class T>
constexpr int separatrix_unresolved_exponent_of() {
  return separatrix_unresolved_exponent - separatrix_extra_digits<T>();
}

}  // namespace detail
}  // namespace gecko
