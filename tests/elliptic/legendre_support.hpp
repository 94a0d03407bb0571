// tests/elliptic/legendre_support.hpp — runs F or E over elliptic_legendre.csv for one type.
#pragma once

#include <gecko/elliptic/ellint_e.hpp>
#include <gecko/elliptic/ellint_f.hpp>
#include <gecko/elliptic/legendre_domain.hpp>

#include <string>

#include "elliptic/reference_table.hpp"

namespace gecko_test {

inline const reference_table& legendre_table() {
  static const reference_table t("elliptic_legendre.csv");
  return t;
}

// which = "F" or "E". T = float: inputs rounded to float, reference = the double kernel at the
// rounded inputs (rows whose rounded inputs leave the domain or the float range are skipped).
// Rows with m > 1 (regions "m_above_one" and "m_above_one_edge", the latter with sin^2 phi
// within an ulp of 1/m) are left out unless `edge` is true; see legendre_edge_excess for them.
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

// For m > 1, near the edge, F is ill-conditioned: a correctly rounded sin(phi) (relative error
// eps/2) and the rounding of m*sin(phi) in Delta^2 = 1 - m sin^2(phi) move F by up to
// kappa_s * eps * 3/4, kappa_s = |d ln F / d ln sin phi| from the table. Returns the worst
// err / (bound + kappa_s) over those rows (<= 1 means every row is within bound + kappa_s eps).
template <class T, class Fn>
long double legendre_edge_excess(const std::string& which, long double bound, Fn fn) {
  const auto& t = legendre_table();
  const auto phi = t.column("phi"), m = t.column("m"), v = t.column(which),
             kappa = t.column("kappa_s"), region = t.column("region");
  long double worst = 0, worst_err = 0, worst_kappa = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, region).rfind("m_above_one", 0) != 0) continue;
    const double pd = t.get<double>(i, phi), md = t.get<double>(i, m);
    if (!float_representable(pd) || !float_representable(md)) continue;
    if (!gecko::detail::in_domain_m_above_one(static_cast<T>(pd), static_cast<T>(md))) continue;
    ++n;
    // float: reference = the double kernel at the float-rounded inputs (if still in domain)
    const T pt = static_cast<T>(pd), mt = static_cast<T>(md);
    if (sizeof(T) == sizeof(float) && !gecko::detail::in_domain_m_above_one(double(pt), double(mt))) continue;
    const long double want = sizeof(T) == sizeof(float) ? static_cast<long double>(fn(double(pt), double(mt)))
                                                        : t.value(i, v);
    const long double err = error_in_eps<T>(fn(pt, mt), want);
    const long double k = t.value(i, kappa);
    if (!(err / (bound + k) <= worst)) { worst = err / (bound + k); worst_err = err; worst_kappa = k; }
  }
  WARN(which << "<" << (sizeof(T) == sizeof(float) ? "float" : sizeof(T) == sizeof(double) ? "double" : "long double")
             << "> for m > 1 (" << n << " rows): worst error " << double(worst_err)
             << " eps where kappa_s = " << double(worst_kappa) << "; worst err/(" << double(bound)
             << " + kappa_s) = " << double(worst));
  return worst;
}

}  // namespace gecko_test
