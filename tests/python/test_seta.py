"""Python API of the two-level seta (python/gecko/seta.py): the contract of the design card
(TwoLevelSeta defaults, .critical_line(Ft=array) -> Fn, theta_joint, status as numpy arrays, NaN
where not solved), accuracy against the committed mpmath references, errors, and the batch call."""
import csv
import dataclasses
import math
import os

import numpy as np
import pytest

import gecko

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
KEYS = ["EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w"]


def test_defaults_are_the_reference_scene():
    s = gecko.TwoLevelSeta()
    assert (s.EI1, s.EI2, s.EA1, s.EA2, s.l1, s.l2, s.w) == (5.0, 2.0, math.inf, 50.0, 1.0, 0.1, 1.0)
    assert s.alpha1 == pytest.approx(math.pi / 6, rel=1e-16) and s.alpha2 == pytest.approx(math.pi / 6, rel=1e-16)
    assert s.ft_max == pytest.approx(10.0, rel=1e-16)


def test_critical_line_contract_and_reference_scene():
    s = gecko.TwoLevelSeta()
    Ft = np.linspace(0.0, 9.9, 100)
    line = s.critical_line(Ft=Ft)
    for name in ("Fn", "theta_joint", "status"):
        arr = getattr(line, name)
        assert isinstance(arr, np.ndarray) and arr.shape == Ft.shape
    assert np.all(line.status == 0)
    assert line.Fn[0] == pytest.approx(0.2499037937772059726562097, abs=1e-13)
    assert line.Fn.min() == pytest.approx(-2.80, abs=0.01)
    # shape of Ft is kept
    two_d = s.critical_line(Ft=Ft.reshape(10, 10))
    assert two_d.Fn.shape == (10, 10)
    np.testing.assert_array_equal(two_d.Fn.reshape(-1), line.Fn)


def _reference_rows():
    path = os.path.join(DATA, "seta_reference.csv")
    with open(path) as f:
        return list(csv.DictReader(f))


def test_matches_mpmath_references():
    rows = _reference_rows()
    assert len(rows) >= 300
    designs = {}
    for r in rows:
        designs.setdefault(r["design_id"], []).append(r)
    assert len(designs) >= 31
    worst = 0.0
    for rs in designs.values():
        s = gecko.TwoLevelSeta(**{k: float(rs[0][k]) for k in KEYS})
        Ft = np.array([float(r["Ft"]) for r in rs])
        line = s.critical_line(Ft=Ft)
        ref = np.array([float(r["Fn"]) for r in rs])
        # 7: solved, but the seta crosses the substrate there (values kept; accuracy still holds)
        assert np.all(np.isin(line.status, (0, 7)))
        err = np.abs(line.Fn - ref) / np.maximum(1.0, np.abs(ref))
        worst = max(worst, err.max())
        np.testing.assert_array_equal(line.turning_points_beam, [int(r["turning_points_seg1"]) for r in rs])
        np.testing.assert_array_equal(line.turning_points_spatula, [int(r["turning_points_seg2"]) for r in rs])
    assert worst <= 1e-11


def test_no_state_is_nan_with_status():
    s = gecko.TwoLevelSeta(EI1=1.63413, EI2=1.15448, l2=0.382758, alpha1=0.694806, alpha2=0.288542,
                           EA1=985.906, EA2=461.675)
    line = s.critical_line(Ft=[-9.5, 0.0, -20.0])
    assert list(line.status) == [2, 0, 2]
    assert math.isnan(line.Fn[0]) and math.isnan(line.theta_joint[2])
    assert not math.isnan(line.Fn[1])


@pytest.mark.parametrize("kwargs, name", [
    (dict(EI1=-1.0), "EI1"), (dict(EI2=0.0), "EI2"), (dict(EA1=0.0), "EA1"), (dict(EA2=-1.0), "EA2"),
    (dict(l1=0.0), "l1"), (dict(l2=math.nan), "l2"), (dict(w=-2.0), "w"), (dict(alpha1=0.0), "alpha1"),
    (dict(alpha1=1.6), "alpha1"), (dict(alpha2=-0.1), "alpha2"), (dict(alpha1=0.8, alpha2=0.8), "alpha1 + alpha2"),
])
def test_bad_design_raises_naming_parameter(kwargs, name):
    with pytest.raises(ValueError, match=name.replace("+", r"\+")):
        gecko.TwoLevelSeta(**kwargs)


