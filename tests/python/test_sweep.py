"""gecko.sweep: many designs as one table — the values (against TwoLevelSeta.characteristics),
only the asked-for solves, order and bitwise equality for any chunk size and thread count,
resuming an interrupted run, the design samplers and their errors."""
import math
import warnings

import numpy as np
import pytest

pd = pytest.importorskip("pandas", reason="gecko.sweep needs pandas (pip install \"gecko-adhesion[sweep]\")")

import gecko  # noqa: E402
from gecko import _core, design_sweep  # noqa: E402
from gecko.design_sweep import FIELDS  # noqa: E402

BOUNDS = {"EI1": (2.0, 8.0), "EI2": (0.5, 4.0, "log"), "alpha2": (0.2, 0.8), "EA2": (20.0, 200.0, "log")}


def designs(n=24, seed=3):
    return gecko.sobol_designs(BOUNDS, n, seed=seed)


def bitwise_equal(a, b):
    """Same columns, same dtypes, same bytes (NaN == NaN)."""
    assert list(a.columns) == list(b.columns)
    for c in a.columns:
        x, y = a[c].to_numpy(), b[c].to_numpy()
        assert x.dtype == y.dtype, c
        assert x.tobytes() == y.tobytes(), c


# ---- values --------------------------------------------------------------------------------------

def test_values_are_the_characteristics_of_each_design():
    d = designs(12)
    t = gecko.sweep(d, outputs=["fn0", "slope_at_zero", "max_pull_off", "ft_at_max_pull_off", "ft_max",
                                "sticky_at_rest", "min_fn", "ft_at_line_end", "fn_at_line_end", "line_end",
                                "folds", "small_fn0", "small_slope_k"], threads=2, progress=False)
    assert len(t) == 12 and (t["status"] == 0).all()
    for i in range(12):
        row = t.iloc[i]
        seta = gecko.TwoLevelSeta(**{f: d[f].iloc[i] for f in FIELDS})
        c = seta.characteristics()
        # the same C++ routine per design: bitwise equal
        assert row["fn0"] == c.fn0 and row["slope_at_zero"] == c.slope_at_zero
        assert row["max_pull_off"] == c.max_pull_off and row["ft_at_max_pull_off"] == c.ft_at_min_fn
        assert row["min_fn"] == c.min_fn and row["ft_at_line_end"] == c.ft_at_line_end
        assert row["fn_at_line_end"] == c.fn_at_line_end
        assert design_sweep.LINE_END[int(row["line_end"])] == c.end
        assert row["folds"] == len(c.folds)
        assert row["ft_max"] == c.ft_max == math.sqrt(2 * seta.EA2 * seta.w)
        assert bool(row["sticky_at_rest"]) == c.sticky_at_rest
        assert row["small_fn0"] == c.small_fn0 and row["small_slope_k"] == c.small_slope_k
        for f in FIELDS:
            assert row[f] == getattr(seta, f)


def test_fn0_and_slope_do_not_depend_on_whether_the_line_is_traced():
    d = designs(10)
    shallow = gecko.sweep(d, outputs=["fn0", "slope_at_zero"], progress=False)
    deep = gecko.sweep(d, outputs=["fn0", "slope_at_zero", "max_pull_off"], progress=False)
    bitwise_equal(shallow[["fn0", "slope_at_zero"]], deep[["fn0", "slope_at_zero"]])
    # and (Fn)0 agrees with the critical line at Ft = 0 solved independently (Newton to 1e-12)
    line = gecko.critical_line_batch(design_sweep.design_matrix(d), [0.0])
    np.testing.assert_allclose(shallow["fn0"], line.Fn[:, 0], rtol=0, atol=1e-10)


def test_only_the_solves_the_outputs_need(monkeypatch):
    depths = []
    real = _core.seta_characteristics_batch

    def spy(flat, depth, threads):
        depths.append(depth)
        return real(flat, depth, threads)

    monkeypatch.setattr(_core, "seta_characteristics_batch", spy)
    d = designs(4)
    for outputs, depth in ((["ft_max"], 0), (["small_fn0", "small_non_sticky"], 0), (["fn0"], 1),
                           (["sticky_at_rest", "ft_max"], 1), (["max_pull_off"], 2), (["fn0", "line_end"], 2)):
        depths.clear()
        t = gecko.sweep(d, outputs=outputs, errors="nan", progress=False)
        assert depths == [depth]  # one chunk, one call at the depth the outputs need
        assert list(t.columns) == list(FIELDS) + outputs + ["status"]
    # closed forms only: (Ft)max without any solve
    t = gecko.sweep(d, outputs="ft_max", progress=False)
    np.testing.assert_array_equal(t["ft_max"], np.sqrt(2 * d["EA2"] * d["w"]))


