// gecko/beam/tanh_sinh.hpp — tanh-sinh (double-exponential) quadrature on (0, 1).
//
// Used by castigliano.hpp for the compliance integrals of docs/theory/frictional_adhesion.md (Appendix 1 of paper
// 000). After the substitution x = L t^2 a tip with ds/dx ~ x^-1/2 (the parabola) gives a smooth
// integrand in t, where tanh-sinh converges double-exponentially; any remaining algebraic
// endpoint singularity (a shape with z' ~ x^-2/3, say) is still integrated to full accuracy,
// which a Gauss rule would not do. Nodes (Takahasi & Mori 1974):
//     t(u) = 1 / (1 + exp(-pi sinh u)),   dt/du = pi cosh(u) t (1 - t),
// on the grid u = j h, halving h level by level and reusing every earlier node. The error of
// level k is roughly the square of that of level k-1, so the difference between two levels
// overestimates the error of the finer one by far; stopping when it is below tol gives an
// actual error near tol^2 once the rule is in its double-exponential regime.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace gecko {

// What a quadrature did: filled in when a pointer to it is passed in the options.
template <class T>
struct quadrature_report {
  T error_estimate = T(0);  // max |I_k - I_(k-1)| over the components, absolute
  int levels = 0;           // finest level used (step 2^-levels)
  int evaluations = 0;      // integrand calls
  bool converged = false;
};

namespace detail {

template <class T>
class tanh_sinh_table {
 public:
  static constexpr int max_levels = 9;

  struct node {
    T t;  // abscissa in (0, 1)
    T w;  // dt/du at this node
  };

  // levels()[0]: u = j (integers); levels()[k], k >= 1: the new nodes u = (2j - 1) 2^-k.
  static const std::vector<std::vector<node>>& levels() {
    static const tanh_sinh_table table;  // thread-safe one-time construction (C++11)
    return table.levels_;
  }

 private:
  tanh_sinh_table() : levels_(max_levels + 1) {
    for (int k = 0; k <= max_levels; ++k) {
      const T h = std::ldexp(T(1), -k);
      // Level 0 takes every integer; finer levels only the odd multiples of their step.
      const long step = (k == 0) ? 1 : 2;
      const long first = (k == 0) ? 0 : 1;
      for (long j = first;; j += step) {
        const T u = T(j) * h;
        bool any = false;
        for (int sign = (j == 0 ? 1 : -1); sign <= 1; sign += 2) {
          node nd;
          if (keep(sign * u, nd)) {
            levels_[k].push_back(nd);
            any = true;
          }
        }
        if (!any) break;
      }
    }
  }

  // Near t = 0 keep nodes down to eps^2 (the weights there are negligible, and x = L t^2 stays a
  // normal number even for float); near t = 1 stop where t would round to 1, so that a clamp-end
  // singularity is never evaluated. The dropped tails are the integrand times the dropped
  // length (eps^2 and eps): below rounding for any bounded integrand.
  static bool keep(T u, node& nd) {
    using std::cosh;
    using std::exp;
    using std::sinh;
    const T pi = T(3.141592653589793238462643383279502884L);
    constexpr T eps = std::numeric_limits<T>::epsilon();
    const T e = pi * sinh(u);
    // t and 1 - t each computed without cancellation.
    const T t = T(1) / (T(1) + exp(-e));
    const T one_minus_t = T(1) / (T(1) + exp(e));
    if (t < eps * eps || one_minus_t < eps) return false;
    nd.t = t;
    nd.w = pi * cosh(u) * t * one_minus_t;
    return true;
  }

  std::vector<std::vector<node>> levels_;
};

// Integrates a vector-valued f over (0, 1). V is a fixed-size Eigen vector (or anything with
// +=, * scalar, and cwiseAbs().maxCoeff()). Stops when max|I_k - I_(k-1)| <= tol * max|I_k|
// after at least min_levels levels.
template <class T, class V, class F>
V tanh_sinh_unit(F&& f, T tol, int min_levels, int max_levels, quadrature_report<T>& report) {
  const auto& levels = tanh_sinh_table<T>::levels();
  if (max_levels > tanh_sinh_table<T>::max_levels) max_levels = tanh_sinh_table<T>::max_levels;
  V sum = V::Zero();
  V previous = V::Zero();
  report = quadrature_report<T>{};
  for (int k = 0; k <= max_levels; ++k) {
    for (const auto& nd : levels[k]) {
      sum += nd.w * f(nd.t);
      ++report.evaluations;
    }
    const V current = sum * std::ldexp(T(1), -k);
    report.levels = k;
    if (k > 0) {
      report.error_estimate = (current - previous).cwiseAbs().maxCoeff();
      const T scale = current.cwiseAbs().maxCoeff();
      if (k >= min_levels && report.error_estimate <= tol * scale) {
        report.converged = true;
        return current;
      }
    }
    previous = current;
  }
  return previous;
}

}  // namespace detail
}  // namespace gecko
