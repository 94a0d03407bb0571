"""Every example scene runs (reduced resolution); the data behind each figure is checked.

Checks are on the numbers that make each figure what it is — number of curves, monotone parts,
endpoints such as (Ft)max, the Kendall line's maximum — not on pixels.
"""
import math
from pathlib import Path

import numpy as np
import pytest

import gecko
from gecko.scene import Cache, run_scene
from gecko.seta import DESIGN_FIELDS

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RES = 0.25  # CI resolution: a quarter of each range's points
_CACHE = Cache()


def run(name, **kw):
    path = EXAMPLES / f"{name}.toml"
    return run_scene(path, resolution=kw.pop("resolution", RES), cache=_CACHE, progress=False, **kw)


def curves_by_role(result, plot):
    out = {}
    for c in result.curves[plot]:
        out.setdefault(c.role, []).append(c)
    return out


def chars(result, study="seta"):
    return [d["characteristics"] for d in result.data[study]]


def kendall_max_closed_form(EA, w):
    """Independent route to the Kendall maximum: at the extremum of Fn^2 = N^2 - Ft^2,
    N = Ft EA/(EA - Ft) with N + N^2/(2EA) = Ft + w; solve for Ft by bisection."""
    def g(ft):
        N = ft * EA / (EA - ft)
        return N + N * N / (2 * EA) - ft - w
    lo, hi = 0.0, math.sqrt(2 * EA * w)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) < 0 else (lo, mid)
    ft = 0.5 * (lo + hi)
    N = ft * EA / (EA - ft)
    return ft, math.sqrt(N * N - ft * ft)


def test_demo_reference_critical_line():
    r = run("demo_reference_critical_line")
    roles = curves_by_role(r, "demo_reference_critical_line")
    assert [len(roles[k]) for k in ("seta", "kendall", "rivlin")] == [1, 1, 1]
    seta = roles["seta"][0]
    ok = np.isfinite(seta.x)
    assert ok.all()
    assert seta.x[0] == pytest.approx(0.2499, abs=1e-4)  # (Fn)0 > 0: not sticky at rest
    c = chars(r)[0]
    assert c["fn0"] == pytest.approx(0.2499, abs=1e-4)
    assert c["max_pull_off"] == pytest.approx(2.80, abs=0.01) and c["ft_at_max_pull_off"] == pytest.approx(7.1, abs=0.1)
    assert c["ft_max"] == 10.0 and not c["sticky_at_rest"]
    # the plotted line's minimum agrees with the characteristic (within the grid spacing)
    assert -seta.x.min() <= c["max_pull_off"] + 1e-9 and -seta.x.min() > c["max_pull_off"] - 0.01
    assert seta.y[-1] == pytest.approx(10.0)  # the line runs to (Ft)max = sqrt(2 EA2 w)
    # Kendall line: Fn = -w at Ft = 0, 0 at (Ft)max, its maximum against a closed form
    k = roles["kendall"][0]
    assert k.x[0] == pytest.approx(kendall_fn_at0(50.0, 1.0), rel=1e-14)
    assert k.y[-1] == pytest.approx(10.0) and k.x[-1] == pytest.approx(0.0, abs=1e-12)
    ft, pull = kendall_max_closed_form(50.0, 1.0)
    kc = r.data["kendall"][0]["characteristics"]
    assert kc["max_pull_off"] == pytest.approx(pull, rel=1e-12)
    assert kc["ft_at_max_pull_off"] == pytest.approx(ft, rel=1e-6)
    assert -k.x.min() <= pull * (1 + 1e-12)
    # Rivlin: monotone, Fn = -sqrt(w^2 + 2 w Ft)
    rv = roles["rivlin"][0]
    assert np.all(np.diff(rv.x) < 0)
    np.testing.assert_allclose(rv.x, -np.sqrt(1 + 2 * rv.y), rtol=1e-15)


def kendall_fn_at0(EA, w):
    # N + N^2/(2EA) = w at Ft = 0
    return -EA * (-1 + math.sqrt(1 + 2 * w / EA))


