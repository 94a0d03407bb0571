// tests/elliptic/legendre_support.hpp — runs F or E over elliptic_legendre.csv for one type.
#pragma once

#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_f.hpp>
#include <gecko/elliptic/legendre_domain.hpp>

#include <string>

#include "elliptic/reference_table.hpp"

namespace gecko_test {

// pi/2 and pi rounded to double (both just below the true values): amplitudes of the edge rows.
const double pio2 = 1.5707963267948966;
const double pi_d = 3.141592653589793;

inline const reference_table& legendre_table() {
  static const reference_table t("elliptic_legendre.csv");
  return t;
}

// which = "F" or "E". T = float: inputs rounded to float, reference = the double kernel at the
// rounded inputs (rows whose rounded inputs leave the domain or the float range are skipped).
// Rows with m > 1 (regions "m_above_one" and "m_above_one_edge", the latter with sin^2 phi
// within an ulp of 1/m) are left out unless `edge` is true.
template <class T, class Fn>
error_tally legendre_tally(const std::string& which, const std::string& what, Fn fn,
                           bool edge = true) {
  const auto& t = legendre_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column(which);
  constexpr bool is_float = sizeof(T) == sizeof(float);
  return tally_table<T>(
      t, what, [&](std::size_t i) { return fn(t.get<T>(i, phi), t.get<T>(i, m)); },
      [&](std::size_t i) -> long double {
        if (is_float) return fn(double(t.get<float>(i, phi)), double(t.get<float>(i, m)));
        return t.value(i, v);
      },
      [&](std::size_t i) {
        if (!edge && t.text(i, t.column("region")).rfind("m_above_one", 0) == 0) return false;
        if (!is_float) return true;
        const double p = t.get<double>(i, phi), mm = t.get<double>(i, m);
        if (!float_representable(p) || !float_representable(mm)) return false;
        const float pf = static_cast<float>(p), mf = static_cast<float>(mm);
        if (mf > 1 && !(gecko::detail::in_domain_m_above_one(pf, mf) &&
                        gecko::detail::in_domain_m_above_one(double(pf), double(mf))))
          return false;
        return float_representable(fn(double(pf), double(mf)));
      });
}

}  // namespace gecko_test
