"""validation/ is an importable package (pytest's pythonpath has the repository root), and its
committed states file is what recheck needs."""
import importlib
import pkgutil

import numpy as np
import pytest

import validation

gecko = pytest.importorskip("gecko")


def test_every_module_imports():
    pytest.importorskip("scipy")
    pytest.importorskip("mpmath")
    for m in pkgutil.iter_modules(validation.__path__):
        importlib.import_module(f"validation.{m.name}")


def test_the_states_file_holds_what_recheck_compares():
    from validation import campaign, recheck
    z = np.load(recheck.STATES)
    n, m = z["FT"].shape
    assert z["P"].shape == (n, len(campaign.FIELDS)) and n == 10000 and m == 6
    for k in ("status", "tpb", "tps", "checked", "v_turns_beam", "v_turns_spatula"):
        assert z[k].shape == (n, m), k
    assert len(str(z["Fn_sha256"])) == len(str(z["beta_sha256"])) == 64
    assert int(z["checked"].sum()) == 39450
    # a few designs re-solved: the statuses the campaign recorded, except states it solved that are
    # now flagged inadmissible (status 7, values kept; issue 13); the whole check: python3 -m validation.recheck
    for i in range(8):
        line = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, z["P"][i]))).critical_line(Ft=z["FT"][i], errors="nan")
        now_inadmissible = (line.status == gecko.CriticalStatus.inadmissible) & (z["status"][i] == 0)
        np.testing.assert_array_equal(np.where(now_inadmissible, 0, line.status), z["status"][i])
        np.testing.assert_array_equal(line.turning_points_beam, z["tpb"][i])


def test_claims_scan_finds_a_known_root_and_confirms_two_campaign_claims():
    # validation/claims.py: the independent scan of R(Fn) = theta1(0) - alpha1 (no gecko code).
    pytest.importorskip("scipy")
    from validation import campaign, claims, recheck
    # a positive control: the reference design's critical state at Ft = 5 is a root the scan finds
    s = gecko.TwoLevelSeta()
    ref = np.array([getattr(s, f) for f in campaign.FIELDS], dtype=float)
    fn = float(s.critical_line(Ft=[5.0]).Fn[0])
    sc = claims.scan_state(ref, 5.0, grid=31, bisections=24)
    near = [r for r in sc["roots"] if abs(r["Fn"] - fn) <= 1e-4 * sc["S"]]
    assert len(near) == 1 and near[0]["in_forms"], sc["roots"]
    # two status-3 claims of the campaign the scan confirms (no root of R in the range)
    z = np.load(recheck.STATES)
    for i, j in ((568, 1), (9597, 5)):
        assert int(z["status"][i, j]) == 3
        sc = claims.scan_state(z["P"][i], float(z["FT"][i, j]), grid=31, bisections=24)
        assert claims.classify(sc) == "no_root", (i, j, sc["roots"])
