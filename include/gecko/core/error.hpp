// gecko/core/error.hpp — the one place where gecko reports bad input.
//
// Every kernel routes domain errors through raise_domain_error, so the choice between throwing
// and returning NaN is made once, by the policy (gecko/core/policy.hpp). Messages name the
// function, the argument, its value and the allowed range, e.g.
//   gecko::ellint_f: m = 2 is out of range: need m <= 1, or sin^2(phi) <= 1/m when m > 1
#pragma once

#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gecko/core/policy.hpp"

namespace gecko {
namespace detail {

template <class T>
std::string format_value(T value) {
  std::ostringstream os;
  os.precision(std::numeric_limits<T>::max_digits10);
  os << value;
  return os.str();
}

}  // namespace detail

// function: "gecko::ellint_f"; argument: "m"; range: the allowed range in words.
template <class T, class Policy>
T raise_domain_error(const char* function, const char* argument, T value, const char* range) {
  if constexpr (Policy::on_domain_error == policies::error_action::return_nan) {
    (void)function; (void)argument; (void)value; (void)range;
    return std::numeric_limits<T>::quiet_NaN();
  } else {
    throw std::domain_error(std::string(function) + ": " + argument + " = " +
                            detail::format_value(value) + " is out of range: need " + range);
  }
}

}  // namespace gecko
