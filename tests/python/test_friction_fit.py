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
    with pytest.raises(ValueError, match="F_perp = nan"):
        gecko.fit_steady_sliding(V, Fp, Fq)
    with pytest.raises(ValueError, match=r"len\(V\) = 2 .*more data than parameters"):
        gecko.fit_steady_sliding(V[:2], Fp[:2], Fp[:2])
    with pytest.raises(ValueError, match="law"):
        gecko.fit_steady_sliding(V, Fp, Fp, gecko.FIG6_VISCOELASTIC.replace(law=lambda v: v))
