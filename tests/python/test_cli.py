"""The gecko command line: help, validate, plan, run, figures; exit codes and quiet output."""
import importlib.util
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from gecko.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DEMO = EXAMPLES / "demo_reference_critical_line.toml"
needs_mpl = pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="drawing needs matplotlib")


def test_help_documents_everything(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--help"])
    assert e.value.code == 0
    out = capsys.readouterr().out
    for word in ("run", "validate", "plan", "figures", "models", "SCENE.toml", "--out DIR", "progress",
                 "--quiet", "CSV", "examples/README.md"):
        assert word in out
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    out = capsys.readouterr().out
    for word in ("--out", "--svg", "--resolution", "--quiet", "--no-figures"):
        assert word in out


def test_validate_ok_and_bad(tmp_path, capsys):
    assert main(["validate", str(DEMO)]) == 0
    assert "ok (3 studies, 3 designs, 1 plots, work: 3 designs, 1203 points, about " in capsys.readouterr().out
    bad = tmp_path / "bad.toml"
    bad.write_text('[[study]]\nmodel = "two_level_seta"\nparameters = { alpha1 = 2.0 }\n')
    assert main(["validate", str(DEMO), str(bad)]) == 2
    err = capsys.readouterr().err
    assert err == (f"gecko: error: {bad}: study[0].parameters.alpha1: alpha1 = 2 is out of range: "
                   "need 0 < value < pi/2 (radians; write e.g. \"pi/6\" or \"deg(30)\")\n")
    assert main(["validate", str(tmp_path / "missing.toml")]) == 2
    assert "missing.toml: cannot read the file" in capsys.readouterr().err


def test_plan(capsys):
    assert main(["plan", str(EXAMPLES / "seta_fig5a_fn0_vs_stiffness_ratio.toml"), "-r", "0.1"]) == 0
    out = capsys.readouterr().out
    assert "fn0: (Fn)0 only: one solve at Ft = 0 per design" in out and "6 design(s)" in out


@needs_mpl
def test_run_writes_png_svg_csv(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", str(DEMO), "--out", str(out), "--svg", "-r", "0.1"]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert names == ["demo_reference_critical_line.csv", "demo_reference_critical_line.png",
                     "demo_reference_critical_line.seta.characteristics.csv",
                     "demo_reference_critical_line.seta.critical_line.csv",
                     "demo_reference_critical_line.svg"]
    assert "5 files" in capsys.readouterr().out
    assert (out / "demo_reference_critical_line.svg").read_text().lstrip().startswith("<?xml")


def test_run_no_figures_and_quiet(tmp_path, capsys):
    assert main(["run", str(DEMO), "-o", str(tmp_path), "--no-figures", "-q", "-r", "0.1"]) == 0
    assert capsys.readouterr() == ("", "")
    assert not list(tmp_path.glob("*.png")) and list(tmp_path.glob("*.csv"))


@needs_mpl
def test_figures_list_and_only(tmp_path, capsys):
    assert main(["figures", "--list"]) == 0
    names = capsys.readouterr().out.split()
    import gecko.scene
    shipped = sorted(p.stem for p in (Path(gecko.scene.__file__).parent / "figures").glob("*.toml"))
    assert sorted(names) == shipped and len(shipped) >= 16
    assert "seta_fig2a_axial_stiffness" in names and "friction_fig8_seta_force_space" in names
    assert main(["figures", "--only", "friction_fig8_seta_force_space", "--out", str(tmp_path), "-q"]) == 0
    assert (tmp_path / "friction_fig8.png").is_file()
    assert main(["figures", "--only", "fig99", "--out", str(tmp_path)]) == 2
    assert "unknown figure 'fig99'" in capsys.readouterr().err
    assert main(["figures"]) == 2  # --out is required to render


@needs_mpl
def test_console_entry_quiet_when_not_a_terminal(tmp_path):
    """``python -m gecko`` (same entry as the ``gecko`` script): stderr is a pipe, so no bar."""
    r = subprocess.run([sys.executable, "-m", "gecko", "run", str(DEMO), "--out", str(tmp_path), "-r", "0.1"],
                       capture_output=True, text=True, check=True)
    assert r.stderr == ""
    assert r.stdout.startswith(f"{DEMO}: 4 files in ")
    r = subprocess.run([sys.executable, "-m", "gecko", "validate", str(tmp_path / "none.toml")],
                       capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.startswith("gecko: error: ")


def test_resolution_from_environment(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("GECKO_RESOLUTION", "0.05")
    assert main(["plan", str(EXAMPLES / "seta_fig5a_fn0_vs_stiffness_ratio.toml")]) == 0
    assert "3 design(s)" in capsys.readouterr().out
    monkeypatch.setenv("GECKO_RESOLUTION", "lots")
    assert main(["plan", str(DEMO)]) == 2  # like a bad --resolution
    assert "GECKO_RESOLUTION: 'lots' is not a number" in capsys.readouterr().err


def test_run_shows_a_scenes_deprecation_warning(tmp_path, capsys):
    # Python's default filters hide a DeprecationWarning raised inside a library; under `gecko run`
    # the scene's deprecated key is the user's input, so the command shows it.
    scene = tmp_path / "dep.toml"
    scene.write_text('title = "dep"\n[[study]]\nname = "seta"\nmodel = "two_level_seta"\n'
                     'outputs = { characteristics = ["slope_k"] }\n')
    with warnings.catch_warnings(record=True) as seen:
        warnings.resetwarnings()
        warnings.simplefilter("ignore", DeprecationWarning)  # as a plain interpreter has it
        assert main(["run", str(scene), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    assert [str(w.message) for w in seen if issubclass(w.category, DeprecationWarning)] == [
        "scene study[0].outputs.characteristics: 'slope_k' is deprecated, use 'slope_at_zero' (the same values)"]
