"""gecko.friction_hierarchy: spatula populations and spatulae on a compliant seta (the hierarchy
of paper 000's Discussion)."""
import math

import numpy as np
import pytest

import gecko
import gecko.friction_hierarchy as fh

V = 1e-4
T_OFF = 1e-4


def eqs_9_10(model, V, G, c, t_off):
    """Eqs 9-10 with the duty factor of eqs 5-6, per spatula (forces of N), for spatulae with
    rigidity c K, re-sticking forces c f1 and detachment energy G: written out independently."""
    K = np.asarray(model.K, dtype=float)
    f1, f2 = c * model.f_par1, c * model.f_perp1
    Kpp, Kqp = c * K[0, 0], c * K[1, 0]
    q = np.sqrt(f1 * f1 + 2 * Kpp * G)
    dd = (q - f1) / Kpp
    duty = dd / (dd + V * t_off)
    return model.N * duty * (f1 + q) / 2, model.N * duty * (f2 + Kqp * dd / 2)


# ---- populations ---------------------------------------------------------------------------------

def test_degenerate_population_is_the_single_population_exactly():
    kw = dict(spatulae=300, t_off=T_OFF, seed=4, samples=64)
    ref = gecko.simulate_spatulae(V, **kw)
    for pop in (dict(stiffness=1.0), dict(length=np.ones(300), G0=np.ones(300)),
                dict(stiffness={"dist": "lognormal", "sigma": 0.0})):
        r = fh.spatula_population(V, **pop, **kw)
        assert r.mean_par == ref.mean_par and r.mean_perp == ref.mean_perp
        np.testing.assert_array_equal(r.F_par, ref.F_par)
        assert r.detachments == ref.detachments
        assert r.population_par == pytest.approx(ref.population_par, rel=1e-14)
        if "length" in pop:  # arrays: no distribution to average over
            assert math.isnan(r.expected_par)
        else:
            assert r.expected_par == pytest.approx(ref.population_par, rel=1e-13)
    # without a population, the three mean fields are eqs 9-10 themselves
    ss = gecko.steady_sliding(V, t_off=T_OFF)
    assert ref.mean_field_par == pytest.approx(float(ss.F_par), rel=1e-14)
    assert ref.population_perp == pytest.approx(float(ss.F_perp), rel=1e-14)


def test_narrow_population_approaches_its_averaged_mean_field():
    model = gecko.FIG6_PLASTIC  # f_par1 > 0: the stretch is not a pure power of K and G
    G = float(model.law(V))
    spec = {"dist": "lognormal", "sigma": 0.05}
    ss = gecko.steady_sliding(V, model, t_off=T_OFF)
    P = float(ss.t_on) + T_OFF
    for periods in (10.5, 100.5):
        for seed in (1, 2, 3):
            r = fh.spatula_population(V, model, length=spec, stiffness=spec, G0=spec, spatulae=400,
                                      duration=periods * P, t_off=T_OFF, seed=seed, samples=4)
            f = r.factors
            c = f["stiffness"] / f["length"] ** 3
            Fp, Fq = eqs_9_10(model, V, f["G0"] * G, c, f["length"] ** 2 * T_OFF)
            # the population average is eqs 9-10 per spatula, averaged
            assert r.population_par == pytest.approx(Fp.mean(), rel=1e-12)
            assert r.population_perp == pytest.approx(Fq.mean(), rel=1e-12)
            # the simulation is within the bound of its finite duration, for every seed
            assert abs(r.mean_par - r.population_par) <= r.bound_par * (1 + 1e-9)
            assert abs(r.mean_perp - r.population_perp) <= r.bound_perp * (1 + 1e-9)
            # the bound is one spatula's range over 2 duration / period: ~ 1 / periods
            assert r.bound_par < 2.0 / periods * abs(r.population_par)
            # the drawn spatulae average to the distribution's average within sampling error
            se = Fp.std() / math.sqrt(Fp.size)
            assert abs(r.population_par - r.expected_par) < 5 * se
    assert r.bound_par < 0.02 * r.population_par


@pytest.mark.parametrize("which, exponent", [("stiffness", 0.5), ("G0", 0.5), ("length", -1.5)])
def test_distribution_average_closed_form(which, exponent):
    # f_par1 = 0 and t_off = 0: F = N sqrt(c K G / 2) with c = s / l^3, so F scales as s^1/2,
    # G0^1/2 and l^-3/2. For a lognormal factor x = exp(sigma z - sigma^2/2) of mean 1,
    # E[x^a] = exp(a (a - 1) sigma^2 / 2).
    sigma = 0.3
    r = fh.spatula_population(V, **{which: {"dist": "lognormal", "sigma": sigma}}, spatulae=2000,
                              seed=9, samples=2)
    F0 = float(gecko.steady_sliding(V).F_par)
    assert r.expected_par == pytest.approx(F0 * math.exp(exponent * (exponent - 1) * sigma ** 2 / 2), rel=1e-12)
    # and the mean spatula's eqs 9-10 differ from the average at second order, as Jensen says
    x = r.factors[which]
    assert r.mean_field_par == pytest.approx(F0 * x.mean() ** exponent, rel=1e-12)
    assert r.population_par == pytest.approx(F0 * np.mean(x ** exponent), rel=1e-12)


