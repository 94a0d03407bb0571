// gecko/beam/castigliano.hpp — compliance of a planar curved beam of any centreline z(x), by
// Castigliano's theorem (docs/theory/frictional_adhesion.md "Curved-beam force law"; paper 000 eqs 1, 11 and
// Appendix 1, eqs A1.1–A1.5).
//
// The beam is clamped at x = L and loaded at its tip x = 0 by (F_par, F_perp). With the paper's
// moment M = -(z - z(0)) F_par - x F_perp (A1.1) and, optionally, the axial force along the
// unit tangent t = (1, z') / sqrt(1 + z'^2), N = F_par t_x - F_perp t_z (the same sign
// convention: it makes the straight inclined beam bend only under the force normal to it),
//     U = (1/2EI) int M^2 ds + (1/2EA) int N^2 ds,   D = dU/dF = C F,
//     C_ij = (1/EI) int m_i m_j ds + (1/EA) int a_i a_j ds,   m = (z - z(0), x),  a = (t_x, -t_z).
// With ds = sqrt(1 + z'^2) dx and the substitution x = L t^2 (dx = 2 L t dt) the integrands
//     bending: m_i m_j * hypot(1, z') * 2 L t,
//     axial:   (1, -z')_i (1, -z')_j / hypot(1, z') * 2 L t
// are smooth in t for a tip with z' ~ x^-1/2 (the parabola); tanh-sinh (tanh_sinh.hpp) then
// integrates them, and copes with other integrable endpoint behaviour too.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "gecko/beam/shape.hpp"
#include "gecko/beam/tanh_sinh.hpp"
#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {

// Length along x, bending rigidity, axial rigidity (infinite: inextensible, no axial term).
template <class T>
struct curved_beam {
  T L = T(1);
  T EI = T(1);
  T EA = std::numeric_limits<T>::infinity();
};

template <class T>
struct quadrature_options {
  // Stop when two successive tanh-sinh levels differ by less than tol * max|C_ij|; the error of
  // the result is then far smaller (about tol^2, see tanh_sinh.hpp). 0 picks eps^(2/3).
  T tol = T(0);
  int max_levels = detail::tanh_sinh_table<T>::max_levels;
  quadrature_report<T>* report = nullptr;  // optional: what the quadrature did
};

namespace detail {

template <class T, class Policy>
bool check_beam(const char* function, const curved_beam<T>& beam) {
  using std::isfinite;
  if (!(beam.L > T(0)) || !isfinite(beam.L)) {
    raise_domain_error<T, Policy>(function, "L", beam.L, "0 < L < inf");
    return false;
  }
  if (!(beam.EI > T(0)) || !isfinite(beam.EI)) {
    raise_domain_error<T, Policy>(function, "EI", beam.EI, "0 < EI < inf");
    return false;
  }
  if (!(beam.EA > T(0))) {  // +inf allowed: inextensible
    raise_domain_error<T, Policy>(function, "EA", beam.EA, "EA > 0 (inf: no axial term)");
    return false;
  }
  return true;
}

template <class T>
Eigen::Matrix<T, 2, 2> nan_matrix() {
  return Eigen::Matrix<T, 2, 2>::Constant(std::numeric_limits<T>::quiet_NaN());
}

template <class T, bool Axial, class Shape, class Policy>
Eigen::Matrix<T, 2, 2> castigliano_compliance_imp(const Shape& shape, const curved_beam<T>& beam,
                                                  const quadrature_options<T>& opts) {
  using std::hypot;
  using std::isfinite;
  using std::pow;
  static const char* function = "gecko::castigliano_compliance";
  using V3 = Eigen::Matrix<T, 3, 1>;
  const T L = beam.L;
  const T inv_EI = T(1) / beam.EI;
  const T inv_EA = Axial ? T(1) / beam.EA : T(0);
  const T z0 = static_cast<T>(shape(T(0)));
  if (!isfinite(z0)) {
    raise_domain_error<T, Policy>(function, "shape", z0, "a finite z(0) at the tip x = 0");
    return nan_matrix<T>();
  }
  bool bad = false;
  T bad_value = T(0);
  auto integrand = [&](T t) -> V3 {
    const T x = L * t * t;
    const T z = static_cast<T>(shape(x)) - z0;
    const T dz = detail::shape_slope<T>(shape, x);
    if (!isfinite(z) || !isfinite(dz)) {
      if (!bad) bad_value = isfinite(z) ? dz : z;
      bad = true;
      return V3::Zero();
    }
    const T ds_dx = hypot(T(1), dz);
    const T jac = T(2) * L * t;  // dx/dt
    const T wb = inv_EI * ds_dx * jac;
    V3 c(wb * z * z, wb * z * x, wb * x * x);
    if constexpr (Axial) {
      // dz^2 / ds_dx stays finite where dz blows up (it grows like |dz|).
      const T wa = inv_EA * jac / ds_dx;
      c += V3(wa, -wa * dz, wa * dz * dz);
    }
    return c;
  };
  const T tol = opts.tol > T(0) ? opts.tol
                                : T(pow(std::numeric_limits<T>::epsilon(), T(2) / T(3)));
  quadrature_report<T> report;
  const V3 c = detail::tanh_sinh_unit<T, V3>(integrand, tol, 3, opts.max_levels, report);
  if (opts.report) *opts.report = report;
  if (bad) {
    raise_domain_error<T, Policy>(function, "shape", bad_value,
                                  "finite z(x) and dz/dx for 0 < x < L");
    return nan_matrix<T>();
  }
  if (!report.converged) {
    if constexpr (Policy::on_domain_error == policies::error_action::return_nan) {
      return nan_matrix<T>();
    } else {
      throw std::runtime_error(std::string(function) +
                               ": tanh-sinh quadrature did not converge to the requested tolerance"
                               " (error estimate " + detail::format_value(report.error_estimate) +
                               "); is z(x) smooth on (0, L)?");
    }
  }
  Eigen::Matrix<T, 2, 2> C;
  C << c(0), c(1), c(1), c(2);
  return C;
}

}  // namespace detail

// C (2x2, symmetric) mapping the tip force (F_par, F_perp) to the tip displacement
// (D_par, D_perp) of the beam with centreline shape z(x) (see shape.hpp for what a shape is).
template <class T, class Shape, class Policy = policies::default_policy>
Eigen::Matrix<T, 2, 2> castigliano_compliance(const Shape& shape, const curved_beam<T>& beam,
                                              const quadrature_options<T>& opts = {},
                                              const Policy& = Policy()) {
  if (!detail::check_beam<T, Policy>("gecko::castigliano_compliance", beam))
    return detail::nan_matrix<T>();
  using std::isinf;
  // Inextensible beams never pay for the axial integrands.
  if (isinf(beam.EA))
    return detail::castigliano_compliance_imp<T, false, Shape, Policy>(shape, beam, opts);
  return detail::castigliano_compliance_imp<T, true, Shape, Policy>(shape, beam, opts);
}

}  // namespace gecko
