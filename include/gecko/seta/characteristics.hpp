// gecko/seta/characteristics.hpp — the characteristic quantities of a two-level seta
// (models.md §1, "Critical line of adhesion" and "Small-deformation approximations"):
//   (Fn)0           critical Fn at Ft = 0 (> 0: not sticky at rest, like a gecko)
//   slope k         dFn/dFt at Ft = 0, the exact tangent of the line (the linear theory's k, eq 21,
//                   is the slope of its straight line; both are reported)
//   max pull-off    -min Fn along the line followed from Ft = 0 and the Ft where it occurs,
//                   refined to dFn/dFt = 0 by a safeguarded secant on the exact slope
//                   (implicit differentiation of the converged residual)
//   (Ft)max         sqrt(2 EA2 w), and Fn where the line ends there
//   sticky at rest  (Fn)0 < 0
// next to the small-deformation formulas (gecko/peel/small_deformation.hpp).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "gecko/peel/small_deformation.hpp"
#include "gecko/seta/critical_line.hpp"

namespace gecko {

template <class T>
struct seta_characteristics {
  T fn0 = std::numeric_limits<T>::quiet_NaN();
  T slope_k = std::numeric_limits<T>::quiet_NaN();
  T min_fn = std::numeric_limits<T>::quiet_NaN();       // most tensile critical Fn on the line
  T ft_at_min_fn = std::numeric_limits<T>::quiet_NaN();
  bool min_fn_interior = false;   // false: the minimum sits at the end of the followed range
  T max_pull_off = std::numeric_limits<T>::quiet_NaN();  // max(0, -min_fn)
  T ft_max = std::numeric_limits<T>::quiet_NaN();        // sqrt(2 EA2 w)
  T ft_at_line_end = std::numeric_limits<T>::quiet_NaN();
  T fn_at_line_end = std::numeric_limits<T>::quiet_NaN();
  bool sticky_at_rest = false;
  line_end end = line_end::no_natural_state;
  std::vector<T> folds;
  small_deformation_line<T> small;  // the linear theory's (Fn)0, k, contact length, criterion
};

namespace detail {

// dFn/dmu and the state at mu (Newton from z), or false.
template <class System, class T>
inline bool slope_at(const System& sys, typename System::vec& z, T mu, typename System::plan_type& plan,
                     T& dfn) {
  int its = 0;
  if (solve_with_plans(sys, z, mu, plan, T(1e-13), 40, its) != critical_status::converged) return false;
  typename System::vec F, JF;
  typename System::mat J;
  T u14[2];
  if (!sys.eval(z, mu, plan, F, J, &JF, u14)) return false;
  const typename System::vec dz = -J.partialPivLu().solve(JF);
  dfn = dz[0];
  return std::isfinite(dfn);
}

template <class Policy, bool E1, bool E2, class T>
inline seta_characteristics<T> characteristics_imp(const TwoLevelSeta<T>& s, const critical_line_options<T>& opt) {
  using System = seta_system<T, Policy, E1, E2>;
  const System sys(make_seta_params(s));
  seta_characteristics<T> c;
  c.small = small_deformation(s, Policy());
  c.ft_max = ft_max(s);
  const T end = opt.ft_end == opt.ft_end ? opt.ft_end : default_ft_end(s);
  using std::fabs; using std::sqrt;
  const T scale = std::max(fabs(end), sqrt(s.EI1 * s.w) / s.l1);
  typename System::vec z0;
  typename System::plan_type plan0;
  critical_state<T> natural;
  traced_line<System> line;
  if (!trace(sys, end, scale, opt, 0, z0, plan0, natural, line)) {
    c.end = line.end;
    return c;
  }
  c.end = line.end;
  for (T f : line.folds) c.folds.push_back(sys.ft_of(f));
  c.fn0 = natural.Fn;
  c.sticky_at_rest = natural.Fn < 0;
  // Slope at Ft = 0 (dFt/dmu = 1 there).
  {
    auto z = z0;
    auto plan = plan0;
    T d;
    if (slope_at(sys, z, T(0), plan, d)) c.slope_k = d;
  }
  const auto& nodes = line.nodes;
  c.ft_at_line_end = sys.ft_of(nodes.back().Ft);
  c.fn_at_line_end = nodes.back().z[0];
  std::size_t imin = 0;
  for (std::size_t i = 1; i < nodes.size(); ++i)
    if (nodes[i].z[0] < nodes[imin].z[0]) imin = i;
  c.min_fn = nodes[imin].z[0];
  c.ft_at_min_fn = sys.ft_of(nodes[imin].Ft);
  c.min_fn_interior = imin > 0 && imin + 1 < nodes.size();
  if (c.min_fn_interior) {
    // g(mu) = dFn/dmu changes sign between the neighbours; Illinois false position on g.
    T a = nodes[imin - 1].Ft, b = nodes[imin + 1].Ft;
    auto guess = [&](T mu) {
      const std::size_t k = mu <= nodes[imin].Ft ? imin - 1 : imin;
      typename System::vec z;
      if (!hermite_guess(nodes[k], nodes[k + 1], mu, z)) z = nodes[imin].z;
      return z;
    };
    auto g = [&](T mu, T& fn, bool& ok) {
      auto z = guess(mu);
      auto plan = line.plans[imin];
      T d = 0;
      ok = slope_at(sys, z, mu, plan, d);
      fn = z[0];
      return d;
    };
    bool oka, okb;
    T fa, fb;
    T ga = g(a, fa, oka), gb = g(b, fb, okb);
    if (oka && okb && ga < 0 && gb > 0) {
      int side = 0;
      T best_mu = nodes[imin].Ft, best_fn = nodes[imin].z[0];
      for (int it = 0; it < 60 && fabs(b - a) > T(1e-13) * scale; ++it) {
        T m = (a * gb - b * ga) / (gb - ga);
        if (!(m > a && m < b)) m = (a + b) / 2;
        bool ok;
        T fm;
        const T gm = g(m, fm, ok);
        if (!ok) break;
        if (fm < best_fn) {
          best_fn = fm;
          best_mu = m;
        }
        if (gm == 0) {
          a = b = m;
          break;
        }
        if (gm < 0) {
          a = m;
          ga = gm;
          if (side == -1) gb /= 2;
          side = -1;
        } else {
          b = m;
          gb = gm;
          if (side == 1) ga /= 2;
          side = 1;
        }
      }
      c.min_fn = best_fn;
      c.ft_at_min_fn = sys.ft_of(best_mu);
    }
  }
  c.max_pull_off = c.min_fn < 0 ? -c.min_fn : T(0);
  return c;
}

}  // namespace detail

template <class T, class Policy = policies::default_policy>
inline seta_characteristics<T> characteristics(const TwoLevelSeta<T>& seta,
                                               const critical_line_options<T>& options = critical_line_options<T>(),
                                               const Policy& = Policy()) {
  using std::isinf;
  constexpr const char* fn = "gecko::characteristics";
  if (!detail::check_seta<T, Policy>(seta, fn)) return seta_characteristics<T>();
  if (options.ft_end == options.ft_end && !detail::check_ft<T, Policy>(options.ft_end, ft_max(seta), fn))
    return seta_characteristics<T>();
  const bool e1 = !isinf(seta.EA1), e2 = !isinf(seta.EA2);
  if (e1 && e2) return detail::characteristics_imp<Policy, true, true>(seta, options);
  if (e1) return detail::characteristics_imp<Policy, true, false>(seta, options);
  if (e2) return detail::characteristics_imp<Policy, false, true>(seta, options);
  return detail::characteristics_imp<Policy, false, false>(seta, options);
}

}  // namespace gecko
