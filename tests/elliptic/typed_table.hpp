// tests/elliptic/typed_table.hpp — runs one kernel over an mpmath table in any of the tested
// scalar types, so that a table case is written once as a TEMPLATE_TEST_CASE over
// float, double, long double.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include "elliptic/reference_table.hpp"

namespace gecko_test {

template <class T>
std::string scalar_name() {
  return std::is_same<T, float>::value ? "float" : std::is_same<T, double>::value ? "double" : "long double";
}

namespace detail {
// kernel(U(table input in T) ...) for the row's input columns.
template <class T, class U, std::size_t N, class Kernel, std::size_t... I>
auto call_row(const reference_table& t, std::size_t row, const std::array<std::size_t, N>& in,
              const Kernel& kernel, std::index_sequence<I...>) {
  return kernel(static_cast<U>(t.get<T>(row, in[I]))...);
}
}  // namespace detail

// Tallies kernel(T...) over the table's rows, in units of eps(T).
// double, long double: the table's inputs (exact doubles) against its mpmath column `ref`.
// float: the inputs rounded to float, against the double kernel at those same rounded inputs
// (the mpmath value belongs to the unrounded inputs); rows whose inputs do not round to normal
// floats are skipped, and so are rows where float_use(row, reference) is false; reference() is
// the double kernel's value there, computed only if float_use asks for it (so that float_use can
// first rule out rows the double kernel would refuse).
template <class T, std::size_t N, class Kernel, class FloatUse>
error_tally kernel_tally(const reference_table& t, const std::string& what,
                         const std::array<std::size_t, N>& in, std::size_t ref, const Kernel& kernel,
                         const FloatUse& float_use) {
  const std::string name = what + "<" + scalar_name<T>() + ">";
  const auto seq = std::make_index_sequence<N>();
  (void)ref;
  (void)float_use;
  auto eval = [&](std::size_t i) { return detail::call_row<T, T>(t, i, in, kernel, seq); };
  if constexpr (std::is_same<T, float>::value) {
    auto want = [&](std::size_t i) { return detail::call_row<float, double>(t, i, in, kernel, seq); };
    return tally_table<T>(
        t, name, eval, [&](std::size_t i) { return static_cast<long double>(want(i)); },
        [&](std::size_t i) {
          for (std::size_t c : in)
            if (!float_representable(t.get<double>(i, c))) return false;
          return float_use(i, [&] { return want(i); });
        });
  } else {
    return tally_table<T>(
        t, name, eval, [&](std::size_t i) { return t.value(i, ref); }, [](std::size_t) { return true; });
  }
}

template <class T, std::size_t N, class Kernel>
error_tally kernel_tally(const reference_table& t, const std::string& what,
                         const std::array<std::size_t, N>& in, std::size_t ref, const Kernel& kernel) {
  return kernel_tally<T>(t, what, in, ref, kernel, [](std::size_t, const auto&) { return true; });
}

// The complete integrals' table (K and E share it), read once per executable.
inline const reference_table& complete_table() {
  static const reference_table t("elliptic_complete.csv");
  return t;
}

}  // namespace gecko_test
