"""gecko.friction, curved-beam part: Castigliano compliance and rigidity (docs/theory/frictional_adhesion.md)."""
import csv
import math
import pathlib

import numpy as np
import pytest

import gecko

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "beam_reference.csv"
EPS = np.finfo(float).eps


def reference():
    with DATA.open() as fh:
        return {f"{r['name']}.{r['quantity']}": float(r["value"]) for r in csv.DictReader(fh)}


REF = reference()


def test_parabolic_closed_form_matches_mpmath():
    C = gecko.parabolic_beam_compliance(1.0, 2.0)  # L^3 / 2EI = 1/4
    a = 4 * C
    np.testing.assert_allclose(a[0, 0], REF["parabola_closed_form.a11"], rtol=4 * EPS)
    np.testing.assert_allclose(a[0, 1], REF["parabola_closed_form.a12"], rtol=4 * EPS)
    np.testing.assert_allclose(a[1, 1], REF["parabola_closed_form.a22"], rtol=4 * EPS)
    # and the closed form is the energy integral (mpmath quadrature): B = a / 2
    assert abs(REF["parabola_closed_form.a11"] - 2 * REF["parabola.B11"]) < 1e-15


def test_castigliano_quadrature_against_closed_form_and_mpmath():
    z = lambda x: np.sqrt(x) / 2  # noqa: E731  complex-step slope
    C, info = gecko.castigliano_compliance(z, L=1.0, EI=1.0, report=True)
    assert info["converged"]
    np.testing.assert_allclose(C, gecko.parabolic_beam_compliance(1.0, 1.0), rtol=1e-13)
    np.testing.assert_allclose(C[0, 0], REF["parabola.B11"], rtol=8 * EPS)
    K = gecko.rigidity(C)
    np.testing.assert_allclose(K, gecko.parabolic_beam_rigidity(1.0, 1.0), rtol=1e-13)
    np.testing.assert_allclose(K[0, 1], REF["parabola_closed_form.K12_unit"], rtol=1e-13)
    # explicit slope, with the axial term (quarter circle, z(0) = 0, C12 = 0 exactly)
    Cq = gecko.castigliano_compliance(lambda x: math.sqrt(2 * x - x * x),
                                      lambda x: (1 - x) / math.sqrt(2 * x - x * x), EA=1.0)
    assert Cq[0, 0] == pytest.approx(REF["quarter_circle.B11"] + REF["quarter_circle.A11"], rel=8 * EPS)
    assert abs(Cq[0, 1]) <= 8 * EPS
    # a shape with z(0) != 0 and no singularity
    Cc = gecko.castigliano_compliance(lambda x: 0.3 + x / 2 + x ** 3)
    assert Cc[1, 1] == pytest.approx(REF["cubic.B22"], rel=32 * EPS)


def test_rigidity_properties_and_normalisation():
    K = gecko.parabolic_beam_rigidity(1.0, 1.0)
    assert K[0, 1] == K[1, 0]
    assert np.all(np.linalg.eigvalsh(K) > 0)
    assert K[0, 1] < 0
    Kn = 5 * K / K[0, 0]
    np.testing.assert_allclose(Kn, [[5, -3.0134], [-3.0134, 1.8989]], atol=1e-4)
    np.testing.assert_allclose(Kn, [[5, -3], [-3, 2]], atol=0.11)


def test_scaling_and_broadcasting():
    L = np.array([0.5, 1.0, 4.0])[:, None]
    EI = np.array([1.0, 3.0])
    C = gecko.parabolic_beam_compliance(L, EI)
    assert C.shape == (3, 2, 2, 2)
    np.testing.assert_allclose(C / (L ** 3 / EI)[..., None, None],
                               np.broadcast_to(gecko.parabolic_beam_compliance(), C.shape), rtol=4 * EPS)
    Cg = gecko.castigliano_compliance(lambda x: np.sqrt(3.0 * x) / 2, L=3.0, EI=0.5)
    np.testing.assert_allclose(Cg, gecko.parabolic_beam_compliance(1.0, 1.0) * 27 / 0.5, rtol=1e-13)
    K = gecko.rigidity(np.stack([C[0, 0], C[2, 1]]))
    assert K.shape == (2, 2, 2)


