"""gecko.scene: plan from the outputs, cache, write atomically, progress only on a terminal."""
import io
import math
import subprocess
import sys

import numpy as np
import pytest

import gecko
from gecko.scene import Cache, SceneError, load_scene, plan_scene, run_scene
from gecko.scene.runner import Progress

SWEEP = {"EI2": {"range": [1.0, 3.0], "num": 6}}


def seta(outputs, **extra):
    d = {"model": "two_level_seta", "parameters": dict(SWEEP), "outputs": outputs}
    d.update(extra)
    return {"study": [d]}


def kernels(scene):
    return plan_scene(load_scene(scene)).kernels("two_level_seta")


def test_plan_picks_only_the_kernels_asked_for():
    assert kernels(seta({"characteristics": ["fn0"]})) == ["fn0"]
    assert kernels(seta({"characteristics": ["small_fn0"]})) == ["small_deformation"]
    assert kernels(seta({"critical_line": True, "characteristics": ["fn0"]})) == ["critical_line", "fn0_from_line"]
    assert kernels(seta({"critical_line": {"Ft": [1.0, 2.0]}, "characteristics": ["fn0"]})) == ["critical_line", "fn0"]
    assert kernels(seta({"characteristics": ["fn0", "max_pull_off"]})) == ["characteristics"]
    assert kernels(seta({"critical_line": True, "shapes": True})) == ["critical_line", "shapes"]
    assert "shapes" not in kernels(seta({"critical_line": True, "characteristics": True}))
    assert kernels(seta({"linear_line": True})) == ["small_deformation"]


def test_plan_names_the_kernel_variant():
    text = plan_scene(load_scene(seta({"critical_line": True}, combine="zip",
                                      parameters={"EA2": [math.inf, 50.0], "EA1": [math.inf, math.inf]}))).describe()
    assert "extensible spatula, inextensible kernel" in text
    assert "no plots: matplotlib is not imported" in text


def test_fn0_only_equals_the_line_at_zero():
    only = run_scene(seta({"characteristics": ["fn0"]}), progress=False)
    full = run_scene(seta({"critical_line": True, "characteristics": True}), progress=False)
    a = [d["characteristics"]["fn0"] for d in only.data["two_level_seta"]]
    b = [d["critical_line"]["Fn"][0] for d in full.data["two_level_seta"]]
    c = [d["characteristics"]["fn0"] for d in full.data["two_level_seta"]]
    np.testing.assert_allclose(a, b, rtol=1e-13)
    np.testing.assert_allclose(a, c, rtol=1e-12)
    assert "critical_line" not in only.data["two_level_seta"][0]


def test_cache_reuses_designs_across_a_sweep_and_across_runs():
    cache = Cache()
    scene = seta({"characteristics": ["fn0", "max_pull_off"]}, combine="cross",
                 variables={"repeat": [1, 2, 3]})  # a variable that changes no design: 3x the same
    r = run_scene(scene, progress=False, cache=cache)
    assert len(r.data["two_level_seta"]) == 18
    assert cache.misses == 6 and cache.hits == 12  # six distinct designs computed once each
    run_scene(scene, progress=False, cache=cache)
    assert cache.misses == 6 and cache.hits == 12 + 18
    fn0 = [d["characteristics"]["fn0"] for d in r.data["two_level_seta"]]
    assert fn0[:6] == fn0[6:12] == fn0[12:]


def test_no_matplotlib_without_plots(tmp_path):
    code = ("import sys, gecko.scene as s\n"
            "s.run_scene({'study': [{'model': 'two_level_seta', 'outputs': {'critical_line': True, 'csv': True}}]},"
            f" out={str(tmp_path)!r}, progress=False)\n"
            "assert 'matplotlib' not in sys.modules, 'matplotlib imported'\n"
            "import gecko.cli\nassert 'matplotlib' not in sys.modules\n")
    subprocess.run([sys.executable, "-c", code], check=True)
    assert (tmp_path / "two_level_seta.critical_line.csv").is_file()


