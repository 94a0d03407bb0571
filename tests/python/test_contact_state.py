"""TwoLevelSeta.contact_state: the forward problem (paper 001 after eq 15), against an independent
ODE shooting (tests/data/contact_state_reference.csv, made by
tests/data/gen_contact_state_reference.py), the critical line, a dense scan, and its input checks."""
import csv
import math
from pathlib import Path

import numpy as np
import pytest

import gecko
from gecko.seta import ContactStatus

DATA = Path(__file__).resolve().parents[1] / "data" / "contact_state_reference.csv"
FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")


def reference_rows():
    with open(DATA, newline="") as f:
        return list(csv.DictReader(f))


def test_matches_ode_shooting_to_1e11_in_a():
    rows = reference_rows()
    assert len(rows) >= 60
    classes = {}
    worst = 0.0
    for r in rows:
        seta = gecko.TwoLevelSeta(**{k: float(r[k]) for k in FIELDS})
        st = seta.contact_state(float(r["Fn"]), float(r["Ft"]))
        where = f"{r['class']} Fn={r['Fn']} Ft={r['Ft']} design={[r[k] for k in FIELDS]}"
        # near (Ft)max the reference design dips below the substrate: inadmissible, values kept
        assert int(st.status) in (ContactStatus.CONVERGED, ContactStatus.INADMISSIBLE), where
        assert (int(st.status) == ContactStatus.INADMISSIBLE) == (float(st.min_z) < -1e-12 * (float(r["l1"]) + float(r["l2"])))
        assert int(st.equilibria) == 1, where
        err = abs(float(st.a) - float(r["a"]))
        worst = max(worst, err)
        assert err <= 1e-11, where
        assert abs(float(st.theta_joint) - float(r["theta_joint"])) <= 1e-10, where
        assert abs(float(st.theta_rate_base) - float(r["theta_rate_base"])) <= 1e-9 * (1 + abs(float(r["theta_rate_base"]))), where
        assert int(st.turning_points) == int(r["turning_points"]), where
        assert float(st.energy_release_rate) == pytest.approx(float(r["w"]), abs=1e-13)
        l1, l2 = float(r["l1"]), float(r["l2"])
        assert l1 < float(st.a) <= l1 + l2
        assert float(st.contact_length) == pytest.approx(l1 + l2 - float(st.a), abs=1e-15)
        classes[r["class"]] = classes.get(r["class"], 0) + 1
    assert classes.get("exact", 0) >= 30 and classes.get("near_singular", 0) >= 8 and classes.get("random", 0) >= 30


def test_on_the_critical_line_a_is_l1_plus_l2():
    for seta in (gecko.TwoLevelSeta(), gecko.TwoLevelSeta(EA2=math.inf), gecko.TwoLevelSeta(EA1=100.0, l2=0.2)):
        ft = np.array([0.0, 1.0, 3.0, 5.0, 7.0])
        line = seta.critical_line(Ft=ft)
        assert (line.status == 0).all()
        st = seta.contact_state(line.Fn, ft)
        assert (st.status == ContactStatus.CONVERGED).all()
        np.testing.assert_allclose(st.a, seta.l1 + seta.l2, rtol=0, atol=1e-11)
        np.testing.assert_allclose(st.theta_joint, line.theta_joint, rtol=0, atol=1e-9)
        np.testing.assert_allclose(st.theta_rate_base, line.theta_rate_base, rtol=0, atol=1e-8)
        below = seta.contact_state(line.Fn - 1e-7, ft)
        assert (below.status == ContactStatus.NO_CONTACT).all()
        above = seta.contact_state(line.Fn + 1e-7, ft)
        assert (above.status == ContactStatus.CONVERGED).all()
        assert (above.a < seta.l1 + seta.l2).all()


def test_default_scan_finds_what_a_dense_scan_finds():
    """No equilibrium missed: the default scan (6 nodes per piece of the orbit) against 64 nodes,
    over a grid of loads of the reference design and two others."""
    for seta in (gecko.TwoLevelSeta(), gecko.TwoLevelSeta(EI1=2.0, EI2=0.5, l2=0.4, alpha2=0.2),
                 gecko.TwoLevelSeta(EA2=math.inf, EI2=1.0, l2=0.3)):
        ftmax = seta.ft_max if math.isfinite(seta.ft_max) else 10.0
        Fn = np.linspace(-5, 3, 81)[None, :]
        Ft = np.linspace(-0.5 * ftmax, 0.999 * ftmax, 41)[:, None]
        a = seta.contact_state(Fn, Ft, all_equilibria=True)
        b = seta.contact_state(Fn, Ft, all_equilibria=True, scan_points=64)
        np.testing.assert_array_equal(a.equilibria, b.equilibria)
        np.testing.assert_array_equal(a.status, b.status)
        k = min(a.a.shape[-1], b.a.shape[-1])
        np.testing.assert_allclose(np.sort(a.a, axis=-1)[..., :k], np.sort(b.a, axis=-1)[..., :k], rtol=0, atol=1e-12)


