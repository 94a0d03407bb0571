// fuzz/fuzz_common.hpp — shared pieces of the elliptic-kernel fuzzers (fuzz/README.md).
//
// * Input decoding: libFuzzer's bytes become doubles through a mode byte, so that a short input
//   reaches the interesting places of the domain (zeros, +-inf, NaN, subnormals, DBL_MAX,
//   1 +- a few ulps, multiples of pi/2 +- a few ulps, log-uniform magnitudes over the whole
//   exponent range) instead of the mostly-huge or mostly-NaN values raw bit patterns give.
// * Checks: every violated property prints the inputs as hex floats (%a, exact) and aborts, which
//   libFuzzer records as a crash with a reproducer file.
// * The reference: the SAME gecko template evaluated in x87 long double (64-bit significand,
//   15-bit exponent). Every double input is exact in long double, the long double evaluation
//   carries an error of a few 2^-64 (2^11 times below double's eps) and never over- or underflows
//   for double inputs, and it takes other branches of the rescaling code (its windows are
//   2^+-2048 instead of 2^+-128). It therefore measures the rounding error of the double
//   evaluation, catches double-specific overflow/underflow and rescaling mistakes and a wrongly
//   computed double series threshold, but not a wrong formula shared by both instantiations;
//   the identities and the second routes (AGM for K, closed form R_C against R_F, R_J(x,y,z,z)
//   against R_D, ...) in the targets cover that.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

static_assert(std::numeric_limits<long double>::digits >= 64,
              "the fuzzers use long double as the reference: need x87 80-bit or binary128");

namespace gecko_fuzz {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double qnan = std::numeric_limits<double>::quiet_NaN();

// Reads the fuzzer's bytes front to back; past the end it yields zeros (libFuzzer prefers
// targets that accept every input).
class Reader {
 public:
  Reader(const uint8_t* data, size_t size) : p_(data), end_(data + size) {}
  uint8_t byte() { return p_ < end_ ? *p_++ : 0; }
  uint64_t u64() {
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | byte();
    return v;
  }
  // A signed offset in [-8, 7] ulps, used to step off a special value.
  int small_int() { return static_cast<int>(byte() & 15) - 8; }

  // One double. mode (a byte) selects how the next bytes are read:
  double number() {
    const uint8_t mode = byte() % 8;
    switch (mode) {
      case 0: {  // any bit pattern: NaNs with payloads, infinities, subnormals, everything
        const uint64_t bits = u64();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
      }
      case 1: return special(byte());
      case 2: return step_ulps(special(byte()), small_int());
      case 3: return log_uniform(false);
      case 4: return log_uniform(true);
      case 5: {  // moderate values in (-4, 4): where the series and branches switch
        const uint64_t u = u64();
        const double frac = static_cast<double>(u >> 11) * 0x1p-53;
        return (u & 1) ? -4 * frac : 4 * frac;
      }
      case 6: {  // 1 - 2^-k * f and 1 + 2^-k * f: parameters approaching 1 from both sides
        const uint8_t k = byte() % 64;
        const double f = 1 + static_cast<double>(u64() >> 12) * 0x1p-52;
        return (k & 1) ? 1 + std::ldexp(f, -static_cast<int>(k)) : 1 - std::ldexp(f, -static_cast<int>(k) - 1);
      }
      default: {  // j * pi/2 +- ulps, for amplitudes (and as an odd-looking Carlson argument)
        const int j = static_cast<int>(byte() % 64) - 32;
        return step_ulps(j * 1.5707963267948966, small_int());
      }
    }
  }

