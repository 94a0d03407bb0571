// Correctly rounded square root of 8 doubles on the FMA units (AVX-512F), bitwise equal to
// _mm512_sqrt_pd / std::sqrt, for the SIMD elliptic loops (elliptic_simd_avx512.cpp).
//
// Why: the vector kernels are bound by the divider/square-root unit (F needs about 14 square
// roots per element), and on AVX-512 cores that unit issues one 8-wide square root per ~20+
// cycles while the FMA unit sits mostly idle. Computing some of the roots here, on the FMA unit,
// lets both units work at once; the results do not change, so the vector loops stay bitwise
// equal to the scalar kernels.
//
// How (for 2^-1000 <= x <= 2^1000; other lanes take the hardware root for the whole vector):
//   y0 = rsqrt14(x)          1/sqrt(x) to 2^-14 relative (vrsqrt14pd)
//   g = x y0, h = y0/2       coupled Newton iteration for sqrt(x) and 1/(2 sqrt(x)):
//   r = 1/2 - g h, g += g r, h += h r    (relative error 2^-14 -> about 1.5 2^-28)
//   g += h (x - g^2)         a Newton step on the exact residual x - g^2 (FMA): the error of g
//                            squares and h's adds its own times g's, about 2^-55 relative in
//                            all, so g is within one ulp of sqrt(x) after rounding;
// then the rounding is made exact (Tuckerman's test): with p, n the neighbours of g,
//   g p - x and g n - x are multiples of the square of g's ulp while x is a multiple of a far
//   larger power of two, so sqrt(x) lies above the midpoint (g + p)/2 exactly when g p < x, and
//   below (g + n)/2 exactly when g n >= x. Both signs are exact from one FMA each (a nonzero
//   exact value does not round to zero here), so g is replaced by p or n where it is not the
//   correctly rounded root. No exact midpoint exists (the same multiple argument).
// Tested bitwise against std::sqrt in tests/bindings/simd_sqrt.cpp (random, near squares,
// near products of neighbours, near powers of two).
#pragma once

#include <immintrin.h>

namespace gecko {
namespace bindings {

inline __m512d sqrt_fma_avx512(__m512d x) {
  const __mmask8 in_range = _mm512_cmp_pd_mask(x, _mm512_set1_pd(0x1p-1000), _CMP_GE_OQ) &
                            _mm512_cmp_pd_mask(x, _mm512_set1_pd(0x1p+1000), _CMP_LE_OQ);
  // zero, subnormal, huge, inf, NaN or negative lanes (rare on the vector paths)
  // (maskz forms: GCC 12 warns about the undefined pass-through operand of the plain intrinsics)
  if (in_range != 0xff) return _mm512_maskz_sqrt_pd(0xff, x);
  const __m512d half = _mm512_set1_pd(0.5);
  const __m512d y = _mm512_maskz_rsqrt14_pd(0xff, x);
  __m512d g = _mm512_mul_pd(x, y);
  __m512d h = _mm512_mul_pd(half, y);
  const __m512d r = _mm512_fnmadd_pd(g, h, half);
  g = _mm512_fmadd_pd(g, r, g);
  h = _mm512_fmadd_pd(h, r, h);
  g = _mm512_fmadd_pd(_mm512_fnmadd_pd(g, g, x), h, g);
  const __m512i bits = _mm512_castpd_si512(g);
  const __m512d p = _mm512_castsi512_pd(_mm512_sub_epi64(bits, _mm512_set1_epi64(1)));
  const __m512d n = _mm512_castsi512_pd(_mm512_add_epi64(bits, _mm512_set1_epi64(1)));
  const __m512d zero = _mm512_setzero_pd();
  const __mmask8 too_big = _mm512_cmp_pd_mask(_mm512_fmsub_pd(g, p, x), zero, _CMP_GE_OQ);
  const __mmask8 too_small = _mm512_cmp_pd_mask(_mm512_fmsub_pd(g, n, x), zero, _CMP_LT_OQ);
  g = _mm512_mask_blend_pd(too_big, g, p);
  return _mm512_mask_blend_pd(too_small, g, n);
}

}  // namespace bindings
}  // namespace gecko
