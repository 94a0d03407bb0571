// The vector types of the SIMD elliptic loops (elliptic_simd_kernels.hpp): U hardware vectors of
// one ISA handled as one vector of U * Hw::W doubles.
//
// Why more than one hardware vector: the kernels are chains of dependent square roots and
// divisions (sincos -> sqrt(Delta^2) -> one duplication step after another -> sqrt(A) -> 1/A ->
// series), each sqrt/div with a latency of about twice its issue interval, and the duplication
// loop ends in a data-dependent branch that keeps the out-of-order core from running ahead into
// the next vector. One chain leaves the divider/sqrt unit idle much of the time; U independent
// chains, interleaved instruction by instruction, fill it. The price: the loop runs until the
// slowest of U * W lanes has converged (frozen lanes pay for the steps; their results do not
// change).
// A struct of U hardware vectors rather than a wider GCC generic vector: a generic vector wider
// than the ISA has no machine mode and lives in memory (measured: slower than U = 1); the struct's
// members are scalarised into registers.
//
// Hw gives: vd, vi (one hardware vector of doubles / of 64-bit masks), W (its lanes),
// sqrt(vd, chain) (correctly rounded, as std::sqrt) and any(vi) (some mask lane set).
#pragma once

namespace gecko {
namespace bindings {

template <class Hw, int U>
struct wide_pack {
  static constexpr int W = Hw::W * U;
  using hd = typename Hw::vd;
  using hi = typename Hw::vi;

  static hd bcast(double x) {
    hd v;
    for (int i = 0; i < Hw::W; ++i) v[i] = x;
    return v;
  }
  static hi bcast_i(long long x) {
    hi v;
    for (int i = 0; i < Hw::W; ++i) v[i] = x;
    return v;
  }

#define GECKO_WIDE_OP(R, A, B, OP, EA, EB)            \
  friend R operator OP(A a, B b) {                    \
    R r;                                              \
    for (int k = 0; k < U; ++k) r.h[k] = (EA)OP(EB);  \
    return r;                                         \
  }

  struct vi {
    hi h[U];
    long long& operator[](int i) { return h[i / Hw::W][i % Hw::W]; }
    long long operator[](int i) const { return h[i / Hw::W][i % Hw::W]; }
    GECKO_WIDE_OP(vi, vi, vi, &, a.h[k], b.h[k])
    GECKO_WIDE_OP(vi, vi, vi, |, a.h[k], b.h[k])
    GECKO_WIDE_OP(vi, vi, vi, +, a.h[k], b.h[k])
    GECKO_WIDE_OP(vi, vi, long long, >=, a.h[k], bcast_i(b))
    friend vi operator~(vi a) {
      for (int k = 0; k < U; ++k) a.h[k] = ~a.h[k];
      return a;
    }
    vi& operator&=(vi b) { return *this = *this & b; }
  };

  struct vd {
    hd h[U];
    double& operator[](int i) { return h[i / Hw::W][i % Hw::W]; }
    double operator[](int i) const { return h[i / Hw::W][i % Hw::W]; }
#define GECKO_WIDE_ARITH(OP)                           \
  GECKO_WIDE_OP(vd, vd, vd, OP, a.h[k], b.h[k])        \
  GECKO_WIDE_OP(vd, vd, double, OP, a.h[k], bcast(b))  \
  GECKO_WIDE_OP(vd, double, vd, OP, bcast(a), b.h[k])
    GECKO_WIDE_ARITH(+)
    GECKO_WIDE_ARITH(-)
    GECKO_WIDE_ARITH(*)
    GECKO_WIDE_ARITH(/)
#undef GECKO_WIDE_ARITH
#define GECKO_WIDE_CMP(OP)                                                                        \
  friend vi operator OP(vd a, vd b) {                                                             \
    vi r;                                                                                         \
    for (int k = 0; k < U; ++k) r.h[k] = (hi)(a.h[k] OP b.h[k]);                                  \
    return r;                                                                                     \
  }                                                                                               \
  friend vi operator OP(vd a, double b) {                                                         \
    vi r;                                                                                         \
    for (int k = 0; k < U; ++k) r.h[k] = (hi)(a.h[k] OP bcast(b));                                \
    return r;                                                                                     \
  }
    GECKO_WIDE_CMP(<)
    GECKO_WIDE_CMP(<=)
    GECKO_WIDE_CMP(>)
    GECKO_WIDE_CMP(>=)
    GECKO_WIDE_CMP(==)
#undef GECKO_WIDE_CMP
    friend vd operator-(vd a) {
      for (int k = 0; k < U; ++k) a.h[k] = -a.h[k];
      return a;
    }
  };
#undef GECKO_WIDE_OP

  // Hw::sqrt(x, k): chain k's root (an ISA may compute some chains' roots on other units)
  static vd sqrt(vd x) {
    for (int k = 0; k < U; ++k) x.h[k] = Hw::sqrt(x.h[k], k);
    return x;
  }
  static bool any(vi m) {
    for (int k = 1; k < U; ++k) m.h[0] |= m.h[k];
    return Hw::any(m.h[0]);
  }
  // bit casts (the generic vectors' (vi)x and (vd)m)
  static vi as_i(vd x) {
    vi r;
    for (int k = 0; k < U; ++k) r.h[k] = (hi)x.h[k];
    return r;
  }
  static vd as_d(vi m) {
    vd r;
    for (int k = 0; k < U; ++k) r.h[k] = (hd)m.h[k];
    return r;
  }
};

}  // namespace bindings
}  // namespace gecko