def test_default_outputs():
    t = gecko.sweep(designs(3), progress=False)
    assert list(t.columns) == list(FIELDS) + list(gecko.DEFAULT_SWEEP_OUTPUTS) + ["status"]
    assert t["sticky_at_rest"].dtype == bool and t["status"].dtype == np.int8
    assert "slope_at_zero" in gecko.DEFAULT_SWEEP_OUTPUTS and "slope_k" not in gecko.DEFAULT_SWEEP_OUTPUTS


def test_slope_k_is_a_deprecated_alias_warned_once_per_call():
    # the tangent at Ft = 0 under its name (issue 13); the deprecated alias slope_k is still an
    # output, the same column bit for bit, with one DeprecationWarning per call (not per chunk)
    # attributed to the caller's line and naming the replacement
    d = designs(3)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        new = gecko.sweep(d, outputs=["slope_at_zero", "paper_k"], chunk_size=1, progress=False)
        old = gecko.sweep(d, outputs=["fn0", "slope_k"], chunk_size=1, progress=False)
    dep = [w for w in seen if issubclass(w.category, DeprecationWarning)]
    assert len(dep) == 1, [str(w.message) for w in dep]
    assert str(dep[0].message) == "gecko.sweep outputs: 'slope_k' is deprecated, use 'slope_at_zero' (the same values)"
    assert dep[0].filename == __file__
    assert new["slope_at_zero"].to_numpy().tobytes() == old["slope_k"].to_numpy().tobytes()
    with pytest.deprecated_call(match="use 'slope_at_zero'"):
        gecko.sweep(d, outputs="slope_k", progress=False)


# ---- determinism -----------------------------------------------------------------------------------

def test_same_table_for_any_chunk_size_and_thread_count():
    d = designs(23)
    outputs = ["fn0", "slope_at_zero", "max_pull_off", "ft_at_max_pull_off", "line_end"]
    ref = gecko.sweep(d, outputs=outputs, chunk_size=1000, threads=1, progress=False)
    for chunk, threads in ((1, 1), (5, 2), (7, 3), (23, 2), (4, 8)):
        t = gecko.sweep(d, outputs=outputs, chunk_size=chunk, threads=threads, progress=False)
        bitwise_equal(t, ref)
        assert t.attrs["sweep"]["chunks"] == math.ceil(23 / chunk)


def test_row_order_is_the_design_order():
    d = designs(9)
    t = gecko.sweep(d.iloc[::-1], outputs=["fn0"], chunk_size=2, progress=False)
    fwd = gecko.sweep(d, outputs=["fn0"], chunk_size=4, progress=False)
    np.testing.assert_array_equal(t["fn0"].to_numpy()[::-1], fwd["fn0"].to_numpy())
    np.testing.assert_array_equal(t["EI1"].to_numpy(), d["EI1"].to_numpy()[::-1])


def test_design_inputs_array_setae_and_partial_tables():
    d = designs(5)
    m = design_sweep.design_matrix(d)
    a = gecko.sweep(m, outputs=["fn0"], progress=False)
    b = gecko.sweep([gecko.TwoLevelSeta(*row) for row in m], outputs=["fn0"], progress=False)
    c = gecko.sweep({"EI1": [5.0, 6.0]}, outputs=["fn0"], progress=False)  # others: reference scene
    bitwise_equal(a, b)
    assert c["fn0"].iloc[0] == gecko.TwoLevelSeta().characteristics().fn0
    assert c["EA2"].tolist() == [50.0, 50.0]


# ---- resuming --------------------------------------------------------------------------------------

class Interrupted(Exception):
    pass


