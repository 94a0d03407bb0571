// gecko/core/parallel.hpp — the one thread pool of the batch calls.
//
// Two ways to deal n independent items to `threads` threads, both deterministic: every item is
// computed by exactly the same code whatever the thread count, so batch results are bitwise
// identical for 1, 2, ... threads (tested in tests/core/parallel.cpp, tests/seta/batch.cpp and the
// Python concurrency and sweep tests).
//   * parallel_for_strided: item i goes to thread i mod threads (round robin). For items of very
//     different cost (seta designs: a line with folds costs ten times one without), it balances.
//   * parallel_for_blocks: thread t gets the contiguous block [n t / threads, n (t+1) / threads).
//     For cheap uniform items (array elements): each thread streams through its own memory and an
//     inner loop can be vectorised.
// An exception in any thread stops that thread's share and is rethrown on the calling thread after
// all threads joined: the one of the lowest-numbered thread, so for blocks the error of the
// smallest failing block.
#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace gecko {
namespace detail {

// Runs work(t) for t in [0, nt) on nt threads (the calling thread takes t = 0) and rethrows the
// first thread's exception, in thread order, after all joined.
template <class Work>
inline void run_on_threads(unsigned nt, Work&& work) {
  std::vector<std::exception_ptr> errors(nt);
  auto guarded = [&](unsigned t) {
    try {
      work(t);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  if (nt <= 1) {
    guarded(0);
  } else {
    std::vector<std::thread> pool;
    pool.reserve(nt - 1);
    for (unsigned t = 1; t < nt; ++t) pool.emplace_back(guarded, t);
    guarded(0);
    for (auto& th : pool) th.join();
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

inline unsigned clamp_threads(std::size_t count, unsigned threads) {
  unsigned nt = threads > 0 ? threads : 1u;
  if (count < nt) nt = count > 0 ? static_cast<unsigned>(count) : 1u;
  return nt;
}

template <class F>
inline void parallel_for_strided(std::size_t count, unsigned threads, F&& f) {
  const unsigned nt = clamp_threads(count, threads);
  run_on_threads(nt, [&](unsigned t) {
    for (std::size_t i = t; i < count; i += nt) f(i);
  });
}

// f(begin, end) once per thread on its contiguous block.
template <class F>
inline void parallel_for_blocks(std::size_t count, unsigned threads, F&& f) {
  const unsigned nt = clamp_threads(count, threads);
  run_on_threads(nt, [&](unsigned t) {
    const std::size_t begin = count * t / nt, end = count * (t + 1) / nt;
    if (begin < end) f(begin, end);
  });
}

}  // namespace detail
}  // namespace gecko
