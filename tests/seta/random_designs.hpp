// Test helper: reproducible random two-level seta designs. splitmix64 rather than <random>'s
// distributions, whose output the standard leaves to the implementation: the same seed gives the
// same designs on every platform, so a failing design can be named by its seed and index.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gecko/seta/two_level_seta.hpp"

namespace seta_test {

// Uniform on [0, 1) with 53 random bits; advances state.
inline double uniform01(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// A design from the box of the design optimiser's sweeps: EI1 in [1, 20], EI2 in [0.1, 5]
// (log-uniform), EA2 in [50, 500], l2 in [0.05, 0.5], alpha1 in [0.3, 1.2], alpha2 in
// [0.05, min(1, pi/2 - alpha1 - 0.05)]; EA1 = inf, l1 = w = 1. Six draws, in this order.
inline gecko::TwoLevelSeta<double> sweep_box_design(std::uint64_t& state) {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = 1 + 19 * uniform01(state);
  s.EI2 = 0.1 * std::exp(std::log(50.0) * uniform01(state));
  s.EA2 = 50 + 450 * uniform01(state);
  s.l2 = 0.05 + 0.45 * uniform01(state);
  s.alpha1 = 0.3 + 0.9 * uniform01(state);
  s.alpha2 = 0.05 + (std::min(1.0, 1.5707963267948966 - s.alpha1 - 0.05) - 0.05) * uniform01(state);
  return s;
}

}  // namespace seta_test