def test_seta_fig2a_axial_stiffness():
    r = run("seta_fig2a_axial_stiffness")
    roles = curves_by_role(r, "seta_fig2a")
    assert len(roles["seta"]) == 4 and len(roles["kendall"]) == 1 and len(roles["rivlin"]) == 1
    inext, *ext = roles["seta"]
    assert inext.meta["values"]["EA2"] == math.inf
    assert np.all(np.diff(inext.x) < 0)  # no maximum pull-off without axial stiffness
    for c in ext:  # (Ft)max = sqrt(2 EA2 w) = 10, and a maximum pull-off inside the line
        assert c.y[-1] == pytest.approx(10.0)
        j = np.nanargmin(c.x)
        assert 0 < j < c.x.size - 1
    cs = chars(r)
    assert [c["ft_max"] for c in cs[1:]] == [10.0, 10.0, 10.0]
    # the beam's axial stiffness matters little (paper: "relatively small"): EA1/w from inf to 50
    # raises the maximum pull-off by about 11 %, monotonically
    pulls = [c["max_pull_off"] for c in cs[1:]]
    assert pulls[0] < pulls[1] < pulls[2] < 1.15 * pulls[0]
    # all four share (Fn)0 closely (axial terms vanish at small forces)
    assert np.ptp([c["fn0"] for c in cs]) < 0.01


def test_seta_fig2b_length_ratio():
    r = run("seta_fig2b_length_ratio")
    roles = curves_by_role(r, "seta_fig2b")
    assert len(roles["seta"]) == 3 and len(roles["kendall"]) == 1
    fn0 = [c["fn0"] for c in chars(r)]
    assert fn0[0] > fn0[1] > fn0[2]  # longer spatula: lower (Fn)0, more adhesive at rest
    for c in roles["seta"]:
        assert c.y[-1] == pytest.approx(10.0)
        n = c.x.size // 3  # near-linear bending part: Fn decreasing with Ft
        assert np.all(np.diff(c.x[:n]) < 0)


def test_seta_fig3a_bending_stiffness_ratio():
    r = run("seta_fig3a_bending_stiffness_ratio")
    roles = curves_by_role(r, "seta_fig3a")
    assert len(roles["seta"]) == 4
    st = r.scene.study("seta")
    assert [p.values["EI2"] / p.values["EI1"] for p in st.points] == pytest.approx([0.1, 0.2, 0.4, 0.8])
    fn0 = [c["fn0"] for c in chars(r)]
    assert all(a > b for a, b in zip(fn0, fn0[1:]))  # beyond the peak near 0.1, (Fn)0 falls
    assert [c.label for c in roles["seta"]] == ["EI₂/EI₁ = 0.1", "EI₂/EI₁ = 0.2", "EI₂/EI₁ = 0.4", "EI₂/EI₁ = 0.8"]


def test_seta_fig3b_second_angle():
    r = run("seta_fig3b_second_angle")
    assert len(curves_by_role(r, "seta_fig3b")["seta"]) == 4
    cs = chars(r)
    fn0 = [c["fn0"] for c in cs]
    pull = [c["max_pull_off"] for c in cs]
    assert all(a > b for a, b in zip(fn0, fn0[1:]))  # larger alpha2: lower (Fn)0
    assert all(a < b for a, b in zip(pull, pull[1:]))


def test_seta_fig3c_angle_distribution():
    r = run("seta_fig3c_angle_distribution")
    st = r.scene.study("seta")
    assert all(p.values["alpha1"] + p.values["alpha2"] == pytest.approx(math.pi / 3) for p in st.points)
    cs = chars(r)
    assert np.ptp([c["fn0"] for c in cs]) < 0.15  # (Fn)0 almost constant ...
    slopes = [abs(c["slope_at_zero"]) for c in cs]
    assert all(a < b for a, b in zip(slopes, slopes[1:]))  # ... while the slope changes a lot
    assert slopes[-1] / slopes[0] > 4


def test_seta_fig4_single_vs_two_level():
    r = run("seta_fig4_single_vs_two_level")
    roles = curves_by_role(r, "seta_fig4")
    assert len(roles["seta"]) == 1 and len(roles["fiber"]) == 3 and len(roles["kendall"]) == 1
    fibers = [d["characteristics"]["fn0"] for d in r.data["fiber"]]
    assert fibers[0] < 0  # the soft single fiber (EI/(w l^2) = 1/2) is sticky at rest ...
    assert chars(r)[0]["fn0"] > 0  # ... the two-level seta is not
    soft = roles["fiber"][0]
    kendall = roles["kendall"][0]
    # the soft fiber stays close to the Kendall line at large shear (Kendall limit)
    upper = soft.y > 5
    kx = np.interp(soft.y[upper], kendall.y, kendall.x)
    assert np.max(np.abs(soft.x[upper] - kx)) < 0.25


