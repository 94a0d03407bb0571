"""gecko.friction: Levenberg-Marquardt fit of eqs 9-10, round trip on noisy synthetic data."""
import numpy as np
import pytest

import gecko


def synthetic(model, noise, seed, n=40):
    rng = np.random.default_rng(seed)
    V = np.logspace(-6, -2, n)
    r = gecko.steady_sliding(V, model)
    return V, r.F_par + noise * rng.standard_normal(n), r.F_perp + noise * rng.standard_normal(n)


def test_fit_viscoelastic_round_trip():
    truth = gecko.FIG6_VISCOELASTIC
    V, Fp, Fq = synthetic(truth, 3e-4, 1)
    guess = truth.replace(f_perp1=3e-7, law=gecko.ViscoelasticDetachment(1e-14, 3e-4, 0.7))
    fit = gecko.fit_steady_sliding(V, Fp, Fq, guess, fit_f_par1=False)
    assert fit.status == "converged"
    assert fit.names == ("G0", "V_star", "n", "f_perp1")
    true = np.array([3e-14, 1e-4, 0.45, 2e-7])
    assert np.all(np.abs(fit.values - true) <= 4 * fit.standard_errors)
    assert np.all(fit.standard_errors / true < 0.1)
    assert fit.model.law.n == fit.values[2]
    # the fitted model reproduces the data to the noise
    r = gecko.steady_sliding(V, fit.model)
    assert np.sqrt(np.mean((r.F_par - Fp) ** 2)) == pytest.approx(3e-4, rel=0.35)


def test_fit_eyring_with_coupling():
    truth = gecko.FIG6_PLASTIC
    V, Fp, Fq = synthetic(truth, 2e-4, 2)
    guess = truth.replace(f_par1=4e-7, K=((6.0, -3.0), (-3.0, 5.0)),
                          law=gecko.EyringDetachment(1e-13, 1e-3))
    fit = gecko.fit_steady_sliding(V, Fp, Fq, guess, fit_coupling=True)
    assert fit.status == "converged"
    true = np.array([3e-14, 6e-4, 6e-7, 0.0, -5.0])
    assert np.all(np.abs(fit.values - true) <= 4 * fit.standard_errors)
    assert fit.covariance.shape == (5, 5)


def test_fit_bad_input():
    V, Fp, Fq = synthetic(gecko.FIG6_VISCOELASTIC, 0.0, 3, n=5)
    Fq[1] = np.nan
    with pytest.raises(ValueError, match=r"F_perp\[1\] = nan"):
        gecko.fit_steady_sliding(V, Fp, Fq)
    with pytest.raises(ValueError, match=r"len\(V\) = 2 .*more data than parameters"):
        gecko.fit_steady_sliding(V[:2], Fp[:2], Fp[:2])
    with pytest.raises(ValueError, match="law"):
        gecko.fit_steady_sliding(V, Fp, Fp, gecko.FIG6_VISCOELASTIC.replace(law=lambda v: v))


def data25(model, sp, sq, seed):
    rng = np.random.default_rng(seed)
    V = np.logspace(-6, -2, 25)
    r = gecko.steady_sliding(V, model)
    return V, r.F_par + sp * rng.standard_normal(25), r.F_perp + sq * rng.standard_normal(25)


@pytest.mark.parametrize("preset,sp,sq,known", [
    ("viscoelastic", 5e-4, 5e-4, False), ("viscoelastic", 5e-4, 2e-4, True),
    ("plastic", 5e-4, 5e-4, False), ("plastic", 2e-4, 8e-4, True)])
def test_fit_coverage_200_seeds(preset, sp, sq, known):
    # Under the default options, started at the preset: >= 90 % of the fits converge, and
    # 2 standard errors cover the truth in >= 90 % of those (95 % if calibrated; 90 % over 200
    # seeds is 3.5 binomial standard deviations below). The default holds f_par1 for the
    # viscoelastic law (G(0) > 0) and fits it for the Eyring law (G(0) = 0).
    truth = gecko.FIG6_VISCOELASTIC if preset == "viscoelastic" else gecko.FIG6_PLASTIC
    law = truth.law
    tv = ([law.G0, law.V_star, law.n] if preset == "viscoelastic"
          else [law.G0, law.V_star, truth.f_par1]) + [truth.f_perp1]
    names = (("G0", "V_star", "n") if preset == "viscoelastic"
             else ("G0", "V_star", "f_par1")) + ("f_perp1",)
    conv, within = 0, np.zeros(len(tv))
    for seed in range(200):
        V, Fp, Fq = data25(truth, sp, sq, 900 + seed)
        fit = gecko.fit_steady_sliding(V, Fp, Fq, truth, sigma=(sp, sq) if known else None)
        assert fit.names == names
        if fit.status != "converged":
            continue
        conv += 1
        within += np.abs(fit.values - tv) <= 2 * fit.standard_errors
    assert conv >= 180
    assert np.all(within >= 0.9 * conv), within / conv


