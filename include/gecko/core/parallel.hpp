// gecko/core/parallel.hpp — the one thread pool of the batch calls.
//
// Item i goes to thread i mod threads (round robin): every item is computed by exactly the same
// code whatever the thread count, so batch results are bitwise identical for 1, 2, ... threads
// (tested in tests/seta/batch.cpp and by the Python concurrency and sweep tests). An exception
// in any thread stops that thread's share and is rethrown on the calling thread after all joined.
#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace gecko {
namespace detail {

template <class F>
inline void parallel_for_strided(std::size_t count, unsigned threads, F&& f) {
  unsigned nt = threads > 0 ? threads : 1u;
  if (count < nt) nt = count > 0 ? static_cast<unsigned>(count) : 1u;
  std::vector<std::exception_ptr> errors(nt);
  auto work = [&](unsigned t) {
    try {
      for (std::size_t i = t; i < count; i += nt) f(i);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  if (nt == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    pool.reserve(nt);
    for (unsigned t = 0; t < nt; ++t) pool.emplace_back(work, t);
    for (auto& th : pool) th.join();
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace detail
}  // namespace gecko
