// AVX2 (4 doubles) instance of the SIMD elliptic loops (elliptic_simd_kernels.hpp), compiled with
// -mavx2 -mfma -ffp-contract=off (src/bindings/CMakeLists.txt); called only where the CPU has both.
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include <immintrin.h>

namespace gecko {
namespace bindings {
namespace simd_avx2 {
struct hw {
  using vd = __m256d;
  typedef long long vi __attribute__((vector_size(32)));
  static constexpr int W = 4;
  static vd sqrt(vd x, int) { return _mm256_sqrt_pd(x); }
  static bool any(vi m) { return _mm256_movemask_pd((__m256d)m) != 0; }
};
// one register per chain: two interleaved spill (16 ymm registers) and were no faster (measured) (elliptic_simd_pack.hpp)
using pack = wide_pack<hw, 1>;
}  // namespace simd_avx2
}  // namespace bindings
}  // namespace gecko

#define GECKO_SIMD_NS simd_avx2
#include "elliptic_simd_kernels.hpp"

const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx2() { return simd_avx2::table(); }
#else
const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx2() { return nullptr; }
#endif
