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
    # now flagged inadmissible (status 7, values kept; issue 13) and states it gave up on (1 or 6)
    # that are now solved (0 or 7: past the line's stall, in the separatrix limit); the whole
    # check: python3 -m validation.recheck
    for i in range(8):
        line = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, z["P"][i]))).critical_line(Ft=z["FT"][i], errors="nan")
        now_inadmissible = (line.status == gecko.CriticalStatus.inadmissible) & (z["status"][i] == 0)
        recovered = np.isin(z["status"][i], (1, 6)) & np.isin(line.status, (0, 7))
        expected = np.where(recovered, line.status, z["status"][i])
        np.testing.assert_array_equal(np.where(now_inadmissible, 0, line.status), expected)
        np.testing.assert_array_equal(np.where(recovered, -1, line.turning_points_beam), z["tpb"][i])


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


def test_claims_since_column_and_a_natural_state_at_the_edge_of_the_forms():
    # validation/claims.py --since/--column/--status: the claims a change made, and those at one
    # column or of one status only
    from validation import claims, recheck
    P, FT = np.zeros((3, 9)), np.zeros((3, 6))
    old = dict(P=P, FT=FT, status=np.array([[1] * 6, [0] * 6, [6] * 6]))
    st = old["status"].copy()
    st[0, :] = 3
    st[2, 0] = 2
    new = dict(P=P, FT=FT, status=st)
    assert claims.new_claims(new, old) == [(0, j) for j in range(6)] + [(2, 0)]
    assert claims.new_claims(new, old, column=1) == [(0, 1)]
    assert claims.new_claims(new, old, column=0) == [(0, 0), (2, 0)]
    assert claims.new_claims(new, old, status=2) == [(2, 0)]
    assert claims.new_claims(new, old, column=0, status=3) == [(0, 0)]
    # Campaign design 88 (validation/README.md, "Where the give-ups end, and natural states at the
    # edge of the forms"): double's homotopy gives up, long double's finds the edge of the forms,
    # and the traced line has no natural state (status 3, line end unsupported_state). A root
    # inside the forms at Ft = 11.08 (the scan's) then lies on a branch the homotopy does not
    # reach, not on a line the solver missed. Without a wider long double there is no retry.
    if np.finfo(np.longdouble).nmant <= np.finfo(np.float64).nmant:
        pytest.skip("long double is no wider than double here: no retry")
    z = np.load(recheck.STATES)
    assert claims.line_end_check(z["P"][88], 11.0791, 3) == "root_but_no_natural_state"


def test_claims_refine_tells_roots_from_jumps_and_noise():
    # validation/claims.py: bisection converges to a sign change whether R passes through 0, jumps
    # across it, or is noise of an inaccurate shot; only the first is a root. Synthetic R: a
    # square-root-like root at -0.2 (|R| falls slowly), a simple root at 0.3, a jump at 0.7, a root
    # at 1.5 whose |R| sits at the shot's noise, and noise of amplitude 1 around 2.5 with an error
    # estimate far below it (as a stiff shot's can be).
    from validation import claims

    def shoot(x):
        x = np.asarray(x, float)
        # a new value at every ulp of x, from integer arithmetic (the same on every machine)
        bits = x.view(np.int64) * np.int64(2654435761) % np.int64(2001)
        noise = np.where(x <= 2.2, -1.0, np.where(x >= 2.8, 1.0, bits / 1000.0 - 1.0))
        r = np.select([x < 0.0, x < 0.5, x < 1.0, x < 2.0],
                      [np.sign(x + 0.2) * np.sqrt(np.abs(x + 0.2)), 2.0 * (x - 0.3), np.where(x < 0.7, -0.4, 0.3),
                       np.where(x < 1.5, -1e-13, 1e-13)], default=noise)
        return r, np.zeros_like(x), np.full(x.shape, 1e-13)

    lo, hi = np.array([-0.45, 0.1, 0.6, 1.2, 2.2]), np.array([-0.05, 0.45, 0.9, 1.8, 2.8])
    r_lo, r_hi = shoot(lo)[0], shoot(hi)[0]
    assert np.all(r_lo * r_hi < 0)
    x, rx, _, _, spread, kind = claims.refine(shoot, lo, hi, r_lo, r_hi, bisections=30)
    np.testing.assert_allclose(x[:4], [-0.2, 0.3, 0.7, 1.5], atol=1e-9)
    assert list(kind) == ["root", "root", "jump", "root", "unresolved"], (list(kind), spread)
    assert abs(spread[2] - 0.7) < 1e-15  # across the jump |R| does not fall at all
    # the state's verdict: a jump is no root; an unresolved sign change leaves it undecided
    scan = {"unreliable_nodes": 0, "roots": [], "jumps": [{}], "unresolved": []}
    assert claims.classify(scan) == "no_root"
    assert claims.classify({**scan, "unresolved": [{}]}) == "undecided"