def test_seta_fig5a_fn0_vs_stiffness_ratio():
    r = run("seta_fig5a_fn0_vs_stiffness_ratio", resolution=0.5)
    assert r.plan.kernels("seta") == ["fn0", "small_deformation"]  # no line traced for (Fn)0
    curves = r.curves["seta_fig5a"]
    assert [c.yname for c in curves] == ["fn0", "small_fn0"]
    for c in curves:
        assert np.all(np.diff(c.x) > 0) and c.x[0] == pytest.approx(0.01) and c.x[-1] == pytest.approx(1.0)
        peak = c.x[np.argmax(c.y)]
        assert 0.07 < peak < 0.15  # both peak near EI2/EI1 = 0.1 (paper)
    exact = curves[0]
    j = np.argmin(np.abs(exact.x - 0.4))
    ref = gecko.TwoLevelSeta(EI2=5 * exact.x[j]).critical_line(Ft=[0.0]).Fn[0]
    assert exact.y[j] == pytest.approx(ref, rel=1e-12)


def test_seta_fig5b_slope_vs_alpha2():
    r = run("seta_fig5b_slope_vs_alpha2")
    curves = r.curves["seta_fig5b"]
    assert [c.yname for c in curves] == ["abs_slope_at_zero", "small_abs_slope_k"]
    for c in curves:
        assert np.all(np.diff(c.y) > 0)  # the paper's 1/|k| grows with alpha2
    st = r.scene.study("seta")
    assert all(p.values["alpha1"] + p.values["alpha2"] == pytest.approx(math.pi / 3) for p in st.points)
    k = [d["characteristics"]["slope_at_zero"] for d in r.data["seta"]]
    np.testing.assert_array_equal(np.abs(k), curves[0].y)
    # both slopes under their own names (issue 13): the tangent at Ft = 0 and the paper's k (eq 16)
    c = gecko.TwoLevelSeta(**{f: st.points[5].values[f] for f in DESIGN_FIELDS}).characteristics()
    got = r.data["seta"][5]["characteristics"]
    assert (got["slope_at_zero"], got["paper_k"]) == (c.slope_at_zero, c.paper_k) and c.slope_at_zero != c.paper_k
    assert "slope_k" not in got  # a deprecated alias only where asked for


def test_seta_fig6a_optimal_structure():
    r = run("seta_fig6a_optimal_structure")
    roles = curves_by_role(r, "seta_fig6a")
    assert len(roles["seta"]) == 1 and len(roles["kendall"]) == 1
    c = chars(r)[0]
    assert c["fn0"] > 0 and c["max_pull_off"] == pytest.approx(2.80, abs=0.01)
    seta = roles["seta"][0]
    j = np.argmin(seta.x)
    assert np.all(np.diff(seta.x[: j + 1]) <= 1e-12)   # pull-off grows with shear up to the maximum
    assert np.all(np.diff(seta.x[j:]) >= -1e-12)       # then falls towards (Ft)max


def test_friction_fig4_spatula_force_trace():
    r = run("friction_fig4_spatula_force_trace")
    roles = curves_by_role(r, "friction_fig4")
    fpar, fperp = roles["f_par"][0], roles["f_perp"][0]
    i = np.flatnonzero(fperp.x == 0.5)[0]
    assert (fpar.y[i], fperp.y[i]) == (-3.0, 2.0)     # compressive after loading
    assert (fpar.y[-1], fperp.y[-1]) == (12.0, -7.0)  # tensile after dragging
    assert np.all(np.diff(fperp.y[i:]) < 0)


def test_friction_fig8_seta_force_space():
    r = run("friction_fig8_seta_force_space")
    (c,) = r.curves["friction_fig8"]
    t = c.meta["t"]
    corners = [np.flatnonzero(t == v)[0] for v in (0.0, 1.0, 2.0, 3.0)]
    assert [(c.x[j], c.y[j]) for j in corners] == [(0, 0), (-1, 2), (9, -4), (0, 0)]