def test_interrupted_run_resumes_from_the_chunks_written(tmp_path, monkeypatch):
    pytest.importorskip("pyarrow")
    d = designs(23)
    outputs = ["fn0", "max_pull_off"]
    fresh = gecko.sweep(d, outputs=outputs, chunk_size=5, progress=False)

    def stop_after_two_chunks(done, total):
        if done >= 10:
            raise Interrupted

    with pytest.raises(Interrupted):
        gecko.sweep(d, outputs=outputs, chunk_size=5, out=tmp_path, progress=stop_after_two_chunks)
    key = design_sweep.sweep_key(design_sweep.design_matrix(d), outputs, 5)
    chunks = sorted(p.name for p in (tmp_path / f"sweep-{key}").iterdir() if p.suffix == ".parquet")
    assert chunks == ["chunk-000000.parquet", "chunk-000001.parquet"]
    assert not (tmp_path / f"sweep-{key}.parquet").exists()

    computed = []
    real = design_sweep.compute_chunk

    def counting(block, outs, threads):
        computed.append(block[0, 0])
        return real(block, outs, threads)

    monkeypatch.setattr(design_sweep, "compute_chunk", counting)
    t = gecko.sweep(d, outputs=outputs, chunk_size=5, out=tmp_path, progress=False)
    assert len(computed) == 3  # chunks 2, 3, 4 only
    assert computed == [d["EI1"].iloc[10], d["EI1"].iloc[15], d["EI1"].iloc[20]]
    assert t.attrs["sweep"]["chunks_reused"] == 2 and t.attrs["sweep"]["chunks_computed"] == 3
    bitwise_equal(t, fresh)
    assert (tmp_path / f"sweep-{key}.parquet").is_file() and not (tmp_path / f"sweep-{key}").exists()
    # finished: a third run reads the table back
    computed.clear()
    again = gecko.sweep(d, outputs=outputs, chunk_size=5, out=tmp_path, progress=False)
    assert computed == [] and again.attrs["sweep"]["chunks_computed"] == 0
    bitwise_equal(again, fresh)


def test_chunk_key_names_designs_outputs_chunk_size_and_version():
    m = design_sweep.design_matrix(designs(6))
    k = design_sweep.sweep_key(m, ["fn0"], 5)
    assert k == design_sweep.sweep_key(m.copy(), ["fn0"], 5)
    m2 = m.copy()
    m2[3, 1] = np.nextafter(m2[3, 1], 10)
    assert len({k, design_sweep.sweep_key(m2, ["fn0"], 5), design_sweep.sweep_key(m, ["fn0", "slope_k"], 5),
                design_sweep.sweep_key(m, ["fn0"], 6)}) == 4


def test_a_damaged_chunk_is_computed_again(tmp_path):
    pytest.importorskip("pyarrow")
    d = designs(6)
    with pytest.raises(Interrupted):
        gecko.sweep(d, outputs=["fn0"], chunk_size=3, out=tmp_path,
                    progress=lambda done, total: (_ for _ in ()).throw(Interrupted) if done >= 3 else None)
    key = design_sweep.sweep_key(design_sweep.design_matrix(d), ["fn0"], 3)
    (tmp_path / f"sweep-{key}" / "chunk-000000.parquet").write_bytes(b"not parquet")
    from gecko._integrity import ResultFileWarning
    with pytest.warns(ResultFileWarning, match="chunk-000000.parquet: content changed"):
        t = gecko.sweep(d, outputs=["fn0"], chunk_size=3, out=tmp_path, progress=False)
    assert t.attrs["sweep"]["chunks_computed"] == 2
    bitwise_equal(t, gecko.sweep(d, outputs=["fn0"], progress=False))


# ---- invalid designs and bad arguments ------------------------------------------------------------

def test_invalid_design_is_refused_before_computing_or_kept_as_status_5():
    d = designs(4)
    d.loc[2, "alpha1"] = 1.2  # alpha1 + alpha2 >= pi/2 for this row
    d.loc[2, "alpha2"] = 0.5
    with pytest.raises(ValueError, match=r"row 2 .*alpha"):
        gecko.sweep(d, outputs=["fn0"], progress=False)
    d.loc[3, "EI1"] = -1.0
    with pytest.raises(ValueError, match=r"row 2 \(and 1 more rows\)"):
        gecko.sweep(d, outputs=["fn0"], progress=False)
    t = gecko.sweep(d, outputs=["fn0", "ft_max", "max_pull_off", "small_fn0", "line_end"], errors="nan",
                    progress=False)
    assert t["status"].tolist() == [0, 0, 5, 5] and t["line_end"].tolist()[2:] == [-1, -1]
    assert t.loc[[2, 3], ["fn0", "ft_max", "max_pull_off", "small_fn0"]].isna().all().all()
    assert np.isfinite(t.loc[[0, 1], ["fn0", "ft_max", "max_pull_off"]]).all().all()


@pytest.mark.parametrize("kwargs, match", [
    ({"outputs": ["fn0", "pull"]}, r"unknown output 'pull'"),
    ({"outputs": []}, r"outputs: need at least one"),
    ({"chunk_size": 0}, r"chunk_size = 0 is out of range"),
    ({"threads": 0}, r"threads = 0 is out of range"),
    ({"errors": "ignore"}, r"errors = 'ignore'"),
    ({"executor": "spark://x"}, r"executor = 'spark://x' is not allowed"),
])
def test_bad_arguments(kwargs, match):
    with pytest.raises(ValueError, match=match):
        gecko.sweep(designs(2), progress=False, **kwargs)


