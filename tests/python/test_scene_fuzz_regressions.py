"""Regressions found while writing fuzz/fuzz_scene.py (atheris): the scene expression evaluator must answer every
input with a float or a SceneError, quickly -- never RecursionError, MemoryError or a hang."""
import time

import pytest

from gecko.scene import SceneError, expr, validate_scene


@pytest.mark.parametrize("text", [
    "+".join(["1"] * 100000),        # was RecursionError in the parser
    "-" * 100000 + "1",              # was MemoryError in the parser
    "+".join(["1"] * 400),           # parsed, then RecursionError in the evaluator
    "-" * 900 + "1",
    "1\x00",                         # null byte
    "10**10**10",                    # must be a float overflow, never a huge integer
    "9**9**9**9",
    "1" + "0" * 5000,                # integer literal beyond Python's digit limit
    "exp(1e308)", "sqrt(-1)", "log(0)", "max()",
])
def test_bad_expressions_are_scene_errors(text):
    t0 = time.perf_counter()
    with pytest.raises(SceneError) as err:
        expr.evaluate(text)
    assert str(err.value)
    assert time.perf_counter() - t0 < 1.0


def test_limits_are_generous_for_real_expressions():
    assert expr.evaluate("+".join(["1"] * 90)) == 90.0
    assert expr.evaluate("(" * 150 + "2" + ")" * 150) == 2.0   # parentheses add no depth
    assert expr.evaluate("pi/3 - alpha2", {"alpha2": 0.5}) == pytest.approx(1.0471975511965976 - 0.5)
    with pytest.raises(SceneError, match="characters long"):
        expr.evaluate("1+" * 600 + "1")
    with pytest.raises(SceneError, match="nested more than"):
        expr.evaluate("-" * (expr.MAX_EXPRESSION_DEPTH + 5) + "1")


def test_huge_expression_in_a_scene_file_is_a_scene_error(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text('[[study]]\nmodel = "kendall"\nparameters = { EA = "' + "+".join(["1"] * 5000) + '" }\n')
    with pytest.raises(SceneError, match="characters long"):
        validate_scene(p)


@pytest.mark.parametrize("text, match", [
    # findings S1/S2 of fuzz/fuzz_scene.py: 100-byte scenes that asked for 1e9 points or 1e10 designs
    ('[[study]]\nmodel = "two_level_seta"\noutputs.critical_line = { Ft = { range = [0, 1], num = 10000000 } }\n',
     "points per grid"),
    ('resolution = 100\n[[study]]\nmodel = "two_level_seta"\n'
     'outputs.critical_line = { Ft = { range = [0, 1], num = 20000 } }\n', "points per grid"),
    ('[[study]]\nmodel = "two_level_seta"\nparameters = { EI1 = { range = [1, 2], num = 1000 }, '
     'EI2 = { range = [1, 2], num = 1000 } }\noutputs.fn0 = true\n', "designs"),
    ('[[study]]\nmodel = "two_level_seta"\nparameters = { EI1 = { range = [1, 2], num = 10000 } }\n'
     'outputs.critical_line = { Ft = { range = [0, 1], num = 5000 } }\n', "evaluations per output"),
])
def test_oversized_studies_are_refused_quickly(tmp_path, text, match):
    p = tmp_path / "big.toml"
    p.write_text(text)
    t0 = time.perf_counter()
    with pytest.raises(SceneError, match=match):
        validate_scene(p)
    assert time.perf_counter() - t0 < 5.0
