// gecko/friction/force_trace.hpp — tip force f(t) = K d(t) along a displacement path
// (paper 000 eqs 1–3 and 11–13, Figs 4 and 8; docs/theory/frictional_adhesion.md). Arrays ready to plot.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <vector>

#include "gecko/beam/rigidity.hpp"
#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"
#include "gecko/friction/path.hpp"

namespace gecko {

template <class T>
struct force_trace_result {
  std::vector<T> t, d_par, d_perp, f_par, f_perp;
};

namespace detail {

template <class T>
void push_sample(force_trace_result<T>& r, const Eigen::Matrix<T, 2, 2>& K,
                 const displacement_path<T>& path, T time) {
  const Eigen::Matrix<T, 2, 1> d = path_at(path, time);
  const Eigen::Matrix<T, 2, 1> f = K * d;  // f = K d, paper 000 eqs (1) and (11)
  r.t.push_back(time);
  r.d_par.push_back(d(0));
  r.d_perp.push_back(d(1));
  r.f_par.push_back(f(0));
  r.f_perp.push_back(f(1));
}

}  // namespace detail

// At the given times (each in [t.front(), t.back()]); K symmetric positive definite.
template <class T, class Policy = policies::default_policy>
force_trace_result<T> force_trace(const Eigen::Matrix<T, 2, 2>& K, const displacement_path<T>& path,
                                  const std::vector<T>& times, const Policy& = Policy()) {
  static const char* function = "gecko::force_trace";
  force_trace_result<T> r;
  if (!detail::check_spd<T, Policy>(function, "K", K) ||
      !detail::check_path<T, Policy>(function, path))
    return r;
  for (T time : times) {
    if (!(time >= path.t.front() && time <= path.t.back())) {
      raise_domain_error<T, Policy>(function, "times", time,
                                    "t[0] <= time <= t[last] (inside the path)");
      const T nan = std::numeric_limits<T>::quiet_NaN();
      r.t.push_back(time);
      r.d_par.push_back(nan);
      r.d_perp.push_back(nan);
      r.f_par.push_back(nan);
      r.f_perp.push_back(nan);
      continue;
    }
    detail::push_sample(r, K, path, time);
  }
  return r;
}

// Uniformly: samples_per_segment points on every leg, every vertex included exactly (so the
// corners of Figs 4 and 8 are on the curve).
template <class T, class Policy = policies::default_policy>
force_trace_result<T> force_trace(const Eigen::Matrix<T, 2, 2>& K, const displacement_path<T>& path,
                                  int samples_per_segment = 50, const Policy& = Policy()) {
  static const char* function = "gecko::force_trace";
  force_trace_result<T> r;
  if (!detail::check_spd<T, Policy>(function, "K", K) ||
      !detail::check_path<T, Policy>(function, path))
    return r;
  if (samples_per_segment < 1) {
    raise_domain_error<T, Policy>(function, "samples_per_segment", T(samples_per_segment),
                                  "samples_per_segment >= 1");
    return r;
  }
  for (std::size_t i = 0; i + 1 < path.t.size(); ++i) {
    for (int j = 0; j < samples_per_segment; ++j) {
      const T s = T(j) / T(samples_per_segment);
      detail::push_sample(r, K, path, path.t[i] + s * (path.t[i + 1] - path.t[i]));
    }
  }
  detail::push_sample(r, K, path, path.t.back());
  return r;
}

}  // namespace gecko
