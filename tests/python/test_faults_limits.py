"""Fault injection, before the work: scenes too large, nested too deep, with names that cannot be
file names, unusable output folders, bad environment variables; and the one exit-code table
(0 ok, 1 the run failed, 2 bad command line / scene / environment / output folder, 130 interrupted)."""
import errno
import os
from pathlib import Path

import pytest

from gecko import _integrity
from gecko.cli import EXIT_CODES, main
from gecko.scene import SceneError, load_scene, run_scene, validate_scene
from gecko.scene import limits

KENDALL = {"study": [{"model": "kendall", "parameters": {"EA": 50.0},
                      "outputs": {"critical_line": {"Ft": {"range": [0, 1], "num": 5}}}}],
           "plot": [{"kind": "critical_line", "name": "k"}]}


def scene_file(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def study(name):
    return {"study": [dict(KENDALL["study"][0], name=name)]}


# ---- nesting ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("text", ["title = " + "[" * 500 + "]" * 500 + "\n",
                                  "x = " + "{a = " * 500 + "1" + "}" * 500 + "\n"])
def test_toml_nested_500_levels_is_a_scene_error(tmp_path, text, capsys):
    p = scene_file(tmp_path, text)
    with pytest.raises(SceneError, match="nested too deeply"):
        validate_scene(p)
    assert main(["validate", p]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_dict_scene_nested_deeper_than_the_limit(tmp_path):
    deep = 1
    for _ in range(limits.MAX_NESTING + 5):
        deep = [deep]
    with pytest.raises(SceneError, match=f"nested more than {limits.MAX_NESTING} levels"):
        load_scene(dict(KENDALL, title=deep))


# ---- work and memory ------------------------------------------------------------------------------------

GRID_1E9 = """[sweep]
designs = "grid"
outputs = ["ft_max"]
[sweep.grid]
EI1 = {range = [1, 10], num = 1000}
EI2 = {range = [1, 10], num = 1000}
alpha2 = {range = [0.1, 0.5], num = 1000}
"""


def test_grid_of_1e9_designs_is_refused_at_validate(tmp_path, capsys):
    p = scene_file(tmp_path, GRID_1E9)
    assert main(["validate", p]) == 2
    err = capsys.readouterr().err
    assert "1000000000 designs, above the limit of 100000000" in err and "GECKO_MAX_DESIGNS" in err
    out = tmp_path / "out"
    assert main(["run", p, "--out", str(out), "-q"]) == 2
    assert not out.exists()  # refused before anything, the folder included


def test_random_sample_scaled_by_resolution_is_refused(tmp_path):
    text = ('[sweep]\ndesigns = "random"\nn = 1000000000\noutputs = ["ft_max"]\n'
            '[sweep.bounds]\nEI1 = [1, 10]\n')
    with pytest.raises(SceneError, match="designs, above the limit"):
        validate_scene(scene_file(tmp_path, text))


def test_limits_are_configurable_and_validated(tmp_path, monkeypatch, capsys):
    p = scene_file(tmp_path, GRID_1E9.replace("num = 1000}", "num = 10}"))  # 1000 designs
    assert main(["validate", p]) == 0
    assert "work: 1000 designs, 1000 points" in capsys.readouterr().out
    monkeypatch.setenv("GECKO_MAX_DESIGNS", "999")
    assert main(["validate", p]) == 2
    assert "1000 designs, above the limit of 999" in capsys.readouterr().err
    monkeypatch.setenv("GECKO_MAX_DESIGNS", "1000")
    assert main(["validate", p]) == 0
    monkeypatch.setenv("GECKO_MAX_MEMORY_MB", "1")
    p2 = scene_file(tmp_path, GRID_1E9.replace("num = 1000}", "num = 40}"), "big.toml")  # 64000 designs
    monkeypatch.setenv("GECKO_MAX_DESIGNS", "100000")
    with pytest.raises(SceneError, match="MiB of memory, above the limit of 1 MiB"):
        validate_scene(p2)
    capsys.readouterr()
    for bad in ("lots", "0", "-5", "1.5"):
        monkeypatch.setenv("GECKO_MAX_MEMORY_MB", bad)
        assert main(["validate", p]) == 2
        assert "environment variable GECKO_MAX_MEMORY_MB" in capsys.readouterr().err


# ---- names ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name, why", [
    ("a\x07b", "control character at position 1"), ("tab\there", "control character"),
    ("x" * 256, "256 bytes long"), ("é" * 128, "256 bytes long"), ("a/b", "no '/'"), ("..", "not '.' or '..'"),
    ("", "non-empty"),
])
def test_study_names_are_checked_at_validation(name, why):
    with pytest.raises(SceneError, match=why):
        load_scene(study(name))


def test_derived_file_name_too_long_is_refused_at_validation(tmp_path):
    text = ('[[study]]\nname = "%s"\nmodel = "kendall"\nparameters = { EA = 50.0 }\n'
            'outputs = { critical_line = { Ft = { range = [0, 1], num = 5 } }, csv = true }\n') % ("x" * 250)
    with pytest.raises(SceneError, match="byte name: need at most 255"):
        validate_scene(scene_file(tmp_path, text))


@pytest.mark.parametrize("section", ["plot", "sweep"])
def test_plot_and_sweep_names_longer_than_255_bytes(section):
    if section == "plot":
        scene = dict(KENDALL, plot=[{"kind": "critical_line", "name": "p" * 300}])
    else:
        scene = {"sweep": {"designs": "grid", "grid": {"EI1": [1, 2]}, "outputs": ["ft_max"], "name": "s" * 300}}
    with pytest.raises(SceneError, match="bytes long in UTF-8"):
        load_scene(scene)


