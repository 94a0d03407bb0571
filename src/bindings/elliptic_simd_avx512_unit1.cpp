// The avx512-sqrt-unit schedule's one-chain instance (elliptic_simd_avx512.cpp): every square root
// on the square-root unit, one zmm vector of 8 doubles per step. Its E loop is the schedule's:
// E keeps about twice as many vectors live as F, and two chains of it spill registers.
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include "simd_avx512_hw.hpp"

namespace gecko {
namespace bindings {
namespace simd_avx512_unit1 {
using pack = wide_pack<avx512_sqrt_unit_hw, 1>;
}  // namespace simd_avx512_unit1
}  // namespace bindings
}  // namespace gecko

#define GECKO_SIMD_NS simd_avx512_unit1
#include "elliptic_simd_kernels.hpp"

const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512_unit1() {
  return simd_avx512_unit1::table();
}
#else
const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512_unit1() { return nullptr; }
#endif