def test_fit_sigma_known_and_rescaled():
    truth = gecko.FIG6_PLASTIC
    V, Fp, Fq = data25(truth, 5e-4, 5e-4, 4)
    a = gecko.fit_steady_sliding(V, Fp, Fq, truth, sigma=(5e-4, np.full(25, 5e-4)))
    b = gecko.fit_steady_sliding(V, Fp, Fq, truth, sigma=(5e-3, 5e-3), absolute_sigma=False)
    c = gecko.fit_steady_sliding(V, Fp, Fq, truth)
    assert a.status == b.status == c.status == "converged"
    assert a.sigma_known and not b.sigma_known and not c.sigma_known
    np.testing.assert_allclose(b.values, a.values, rtol=1e-7)
    np.testing.assert_allclose(b.standard_errors, a.standard_errors * np.sqrt(a.chi2 / a.dof),
                               rtol=1e-6)
    np.testing.assert_allclose(c.standard_errors, b.standard_errors, rtol=1e-6)
    assert a.chi2 == pytest.approx(a.rss / 5e-4 ** 2, rel=1e-10)
    # Unequal weights change the estimates; a tenfold sigma on F_perp nearly removes it.
    d = gecko.fit_steady_sliding(V, Fp, Fq, truth, sigma=(5e-4, 5e-2))
    assert d.status == "converged" and not np.allclose(d.values, a.values, rtol=1e-6)


def test_fit_overflowing_data_is_not_converged():
    V, Fp, Fq = data25(gecko.FIG6_VISCOELASTIC, 0.0, 0.0, 1)
    fit = gecko.fit_steady_sliding(V, 1e200 * Fp, 1e200 * Fq)
    assert fit.status == "non_finite" and "overflow" in fit.reason
    assert fit.status_code == gecko.FitStatus.non_finite


def test_fit_not_identifiable_reports_directions_and_profiles():
    truth = gecko.FIG6_VISCOELASTIC
    seen = 0
    for seed in range(40):
        V, Fp, Fq = data25(truth, 5e-4, 5e-4, 300 + seed)
        fit = gecko.fit_steady_sliding(V, Fp, Fq, truth, fit_f_par1=True)  # every offset free
        assert fit.status in ("converged", "not_identifiable"), fit.reason
        if fit.status == "not_identifiable":
            seen += 1
            assert "ln(V_star)" in fit.undetermined[0] and "ln(G0)" in fit.undetermined[0]
            assert np.all(np.isfinite(fit.profile_lower) | np.isinf(fit.profile_lower))
            assert fit.profile_lower[1] < truth.law.V_star
    assert seen > 0


def test_fit_parametric_law_and_profile():
    truth = gecko.FIG6_VISCOELASTIC
    V, Fp, Fq = data25(truth, 5e-4, 5e-4, 6)
    law = gecko.ParametricLaw(lambda V, G0, V_star, n: G0 * (1 + (V / V_star) ** n),
                              {"G0": 2e-14, "V_star": 2e-4, "n": 0.6})
    a = gecko.fit_steady_sliding(V, Fp, Fq, truth.replace(law=law), fit_f_par1=False,
                                 sigma=(5e-4, 5e-4), profile=True)
    b = gecko.fit_steady_sliding(V, Fp, Fq, truth, fit_f_par1=False, sigma=(5e-4, 5e-4),
                                 profile=True)
    assert a.status == b.status == "converged"
    assert a.names == b.names == ("G0", "V_star", "n", "f_perp1")
    np.testing.assert_allclose(a.values, b.values, rtol=1e-6)
    np.testing.assert_allclose(a.profile_lower, b.profile_lower, rtol=1e-4)
    assert set(a.model.law.params) == {"G0", "V_star", "n"}
    assert np.all(b.profile_lower < b.values) and np.all(b.values < b.profile_upper)
    # 95 % profile intervals are about 1.96 times wider than the 68 % ones.
    c = gecko.fit_steady_sliding(V, Fp, Fq, truth, fit_f_par1=False, sigma=(5e-4, 5e-4),
                                 profile=True, profile_level=0.95)
    np.testing.assert_allclose((c.profile_upper - c.profile_lower)
                               / (b.profile_upper - b.profile_lower), 1.96, rtol=0.1)
    # The fitted law works in steady_sliding.
    r = gecko.steady_sliding(V, a.model)
    assert np.all(np.isfinite(r.F_par))