# ---- the output folder ------------------------------------------------------------------------------------

def no_compute(monkeypatch):
    from gecko.scene import runner
    called = []
    monkeypatch.setattr(runner._Executor, "run", lambda self, step: called.append(step))
    return called


def test_read_only_and_uncreatable_output_folders_agree_exit_2_before_computing(tmp_path, monkeypatch, capsys):
    p = scene_file(tmp_path, "")
    Path(p).write_text(
        '[[study]]\nmodel = "kendall"\nparameters = { EA = 50.0 }\n'
        'outputs = { critical_line = { Ft = { range = [0, 1], num = 5 } } }\n'
        '[[plot]]\nkind = "critical_line"\nname = "k"\n')
    called = no_compute(monkeypatch)
    blocker = tmp_path / "a_file"
    blocker.write_text("x")
    assert main(["run", p, "--out", str(blocker / "sub"), "-q", "--no-figures"]) == 2
    e1 = capsys.readouterr().err
    ro = tmp_path / "ro"
    ro.mkdir()
    real_open = os.open

    def read_only(path, flags, *a):
        if str(path).startswith(str(ro)) and flags & os.O_CREAT:
            raise PermissionError(errno.EACCES, "Permission denied", path)
        return real_open(path, flags, *a)

    monkeypatch.setattr(_integrity.os, "open", read_only)
    assert main(["run", p, "--out", str(ro), "-q", "--no-figures"]) == 2
    e2 = capsys.readouterr().err
    assert "cannot write to the output folder" in e1 and "cannot write to the output folder" in e2
    assert "Permission denied" in e2 and called == []


@pytest.mark.skipif(os.name == "nt" or os.geteuid() == 0, reason="root writes to read-only folders")
def test_read_only_output_folder_for_real(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        with pytest.raises(SceneError, match="cannot write to the output folder"):
            run_scene(KENDALL, ro, draw=False, progress=False)
    finally:
        ro.chmod(0o700)


def test_disk_full_while_writing_the_scene_exits_1_and_leaves_nothing(tmp_path, monkeypatch, capsys):
    p = scene_file(tmp_path, '[[study]]\nmodel = "kendall"\nparameters = { EA = 50.0 }\n'
                             'outputs = { critical_line = { Ft = { range = [0, 1], num = 5 } } }\n'
                             '[[plot]]\nkind = "critical_line"\nname = "k"\n')
    out = tmp_path / "out"

    def full(self, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(Path, "write_text", full)
    assert main(["run", p, "--out", str(out), "-q", "--no-figures"]) == 1
    assert "No space left on device" in capsys.readouterr().err
    assert os.listdir(out) == []  # no staging folder, no half-written file


# ---- the exit-code table ----------------------------------------------------------------------------------

def test_help_documents_the_exit_codes_and_limits(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--help"])
    assert e.value.code == 0
    out = " ".join(capsys.readouterr().out.split())
    assert sorted(EXIT_CODES) == [0, 1, 2, 130]
    for code, text in EXIT_CODES.items():
        assert f"{code} {' '.join(text.split())}" in out
    for var in ("GECKO_MAX_DESIGNS", "GECKO_MAX_MEMORY_MB", "GECKO_RESOLUTION"):
        assert var in out


@pytest.mark.parametrize("argv", [["run", "S", "--out", "o", "--threads", "0"],
                                  ["run", "S", "--out", "o", "--resolution", "nan"],
                                  ["plan", "S", "-r", "-1"], ["run", "S"], ["nonsense"]])
def test_bad_command_lines_exit_2(argv, capsys):
    with pytest.raises(SystemExit) as e:
        main(argv)
    assert e.value.code == 2


@pytest.mark.parametrize("value", ["lots", "0", "nan", "-1", "1e9"])
def test_bad_resolution_environment_variable_exits_2(value, monkeypatch, capsys, tmp_path):
    monkeypatch.setenv("GECKO_RESOLUTION", value)
    p = scene_file(tmp_path, '[[study]]\nmodel = "kendall"\n'
                             'outputs = { critical_line = { Ft = { range = [0, 1], num = 5 } } }\n')
    assert main(["validate", p]) == 2
    assert "environment variable GECKO_RESOLUTION" in capsys.readouterr().err


def test_interrupt_exits_130_and_a_failure_exits_1(tmp_path, monkeypatch, capsys):
    import gecko.scene
    from gecko._sweep_store import SweepInterrupted
    p = scene_file(tmp_path, '[[study]]\nmodel = "kendall"\n'
                             'outputs = { critical_line = { Ft = { range = [0, 1], num = 5 } } }\n')

    def interrupted(*a, **k):
        raise SweepInterrupted("sweep interrupted after 5 of 9 designs; the finished work is kept in X", 5, 9, "X")
    monkeypatch.setattr(gecko.scene, "run_scene", interrupted)
    assert main(["run", p, "--out", str(tmp_path / "o")]) == 130
    assert "interrupted after 5 of 9 sweep designs, which are kept in X" in capsys.readouterr().err

    def failed(*a, **k):
        raise RuntimeError("the solver broke")
    monkeypatch.setattr(gecko.scene, "run_scene", failed)
    assert main(["run", p, "--out", str(tmp_path / "o")]) == 1
    assert "RuntimeError: the solver broke" in capsys.readouterr().err