def test_broadcasting_and_shapes():
    seta = gecko.TwoLevelSeta()
    st = seta.contact_state(np.array([[-1.0], [0.0], [-0.5]]), np.array([0.0, 2.0, 5.0, 7.0]))
    assert st.a.shape == (3, 4) and st.status.shape == (3, 4) and st.turning_points.shape == (3, 4)
    one = seta.contact_state(-0.5, 2.0)
    assert np.shape(one.a) == () and int(one.status) == 0
    assert float(one.a) == float(st.a[2, 1])
    allq = seta.contact_state(np.array([[-1.0], [0.0], [-0.5]]), np.array([0.0, 2.0, 5.0, 7.0]), all_equilibria=True)
    assert allq.a.shape[:2] == (3, 4) and allq.status.shape == (3, 4)
    ok = st.status == 0
    np.testing.assert_array_equal(allq.a[..., 0][ok], st.a[ok])
    assert (allq.state_status[..., 0][ok] == 0).all()
    names = st.status_names()
    assert names.shape == (3, 4) and set(names.ravel()) <= {m.name for m in ContactStatus}


def test_statuses_without_equilibrium():
    seta = gecko.TwoLevelSeta()
    assert int(seta.contact_state(-5.0, 2.0).status) == ContactStatus.NO_CONTACT
    pushed = seta.contact_state(20.0, 2.0)
    assert int(pushed.status) == ContactStatus.BEYOND_JOINT and math.isnan(float(pushed.a))
    # Ft < -(Ft)max: no edge can be in equilibrium (Griffith, eq 3)
    assert int(seta.contact_state(0.0, -10.5).status) == ContactStatus.NO_CONTACT
    # the reference design is not sticky at rest (eq 22); a stiffer-spatula design is
    assert int(seta.contact_state(0.0, 0.0).status) == ContactStatus.NO_CONTACT
    sticky = gecko.TwoLevelSeta(EI1=4.0, EI2=1.5)
    k2 = math.sqrt(2 / 1.5)
    beta = math.pi / 3 + 1.5 / 4 * k2
    assert float(sticky.contact_state(0.0, 0.0).a) == pytest.approx(1 + (math.pi / 2 - beta) / k2, abs=1e-15)


def test_bad_input_is_named():
    seta = gecko.TwoLevelSeta()
    with pytest.raises(ValueError, match=r"Fn.*\(at index \(1, 0\)\)"):
        seta.contact_state(np.array([[0.0], [math.nan]]), np.array([1.0, 2.0]))
    with pytest.raises(ValueError, match=r"\(Ft\)max"):
        seta.contact_state(0.0, 10.01)
    with pytest.raises(ValueError, match="broadcast"):
        seta.contact_state(np.zeros(3), np.zeros(4))
    with pytest.raises(ValueError, match="Ft"):
        seta.contact_state(0.0, math.inf)
    with pytest.raises(ValueError, match="errors"):
        seta.contact_state(0.0, 0.0, errors="ignore")
    with pytest.raises(ValueError, match="scan_points"):
        seta.contact_state(0.0, 0.0, scan_points=2)
    st = seta.contact_state(np.array([math.nan, -0.5, 0.0]), np.array([1.0, 2.0, 11.0]), errors="nan")
    assert list(st.status) == [ContactStatus.INVALID_INPUT, ContactStatus.CONVERGED, ContactStatus.INVALID_INPUT]
    assert math.isnan(st.a[0]) and math.isnan(st.a[2]) and math.isfinite(st.a[1])


