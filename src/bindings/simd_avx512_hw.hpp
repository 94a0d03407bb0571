// The AVX-512F hardware vector of the SIMD elliptic loops (elliptic_simd_pack.hpp's Hw traits,
// less the square root, which each schedule places on its own unit): 8 doubles in a zmm register.
// Included only by translation units compiled with -mavx512f.
#pragma once

#include <immintrin.h>

namespace gecko {
namespace bindings {

struct avx512_base {
  using vd = __m512d;
  typedef long long vi __attribute__((vector_size(64)));
  static constexpr int W = 8;
  static bool any(vi m) { return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0; }
  // maskz form: GCC 12 warns about the undefined pass-through operand of _mm512_sqrt_pd.
  static vd unit_sqrt(vd x) { return _mm512_maskz_sqrt_pd(0xff, x); }
};

// Every chain's square roots on the square-root unit (the avx512-sqrt-unit schedule).
struct avx512_sqrt_unit_hw : avx512_base {
  static vd sqrt(vd x, int) { return unit_sqrt(x); }
};

}  // namespace bindings
}  // namespace gecko
