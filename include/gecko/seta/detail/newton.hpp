// gecko/seta/detail/newton.hpp — safeguarded Newton for the small smooth systems of the seta.
//
// Affine-invariant damped Newton (Deuflhard, "Newton Methods for Nonlinear Problems", 2004,
// NLEQ-ERR): a step lambda dz is accepted when the simplified Newton correction at the trial
// point, dzbar = -J(z)^-1 F(z + lambda dz), is smaller than dz (monotone contraction); otherwise
// lambda is halved. dzbar costs no new Jacobian (the old LU is reused) and doubles as the
// convergence test: once ||dzbar|| <= tol the iterate z + dzbar is accurate to about
// theta ||dzbar||, far below tol. An initial step below tol is accepted without another
// evaluation (its error is O(||dz||^2)). Norms are the system's scaled max norms.
//
// A System provides: n, vec, mat, plan_type, and
//   bool eval(const vec& z, T Ft, const plan_type&, vec& F, mat& J, vec* dF_dFt, T u14[2]) const;
//   T step_norm(const vec& dz, const vec& z) const;
#pragma once

#include <Eigen/Dense>

namespace gecko {
namespace detail {

enum class newton_code { converged, not_converged, singular, invalid_start };

// omega > 0: a known bound of the affine Lipschitz constant of J along the line (estimated by
// the continuation). Then the first step is accepted without another evaluation as soon as the
// Newton-Kantorovich bound of the error after it, omega/2 ||dz||^2, is below tol (a line's dense
// output, gecko/seta/detail/line_output.hpp, where its chord steps did not settle a state).
template <class System, class T>
inline newton_code newton_fixed_ft(const System& sys, typename System::vec& z, T Ft,
                                   const typename System::plan_type& plan, T tol, int max_iterations,
                                   int& iterations, T u14[2], T omega = T(0)) {
  using vec = typename System::vec;
  using mat = typename System::mat;
  vec F, Ft_trial;
  mat J, J_trial;
  T u14_trial[2];
  iterations = 1;
  if (!sys.eval(z, Ft, plan, F, J, nullptr, u14)) return newton_code::invalid_start;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::PartialPivLU<mat> lu(J);
    const vec dz = -lu.solve(F);
    if (!dz.allFinite()) return newton_code::singular;
    const T nd = sys.step_norm(dz, z);
    if (nd <= tol || (omega > 0 && omega * nd * nd <= 2 * tol)) {
      z += dz;
      return newton_code::converged;
    }
    T lambda = 1;
    for (;;) {
      const vec zt = z + lambda * dz;
      ++iterations;
      if (sys.eval(zt, Ft, plan, Ft_trial, J_trial, nullptr, u14_trial)) {
        const vec dzbar = -lu.solve(Ft_trial);
        const T nb = sys.step_norm(dzbar, zt);
        if (nb < nd) {
          z = zt;
          F = Ft_trial;
          J = J_trial;
          u14[0] = u14_trial[0];
          u14[1] = u14_trial[1];
          if (lambda == 1 && nb <= tol) {
            z += dzbar;
            return newton_code::converged;
          }
          break;
        }
      }
      lambda /= 2;
      if (lambda < T(1) / 1024) return newton_code::not_converged;
    }
  }
  return newton_code::not_converged;
}

}  // namespace detail
}  // namespace gecko
