// gecko/core/policy.hpp — what a kernel does on bad input, and how hard it works for accuracy.
//
// Modelled on Boost.Math policies, reduced to the two choices gecko needs:
//   * on a domain error: throw std::domain_error (default) or return NaN (batch calls), and
//   * the precision target: full precision of the scalar type (default) or a coarser relative
//     accuracy 2^-Bits, which lets the Carlson duplication stop earlier (run time against error).
#pragma once

namespace gecko {
namespace policies {

enum class error_action { throw_domain_error, return_nan };

template <error_action OnDomainError = error_action::throw_domain_error, unsigned PrecisionBits = 0>
struct policy {
  static constexpr error_action on_domain_error = OnDomainError;
  // 0 means "full precision of the scalar type"; otherwise the target relative error is
  // about 2^-PrecisionBits (capped at the type's own precision).
  static constexpr unsigned precision_bits = PrecisionBits;
};

using default_policy = policy<>;
// Batch calls: a bad element becomes NaN instead of aborting the whole array.
using nan_policy = policy<error_action::return_nan>;
// Trade accuracy for speed: relative error about 2^-Bits.
template <unsigned Bits, error_action OnDomainError = error_action::throw_domain_error>
using precision = policy<OnDomainError, Bits>;

}  // namespace policies
}  // namespace gecko
