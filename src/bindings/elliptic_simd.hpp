// SIMD batch loops of the elliptic ufuncs (float64 F, E and R_F): the interface between the
// ufunc loops (elliptic_ufuncs.cpp, compiled for the baseline ISA) and the per-ISA translation
// units elliptic_simd_{sse,avx2,avx512}.cpp, which include elliptic_simd_kernels.hpp with their
// own compiler flags.
//
// Why our own loops and not xsimd or Highway: the three kernels need only + - * /, sqrt,
// comparisons, blends and "any lane still active", which GCC/Clang vector extensions give
// directly (the __m128d/__m256d/__m512d types are such vectors, so a + b and a < b work on
// them); one template written against a four-line traits struct covers every width. A library
// would be a new build dependency (or a vendored copy) for that, and its dispatch would still have
// to be wired into the numpy loops. Runtime dispatch is __builtin_cpu_supports (which checks the
// OS's saving of the wide registers as well), picked once at import.
//
// Every lane is computed exactly as that element alone would be (converged lanes are frozen by
// masks, tails are padded with benign arguments and run through the same vector code), so the
// results do not depend on how the array is cut into threads' blocks or vectors. Lanes outside
// the vector path's region (NaN, infinities, m > 1, |phi| > pi/2, arguments R_F must rescale)
// are recomputed by the scalar kernel given as `lane_fn`.
#pragma once

#include <cstddef>

namespace gecko {
namespace bindings {
namespace simd {

enum level : int { scalar = 0, sse = 1, avx2 = 2, avx512 = 3, avx512_sqrt_unit = 4 };

// Scalar kernel of one element: args[0 .. nin) -> result (the ufuncs pass nan_policy kernels).
using lane_fn = double (*)(const double* args);

// One batch kernel: in[k] points at n contiguous doubles of argument k; out at n doubles.
using batch_fn = void (*)(const double* const* in, double* out, std::size_t n, lane_fn fallback);

struct kernels {
  batch_fn ellint_f;
  batch_fn ellint_e;
  batch_fn carlson_rf;
  int width;  // doubles per vector
};

// The table of one ISA level, or nullptr where it was not compiled in (non-x86 builds).
const kernels* kernels_sse();
const kernels* kernels_avx2();
const kernels* kernels_avx512();
const kernels* kernels_avx512_sqrt_unit();  // same bits, another schedule (elliptic_simd_avx512.cpp)
const kernels* kernels_avx512_unit1();       // its one-chain part

}  // namespace simd
}  // namespace bindings
}  // namespace gecko
