"""Scenes with [sweep] and [optimize]: validation errors that name the key, the same table as
gecko.sweep, the files `gecko run` writes, the example scenes, the optimisation wiring."""
import json
import math
import socket
import warnings
from pathlib import Path

import numpy as np
import pytest

pd = pytest.importorskip("pandas", reason="sweeps need pandas (pip install \"gecko-adhesion[sweep]\")")

import gecko  # noqa: E402
from gecko.cli import main  # noqa: E402
from gecko.scene import SceneError, load_scene, plan_scene, run_scene  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def sweep_scene(**kw):
    s = {"designs": "sobol", "n": 16, "seed": 3, "bounds": {"EI1": [2, 8], "alpha2": [0.1, "pi/4"]},
         "outputs": ["fn0", "max_pull_off"]}
    s.update(kw)
    return {"title": "t", "sweep": s}


def test_sweep_scene_gives_the_table_of_gecko_sweep():
    r = run_scene(sweep_scene(parameters={"EA2": 80}), progress=False)
    direct = gecko.sweep(gecko.sobol_designs({"EI1": (2, 8), "alpha2": (0.1, math.pi / 4)}, 16, seed=3,
                                             fixed={"EA2": 80}), outputs=["fn0", "max_pull_off"], progress=False)
    pd.testing.assert_frame_equal(r.sweep, direct, check_exact=True)
    assert (r.sweep["EA2"] == 80).all()


@pytest.mark.parametrize("designs, extra", [
    ("random", {}), ("latin_hypercube", {}),
    ("grid", {"grid": {"EI1": [2, 4], "alpha2": {"range": [0.1, 0.5], "num": 3}}, "bounds": None, "n": None,
              "seed": None}),
])
def test_every_kind_of_designs(designs, extra):
    kw = {"designs": designs, **extra}
    s = sweep_scene(**kw)
    s["sweep"] = {k: v for k, v in s["sweep"].items() if v is not None}
    r = run_scene(s, progress=False)
    assert len(r.sweep) == (6 if designs == "grid" else 16)
    # 6: a line given up before its end (its max pull-off NaN); (Fn)0 is there for every design
    assert r.sweep["status"].isin([0, 6]).all() and np.isfinite(r.sweep["fn0"]).all()
    assert (r.sweep["status"] == 0).sum() >= len(r.sweep) - 2
    if designs == "grid":
        assert r.sweep["EI1"].tolist() == [2, 2, 2, 4, 4, 4]


def test_deprecated_sweep_output_warns_once_per_run_with_its_key():
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        r = run_scene(sweep_scene(n=4, outputs=["fn0", "slope_k"], chunk_size=1), progress=False)
    dep = [str(w.message) for w in seen if issubclass(w.category, DeprecationWarning)]
    # the parser names the key; gecko.sweep, called by the run, does not warn a second time
    assert dep == ["scene sweep.outputs: 'slope_k' is deprecated, use 'slope_at_zero' (the same values)"]
    direct = gecko.sweep(r.sweep[list(gecko.design_sweep.FIELDS)], outputs=["slope_at_zero"], progress=False)
    assert r.sweep["slope_k"].to_numpy().tobytes() == direct["slope_at_zero"].to_numpy().tobytes()


def test_table_designs_relative_to_the_scene(tmp_path):
    pd.DataFrame({"EI1": [3.0, 4.0], "l2": [0.1, 0.2]}).to_csv(tmp_path / "designs.csv", index=False)
    (tmp_path / "s.toml").write_text('[sweep]\ndesigns = "table"\ntable = "designs.csv"\noutputs = ["fn0"]\n'
                                     '[sweep.parameters]\nEA2 = 70\n')
    r = run_scene(tmp_path / "s.toml", progress=False)
    assert r.sweep["l2"].tolist() == [0.1, 0.2] and (r.sweep["EA2"] == 70).all()
    assert r.sweep["fn0"].iloc[0] == gecko.TwoLevelSeta(EI1=3.0, EA2=70).characteristics().fn0


def test_resolution_scales_the_sample():
    assert len(run_scene(sweep_scene(n=40), resolution=0.25, progress=False).sweep) == 10


