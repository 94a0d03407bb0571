"""gecko.friction: detachment laws, stretch at detachment, resonant frequency (eqs 4, 7, 8, A2.6)."""
import numpy as np
import pytest

import gecko


def test_laws_vectorised():
    V = np.logspace(-7, -2, 11)
    np.testing.assert_allclose(gecko.viscoelastic_detachment(V, 2.0, 1e-4, 0.45),
                               2.0 * (1 + (V / 1e-4) ** 0.45), rtol=4e-16)
    np.testing.assert_allclose(gecko.eyring_detachment(V, 2.0, 6e-4), 2.0 * np.arcsinh(V / 6e-4),
                               rtol=4e-16)
    law = gecko.ViscoelasticDetachment(2.0, 1e-4, 0.45)
    assert law(0.0) == 2.0 and isinstance(law(0.0), float)
    G = gecko.viscoelastic_detachment(V[:, None], [1.0, 2.0], 1e-4, 0.45)
    assert G.shape == (11, 2)


def test_stretch_energy_balance():
    K, f1, G = 6.0, np.array([-2e-7, 0.0, 6e-7]), 3e-14
    dd = gecko.detachment_stretch(K, f1, G)
    np.testing.assert_allclose(K * dd ** 2 / 2 + f1 * dd, G, rtol=1e-14)
    # no cancellation for f1 > 0 and tiny G
    assert gecko.detachment_stretch(6.0, 1.0, 1e-30) == pytest.approx(1e-30, rel=1e-14)


def test_resonant_frequency_is_half_the_printed_value():
    nu = gecko.resonant_frequency(100e-9, 1e-6, 1.5e9, 1000.0)
    assert nu == pytest.approx(17.146e6, rel=1e-4)
    assert 2 * nu == pytest.approx(34.3e6, rel=2e-3)


def test_detachment_bad_input():
    with pytest.raises(ValueError, match="G0 = 0"):
        gecko.viscoelastic_detachment(1.0, 0.0, 1.0, 0.5)
    with pytest.raises(ValueError, match="n = -0.5"):
        gecko.viscoelastic_detachment(1.0, 1.0, 1.0, -0.5)
    with pytest.raises(ValueError, match="V_star = 0"):
        gecko.eyring_detachment(1.0, 1.0, 0.0)
    with pytest.raises(ValueError, match="V = -1"):
        gecko.eyring_detachment([1.0, -1.0], 1.0, 1.0)
    out = gecko.eyring_detachment([1.0, -1.0], 1.0, 1.0, errors="nan")
    assert np.isfinite(out[0]) and np.isnan(out[1])
    with pytest.raises(ValueError, match="G = -1"):
        gecko.detachment_stretch(1.0, 0.0, -1.0)
    with pytest.raises(ValueError, match="errors"):
        gecko.eyring_detachment(1.0, 1.0, 1.0, errors="ignore")
