// The one place that turns "is each level's fiber extensible?" into compile-time flags.
//
// A level with EA = +infinity is inextensible: its stretching terms vanish identically
// (1/EA = 0), so the kernels are instantiated without them rather than multiplying by zero at
// run time. Every public entry point that needs the flags calls visit_extensibility instead of
// spelling out the four (or two) branches itself:
//
//   return detail::visit_extensibility(seta, [&](auto E1, auto E2) {
//     return detail::kernel_imp<Policy, decltype(E1)::value, decltype(E2)::value>(...);
//   });
//
// f receives std::integral_constant<bool, E> arguments (std::true_type when extensible).
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include "gecko/seta/two_level_seta.hpp"

namespace gecko {
namespace detail {

// Two levels: f(std::integral_constant<bool, e1>{}, std::integral_constant<bool, e2>{}).
template <class F>
inline decltype(auto) visit_extensibility(bool e1, bool e2, F&& f) {
  using yes = std::true_type;
  using no = std::false_type;
  if (e1 && e2) return std::forward<F>(f)(yes{}, yes{});
  if (e1) return std::forward<F>(f)(yes{}, no{});
  if (e2) return std::forward<F>(f)(no{}, yes{});
  return std::forward<F>(f)(no{}, no{});
}

// One level (a single fiber): f(std::integral_constant<bool, e>{}).
template <class F>
inline decltype(auto) visit_extensibility(bool e, F&& f) {
  if (e) return std::forward<F>(f)(std::true_type{});
  return std::forward<F>(f)(std::false_type{});
}

// Level i is extensible when its EA is finite (EA = +infinity means inextensible).
template <class T>
inline bool is_extensible(const T& EA) {
  using std::isinf;
  return !isinf(EA);
}

template <class T, class F>
inline decltype(auto) visit_extensibility(const TwoLevelSeta<T>& seta, F&& f) {
  return visit_extensibility(is_extensible(seta.EA1), is_extensible(seta.EA2), std::forward<F>(f));
}

}  // namespace detail
}  // namespace gecko