  static double special(uint8_t i) {
    static const double table[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 4.0, 0.25, 3.0, -2.0, 1.0 / 3, 0x1.fffffffffffffp-1,
        eps, DBL_MIN, std::numeric_limits<double>::denorm_min(), DBL_MAX, -DBL_MAX, 1e-300, 1e300,
        1e-150, 1e150, inf, -inf, qnan, 1.5707963267948966, 3.141592653589793, 4.71238898038469,
        6.283185307179586, 1e16, 0x1p52, 0x1p53, 0x1p63, 1e-8, 1e8, 1e-16, 0.9999, 0.785398163397448,
        -1e300, -1e-300, 0x1p-1022 * 3, 0x1p1000, 0x1p-1000, 16.0, 1.0 / 16, 0x1.8p0, 100.0, 1e-3};
    return table[i % (sizeof table / sizeof table[0])];
  }

  // v moved by k ulps (nextafter k times; stays put at +-inf and NaN).
  static double step_ulps(double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, inf);
    for (; k < 0; ++k) v = std::nextafter(v, -inf);
    return v;
  }

  double log_uniform(bool negative) {
    // exponent over the whole range including subnormals, 52 random significand bits
    const int e = static_cast<int>((static_cast<unsigned>(byte()) << 8 | byte()) % 2098) - 1074;
    const double f = 1 + static_cast<double>(u64() >> 12) * 0x1p-52;
    const double v = std::ldexp(f, e);
    return negative ? -v : v;
  }

 private:
  const uint8_t* p_;
  const uint8_t* end_;
};

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "\n*** gecko fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline std::string hex(long double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%La (%.21Lg)", v, v);
  return buf;
}

// Result of one call under the throwing policy.
struct Outcome {
  double value = qnan;
  bool threw = false;
};

// Calls f(); std::domain_error is the one allowed exception (with a message naming gecko's
// function); anything else is a finding.
template <class F>
Outcome call_throwing(const char* name, F&& f, const std::string& args) {
  Outcome o;
  try {
    o.value = f();
  } catch (const std::domain_error& e) {
    o.threw = true;
    const std::string msg = e.what();
    if (msg.find("gecko::") != 0 || msg.find("out of range") == std::string::npos)
      fail(std::string(name) + args + ": domain_error message does not name the function/range: " + msg);
  } catch (const std::exception& e) {
    fail(std::string(name) + args + ": threw a non-domain_error exception: " + e.what());
  } catch (...) {
    fail(std::string(name) + args + ": threw a non-std exception");
  }
  return o;
}

