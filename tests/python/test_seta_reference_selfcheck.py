"""Re-verify a sample of the committed seta reference rows (tests/data/seta_reference.csv) with the
arbitrary-precision ODE route (tests/data/seta_taylor.py): forward shooting from the base with the
recorded (Fn, theta1'(0)) must satisfy both contact-edge conditions, and solving again from a
perturbed Fn must return the recorded Fn, theta_joint and turning-point counts.  Pure Python
(mpmath), no compiled gecko module needed; runs in a few seconds."""
import csv
import math
import os
import sys

import pytest

mpmath = pytest.importorskip("mpmath")
from mpmath import mp, mpf  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
sys.path.insert(0, DATA)
import seta_taylor as st  # noqa: E402

KEYS = ["EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w"]


def _rows():
    with open(os.path.join(DATA, "seta_reference.csv")) as f:
        return list(csv.DictReader(f))


def _design(row):
    return st.mp_design({k: float(row[k]) for k in KEYS})


def _sample():
    """Deterministic sample covering every kind of row present in the file."""
    rows = _rows()
    picks = {}

    def take(name, pred):
        for i, r in enumerate(rows):
            if pred(r):
                picks.setdefault(name, i)
                return

    take("reference_Ft0", lambda r: r["design_id"] == "0" and float(r["Ft"]) == 0.0)
    take("reference_Ft7", lambda r: r["design_id"] == "0" and float(r["Ft"]) == 7.0)
    take("turning_seg1", lambda r: int(r["turning_points_seg1"]) > 0)
    take("turning_seg2", lambda r: int(r["turning_points_seg2"]) > 0)
    take("ode_only", lambda r: r["route"] == "ode")
    take("extensible_both", lambda r: r["EA1"] != "inf" and r["EA2"] != "inf" and float(r["Ft"]) > 0)
    take("inextensible_spatula", lambda r: r["EA2"] == "inf" and float(r["Ft"]) > 0)
    take("negative_Ft", lambda r: float(r["Ft"]) < 0 and r["design_id"] != "0")
    take("after_fold", lambda r: int(r["branch"]) > 0)
    return [(name, rows[i]) for name, i in sorted(picks.items(), key=lambda kv: kv[1])]


SAMPLE = _sample()


def test_file_shape():
    rows = _rows()
    assert len(rows) >= 200
    assert len({r["design_id"] for r in rows}) >= 31
    assert any(int(r["turning_points_seg1"]) + int(r["turning_points_seg2"]) > 0 for r in rows)
    for r in rows:
        assert r["route"] in ("quad+ode", "ode")
        assert math.isfinite(float(r["Fn"]))


@pytest.mark.parametrize("name,row", SAMPLE, ids=[s[0] for s in SAMPLE])
def test_row_against_ode_route(name, row):
    mp.dps = 30
    d = _design(row)
    Ft = mpf(float(row["Ft"]))
    Fn, beta, p0 = mpf(row["Fn"]), mpf(row["theta_joint"]), mpf(row["theta1p0"])
    # forward shot from the base (theta1(0) = alpha1, theta1'(0) recorded): contact-edge conditions
    r1, r2, pa = st.shoot_forward(d, Fn, Ft, p0)
    assert abs(r1) < 1e-18 and abs(r2) < 1e-18, (r1, r2)
    assert pa >= 0
    # a state 1e-12 away in Fn must violate them (the check can fail)
    q1, q2, _ = st.shoot_forward(d, Fn + mpf("1e-12"), Ft, p0)
    assert max(abs(q1), abs(q2)) > 1e-16
    # solve again from a perturbed start (backward shooting, secant in Fn)
    Fs, _ = st.solve_fn(d, Ft, Fn * (1 + mpf("1e-7")) + mpf("1e-9"))
    assert Fs is not None
    assert abs(Fs - Fn) <= mpf("1e-20") * max(1, abs(Fn))
    s = st.shoot_back(d, Fs, Ft, track=True)
    assert abs(s["beta"] - beta) <= 1e-20
    assert abs(s["theta1p0"] - p0) <= mpf("1e-18") * max(1, abs(p0))
    assert (s["turn1"], s["turn2"]) == (int(row["turning_points_seg1"]), int(row["turning_points_seg2"]))


def test_reference_scene_characteristics():
    with open(os.path.join(DATA, "seta_reference_designs.csv")) as f:
        des = {r["design_id"]: r for r in csv.DictReader(f)}
    ref = des["0"]
    assert abs(float(ref["Fn0"]) - 0.2499) < 1e-4              # docs/theory/two_level_seta.md
    assert abs(float(ref["min_Fn"]) + 2.80) < 0.01
    assert abs(float(ref["Ft_at_min"]) - 7.1) < 0.05
    assert float(ref["Ft_max"]) == 10.0
    row0 = [r for r in _rows() if r["design_id"] == "0" and float(r["Ft"]) == 0.0][0]
    assert mpf(row0["Fn"]) == mpf(ref["Fn0"])


def test_beyond_ftmax_rows_have_negative_edge_slope():
    """The continuation past (Ft)max solves the same equations with theta2'(a) < 0."""
    with open(os.path.join(DATA, "seta_reference_beyond_ftmax.csv")) as f:
        rows = list(csv.DictReader(f))
    assert rows
    mp.dps = 30
    for row in (rows[0], rows[-1]):
        d = _design(row)
        Ft = mpf(float(row["Ft"]))
        Fn, p0 = mpf(row["Fn"]), mpf(row["theta1p0"])
        r1, r2, pa = st.shoot_forward(d, Fn, Ft, p0)
        assert abs(r1) < 1e-18 and abs(r2) < 1e-18
        assert pa < 0 and abs(pa - mpf(row["theta2p_a"])) < 1e-18
        Fs, _ = st.solve_fn(d, Ft, Fn * (1 + mpf("1e-7")), kap=-st.kappa(d, Ft))
        assert abs(Fs - Fn) <= mpf("1e-20") * max(1, abs(Fn))
