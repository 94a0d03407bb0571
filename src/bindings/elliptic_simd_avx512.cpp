// AVX-512F instances of the SIMD elliptic loops (elliptic_simd_kernels.hpp), compiled with
// -mavx512f -ffp-contract=off (src/bindings/CMakeLists.txt); called only where the CPU has it.
// Two schedules of the same arithmetic give the same bits (every lane is computed alone, and both
// root units round correctly); which is faster depends on the chip:
//   avx512            (this file) two interleaved chains of 8 doubles, chain 1's square roots on
//                     the FMA unit (simd_sqrt_avx512.hpp), so that both units work at once. On a
//                     2-core AVX-512 Xeon, against both chains on the square-root unit (medians of
//                     three interleaved runs each): one thread F 1.25x, R_F 1.14x, E 1.16x faster;
//                     two threads F 1.08x, R_F 1.19x, E 0.94x (the E kernel before
//                     gecko/elliptic/legendre_rf_rd.hpp).
//   avx512-sqrt-unit  (elliptic_simd_avx512_unit{1,2}.cpp) every square root on the square-root
//                     unit; F and R_F on two chains, E on one. Measured on AMD's Zen 4, whose
//                     AVX-512 runs on 256-bit units: see elliptic_simd_avx512_unit2.cpp.
// elliptic_ufuncs.cpp picks avx512-sqrt-unit on AMD processors, avx512 elsewhere.
// Each schedule has a translation unit of its own: all three instances compiled in one, GCC
// inlined less and the loops ran up to 1.25x slower (measured on the AMD EPYC).
#include "elliptic_simd.hpp"
#include "elliptic_simd_pack.hpp"

#if defined(GECKO_SIMD_X86)
#include "simd_avx512_hw.hpp"
#include "simd_sqrt_avx512.hpp"

namespace gecko {
namespace bindings {
namespace simd_avx512 {
struct hw : avx512_base {
  static vd sqrt(vd x, int chain) { return chain == 0 ? unit_sqrt(x) : sqrt_fma_avx512(x); }
};
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
