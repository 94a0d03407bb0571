// gecko/friction/path.hpp — piecewise-linear displacement paths (d_par, d_perp)(t) and the
// paper's two: the spatula of Fig 4 (paper 000 eq 3) and the seta loop of Fig 8 (eq 13);
// and the paper's illustrative rigidity K = [[5, -3], [-3, 2]] (eqs 2 and 12). docs/theory/frictional_adhesion.md.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {

// Vertices of the path: at time t[i] the tip displacement is (d_par[i], d_perp[i]); straight
// lines in between. Times must increase strictly.
template <class T>
struct displacement_path {
  std::vector<T> t;
  std::vector<T> d_par;
  std::vector<T> d_perp;
};

// Paper 000 eqs 2 and 12 (arbitrary units): the normalised parabolic-beam rigidity, rounded.
template <class T>
Eigen::Matrix<T, 2, 2> paper_rigidity() {
  Eigen::Matrix<T, 2, 2> K;
  K << T(5), T(-3), T(-3), T(2);
  return K;
}

// Fig 4 / eq 3: load (0,0) -> (0,1) by t = 0.5 s, then drag -> (3,1) by t = 2 s.
template <class T>
displacement_path<T> fig4_spatula_path() {
  return {{T(0), T(0.5), T(2)}, {T(0), T(0), T(3)}, {T(0), T(1), T(1)}};
}

// Fig 8 / eq 13: load (0,0) -> (4,7), drag -> (6,7), pull -> (0,0). The paper gives no times;
// each leg takes one time unit here (only the order matters for the force-space loop).
template <class T>
displacement_path<T> fig8_seta_path() {
  return {{T(0), T(1), T(2), T(3)}, {T(0), T(4), T(6), T(0)}, {T(0), T(7), T(7), T(0)}};
}

namespace detail {

template <class T, class Policy>
bool check_path(const char* function, const displacement_path<T>& p) {
  using std::isfinite;
  if (p.t.size() < 2) {
    raise_domain_error<T, Policy>(function, "t", T(p.t.size()), "at least 2 path vertices");
    return false;
  }
  if (p.d_par.size() != p.t.size() || p.d_perp.size() != p.t.size()) {
    raise_domain_error<T, Policy>(function, "d_par", T(p.d_par.size()),
                                  "t, d_par and d_perp of equal length");
    return false;
  }
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    if (!isfinite(p.t[i])) {
      raise_domain_error<T, Policy>(function, "t", p.t[i], "finite path times");
      return false;
    }
    if (i > 0 && !(p.t[i] > p.t[i - 1])) {
      raise_domain_error<T, Policy>(function, "t", p.t[i],
                                    "strictly increasing path times t[i] > t[i-1]");
      return false;
    }
    if (!isfinite(p.d_par[i])) {
      raise_domain_error<T, Policy>(function, "d_par", p.d_par[i], "finite displacements");
      return false;
    }
    if (!isfinite(p.d_perp[i])) {
      raise_domain_error<T, Policy>(function, "d_perp", p.d_perp[i], "finite displacements");
      return false;
    }
  }
  return true;
}

// Displacement at time `time` in [t.front(), t.back()] (checked by the caller).
template <class T>
Eigen::Matrix<T, 2, 1> path_at(const displacement_path<T>& p, T time) {
  // Segment i: t[i] <= time <= t[i+1]; the last vertex belongs to the last segment.
  auto it = std::upper_bound(p.t.begin(), p.t.end(), time);
  std::size_t i = static_cast<std::size_t>(it - p.t.begin());
  i = (i == 0) ? 0 : i - 1;
  if (i >= p.t.size() - 1) i = p.t.size() - 2;
  const T s = (time - p.t[i]) / (p.t[i + 1] - p.t[i]);
  // Written as a + s (b - a) and, at s = 1, exactly b: vertices are reproduced exactly.
  Eigen::Matrix<T, 2, 1> d;
  if (s == T(1)) {
    d << p.d_par[i + 1], p.d_perp[i + 1];
  } else {
    d << p.d_par[i] + s * (p.d_par[i + 1] - p.d_par[i]),
        p.d_perp[i] + s * (p.d_perp[i + 1] - p.d_perp[i]);
  }
  return d;
}

}  // namespace detail
}  // namespace gecko