def test_ft_beyond_ft_max():
    s = gecko.TwoLevelSeta()
    with pytest.raises(ValueError, match=r"Ft = 10.5 .*\(Ft\)max"):
        s.critical_line(Ft=[1.0, 10.5])
    line = s.critical_line(Ft=[1.0, 10.5], errors="nan")
    assert list(line.status) == [0, 5] and math.isnan(line.Fn[1])
    with pytest.raises(ValueError, match="errors"):
        s.critical_line(Ft=[1.0], errors="ignore")


def test_traced_line_and_characteristics():
    s = gecko.TwoLevelSeta()
    line = s.critical_line()
    assert "Ft)max" in line.end and line.Ft[-1] == pytest.approx(10.0, rel=1e-14)
    c = s.characteristics()
    assert c.fn0 == pytest.approx(0.2499037937772059726562097, abs=1e-13)
    assert c.max_pull_off == pytest.approx(2.802412557605301074597652, rel=1e-12)
    assert c.ft_at_min_fn == pytest.approx(7.123205952979077, rel=1e-7)
    assert not c.sticky_at_rest and c.small_non_sticky
    assert c.small_fn0 == pytest.approx(0.3396, abs=1e-3)
    assert s.small_deformation_fn(0.0) == pytest.approx(c.small_fn0)


def test_small_deformation_slope_is_the_papers_eq_21():
    # Paper 001 eq 21, as printed in the paper's groups (chi = l2/l1, xi = EI2/EI1):
    #   |k| = cot(a1 + a2) + sin a2 / (sin^2(a1 + a2) [chi^2/xi + 2 chi + sin a1 / sin(a1 + a2)]).
    # It is |dFn/dFt| of eq 18, so the k of eq 16 (whose right side the scan loses) is dFn/dFt and
    # Fn ~ (Fn)0 + k Ft with k < 0 here; were k = dFt/dFn, this magnitude would be 1/|k|.
    rng = np.random.default_rng(21)
    for _ in range(200):
        a1, a2 = rng.uniform(0.05, 0.7, 2)
        if a1 + a2 >= math.pi / 2 - 0.05:
            continue
        EI1, EI2 = rng.uniform(0.5, 20), rng.uniform(0.05, 10)
        l2 = rng.uniform(0.02, 0.5)
        s = gecko.TwoLevelSeta(EI1=EI1, EI2=EI2, l2=l2, alpha1=a1, alpha2=a2)
        chi, xi, a12 = l2 / 1.0, EI2 / EI1, a1 + a2
        eq21 = 1 / math.tan(a12) + math.sin(a2) / (
            math.sin(a12) ** 2 * (chi * chi / xi + 2 * chi + math.sin(a1) / math.sin(a12)))
        k = s.small_deformation()["slope_k"]
        assert k < 0 and -k == pytest.approx(eq21, rel=1e-13)


