// gecko/friction/detachment.hpp — rate-dependent detachment of a spatula (paper 000 eqs 4, 7, 8,
// A2.6; docs/theory/frictional_adhesion.md "Rate-dependent detachment" and "Spatula stick-slip").
//
//   viscoelastic (eq 7):  G(V) = G0 (1 + (V/V*)^n)
//   plastic / Eyring (eq 8): G(V) = G0 asinh(V/V*)
//   stretch at detachment (A2.6), from the energy balance K_par_par dd^2/2 + f_par1 dd = G(V):
//       dd = (-f_par1 + sqrt(f_par1^2 + 2 K_par_par G)) / K_par_par
//   resonant frequency (eq 4): nu_R = 0.14 (D / L^2) sqrt(E / rho), and t_off ~ 1 / nu_R.
//
// Any callable T(T) is a detachment law too (steady_sliding.hpp takes one); its values are
// checked to be finite and >= 0 where they are used.
#pragma once

#include <cmath>
#include <limits>

#include "gecko/core/error.hpp"
#include "gecko/core/policy.hpp"

namespace gecko {
namespace detail {

template <class T, class Policy>
bool check_velocity(const char* function, T V) {
  using std::isfinite;
  if (!(V >= T(0)) || !isfinite(V)) {
    raise_domain_error<T, Policy>(function, "V", V, "0 <= V < inf (drag velocity)");
    return false;
  }
  return true;
}

template <class T, class Policy>
bool check_positive(const char* function, const char* name, T value, const char* range) {
  using std::isfinite;
  if (!(value > T(0)) || !isfinite(value)) {
    raise_domain_error<T, Policy>(function, name, value, range);
    return false;
  }
  return true;
}

}  // namespace detail

template <class T, class Policy = policies::default_policy>
T viscoelastic_detachment_energy(T V, T G0, T V_star, T n, const Policy& = Policy()) {
  using std::pow;
  static const char* f = "gecko::viscoelastic_detachment";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!detail::check_positive<T, Policy>(f, "G0", G0, "0 < G0 < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "V_star", V_star, "0 < V_star < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "n", n, "0 < n < inf")) return nan;
  if (!detail::check_velocity<T, Policy>(f, V)) return nan;
  return G0 * (T(1) + pow(V / V_star, n));  // paper 000 eq (7)
}

template <class T, class Policy = policies::default_policy>
T eyring_detachment_energy(T V, T G0, T V_star, const Policy& = Policy()) {
  using std::asinh;
  static const char* f = "gecko::eyring_detachment";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!detail::check_positive<T, Policy>(f, "G0", G0, "0 < G0 < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "V_star", V_star, "0 < V_star < inf")) return nan;
  if (!detail::check_velocity<T, Policy>(f, V)) return nan;
  return G0 * asinh(V / V_star);  // paper 000 eq (8)
}

// The two laws as function objects (what steady_sliding, simulate_spatulae and the fit take).
template <class T, class Policy = policies::default_policy>
struct viscoelastic_detachment {
  T G0, V_star, n;
  T operator()(T V) const { return viscoelastic_detachment_energy<T>(V, G0, V_star, n, Policy()); }
};

template <class T, class Policy = policies::default_policy>
struct eyring_detachment {
  T G0, V_star;
  T operator()(T V) const { return eyring_detachment_energy<T>(V, G0, V_star, Policy()); }
};

// Paper 000 eq (A2.6), in the form without cancellation for either sign of f_par1.
template <class T, class Policy = policies::default_policy>
T detachment_stretch(T K_par_par, T f_par1, T G, const Policy& = Policy()) {
  using std::isfinite;
  using std::sqrt;
  static const char* f = "gecko::detachment_stretch";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!detail::check_positive<T, Policy>(f, "K_par_par", K_par_par, "0 < K_par_par < inf"))
    return nan;
  if (!isfinite(f_par1)) return raise_domain_error<T, Policy>(f, "f_par1", f_par1, "finite f_par1");
  if (!(G >= T(0)) || !isfinite(G))
    return raise_domain_error<T, Policy>(f, "G", G, "0 <= G < inf (detachment energy)");
  const T q = sqrt(f_par1 * f_par1 + T(2) * K_par_par * G);
  // f_par1 > 0: -f + q cancels; multiply by (f + q)/(f + q) instead.
  return f_par1 > T(0) ? T(2) * G / (f_par1 + q) : (q - f_par1) / K_par_par;
}

// Eq 4: resonant frequency of a cantilevered spatula of diameter D and length L. For D = 100 nm,
// L = 1 um, E = 1.5 GPa, rho = 1000 kg/m^3 this gives 17.1 MHz; the paper prints 34.3 MHz, twice
// what its own formula gives (docs/theory/frictional_adhesion.md), so its t_off ~ 0.03 us is really ~ 0.06 us.
template <class T, class Policy = policies::default_policy>
T resonant_frequency(T D, T L, T E, T rho, const Policy& = Policy()) {
  using std::sqrt;
  static const char* f = "gecko::resonant_frequency";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  if (!detail::check_positive<T, Policy>(f, "D", D, "0 < D < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "L", L, "0 < L < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "E", E, "0 < E < inf")) return nan;
  if (!detail::check_positive<T, Policy>(f, "rho", rho, "0 < rho < inf")) return nan;
  return T(0.14) * (D / (L * L)) * sqrt(E / rho);  // paper 000 eq (4)
}

}  // namespace gecko
