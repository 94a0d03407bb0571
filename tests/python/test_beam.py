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
