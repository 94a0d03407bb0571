// gecko/seta/solve_on_line.hpp — solve_critical without a guess: the state at Ft on the line
// followed from Ft = 0 (gecko/seta/critical_line.hpp), for callers that have no nearby state.
// With a guess, gecko/seta/solve_critical.hpp solves by Newton alone.
#pragma once

#include "gecko/core/policy.hpp"
#include "gecko/seta/critical_line.hpp"

namespace gecko {

// Without a guess: the state on the line followed from Ft = 0.
template <class T, class Policy = policies::default_policy>
inline critical_state<T> solve_critical(const TwoLevelSeta<T>& seta, T Ft) {
  critical_state<T> r;
  critical_line_at(seta, &Ft, 1, &r, critical_line_options<T>(), Policy());
  return r;
}

}  // namespace gecko