def test_failed_render_leaves_nothing(tmp_path, monkeypatch):
    import gecko.scene.render as render

    def boom(*a, **k):
        raise RuntimeError("renderer broke")
    monkeypatch.setattr(render, "render_plot", boom)
    scene = {"study": [{"model": "kendall", "outputs": {"csv": True}}], "plot": [{"kind": "critical_line"}]}
    with pytest.raises(RuntimeError, match="renderer broke"):
        run_scene(scene, tmp_path / "out", progress=False)
    assert list((tmp_path / "out").iterdir()) == []  # no CSV, no PNG, no staging folder


def test_bad_scene_creates_no_output_folder(tmp_path):
    with pytest.raises(SceneError):
        run_scene({"study": [{"model": "kendall", "parameters": {"EA": -1}}]}, tmp_path / "out", progress=False)
    assert not (tmp_path / "out").exists()


def test_existing_files_replaced_whole(tmp_path):
    scene = {"study": [{"model": "rivlin", "outputs": {"critical_line": {"Ft": [0, 1.5]}}}],
             "plot": [{"kind": "critical_line", "name": "r"}]}
    (tmp_path / "r.csv").write_text("old")
    run_scene(scene, tmp_path, progress=False, draw=False)
    lines = (tmp_path / "r.csv").read_text().splitlines()
    assert lines[0] == "study,curve,label,panel,Fn_bar,Ft_bar"
    assert lines[1:] == ["rivlin,0,Rivlin model,0,-1.0,0.0", "rivlin,0,Rivlin model,0,-2.0,1.5"]


def test_progress_bar_only_on_a_terminal_and_after_a_delay():
    class Tty(io.StringIO):
        def isatty(self):
            return True
    quiet = io.StringIO()
    p = Progress(3, "x", stream=quiet)
    p.advance(3)
    p.close()
    assert quiet.getvalue() == ""  # not a terminal
    tty = Tty()
    p = Progress(3, "x", stream=tty, delay=60)
    p.advance(3)
    p.close()
    assert tty.getvalue() == ""  # short work: no bar
    tty = Tty()
    p = Progress(4, "scene", stream=tty, delay=0)
    p.advance(2, "seta")
    assert "scene [###############...............] 2/4 seta" in tty.getvalue()
    p.close()
    assert tty.getvalue().endswith("\r")


def test_kernel_refusal_names_the_study(monkeypatch):
    def refuse(self, *a, **k):
        raise ValueError("gecko::fiber: EI = 1 is out of range")
    monkeypatch.setattr(gecko.SingleFiber, "critical_line", refuse)
    with pytest.raises(SceneError) as info:
        run_scene({"study": [{"model": "kendall"}, {"model": "single_fiber", "outputs": {"critical_line": True}}]},
                  progress=False)
    assert str(info.value) == "<dict>: study[1]: gecko::fiber: EI = 1 is out of range"


def test_fn0_batch_computes_each_design_once():
    cache = Cache()
    r = run_scene(seta({"characteristics": ["fn0"]}, variables={"repeat": [1, 2]}), progress=False, cache=cache)
    assert (cache.misses, cache.hits) == (6, 6)
    fn0 = [d["characteristics"]["fn0"] for d in r.data["two_level_seta"]]
    assert fn0[:6] == fn0[6:]  # cross order: variables first (repeat outer), then parameters


def test_linear_line_and_small_characteristics_are_closed_forms():
    r = run_scene(seta({"linear_line": {"Ft": [0.0, 2.0]}, "characteristics": ["small_fn0", "small_slope_k"]}),
                  progress=False)
    for p, d in zip(r.scene.studies[0].points, r.data["two_level_seta"]):
        small = gecko.TwoLevelSeta(EI2=p.values["EI2"]).small_deformation()
        assert d["characteristics"]["small_fn0"] == small["fn0"]
        np.testing.assert_array_equal(d["linear_line"]["Fn"], small["fn0"] + small["slope_k"] * np.array([0.0, 2.0]))
