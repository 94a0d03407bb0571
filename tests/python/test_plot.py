"""gecko.plot: functions that draw on a given Axes (Agg), with the papers' labels and ranges."""
import math

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
from matplotlib.figure import Figure  # noqa: E402

import gecko  # noqa: E402
import gecko.plot as gp  # noqa: E402


def axes():
    return Figure().add_subplot(1, 1, 1)


def test_force_space_axes_labels_and_ranges():
    ax = gp.force_space_axes(axes())
    assert ax.get_xlabel() == r"$\bar F_n = F_n/w$" and ax.get_ylabel() == r"$\bar F_t = F_t/w$"
    assert ax.get_xlim() == (-5.0, 2.0) and ax.get_ylim() == (0.0, 10.5)


def test_seta_line_and_peel_lines_data():
    ax = axes()
    (line,) = gp.seta_critical_line(ax, gecko.TwoLevelSeta(w=2.0), label="seta")
    x, y = line.get_data()
    assert y[0] == 0 and y[-1] == pytest.approx(math.sqrt(2 * 50 * 2) / 2)  # non-dimensional by w
    assert x[0] == pytest.approx(gecko.TwoLevelSeta(w=2.0).critical_line(Ft=[0.0]).Fn[0] / 2)
    (k,) = gp.kendall_line(ax, EA=50, w=1)
    kx, ky = k.get_data()
    assert k.get_label() == "Kendall model" and k.get_linestyle() == "--"
    assert ky[-1] == pytest.approx(10.0) and kx[-1] == pytest.approx(0.0, abs=1e-12)
    (rv,) = gp.rivlin_line(ax)
    rx, ry = rv.get_data()
    np.testing.assert_allclose(rx, -np.sqrt(1 + 2 * ry))
    assert [t.get_text() for t in ax.legend().get_texts()] == ["seta", "Kendall model", "Rivlin model"]


def test_fiber_linear_and_characteristic():
    ax = axes()
    (f,) = gp.fiber_critical_line(ax, gecko.SingleFiber(), Ft=[0.0, 1.0])
    assert f.get_data()[0][0] == pytest.approx(gecko.SingleFiber().critical_line([0.0]).Fn[0])
    (lin,) = gp.linear_line(ax, [0.3, 0.0], [0.0, 1.0])
    assert lin.get_linestyle() == "-."
    (c,) = gp.characteristic(ax, [1, 2], [3, 4], label="fn0", small=True, xlabel="xi", ylabel="fn0")
    assert c.get_linestyle() == "--" and ax.get_xlabel() == "xi"


def test_friction_figures_draw():
    ax = axes()
    a, b = gp.force_trace(ax, gecko.force_trace())
    assert b.get_data()[1][-1] == -7.0 and a.get_data()[1][-1] == 12.0
    ax = axes()
    tr = gecko.force_trace(path=gecko.FIG8_SETA_PATH)
    (fs,) = gp.force_space(ax, tr.f_par, tr.f_perp)
    assert len(ax.texts) == 3  # one arrow per leg: load, drag, pull
    fig = Figure()
    ax1, ax2 = fig.subplots(1, 2)
    V = np.geomspace(1e-6, 1e-3, 5)
    ss = gecko.steady_sliding(V)
    p, q = gp.steady_sliding((ax1, ax2), V, ss.F_par, ss.F_perp, label="visco")
    np.testing.assert_allclose(p.get_data()[0], V * 1e6)
    assert "µm/s" in ax1.get_xlabel()


def test_shapes_and_sensitivities_draw():
    seta = gecko.TwoLevelSeta()
    sh = seta.shape(5.0, 50)
    ax = axes()
    (c,) = gp.deformed_shapes(ax, [sh["x"]], [sh["z"]], ["Ft = 5"])
    assert c.get_data()[1][-1] == pytest.approx(0.0, abs=1e-12)
    ax = axes()
    s = seta.sensitivities([0.0, 1.0])
    arts = gp.sensitivities(ax, [0.0, 1.0], {"EI1": s["dFn"][:, 0], "l2": s["dFn"][:, 5]})
    assert len(arts) == 2 and ax.get_xlabel() == gp.FT_LABEL
