"""Optional dependencies: each one, when missing, is reported with the extra that installs it.

The missing package is simulated by putting None in sys.modules (import then raises
ModuleNotFoundError), which is what a user without the package sees.
"""
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import gecko
from gecko import _optional, design_sweep

ROOT = Path(__file__).resolve().parents[2]


def hint(extra):
    return rf'pip install "gecko-adhesion\[{extra}\]"'


def test_install_hint_names_the_distribution_and_extra():
    assert _optional.install_hint("plot") == 'pip install "gecko-adhesion[plot]"'
    assert _optional.install_hint(None, "tomli") == "pip install tomli"
    with pytest.raises(ValueError):
        _optional.install_hint(None)


def test_require_returns_the_module_when_present():
    assert _optional.require("math", "a test") is importlib.import_module("math")


@pytest.mark.parametrize("module, extra", [("matplotlib", "plot"), ("pandas", "sweep"),
                                           ("pyarrow", "sweep"), ("scipy", "optimize"),
                                           ("dask", "dask"), ("distributed", "dask")])
def test_require_names_the_extra_of_each_optional_package(monkeypatch, module, extra):
    monkeypatch.setitem(sys.modules, module, None)
    with pytest.raises(ImportError, match=hint(extra)) as info:
        _optional.require(module, "something")
    assert isinstance(info.value, ModuleNotFoundError)       # old `except ModuleNotFoundError` still works
    assert f"something needs the optional package {module!r}" in str(info.value)


def test_a_submodule_names_the_top_level_package(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)   # in case an earlier test imported it
    with pytest.raises(ImportError, match=r"'pyarrow'.*" + hint("sweep")):
        _optional.require("pyarrow.parquet", "Parquet files")


def test_gecko_plot_without_matplotlib(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.delitem(sys.modules, "gecko.plot", raising=False)
    with pytest.raises(ImportError, match=r"gecko\.plot needs the optional package 'matplotlib'.*" + hint("plot")):
        importlib.import_module("gecko.plot")


def test_drawing_a_scene_without_matplotlib(monkeypatch):
    from gecko.scene import render
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    with pytest.raises(ImportError, match=hint("plot")):
        render._figure((3, 2))


def test_sweep_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=hint("sweep")):
        gecko.sweep(design_sweep.design_matrix({"EI1": [5.0]}), progress=False)


def test_sweep_to_parquet_without_pyarrow(monkeypatch, tmp_path):
    pytest.importorskip("pandas")
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    with pytest.raises(ImportError, match=hint("sweep")):
        gecko.sweep(design_sweep.design_matrix({"EI1": [5.0]}), out=tmp_path, progress=False)


def test_sobol_designs_without_scipy(monkeypatch):
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.stats", None)
    monkeypatch.setitem(sys.modules, "scipy.stats.qmc", None)
    with pytest.raises(ImportError, match=hint("sweep")):
        gecko.sobol_designs({"EI2": (0.2, 5.0)}, n=4, seed=1)


def test_dask_executor_without_distributed(monkeypatch):
    pytest.importorskip("pandas")
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(ImportError, match=hint("dask")):
        gecko.sweep(design_sweep.design_matrix({"EI1": [5.0]}), executor="dask://127.0.0.1:1",
                    progress=False)


def test_optimize_without_scipy(monkeypatch):
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.optimize", None)
    monkeypatch.setitem(sys.modules, "scipy.stats", None)
    with pytest.raises(ImportError, match=hint("optimize")):
        gecko.optimize_seta("max_pull_off", {"alpha2": (0.05, 1.0)}, ["not_sticky"])


def test_cli_without_matplotlib_names_the_extra(tmp_path):
    # A fresh interpreter in which matplotlib cannot be imported: the command exits 2 with the hint.
    scene = ROOT / "examples" / "friction_fig4_spatula_force_trace.toml"
    code = ("import sys; sys.modules['matplotlib'] = None; sys.modules['matplotlib.figure'] = None; "
            "from gecko.cli import main; sys.exit(main(sys.argv[1:]))")
    env_path = str(Path(gecko.__file__).resolve().parents[1])
    r = subprocess.run([sys.executable, "-c", code, "run", str(scene), "--out", str(tmp_path), "--quiet"],
                       capture_output=True, text=True, env={"PYTHONPATH": env_path, "PATH": "/usr/bin:/bin"},
                       timeout=300)
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert 'pip install "gecko-adhesion[plot]"' in r.stderr, r.stderr
    assert "Traceback" not in r.stderr


def test_toml_without_tomllib_or_tomli(monkeypatch, tmp_path):
    from gecko.scene import SceneError
    monkeypatch.setitem(sys.modules, "tomllib", None)
    monkeypatch.setitem(sys.modules, "tomli", None)
    import gecko.scene.toml as toml_mod
    try:
        fresh = importlib.reload(toml_mod)
        assert fresh._toml is None
        p = tmp_path / "s.toml"
        p.write_text("a = 1\n")
        with pytest.raises(SceneError, match=r"pip install tomli"):
            fresh.load_toml(p)
    finally:
        monkeypatch.undo()
        importlib.reload(toml_mod)


def test_tomli_is_a_dependency_below_python_3_11():
    tomllib = pytest.importorskip("tomllib")
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    deps = meta["project"]["dependencies"]
    assert any(d.replace(" ", "").startswith("tomli") and "python_version<'3.11'" in d.replace(" ", "")
               for d in deps), deps
    extras = meta["project"]["optional-dependencies"]
    assert not any("dask" in d for d in extras["sweep"])            # [sweep] does not force dask
    assert any("dask" in d for d in extras["dask"])
    for module, extra in _optional.EXTRAS.items():
        if extra is not None:
            assert any(d.split("[")[0].split(">")[0].split("=")[0].strip() in (module, "dask")
                       for d in extras[extra]), (module, extra)
