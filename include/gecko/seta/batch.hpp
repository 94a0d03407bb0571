// gecko/seta/batch.hpp — many designs x many Ft in one call, on several threads.
//
// Each design's critical line (gecko/seta/critical_line.hpp: natural state, continuation, states
// at the requested Ft) is independent of the others, so designs are dealt round-robin to
// threads (gecko/core/parallel.hpp) with no shared mutable state; the result is bitwise identical for any thread
// count. out is row-major: out[i * count + j] is design i at Ft[j]. Under nan_policy a bad design
// or Ft gives status invalid_input in its entries; under the default policy the first error is
// rethrown (std::domain_error) after all threads have joined.
#pragma once

#include <cstddef>

#include "gecko/core/parallel.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/seta/critical_line.hpp"

namespace gecko {

template <class T, class Policy = policies::default_policy>
inline void critical_line_batch(const TwoLevelSeta<T>* designs, std::size_t design_count, const T* Ft,
                                std::size_t count, critical_state<T>* out, unsigned threads = 1,
                                const critical_line_options<T>& options = critical_line_options<T>(),
                                const Policy& pol = Policy()) {
  detail::parallel_for_strided(design_count, threads, [&](std::size_t i) {
    critical_line_at(designs[i], Ft, count, out + i * count, options, pol);
  });
}

}  // namespace gecko
