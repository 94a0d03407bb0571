"""Grids of a scene: the numbers of a grid spec (a list, ``range``, ``logrange`` or ``values``).

Below the schema and the [sweep]/[optimize] sections, which both read grids."""
from __future__ import annotations

import math
from typing import Dict

import numpy as np

from . import expr
from .errors import SceneError
from .models import _tname, check_grid

DEFAULT_GRIDS = {
    "critical_line": {"range": [0, "ft_end"], "num": 200},
    "linear_line": {"range": [0, "ft_end"], "num": 50},
    "sensitivities": {"range": [0, "0.95*ft_end"], "num": 50},
    "forces": {"logrange": [1e-6, 1e-3], "num": 100},
}


def _number(v, key: str, env: Dict[str, float], allowed=()) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, str)):
        raise SceneError(f"need a number or an expression string; got {_tname(v)}", key=key)
    if isinstance(v, str):
        return expr.evaluate(v, env, key, allowed)
    return float(v)


# Limit on one grid (scene fuzzing: validation must stay fast and bounded).
MAX_GRID_POINTS = 1_000_000


def eval_grid(spec, env: Dict[str, float], key: str, resolution: float = 1.0) -> np.ndarray:
    """Numbers of a grid spec (list, range, logrange, values); ranges scale with ``resolution``."""
    check_grid(spec, key)
    if isinstance(spec, list):
        return np.array([_number(v, f"{key}[{i}]", env) for i, v in enumerate(spec)], dtype=np.float64)
    if "values" in spec:
        return eval_grid(spec["values"], env, f"{key}.values", resolution)
    form = "range" if "range" in spec else "logrange"
    a, b = (_number(v, f"{key}.{form}[{i}]", env) for i, v in enumerate(spec[form]))
    num = max(2, int(round(spec["num"] * resolution)))
    # A 100-byte scene must not be able to ask for 1e9 points (found by fuzz/fuzz_scene.py): cap
    # a grid after the resolution is applied. Larger runs belong in a [sweep] section (chunked).
    if num > MAX_GRID_POINTS:
        raise SceneError(f"num x resolution = {num} is out of range: need at most {MAX_GRID_POINTS} "
                         "points per grid (use a [sweep] section for larger runs)", key=f"{key}.num")
    if not (math.isfinite(a) and math.isfinite(b)):
        raise SceneError(f"[{a}, {b}] is out of range: the bounds must be finite", key=f"{key}.{form}")
    if form == "logrange":
        if not (a > 0 and b > 0):
            raise SceneError(f"[{a:g}, {b:g}] is out of range: logrange bounds must be > 0", key=f"{key}.{form}")
        return np.geomspace(a, b, num)
    return np.linspace(a, b, num)