def test_bad_design_tables():
    with pytest.raises(ValueError, match=r"unknown design parameter 'E1'"):
        gecko.sweep({"E1": [1.0]}, progress=False)
    with pytest.raises(ValueError, match=r"different lengths"):
        gecko.sweep({"EI1": [1.0, 2.0], "EI2": [1.0]}, progress=False)
    with pytest.raises(ValueError, match=r"shape \(n, 9\)"):
        gecko.sweep(np.ones((3, 4)), progress=False)
    with pytest.raises(ValueError, match=r"at least one design"):
        gecko.sweep(np.ones((0, 9)), progress=False)


def test_without_pandas_the_error_names_the_extra(monkeypatch):
    import sys
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r"pip install \"gecko-adhesion\[sweep\]\""):
        gecko.sweep(design_sweep.design_matrix({"EI1": [5.0]}), progress=False)


# ---- samplers ----------------------------------------------------------------------------------------

def test_grid_is_every_combination_first_name_slowest():
    g = gecko.design_grid({"EI1": [1, 2, 3], "alpha2": [0.1, 0.2]}, fixed={"EA2": 100})
    assert len(g) == 6
    assert g["EI1"].tolist() == [1, 1, 2, 2, 3, 3] and g["alpha2"].tolist() == [0.1, 0.2] * 3
    assert (g["EA2"] == 100).all() and (g["l2"] == 0.1).all() and list(g.columns) == list(FIELDS)


def test_samplers_stay_in_bounds_and_are_reproducible():
    for make in (gecko.random_designs, gecko.sobol_designs, gecko.latin_hypercube_designs):
        a, b = make(BOUNDS, 64, seed=7), make(BOUNDS, 64, seed=7)
        bitwise_equal(a, b)
        assert not a.equals(make(BOUNDS, 64, seed=8))
        for name, bd in BOUNDS.items():
            assert (a[name] >= bd[0]).all() and (a[name] <= bd[1]).all()
        assert (a["l1"] == 1.0).all()  # not sampled: the reference scene


def test_latin_hypercube_has_one_design_per_stratum():
    n = 50
    d = gecko.latin_hypercube_designs({"EI1": (1.0, 6.0), "alpha2": (0.0, 0.5)}, n, seed=2)
    for name, (lo, hi) in (("EI1", (1.0, 6.0)), ("alpha2", (0.0, 0.5))):
        strata = np.floor((d[name].to_numpy() - lo) / (hi - lo) * n).astype(int)
        assert sorted(strata) == list(range(n))


def test_log_bounds_sample_the_logarithm():
    d = gecko.latin_hypercube_designs({"EA2": (1.0, 1e4, "log")}, 40, seed=1)
    strata = np.floor(np.log10(d["EA2"].to_numpy()) / 4 * 40).astype(int)
    assert sorted(strata) == list(range(40))


@pytest.mark.parametrize("bounds, match", [
    ({"EI1": (3.0, 2.0)}, r"bounds for EI1 = \(3, 2\) are out of range: need lower < upper, both within 0 < EI1 < inf"),
    ({"EI1": (2.0, 2.0)}, r"bounds for EI1 .*lower < upper"),
    ({"EI1": (-1.0, 2.0)}, r"bounds for EI1 = \(-1, 2\) are out of range: need 0 < EI1 < inf"),
    ({"alpha1": (0.1, 2.0)}, r"bounds for alpha1 .*0 < alpha1 < pi/2"),
    ({"alpha2": (0.0, 0.5, "log")}, r"alpha2 .*log scale needs lower > 0"),
    ({"EA2": (1.0, math.inf)}, r"EA2 .*fix it instead of sampling"),
    ({"EI1": (1.0, math.nan)}, r"bounds for EI1"),
    ({"stiffness": (1.0, 2.0)}, r"unknown design parameter 'stiffness'; allowed: EI1, EI2"),
    ({"EI1": (1.0,)}, r"need \(lower, upper\)"),
    ({}, r"non-empty mapping"),
])
def test_bad_bounds_name_the_parameter_and_range(bounds, match):
    for make in (gecko.random_designs, gecko.sobol_designs, gecko.latin_hypercube_designs):
        with pytest.raises(ValueError, match=match):
            make(bounds, 8)


def test_bad_sample_size_and_grid():
    with pytest.raises(ValueError, match=r"n = 0 is out of range"):
        gecko.random_designs({"EI1": (1, 2)}, 0)
    with pytest.raises(ValueError, match=r"unknown design parameter 'x'"):
        gecko.design_grid({"x": [1]})
    with pytest.raises(ValueError, match=r"fixed: unknown design parameter 'y'"):
        gecko.random_designs({"EI1": (1, 2)}, 3, fixed={"y": 1})


