// The one vectorisation helper of the bindings: every elementwise or batch loop of gecko._core
// (elliptic, friction, seta) runs through here, on the one thread pool (gecko/core/parallel.hpp),
// without the GIL.
//
//   threads_for(n, requested)         how many threads a loop of n elements uses
//   for_each_element(n, threads, f)   f(i) for every i, contiguous blocks per thread
//   for_each_block(n, threads, f)     f(begin, end) once per thread (kernels that take a range)
//   for_each_item(n, threads, f)      f(i) for every i, round robin (items of uneven cost: designs)
//   map_elements(f, threads, a, b..)  out[i] = f(a[i], b[i], ...) over equal-length flat arrays
//
// All of them must be called with the GIL held.
// Errors: a std::domain_error thrown by f at element i is rethrown, after all threads joined and
// with the GIL held again, as element_error (a std::domain_error, so ValueError in Python) whose
// message ends in "(at element i)": the smallest failing i, whatever the thread count. The Python
// face (gecko._vectorize) turns that flat index into the index of the caller's broadcast shape.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <utility>

#include "bindings.hpp"
#include "gecko/core/parallel.hpp"

namespace gecko {
namespace bindings {

// Elements below this per thread are not worth a thread (measured on the elliptic kernels: a
// thread start costs about as much as 2,000 evaluations).
constexpr std::size_t min_elements_per_thread = 16384;

struct element_error : std::domain_error {
  std::size_t index;
  element_error(const std::string& what, std::size_t i)
      : std::domain_error(what + " (at element " + std::to_string(i) + ")"), index(i) {}
};

// requested > 0: exactly that many (capped by n); 0: automatic, up to the hardware's threads with
// at least min_elements_per_thread each. Negative requests are refused by the callers' checks.
inline unsigned threads_for(std::size_t n, int requested) {
  if (requested > 0) return detail::clamp_threads(n, static_cast<unsigned>(requested));
  // Asked once: glibc answers by reading /sys on every call (about 20 us, more than a whole
  // scalar ufunc call).
  static const unsigned hw = std::thread::hardware_concurrency();
  const std::size_t by_size = n / min_elements_per_thread;
  std::size_t nt = hw == 0 ? 1 : hw;
  if (by_size < nt) nt = by_size;
  return nt < 1 ? 1u : static_cast<unsigned>(nt);
}

namespace detail_vectorize {
template <class F>
inline void call_indexed(F& f, std::size_t i) {
  try {
    f(i);
  } catch (const element_error&) {
    throw;
  } catch (const std::domain_error& e) {
    throw element_error(e.what(), i);
  }
}
}  // namespace detail_vectorize

// f(i) for i in [0, n), each thread on its contiguous block, the GIL released. The first failing
// element of each block stops that block; the lowest block's error is rethrown (smallest index).
template <class F>
inline void for_each_element(std::size_t n, unsigned threads, F&& f) {
  py::gil_scoped_release release;
  gecko::detail::parallel_for_blocks(n, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) detail_vectorize::call_indexed(f, i);
  });
}

// f(begin, end) once per thread on its contiguous block, the GIL released (for kernels that loop
// over a range themselves). Errors are rethrown as they are: the kernel knows no element index.
template <class F>
inline void for_each_block(std::size_t n, unsigned threads, F&& f) {
  py::gil_scoped_release release;
  gecko::detail::parallel_for_blocks(n, threads, f);
}

// f(i) round robin over the threads (designs of uneven cost), the GIL released. With several
// threads failing, the error of the lowest-numbered thread is rethrown; callers that need the
// smallest failing index use nan_policy and report statuses instead (the seta batch calls do).
template <class F>
inline void for_each_item(std::size_t n, unsigned threads, F&& f) {
  py::gil_scoped_release release;
  gecko::detail::parallel_for_strided(n, threads, [&](std::size_t i) { detail_vectorize::call_indexed(f, i); });
}

// out[i] = f(in[i]...) over equal-length 1-D arrays (the Python layer broadcasts and flattens).
template <class F, class... Arrays>
inline py::array_t<double> map_elements(F f, int threads, const Arrays&... in) {
  const py::ssize_t n = std::get<0>(std::forward_as_tuple(in...)).size();
  if (((in.ndim() != 1) || ...)) throw std::invalid_argument("gecko._core: array arguments must be one-dimensional");
  if (((in.size() != n) || ...)) throw std::invalid_argument("gecko._core: array arguments must have equal length");
  py::array_t<double> out(n);
  double* o = out.mutable_data();
  const auto ptrs = std::make_tuple(in.data()...);
  for_each_element(static_cast<std::size_t>(n), threads_for(static_cast<std::size_t>(n), threads),
                   [&](std::size_t i) { o[i] = std::apply([&](auto... p) { return f(p[i]...); }, ptrs); });
  return out;
}

}  // namespace bindings
}  // namespace gecko
