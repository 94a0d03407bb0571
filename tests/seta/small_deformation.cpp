// Tests of gecko/seta/small_deformation.hpp, the seta's linear theory (paper eqs 7 and 18-22):
// the closed forms (Fn)0 (eqs 19-20) and k (eq 21) must put every point of their line on the
// linear critical-line equation (eq 18) written out directly from P and Q, the contact length
// must satisfy the rest equation (eq 7), and the non-sticky criterion is eq 22 itself.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "gecko/seta/small_deformation.hpp"

namespace {

// Left side minus right side of paper eq 18, with P and Q from their definitions; also returns
// the sum of the absolute values of the terms (the scale for a rounding bound).
template <class T>
T eq18_residual(const gecko::TwoLevelSeta<T>& s, T Fn, T Ft, T& scale) {
  using std::cos; using std::fabs; using std::sin; using std::sqrt;
  const T a12 = s.alpha1 + s.alpha2;
  const T Meq = sqrt(2 * s.EI2 * s.w);
  const T P = Ft * cos(a12) + Fn * sin(a12);
  const T Q = Ft * cos(s.alpha1) + Fn * sin(s.alpha1);
  const T half_pi = T(1.570796326794896619231321691639751442L);
  const T terms[] = {P * s.l2 * s.l2 / (2 * s.EI2), Meq * s.l2 / s.EI2, Q * s.l1 * s.l1 / (2 * s.EI1),
                     (P * s.l2 + Meq) * s.l1 / s.EI1, half_pi, a12};
  scale = 0;
  for (const T& t : terms) scale += fabs(t);
  return terms[0] + terms[1] + terms[2] + terms[3] - (half_pi - a12);
}

}  // namespace

TEMPLATE_TEST_CASE("small-deformation line satisfies paper eqs 7, 18 and 22", "[seta][small_deformation]", float,
                   double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  gecko::TwoLevelSeta<T> ref;  // the paper's reference scene
  gecko::TwoLevelSeta<T> stiff_spatula;
  stiff_spatula.EI2 = T(4);      // EI2/EI1 = 0.8: Meq grows, the seta turns sticky at rest
  stiff_spatula.alpha2 = T(0.9);
  for (const auto& s : {ref, stiff_spatula}) {
    const auto r = gecko::small_deformation(s);
    for (const T Ft : {T(0), T(0.5), T(2), T(7)}) {
      T scale = 0;
      const T fn = gecko::small_deformation_fn(s, Ft);
      CHECK(fn == r.fn0 + r.slope_k * Ft);
      const T residual = eq18_residual(s, fn, Ft, scale);  // sets scale
      CHECK(std::fabs(residual) <= 32 * eps * scale);
    }
    // eq 7: Meq l1/EI1 + Meq (l2 - lc)/EI2 = pi/2 - (alpha1 + alpha2).
    const T Meq = std::sqrt(2 * s.EI2 * s.w);
    const T Delta = T(1.570796326794896619231321691639751442L) - (s.alpha1 + s.alpha2);
    const T lhs = Meq * s.l1 / s.EI1 + Meq * (s.l2 - r.contact_length) / s.EI2;
    CHECK(std::fabs(lhs - Delta) <= 32 * eps * (std::fabs(lhs) + std::fabs(Delta) + Meq * s.l2 / s.EI2));
    // eq 22, and its meaning: non-sticky at rest exactly when the line starts at (Fn)0 >= 0.
    CHECK(r.non_sticky == (Meq * (s.l1 / s.EI1 + s.l2 / s.EI2) <= Delta));
    CHECK(r.non_sticky == (r.fn0 >= 0));
  }
  CHECK(gecko::small_deformation(ref).non_sticky);
  CHECK_FALSE(gecko::small_deformation(stiff_spatula).non_sticky);
  // The paper's qualitative value at the reference scene: (Fn)0 ~ 0.34 (exact line: ~0.25).
  CHECK(gecko::small_deformation(ref).fn0 == Approx(0.3397).margin(2e-3));
}

TEST_CASE("small-deformation: a bad design names the field or gives NaN", "[seta][small_deformation][errors]") {
  gecko::TwoLevelSeta<double> s;
  s.EI2 = -1;
  CHECK_THROWS_WITH(gecko::small_deformation(s), Catch::Contains("EI2"));
  const auto r = gecko::small_deformation(s, gecko::policies::nan_policy());
  CHECK(std::isnan(r.fn0));
  CHECK(std::isnan(r.slope_k));
  CHECK(std::isnan(r.contact_length));
  CHECK_FALSE(r.non_sticky);
}
