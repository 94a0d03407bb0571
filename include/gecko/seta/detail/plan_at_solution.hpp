// gecko/seta/detail/plan_at_solution.hpp — the Carlson plan of a converged state whose plan lapsed.
//
// A solver holds its plan fixed while it converges and checks it at the converged state
// (System::plan_valid); where it no longer applies there, the state is re-planned and corrected
// again (gecko/seta/detail/continuation.hpp, gecko/seta/solve_critical.hpp).
#pragma once

#include "gecko/seta/elastica_segment.hpp"

namespace gecko {
namespace detail {

// The plan at a state z that solves the equations at mu (converged, but under a plan found no
// longer valid there): the segments' lengths there are l1 and l2, which fix the libration period
// counts (System::plan_solved). The phases alone (System::plan) are defined modulo 4K and drop a
// period where the ends' phases coincide (paper 001 eq (15) with l = 4K): a corrector re-planned
// so would start from a residual off by 4K and give up. plan_solved only adds periods
// to plan's choice, so its state is plan's; plan remains the fallback should it ever not be ok.
template <class System>
inline typename System::plan_type plan_at_solution(const System& sys, const typename System::vec& z,
                                                   typename System::value_type mu) {
  auto p = sys.plan_solved(z, mu);
  if (System::plan_state(p) == segment_state::ok) return p;
  return sys.plan(z, mu);
}

}  // namespace detail
}  // namespace gecko