def test_beam_bad_input():
    with pytest.raises(ValueError, match="L = -1"):
        gecko.parabolic_beam_compliance(-1.0, 1.0)
    assert np.isnan(gecko.parabolic_beam_rigidity([1.0, 0.0], 1.0, errors="nan")[1]).all()
    with pytest.raises(ValueError, match="EI = 0"):
        gecko.castigliano_compliance(lambda x: x, EI=0.0)
    with pytest.raises(ValueError, match="shape"):
        gecko.castigliano_compliance(lambda x: np.log(x) if x > 0 else -np.inf)
    with pytest.raises(ValueError, match="dzdx"):
        gecko.castigliano_compliance(lambda x: math.sqrt(x))  # math.sqrt refuses complex
    with pytest.raises(ValueError, match="symmetric"):
        gecko.rigidity([[1.0, 0.2], [0.1, 1.0]])
    with pytest.raises(ValueError, match="positive definite"):
        gecko.rigidity([[1.0, 2.0], [2.0, 1.0]])
    with pytest.raises(ZeroDivisionError):  # an exception in the user's z propagates
        gecko.castigliano_compliance(lambda x: 1 / 0)


# ---- any centreline (issue 14) ----------------------------------------------------------
# Closed forms, EI = 1, from C_ij = int m_i m_j ds (bending) + int a_i a_j ds / EA (axial) with
# m = (z - z_tip, x - x_tip), a = (t_x, -t_z), t the unit tangent (paper 000 eq A1.1):
# * straight beam of length l at angle a to the x axis, x = s cos a, z = s sin a:
#     m = s (sin a, cos a)  ->  C = l^3/3 [[sin^2, sin cos], [sin cos, cos^2]]
#     a = (cos a, -sin a)   ->  + l/EA [[cos^2, -sin cos], [-sin cos, sin^2]]
# * quarter circle, radius R, tip tangent horizontal, clamp tangent vertical: x = R sin p,
#   z = R (1 - cos p), p in [0, pi/2], ds = R dp:
#     C11 = R^3 int (1 - cos p)^2 = R^3 (3 pi/4 - 2),  C12 = R^3 int (1 - cos p) sin p = R^3/2,
#     C22 = R^3 int sin^2 p = R^3 pi/4;  axial: a = (cos p, -sin p): R/EA [[pi/4, -1/2], ...]
# * the other orientation (tip tangent vertical): x = R (1 - cos p), z = R sin p: C11 and C22
#   swap, C12 = R^3/2; axial R/EA [[pi/4, -1/2], [-1/2, pi/4]] as well.
# * semicircular hook, x = R sin p, z = R (1 - cos p), p in [0, pi] (tip and clamp on the z
#   axis, the hook bulging to +x): C11 = R^3 int_0^pi (1 - cos p)^2 = 3 pi R^3 / 2,
#   C12 = R^3 int_0^pi (1 - cos p) sin p = 2 R^3, C22 = R^3 int_0^pi sin^2 = pi R^3 / 2;
#   axial R/EA [[pi/2, 0], [0, pi/2]].
PI = np.pi


def quarter_A(R):
    return (lambda t: R * np.sin(PI / 2 * t), lambda t: R * (1 - np.cos(PI / 2 * t)))


def test_curve_straight_inclined_beam():
    a, l, EA = 0.7, 1.8, 3.0
    C = gecko.castigliano_compliance(curve=(lambda t: l * np.cos(a) * t,
                                            lambda t: l * np.sin(a) * t), EA=EA)
    s, c = np.sin(a), np.cos(a)
    ref = l ** 3 / 3 * np.array([[s * s, s * c], [s * c, c * c]]) \
        + l / EA * np.array([[c * c, -s * c], [-s * c, s * s]])
    np.testing.assert_allclose(C, ref, rtol=4e-15, atol=4e-15 * abs(ref).max())
    # A vertical pillar (a = pi/2) is a parametric curve, not a graph.
    Cv = gecko.castigliano_compliance(curve=(lambda t: 0 * t, lambda t: l * t))
    np.testing.assert_allclose(Cv, [[l ** 3 / 3, 0], [0, 0]], atol=4e-15 * l ** 3)