def test_progress_callback_sees_every_design():
    seen = []
    gecko.sweep(designs(11), outputs=["ft_max"], chunk_size=4, progress=lambda d, t: seen.append((d, t)))
    assert seen == [(0, 11), (4, 11), (8, 11), (11, 11)]


def test_binding_errors_and_thread_independence():
    m = design_sweep.design_matrix(designs(7)).reshape(-1)
    with pytest.raises(ValueError):
        _core.seta_characteristics_batch(m[:-1], 1, 1)
    with pytest.raises(ValueError):
        _core.seta_characteristics_batch(m, 3, 1)
    one = _core.seta_characteristics_batch(m, 2, 1)
    many = _core.seta_characteristics_batch(m, 2, 16)  # more threads than designs
    for k in one:
        assert np.asarray(one[k]).tobytes() == np.asarray(many[k]).tobytes(), k


def test_every_kernel_kind_matches_the_single_design_call():
    """Extensible beam and/or spatula, inextensible: the four compile-time kernels."""
    rows = [dict(), dict(EI1=1.63413, EI2=1.15448, l2=0.382758, alpha1=0.694806, alpha2=0.288542, EA1=985.906,
                         EA2=461.675),
            dict(EI1=20.0, EI2=0.05, l2=0.02, alpha1=0.3, alpha2=0.9, EA1=math.inf, EA2=1e4),
            dict(EI1=0.5, EI2=2.0, l2=0.5, alpha1=1.2, alpha2=0.1, EA1=300.0, EA2=math.inf),
            dict(EA1=math.inf, EA2=math.inf)]
    setae = [gecko.TwoLevelSeta(**r) for r in rows]
    t = gecko.sweep(setae, outputs=["fn0", "slope_at_zero", "max_pull_off", "ft_at_line_end", "line_end"],
                    threads=2, progress=False)
    for i, s in enumerate(setae):
        c = s.characteristics()
        got = t.iloc[i]
        for col, want in (("fn0", c.fn0), ("slope_at_zero", c.slope_at_zero), ("max_pull_off", c.max_pull_off),
                          ("ft_at_line_end", c.ft_at_line_end)):
            assert np.float64(got[col]).tobytes() == np.float64(want).tobytes(), (i, col)
        assert design_sweep.LINE_END[int(got["line_end"])] == c.end


def test_the_batch_call_releases_the_gil():
    from test_concurrency import _share_during  # the probe of tests/python/test_concurrency.py
    m = design_sweep.design_matrix(designs(400)).reshape(-1)
    assert _share_during(lambda: _core.seta_characteristics_batch(m, 2, 1)) > 0.3


def test_a_line_given_up_is_flagged_not_reported_as_its_minimum():
    """Wide random designs: where the continuation gave up before the line's end (no convergence,
    point budget, stalled), the max pull-off over the followed part is only a bound: status 6 and
    NaN, with (Fn)0 kept (likewise where the kernel could not establish the minimum); elsewhere
    the values of TwoLevelSeta.characteristics."""
    wide = {"EI1": (0.1, 50.0, "log"), "EI2": (0.01, 50.0, "log"), "l2": (0.01, 1.0), "alpha1": (0.05, 0.7),
            "alpha2": (0.0, 0.8), "EA2": (1.0, 1e4, "log"), "EA1": (1.0, 1e4, "log")}
    d = gecko.random_designs(wide, 16, seed=2)
    t = gecko.sweep(d, outputs=["fn0", "max_pull_off", "ft_at_max_pull_off", "line_end"], errors="nan",
                    progress=False)
    given_up = {design_sweep.LINE_END[k] for k in design_sweep._GIVEN_UP}
    flagged = 0
    for i in range(len(d)):
        c = gecko.TwoLevelSeta(**{f: d[f].iloc[i] for f in FIELDS}).characteristics()
        row = t.iloc[i]
        assert design_sweep.LINE_END[int(row["line_end"])] == c.end
        if row["status"] in (1, 3):  # no natural state: nothing to report
            assert math.isnan(row["fn0"]) and math.isnan(c.fn0)
        elif c.end in given_up or math.isnan(c.min_fn):  # given up, or the minimum not established
            flagged += 1
            assert row["status"] == 6 and math.isnan(row["max_pull_off"]) and math.isnan(row["ft_at_max_pull_off"])
            assert row["fn0"] == c.fn0
        else:
            assert row["status"] == 0 and row["max_pull_off"] == c.max_pull_off and row["fn0"] == c.fn0
    assert flagged >= 1