def test_run_writes_table_and_plot_and_no_chunks(tmp_path):
    pytest.importorskip("pyarrow")
    pytest.importorskip("matplotlib")
    s = sweep_scene(name="designs", plot={"x": "fn0", "y": "max_pull_off", "color": "EI1"})
    r = run_scene(s, tmp_path, progress=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["designs.parquet", "designs.png"]
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "designs.parquet"), r.sweep, check_exact=True)
    s = sweep_scene(name="designs_csv", format="csv")
    run_scene(s, tmp_path, progress=False, draw=False)
    back = pd.read_csv(tmp_path / "designs_csv.csv")
    np.testing.assert_array_equal(back["fn0"].to_numpy(), r.sweep["fn0"].to_numpy())  # %.17g round-trips


def test_interrupted_scene_sweep_resumes(tmp_path, monkeypatch):
    pytest.importorskip("pyarrow")
    from gecko import design_sweep
    calls = []
    real = design_sweep.compute_chunk
    interrupt_at = [3]

    def flaky(block, outputs, threads):
        calls.append(len(block))
        if len(calls) == interrupt_at[0]:
            raise KeyboardInterrupt
        return real(block, outputs, threads)

    monkeypatch.setattr(design_sweep, "compute_chunk", flaky)
    s = sweep_scene(chunk_size=4)
    with pytest.raises(KeyboardInterrupt):
        run_scene(s, tmp_path, progress=False, draw=False)
    assert not (tmp_path / "sweep.parquet").exists()  # nothing half-written in place
    calls.clear()
    interrupt_at[0] = 0
    r = run_scene(s, tmp_path, progress=False, draw=False)
    assert calls == [4, 4] and r.sweep.attrs["sweep"]["chunks_reused"] == 2
    assert (tmp_path / "sweep.parquet").is_file()
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".gecko-sweep")]


@pytest.mark.parametrize("change, key, match", [
    ({"designs": "halton"}, "sweep.designs", "'halton' is not allowed; allowed: 'grid', 'random'"),
    ({"designs": None}, "sweep.designs", "missing key 'designs'"),
    ({"bounds": {"EI1": [3, 2]}}, "sweep.bounds.EI1", r"need lower < upper, both within 0 < EI1 < inf"),
    ({"bounds": {"alpha1": [0.1, 2]}}, "sweep.bounds.alpha1", r"0 < alpha1 < pi/2"),
    ({"bounds": {"EI1": [1, 2, "cubic"]}}, "sweep.bounds.EI1[2]", "'cubic' is not allowed"),
    ({"bounds": {"EI1": ["pi/0", 2]}}, "sweep.bounds.EI1[0]", "cannot evaluate 'pi/0'"),
    ({"bounds": {"k": [1, 2]}}, "sweep.bounds.k", "unknown design parameter 'k'"),
    ({"n": 0}, "sweep.n", r"0 is out of range: need an integer in \[1, "),
    ({"n": None}, "sweep", "designs = 'sobol' needs the key 'n'"),
    ({"grid": {"EI1": [1, 2]}}, "sweep.grid", "'grid' is not used by designs = 'sobol'"),
    ({"outputs": ["fn0", "grip"]}, "sweep.outputs[1]", "unknown output 'grip'"),
    ({"executor": "dask:/x"}, "sweep.executor", "need 'threads' or 'dask://host:port'"),
    ({"errors": "skip"}, "sweep.errors", "'skip' is not allowed"),
    ({"format": "xlsx"}, "sweep.format", "'xlsx' is not allowed"),
    ({"chunk_size": 0}, "sweep.chunk_size", "out of range"),
    ({"connect_timeout": 0}, "sweep.connect_timeout", "out of range"),
    ({"colour": 1}, "sweep.colour", "unknown key 'colour'"),
    ({"parameters": {"EA3": 1}}, "sweep.parameters.EA3", "unknown parameter 'EA3'"),
    ({"parameters": {"EI1": 1}}, "sweep.bounds.EI1", "both sampled and fixed"),
    ({"plot": {"x": "fn0"}}, "sweep.plot", "missing key 'y'"),
    ({"plot": {"x": "fn0", "y": "slope_k"}}, "sweep.plot.y", "'slope_k' is not a column of this sweep"),
    ({"name": "a/b"}, "sweep.name", "not allowed"),
    ({"designs": "table", "n": None, "bounds": None, "seed": None, "table": "nope.csv"}, "sweep.table", "no such file"),
])
def test_bad_sweep_tables_name_the_key(change, key, match):
    s = sweep_scene()
    for k, v in change.items():
        if v is None:
            s["sweep"].pop(k, None)
        else:
            s["sweep"][k] = v
    with pytest.raises(SceneError, match=match) as err:
        load_scene(s)
    assert err.value.key == key


