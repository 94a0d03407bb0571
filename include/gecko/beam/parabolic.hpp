// gecko/beam/parabolic.hpp — closed-form compliance and rigidity of the parabolic beam
// z = sqrt(L x)/2 (paper 000 Appendix 1, eq A1.5; docs/theory/frictional_adhesion.md with the corrected sign of a11):
//     C = (L^3 / 2EI) [[a11, a12], [a12, a22]],
//     a11 = 33 sqrt17/512 - ln(4 + sqrt17)/2048,   a12 = (391 sqrt17 + 1)/3840,
//     a22 = 2077 sqrt17/12288 + ln(4 + sqrt17)/16384.
// Bending only (inextensible). K = C^-1 normalises to [[5, -3.0134], [-3.0134, 1.8989]].
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "gecko/beam/castigliano.hpp"
#include "gecko/beam/rigidity.hpp"
#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {
namespace detail {

// The dimensionless matrix a of A1.5, in T. (Evaluated from sqrt and log rather than stored so
// that it is correctly rounded-ish in every T, long double included.)
template <class T>
Eigen::Matrix<T, 2, 2> parabolic_beam_coefficients() {
  using std::log;
  using std::sqrt;
  const T s17 = sqrt(T(17));
  const T lg = log(T(4) + s17);
  const T a11 = T(33) * s17 / T(512) - lg / T(2048);
  const T a12 = (T(391) * s17 + T(1)) / T(3840);
  const T a22 = T(2077) * s17 / T(12288) + lg / T(16384);
  Eigen::Matrix<T, 2, 2> a;
  a << a11, a12, a12, a22;
  return a;
}

}  // namespace detail

template <class T, class Policy = policies::default_policy>
Eigen::Matrix<T, 2, 2> parabolic_beam_compliance(T L, T EI, const Policy& = Policy()) {
  if (!detail::check_beam<T, Policy>("gecko::parabolic_beam_compliance", curved_beam<T>{L, EI}))
    return detail::nan_matrix<T>();
  return (L * L * L / (T(2) * EI)) * detail::parabolic_beam_coefficients<T>();
}

template <class T, class Policy = policies::default_policy>
Eigen::Matrix<T, 2, 2> parabolic_beam_rigidity(T L, T EI, const Policy& = Policy()) {
  if (!detail::check_beam<T, Policy>("gecko::parabolic_beam_rigidity", curved_beam<T>{L, EI}))
    return detail::nan_matrix<T>();
  return (T(2) * EI / (L * L * L)) * detail::inverse_spd2(detail::parabolic_beam_coefficients<T>());
}

}  // namespace gecko