inline bool same_bits_or_both_nan(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// The throwing and the NaN policy must agree: NaN exactly where the throwing policy throws,
// the identical value elsewhere (they share every line of code but the error action).
inline void check_policies(const char* name, const std::string& args, const Outcome& thrown, double nan_value) {
  if (thrown.threw && !std::isnan(nan_value))
    fail(std::string(name) + args + ": throws under default_policy but nan_policy returns " + hex(nan_value));
  if (!thrown.threw && !same_bits_or_both_nan(thrown.value, nan_value))
    fail(std::string(name) + args + ": default_policy gives " + hex(thrown.value) + " but nan_policy gives " +
         hex(nan_value));
}

inline void check_expected_throw(const char* name, const std::string& args, bool threw, bool should_throw) {
  if (threw != should_throw)
    fail(std::string(name) + args + (should_throw ? ": accepted an argument outside the documented domain"
                                                  : ": raised a domain error inside the documented domain"));
}

// |got - ref| within tol_eps * eps relative to the long double reference, plus an absolute slack
// `abs_slack` (conditioning terms; 0 for well-conditioned functions). Over- and underflow of the
// double result are judged against the reference's magnitude:
//   |ref| > DBL_MAX  -> got must be +-inf or within tol of DBL_MAX (overflow is correct);
//   |ref| < DBL_MIN  -> the exact result is subnormal or underflows: |got - ref| <= DBL_MIN is
//                       accepted (gradual underflow loses relative accuracy by design; results
//                       flushed to zero there are counted, see README), and above DBL_MIN the
//                       relative bound applies in full: a normal-range result has no excuse.
inline void check_close(const char* name, const std::string& args, double got, long double ref, double tol_eps,
                        long double abs_slack = 0) {
  if (std::isnan(ref)) {
    if (!std::isnan(got)) fail(std::string(name) + args + ": long double reference is NaN but double gives " + hex(got));
    return;
  }
  if (std::isnan(got)) fail(std::string(name) + args + ": NaN inside the domain; reference " + hex(ref));
  const long double aref = std::fabs(ref);
  if (std::isinf(ref) || aref > DBL_MAX) {
    if (std::isinf(got) && std::signbit(got) == std::signbit(ref)) return;
    if (std::fabs(static_cast<long double>(got)) >= DBL_MAX * (1 - tol_eps * eps) &&
        std::signbit(got) == std::signbit(ref))
      return;
    fail(std::string(name) + args + ": reference overflows (" + hex(ref) + ") but double gives " + hex(got));
  }
  // within the error bound of the overflow threshold, rounding may legitimately tip over
  if (std::isinf(got) && !(aref >= DBL_MAX * (1 - tol_eps * eps) && std::signbit(got) == std::signbit(ref)))
    fail(std::string(name) + args + ": infinite result, reference " + hex(ref));
  if (std::isinf(got)) return;
  const long double err = std::fabs(static_cast<long double>(got) - ref);
  if (aref < DBL_MIN) {
    if (err <= DBL_MIN + abs_slack) return;
    fail(std::string(name) + args + ": underflow-range result " + hex(got) + " vs reference " + hex(ref));
  }
  const long double bound = tol_eps * eps * aref + abs_slack;
  if (!(err <= bound))
    fail(std::string(name) + args + ": got " + hex(got) + ", long double reference " + hex(ref) + ", error " +
         hex(err / (eps * aref)) + " eps > bound " + hex(bound / (eps * aref)) + " eps");
}

// Identity check between two double expressions: |a - b| <= tol_eps * eps * scale (+ slack).
inline void check_identity(const char* what, const std::string& args, long double a, long double b, double tol_eps,
                           long double scale, long double slack = 0) {
  if (std::isnan(a) || std::isnan(b)) fail(std::string(what) + args + ": NaN in an identity: " + hex(a) + " vs " + hex(b));
  // Within the bound of the overflow threshold either side may round to +-inf, as check_close
  // accepts for the value itself (R_D(1, 0x1.0000000000002p-1022, 0x0.4p-1022) is 0.17 eps
  // below DBL_MAX, and both argument orders give +inf): the two agree when both lie within the
  // bound of DBL_MAX with the same sign. inf - inf would otherwise read as a NaN difference.
  if (std::isinf(a) || std::isinf(b)) {
    const long double edge = static_cast<long double>(DBL_MAX) * (1 - tol_eps * eps);
    if (std::fabs(a) >= edge && std::fabs(b) >= edge && std::signbit(a) == std::signbit(b) && scale >= edge) return;
    fail(std::string(what) + args + ": " + hex(a) + " vs " + hex(b) + ": infinite, and not both within " +
         hex(tol_eps) + " eps of the overflow threshold (scale " + hex(scale) + ")");
  }
  const long double err = std::fabs(a - b);
  const long double bound = tol_eps * eps * scale + slack;
  if (!(err <= bound))
    fail(std::string(what) + args + ": " + hex(a) + " vs " + hex(b) + ", |diff| = " + hex(err / (eps * scale)) +
         " eps(scale) > bound " + hex(bound / (eps * scale)) + " (scale " + hex(scale) + ")");
}

inline std::string fmt_args(std::initializer_list<double> xs) {
  std::string s = "(";
  bool first = true;
  for (double x : xs) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%a", first ? "" : ", ", x);
    s += buf;
    first = false;
  }
  s += ")";
  // GECKO_FUZZ_TRACE=1 ./fuzz_x crash-file: print the decoded arguments before the call (a
  // sanitizer report aborts before any check can print them).
  static const bool trace = std::getenv("GECKO_FUZZ_TRACE") != nullptr;
  if (trace) std::fprintf(stderr, "args %s\n", s.c_str());
  return s;
}

inline bool normal_or_zero(double v) { return v == 0 || std::isnormal(v); }

}  // namespace gecko_fuzz