def test_line_ends_first_integrals_match_the_solved_rates():
    # validation/line_ends.py measures each segment's distance from its separatrix through the
    # first integrals' constants M (the spatula's from Griffith's condition, the beam's from the
    # joint); on solved states R(u) must equal EI/2 theta'^2 at the segment's other end too.
    import math
    from validation import campaign, line_ends
    s = gecko.TwoLevelSeta()
    d = {f: float(getattr(s, f)) for f in campaign.FIELDS}
    line = s.critical_line(Ft=np.linspace(0.0, 9.5, 8))
    assert np.all(line.status == 0)
    q = line_ends.node_quantities(line, d)
    N, phi = np.hypot(line.Fn, line.Ft), np.arctan2(line.Fn, line.Ft)
    c2 = 1.0 / d["EA2"]
    # spatula: R(1) from the separatrix distance, R(u) at the joint from the joint rate
    M2 = line.Ft + d["w"]
    u = np.sin(line.theta_joint - phi)
    np.testing.assert_allclose(M2 - N * u - c2 * N * N * u * u / 2, d["EI2"] / 2 * line.theta_rate_joint ** 2,
                               rtol=1e-9, atol=1e-9)
    # beam (inextensible here): M1 from the joint (moment continuity, eq 4), checked at the base
    k1 = d["EI2"] / d["EI1"] * line.theta_rate_joint
    v = np.sin(line.theta_joint - d["alpha2"] - phi)
    M1 = d["EI1"] / 2 * k1 ** 2 + N * v
    u0 = np.sin(d["alpha1"] - phi)
    np.testing.assert_allclose(M1 - N * u0, d["EI1"] / 2 * line.theta_rate_base ** 2, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(q["beam_separatrix"], (M1 - N) / (np.abs(M1) + N), rtol=1e-12)
    # the reference line crosses both separatrices (the distances have opposite signs at Ft = 0 and
    # 9.5) and every state between is solved: crossing one is not what makes a line give up
    for key in ("spatula_separatrix", "beam_separatrix"):
        assert q[key][0] > 1e-3 and q[key][-1] < -1e-3, q[key]
    node = {k: float(v[0]) for k, v in q.items()}
    assert line_ends.mechanism("stalled", node) == "other"
    assert line_ends.mechanism("stalled", {**node, "beam_separatrix": 1e-11}) == "beam_separatrix"
    assert line_ends.mechanism("reached_ft_end", {**node, "beam_separatrix": 1e-11}) == "now_reached"
    assert math.isfinite(node["spatula_elastic_lengths"])
    np.testing.assert_allclose(q["beam_axial_load_rel"], N / d["EA1"], rtol=1e-15)
    designs = [{"design": 0, "mechanism": "other", "ft_end": -1.0, "last": node, "on_forms_edge_since_ft": None},
               {"design": 1, "mechanism": "other", "ft_end": 2.0, "last": {**node, "beam_axial_load_rel": 3.0},
                "on_forms_edge_since_ft": None}]
    summary = line_ends.by_mechanism(designs, np.array([[6, 6, 0], [0, 6, 2]]))["other"]
    assert summary["designs"] == 2 and summary["status6_states"] == 3 and summary["traced_to_negative_ft"] == 1
    assert summary["beam_axial_load_rel_min_median_max"][2] == 3.0 and summary["on_forms_edge"] == 0
    # the edge of the forms, 1 - b4 (b4 = c N / (1 + sqrt(1 + 2 c M))): 1 for the inextensible beam,
    # the spatula's from its first integral's M2 = Ft + w; the reference line stays off it
    np.testing.assert_array_equal(q["beam_forms_edge"], 1.0)
    np.testing.assert_allclose(q["spatula_forms_edge"], 1 - c2 * N / (1 + np.sqrt(1 + 2 * c2 * M2)), rtol=1e-15)
    assert line_ends.on_forms_edge_since(q) is None
    assert line_ends.mechanism("stalled", {**node, "beam_forms_edge": 1e-12}) == "beam_forms_edge"
    assert line_ends.mechanism("stalled", {**node, "spatula_forms_edge": 1e-12}) == "spatula_forms_edge"


def test_line_lengths_counts_elastic_lengths_by_status(tmp_path):
    # line_ends.lengths: the longer segment's l sqrt(N / EI), N = hypot(Fn, Ft) where Fn is known,
    # else the lower bound |Ft|; here a beam (EI1 = 1, l1 = 1) and a spatula (EI2 = 1e-2, l2 = 0.1)
    # make the spatula's count l2 sqrt(N / EI2) = sqrt(N) the same as the beam's.
    from validation import line_ends
    P = np.array([[1.0, 1e-2, np.inf, np.inf, 1.0, 0.1, 0.5, 0.5, 1.0]] * 2)
    FT = np.array([[0.0, 20.0, 400.0], [-2500.0, 0.0, 900.0]])
    Fn = np.array([[-4.0, -15.0, np.nan], [np.nan, -9.0, np.nan]])
    status = np.array([[0, 0, 6], [6, 7, 1]], dtype=np.int8)
    f = tmp_path / "states.npz"
    np.savez(f, P=P, FT=FT, Fn=Fn, status=status)
    r = line_ends.lengths(str(f))["by_status"]
    assert r["0"]["states"] == 2 and r["0"]["max"] == 5.0  # sqrt(hypot(-15, 20))
    assert r["7"]["max"] == 3.0
    assert r["6"]["states"] == 2 and r["6"]["max"] == 50.0  # sqrt(|-2500|), the lower bound
    assert r["6"]["percent_above"]["30"] == 50.0 and r["6"]["percent_above"]["10"] == 100.0
    assert r["1"]["max"] == 30.0 and r["1"]["percent_above"]["30"] == 0.0


def test_forms_edge_from_fn_and_beta_matches_the_solved_rates():
    # line_ends.forms_edge takes the joint rate from the spatula's first integral (a states file
    # has Fn and beta only); on solved states of a design with an extensible beam it must give the
    # 1 - b4 that node_quantities gives from the solver's own joint rate, and count them by status
    from validation import campaign, line_ends
    s = gecko.TwoLevelSeta(EA1=60.0)
    d = {f: float(getattr(s, f)) for f in campaign.FIELDS}
    ft = np.linspace(-3.0, 9.0, 7)
    line = s.critical_line(Ft=ft)
    assert np.all(line.status == 0)
    q = line_ends.node_quantities(line, d)
    P = np.array([[d[f] for f in campaign.FIELDS]])
    edge = line_ends.forms_edge(P, ft[None, :], line.Fn[None, :], line.theta_joint[None, :])[0]
    np.testing.assert_allclose(edge, np.minimum(q["beam_forms_edge"], q["spatula_forms_edge"]), rtol=0, atol=1e-12)
    assert np.all(edge < 1) and np.all(edge > 1e-3)
    # the beam's stretch at its joint end, 1 + T/EA1 with T = Ft sin(theta1) - Fn cos(theta1)
    th1 = line.theta_joint - d["alpha2"]
    joint = 1 + (line.Ft * np.sin(th1) - line.Fn * np.cos(th1)) / d["EA1"]
    np.testing.assert_allclose(q["beam_joint_stretch"], joint, rtol=0, atol=1e-13)
    assert np.all(line_ends.end_stretch(P, ft[None, :], line.Fn[None, :], line.theta_joint[None, :])[0] <= joint)
    assert np.ptp(joint) > 1e-3   # the load changes it along the line
    r = line_ends.forms_edge_solved(P, ft[None, :], line.Fn[None, :], line.theta_joint[None, :],
                                    np.array([[0, 0, 7, 0, 6, 0, 0]]))
    assert r["solved"] == 6 and r["below"]["0.001"] == {} and r["within_1e-6"] == []


def test_status1_designs_sorts_the_designs_by_their_scales():
    # FIELDS order: EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w
    from validation import status1_designs as sd
    P = np.array([
        [0.1, 100.0, np.inf, np.inf, 1.0, 0.01, 0.5, 0.5, 1.0],   # sqrt(200)/(2 pi 0.1) = 22.5 turns
        [1.0, 1e-4, np.inf, np.inf, 1.0, 0.5, 0.5, 0.5, 1.0],     # 0.0023 turns; l2 sqrt(2e4) = 70.7
        [1.0, 1.0, 2.0, np.inf, 1.0, 0.1, 0.5, 0.5, 1.0],         # 0.23 turns, 0.14 lengths, strain 0.5
        [1.0, 1.0, 1e3, 1e3, 1.0, 0.1, 0.5, 0.5, 1.0],            # nothing extreme
    ])
    turns, lengths, strain = sd.design_scales(P)
    assert turns[0] == pytest.approx(np.sqrt(200) / (2 * np.pi * 0.1))
    assert lengths[1] == pytest.approx(0.5 * np.sqrt(2e4)) and strain[2] == 0.5 and strain[0] == 0
    assert list(sd.classify(P)) == [0, 1, 2, 3]
    status = np.array([[1, 1, 1], [1, 1, 1], [0, 1, 6], [0, 7, 3]], dtype=np.int8)
    r = sd.summary(P, status)
    assert r["status1_states"] == 7 and r["status1_states_in_designs_without_natural_state"] == 6
    assert r["classes_without_natural_state"] == {"coiled beam": 1, "long spatula": 1, "extensible": 0, "other": 0}
    assert r["classes_with_a_solved_state"] == {"coiled beam": 0, "long spatula": 0, "extensible": 1, "other": 1}
    top = r["by_beam_turns"][-1]
    assert top["beam_turns"] == [10.0, None] and top["designs"] == 1 and top["without_natural_state"] == 1


def test_status1_designs_scan_samples_both_halves_and_tallies_the_verdicts(monkeypatch):
    from validation import claims
    from validation import status1_designs as sd
    P = np.array([[0.1, 100.0, np.inf, np.inf, 1.0, 0.01, 0.5, 0.5, 1.0]] * 3
                 + [[1.0, 1e-4, np.inf, np.inf, 1.0, 0.5, 0.5, 0.5, 1.0]] * 3 + [[1.0] * 9])
    status = np.array([[1, 1]] * 6 + [[0, 0]], dtype=np.int8)
    seen = []

    def fake_scan(p, ft):  # a root inside the forms for the coiled designs, none for the others
        seen.append((float(p[0]), ft))
        coiled = p[0] == 0.1
        return {"roots": [{"Fn": -1.0, "beta": 0.5, "in_forms": True}] if coiled else [], "jumps": [],
                "unresolved": [], "unreliable_nodes": 0}

    monkeypatch.setattr(claims, "scan_state", fake_scan)
    r = sd.scan_sample(P, status, 4, seed=0)
    assert len(r["designs"]) == 4 and all(ft == 0.0 for _, ft in seen)
    assert all(d["design"] < 6 for d in r["designs"])  # the solved design is never drawn
    assert r["verdicts"] == {"coiled beam": {"root_in_forms": 2}, "long spatula": {"no_root": 2}}


def test_hermite_minimum_is_exact_for_a_cubic():
    from validation import verify
    # z(t) = (t - 0.3)^2 (t + 1) - 0.05 on [0, 1]: minimum at t = 0.3 (z = -0.05), inside the step
    z = lambda t: (t - 0.3) ** 2 * (t + 1) - 0.05  # noqa: E731
    dz = lambda t: 2 * (t - 0.3) * (t + 1) + (t - 0.3) ** 2  # noqa: E731
    lo = verify._hermite_min(np.array([z(0.0)]), np.array([dz(0.0)]), np.array([z(1.0)]), np.array([dz(1.0)]))
    assert abs(lo[0] + 0.05) < 1e-15
    # monotone: the smaller end
    lo = verify._hermite_min(np.array([1.0]), np.array([-0.5]), np.array([0.5]), np.array([-0.5]))
    assert lo[0] == 0.5


def test_admissibility_shot_confirms_min_z_and_flags_injected_errors():
    # validation/admissibility.py: the lowest height by the independent shot (no gecko code) against
    # gecko's min_z and status; the reference design with alpha2 = 1 crosses the substrate near (Ft)max
    pytest.importorskip("scipy")
    from validation import admissibility, campaign
    s = gecko.TwoLevelSeta(alpha2=1.0)
    ft = np.array([[5.0, 9.9, 9.999]])
    line = s.critical_line(Ft=ft[0])
    status = line.status[None, :].astype(np.int64)
    np.testing.assert_array_equal(status[0], [0, 7, 7])
    P = np.array([[getattr(s, f) for f in campaign.FIELDS]], dtype=float)
    Fn, min_z = line.Fn[None, :], line.min_z[None, :]
    r = admissibility.check(P, ft, Fn, status, min_z)
    assert r["conclusive"].all() and not r["wrong"].any() and not r["differs"].any()
    assert np.nanmax(r["dev"]) < 1e-12 and r["shot_min_z"][0, 2] < -1e-3
    # injected: a crossing state called admissible, an admissible one called crossing, a wrong depth
    bad = status.copy()
    bad[0, 1] = 0
    assert admissibility.check(P, ft, Fn, bad, min_z)["wrong_admissible"][0].tolist() == [False, True, False]
    bad = status.copy()
    bad[0, 0] = 7
    mz = min_z.copy()
    mz[0, 0] = -0.01
    r = admissibility.check(P, ft, Fn, bad, mz)
    assert r["wrong_inadmissible"][0].tolist() == [True, False, False]
    mz = min_z.copy()
    mz[0, 2] += 1e-7
    assert admissibility.check(P, ft, Fn, status, mz)["differs"][0].tolist() == [False, False, True]
    # status 7 with the check not made (min_z NaN): an admissible state and a crossing one
    bad = np.array([[7, 7, 7]])
    mz = min_z.copy()
    mz[0, 0] = mz[0, 1] = np.nan
    r = admissibility.check(P, ft, Fn, bad, mz)
    assert r["unchecked"][0].tolist() == [True, True, False]
    assert r["unchecked_above"][0].tolist() == [True, False, False]
    assert r["unchecked_crossing"][0].tolist() == [False, True, False]
    assert not r["flagged_by_sign"].any()


def test_admissibility_sign_decided_where_the_shot_is_not_conclusive(monkeypatch):
    # Where the double shot is not conclusive (uncertainty above TOL / 10) its sign can still be
    # certain by its own uncertainty, and admissibility.py reports the verdicts it contradicts there
    # ("by sign"). The bookkeeping is tested here on injected shots. (For deep states these flags
    # are the double shot's own errors wherever admissibility_mp.py decides them: its uncertainty
    # estimate diverges with it; validation/README.md.)
    from validation import admissibility, campaign
    s = gecko.TwoLevelSeta()
    P = np.array([[getattr(s, f) for f in campaign.FIELDS]], dtype=float)
    L = s.l1 + s.l2
    shot = np.array([-0.35, -0.35, 0.0, 0.0, -2e-3]) * L
    unc = np.array([6e-4, 6e-4, 6e-4, 6e-4, 6e-4]) * L
    monkeypatch.setattr(admissibility.verify, "heights", lambda d, Ft, Fn: (shot.copy(), unc.copy()))
    ft = np.zeros((1, 5))
    Fn = np.ones((1, 5))
    status = np.array([[0, 7, 0, 7, 0]])
    min_z = np.array([[0.0, -0.39 * L, 0.0, -0.2 * L, 0.0]])
    r = admissibility.check(P, ft, Fn, status, min_z)
    assert not r["conclusive"].any() and not r["wrong"].any()
    # certain crossing called admissible; a crossing called crossing; the edge at 0 (sign not
    # certain above -1e-12 L by 10 u) is not judged; a 7 whose shot is within 10 u of 0 is not
    # judged either; -2e-3 L with u = 6e-4 L is not certain by ten times u
    assert r["flagged_admissible_by_sign"][0].tolist() == [True, False, False, False, False]
    assert not r["flagged_inadmissible_by_sign"].any()
    assert r["sign_decided"][0].tolist() == [True, True, False, False, False]
    shot[2:4] = 0.1 * L  # certainly above the substrate: a 7 there is wrong, a 0 right
    r = admissibility.check(P, ft, Fn, status, min_z)
    assert r["flagged_inadmissible_by_sign"][0].tolist() == [False, False, False, True, False]
    assert r["flagged_by_sign"][0].tolist() == [True, False, False, True, False]


def test_changed_compares_lowest_heights_of_states_both_solved():
    # validation/changed.py: min_z of the states solved in both files, relative to l1 + l2; a NaN in
    # one file only and a crossing verdict (below -1e-12 (l1 + l2)) that flips are counted.
    from validation import changed
    P = np.array([[1.0, 0.1, np.inf, 50.0, 1.0, 0.1, 0.5, 0.5, 1.0]])  # l1 + l2 = 1.1
    status = np.array([[0, 0, 7, 0, 1]], dtype=np.int8)
    old = {"P": P, "status": status, "min_z": np.array([[0.0, -1.1e-3, -2.2e-13, np.nan, np.nan]])}
    new = {"P": P, "status": status.copy(), "min_z": np.array([[0.0, -1.1e-3 + 1.1e-15, -2.2e-12, 0.0, -5.0]])}
    r = changed.height_changes(old, new)
    assert r["solved_in_both"] == 4 and r["checked_in_both"] == 3
    assert r["nan_in_one_only"] == 1
    assert r["changed"] == 2 and r["verdicts_flipped"] == 1
    assert abs(r["max_rel_change"] - (2.2e-12 - 2.2e-13) / 1.1) < 1e-20
    assert changed.height_changes({"status": status}, new) is None


def test_changed_judges_beta_as_well_as_fn(tmp_path, monkeypatch):
    # validation/changed.py: a moved state whose Fn the verifier confirms but whose beta it finds
    # 1e-6 off is silently wrong (in beta), and the moved states are listed with both changes.
    from validation import campaign, changed
    P = np.array([[1.0, 0.1, np.inf, 50.0, 1.0, 0.1, 0.5, 0.5, 1.0]])
    FT = np.array([[1.0, 2.0, 3.0]])
    status = np.zeros((1, 3), dtype=np.int8)
    turns = np.zeros((1, 3), dtype=np.int64)
    old = dict(P=P, FT=FT, status=status, Fn=np.array([[1.0, 2.0, 3.0]]), beta=np.array([[0.1, 0.2, 0.3]]),
               tpb=turns, tps=turns)
    new = dict(old, Fn=np.array([[1.0, 2.0 + 1e-9, 3.0]]), beta=np.array([[0.1, 0.2 + 1e-6, 0.3 + 1e-6]]))
    np.savez(tmp_path / "old.npz", **old)
    np.savez(tmp_path / "new.npz", **new)

    def verify(P, FT, Fn, beta, status):
        z = np.zeros(status.shape)
        # the verifier's root is the old state; conclusive in both except beta in column 2
        return dict(dFn=Fn - old["Fn"], dbeta=beta - old["beta"], fn_uncert=z + 1e-14,
                    beta_uncert=np.array([[1e-14, 1e-14, 1e-6]]), turns_beam=turns, turns_spatula=turns,
                    root_turns_beam=turns, root_turns_spatula=turns)

    monkeypatch.setattr(campaign, "verify_states", verify)
    r = changed.run(str(tmp_path / "old.npz"), str(tmp_path / "new.npz"))
    assert r["moved"] == 2 and r["verified_conclusive"] == 2 and r["verified_conclusive_beta"] == 1
    assert r["silently_wrong"] == 1
    assert r["wrong_states"][0]["column"] == 1 and r["wrong_states"][0]["wrong_in"] == ["beta"]
    assert abs(r["max_abs_dbeta_conclusive"] - 1e-6) < 1e-12
    assert [m["column"] for m in r["moved_states"]] == [1, 2]
    assert abs(r["moved_states"][1]["change_beta"] - 1e-6) < 1e-12


def test_classify_takes_no_verdict_from_a_root_on_another_branch():
    """A verifier root 1e-6 away from the returned Fn, with its own uncertainty far below the
    threshold, flags the state wrong; the same root with other turning points than the state (at the
    returned Fn or at the root itself) is another branch of the shot: no verdict, counted apart."""
    from validation import campaign
    P = np.ones((1, len(campaign.FIELDS)))
    FT, Fn, beta = np.full((1, 3), 10.0), np.full((1, 3), -5.0), np.full((1, 3), 1.0)
    status = np.zeros((1, 3), dtype=np.int64)
    tpb, tps = np.ones((1, 3), dtype=np.int64), np.ones((1, 3), dtype=np.int64)
    v = dict(dFn=np.full((1, 3), 5e-6), dbeta=np.zeros((1, 3)), fn_uncert=np.full((1, 3), 1e-14),
             beta_uncert=np.full((1, 3), 1e-14),
             turns_beam=np.array([[1, 0, 1]]), turns_spatula=np.ones((1, 3), dtype=np.int64),
             root_turns_beam=np.array([[1, 1, 3]]), root_turns_spatula=np.ones((1, 3), dtype=np.int64))
    without = campaign.classify(P, FT, Fn, beta, status, v)
    assert without["wrong_fn"].all() and not without["other_branch"].any()
    cl = campaign.classify(P, FT, Fn, beta, status, v, turns=(tpb, tps))
    assert cl["wrong_fn"].tolist() == [[True, False, False]]
    assert cl["other_branch"].tolist() == [[False, True, True]]
    assert cl["inconclusive_fn"].tolist() == [[False, True, True]]


def test_bracket_route_proves_a_root_and_refuses_an_injected_error():
    # The reference design at Ft = 5: the bracketing shot finds gecko's root between Fn -+ 1e-11
    # (same turning points, base rate and beta), and finds no sign change around an Fn moved by
    # 1e-9 (relative), where the state would be wrong.
    pytest.importorskip("mpmath")
    import math
    from validation import separatrix  # noqa: F401  (puts tests/data on the path)
    import seta_separatrix_mp as ssm
    s = gecko.TwoLevelSeta()
    d = {k: float(getattr(s, k)) for k in ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")}
    line = s.critical_line(Ft=[5.0])
    Fn, beta, q = float(line.Fn[0]), float(line.theta_joint[0]), float(line.theta_rate_base[0])
    assert int(line.status[0]) == 0
    L = sum(ssm.saddle_lengths(d, math.hypot(Fn, 5.0)))
    b = ssm.bracket_route(d, 5.0, Fn, L, halvings=12)
    assert b is not None
    assert abs(float(b["Fn"]) - Fn) <= 1e-11 * max(1, abs(Fn))
    assert abs(float(b["beta"]) - beta) <= 1e-11
    assert abs(float(b["q"]) - q) <= 1e-8 * max(1, abs(q))
    assert tuple(b["turns"]) == (int(line.turning_points_beam[0]), int(line.turning_points_spatula[0]))
    assert ssm.bracket_route(d, 5.0, Fn * (1 + 1e-9), L, halvings=2) is None
    # the two end shots alone: the sign change and beta at both ends, no bisection
    e = ssm.bracket_ends(d, 5.0, Fn, L)
    assert e["sign_change"] and max(abs(float(b) - beta) for b in e["beta"]) <= 1e-11
    assert not ssm.bracket_ends(d, 5.0, Fn * (1 + 1e-9), L)["sign_change"]
    # extensible: the saddle's time constant counts 1 + N/EA
    assert ssm.saddle_lengths(dict(d, EA1=2.0), 6.0)[0] == pytest.approx(math.sqrt(6.0 * 4.0 / d["EI1"]))


def test_admissibility_mp_heights_agree_and_verdicts_flag_injected_errors():
    # validation/admissibility_mp.py: the arbitrary-precision bracketing shot carries the height; on
    # the reference design with alpha2 = 1 (crossing near (Ft)max) its lowest height is gecko's
    # min_z, and the verdict rule flags a crossing called admissible and an admissible state called
    # crossing.
    pytest.importorskip("mpmath")
    from validation import admissibility_mp, campaign
    s = gecko.TwoLevelSeta(alpha2=1.0)
    fts = np.array([5.0, 9.9, 9.999])
    line = s.critical_line(Ft=fts)
    P = np.array([getattr(s, f) for f in campaign.FIELDS], dtype=float)
    for j in (0, 2):
        r = admissibility_mp.check((0, j, P, fts, float(line.min_z[j]), 60))
        assert r["verdict"] == "correct", r
        assert abs(r["shot_min_z"] - float(line.min_z[j])) <= 1e-12
    assert r["shot_min_z"] < -1e-3 and r["status"] == 7
    L = s.l1 + s.l2
    assert admissibility_mp.verdict(0, 0.0, r["shot_min_z"], L) == "wrong"
    assert admissibility_mp.verdict(7, -0.01, 0.0, L) == "wrong"
    assert admissibility_mp.verdict(7, r["shot_min_z"] + 1e-6, r["shot_min_z"], L) == "differs"


def test_folds_bisection_brackets_the_fold_and_refuses_other_statuses():
    # validation/folds.py finds a fold's Ft from gecko's statuses alone: solved (0 or 7) short of
    # it, 2 or 6 past it. A seta stand-in with a known fold at Ft = -3.25 (and, in the second, a
    # stretch of status 3 on the way) checks the bracket and the refusal.
    from validation import folds

    class Line:
        def __init__(self, st):
            self.status = np.array([st])

    class Folded:
        def __init__(self, fold, other=None):
            self.fold, self.other = fold, other

        def critical_line(self, Ft, errors):
            x = Ft[0]
            if self.other is not None and self.other[0] <= x <= self.other[1]:
                return Line(3)
            return Line(7 if x > self.fold else 6)

    lo, hi = folds.fold_ft(Folded(-3.25), -10.0)
    assert hi < -3.25 < lo and lo - hi < 10.0 / 2**29
    assert folds.fold_ft(Folded(-3.25, other=(-6.0, -4.0)), -10.0) is None


def test_folds_pair_verdict_wants_a_partner_that_closes_as_the_square_root():
    # validation/folds.py's pair test: two roots that merge at the fold, their gap ~ sqrt(distance),
    # none left past it. Injected failures: a gap that does not close, a root past the fold, no
    # partner found, no state short of the fold.
    from validation import folds

    def pair(eta, gap, past=0, found=True):
        return dict(eta=eta, B=1.0 if found else None, gap=gap, past_changes=past)

    fold = [pair(1e-4, 3e-3), pair(1e-6, 3e-4)]
    assert folds.pair_verdict(fold) == "fold_confirmed"
    assert folds.pair_verdict([pair(1e-4, 3e-3), pair(1e-6, 2.5e-3)]) == "undecided"  # 311-like
    assert folds.pair_verdict([pair(1e-4, 3e-3), pair(1e-6, 3e-4, past=3)]) == "root_past_fold"
    assert folds.pair_verdict([pair(1e-4, 3e-3), pair(1e-6, 3e-4, found=False)]) == "undecided"
    assert folds.pair_verdict([pair(1e-4, 3e-3), None]) == "undecided"


def test_folds_parabola_law_and_verdict_on_a_made_fold_and_injected_failures():
    # validation/folds.py's parabola test: gecko's states short of a quadratic fold follow
    # Fn = Ff + c x + e x^2 + f x^3 (x = sqrt(distance)), whose differences fall by sqrt(10) per
    # decade; a line that goes on with a finite slope falls by 10. The partner predicted on the
    # returning branch, Ff - c x + e x^2 - f x^3, must be a shot root on A's path. Injected
    # failures: a finite slope, an unconfirmed state, a partner on another path or too far away.
    import math

    from validation import folds

    etas = list(folds.PARABOLA_ETAS)
    Ff, c, e, f = 14.36, -317.3, 0.54, 96.9  # design 7529's fold (validation/README.md)
    A = [Ff + c * math.sqrt(t) + e * t + f * t ** 1.5 for t in etas]
    ratios, coef = folds.sqrt_law(A, etas)
    assert all(abs(r - math.sqrt(10)) < 0.05 for r in ratios)
    assert max(abs(a - b) for a, b in zip(coef, (Ff, c, e, f))) < 1e-6 * abs(c)
    x = math.sqrt(folds.PARTNER_ETA)
    B = Ff - c * x + e * x * x - f * x ** 3
    gap = abs(A[-1] - B)
    path = dict(Fn=A[-1], q=-64.2, turns=[1, 0])

    def made(ratios=ratios, confirmed=True, partner=dict(Fn=B + gap / 40, q=-64.1, turns=[1, 0])):
        conf = [dict(eta=t, A=A[etas.index(t)], A_root=dict(path, Fn=A[etas.index(t)]) if confirmed else None)
                for t in folds.CONFIRM_ETAS]
        return dict(ratios=ratios, sqrt_law=all(abs(r / math.sqrt(10) - 1) <= 0.1 for r in ratios), confirm=conf,
                    partner=dict(B_predicted=B, gap=gap, roots=[partner]))

    assert folds.parabola_verdict(made()) == "fold_confirmed"
    lin = [1.0 - 2.0 * t for t in etas]
    assert folds.parabola_verdict(made(ratios=folds.sqrt_law(lin, etas)[0])) == "no_fold"
    assert folds.parabola_verdict(made(confirmed=False)) == "undecided"
    assert folds.parabola_verdict(made(partner=dict(Fn=B, q=-64.1, turns=[3, 0]))) == "undecided"  # 7581-like
    assert folds.parabola_verdict(made(partner=dict(Fn=B, q=+64.1, turns=[1, 0]))) == "undecided"
    assert folds.parabola_verdict(made(partner=dict(Fn=B + gap / 10, q=-64.1, turns=[1, 0]))) == "undecided"
    assert folds.parabola_verdict(dict(A=[1.0])) == "undecided"


def test_verifier_scalar_route_steps_exactly_as_the_array_route(monkeypatch):
    """verify.py steps up to SCALAR_STATES states one by one in Python floats and more as stacked
    arrays: both must give the same shot, turning points included, and both a NaN for a shot that
    blows up (the float route catches sin(inf))."""
    from validation import verify

    rng = np.random.default_rng(3)
    m = 12
    theta, p = rng.uniform(-2, 2, m), rng.uniform(-3, 3, m)
    h = np.full(m, -0.05)
    Fn, Ft = rng.uniform(-20, 20, m), rng.uniform(-20, 20, m)
    inv_ei, inv_ea = rng.uniform(0.5, 2, m), np.where(rng.random(m) < 0.5, 0.0, rng.uniform(0, 0.1, m))
    Ft[-1], h[-1] = 1e300, -1e3   # blows up within the steps
    runs = {}
    for limit in (0, m):
        monkeypatch.setattr(verify, "SCALAR_STATES", limit)
        with np.errstate(all="ignore"):
            runs[limit] = verify._rk8_uniform(theta, p, h, 400, Fn, Ft, inv_ei, inv_ea, count_turns=True)
    (ta, pa, ua), (ts, ps, us) = runs[0], runs[m]
    assert np.isnan(ta[-1]) and np.isnan(ts[-1])
    np.testing.assert_allclose(ts[:-1], ta[:-1], rtol=0, atol=1e-14 * np.abs(ta[:-1]).max())
    np.testing.assert_allclose(ps[:-1], pa[:-1], rtol=0, atol=1e-14 * np.abs(pa[:-1]).max())
    np.testing.assert_array_equal(us[:-1], ua[:-1])
    assert ua[:-1].sum() > m   # the states turn: the counts are compared, not only zeros


def test_end_stretch_finds_a_segment_compressed_past_zero_length():
    # line_ends.end_stretch: 1 + T/EA at the four segment ends, T = Ft sin(theta) - Fn cos(theta).
    # An inextensible spatula (stretch 1) on a beam with EA1 = 2 under Fn = 4, Ft = 0: T = -4 cos
    # theta1, so the base (theta1 = alpha1 = 0) has stretch 1 - 2 = -1; with alpha1 = pi/2 the base
    # is unloaded and the joint (theta1 = beta - alpha2 = 0.3) has 1 - 2 cos(0.3).
    from validation import line_ends
    P = np.array([[1.0, 1.0, 2.0, np.inf, 1.0, 1.0, 0.0, 0.2, 1.0],
                  [1.0, 1.0, 2.0, np.inf, 1.0, 1.0, np.pi / 2, 0.2, 1.0]])
    FT, Fn, beta = np.zeros((2, 2)), np.array([[4.0, 0.5], [4.0, 0.5]]), np.full((2, 2), 0.5)
    low = line_ends.end_stretch(P, FT, Fn, beta)
    np.testing.assert_allclose(low[0], [-1.0, 0.75], rtol=0, atol=1e-15)
    np.testing.assert_allclose(low[1], [1 - 2 * np.cos(0.3), 1 - 0.25 * np.cos(0.3)], rtol=0, atol=1e-15)
    r = line_ends.end_stretch_solved(P, FT, Fn, beta, np.array([[0, 0], [7, 6]]))
    assert r == {"solved": {"0": 2, "7": 1}, "at_most_zero_at_an_end": {"0": 1, "7": 1},
                 "c_N_above_1": {"0": 1, "7": 1}}


def test_verify_timing_compares_outputs_to_the_bit():
    from validation import verify_timing
    a = {"dFn": np.array([1.0, np.nan]), "steps": np.array([16, 32])}
    assert verify_timing.differing_keys(a, {k: v.copy() for k, v in a.items()}) == []
    assert verify_timing.differing_keys(a, {"dFn": np.array([1.0, np.nan]), "steps": np.array([16, 33])}) == ["steps"]
    assert verify_timing.differing_keys(a, {"dFn": np.array([np.nextafter(1.0, 2.0), np.nan])}) == ["dFn", "steps"]


def test_stretch_check_of_a_line_that_leaves_the_model():
    # validation/stretch.py checks the stretch rule with its own ODE shot: at design 6580's line
    # towards Ft = -726.36 (tests/seta/admissibility.cpp), the last node is compressed to zero
    # length and the node before it is not, and the target lies beyond the line.
    pytest.importorskip("scipy")
    from validation import campaign, stretch
    p = [9.234011903410433, 8632.183289992317, 1898.1613549209487, 335194.8826055024, 1.0,
         0.08155494130194677, 1.474315464438074, 0.028604678886875907, 1.0]
    line = campaign.seta(p).critical_line(ft_end=-726.3553702242612)
    last = stretch.stretch_verdict(p, line.Fn[-1], line.Ft[-1], line.theta_joint[-1])
    before = stretch.stretch_verdict(p, line.Fn[-2], line.Ft[-2], line.theta_joint[-2])
    assert last["stretch"] == "nonpositive" and before["stretch"] == "positive"
    assert before["base_miss"] < 1e-6 and abs(before["shot_min_stretch"] - line.min_stretch[-2]) < 1e-9
    assert stretch.check_beyond_line(p, -726.3553702242612)["verdict"] == "beyond_first_inverted_node"
    # A segment end compressed past EA decides without a shot (the base at Fn = 1e5: 1 - 4.4).
    v = stretch.stretch_verdict(p, 1e5, -726.0, 0.0)
    assert v["stretch"] == "nonpositive" and v["by"] == "segment_end" and v["lowest_end_stretch"] < -4


def test_give_ups_alone_solves_a_state_alone_and_holds_a_farther_ft_to_ft_max(tmp_path):
    # Campaign design 954: its Ft = 264.05 is given up on in a call with its farther Ft (3930.81)
    # and solved alone (validation/README.md, "Give-ups that a call with their Ft alone solves");
    # twice its farthest Ft lies beyond (Ft)max, which --farther must not pass to the solver.
    from validation import campaign, give_ups_alone, recheck
    z = np.load(recheck.STATES)
    P, FT = z["P"][954:955], z["FT"][954:955]
    j_near = int(np.argmin(np.abs(FT[0] - 264.05)))
    j_far = int(np.argmax(FT[0]))
    assert abs(FT[0, j_near] - 264.05) < 0.01 and 2 * FT[0, j_far] > campaign.seta(P[0]).ft_max
    status = np.zeros_like(z["status"][954:955])
    status[0, [j_near, j_far]] = 6
    path = tmp_path / "rerun.npz"
    np.savez(path, P=P, FT=FT, status=status)
    alone = give_ups_alone.run(str(path))
    rows = {round(r["Ft"], 2): r for r in alone["states"]}
    assert alone["status_6"] == 2 and rows[264.05]["alone_status"] == 0
    assert rows[264.05]["farthest_on_its_line"] == FT[0, j_far]
    farther = give_ups_alone.run(str(path), farther=2.0)  # clipped to (Ft)max: no ValueError
    assert farther["farther"] == 2.0 and farther["status_6"] == 2
    with pytest.raises(SystemExit):
        give_ups_alone.main([str(path), "--farther", "1"])
