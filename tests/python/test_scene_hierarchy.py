"""The hierarchy scenes (gecko.scene.hierarchy): spatula populations and the compliant seta, their
example files, tables and checks."""
import math
from pathlib import Path

import numpy as np
import pytest

import gecko
import gecko.friction_hierarchy as fh
from gecko.scene import SceneError, load_scene, run_scene

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "more"


def test_population_example():
    r = run_scene(EXAMPLES / "friction_spatula_population.toml", progress=False)
    curves = r.curves["friction_spatula_population"]
    by = {(c.role, c.panel): c for c in curves}
    sim, pop, mf, ex = (by[(k, 0)] for k in ("simulated", "population", "mean_field", "expected"))
    np.testing.assert_array_equal(sim.x, [0.0, 0.2, 0.4, 0.6, 0.8])
    # the simulation is within its bound of the population average, at every width
    assert np.all(np.abs(sim.y - pop.y) <= sim.meta["bound"] * (1 + 1e-9))
    # no spread: the three mean fields agree with eqs 9-10
    F0 = float(gecko.steady_sliding(1e-4, t_off=1e-4).F_par)
    assert pop.y[0] == pytest.approx(F0, rel=1e-13) and ex.y[0] == pytest.approx(F0, rel=1e-12)
    # with spread, averaging falls below the mean spatula's force (F concave in K and G0)
    assert np.all(ex.y[1:] < mf.y[1:]) and np.all(np.diff(ex.y) < 0)
    text = run_scene(EXAMPLES / "friction_spatula_population.toml", progress=False, draw=False).data
    assert len(text["population"]) == 5


def test_compliant_seta_example():
    r = run_scene(EXAMPLES / "friction_compliant_seta.toml", progress=False, draw=False)
    curves = {c.study: c for c in r.curves["friction_stick_slip_map"]}
    np.testing.assert_array_equal(curves["identical"].x, [0.1, 1.0, 10.0, 100.0, 1000.0])
    # identical spatulae with a fixed re-sticking time: stick-slip up to k_s = 100 N K in 300 cycles
    assert curves["identical"].meta["stick_slip"].tolist() == [True, True, True, True, False]
    # a spread of stiffness and G0, or random re-sticking: smooth from k_s = 10 N K up
    for name in ("spread", "random_resticking"):
        assert curves[name].meta["stick_slip"].tolist() == [True, True, False, False, False], name
    # the traces: a sawtooth from ~0 to ~2x the mean force for the soft spring, a few % for the stiff
    soft, stiff = (row["seta"] for row in r.data["traces"])
    assert soft["regime"] == "stick-slip" and soft["max_slip_fraction"] > 0.9
    assert stiff["regime"] == "smooth" and stiff["std_par"] < 0.1 * stiff["mean_par"]
    # one point is compliant_seta itself
    row = r.data["identical"][2]["seta"]
    direct = fh.compliant_seta(1e-4, stiffness_ratio=10.0, t_off=1e-4, spatulae=200, periods=300, seed=1,
                               samples=1000)
    assert row["relative_drop"] == direct.relative_drop and row["regime"] == direct.regime


def test_hierarchy_scene_errors():
    base = {"model": "compliant_seta", "outputs": {"seta": True}}
    with pytest.raises(SceneError, match="stiffness_ratio = -1 is out of range"):
        load_scene({"study": [dict(base, parameters={"stiffness_ratio": -1.0})]})
    with pytest.raises(SceneError, match="spatulae = 2.5 is out of range"):
        load_scene({"study": [dict(base, parameters={"spatulae": 2.5})]})
    with pytest.raises(SceneError, match="stiffness_width = 1.5 is out of range"):
        load_scene({"study": [{"model": "spatula_population", "parameters": {"stiffness_width": 1.5},
                               "outputs": {"population": True}}]})
    with pytest.raises(SceneError, match="unknown key"):
        load_scene({"study": [dict(base, outputs={"seta": {"x": 1}})]})
    # too few simulated spatulae to classify: the kernel's error, with the study's key
    with pytest.raises(SceneError, match="simulate more spatulae"):
        run_scene({"study": [dict(base, parameters={"spatulae": 10.0})]}, progress=False)
    # a stick_slip_map needs the stiffness ratio swept
    with pytest.raises(SceneError, match="needs stiffness_ratio swept"):
        run_scene({"study": [dict(base, parameters={"periods": 2.0})],
                   "plot": [{"kind": "stick_slip_map"}]}, progress=False, draw=False)


def test_hierarchy_tables(tmp_path):
    scene = {"study": [{"name": "s", "model": "compliant_seta",
                        "parameters": {"stiffness_ratio": [0.1, 10.0], "periods": 5.0, "t_off": 1e-4},
                        "outputs": {"seta": True, "csv": True}},
                       {"name": "p", "model": "spatula_population",
                        "parameters": {"G0_width": 0.2, "periods": 5.0}, "outputs": {"population": True, "csv": True}}]}
    r = run_scene(scene, tmp_path, progress=False, draw=False)
    names = {f.name for f in r.files}
    assert {"s.seta.csv", "s.seta_trace.csv", "p.population.csv"} <= names
    lines = (tmp_path / "s.seta.csv").read_text().splitlines()
    assert lines[0].startswith("design,stiffness_ratio,spring,") and len(lines) == 3
    assert math.isfinite(float((tmp_path / "p.population.csv").read_text().splitlines()[1].split(",")[1]))
