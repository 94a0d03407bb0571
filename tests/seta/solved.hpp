// Test helper: a solved critical state. Status 7 (inadmissible: the seta crosses the substrate, or
// exceeds a strain limit) is a solution of the equations with its values kept, so the tests of the
// equations' accuracy accept it; admissibility itself is tested in tests/seta/admissibility.cpp.
#pragma once

#include "gecko/seta/solve_critical.hpp"

namespace seta_test {
inline bool solved(gecko::critical_status s) {
  return s == gecko::critical_status::converged || s == gecko::critical_status::inadmissible;
}
}  // namespace seta_test
