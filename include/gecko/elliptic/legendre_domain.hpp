// gecko/elliptic/legendre_domain.hpp — argument checks shared by ellint_f and ellint_e.
//
// Real domain of F(phi|m), E(phi|m): any finite phi when m <= 1; for m > 1 the integrand
// 1/sqrt(1 - m sin^2 theta) must stay real on [0, phi], i.e. |phi| <= arcsin(1/sqrt m)
// (equivalently |phi| <= pi/2 and sin^2 phi <= 1/m; DLMF 19.2.4 with 19.7.4).
// Delta^2 = 1 - m sin^2 phi is formed with one fused multiply-add; at the boundary a value a few
// ulps below zero is the rounding of an exact zero and is accepted (and clamped to 0).
#pragma once

#include <cmath>
#include <limits>

#include "gecko/elliptic/angle_reduction.hpp"

namespace gecko {
namespace detail {

// 1 - m s^2 for m > 1 (s = sin phi >= 0), before clamping.
template <class T>
inline T delta2_m_above_one(T s, T m) {
  using std::fma;
  return fma(-(m * s), s, T(1));
}

// Tolerance for the boundary test: rounding of sin phi (1/2 ulp, doubled by squaring) and of
// m*s (1/2 ulp), with margin.
template <class T>
constexpr T delta2_boundary_slack() {
  return 4 * std::numeric_limits<T>::epsilon();
}

// True when (phi, m) with m > 1 lies in the real domain (up to rounding at the boundary).
template <class T>
inline bool in_domain_m_above_one(T phi, T m) {
  using std::fabs;
  using std::sin;
  const T a = fabs(phi);
  if (!(a <= pi_constants<T>::pio2_below)) return false;
  return delta2_m_above_one(sin(a), m) >= -delta2_boundary_slack<T>();
}

constexpr const char* legendre_m_range = "m <= 1, or sin^2(phi) <= 1/m with |phi| <= pi/2 when m > 1";

}  // namespace detail
}  // namespace gecko