def test_traced_nodes_carry_a_status():
    # Reference scene: every node re-solved (status 0) and equal to the state solved at its Ft; the
    # end node at (Ft)max is solved too but inadmissible (7: the joint dips below the substrate).
    s = gecko.TwoLevelSeta()
    line = s.critical_line()
    assert line.status.dtype == np.int32 and np.all(line.status[:-1] == 0) and line.status[-1] == 7
    assert line.Ft[-1] == s.ft_max and line.min_z[-1] < 0
    pick = np.arange(1, len(line.Ft), max(1, len(line.Ft) // 12))
    at = s.critical_line(Ft=line.Ft[pick])
    np.testing.assert_allclose(at.Fn, line.Fn[pick], rtol=1e-12, atol=1e-12)
    raw = s.critical_line(resolve_nodes=False)   # the continuation's own nodes, marked as such
    assert raw.status[0] == 0 and np.all(raw.status[1:] == 1)
    np.testing.assert_array_equal(raw.Ft, line.Ft)
    np.testing.assert_allclose(raw.Fn, line.Fn, rtol=1e-8, atol=1e-8)
    with pytest.raises(ValueError, match="resolve_nodes"):
        s.critical_line(Ft=[1.0], resolve_nodes=False)
    # A line at forces ~100 whose Newton steps at 1e-12 hit their rounding floor at some nodes
    # (validation/traced_nodes.py): those nodes say so (status 1) and keep finite values.
    s = gecko.TwoLevelSeta(EI1=3.4819510836166394, EI2=15.497815605161746, EA1=15.40193091295868,
                           EA2=3183.8725667297713, l2=0.02038078921865084, alpha1=0.5386040251416762,
                           alpha2=1.0098973821140953)
    line = s.critical_line()
    # (7: solved, but this seta crosses the substrate already at rest)
    assert set(np.unique(line.status)) <= {0, 1, 7} and np.any(line.status == 1) and line.status[0] in (0, 7)
    assert np.all(np.isfinite(line.Fn)) and np.all(np.isfinite(line.theta_joint))


def test_solve_with_and_without_guess():
    s = gecko.TwoLevelSeta()
    a = s.solve(5.0)
    b = s.solve(5.0, (-2.4, 1.49))
    assert a["status"] == 0 and b["status"] == 0
    assert a["Fn"] == pytest.approx(b["Fn"], abs=1e-13)


def test_peel_lines_vectorised():
    Ft = np.array([0.0, 1.0, 5.0])
    k = gecko.kendall_fn(Ft, 50.0, 1.0)
    N2 = k ** 2 + Ft ** 2
    np.testing.assert_allclose(np.sqrt(N2) + N2 / 100.0 - Ft - 1.0, 0.0, atol=1e-14)
    assert gecko.rivlin_fn(2.0, 1.0) == pytest.approx(-math.sqrt(5.0), rel=1e-15)
    np.testing.assert_allclose(gecko.kendall_fn(Ft, math.inf, 1.0), gecko.rivlin_fn(Ft, 1.0), rtol=1e-15)
    with pytest.raises(ValueError, match="Ft"):
        gecko.rivlin_fn(-1.0, 1.0)
    assert math.isnan(gecko.rivlin_fn(-1.0, 1.0, errors="nan"))


def test_batch_equals_serial_bitwise_and_thread_independent():
    designs = [gecko.TwoLevelSeta(), gecko.TwoLevelSeta(EI1=3.0, EA2=80.0),
               gecko.TwoLevelSeta(EI1=1.63413, EI2=1.15448, l2=0.382758, alpha1=0.694806, alpha2=0.288542,
                                  EA1=985.906, EA2=461.675)]
    Ft = np.array([0.0, 0.5, 2.0, 4.0, -1.0])
    one = gecko.critical_line_batch(designs, Ft, threads=1)
    two = gecko.critical_line_batch(designs, Ft, threads=2)
    np.testing.assert_array_equal(one.Fn, two.Fn)
    np.testing.assert_array_equal(one.status, two.status)
    for i, d in enumerate(designs):
        serial = d.critical_line(Ft=Ft)
        np.testing.assert_array_equal(one.Fn[i], serial.Fn)
        np.testing.assert_array_equal(one.theta_joint[i], serial.theta_joint)
    # designs as a (n, 9) array
    arr = np.array([[getattr(d, k) for k in KEYS] for d in designs])
    np.testing.assert_array_equal(gecko.critical_line_batch(arr, Ft, threads=2).Fn, one.Fn)
    bad = arr.copy()
    bad[1, 0] = -1.0
    with pytest.raises(ValueError, match="EI1"):
        gecko.critical_line_batch(bad, Ft)
    res = gecko.critical_line_batch(bad, Ft, errors="nan", threads=2)
    assert np.all(res.status[1] == 5) and np.all(np.isnan(res.Fn[1]))
    np.testing.assert_array_equal(res.Fn[0], one.Fn[0])


def test_mixed_signs_equal_each_direction_alone():
    # critical_line(Ft=...) computes the natural state once for the lines followed from it towards
    # positive and negative Ft: each direction's states are bit for bit those of a call with that
    # direction's targets alone. Designs: the reference; campaign design 67, whose followed line
    # never leaves Ft = 0 (its positive targets are solved on the separatrix limit, its negative
    # one lies past a fold where the long-double retry's march turns back: status 2); campaign
    # design 1005, whose positive targets are solved by the long-double retry of give-ups
    # (tests/data/seta_separatrix_reference.csv, long_double_1005); campaign design 1138, whose
    # negative target is given up (status 6).
    cases = [
        (gecko.TwoLevelSeta(), [-3.0, 0.0, 2.0, -0.5, 9.0]),
        (gecko.TwoLevelSeta(EI1=0.21555292182338973, EI2=43.0027243533097, EA1=64.20496458992673,
                            EA2=25673.606329746704, l1=1.0, l2=0.0065046909845071655,
                            alpha1=0.24539953004201956, alpha2=1.0586604563532502, w=1.0),
         [-118.56693623635869, 0.0, 84.25776419106023, 51.35427316960929, -40.0]),
        (gecko.TwoLevelSeta(EI1=0.27838952633169495, EI2=1.270807598552047, EA1=34629.42471111142,
                            EA2=87772.04693377482, l1=1.0, l2=0.09695729933128887,
                            alpha1=1.006282082105714, alpha2=0.2716690124304871, w=1.0),
         [-116.02457981371899, 0.0, 164.2456444511225, 210.259320846518, 377.08184261870156]),
        (gecko.TwoLevelSeta(EI1=0.5421669712904107, EI2=47.673083959971024, EA1=374037.1413891302,
                            EA2=90451.84182407723, l1=1.0, l2=0.0011356885913837145,
                            alpha1=0.22548794524791066, alpha2=1.033968993181213, w=1.0),
         [-403.50252950485987, 0.0, 214.9361214716802, 264.0005747706312, 382.7949630742352]),
    ]
    fields = ("Fn", "theta_joint", "status", "turning_points_beam", "turning_points_spatula",
              "theta_rate_joint", "theta_rate_base", "min_z")
    statuses = set()
    for seta, ft in cases:
        ft = np.array(ft)
        both = seta.critical_line(Ft=ft, errors="nan")
        statuses.update(both.status.tolist())
        for part in (ft >= 0, ft < 0):
            alone = seta.critical_line(Ft=ft[part], errors="nan")
            for f in fields:
                np.testing.assert_array_equal(getattr(both, f)[part], getattr(alone, f), err_msg=f)
    assert {0, 2, 6} <= statuses  # solved states, a claim past a fold and a give-up are all compared
    fiber = gecko.SingleFiber()
    ft = np.array([-2.0, 0.0, 5.0, -0.25, 9.9])
    both = fiber.critical_line(Ft=ft)
    for part in (ft >= 0, ft < 0):
        alone = fiber.critical_line(Ft=ft[part])
        np.testing.assert_array_equal(both.Fn[part], alone.Fn)
        np.testing.assert_array_equal(both.status[part], alone.status)


@pytest.mark.skipif(np.finfo(np.longdouble).nmant <= np.finfo(np.float64).nmant,
                    reason="the retry of give-ups runs only where long double is wider than double")
def test_retry_reports_the_line_it_followed_not_status_1():
    # Campaign design 7775: double's homotopy to the natural state gives up (status 1 everywhere);
    # the long-double retry finds it and solves Ft = 0 and the positive targets, and its line
    # towards negative Ft turns back at a fold before Ft = -504.93 (its separatrix march in
    # arclength comes back over Ft = 0). That target is status 2 (not on the line from Ft = 0), as
    # the retry's line says; it was status 1, and then 6 while the march claimed nothing past a
    # fold (validation/README.md, "Targets past a turned-back march").
    seta = gecko.TwoLevelSeta(EI1=0.10080516101182974, EI2=8.879466999540858, EA1=4.2413084413714754,
                              EA2=571589.1012556991, l1=1.0, l2=0.02122973292440997,
                              alpha1=0.1667794760138022, alpha2=1.2463937247486194, w=1.0)
    line = seta.critical_line(Ft=[-504.92748189, 0.0, 38.97285313], errors="nan")
    np.testing.assert_array_equal(line.status, [2, 0, 0])
    assert np.isnan(line.Fn[0]) and line.Fn[1] == pytest.approx(-59.49229976, rel=1e-9)


def test_exports():
    for name in ("TwoLevelSeta", "kendall_fn", "rivlin_fn", "critical_line_batch"):
        assert name in gecko.__all__ and hasattr(gecko, name)


def test_single_fiber():
    f = gecko.SingleFiber()
    assert (f.EI, f.EA, f.l, f.w) == (0.5, 50.0, 1.0, 1.0) and f.alpha == pytest.approx(math.pi / 3)
    line = f.critical_line(Ft=np.array([0.0, 1.0, 5.0, 9.9]))
    assert np.all(line.status == 0) and np.all(np.isnan(line.theta_joint))
    # Verified against an RK4 shooting in tests/seta/single_fiber.cpp; here: value at Ft = 0 and the
    # turning point at rest (the fiber is sticky at rest and inflected).
    assert line.Fn[0] == pytest.approx(-1.624169892931951, abs=1e-12)
    assert line.turning_points_beam[0] == 1
    with pytest.raises(ValueError, match="alpha"):
        gecko.SingleFiber(alpha=2.0)
    assert "SingleFiber" in gecko.__all__


def test_sensitivities_against_finite_differences():
    s = gecko.TwoLevelSeta()
    sens = s.sensitivities([0.0, 5.0])
    assert sens["dFn"].shape == (2, 9) and list(sens["status"]) == [0, 0]
    assert sens["parameters"][0] == "EI1"
    assert sens["dFn"][0, 2] == 0.0  # EA1 = inf
    for j, name in enumerate(sens["parameters"]):
        v = getattr(s, name)
        if math.isinf(v):
            continue
        h = 1e-5 * abs(v)
        kp = {k: getattr(s, k) for k in KEYS}
        km = dict(kp)
        kp[name] = v + h
        km[name] = v - h
        fp = gecko.TwoLevelSeta(**kp).critical_line(Ft=[0.0, 5.0]).Fn
        fm = gecko.TwoLevelSeta(**km).critical_line(Ft=[0.0, 5.0]).Fn
        np.testing.assert_allclose(sens["dFn"][:, j], (fp - fm) / (2 * h), rtol=1e-6, atol=1e-6)


def test_shape():
    s = gecko.TwoLevelSeta()
    sh = s.shape(5.0, steps=200)
    assert sh["status"] == 0 and len(sh["x"]) == 401
    assert abs(sh["closing_error"]) < 1e-10 and sh["z"][-1] == 0.0 and sh["z"][0] > 0


# ---- admissibility, exact shapes, unbounded lines, the paper's k, bad input (issue 13) ----------

def test_inadmissible_states_get_status_7_with_values_kept():
    s = gecko.TwoLevelSeta(alpha2=1.0)
    line = s.critical_line(Ft=[0.0, 5.0, 9.999])
    assert list(line.status) == [0, 0, 7]
    assert np.isfinite(line.Fn).all() and np.isfinite(line.theta_joint).all()
    assert line.min_z[0] == 0.0 and -5e-3 < line.min_z[2] < -5e-4
    assert abs(line.min_z_at[2] - s.l1) < 1e-12          # the joint is the lowest point
    assert gecko.STATUS[7].startswith("inadmissible")
    # every API: the traced line, the batch, the one-state solve
    assert 7 in set(s.critical_line().status.tolist())
    b = gecko.critical_line_batch([s, gecko.TwoLevelSeta()], [5.0, 9.999])
    assert b.status.tolist() == [[0, 7], [0, 0]] and np.isfinite(b.min_z).all()
    assert s.solve(9.999)["status"] == 7


def test_strain_limit():
    s = gecko.TwoLevelSeta()
    line = s.critical_line(Ft=[2.0, 9.0], strain_limit=0.1)
    assert line.status.tolist() == [0, 7]
    assert line.max_axial_strain[1] > 0.1
    assert abs(s.critical_line(Ft=[s.ft_max]).max_axial_strain[0] - 0.2) < 1e-12  # 20 % at (Ft)max
    with pytest.raises(ValueError, match="strain_limit"):
        s.critical_line(Ft=[1.0], strain_limit=float("nan"))
    c = s.characteristics(strain_limit=0.1)
    assert c.min_status == "admissible_end" and c.admissible_end_ft <= 5.0 + 1e-9


def test_a_segment_compressed_to_zero_length_is_inadmissible_and_ends_the_line():
    # Design 6580 of the 10,000-design re-run: towards negative Ft its beam's compression reaches
    # EA1 near Ft = -530.8, where the stretch 1 + T/EA1 passes zero (a rod of negative length
    # beyond). The followed line ends there, "left the model"; the Ft beyond it are status 3.
    s = gecko.TwoLevelSeta(EI1=9.234011903410433, EI2=8632.183289992317, EA1=1898.1613549209487,
                           EA2=335194.8826055024, l2=0.08155494130194677, alpha1=1.474315464438074,
                           alpha2=0.028604678886875907)
    at = s.critical_line(Ft=[-726.3553702242612, -300.0])
    assert at.status.tolist() == [3, 0] and np.isnan(at.min_stretch[0]) and 0 < at.min_stretch[1] < 1
    line = s.critical_line(ft_end=-726.3553702242612)
    assert line.end_code == gecko.LineEnd.unsupported_state and "compressed to zero length" in line.end
    assert line.min_stretch[-1] <= 0 < line.min_stretch[-2] and line.status[-1] == 7
    assert -560 < line.Ft[-1] < -500
    assert "compressed to zero length" in gecko.STATUS[7] and "compressed to zero length" in gecko.STATUS[3]
    # The reference design's beam is inextensible (stretch 1) and its spatula stretches: every state
    # reports a stretch in (0, 1], the one-state solve and the forward problem as well.
    ref = gecko.TwoLevelSeta()
    r = ref.critical_line(Ft=[0.0, 5.0, 9.5])
    assert ((r.min_stretch > 0) & (r.min_stretch <= 1)).all()
    assert ref.solve(5.0).min_stretch == r.min_stretch[1]
    c = ref.contact_state([-1.0, 0.0], 2.0)
    assert c.status.tolist() == [0, 0] and ((c.min_stretch > 0) & (c.min_stretch <= 1)).all()


def test_characteristics_admissible_part_bound_and_k():
    c = gecko.TwoLevelSeta().characteristics()
    assert not c.admissible_to_end and 9.99 < c.admissible_end_ft < 10.0
    assert c.min_status == "stationary" and abs(c.max_pull_off - 2.8024125) < 1e-6
    with pytest.warns(DeprecationWarning, match="SetaCharacteristics: 'slope_k' is deprecated, use 'slope_at_zero'"):
        assert c.slope_k == c.slope_at_zero
    assert c.slope_at_zero < c.paper_k < 0 and "slope_k" not in {f.name for f in dataclasses.fields(c)}
    for ea2 in (math.inf, 1e300):
        s = gecko.TwoLevelSeta(EA2=ea2)
        c = s.characteristics()
        assert math.isnan(c.max_pull_off) and c.max_pull_off_is_bound, ea2
        t = gecko.sweep([s], outputs=["max_pull_off", "max_pull_off_is_bound"], progress=False)
        assert math.isnan(t["max_pull_off"].iloc[0])           # characteristics() and sweep() agree


def test_shape_is_exact_and_reports_its_errors():
    s = gecko.TwoLevelSeta()
    a, b = s.shape(5.0, steps=7), s.shape(5.0, steps=700)
    assert a["shape_status"] == 0 and b["shape_status"] == 0
    assert a["max_closing_error"] < 1e-10 and a["error_estimate"] < 1e-10
    np.testing.assert_allclose(a["z"], b["z"][::100], rtol=0, atol=1e-11)
    with pytest.raises(ValueError, match="steps"):
        s.shape(5.0, steps=0)


def test_bad_input_is_refused_not_clipped():
    s = gecko.TwoLevelSeta()
    with pytest.raises(ValueError, match="ft_end"):
        s.characteristics(ft_end=float("nan"))
    with pytest.raises(ValueError, match="ft_end"):
        s.critical_line(ft_end=float("nan"))
    with pytest.raises(ValueError, match="Ft"):
        s.shape(s.ft_max * 1.01)
    with pytest.raises(ValueError, match="Ft"):
        s.sensitivities([[1.0, 2.0]])
    with pytest.raises(ValueError, match="shape"):
        gecko.critical_line_batch(np.ones((3, 6)), [1.0])
    with pytest.raises(ValueError, match="Ft"):
        gecko.critical_line_batch([s], [[1.0], [2.0]])
    with pytest.raises(ValueError, match="Ft"):
        s.small_deformation_fn([0.0, float("nan")])
    with pytest.raises(ValueError, match="Ft"):
        s.solve(float("nan"))
