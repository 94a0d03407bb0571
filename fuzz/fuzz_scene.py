#!/usr/bin/env python3
"""Atheris fuzz target for the scene parser: gecko.scene.validate_scene and gecko.scene.expr.

    python3 fuzz/fuzz_scene.py -seed=1 -runs=20000 -timeout=10 fuzz/corpus/scene

Property: any bytes, read as a scene file, give either a valid ``Scene`` or a
``gecko.scene.SceneError`` (a ValueError subclass) with a non-empty message -- never another
exception type, never a hang (libFuzzer's -timeout turns a slow input into a finding). The first
byte selects the mode:

* even: the rest is a scene file: written to a temporary file and loaded with
  ``validate_scene(path)`` (covers the UTF-8 decoding, tomllib, every schema check, the
  expression evaluator and the models' C++ range checks);
* odd: the rest is one expression for ``gecko.scene.expr``: ``names_in`` and ``evaluate`` with a
  few names bound; the value must be a float.

Findings S1/S2 (fuzz/README.md "Findings"): the number of designs of a study and of grid points
were unbounded; schema.py now caps them (1e6 points per grid, 1e5 designs, 1e7 evaluations per
output). Inputs whose estimated work exceeds WORK_LIMIT are still skipped (counted), only to keep
the rate up: validating up to the caps takes seconds. GECKO_FUZZ_STRICT=1 checks them as well.
"""
import atexit
import math
import os
import sys
import tempfile

import atheris

with atheris.instrument_imports(include=["gecko.scene"]):
    import gecko.scene as scene
    from gecko.scene import SceneError, expr

try:
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python < 3.11
    import tomli as tomllib

WORK_LIMIT = 20000  # designs x (1 + grid points): a fraction of a second to validate
STRICT = os.environ.get("GECKO_FUZZ_STRICT") == "1"
# one scratch file per process, rewritten for every input (validate_scene reads paths)
_tmp = tempfile.NamedTemporaryFile(prefix="gecko-fuzz-scene-", suffix=".toml", delete=False)
_tmp.close()
_skipped = [0]


def _sweep_len(v, res):
    if isinstance(v, list):
        return max(1, len(v))
    if isinstance(v, dict):
        if "values" in v and isinstance(v["values"], list):
            return max(1, len(v["values"]))
        n = v.get("num")
        if isinstance(n, (int, float)) and not isinstance(n, bool) and math.isfinite(n):
            return max(2, int(abs(n) * res))
    return 1


def _grid_points(v, res):
    """Largest grid anywhere below an outputs table."""
    if isinstance(v, dict):
        here = _sweep_len(v, res) if ("num" in v or "values" in v) else 1
        return max([here] + [_grid_points(x, res) for x in v.values()])
    if isinstance(v, list):
        return max([len(v)] + [_grid_points(x, res) for x in v])
    return 1


def estimated_work(data) -> float:
    """Designs x grid points the validation would evaluate (findings S1/S2)."""
    if not isinstance(data, dict):
        return 0
    res = data.get("resolution", 1.0)
    res = float(res) if isinstance(res, (int, float)) and not isinstance(res, bool) and 0 < res <= 100 else 1.0
    studies = data.get("study")
    studies = [studies] if isinstance(studies, dict) else studies if isinstance(studies, list) else []
    total = 0.0
    for s in studies:
        if not isinstance(s, dict):
            continue
        designs = 1.0
        for table in ("parameters", "variables"):
            t = s.get(table)
            if isinstance(t, dict):
                for v in t.values():
                    designs *= _sweep_len(v, res)
        total += designs * (1 + _grid_points(s.get("outputs"), res))
    return total


def check_scene(text: bytes) -> None:
    if not STRICT:
        try:
            data = tomllib.loads(text.decode("utf-8"))
        except (UnicodeDecodeError, tomllib.TOMLDecodeError, RecursionError):
            data = None  # the parser must reject it with a SceneError: checked below
        if data is not None and estimated_work(data) > WORK_LIMIT:
            _skipped[0] += 1
            if _skipped[0] in (1, 10, 100, 1000, 10000, 100000):  # libFuzzer exits without atexit
                print(f"fuzz_scene: {_skipped[0]} inputs above WORK_LIMIT skipped so far (above the fuzzing work limit)",
                      file=sys.stderr)
            return
    with open(_tmp.name, "wb") as f:
        f.write(text)
    try:
        result = scene.validate_scene(_tmp.name)
    except SceneError as err:
        if not str(err):
            raise AssertionError("SceneError without a message") from err
        return
    if not isinstance(result, scene.Scene):
        raise AssertionError(f"validate_scene returned {type(result).__name__}, not a Scene")


def check_expression(text: str) -> None:
    env = {"a": 1.5, "ft_max": 10.0, "alpha2": math.pi / 6}
    try:
        names = expr.names_in(text)
        value = expr.evaluate(text, env, key="x", allowed=env)
    except SceneError as err:
        if not str(err):
            raise AssertionError("SceneError without a message") from err
        return
    if not isinstance(names, (set, frozenset)):
        raise AssertionError(f"names_in returned {type(names).__name__}")
    if not isinstance(value, float):
        raise AssertionError(f"evaluate({text!r}) returned {type(value).__name__}, not float")


def TestOneInput(data: bytes) -> None:
    if not data:
        return
    if data[0] % 2 == 0:
        check_scene(data[1:])
    else:
        check_expression(data[1:].decode("utf-8", errors="replace"))


def main() -> None:
    atexit.register(os.unlink, _tmp.name)  # when the interpreter exits normally (not after -runs)
    atheris.Setup(sys.argv, TestOneInput)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
