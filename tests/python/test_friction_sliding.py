"""gecko.friction: steady sliding (eqs 5, 6, 9, 10), presets, Python laws."""
import pathlib

import numpy as np
import pytest

import gecko


def eq9_10(V, m, G):
    K = np.asarray(m.K)
    q = np.sqrt(m.f_par1 ** 2 + 2 * K[0, 0] * G)
    return m.N / 2 * (m.f_par1 + q), m.N * (m.f_perp1 + K[1, 0] / (2 * K[0, 0]) * (q - m.f_par1))


@pytest.mark.parametrize("model", [gecko.FIG6_VISCOELASTIC, gecko.FIG6_PLASTIC])
def test_steady_sliding_is_eqs_9_10(model):
    V = np.logspace(-7, -1, 50)
    r = gecko.steady_sliding(V, model)
    Fp, Fq = eq9_10(V, model, model.law(V))
    np.testing.assert_allclose(r.F_par, Fp, rtol=1e-14)
    np.testing.assert_allclose(r.F_perp, Fq, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(r.t_on, r.stretch / V, rtol=1e-15)


def test_fig6_presets():
    m = gecko.FIG6_VISCOELASTIC
    K = np.asarray(m.K)
    assert m.N * np.sqrt(K[0, 0] * m.law.G0 / 2) == pytest.approx(0.03, rel=1e-14)
    assert m.N * m.f_perp1 == pytest.approx(0.02, rel=1e-14)
    V = np.array([0.0, 3e-4])
    g = 1 + (V / 1e-4) ** 0.45
    r = gecko.steady_sliding(V, m)
    np.testing.assert_allclose(r.F_par, 0.03 * np.sqrt(g), rtol=1e-14)
    np.testing.assert_allclose(r.F_perp, 0.02 * (1 - 0.8 * np.sqrt(g)), rtol=1e-13)
    p = gecko.FIG6_PLASTIC
    h = np.sqrt(1 + np.arcsinh(V / 6e-4))
    r = gecko.steady_sliding(V, p)
    np.testing.assert_allclose(r.F_par, 0.03 * (1 + h), rtol=1e-14)
    np.testing.assert_allclose(r.F_perp, -0.025 * (h - 1), rtol=1e-13, atol=1e-18)


def test_finite_t_off_duty_factor():
    V = np.array([1e-5, 1e-4, 1e-3])
    r0 = gecko.steady_sliding(V, t_off=0.0)
    r1 = gecko.steady_sliding(V, t_off=1e-3)
    duty = r0.t_on / (r0.t_on + 1e-3)
    np.testing.assert_allclose(r1.F_par, duty * r0.F_par, rtol=1e-14)
    np.testing.assert_allclose(r1.F_perp, duty * r0.F_perp, rtol=1e-14)


def test_python_callable_laws():
    m = gecko.FIG6_VISCOELASTIC
    V = np.logspace(-6, -2, 7).reshape(7, 1)
    ref = gecko.steady_sliding(V, m)
    # vectorised callable
    vec = gecko.steady_sliding(V, m.replace(law=lambda v: 3e-14 * (1 + (v / 1e-4) ** 0.45)))
    np.testing.assert_allclose(vec.F_par, ref.F_par, rtol=1e-14)
    assert vec.F_par.shape == (7, 1)
    # scalar-only callable (math functions refuse arrays): called element by element
    import math
    calls = []

    def scalar_law(v):
        calls.append(v)
        return 3e-14 * (1 + math.pow(v / 1e-4, 0.45))  # TypeError on an array

    sc = gecko.steady_sliding(V, m.replace(law=scalar_law))
    np.testing.assert_allclose(sc.F_perp, ref.F_perp, rtol=1e-13)
    assert len(calls) == 1 + 7  # the refused vectorised try, then one call per element
    assert isinstance(gecko.steady_sliding(1e-4).F_par, float)


def test_sliding_bad_input():
    m = gecko.FIG6_VISCOELASTIC
    with pytest.raises(ValueError, match="V = -1"):
        gecko.steady_sliding([1e-4, -1.0], m)
    out = gecko.steady_sliding([1e-4, -1.0], m, errors="nan")
    assert np.isfinite(out.F_par[0]) and np.isnan(out.F_par[1])
    with pytest.raises(ValueError, match="V = -1"):
        gecko.steady_sliding([-1.0], m.replace(law=lambda v: v))
    with pytest.raises(ValueError, match="symmetric"):
        gecko.steady_sliding(1e-4, m.replace(K=((6.0, -3.0), (-3.2, 2.4))))
    with pytest.raises(ValueError, match="positive definite"):
        gecko.steady_sliding(1e-4, m.replace(K=((6.0, -3.2), (-3.2, 1.0))))
    with pytest.raises(ValueError, match="G0 = 0"):
        gecko.steady_sliding(1e-4, m.replace(law=gecko.ViscoelasticDetachment(0.0, 1e-4, 0.45)))
    with pytest.raises(ValueError, match="n = 0"):
        gecko.steady_sliding(1e-4, m.replace(law=gecko.ViscoelasticDetachment(1e-14, 1e-4, 0.0)))
    with pytest.raises(ValueError, match="V_star = -1"):
        gecko.steady_sliding(1e-4, m.replace(law=gecko.EyringDetachment(1e-14, -1.0)))
    with pytest.raises(ValueError, match="N = 0"):
        gecko.steady_sliding(1e-4, m.replace(N=0.0))
    with pytest.raises(ValueError, match="G = nan"):
        gecko.steady_sliding(1e-4, m.replace(law=lambda v: np.nan * v))
    with pytest.raises(ValueError, match="t_off = -1"):
        gecko.steady_sliding(1e-4, t_off=-1.0)


def test_long_arrays_threads_and_forces_only():
    V = np.logspace(-7, -1, 450_001)
    full = gecko.steady_sliding(V)
    fo = gecko.steady_sliding(V, forces_only=True)
    assert fo.stretch is None and fo.t_on is None
    np.testing.assert_array_equal(fo.F_par, full.F_par)
    np.testing.assert_array_equal(fo.F_perp, full.F_perp)
    # a bad velocity deep inside a chunk run by a worker thread still raises, naming it
    bad = V.copy()
    bad[400_000] = -2.0
    with pytest.raises(ValueError, match="V = -2"):
        gecko.steady_sliding(bad, gecko.FIG6_PLASTIC)
    out = gecko.steady_sliding(bad, errors="nan", forces_only=True)
    assert np.isnan(out.F_par[400_000]) and np.isfinite(out.F_par[399_999])


def test_straight_pillar_and_dragging_against_the_curvature():
    # F_par does not depend on K_perp_par (eq 9); F_perp = N (f_perp1 + K_perp_par dd / 2)
    # (eq 10): a straight pillar (K_perp_par = 0) keeps the re-sticking load at every speed,
    # and dragging against the curvature (K_perp_par > 0) makes the normal force more
    # compressive the faster it is dragged: regular friction, which needs a load; the paper's
    # curved beam (K_perp_par < 0) turns it tensile instead.
    V = np.logspace(-7, -2, 30)
    base = gecko.FIG6_VISCOELASTIC
    k = base.K[0][1]
    curved = gecko.steady_sliding(V, base)
    pillar = gecko.steady_sliding(V, base.replace(K=((6.0, 0.0), (0.0, 2.4))))
    against = gecko.steady_sliding(V, base.replace(K=((6.0, -k), (-k, 2.4))))
    np.testing.assert_array_equal(pillar.F_par, curved.F_par)
    np.testing.assert_array_equal(against.F_par, curved.F_par)
    np.testing.assert_allclose(pillar.F_perp, base.N * base.f_perp1, rtol=1e-15)
    np.testing.assert_allclose(against.F_perp + curved.F_perp, 2 * base.N * base.f_perp1,
                               rtol=1e-13)
    assert np.all(against.F_perp > 0) and np.all(np.diff(against.F_perp) > 0)
    assert curved.F_perp[-1] < 0
    # The stochastic simulation agrees with the mean field at K_perp_par > 0 as well.
    sim = gecko.simulate_spatulae(1e-4, base.replace(K=((6.0, -k), (-k, 2.4))), spatulae=400,
                                  seed=3)
    mf = gecko.steady_sliding(1e-4, base.replace(K=((6.0, -k), (-k, 2.4))))
    assert sim.mean_perp == pytest.approx(float(mf.F_perp), rel=0.02)


def test_fig6_viscoelastic_normal_force_changes_sign_at_27_8_um_per_s():
    # The Fig 6 scene text: F_perp = N (f_perp1 + rho q / 2) with f_par1 = 0 vanishes where
    # q = -2 f_perp1 / rho, i.e. G(V) = 2 f_perp1^2 / (rho^2 K_par_par): V = 27.843 um/s.
    m = gecko.FIG6_VISCOELASTIC
    K, Kqp, f2, law = m.K[0][0], m.K[0][1], m.f_perp1, m.law
    G = 2 * f2 ** 2 * K / Kqp ** 2
    V0 = law.V_star * (G / law.G0 - 1) ** (1 / law.n)
    assert V0 == pytest.approx(27.843e-6, rel=1e-4)
    F = gecko.steady_sliding([V0 * (1 - 1e-9), V0, V0 * (1 + 1e-9)], m).F_perp
    assert F[0] > 0 > F[2] and abs(F[1]) < 1e-15
    assert np.all(gecko.steady_sliding(np.logspace(-9, -2, 50), gecko.FIG6_PLASTIC).F_perp[1:] < 0)
    text = (pathlib.Path(gecko.__file__).parent / "scene" / "figures"
            / "friction_fig6_steady_sliding.toml").read_text()
    assert "27.8 um/s" in text


def test_plastic_t_on_at_rest_is_its_limit():
    m = gecko.FIG6_PLASTIC
    r = gecko.steady_sliding([0.0, 1e-12], m)
    limit = m.law.G0 / (m.law.V_star * m.f_par1)
    assert r.t_on[0] == pytest.approx(limit, rel=1e-15)
    assert r.t_on[1] == pytest.approx(limit, rel=1e-6)


def test_t_off_from_eq4():
    # nu_R = 0.14 (D/L^2) sqrt(E/rho) = 0.14 * 1e5 * sqrt(1.5e6) = 17.146 MHz for the paper's
    # spatula; t_off = 1/nu_R = 58.32 ns.
    t_ref = 1.0 / (0.14 * 1e-7 / 1e-12 * np.sqrt(1.5e9 / 1000.0))
    V = np.logspace(-6, -1, 6)
    a = gecko.steady_sliding(V, t_off="eq4")
    b = gecko.steady_sliding(V, t_off=t_ref)
    np.testing.assert_allclose(a.F_par, b.F_par, rtol=1e-14)
    # A stiffer, shorter spatula (L = 0.5 um): nu_R x 4, t_off / 4.
    c = gecko.steady_sliding(V, t_off="eq4", spatula={"L": 0.5e-6})
    d = gecko.steady_sliding(V, t_off=t_ref / 4)
    np.testing.assert_allclose(c.F_par, d.F_par, rtol=1e-14)
    # The duty factor only matters where t_on ~ t_off: at 10 cm/s it costs a few per cent.
    assert a.F_par[-1] < gecko.steady_sliding(V[-1]).F_par
    with pytest.raises(ValueError, match="t_off = 'eq5' is not allowed"):
        gecko.steady_sliding(V, t_off="eq5")
    with pytest.raises(ValueError, match="unknown keys"):
        gecko.steady_sliding(V, t_off="eq4", spatula={"W": 1.0})
    with pytest.raises(ValueError, match="only used with t_off='eq4'"):
        gecko.steady_sliding(V, t_off=0.0, spatula={"L": 1e-6})
    sim = gecko.simulate_spatulae(1e-3, t_off="eq4", spatulae=200, seed=2)
    ref = gecko.steady_sliding(1e-3, t_off="eq4")
    assert sim.mean_par == pytest.approx(float(ref.F_par), rel=0.01)
