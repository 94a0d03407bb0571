// gecko/beam/rigidity.hpp — rigidity K = C^-1 of a tip compliance C, and the checks a rigidity
// matrix must pass (docs/theory/frictional_adhesion.md: f = K d with K symmetric, K_par_par > 0, K_perp_perp > 0,
// K_par_perp = K_perp_par < 0; paper 000 eq 1).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {
namespace detail {

// a d - b c with one rounding error (Kahan): the compliance of a curved beam is ill-conditioned
// (det/C11^2 ~ 0.1 for the parabola), and the naive product difference would lose digits that
// the quadrature worked for.
template <class T>
T det2(T a, T b, T c, T d) {
  using std::fma;
  const T w = b * c;
  const T e = fma(-b, c, w);  // exact rounding error of w
  const T f = fma(a, d, -w);
  return f + e;
}

// Symmetric (to 8 eps of the largest entry) and positive definite; name is the argument.
template <class T, class Policy>
bool check_spd(const char* function, const char* name, const Eigen::Matrix<T, 2, 2>& M) {
  using std::abs;
  using std::isfinite;
  if (!M.allFinite()) {
    raise_domain_error<T, Policy>(function, name, M.sum(), "a finite matrix");
    return false;
  }
  const T scale = M.cwiseAbs().maxCoeff();
  const T asym = M(0, 1) - M(1, 0);
  if (abs(asym) > T(8) * std::numeric_limits<T>::epsilon() * scale) {
    raise_domain_error<T, Policy>(function, name, asym,
                                  "a symmetric matrix: M(0,1) - M(1,0) = 0 (to 8 eps)");
    return false;
  }
  if (!(M(0, 0) > T(0))) {
    raise_domain_error<T, Policy>(function, name, M(0, 0),
                                  "positive definite: M(0,0) > 0 and det M > 0");
    return false;
  }
  const T det = det2(M(0, 0), M(0, 1), M(1, 0), M(1, 1));
  if (!(det > T(0))) {
    raise_domain_error<T, Policy>(function, name, det,
                                  "positive definite: M(0,0) > 0 and det M > 0");
    return false;
  }
  return true;
}

// The frictional-adhesion models need the coupling K_par_perp < 0 as well (paper 000 eq 1).
template <class T, class Policy>
bool check_coupled_rigidity(const char* function, const Eigen::Matrix<T, 2, 2>& K) {
  if (!check_spd<T, Policy>(function, "K", K)) return false;
  if (!(K(0, 1) < T(0))) {
    raise_domain_error<T, Policy>(function, "K", K(0, 1),
                                  "coupling K(0,1) = K_par_perp < 0 (paper 000 eq 1)");
    return false;
  }
  return true;
}

template <class T>
Eigen::Matrix<T, 2, 2> inverse_spd2(const Eigen::Matrix<T, 2, 2>& M) {
  const T det = det2(M(0, 0), M(0, 1), M(1, 0), M(1, 1));
  Eigen::Matrix<T, 2, 2> inv;
  const T off = -M(0, 1) / det;
  inv << M(1, 1) / det, off, off, M(0, 0) / det;  // exactly symmetric
  return inv;
}

}  // namespace detail

// K = C^-1 for a symmetric positive definite compliance C (else a domain error naming "C").
template <class T, class Policy = policies::default_policy>
Eigen::Matrix<T, 2, 2> rigidity(const Eigen::Matrix<T, 2, 2>& C, const Policy& = Policy()) {
  if (!detail::check_spd<T, Policy>("gecko::rigidity", "C", C))
    return Eigen::Matrix<T, 2, 2>::Constant(std::numeric_limits<T>::quiet_NaN());
  return detail::inverse_spd2(C);
}

}  // namespace gecko