def test_invalid_sampled_design_is_a_scene_error_or_status_5():
    s = sweep_scene(bounds={"alpha1": [0.5, 1.2], "alpha2": [0.3, 0.6]}, n=32)
    with pytest.raises(SceneError, match=r"sweep: designs: row \d+ .*alpha") as err:
        run_scene(s, progress=False)
    assert err.value.key == "sweep"
    r = run_scene(sweep_scene(bounds={"alpha1": [0.5, 1.2], "alpha2": [0.3, 0.6]}, n=32, errors="nan"),
                  progress=False)
    bad = (r.sweep["alpha1"] + r.sweep["alpha2"]) >= math.pi / 2
    assert bad.any() and (r.sweep["status"][bad] == 5).all() and (r.sweep["status"][~bad] == 0).all()


def test_scene_needs_study_or_section():
    with pytest.raises(SceneError, match=r"a \[sweep\] or \[optimize\] section") as err:
        load_scene({"title": "x"})
    assert err.value.key == "study"
    with pytest.raises(SceneError, match=r"\[\[plot\]\] tables draw studies") as err:
        load_scene({**sweep_scene(), "plot": [{"kind": "critical_line"}]})


def test_unreachable_dask_executor_in_a_scene():
    pytest.importorskip("distributed")
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    with pytest.raises(ConnectionError, match=rf"dask://127.0.0.1:{port}.*within 1 s"):
        run_scene(sweep_scene(executor=f"dask://127.0.0.1:{port}", connect_timeout=1), progress=False)


def test_plan_says_what_the_outputs_need():
    text = plan_scene(load_scene(sweep_scene(outputs=["fn0"]))).describe()
    assert "natural state at Ft = 0 per design, no line traced" in text
    text = plan_scene(load_scene(sweep_scene(outputs=["ft_max"]))).describe()
    assert "closed forms only, no solver" in text


# ---- [optimize] -------------------------------------------------------------------------------------

def optimize_scene(**kw):
    o = {"objective": "max_pull_off", "vary": {"alpha2": [0.05, 1.0], "EI2/EI1": [0.05, 1.0]},
         "constraints": {"not_sticky": True}, "starts": 2, "seed": 0}
    o.update(kw)
    return {"optimize": o}


@pytest.mark.parametrize("change, key, match", [
    ({"objective": "grip"}, "optimize.objective", "'grip' is not allowed; allowed: 'max_pull_off'"),
    ({"objective": None}, "optimize.objective", "missing key 'objective'"),
    ({"vary": {"alpha2": [0.5, 0.1]}}, "optimize.vary.alpha2", "need lower < upper"),
    ({"vary": {"k": [0.1, 0.5]}}, "optimize.vary.k", "unknown parameter 'k'"),
    ({"vary": {"EI2/EI1": [0.5, "inf"]}}, "optimize.vary.EI2/EI1", "need finite 0 <= lower < upper"),
    ({"vary": None}, "optimize.vary", "need vary = "),
    ({"starts": 0}, "optimize.starts", "out of range"),
    ({"constraints": {"sticky": True}}, "optimize.constraints.sticky", "unknown key 'sticky'"),
    ({"constraints": {"not_sticky": 1}}, "optimize.constraints.not_sticky", "need true or false"),
    ({"ft": 2.0}, "optimize.ft", "only used by objective = 'pull_off_at'"),
    ({"objective": "pull_off_at"}, "optimize", "needs ft ="),
    ({"fixed": {"alpha2": 0.3}}, "optimize.vary.alpha2", "both fixed and varied"),
    ({"EA2": 50, "fixed": {"EA2": 60}}, "optimize.EA2", "both here and in fixed"),
    ({"method": "BFGS"}, "optimize.method", "'BFGS' is not allowed"),
    ({"budget": 3}, "optimize.budget", "unknown key 'budget'"),
])
def test_bad_optimize_tables_name_the_key(change, key, match):
    s = optimize_scene()
    for k, v in change.items():
        if v is None:
            s["optimize"].pop(k)
        else:
            s["optimize"][k] = v
    with pytest.raises(SceneError, match=match) as err:
        load_scene(s)
    assert err.value.key == key


