"""gecko.friction: stochastic check of the mean field (simulate_spatulae)."""
import numpy as np
import pytest

import gecko


def test_reproducible_and_close_to_mean_field():
    a = gecko.simulate_spatulae(1e-4, spatulae=300, t_off=1e-3, resticking="exponential", seed=5)
    b = gecko.simulate_spatulae(1e-4, spatulae=300, t_off=1e-3, resticking="exponential", seed=5)
    assert a.mean_par == b.mean_par
    np.testing.assert_array_equal(a.F_perp, b.F_perp)
    mf = gecko.steady_sliding(1e-4, t_off=1e-3)
    assert a.mean_par == pytest.approx(mf.F_par, rel=0.02)
    assert a.mean_perp == pytest.approx(mf.F_perp, rel=0.05)
    assert len(a.t) == 200 and a.detachments > 0


def test_convergence_rate_exponential_resticking():
    # RMS error over seeds falls as (M T)^-1/2: 16x (M T) -> 4x smaller.
    mf = gecko.steady_sliding(1e-4, t_off=1e-3)
    P = mf.t_on + 1e-3

    def rms(M, T, R=60):
        e = [gecko.simulate_spatulae(1e-4, spatulae=M, duration=T * P, t_off=1e-3,
                                     resticking="exponential", samples=2, seed=1000 * M + s).mean_par
             - mf.F_par for s in range(R)]
        return np.sqrt(np.mean(np.square(e)))

    r1, r2 = rms(20, 20), rms(80, 80)
    assert r1 / r2 == pytest.approx(4.0, rel=0.3)


def test_fluctuations_scale_as_one_over_sqrt_m():
    s1 = np.mean([gecko.simulate_spatulae(1e-4, spatulae=100, t_off=1e-3, resticking="exponential",
                                          seed=s).std_par for s in range(10)])
    s2 = np.mean([gecko.simulate_spatulae(1e-4, spatulae=1600, t_off=1e-3, resticking="exponential",
                                          seed=s).std_par for s in range(10)])
    assert s1 / s2 == pytest.approx(4.0, rel=0.25)


def test_simulation_bad_input():
    with pytest.raises(ValueError, match="V = 0"):
        gecko.simulate_spatulae(0.0, duration=1.0)
    with pytest.raises(ValueError, match="V = -1"):
        gecko.simulate_spatulae(-1.0, duration=1.0)
    with pytest.raises(ValueError, match="resticking"):
        gecko.simulate_spatulae(1e-4, resticking="poisson")
    with pytest.raises(ValueError, match="t_off = -1"):
        gecko.simulate_spatulae(1e-4, duration=1.0, t_off=-1.0)