@pytest.mark.parametrize("R", [1.0, 0.37])
def test_curve_quarter_circles_both_orientations(R):
    ref_A = R ** 3 * np.array([[3 * PI / 4 - 2, 0.5], [0.5, PI / 4]])
    ref_B = R ** 3 * np.array([[PI / 4, 0.5], [0.5, 3 * PI / 4 - 2]])
    axial = R / 2.0 * np.array([[PI / 4, -0.5], [-0.5, PI / 4]])
    CA = gecko.castigliano_compliance(curve=quarter_A(R), EA=2.0)
    CB = gecko.castigliano_compliance(curve=(lambda t: R * (1 - np.cos(PI / 2 * t)),
                                             lambda t: R * np.sin(PI / 2 * t)), EA=2.0)
    np.testing.assert_allclose(CA, ref_A + axial, rtol=1e-14, atol=1e-15 * R)
    np.testing.assert_allclose(CB, ref_B + axial, rtol=1e-14, atol=1e-15 * R)
    # The same quarter circle as a graph with a vertical tangent at the clamp, default tol.
    Cg, info = gecko.castigliano_compliance(lambda x: R - np.sqrt(R * R - x * x), L=R,
                                            report=True)
    assert info["converged"]
    np.testing.assert_allclose(Cg, ref_A, rtol=2e-12)


def test_curve_semicircular_hook_callables_and_samples():
    R = 0.8
    ref = R ** 3 * np.array([[1.5 * PI, 2.0], [2.0, 0.5 * PI]]) + R / 5.0 * np.eye(2) * PI / 2
    C = gecko.castigliano_compliance(curve=(lambda t: R * np.sin(PI * t),
                                            lambda t: R * (1 - np.cos(PI * t))), EA=5.0)
    np.testing.assert_allclose(C, ref, rtol=1e-14)
    pytest.importorskip("scipy")
    t = np.linspace(0, 1, 400)
    Cs = gecko.castigliano_compliance(curve=(R * np.sin(PI * t), R * (1 - np.cos(PI * t))),
                                      EA=5.0)
    np.testing.assert_allclose(Cs, ref, rtol=1e-8)   # spline interpolation error ~ h^4


def test_lost_complex_part_is_detected():
    # z = |x|, the 45 degree line: C22 = int_0^1 x^2 sqrt(2) dx = sqrt(2)/3 = 0.4714 (the complex
    # step through abs would give 1/3).
    with pytest.warns(RuntimeWarning, match="drops the imaginary part"):
        C = gecko.castigliano_compliance(lambda x: abs(x))
    np.testing.assert_allclose(C, np.full((2, 2), np.sqrt(2) / 3), rtol=1e-10)
    with pytest.warns(RuntimeWarning, match="curve z"):
        Cc = gecko.castigliano_compliance(curve=(lambda t: t, lambda t: np.real(t + 0 * t)))
    np.testing.assert_allclose(Cc, np.full((2, 2), np.sqrt(2) / 3), rtol=1e-10)
    scipy_interp = pytest.importorskip("scipy.interpolate")
    R = 1.0
    p = np.linspace(0, PI / 2, 60)
    sx = scipy_interp.CubicSpline(p / (PI / 2), R * np.sin(p))
    sz = scipy_interp.CubicSpline(p / (PI / 2), R * (1 - np.cos(p)))
    with pytest.warns(RuntimeWarning):
        Cs = gecko.castigliano_compliance(curve=(sx, sz))
    np.testing.assert_allclose(Cs, R ** 3 * np.array([[3 * PI / 4 - 2, 0.5], [0.5, PI / 4]]),
                               rtol=1e-6)


def test_curve_bad_options():
    with pytest.raises(ValueError, match="max_levels = 10 is out of range"):
        gecko.castigliano_compliance(lambda x: x, max_levels=10)
    with pytest.raises(ValueError, match="max_levels = 13 is out of range"):
        gecko.castigliano_compliance(curve=quarter_A(1.0), max_levels=13)
    with pytest.raises(ValueError, match="tol = -1"):
        gecko.castigliano_compliance(curve=quarter_A(1.0), tol=-1.0)
    with pytest.raises(ValueError, match="not both"):
        gecko.castigliano_compliance(lambda x: x, curve=quarter_A(1.0))
    with pytest.raises(ValueError, match="EI = 0"):
        gecko.castigliano_compliance(curve=quarter_A(1.0), EI=0.0)
    with pytest.raises(ValueError, match="coincide"):
        gecko.castigliano_compliance(curve=([0, 1, 1, 2], [0, 0, 0, 1]))
    with pytest.raises(ValueError, match="vectorised"):
        gecko.castigliano_compliance(curve=(lambda t: [1.0, 2.0], lambda t: t))
