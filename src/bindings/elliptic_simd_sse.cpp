// SSE2 (2 doubles) instance of the SIMD elliptic loops (elliptic_simd_kernels.hpp); SSE2 is the
// x86-64 baseline, so this needs no extra ISA flag (only -ffp-contract=off, src/bindings/CMakeLists.txt).
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include <immintrin.h>

namespace gecko {
namespace bindings {
namespace simd_sse {
struct hw {
  using vd = __m128d;
  typedef long long vi __attribute__((vector_size(16)));
  static constexpr int W = 2;
  static vd sqrt(vd x, int) { return _mm_sqrt_pd(x); }
  static bool any(vi m) { return _mm_movemask_pd((__m128d)m) != 0; }
};
// one register per chain: two (measured) sped F up but slowed R_F (elliptic_simd_pack.hpp)
using pack = wide_pack<hw, 1>;
}  // namespace simd_sse
}  // namespace bindings
}  // namespace gecko

#define GECKO_SIMD_NS simd_sse
#include "elliptic_simd_kernels.hpp"

const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_sse() { return simd_sse::table(); }
#else
const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_sse() { return nullptr; }
#endif