def test_friction_fig6_steady_sliding():
    r = run("friction_fig6_steady_sliding")
    curves = r.curves["friction_fig6"]
    assert len(curves) == 4 and sorted(c.panel for c in curves) == [0, 0, 1, 1]
    by = {(c.study, c.yname): c for c in curves}
    for model in ("viscoelastic", "plastic"):
        fpar, fperp = by[(model, "F_par")], by[(model, "F_perp")]
        assert np.all(np.diff(fpar.y) > 0)   # friction grows with velocity
        assert np.all(np.diff(fperp.y) < 0)  # adhesion (tensile normal force) grows too
        assert fperp.y[-1] < 0
    # the fits' low-velocity limits: N sqrt(K G0/2) = 0.03 N (viscoelastic), N f_par1 = 0.06 N (plastic)
    assert by[("viscoelastic", "F_par")].y[0] == pytest.approx(0.03, rel=0.03)
    assert by[("plastic", "F_par")].y[0] == pytest.approx(0.06, rel=1e-3)


def test_more_shapes_and_sensitivities():
    r = run_scene(EXAMPLES / "more" / "reference_shapes_and_sensitivities.toml", progress=False, resolution=RES)
    shapes = r.curves["reference_shapes"]
    assert len(shapes) == 3
    for c in shapes:
        assert c.meta["status"] == 0 and abs(c.meta["closing_error"]) < 1e-8
        assert c.x[0] == 0 and c.y[-1] == pytest.approx(0.0, abs=1e-12)  # clamp at x = 0, edge on the substrate
    sens = r.curves["reference_sensitivities"]
    assert [c.yname for c in sens] == ["dFn_dEI1", "dFn_dEI2", "dFn_dl2", "dFn_dalpha1", "dFn_dalpha2"]
    # check one derivative against a central difference of the critical line
    ft = sens[0].x[3]
    h = 1e-6
    fd = (gecko.TwoLevelSeta(alpha2=math.pi / 6 + h).critical_line(Ft=[ft]).Fn[0]
          - gecko.TwoLevelSeta(alpha2=math.pi / 6 - h).critical_line(Ft=[ft]).Fn[0]) / (2 * h)
    assert sens[4].y[3] == pytest.approx(fd, rel=1e-6)


def test_seta_contact_contours():
    """Contours of a: between l1 and l1 + l2 where the load has one equilibrium on the spatula; at
    each Ft the contact state just above the critical line has a close to l1 + l2, and a falls
    towards l1 as the load pushes (Ft = 0 row, where a is monotone in Fn)."""
    r = run("seta_contact_contours")
    d = r.data["seta"][0]["contact_contours"]
    a, status, Fn, Ft = d["a"], d["status"], d["Fn"], d["Ft"]
    ok = status == 0
    assert ok.sum() > 50
    assert np.all((a[ok] > 1.0) & (a[ok] <= 1.1))
    assert np.all(np.isnan(a[(status != 0) & (status != 7)]))  # inadmissible states keep a
    row = a[0][ok[0]]  # Ft = 0: from the critical line (Fn)0 = 0.25 up to the joint line
    assert np.all(np.diff(row) < 0)
    assert Fn[ok[0]][0] == pytest.approx(0.25, abs=6.0 / Fn.size * 1.01)
    seta = gecko.TwoLevelSeta()
    line = seta.critical_line(Ft=Ft[:5])
    st = seta.contact_state(line.Fn + 1e-9, Ft[:5])
    assert np.all(np.abs(st.a - 1.1) < 1e-6)
    (c,) = r.curves["seta_contact_contours"]
    assert c.role == "contact_contours" and c.x.size == a.size


def test_every_example_renders(tmp_path):
    """All example scenes draw (PNG + SVG) at low resolution; every plot gets its CSV."""
    pytest.importorskip("matplotlib")
    for path in sorted(EXAMPLES.rglob("*.toml")):
        r = run_scene(path, tmp_path, formats=["svg"], resolution=0.1, progress=False, cache=_CACHE)
        for p in r.scene.plots:
            for ext in ("png", "svg", "csv"):
                f = tmp_path / f"{p.name}.{ext}"
                assert f.is_file() and f.stat().st_size > 0
            assert (tmp_path / f"{p.name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list(tmp_path.glob(".gecko-staging-*"))