def test_fit_bad_sigma_and_options():
    V, Fp, Fq = data25(gecko.FIG6_PLASTIC, 5e-4, 5e-4, 1)
    with pytest.raises(ValueError, match=r"sigma_perp\[3\] = 0.0"):
        s = np.full(25, 1e-3)
        s[3] = 0
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC, sigma=(1e-3, s))
    with pytest.raises(ValueError, match="sigma_par must be a scalar or have one entry"):
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC, sigma=(np.ones(3), 1.0))
    with pytest.raises(ValueError, match="sigma must be a pair"):
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC, sigma=1e-3)
    with pytest.raises(ValueError, match="profile_level"):
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC, profile_level=1.5)
    law = gecko.ParametricLaw(lambda V, G0: G0 * np.ones_like(V), {"G0": -1.0})
    with pytest.raises(ValueError, match="G0 = -1"):
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC.replace(law=law))


def test_fit_f_par1_default_follows_the_law():
    V, Fp, Fq = data25(gecko.FIG6_VISCOELASTIC, 5e-4, 5e-4, 12)
    ve = gecko.FIG6_VISCOELASTIC
    assert "f_par1" not in gecko.fit_steady_sliding(V, Fp, Fq, ve).names
    assert "f_par1" in gecko.fit_steady_sliding(V, Fp, Fq, ve, fit_f_par1=True).names
    assert "f_par1" in gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC).names
    assert "f_par1" not in gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC,
                                                    fit_f_par1=False).names
    # a ParametricLaw: G(0) > 0 holds it, G(0) = 0 or a law failing at V = 0 fits it
    plateau = gecko.ParametricLaw(lambda V, G0, V_star: G0 * (1 + np.sqrt(V / V_star)),
                                  {"G0": 3e-14, "V_star": 1e-4})
    power = gecko.ParametricLaw(lambda V, G1: G1 * np.sqrt(V / 1e-4), {"G1": 3e-14})
    logv = gecko.ParametricLaw(lambda V, G1: G1 * np.log(V / 1e-7), {"G1": 3e-14})
    for law, fitted in ((plateau, False), (power, True), (logv, True)):
        fit = gecko.fit_steady_sliding(V, Fp, Fq, ve.replace(law=law))
        assert ("f_par1" in fit.names) == fitted, law


def test_fit_bad_input_names_the_argument():
    V, Fp, Fq = data25(gecko.FIG6_PLASTIC, 5e-4, 5e-4, 1)
    fit = gecko.fit_steady_sliding
    with pytest.raises(ValueError, match=r"F_par has shape \(24,\) and V has shape \(25,\)"):
        fit(V, Fp[:24], Fq)
    with pytest.raises(ValueError, match=r"F_perp has shape \(\) and V"):
        fit(V, Fp, 0.01)  # no broadcasting of a scalar force
    with pytest.raises(ValueError, match=r"V\[4\] = nan .*0 <= V < inf"):
        fit(np.where(np.arange(25) == 4, np.nan, V), Fp, Fq)
    with pytest.raises(ValueError, match=r"V\[0\] = -1e-06"):
        fit(-V, Fp, Fq)
    with pytest.raises(ValueError, match=r"F_par\[7\] = inf"):
        fit(V, np.where(np.arange(25) == 7, np.inf, Fp), Fq)
    with pytest.raises(ValueError, match=r"sigma_par\[0\] = -0.001"):
        fit(V, Fp, Fq, sigma=(-1e-3, 1e-3))
    with pytest.raises(ValueError, match=r"sigma_perp\[0\] = nan"):
        fit(V, Fp, Fq, sigma=(1e-3, np.nan))
    with pytest.raises(ValueError, match="fit_f_par1 = 'no' is not allowed"):
        fit(V, Fp, Fq, fit_f_par1="no")
    with pytest.raises(ValueError, match="profile = 1 is not allowed"):
        fit(V, Fp, Fq, profile=1)
    with pytest.raises(ValueError, match="max_condition"):
        fit(V, Fp, Fq, max_condition=0.5)
    with pytest.raises(ValueError, match="max_iterations"):
        fit(V, Fp, Fq, max_iterations=0)
    # a ParametricLaw that cannot be evaluated at its start is named, with what went wrong
    base = gecko.FIG6_PLASTIC
    raising = gecko.ParametricLaw(lambda V, a: a / 0, {"a": 1.0})
    with pytest.raises(ValueError, match="guess.law: .*raised ZeroDivisionError"):
        fit(V, Fp, Fq, base.replace(law=raising))
    short = gecko.ParametricLaw(lambda V, a: a * np.ones(3), {"a": 1e-14})
    with pytest.raises(ValueError, match=r"guess.law returns shape \(3,\) for 25 velocities"):
        fit(V, Fp, Fq, base.replace(law=short))
    nan_below = gecko.ParametricLaw(lambda V, a: a * np.sqrt(np.log(V / 1e-5)), {"a": 1e-14})
    with pytest.raises(ValueError, match=r"guess.law gives G = nan at V\[0\] = 1e-06"):
        fit(V, Fp, Fq, base.replace(law=nan_below))


