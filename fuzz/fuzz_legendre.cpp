// fuzz/fuzz_legendre.cpp — libFuzzer target for the Legendre forms F(phi|m), E(phi|m), K(m) and
// ellint_ek (E(m), K(m) together), double. See fuzz/README.md.
//
// First byte: which function; then phi and m (fuzz_common.hpp: Reader::number), with an extra
// mode that puts phi on the m > 1 domain boundary arcsin(1/sqrt m) +- a few ulps.
// Checked for every input:
//   1. no crash, no sanitizer report, no exception other than std::domain_error;
//   2. domain errors exactly where the documented domain says, decided independently in long
//      double: m > 1 needs |phi| <= arcsin(1/sqrt m); within 16 eps of the boundary
//      (Delta^2 = 1 - m sin^2 phi in [-16 eps, 16 eps]) either answer is accepted, because the
//      header decides from a rounded sin phi and accepts Delta^2 >= -4 eps. NaN in -> NaN out,
//      no throw; nan_policy NaN exactly where default_policy throws, identical bits elsewhere;
//   3. accuracy against the long double evaluation of the same template:
//        m <= 1: 8 eps relative (the tests assert 3 eps (F) and 4 eps (E) against mpmath; the
//                exact double phi is exact in long double too, and every term is positive);
//        m > 1:  F and E increase with phi and the header's result is documented as the exact
//                value at a phi within a few ulps (gecko/elliptic/ellint_f.hpp, conditioning
//                note: dF/dphi = 1/Delta is unbounded at the boundary). Checked as exactly
//                that: the double result must lie in [ref(phi - d), ref(phi + d)] widened by
//                8 eps, d = 4 eps (|phi| + tan|phi|) (rounding of sin phi and of m sin phi,
//                each eps/2 relative, moves phi by eps/2 tan phi).
//      K, E(m): 4 eps (tests: 4 eps) against long double; K also against the AGM (ellint_k,
//      a different algorithm), E(m) against the incomplete E(pi/2|m) in long double.
//   4. identities: oddness F(-phi) = -F(phi) exactly; F(phi + pi|m) = F(phi|m) + 2K(m) and
//      E(phi + pi|m) = E(phi|m) + 2E(m) (DLMF 19.2.10; the rounding of phi + pi is accounted
//      for with the largest slope of the integrand); Legendre's relation
//      E K' + E' K - K K' = pi/2 (DLMF 19.7.1) at m and 1 - m.
#include <algorithm>
#include <cstdint>

#include "fuzz_common.hpp"
#include "gecko/elliptic/ellint_e.hpp"
#include "gecko/elliptic/ellint_ek.hpp"
#include "gecko/elliptic/ellint_f.hpp"
#include "gecko/elliptic/ellint_k.hpp"

using namespace gecko_fuzz;
using gecko::policies::default_policy;
using gecko::policies::nan_policy;