def test_optimize_scene_passes_plain_values_to_the_optimiser(monkeypatch, tmp_path):
    """The runner hands optimize_from_scene the validated table (expressions evaluated, starts
    scaled by the resolution) and writes what it returns."""
    from gecko import optimize
    seen = {}
    real = optimize.optimize_from_scene

    def spy(spec):
        seen.update(spec)
        return real(spec)

    monkeypatch.setattr(optimize, "optimize_from_scene", spy)
    s = optimize_scene(vary={"alpha2": [0.05, "pi/3 - 0.05"]}, fixed={"EA2": "25*2"}, starts=4, name="best")
    r = run_scene(s, tmp_path, resolution=0.5, progress=False, draw=False)
    assert seen == {"objective": "max_pull_off", "vary": {"alpha2": [0.05, math.pi / 3 - 0.05]},
                    "fixed": {"EA2": 50.0}, "constraints": {"not_sticky": True}, "starts": 2, "seed": 0}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["best.csv", "best.json"]
    d = json.loads((tmp_path / "best.json").read_text())
    assert d["objective"] == "max_pull_off" and d["value"] == r.optimum.value
    assert d["design"]["alpha2"] == r.optimum.design["alpha2"]
    line = pd.read_csv(tmp_path / "best.csv")
    np.testing.assert_array_equal(line["Fn"].to_numpy(), r.optimum.line.Fn)


# ---- the example scenes and the command line --------------------------------------------------------

def test_example_sweep_scene(tmp_path):
    pytest.importorskip("pyarrow")
    pytest.importorskip("matplotlib")
    assert main(["run", str(EXAMPLES / "sweep_random_designs.toml"), "-o", str(tmp_path), "-q", "-r", "0.1"]) == 0
    t = pd.read_parquet(tmp_path / "sweep_random_designs.parquet")
    assert len(t) == 102 and t["status"].isin([0, 6]).all() and (t["status"] == 0).mean() > 0.95
    assert (tmp_path / "sweep_random_designs.png").read_bytes()[:4] == b"\x89PNG"
    # non-sticky designs exist and the pull-off is never negative
    ok = t["status"] == 0
    assert (t["fn0"] > 0).any() and (t["max_pull_off"][ok] >= 0).all()
    assert t["sticky_at_rest"].tolist() == (t["fn0"] < 0).tolist()


def test_example_optimize_scene(tmp_path):
    pytest.importorskip("matplotlib")
    assert main(["run", str(EXAMPLES / "optimize_max_pull_off.toml"), "-o", str(tmp_path), "-q", "-r", "0.5"]) == 0
    d = json.loads((tmp_path / "optimize_max_pull_off.json").read_text())
    assert d["status"] == "optimal"
    seta = gecko.TwoLevelSeta(**{k: float(v) for k, v in d["design"].items()})
    c = seta.characteristics()
    assert c.fn0 >= -1e-7  # the constraint: not sticky at rest
    assert d["value"] == pytest.approx(c.max_pull_off, rel=1e-9)
    assert d["value"] > gecko.TwoLevelSeta().characteristics().max_pull_off
    assert (tmp_path / "optimize_max_pull_off.png").read_bytes()[:4] == b"\x89PNG"


def test_cli_validate_and_plan(capsys):
    assert main(["validate", str(EXAMPLES / "sweep_random_designs.toml"),
                 str(EXAMPLES / "optimize_max_pull_off.toml")]) == 0
    out = capsys.readouterr().out
    assert "sweep of 1024 designs" in out and "optimize" in out
    assert main(["plan", str(EXAMPLES / "sweep_random_designs.toml")]) == 0
    assert "critical line followed to its end per design" in capsys.readouterr().out