def test_uniform_distribution_average():
    h = 0.5
    r = fh.spatula_population(V, stiffness={"dist": "uniform", "width": h}, spatulae=500, seed=2, samples=2)
    F0 = float(gecko.steady_sliding(V).F_par)
    # E[s^1/2] for s uniform on [1 - h, 1 + h]
    exact = ((1 + h) ** 1.5 - (1 - h) ** 1.5) / (1.5 * 2 * h)
    assert r.expected_par == pytest.approx(F0 * exact, rel=1e-10)
    assert r.factors["stiffness"].min() >= 1 - h and r.factors["stiffness"].max() <= 1 + h


def test_population_bad_input():
    with pytest.raises(ValueError, match=r"stiffness has 3 entries"):
        fh.spatula_population(V, stiffness=[1.0, 1.0, 1.0], spatulae=4)
    with pytest.raises(ValueError, match=r"G0\[2\] = -1.0 is out of range"):
        fh.spatula_population(V, G0=[1.0, 1.0, -1.0, 1.0], spatulae=4)
    with pytest.raises(ValueError, match="dist = 'lognormal'"):
        fh.spatula_population(V, length={"dist": "normal", "sigma": 0.1}, spatulae=4)
    with pytest.raises(ValueError, match=r"width = 1.5 is out of range"):
        fh.spatula_population(V, length={"dist": "uniform", "width": 1.5}, spatulae=4)
    with pytest.raises(ValueError, match="exactly dist and sigma"):
        fh.spatula_population(V, length={"dist": "lognormal", "sigma": 0.1, "mean": 2}, spatulae=4)
    with pytest.raises(ValueError, match="spatulae = 0"):
        fh.spatula_population(V, G0=1.0, spatulae=0)


# ---- the compliant seta ---------------------------------------------------------------------------

def test_stiff_spring_is_the_rigid_drive():
    r = fh.compliant_seta(V, stiffness_ratio=1e6, t_off=T_OFF, seed=2)
    ss = gecko.steady_sliding(V, t_off=T_OFF)
    assert r.regime == "smooth"
    assert r.relative_drop < 2 * r.granularity  # the largest drop is one or two lone spatulae
    assert r.mean_par == pytest.approx(float(ss.F_par), rel=0.02)
    assert r.collective_stiffness == pytest.approx(gecko.FIG6_VISCOELASTIC.N * 6.0)
    assert r.spring == pytest.approx(1e6 * r.collective_stiffness)


def test_soft_spring_slips_at_the_seta_level():
    # identical spatulae, fixed re-sticking: they detach together and re-stick together
    r = fh.compliant_seta(V, stiffness_ratio=0.01, t_off=T_OFF, seed=2)
    assert r.regime == "stick-slip"
    assert r.max_slip_fraction == 1.0         # the whole population lets go in one slip
    assert r.relative_drop > 1.5              # from about twice the mean force to about 0
    assert r.std_par > 0.3 * r.mean_par


def test_map_and_what_desynchronises_the_spatulae():
    ratios = [0.1, 10.0, 300.0]
    m = fh.stick_slip_map(ratios, [V], t_off=T_OFF, seed=2, periods=15)
    assert m.stick_slip.shape == (1, 3)
    assert m.stick_slip[0].tolist() == [True, True, False]
    assert m.max_slip_fraction[0, 0] == 1.0 and m.max_slip_fraction[0, 2] <= 0.02
    # one point of the map is compliant_seta itself
    r = fh.compliant_seta(V, stiffness_ratio=10.0, t_off=T_OFF, seed=2, periods=15)
    assert m.relative_drop[0, 1] == r.relative_drop
    # a spread of stiffness and G0 keeps the spatulae apart at k_s = 10 N K (largest slip: a few
    # spatulae, against a quarter of them or more when they are identical)
    spread = {"dist": "lognormal", "sigma": 0.3}
    r = fh.compliant_seta(V, stiffness_ratio=10.0, t_off=T_OFF, seed=2, periods=15, stiffness=spread, G0=spread)
    assert r.regime == "smooth" and r.relative_drop < 0.5 * m.relative_drop[0, 1]


def test_compliant_seta_bad_input():
    with pytest.raises(ValueError, match="exactly one of stiffness_ratio"):
        fh.compliant_seta(V, stiffness_ratio=1.0, spring=1.0)
    with pytest.raises(ValueError, match="exactly one of stiffness_ratio"):
        fh.compliant_seta(V)
    with pytest.raises(ValueError, match="stiffness_ratio = -1.0 is out of range"):
        fh.compliant_seta(V, stiffness_ratio=-1.0)
    with pytest.raises(ValueError, match="spatulae = 10 is out of range for threshold"):
        fh.compliant_seta(V, stiffness_ratio=1.0, spatulae=10)
    with pytest.raises(ValueError, match="V = 0"):
        fh.compliant_seta(0.0, stiffness_ratio=1.0)
    with pytest.raises(ValueError, match="transient = 1"):
        fh.compliant_seta(V, stiffness_ratio=1.0, transient=1.0)
    with pytest.raises(ValueError, match="threshold = 2"):
        fh.compliant_seta(V, stiffness_ratio=1.0, threshold=2.0)