def test_bad_input_names_argument_value_index_and_range():
    # issue 13 item 7: nothing silently clipped; each error says what, which element, and what is allowed
    seta = gecko.TwoLevelSeta()
    with pytest.raises(ValueError, match=r"Fn = nan .*need a finite normal force \(at index 2\)"):
        seta.contact_state([0.0, 1.0, math.nan], 1.0)
    with pytest.raises(ValueError, match=r"Fn = inf .*need a finite normal force"):
        seta.contact_state(math.inf, 1.0)
    with pytest.raises(ValueError, match=r"Ft = 10.01 .*need Ft <= \(Ft\)max = sqrt\(2 EA2 w\) = 10 \(at index 1\)"):
        seta.contact_state([0.0, 0.0], [1.0, 10.01])
    with pytest.raises(ValueError, match=r"Ft = nan .*need a finite shear force"):
        seta.contact_state(0.0, math.nan)
    with pytest.raises(ValueError, match=r"shapes \(3,\) and \(4,\)\): need shapes that broadcast"):
        seta.contact_state(np.zeros(3), np.zeros(4))
    # under errors="nan": the statuses critical_line gives the same Ft (5 beyond (Ft)max, 2 below -(Ft)max)
    ft = np.array([10.01, -10.01, math.nan])
    st = seta.contact_state(np.zeros(3), ft, errors="nan")
    line = seta.critical_line(Ft=ft, errors="nan")
    assert list(st.status) == list(line.status) == [ContactStatus.INVALID_INPUT, ContactStatus.NO_CONTACT,
                                                    ContactStatus.INVALID_INPUT]


def test_threads_give_the_same_numbers():
    seta = gecko.TwoLevelSeta()
    Fn = np.linspace(-3, 2, 200)[None, :]
    Ft = np.linspace(0, 9.9, 100)[:, None]
    a1 = seta.contact_state(Fn, Ft, threads=1)
    a2 = seta.contact_state(Fn, Ft, threads=2)
    np.testing.assert_array_equal(a1.status, a2.status)
    np.testing.assert_array_equal(a1.a, a2.a)


def test_contact_contours_scene(tmp_path):
    from gecko.scene import run_scene
    scene = {
        "title": "contours",
        "study": [{"name": "seta", "model": "two_level_seta",
                   "outputs": {"contact_contours": {"Fn": {"range": [-3, 1], "num": 41},
                                                    "Ft": {"range": [0, 9], "num": 10}, "levels": [1.02, 1.05, 1.08]},
                               "csv": True}}],
        "plot": [{"name": "contours", "kind": "contact_contours"}],
    }
    r = run_scene(scene, out=tmp_path, progress=False)
    d = r.data["seta"][0]["contact_contours"]
    assert d["a"].shape == (10, 41)
    seta = gecko.TwoLevelSeta()
    direct = seta.contact_state(d["Fn"][None, :], d["Ft"][:, None])
    np.testing.assert_array_equal(d["a"], direct.a)
    (c,) = r.curves["contours"]
    assert c.role == "contact_contours" and c.x.size == 410
    text = (tmp_path / "contours.csv").read_text().splitlines()
    assert text[0].split(",")[-2:] == ["a_over_l1", "status"]
    assert len(text) == 411
    assert (tmp_path / "contours.png").stat().st_size > 0
    assert (tmp_path / "seta.contact_contours.csv").exists()


def test_contact_contours_scene_checks_its_grids():
    from gecko.scene import SceneError, load_scene
    bad = {"study": [{"name": "s", "model": "two_level_seta",
                      "outputs": {"contact_contours": {"Ft": {"range": [0, 11], "num": 3}}}}]}
    with pytest.raises(SceneError, match=r"contact_contours\.Ft"):
        load_scene(bad)
    bad2 = {"study": [{"name": "s", "model": "two_level_seta", "outputs": {"contact_contours": {"levels": 0}}}]}
    with pytest.raises(SceneError, match="levels"):
        load_scene(bad2)


def test_inadmissible_states_keep_their_values():
    ref = gecko.TwoLevelSeta()
    fn = float(ref.critical_line(Ft=[9.0]).Fn[0]) + 1e-4
    ok = ref.contact_state(fn, 9.0)
    assert int(ok.status) == ContactStatus.CONVERGED and float(ok.max_axial_strain) > 0.17
    lim = ref.contact_state(fn, 9.0, strain_limit=0.1)
    assert int(lim.status) == ContactStatus.INADMISSIBLE
    assert float(lim.a) == float(ok.a) and float(lim.theta_joint) == float(ok.theta_joint)
    with pytest.raises(ValueError, match="strain_limit"):
        ref.contact_state(fn, 9.0, strain_limit=-1.0)
    soft = gecko.TwoLevelSeta(EI1=1.5, EI2=0.3, l2=0.5, alpha1=0.3, alpha2=0.6, EA1=80.0)
    st = soft.contact_state(np.linspace(-5, 3, 41)[None, :], np.linspace(-5, 10, 41)[:, None])
    bad = st.status == ContactStatus.INADMISSIBLE
    assert bad.any()
    assert np.isfinite(st.a[bad]).all() and (st.min_z[bad] < 0).all()
    good = st.status == ContactStatus.CONVERGED
    assert (st.min_z[good] >= -1e-12 * 1.5).all()
