// The avx512-sqrt-unit schedule (elliptic_simd_avx512.cpp): every square root on the square-root
// unit; F and R_F on two interleaved chains of 8 doubles (this file), E on one
// (elliptic_simd_avx512_unit1.cpp). On a 2-core AMD EPYC (Zen 4), faster than the avx512
// schedule by (time ratios, 1e6 elements, medians of interleaved rounds of bench/tradeoff/
// simd_batch.py): one thread F 1.16x, E 1.32x, R_F 1.21x, two threads F 1.18x, E 1.34x,
// R_F 1.21x in the run behind bench/results/tradeoff.csv; one thread F 1.16x, E 1.26x, R_F 1.27x,
// two threads F 1.15x, E 1.27x, R_F 1.24x in the run behind bench/results/simd_batch.md.
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include "simd_avx512_hw.hpp"

namespace gecko {
namespace bindings {
namespace simd_avx512_unit2 {
using pack = wide_pack<avx512_sqrt_unit_hw, 2>;
}  // namespace simd_avx512_unit2
}  // namespace bindings
}  // namespace gecko

#define GECKO_SIMD_NS simd_avx512_unit2
#include "elliptic_simd_kernels.hpp"

const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512_sqrt_unit() {
  const kernels* one = kernels_avx512_unit1();
  static const kernels t = {&simd_avx512_unit2::batch<simd_avx512_unit2::kernel_f>, one->ellint_e,
                            &simd_avx512_unit2::batch<simd_avx512_unit2::kernel_rf>, simd_avx512_unit2::W};
  return &t;
}
#else
const gecko::bindings::simd::kernels* gecko::bindings::simd::kernels_avx512_sqrt_unit() { return nullptr; }
#endif
