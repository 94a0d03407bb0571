"""gecko.friction: force traces for displacement paths (Figs 4 and 8 of paper 000)."""
import numpy as np
import pytest

import gecko


def test_fig4_spatula_trace():
    tr = gecko.force_trace()  # Fig 4 path, paper K
    assert tr.t[0] == 0 and tr.t[-1] == 2
    i = np.flatnonzero(tr.t == 0.5)[0]
    assert (tr.f_par[i], tr.f_perp[i]) == (-3, 2)  # compressive after loading
    assert (tr.f_par[-1], tr.f_perp[-1]) == (12, -7)  # tensile after dragging
    np.testing.assert_allclose(tr.f_par, 5 * tr.d_par - 3 * tr.d_perp, atol=1e-14)
    np.testing.assert_allclose(tr.f_perp, -3 * tr.d_par + 2 * tr.d_perp, atol=1e-14)


def test_fig8_seta_loop():
    tr = gecko.force_trace(gecko.paper_rigidity(), gecko.FIG8_SETA_PATH, times=[0, 1, 2, 3])
    np.testing.assert_array_equal(tr.f_par, [0, -1, 9, 0])
    np.testing.assert_array_equal(tr.f_perp, [0, 2, -4, 0])
    full = gecko.force_trace(path=gecko.FIG8_SETA_PATH, samples_per_segment=10)
    assert len(full.t) == 31


def test_trace_bad_input():
    with pytest.raises(ValueError, match="t = 0.5"):
        gecko.force_trace(path=([0, 0.5, 0.5], [0, 1, 2], [0, 0, 0]))
    with pytest.raises(ValueError, match="symmetric"):
        gecko.force_trace([[5, -3], [-2, 2]])
    with pytest.raises(ValueError, match="positive definite"):
        gecko.force_trace([[5, -4], [-4, 2]])
    with pytest.raises(ValueError, match="times = 3"):
        gecko.force_trace(times=[3.0])
    with pytest.raises(ValueError, match="2x2"):
        gecko.force_trace(np.eye(3))


def test_trace_straight_pillar_and_against_the_curvature():
    # Fig 4 path: load (0,0)->(0,1), drag (0,1)->(3,1). f_perp = K_perp_par d_par + K_perp_perp
    # d_perp: with K_perp_par = 0 (straight pillar) it stays at the load, with K_perp_par > 0
    # (dragged against the curvature) it grows compressive during the drag; with the paper's
    # K_perp_par = -3 it turns tensile (-7).
    for kpq, end in ((0.0, 2.0), (3.0, 11.0), (-3.0, -7.0)):
        tr = gecko.force_trace(((5.0, kpq), (kpq, 2.0)))
        assert tr.f_perp[-1] == pytest.approx(end, abs=1e-14)
        drag = tr.t >= 0.5
        if kpq >= 0:
            assert np.all(tr.f_perp[drag] >= 2.0 - 1e-14)