def test_fit_reports_why_it_stopped():
    V, Fp, Fq = data25(gecko.FIG6_PLASTIC, 5e-4, 5e-4, 2)
    ok = gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_PLASTIC)
    assert ok.status == "converged" and ok.reason.split(":")[0] in ("gradient", "ftol", "xtol")
    far = gecko.FIG6_PLASTIC.replace(law=gecko.EyringDetachment(1e-10, 1.0))
    short = gecko.fit_steady_sliding(V, Fp, Fq, far, max_iterations=1)
    assert short.status == "max_iterations" and "max_iterations" in short.reason
    assert short.status_code == gecko.FitStatus.max_iterations


def test_fit_parametric_law_bounds():
    truth = gecko.FIG6_VISCOELASTIC
    V, Fp, Fq = data25(truth, 5e-4, 5e-4, 5)
    f = lambda V, G0, V0, n: G0 * (1 + (V / V0) ** n)  # noqa: E731
    start = {"G0": 2e-14, "V0": 2e-4, "n": 0.6}
    kw = dict(sigma=(5e-4, 5e-4), profile=True)
    free = gecko.fit_steady_sliding(V, Fp, Fq, truth.replace(law=gecko.ParametricLaw(f, start)), **kw)
    law = gecko.ParametricLaw(f, start, bounds={"n": (0.0, 2.0), "V0": (1e-6, None)})
    box = gecko.fit_steady_sliding(V, Fp, Fq, truth.replace(law=law), **kw)
    # bounds far from the optimum: the same estimate, errors and profile intervals
    assert free.status == box.status == "converged"
    np.testing.assert_allclose(box.values, free.values, rtol=1e-6)
    np.testing.assert_allclose(box.standard_errors, free.standard_errors, rtol=1e-3)
    np.testing.assert_allclose(box.profile_lower, free.profile_lower, rtol=1e-3)
    np.testing.assert_allclose(box.profile_upper, free.profile_upper, rtol=1e-3)
    assert box.model.law.bounds == law.bounds
    # a bound that binds: the fit stays inside and says the error is not defined there
    tight = gecko.ParametricLaw(f, {**start, "n": 0.3}, bounds={"n": (0.1, 0.35)})
    pinned = gecko.fit_steady_sliding(V, Fp, Fq, truth.replace(law=tight), sigma=(5e-4, 5e-4))
    assert 0.1 < pinned.values[2] <= 0.35
    if pinned.values[2] > 0.35 - 1e-6:
        assert np.isnan(pinned.standard_errors[2]) and "ended at a bound" in pinned.reason


@pytest.mark.parametrize("bounds,match", [
    ({"m": (0, 1)}, "unknown parameter 'm'"), ({"n": (1, 0)}, "need lower < upper"),
    ({"n": (0.7, 2)}, r"params\['n'\] = 0.6 is out of range: need a start strictly inside"),
    ({"n": 3}, r"bounds\['n'\] = 3 is not allowed"), ({"n": (np.nan, 1)}, "need lower < upper"),
    ([("n", 0, 1)], "need a dict")])
def test_fit_bad_bounds(bounds, match):
    V, Fp, Fq = data25(gecko.FIG6_VISCOELASTIC, 5e-4, 5e-4, 5)
    law = gecko.ParametricLaw(lambda V, G0, V0, n: G0 * (1 + (V / V0) ** n),
                              {"G0": 2e-14, "V0": 2e-4, "n": 0.6}, bounds=bounds)
    with pytest.raises(ValueError, match=match):
        gecko.fit_steady_sliding(V, Fp, Fq, gecko.FIG6_VISCOELASTIC.replace(law=law))
