// AVX-512F (2 x 8 doubles) instance of the SIMD elliptic loops (elliptic_simd_kernels.hpp), compiled
// with -mavx512f -ffp-contract=off (src/bindings/CMakeLists.txt); called only where the CPU has it.
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include <immintrin.h>

#include "simd_sqrt_avx512.hpp"

namespace gecko {
namespace bindings {
namespace simd_avx512 {
struct hw {
  using vd = __m512d;
  typedef long long vi __attribute__((vector_size(64)));
  static constexpr int W = 8;
  // Chain 0 on the square-root unit, chain 1 on the FMA unit (simd_sqrt_avx512.hpp), so that both
  // work at once; same bits. Against both chains on the square-root unit (bench/tradeoff/
  // simd_batch.py, medians of three interleaved runs each, 2-core AVX-512 Xeon): one thread F 1.25x,
  // R_F 1.14x, E 1.16x faster; two threads F 1.08x, R_F 1.19x, E 0.94x (E slower: measured, not
  // understood; the FMA unit may cost clock on both cores). maskz form: GCC 12 warns about the
  // undefined pass-through operand of _mm512_sqrt_pd.
  static vd sqrt(vd x, int chain) { return chain == 0 ? _mm512_maskz_sqrt_pd(0xff, x) : sqrt_fma_avx512(x); }
  static bool any(vi m) { return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0; }
};
// two interleaved chains (32 zmm registers hold both): F and R_F about 1.2x faster than one (measured, E unchanged) (elliptic_simd_pack.hpp)
using pack = wide_pack<hw, 2>;
}  // namespace simd_avx512
}  // namespace bindings
}  // namespace gecko

#define GECKO_SIMD_NS simd_avx512
#include "elliptic_simd_kernels.hpp"

const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512() { return simd_avx512::table(); }
#else
const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512() { return nullptr; }
#endif