namespace {

constexpr double tol_legendre = 8, tol_complete = 4;
constexpr long double pi_l = 3.141592653589793238462643383279502884L;

// phi and m, where phi may be put on the m > 1 boundary.
struct PhiM {
  double phi, m;
};

PhiM read_phi_m(Reader& in) {
  const uint8_t how = in.byte();
  double phi = in.number();
  const double m = in.number();
  if (how % 4 == 0 && m > 1 && std::isfinite(m)) {
    // the edge of the real domain, arcsin(1/sqrt m), +- a few ulps, either sign
    const long double edge = std::asin(1 / std::sqrt(static_cast<long double>(m)));
    phi = Reader::step_ulps(static_cast<double>(edge), in.small_int());
    if (how & 4) phi = -phi;
  }
  return {phi, m};
}

// Delta^2 = 1 - m sin^2 phi in long double (only for m > 1, |phi| <= pi/2)
long double delta2(double phi, double m) {
  const long double s = std::sin(static_cast<long double>(phi));
  return 1 - m * s * s;
}

// 1: must throw, 0: must not, -1: within rounding of the boundary, either is right.
int expected_domain_error(double phi, double m) {
  if (std::isnan(phi) || std::isnan(m)) return 0;
  if (!std::isfinite(phi)) return 1;
  if (!(m > 1)) return 0;
  if (std::isinf(m)) return 1;
  if (std::fabs(phi) > pi_l / 2) return 1;
  const long double d2 = delta2(phi, m);
  if (d2 > 16 * eps) return 0;
  if (d2 < -16 * eps) return 1;
  return -1;
}

// Finding F5 (fuzz/README.md "Findings": the odd-quadrant tail for m -> -inf overflowed or its
// R_D underflowed) is fixed in the headers; its filter is gone.

template <class Fn>
void check_legendre(const char* name, Fn fn, double phi, double m, bool uses_rd) {
  const std::string a = fmt_args({phi, m});
  const Outcome o = call_throwing(name, [&] { return fn(phi, m, default_policy()); }, a);
  const double nan_v = fn(phi, m, nan_policy());
  check_policies(name, a, o, nan_v);
  const int expect = expected_domain_error(phi, m);
  if (expect >= 0) check_expected_throw(name, a, o.threw, expect == 1);
  if (std::isnan(phi) || std::isnan(m)) {
    if (!std::isnan(o.value)) fail(std::string(name) + a + ": NaN input did not give NaN");
    return;
  }
  if (o.threw) return;
  // oddness is exact (copysign)
  const double odd = fn(-phi, m, default_policy());
  if (!same_bits_or_both_nan(odd, -o.value)) fail(std::string(name) + a + ": f(-phi) != -f(phi): " + hex(odd));

  const long double ref = fn(static_cast<long double>(phi), static_cast<long double>(m), nan_policy());
  if (m <= 1 || std::isinf(m)) {
    check_close(name, a, o.value, ref, tol_legendre);
    return;
  }
  // m > 1: backward stable in phi (see the header comment above)
  const long double ap = std::fabs(static_cast<long double>(phi));
  const long double d = 4 * eps * (ap + std::tan(ap));
  const long double edge = std::asin(1 / std::sqrt(static_cast<long double>(m)));
  const long double lo_phi = std::max(0.0L, ap - d), hi_phi = std::min(edge, ap + d);
  long double lo = fn(lo_phi, static_cast<long double>(m), nan_policy());
  long double hi = fn(hi_phi, static_cast<long double>(m), nan_policy());
  if (std::isnan(hi)) hi = fn(std::nextafter(edge, 0.0L), static_cast<long double>(m), nan_policy());
  if (std::isnan(lo) || std::isnan(hi) || std::isnan(ref)) {
    if (!std::isnan(ref)) fail(std::string(name) + a + ": long double bracket failed");
    return;  // the long double evaluation itself refuses: nothing to compare
  }
  const long double got = std::fabs(static_cast<long double>(o.value));
  if (std::isnan(o.value)) fail(std::string(name) + a + ": NaN inside the domain");
  // The long double reference is itself only backward stable: its Delta^2 carries an absolute
  // error of a few 2^-64, and F = s R_F(c^2, Delta^2, 1) has a sqrt(Delta^2) singularity
  // (dR_F/dy ~ -1/(2 c sqrt(y))), so near the edge its value is uncertain by up to
  // (s/c) sqrt(2^-60) ~ 1e-9/c: F_L(edge) was 9e-10 below mpmath's for m = 1.0005, where the
  // double result was right. E has no such singularity (its sqrt parts cancel).
  long double ref_slack_lo = 0, ref_slack_hi = 0;
  if (!uses_rd) {
    const long double dl = std::ldexp(static_cast<long double>(m), -60);
    auto slack = [&](long double ph) {
      const long double sn = std::sin(ph), cs = std::cos(ph), d2 = 1 - m * sn * sn;
      const long double up = std::sqrt(std::max(0.0L, d2) + dl), down = std::sqrt(std::max(0.0L, d2 - dl));
      return sn / cs * (up - down);
    };
    ref_slack_lo = slack(lo_phi);
    ref_slack_hi = slack(hi_phi);
  }
  if (!(got >= lo * (1 - tol_legendre * eps) - ref_slack_lo && got <= hi * (1 + tol_legendre * eps) + ref_slack_hi))
    fail(std::string(name) + a + ": |result| " + hex(got) + " outside the backward-error bracket [" + hex(lo) + ", " +
         hex(hi) + "] (ref " + hex(ref) + ")");
}

void fuzz_f(Reader& in) {
  const PhiM pm = read_phi_m(in);
  check_legendre("ellint_f", [](auto phi, auto m, auto pol) { return gecko::ellint_f(phi, m, pol); }, pm.phi, pm.m, false);
}

void fuzz_e(Reader& in) {
  const PhiM pm = read_phi_m(in);
  check_legendre("ellint_e", [](auto phi, auto m, auto pol) { return gecko::ellint_e(phi, m, pol); }, pm.phi, pm.m, true);
}

void fuzz_complete(Reader& in) {
  const double m = in.number();
  const std::string a = fmt_args({m});
  const Outcome k = call_throwing("ellint_k", [&] { return gecko::ellint_k(m, default_policy()); }, a);
  check_policies("ellint_k", a, k, gecko::ellint_k(m, nan_policy()));
  bool ek_threw = false;
  gecko::ellint_ek_result<double> ek{qnan, qnan};
  try {
    ek = gecko::ellint_ek(m, default_policy());
  } catch (const std::domain_error&) {
    ek_threw = true;
  } catch (...) {
    fail("ellint_ek" + a + ": threw something other than std::domain_error");
  }
  const auto ekn = gecko::ellint_ek(m, nan_policy());
  if (ek_threw && !(std::isnan(ekn.E) && std::isnan(ekn.K))) fail("ellint_ek" + a + ": nan_policy disagrees");
  if (!ek_threw && !(same_bits_or_both_nan(ek.E, ekn.E) && same_bits_or_both_nan(ek.K, ekn.K)))
    fail("ellint_ek" + a + ": nan_policy gives other bits");
  const bool bad = m > 1;
  check_expected_throw("ellint_k", a, k.threw, bad);
  check_expected_throw("ellint_ek", a, ek_threw, bad);
  if (std::isnan(m)) {
    if (!std::isnan(k.value) || !std::isnan(ek.E) || !std::isnan(ek.K)) fail("ellint_k/ek" + a + ": NaN in, not NaN out");
    return;
  }
  if (bad) return;
  const long double ml = m;
  const long double k_agm = gecko::ellint_k(ml);                   // AGM, long double
  const long double k_rf = gecko::ellint_ek(ml).K;                 // R_F, long double
  const long double e_ref = gecko::ellint_ek(ml).E;
  check_close("ellint_k (AGM)", a, k.value, k_agm, tol_complete);
  check_close("ellint_ek.K (R_F) vs AGM", a, ek.K, k_agm, tol_complete);
  check_close("ellint_k vs ellint_ek.K, long double", a, static_cast<double>(k_rf), k_agm, 1);
  check_close("ellint_ek.E", a, ek.E, e_ref, tol_complete);
  if (std::isfinite(m)) {
    // E(m) = E(pi/2|m): the incomplete route (DLMF 19.25.10 instead of 19.25.1), in long double;
    // pi/2 rounded to long double moves E by at most 2^-64 * sqrt(max(1, 1 - m))
    const long double e_inc = gecko::ellint_e(pi_l / 2, ml);
    check_close("ellint_ek.E vs ellint_e(pi/2)", a, ek.E, e_inc, tol_complete + 1);
  }
  // Legendre's relation at the pair (1 - mc, mc), mc in [1/2, 1) so that 1 - mc is exact.
  if (m > 0 && m < 1) {
    const double mc = m >= 0.5 ? m : 1 - m;
    const double m1 = 1 - mc;  // exact (Sterbenz)
    if (m1 > 0) {
      const auto a1 = gecko::ellint_ek(m1), a2 = gecko::ellint_ek(mc);
      const long double E = a1.E, K = a1.K, Ep = a2.E, Kp = a2.K;
      const long double lhs = E * Kp + Ep * K - K * Kp;
      // each factor within 4 eps, products add 2 roundings: 12 eps of every term, summed
      const long double scale = E * Kp + Ep * K + K * Kp;
      check_identity("Legendre relation", fmt_args({m1, mc}), lhs, pi_l / 2, 12, scale);
    }
  }
}

// F(phi + pi|m) = F(phi|m) + 2 K(m), E likewise with 2 E(m) (DLMF 19.2.10), m <= 1.
void fuzz_period(Reader& in) {
  const double phi = in.number(), m = in.number();
  if (!std::isfinite(phi) || !(m <= 1) || !std::isfinite(m) || std::fabs(phi) > 1e15) return;
  const double phi2 = phi + 3.141592653589793;
  if (!std::isfinite(phi2)) return;
  const std::string a = fmt_args({phi, m});
  // phi2 - phi is not pi exactly: the integrands are at most 1/sqrt(1 - m) (F, m >= 0), 1
  // (F, m < 0), 1 (E, m >= 0), sqrt(1 - m) (E, m < 0) in size
  // plus the backward error of each evaluation's own reduction phi = j pi/2 + r (a few ulps of
  // |r| <= pi/4, so 4 eps absolute each), which the integrand's slope turns into a forward error
  const long double dphi = std::fabs((static_cast<long double>(phi2) - phi) - pi_l) + 8 * eps;
  const long double lm = m;
  const long double slope_f = m >= 0 ? (m < 1 ? 1 / std::sqrt(1 - lm) : 0.0L) : 1.0L;
  const long double slope_e = m >= 0 ? 1.0L : std::sqrt(1 - lm);
  const auto ek = gecko::ellint_ek(m);
  if (m < 1) {
    const double f1 = gecko::ellint_f(phi, m), f2 = gecko::ellint_f(phi2, m);
    const long double sc = std::fabs(static_cast<long double>(f1)) + std::fabs(static_cast<long double>(f2)) + 2 * ek.K;
    if (sc <= DBL_MAX && sc >= DBL_MIN)
      check_identity("F(phi + pi) = F(phi) + 2K", a, f2, static_cast<long double>(f1) + 2 * static_cast<long double>(ek.K),
                     2 * tol_legendre, sc, dphi * slope_f * (1 + 1e-6));
  }
  const double e1 = gecko::ellint_e(phi, m), e2 = gecko::ellint_e(phi2, m);
  const long double sc = std::fabs(static_cast<long double>(e1)) + std::fabs(static_cast<long double>(e2)) + 2 * ek.E;
  if (sc <= DBL_MAX && sc >= DBL_MIN)
    check_identity("E(phi + pi) = E(phi) + 2E", a, e2, static_cast<long double>(e1) + 2 * static_cast<long double>(ek.E),
                   2 * tol_legendre, sc, dphi * slope_e * (1 + 1e-6));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Reader in(data, size);
  switch (in.byte() % 4) {
    case 0: fuzz_f(in); break;
    case 1: fuzz_e(in); break;
    case 2: fuzz_complete(in); break;
    default: fuzz_period(in); break;
  }
  return 0;
}
