// gecko/beam/shape.hpp — centreline shapes z(x) of a planar curved beam, and their slope.
//
// docs/theory/frictional_adhesion.md "Curved-beam force law": the beam's centreline is z(x) for x in [0, L], the tip
// (where the force acts) at x = 0 and the clamp at x = L. Castigliano's integrals need z and the
// slope z' = dz/dx (through ds = sqrt(1 + z'^2) dx). A *shape* is
//   * any callable z(x), whose slope gecko takes by the complex step
//       z'(x) = Im z(x + i h) / h,  h = eps x  (truncation O(h^2 z'''/z'), far below rounding, and
//       no subtraction, hence no cancellation however small h is),
//     so the callable must also accept std::complex<T> (a generic lambda using sqrt, exp, pow,
//     sin, ... from <cmath>/<complex> does; one using abs, comparisons or fmin does not), or
//   * an object with operator()(x) and a member slope(x) giving z' exactly (make_shape builds one
//     from two callables); gecko then never takes a complex step.
// The complex step is exact to rounding for real-analytic z, unlike a finite difference, which
// would cap the accuracy of the compliance near 1e-10 — too little for a 1e-13 rigidity.
#pragma once

#include <cmath>
#include <complex>
#include <limits>
#include <type_traits>
#include <utility>

namespace gecko {

// The parabola of Appendix 1 (paper 000): z = sqrt(L x)/2, vertical tangent at the tip, so
// ds/dx = sqrt(1 + L/(16 x)) ~ x^-1/2 there.
template <class T>
struct parabolic_shape {
  T L;
  template <class U>
  U operator()(U x) const {
    using std::sqrt;
    return sqrt(U(L) * x) / U(2);
  }
  T slope(T x) const {
    using std::sqrt;
    return sqrt(L) / (T(4) * sqrt(x));
  }
};

// A shape with an explicit slope: z(x) and dzdx(x) given by the user.
template <class Z, class DZ>
struct explicit_slope_shape {
  Z z;
  DZ dzdx;
  template <class U>
  auto operator()(U x) const -> decltype(z(x)) {
    return z(x);
  }
  template <class U>
  auto slope(U x) const -> decltype(dzdx(x)) {
    return dzdx(x);
  }
};

template <class Z, class DZ>
explicit_slope_shape<Z, DZ> make_shape(Z z, DZ dzdx) {
  return {std::move(z), std::move(dzdx)};
}

namespace detail {

template <class S, class T, class = void>
struct has_slope : std::false_type {};
template <class S, class T>
struct has_slope<S, T, std::void_t<decltype(std::declval<const S&>().slope(std::declval<T>()))>>
    : std::true_type {};

template <class S, class T, class = void>
struct accepts_complex : std::false_type {};
template <class S, class T>
struct accepts_complex<
    S, T, std::void_t<decltype(std::declval<const S&>()(std::declval<std::complex<T>>()))>>
    : std::true_type {};

// z'(x) of a shape: its own slope() when it has one, else the complex step.
template <class T, class Shape>
T shape_slope(const Shape& shape, T x) {
  if constexpr (has_slope<Shape, T>::value) {
    return static_cast<T>(shape.slope(x));
  } else {
    static_assert(accepts_complex<Shape, T>::value,
                  "gecko: a shape without a slope(x) member must accept std::complex<T> so that "
                  "its slope can be taken by the complex step; or build it with "
                  "gecko::make_shape(z, dzdx)");
    // Relative step: near a tip singularity z varies on the scale x itself. The floor keeps h a
    // normal number for the (negligibly weighted) quadrature nodes closest to the tip.
    constexpr T eps = std::numeric_limits<T>::epsilon();
    constexpr T floor = std::numeric_limits<T>::min() / eps;
    const T h = eps * x > floor ? eps * x : floor;
    const std::complex<T> zc = std::complex<T>(shape(std::complex<T>(x, h)));
    return zc.imag() / h;
  }
}

}  // namespace detail
}  // namespace gecko
