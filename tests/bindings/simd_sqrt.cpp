// Tests for src/bindings/simd_sqrt_avx512.hpp: the square root on the FMA unit is bitwise the
// correctly rounded one (std::sqrt) on every lane, at random arguments over its whole range and
// at the arguments where rounding is hardest: next to exact squares g^2, next to products g n of
// neighbouring doubles (the sqrt lies next to a midpoint there), and next to powers of two
// (a binade edge between g and its neighbour); lanes outside [2^-1000, 2^1000] (zero,
// subnormal, huge, inf, NaN, negative) mixed in take the hardware root.
// Compiled for AVX-512F by a target pragma around the header alone (not the whole file, so that
// no inline function of Catch2 or the standard library is emitted with AVX-512 instructions);
// skipped with a warning where the CPU or compiler lacks it.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GECKO_TEST_AVX512 1
#pragma GCC push_options
#pragma GCC target("avx512f")
#include "simd_sqrt_avx512.hpp"
static void sqrt_fma8(const double* in, double* out) {
  _mm512_storeu_pd(out, gecko::bindings::sqrt_fma_avx512(_mm512_loadu_pd(in)));
}
#pragma GCC pop_options
#endif

namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}
// x moved by k ulps (k in -2..2), staying a positive finite double here
double ulps_away(double x, int k) { return from_bits(bits(x) + static_cast<std::uint64_t>(static_cast<std::int64_t>(k))); }

}  // namespace

TEST_CASE("simd sqrt on the FMA unit: bitwise std::sqrt on every lane") {
#if GECKO_TEST_AVX512
  if (!__builtin_cpu_supports("avx512f")) {
    WARN("simd_sqrt: this CPU has no AVX-512F; not tested here");
    return;
  }
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> mant(1, 2);
  std::uniform_int_distribution<int> expo(-1000, 999), half_expo(-500, 499), kind(0, 4), step(-2, 2);
  long mismatches = 0, checked = 0;
  double in[8], out[8];
  auto check = [&] {
    sqrt_fma8(in, out);
    for (int l = 0; l < 8; ++l) {
      const double want = std::sqrt(in[l]);
      const bool same = std::isnan(want) ? std::isnan(out[l]) : bits(want) == bits(out[l]);
      if (!same) {
        if (mismatches < 5) UNSCOPED_INFO(std::hexfloat << "x = " << in[l] << ": got " << out[l] << ", want " << want);
        ++mismatches;
      }
      ++checked;
    }
  };
  for (int v = 0; v < 250000; ++v) {
    const int k = kind(gen);
    for (int l = 0; l < 8; ++l) {
      const double g = std::ldexp(mant(gen), half_expo(gen));
      switch (k) {
        case 0: in[l] = std::ldexp(mant(gen), expo(gen)); break;                           // random
        case 1: in[l] = ulps_away(g * g, step(gen)); break;                                 // near g^2
        case 2: in[l] = ulps_away(g * std::nextafter(g, 4.0), step(gen)); break;          // near g n
        case 3: in[l] = ulps_away(std::ldexp(1.0, expo(gen)), step(gen)); break;            // binade edges
        default: in[l] = ulps_away(std::ldexp(std::floor(mant(gen) * 8), half_expo(gen) * 2), step(gen));
      }
    }
    check();
  }
  // the range edges, and lanes outside the range mixed with ordinary ones
  const double inf = std::numeric_limits<double>::infinity();
  const double specials[] = {0x1p-1000, 0x1p+1000, ulps_away(0x1p-1000, -1), ulps_away(0x1p+1000, 1), 0.0, -0.0,
                             4.9e-324, 2.2e-308, 1e300, std::numeric_limits<double>::max(), inf, -1.0,
                             std::numeric_limits<double>::quiet_NaN(), 2.0, 3.0, 1.0};
  for (int start = 0; start < 16; start += 8) {
    std::memcpy(in, specials + start, sizeof in);
    check();
  }
  for (int i = 0; i < 8; ++i) in[i] = 2.0 + i;  // all in range, exact squares among them
  in[2] = 4.0;
  check();
  INFO("checked " << checked << " lanes");
  CHECK(mismatches == 0);
#else
  WARN("simd_sqrt: not an x86-64 GCC build; not tested here");
#endif
}
