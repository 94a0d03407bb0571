"""The ``[sweep]`` and ``[optimize]`` sections of a scene: many designs as one table, and a design
optimisation (gecko.design_sweep, gecko.optimize).

    [sweep]                              # characteristics of many two-level seta designs
    designs = "sobol"                    # "grid", "random", "sobol", "latin_hypercube" or "table"
    n = 1024                             # sample size (scaled by the resolution)
    seed = 1
    outputs = ["fn0", "slope_at_zero", "max_pull_off", "ft_max", "sticky_at_rest"]
    errors = "nan"                       # keep invalid designs as rows with status 5
    executor = "threads"                 # or "dask://host:8786"
    [sweep.bounds]                       # random / sobol / latin_hypercube: [lower, upper(, "log")]
    EI1 = [1, 10, "log"]
    alpha2 = [0, "pi/4"]
    [sweep.parameters]                   # fixed values of the other fields (default: reference)
    EA2 = 100

    [optimize]                           # gecko.optimize.optimize_from_scene's table
    objective = "max_pull_off"
    vary = { alpha2 = [0, "pi/3"], "EI2/EI1" = [0.05, 1] }
    constraints = { not_sticky = true }

Every error is a SceneError naming the key; nothing here computes.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from .._renamed import warn_renamed
from . import expr
from .errors import SceneError
from .grids import eval_grid
from .models import _check_keys, _int_in, _tname

SWEEP_KEYS = ("designs", "n", "seed", "bounds", "grid", "table", "parameters", "outputs", "chunk_size",
              "executor", "connect_timeout", "errors", "format", "name", "plot")
SWEEP_DESIGNS = ("grid", "random", "sobol", "latin_hypercube", "table")
SWEEP_PLOT_KEYS = ("x", "y", "color", "xscale", "yscale")
# the [optimize] table is gecko.optimize.optimize_from_scene's; "name" is the scene's own
OPTIMIZE_KEYS = ("objective", "ft", "vary", "constraints", "starts", "seed", "fixed", "method", "maxiter",
                 "include_base", "quadrature_nodes", "name")
OPTIMIZE_DERIVED = ("EI2/EI1", "l2/l1", "alpha1+alpha2")


@dataclass
class SweepSpec:
    designs: str
    n: Optional[int] = None
    seed: int = 0
    bounds: Dict[str, Tuple] = field(default_factory=dict)      # name -> (lower, upper) or (.., "log")
    grid: Dict[str, np.ndarray] = field(default_factory=dict)
    table: Optional[str] = None
    fixed: Dict[str, float] = field(default_factory=dict)
    outputs: List[str] = field(default_factory=list)
    chunk_size: int = 10000
    executor: str = "threads"
    connect_timeout: float = 10.0
    errors: str = "raise"
    format: str = "parquet"
    name: str = "sweep"
    plot: Optional[Dict[str, str]] = None

    def describe(self) -> str:
        if self.designs == "grid":
            what = f"grid over {', '.join(self.grid)} ({self.size} designs)"
        elif self.designs == "table":
            what = f"designs from {self.table}"
        else:
            what = f"{self.n} {self.designs} designs over {', '.join(self.bounds)} (seed {self.seed})"
        from ..design_sweep import SWEEP_OUTPUTS
        depth = max(SWEEP_OUTPUTS[o] for o in self.outputs)
        how = ("closed forms only, no solver", "natural state at Ft = 0 per design, no line traced",
               "critical line followed to its end per design")[depth]
        return (f"sweep {self.name!r}: {what}; outputs {', '.join(self.outputs)}: {how}; "
                f"chunks of {self.chunk_size} on {self.executor} -> {self.name}.{self.format}")

    @property
    def size(self) -> int:
        if self.designs == "grid":
            return int(np.prod([len(v) for v in self.grid.values()]))
        return int(self.n or 0)

    def design_table(self):
        """The designs as a DataFrame (pandas needed)."""
        from .. import design_sweep as ds
        if self.designs == "grid":
            return ds.design_grid(self.grid, fixed=self.fixed)
        if self.designs == "table":
            from .._optional import require
            pd = require("pandas", "a [sweep] design table", "sweep")
            t = pd.read_parquet(self.table) if self.table.endswith(".parquet") else pd.read_csv(self.table)
            for k, v in self.fixed.items():
                if k not in t.columns:
                    t[k] = v
            return t
        maker = {"random": ds.random_designs, "sobol": ds.sobol_designs,
                 "latin_hypercube": ds.latin_hypercube_designs}[self.designs]
        return maker(self.bounds, self.n, seed=self.seed, fixed=self.fixed)


@dataclass
class OptimizeSpec:
    table: Dict[str, Any]      # plain values, as gecko.optimize.optimize_from_scene takes it
    name: str = "optimum"

    def describe(self) -> str:
        t = self.table
        return (f"optimize {self.name!r}: maximise {t['objective']} over {', '.join(t['vary'])}, "
                f"{t.get('starts', 8)} starts (SLSQP, exact gradients) -> {self.name}.json, {self.name}.png")


def _num(v, key: str) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, str)):
        raise SceneError(f"need a number or an expression string such as \"pi/6\"; got {_tname(v)}", key=key)
    return expr.evaluate(v, {}, key) if isinstance(v, str) else float(v)


def _name(v, key: str, default: str) -> str:
    if v is None:
        return default
    if not isinstance(v, str) or not v or v[0] == "." or not all(c.isalnum() or c in "-_." for c in v):
        raise SceneError(f"{v!r} is not allowed: need a file-name stem of letters, digits, '-', '_', '.'", key=key)
    from .limits import check_name
    return check_name(v, key)


def _fixed(table, key: str, allowed) -> Dict[str, float]:
    if not isinstance(table, dict):
        raise SceneError(f"need a table {{name = value}}; got {_tname(table)}", key=key)
    out = {}
    for k, v in table.items():
        if k not in allowed:
            raise SceneError(f"unknown parameter {k!r}; allowed: " + ", ".join(allowed), key=f"{key}.{k}")
        out[k] = _num(v, f"{key}.{k}")
    return out


def parse_sweep(t, res: float, base_dir: Optional[str]) -> SweepSpec:
    from ..design_sweep import DEFAULT_SWEEP_OUTPUTS, SWEEP_OUTPUTS
    from ..designs import FIELDS, parse_bounds
    key = "sweep"
    if not isinstance(t, dict):
        raise SceneError(f"need a table; got {_tname(t)}", key=key)
    _check_keys(t, SWEEP_KEYS, key)
    kind = t.get("designs")
    if kind not in SWEEP_DESIGNS:
        raise SceneError(("missing key 'designs'" if kind is None else f"{kind!r} is not allowed")
                         + "; allowed: " + ", ".join(map(repr, SWEEP_DESIGNS)), key=f"{key}.designs")
    spec = SweepSpec(kind)
    spec.fixed = _fixed(t.get("parameters", {}), f"{key}.parameters", FIELDS)
    # which keys go with which kind of designs
    needs = {"grid": ("grid",), "table": ("table",), "random": ("bounds", "n"), "sobol": ("bounds", "n"),
             "latin_hypercube": ("bounds", "n")}[kind]
    for k in ("grid", "table", "bounds", "n", "seed"):
        if k in needs and k not in t:
            raise SceneError(f"designs = {kind!r} needs the key {k!r}", key=key)
        if k in t and k not in needs and not (k == "seed" and kind in ("random", "sobol", "latin_hypercube")):
            raise SceneError(f"{k!r} is not used by designs = {kind!r} (it needs: {', '.join(needs)})",
                             key=f"{key}.{k}")
    if "n" in t:
        spec.n = max(1, int(round(_int_in(t["n"], f"{key}.n", 1, 10**9) * res)))
    if "seed" in t:
        spec.seed = _int_in(t["seed"], f"{key}.seed", 0, 2**63 - 1)
    if "bounds" in t:
        b = t["bounds"]
        if not isinstance(b, dict) or not b:
            raise SceneError("need a table {name = [lower, upper]} or [lower, upper, \"log\"]; names: "
                             + ", ".join(FIELDS), key=f"{key}.bounds")
        for name, v in b.items():
            k = f"{key}.bounds.{name}"
            if name in spec.fixed:
                raise SceneError(f"{name!r} is both sampled and fixed in [sweep.parameters]", key=k)
            if not (isinstance(v, list) and len(v) in (2, 3)):
                raise SceneError("need [lower, upper] or [lower, upper, \"log\"]", key=k)
            scale = v[2] if len(v) == 3 else "linear"
            if scale not in ("linear", "log"):
                raise SceneError(f"{scale!r} is not allowed: the third entry is 'linear' or 'log'", key=f"{k}[2]")
            lo, hi = _num(v[0], f"{k}[0]"), _num(v[1], f"{k}[1]")
            try:
                parse_bounds({name: (lo, hi, scale)})
            except ValueError as exc:
                raise SceneError(str(exc), key=k) from None
            spec.bounds[name] = (lo, hi, scale)
    if "grid" in t:
        g = t["grid"]
        if not isinstance(g, dict) or not g:
            raise SceneError("need a table {name = values}: a list, {range = [a, b], num = N} or {logrange = ...}",
                             key=f"{key}.grid")
        for name, v in g.items():
            k = f"{key}.grid.{name}"
            if name not in FIELDS:
                raise SceneError(f"unknown parameter {name!r}; allowed: " + ", ".join(FIELDS), key=k)
            if name in spec.fixed:
                raise SceneError(f"{name!r} is both swept and fixed in [sweep.parameters]", key=k)
            spec.grid[name] = eval_grid(v, {}, k, res)
    if "table" in t:
        p = t["table"]
        if not isinstance(p, str) or not p.endswith((".csv", ".parquet")):
            raise SceneError("need the path of a .csv or .parquet file with one column per design parameter "
                             "(relative to the scene file)", key=f"{key}.table")
        full = p if os.path.isabs(p) or base_dir is None else os.path.join(base_dir, p)
        if not os.path.isfile(full):
            raise SceneError(f"no such file: {full!r}", key=f"{key}.table")
        spec.table = full
    outs = t.get("outputs", list(DEFAULT_SWEEP_OUTPUTS))
    if isinstance(outs, str):
        outs = [outs]
    if not (isinstance(outs, list) and outs and all(isinstance(o, str) for o in outs)):
        raise SceneError("need a non-empty list of names from: " + ", ".join(SWEEP_OUTPUTS), key=f"{key}.outputs")
    for i, o in enumerate(outs):
        if o not in SWEEP_OUTPUTS:
            raise SceneError(f"unknown output {o!r}; allowed: " + ", ".join(SWEEP_OUTPUTS), key=f"{key}.outputs[{i}]")
    spec.outputs = list(dict.fromkeys(outs))
    warn_renamed(spec.outputs, f"scene {key}.outputs")
    if "chunk_size" in t:
        spec.chunk_size = _int_in(t["chunk_size"], f"{key}.chunk_size", 1, 10**8)
    ex = t.get("executor", "threads")
    if not (isinstance(ex, str) and (ex == "threads" or (ex.startswith("dask://") and len(ex) > 7))):
        raise SceneError(f"{ex!r} is not allowed: need 'threads' or 'dask://host:port'", key=f"{key}.executor")
    spec.executor = ex
    if "connect_timeout" in t:
        v = t["connect_timeout"]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 < v <= 3600:
            raise SceneError(f"{v!r} is out of range: need seconds in (0, 3600]", key=f"{key}.connect_timeout")
        spec.connect_timeout = float(v)
    spec.errors = t.get("errors", "raise")
    if spec.errors not in ("raise", "nan"):
        raise SceneError(f"{spec.errors!r} is not allowed: need 'raise' (refuse an invalid design) or 'nan' "
                         "(keep it as a row with status 5)", key=f"{key}.errors")
    spec.format = t.get("format", "parquet")
    if spec.format not in ("parquet", "csv"):
        raise SceneError(f"{spec.format!r} is not allowed: need 'parquet' or 'csv'", key=f"{key}.format")
    spec.name = _name(t.get("name"), f"{key}.name", "sweep")
    if "plot" in t:
        p = t["plot"]
        if not isinstance(p, dict):
            raise SceneError("need a table {x = OUTPUT, y = OUTPUT, color = OUTPUT}", key=f"{key}.plot")
        _check_keys(p, SWEEP_PLOT_KEYS, f"{key}.plot")
        cols = list(spec.outputs) + list(FIELDS)
        for k in ("x", "y", "color"):
            if k in ("x", "y") and k not in p:
                raise SceneError(f"missing key {k!r}: a column of the table ({', '.join(cols)})", key=f"{key}.plot")
            if k in p and p[k] not in cols:
                raise SceneError(f"{p[k]!r} is not a column of this sweep; columns: " + ", ".join(cols),
                                 key=f"{key}.plot.{k}")
        for k in ("xscale", "yscale"):
            if k in p and p[k] not in ("linear", "log"):
                raise SceneError(f"{p[k]!r} is not allowed; allowed: 'linear', 'log'", key=f"{key}.plot.{k}")
        spec.plot = dict(p)
    return spec


def parse_optimize(t, res: float) -> OptimizeSpec:
    """Checks the [optimize] table (keys, types, ranges) and returns it with plain values: numbers
    evaluated, ``starts`` scaled by the resolution; gecko.optimize runs it."""
    from ..designs import FIELDS, parse_bounds
    key = "optimize"
    if not isinstance(t, dict):
        raise SceneError(f"need a table; got {_tname(t)}", key=key)
    params = tuple(FIELDS) + OPTIMIZE_DERIVED
    _check_keys(t, OPTIMIZE_KEYS + params, key)
    out: Dict[str, Any] = {}
    obj = t.get("objective")
    from ..optimize import OBJECTIVES as objectives
    if obj not in objectives:
        raise SceneError(("missing key 'objective'" if obj is None else f"{obj!r} is not allowed")
                         + "; allowed: " + ", ".join(map(repr, objectives)), key=f"{key}.objective")
    out["objective"] = obj
    if "ft" in t:
        if obj != "pull_off_at":
            raise SceneError("ft is only used by objective = 'pull_off_at'", key=f"{key}.ft")
        out["ft"] = _num(t["ft"], f"{key}.ft")
        if not math.isfinite(out["ft"]):
            raise SceneError("need a finite shear force", key=f"{key}.ft")
    elif obj == "pull_off_at":
        raise SceneError("objective = 'pull_off_at' needs ft = the shear force where the pull-off is maximised",
                         key=key)
    vary = t.get("vary")
    if not isinstance(vary, dict) or not vary:
        raise SceneError("missing or empty: need vary = {name = [lower, upper]}; names: " + ", ".join(params),
                         key=f"{key}.vary")
    out["vary"] = {}
    for name, v in vary.items():
        k = f"{key}.vary.{name}"
        if name not in params:
            raise SceneError(f"unknown parameter {name!r}; allowed: " + ", ".join(params), key=k)
        if not (isinstance(v, list) and len(v) == 2):
            raise SceneError("need [lower, upper]", key=k)
        lo, hi = _num(v[0], f"{k}[0]"), _num(v[1], f"{k}[1]")
        if name in FIELDS:
            try:
                parse_bounds({name: (lo, hi)})
            except ValueError as exc:
                raise SceneError(str(exc), key=k) from None
        elif not (math.isfinite(lo) and math.isfinite(hi) and lo < hi and lo >= 0):
            raise SceneError(f"[{lo:g}, {hi:g}] is out of range: need finite 0 <= lower < upper", key=k)
        out["vary"][name] = [lo, hi]
    fixed = _fixed(t.get("fixed", {}), f"{key}.fixed", params)
    for name in params:
        if name in t:
            if name in fixed:
                raise SceneError(f"{name!r} is given both here and in fixed", key=f"{key}.{name}")
            fixed[name] = _num(t[name], f"{key}.{name}")
    for name in fixed:
        if name in out["vary"]:
            raise SceneError(f"{name!r} is both fixed and varied", key=f"{key}.vary.{name}")
    if fixed:
        out["fixed"] = fixed
    cons = t.get("constraints", {})
    if not isinstance(cons, dict):
        raise SceneError("need a table {not_sticky = true, fn0_min = number}", key=f"{key}.constraints")
    _check_keys(cons, ("not_sticky", "fn0_min"), f"{key}.constraints")
    if "not_sticky" in cons and not isinstance(cons["not_sticky"], bool):
        raise SceneError("need true or false", key=f"{key}.constraints.not_sticky")
    c = dict(cons)
    if "fn0_min" in c:
        c["fn0_min"] = _num(c["fn0_min"], f"{key}.constraints.fn0_min")
        if not math.isfinite(c["fn0_min"]):
            raise SceneError("need a finite number", key=f"{key}.constraints.fn0_min")
    if c:
        out["constraints"] = c
    if "starts" in t:
        out["starts"] = max(1, int(round(_int_in(t["starts"], f"{key}.starts", 1, 1024) * min(res, 1.0))))
    if "seed" in t:
        out["seed"] = _int_in(t["seed"], f"{key}.seed", 0, 2**63 - 1)
    if "maxiter" in t:
        out["maxiter"] = _int_in(t["maxiter"], f"{key}.maxiter", 1, 10000)
    if "quadrature_nodes" in t:
        out["quadrature_nodes"] = _int_in(t["quadrature_nodes"], f"{key}.quadrature_nodes", 4, 400)
    if "method" in t:
        if t["method"] != "SLSQP":
            raise SceneError(f"{t['method']!r} is not allowed: need 'SLSQP'", key=f"{key}.method")
        out["method"] = "SLSQP"
    if "include_base" in t:
        if not isinstance(t["include_base"], bool):
            raise SceneError("need true or false", key=f"{key}.include_base")
        out["include_base"] = t["include_base"]
    return OptimizeSpec(out, _name(t.get("name"), f"{key}.name", "optimum"))
