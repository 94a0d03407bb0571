"""Scene schema: read a TOML file or dict, check every key, expand the sweeps.

A scene (see ``examples/README.md`` for the full reference)::

    title = "Fig 2b: effect of l2/l1"
    resolution = 1.0                       # scales the number of points of every range

    [[study]]
    name = "seta"
    model = "two_level_seta"               # see gecko.scene.MODELS
    combine = "cross"                      # or "zip": how several swept names combine
    label = "l2/l1 = {l2:g}"               # legend template (optional)
    [study.parameters]                     # value, expression string, list (sweep) or range table
    l2 = [0.1, 0.2, 0.3]
    [study.variables]                      # free names for expressions and sweeps
    [study.outputs]
    critical_line = { Ft = { range = [0, "ft_end"], num = 200 } }

    [[plot]]
    name = "fig2b"
    kind = "critical_line"

Every error is a :class:`SceneError` naming the file, the key path and what is allowed.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Dict, List, Optional

import numpy as np

from .._renamed import warn_renamed
from . import expr
from .errors import SceneError
from .models import (CHARACTERISTIC_LABELS, MODELS, Model, OutputSpec, Param, _check_keys, _tname,
                     parse_output)
from .grids import DEFAULT_GRIDS, MAX_GRID_POINTS, _number, eval_grid  # noqa: F401  (old names)
from .toml import load_toml

TOP_KEYS = ("title", "description", "resolution", "study", "plot", "sweep", "optimize")
STUDY_KEYS = ("name", "model", "label", "combine", "parameters", "variables", "outputs")
PLOT_KEYS = ("name", "kind", "studies", "x", "y", "xlim", "ylim", "xscale", "yscale", "title",
             "xlabel", "ylabel", "legend", "formats", "size", "arrows")

#: plot kind -> the study output it draws
PLOT_KINDS = {
    "critical_line": ("critical_line", "linear_line"),
    "characteristic": ("characteristics",),
    "shapes": ("shapes",),
    "sensitivities": ("sensitivities",),
    "force_trace": ("force_trace",),
    "force_space": ("force_trace",),
    "steady_sliding": ("forces",),
    "contact_contours": ("contact_contours",),
    "sliding_fit": ("fit",),
}
FORMATS = ("png", "svg", "pdf")

# Limits on what one study may expand to (scene fuzzing: validation must stay fast and bounded).
MAX_STUDY_DESIGNS = 100_000
MAX_STUDY_EVALUATIONS = 10_000_000


# ---- values -------------------------------------------------------------------------------------

def _is_sweep(v) -> bool:
    return isinstance(v, list) or (isinstance(v, dict) and any(k in v for k in ("range", "logrange", "values")))


# ---- scene objects --------------------------------------------------------------------------------

@dataclass
class Point:
    """One design of a study: every parameter resolved, plus the values of the swept names."""

    index: int
    values: Dict[str, Any]
    swept: Dict[str, Any]
    params: frozenset = frozenset()  # the model's parameter names among ``values``


@dataclass
class Study:
    name: str
    model: Model
    key: str
    combine: str
    label: Optional[str]
    points: List[Point]
    outputs: Dict[str, OutputSpec]
    swept_names: List[str]

    def env(self, point: Point) -> Dict[str, float]:
        """Names usable in output grids: the design, its variables and ``ft_max``, ``ft_end``."""
        env = {k: v for k, v in point.values.items() if isinstance(v, float)}
        m = self.model.name
        w = env.get("w", 1.0)
        ea = env.get("EA2" if m == "two_level_seta" else "EA", math.inf)
        if m in ("two_level_seta", "single_fiber", "kendall", "rivlin"):
            env["ft_max"] = math.sqrt(2 * ea * w)
            env["ft_end"] = env["ft_max"] if math.isfinite(env["ft_max"]) else 10.0 * w
        return env

    def label_for(self, point: Point, plot_has_many_studies: bool = False) -> str:
        if self.label:
            fields = {k: _Num(v) if isinstance(v, float) else v for k, v in point.values.items()}
            try:
                return self.label.format(**fields)
            except KeyError as exc:
                raise SceneError(f"unknown name {exc.args[0]!r} in the label {self.label!r}; names: "
                                 + ", ".join(fields) + " (write {{ and }} for literal braces)",
                                 key=f"{self.key}.label") from None
            except (IndexError, ValueError) as exc:
                raise SceneError(f"cannot format the label {self.label!r}: {exc} (write {{{{ and }}}} for "
                                 "literal braces)", key=f"{self.key}.label") from None
        parts = [f"{_symbol(self.model, n)} = {_fmt(n, point.swept[n])}" for n in self.swept_names]
        if not parts:
            return default_title(self, point)
        text = ", ".join(parts)
        return f"{self.model.title}: {text}" if plot_has_many_studies else text


@dataclass
class PlotSpec:
    name: str
    kind: str
    key: str
    studies: List[str]
    x: Optional[str] = None
    y: List[str] = field(default_factory=list)
    options: Dict[str, Any] = field(default_factory=dict)
    formats: List[str] = field(default_factory=lambda: ["png"])


@dataclass
class Scene:
    """A validated scene (:func:`load_scene`).

    Attributes
    ----------
    title, description : str
        As in the file.
    resolution : float
        Scale of every grid's number of points.
    studies : list of Study
        Each a model, its designs (:class:`Point`) and the outputs asked for.
    plots : list of PlotSpec
        The figures to draw.
    source : str
        The file, or ``"<dict>"``.
    sweep, optimize : optional
        The ``[sweep]`` and ``[optimize]`` sections, when present.

    Examples
    --------
    >>> from gecko.scene import load_scene
    >>> sc = load_scene({"title": "t", "study": [{"name": "k", "model": "kendall",
    ...                                          "outputs": {"characteristics": True}}]})
    >>> sc.study("k").model.name
    'kendall'
    """
    title: str
    description: str
    resolution: float
    studies: List[Study]
    plots: List[PlotSpec]
    source: str = "<dict>"
    sweep: Optional[Any] = None       # design_sections.SweepSpec: many designs as one table
    optimize: Optional[Any] = None    # design_sections.OptimizeSpec: a design optimisation

    def study(self, name: str) -> Study:
        for s in self.studies:
            if s.name == name:
                return s
        raise KeyError(name)


def default_title(study: Study, point: Point) -> str:
    m = study.model.name
    v = point.values
    if m == "kendall":
        return f"Kendall model ($EA/w$ = {_fmt('EA', v['EA'] / v['w'])})"
    if m == "rivlin":
        return "Rivlin model"
    if m == "single_fiber":
        return f"single-level, $EI/(wl^2)$ = {_fmt('EI', v['EI'] / (v['w'] * v['l'] ** 2))}"
    if m == "steady_sliding":
        return f"{v['preset']} fit" if study.name == study.model.name else study.name
    if m == "sliding_fit":
        return study.name
    return study.name if study.name != m else study.model.title


class _Num(float):
    """A float whose format spec also accepts ``pi`` (write an angle as a fraction of pi)."""

    def __format__(self, spec: str) -> str:
        if spec == "pi":
            return _pi_fraction(float(self))
        if math.isinf(self):
            return "∞" if self > 0 else "-∞"
        return format(float(self), spec)


def _pi_fraction(v: float) -> str:
    from fractions import Fraction
    f = Fraction(v / math.pi).limit_denominator(72)
    if abs(float(f) * math.pi - v) > 1e-9 * max(1.0, abs(v)):
        return f"{v:.4g}"
    if f == 0:
        return "0"
    top = "π" if f.numerator == 1 else "-π" if f.numerator == -1 else f"{f.numerator}π"
    return top if f.denominator == 1 else f"{top}/{f.denominator}"


_ANGLES = {"alpha1", "alpha2", "alpha"}


def _fmt(name: str, v) -> str:
    if isinstance(v, float):
        if math.isinf(v):
            return "∞"
        if name in _ANGLES:
            return _pi_fraction(v)
        return f"{v:g}"
    return str(v)


def _symbol(model: Model, name: str) -> str:
    p = model.param(name)
    return (p.symbol or name) if p else name


# ---- parsing -----------------------------------------------------------------------------------

def load_scene(scene, *, resolution: Optional[float] = None) -> Scene:
    """A validated scene from a TOML path or a dict.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        A TOML file, the same structure as a dict, or a Scene (returned as is).
    resolution : float, optional
        Scales the number of points of every grid; overrides the file's ``resolution``.

    Returns
    -------
    Scene
        Title, description, studies (each with its model, designs and outputs), plots, and the
        optional ``[sweep]`` and ``[optimize]`` sections.

    Raises
    ------
    SceneError
        If the scene cannot be read or is not valid; the message names the file and the key.

    Examples
    --------
    >>> from gecko.scene import load_scene
    >>> scene = {"title": "two angles", "study": [{"name": "seta", "model": "two_level_seta",
    ...          "parameters": {"alpha2": [0.3, 0.5]}, "outputs": {"characteristics": ["fn0"]}}]}
    >>> sc = load_scene(scene)
    >>> sc.title, len(sc.studies[0].points)
    ('two angles', 2)
    """
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return parse_scene(scene, "<dict>", resolution=resolution)
    return parse_scene(load_toml(scene), str(scene), resolution=resolution)


def parse_scene(data: dict, source: str = "<dict>", *, resolution: Optional[float] = None) -> Scene:
    from .limits import check_file_names, check_nesting, check_work
    try:
        check_nesting(data)
        scene = _parse(data, resolution, None if source == "<dict>" else str(Path(source).resolve().parent))
        scene.source = source
        check_file_names(scene)
        check_work(scene)  # before anything is computed (gecko.scene.limits)
    except SceneError as err:
        raise err.at(source=source) from None
    return scene


def _parse(data, resolution_override, base_dir: Optional[str] = None) -> Scene:
    if not isinstance(data, dict):
        raise SceneError(f"a scene is a table (dict); got {_tname(data)}")
    _check_keys(data, TOP_KEYS, "")
    title = data.get("title", "")
    description = data.get("description", "")
    for k, v in (("title", title), ("description", description)):
        if not isinstance(v, str):
            raise SceneError(f"need a string; got {_tname(v)}", key=k)
    res = data.get("resolution", 1.0)
    if isinstance(res, bool) or not isinstance(res, (int, float)) or not (0 < res <= 100):
        raise SceneError(f"{res!r} is out of range: need a number in (0, 100]", key="resolution")
    res = float(resolution_override) if resolution_override is not None else float(res)
    if not 0 < res <= 100:
        raise SceneError(f"resolution {res!r} is out of range: need a number in (0, 100]")
    from .design_sections import parse_optimize, parse_sweep
    sweep = parse_sweep(data["sweep"], res, base_dir) if "sweep" in data else None
    optimize = parse_optimize(data["optimize"], res) if "optimize" in data else None
    studies_raw = data.get("study")
    if studies_raw is None and (sweep is not None or optimize is not None):
        studies_raw = []
        if data.get("plot"):
            raise SceneError("[[plot]] tables draw studies, and this scene has no [[study]]; a sweep "
                             "draws its own plot ([sweep.plot])", key="plot")
    elif studies_raw is None:
        raise SceneError("missing [[study]]: a scene needs at least one study (or a [sweep] or "
                         "[optimize] section)", key="study")
    if isinstance(studies_raw, dict):
        studies_raw = [studies_raw]
    if not isinstance(studies_raw, list) or (not studies_raw and sweep is None and optimize is None):
        raise SceneError("need one or more [[study]] tables", key="study")
    studies = []
    for i, s in enumerate(studies_raw):
        studies.append(_parse_study(s, f"study[{i}]", res, base_dir))
    names = [s.name for s in studies]
    for i, n in enumerate(names):
        if names.index(n) != i:
            raise SceneError(f"duplicate study name {n!r}; give each study a distinct name", key=f"study[{i}].name")
    plots_raw = data.get("plot", [])
    if isinstance(plots_raw, dict):
        plots_raw = [plots_raw]
    if not isinstance(plots_raw, list):
        raise SceneError("need [[plot]] tables", key="plot")
    plots = [_parse_plot(p, f"plot[{i}]", studies) for i, p in enumerate(plots_raw)]
    pn = [p.name for p in plots]
    for i, n in enumerate(pn):
        if pn.index(n) != i:
            raise SceneError(f"duplicate plot name {n!r}; plot names become file names and must differ",
                             key=f"plot[{i}].name")
    names = {sweep.name if sweep else None, optimize.name if optimize else None} - {None}
    for i, p in enumerate(plots):
        if p.name in names:
            raise SceneError(f"plot name {p.name!r} is also the name of the [sweep] or [optimize] output; "
                             "file names must differ", key=f"plot[{i}].name")
    if sweep is not None and optimize is not None and sweep.name == optimize.name:
        raise SceneError(f"[sweep] and [optimize] have the same name {sweep.name!r}; file names must differ",
                         key="optimize.name")
    return Scene(title, description, res, studies, plots, sweep=sweep, optimize=optimize)


def _parse_study(s, key: str, res: float, base_dir: Optional[str] = None) -> Study:
    if not isinstance(s, dict):
        raise SceneError(f"need a table; got {_tname(s)}", key=key)
    _check_keys(s, STUDY_KEYS, key)
    model_name = s.get("model")
    if model_name is None:
        raise SceneError("missing key 'model'; allowed models: " + ", ".join(MODELS), key=key)
    if model_name not in MODELS:
        raise SceneError(f"unknown model {model_name!r}; allowed models: " + ", ".join(MODELS), key=f"{key}.model")
    model = MODELS[model_name]
    name = s.get("name", model_name)
    from .limits import check_name
    check_name(name, f"{key}.name", "study name")
    combine = s.get("combine", "cross")
    if combine not in ("cross", "zip"):
        raise SceneError(f"{combine!r} is not allowed: need 'cross' (every combination) or 'zip' (pairwise)",
                         key=f"{key}.combine")
    label = s.get("label")
    if label is not None and not isinstance(label, str):
        raise SceneError(f"need a string (a format template such as 'l2 = {{l2:g}}'); got {_tname(label)}",
                         key=f"{key}.label")
    params = s.get("parameters", {})
    variables = s.get("variables", {})
    for k, t in (("parameters", params), ("variables", variables)):
        if not isinstance(t, dict):
            raise SceneError(f"need a table; got {_tname(t)}", key=f"{key}.{k}")
    allowed = [p.name for p in model.params]
    for k in params:
        if k not in allowed:
            raise SceneError(f"unknown parameter {k!r} for model {model_name!r}; allowed: " + ", ".join(allowed)
                             + " (free names go in [study.variables])", key=f"{key}.parameters.{k}")
    for k in variables:
        if k in allowed or k in expr.CONSTANTS or k in expr.FUNCTIONS or not k.isidentifier():
            raise SceneError(f"variable name {k!r} is not allowed: it must be an identifier that is not a "
                             "parameter, constant or function name", key=f"{key}.variables.{k}")
    points, swept = _expand(model, params, variables, combine, key, res, base_dir)
    outputs: Dict[str, OutputSpec] = {}
    out_raw = s.get("outputs", {})
    if not isinstance(out_raw, dict):
        raise SceneError(f"need a table; got {_tname(out_raw)}", key=f"{key}.outputs")
    for k, v in out_raw.items():
        spec = parse_output(model, k, v, f"{key}.outputs.{k}")
        if spec is not None:
            outputs[k] = spec
    study = Study(name, model, key, combine, label, points, outputs, swept)
    if label is not None and points:
        study.label_for(points[0])
    # evaluate every grid now so that a bad expression is reported by `gecko validate`
    for spec in outputs.values():
        if spec.options.get("grid") is not None:
            for p in points:
                gkey = f"{key}.outputs.{spec.name}.{spec.options['grid_key']}"
                g = eval_grid(spec.options["grid"], study.env(p), gkey, res)
                if len(points) * g.size > MAX_STUDY_EVALUATIONS:
                    raise SceneError(f"{len(points)} designs x {g.size} grid points is out of range: need at "
                                     f"most {MAX_STUDY_EVALUATIONS} evaluations per output (use a [sweep] "
                                     "section for larger runs)", key=gkey)
                _check_grid_values(study, spec.name, g, p, gkey)
    if "contact_contours" in outputs:  # two grids (Fn, Ft): evaluated here for the same reasons
        spec = outputs["contact_contours"]
        for p in points:
            gn = eval_grid(spec.options["Fn"], study.env(p), f"{key}.outputs.contact_contours.Fn", res)
            gt = eval_grid(spec.options["Ft"], study.env(p), f"{key}.outputs.contact_contours.Ft", res)
            if len(points) * gn.size * gt.size > MAX_STUDY_EVALUATIONS:
                raise SceneError(f"{len(points)} designs x {gn.size} x {gt.size} loads is out of range: need at most "
                                 f"{MAX_STUDY_EVALUATIONS} evaluations per output", key=f"{key}.outputs.contact_contours")
            _check_grid_values(study, "contact_contours", gn, p, f"{key}.outputs.contact_contours.Fn")
            _check_grid_values(study, "contact_contours_ft", gt, p, f"{key}.outputs.contact_contours.Ft")
    return study


def _check_grid_values(study: Study, output: str, g: np.ndarray, p: Point, key: str) -> None:
    if not np.all(np.isfinite(g)):
        raise SceneError("grid values must be finite", key=key)
    if output == "forces" and np.any(g < 0):
        raise SceneError(f"velocity {g.min():g} is out of range: need V >= 0", key=key)
    env = study.env(p)
    if output in ("critical_line", "shapes", "sensitivities", "contact_contours_ft") and "ft_max" in env:
        bad = g[np.abs(g) > env["ft_max"] * (1 + 1e-12)]
        if bad.size:
            raise SceneError(f"Ft = {bad[0]:g} is out of range: need |Ft| <= (Ft)max = sqrt(2 EA w) = "
                             f"{env['ft_max']:g} for this design", key=key)


def _expand(model: Model, params: dict, variables: dict, combine: str, key: str, res: float,
            base_dir: Optional[str] = None):
    """All designs of a study: sweeps (zip or cross), then expressions, then range checks."""
    sweeps: Dict[str, list] = {}
    fixed: Dict[str, Any] = {}
    exprs: Dict[str, str] = {}
    sources = [("variables", n, v) for n, v in variables.items()] + [("parameters", n, v) for n, v in params.items()]
    for section, n, v in sources:
        k = f"{key}.{section}.{n}"
        p = model.param(n)
        kind = p.kind if p else "float"
        if kind == "float":
            if _is_sweep(v):
                vals = eval_grid(v, {}, k, res) if not isinstance(v, list) else None
                if vals is None:
                    vals = [_sweep_entry(x, f"{k}[{i}]") for i, x in enumerate(v)]
                    if not vals:
                        raise SceneError("an empty sweep; need at least one value", key=k)
                sweeps[n] = [float(x) if not isinstance(x, str) else x for x in vals]
            elif isinstance(v, str):
                exprs[n] = v
                expr.names_in(v, k)
            elif isinstance(v, bool) or not isinstance(v, (int, float)):
                raise SceneError(f"need a number, an expression string, a list (sweep) or a range table; got {_tname(v)}", key=k)
            else:
                fixed[n] = float(v)
        elif kind == "choice":
            if isinstance(v, list):
                for i, x in enumerate(v):
                    _check_choice(p, x, f"{k}[{i}]")
                sweeps[n] = list(v)
            else:
                fixed[n] = _check_choice(p, v, k)
        elif kind == "matrix":
            if isinstance(v, dict):
                _check_keys(v, ["values"], k)
                vals = v.get("values")
                if not isinstance(vals, list) or not vals:
                    raise SceneError("need {values = [K1, K2, ...]} with 2x2 matrices", key=k)
                sweeps[n] = [_matrix(x, f"{k}.values[{i}]") for i, x in enumerate(vals)]
            else:
                fixed[n] = _matrix(v, k)
        elif kind == "path":
            fixed[n] = _path(v, k)
        elif kind in ("law", "data"):  # gecko.scene.sliding_fit
            from .sliding_fit import parse_data, parse_law
            fixed[n] = parse_law(v, k) if kind == "law" else parse_data(v, k, base_dir)
    names = list(sweeps)
    if combine == "zip" and names:
        lens = {n: len(sweeps[n]) for n in names}
        if len(set(lens.values())) > 1:
            raise SceneError("combine = 'zip' needs sweeps of equal length; got "
                             + ", ".join(f"{n}: {m}" for n, m in lens.items()), key=f"{key}.combine")
        combos = list(zip(*(sweeps[n] for n in names)))
    else:
        total = math.prod(len(sweeps[n]) for n in names)
        if total > MAX_STUDY_DESIGNS:
            raise SceneError(f"the sweeps combine into {total} designs, which is out of range: need at "
                             f"most {MAX_STUDY_DESIGNS} per study (use combine = 'zip', fewer points, "
                             "or a [sweep] section)", key=f"{key}.parameters")
        combos = list(itertools.product(*(sweeps[n] for n in names)))
    points = []
    for idx, combo in enumerate(combos):
        vals = dict(fixed)
        swept = dict(zip(names, combo))
        sw_exprs = {n: v for n, v in swept.items() if isinstance(v, str)}
        vals.update({n: v for n, v in swept.items() if not isinstance(v, str)})
        pending = dict(exprs)
        pending.update(sw_exprs)
        for p in model.params:
            if p.name not in vals and p.name not in pending and p.kind in ("float", "choice", "matrix", "path",
                                                                            "law", "data"):
                if p.default is not None or p.kind != "float":
                    vals[p.name] = p.default
                else:
                    vals[p.name] = None
        _resolve(pending, vals, model, key)
        for n in list(swept):
            swept[n] = vals[n]
        _defaults_from_preset(model, vals)
        for p in model.params:
            v = vals.get(p.name)
            section = "parameters"
            if p.check is not None and v is not None:
                why = p.check(v)
                if why:
                    where = f" (design {idx + 1} of the sweep: " + _design_text(swept) + ")" if swept else ""
                    raise SceneError(f"{p.name} = {_fmt(p.name, v)} is out of range: {why}{where}",
                                     key=f"{key}.{section}.{p.name}")
        if p_err := _cross_check(model, vals):
            where = (" (design " + _design_text(swept) + ")") if swept else ""
            raise SceneError(p_err + where, key=f"{key}.parameters")
        points.append(Point(idx, vals, swept, frozenset(p.name for p in model.params)))
    return points, names


def _design_text(swept: dict) -> str:
    return ", ".join(f"{n} = {_fmt(n, v)}" for n, v in swept.items())


def _sweep_entry(x, key):
    if isinstance(x, bool) or not isinstance(x, (int, float, str)):
        raise SceneError(f"need a number or an expression string; got {_tname(x)}", key=key)
    if isinstance(x, str):
        expr.names_in(x, key)
    return x


def _check_choice(p: Param, v, key: str) -> str:
    if v not in p.choices:
        raise SceneError(f"{v!r} is not allowed; allowed values: " + ", ".join(map(repr, p.choices)), key=key)
    return v


def _matrix(v, key: str):
    ok = (isinstance(v, list) and len(v) == 2 and all(isinstance(r, list) and len(r) == 2 for r in v)
          and all(isinstance(x, (int, float, str)) and not isinstance(x, bool) for r in v for x in r))
    if not ok:
        raise SceneError("need a 2x2 matrix [[a, b], [c, d]] of numbers", key=key)
    m = tuple(tuple(_number(x, f"{key}[{i}][{j}]", {}) for j, x in enumerate(r)) for i, r in enumerate(v))
    if not all(math.isfinite(x) for r in m for x in r):
        raise SceneError("the matrix entries must be finite", key=key)
    if m[0][1] != m[1][0] or not (m[0][0] > 0 and m[1][1] > 0 and m[0][0] * m[1][1] - m[0][1] ** 2 > 0):
        raise SceneError(f"{[list(r) for r in m]} is out of range: a rigidity matrix must be symmetric "
                         "positive definite", key=key)
    return m


def _path(v, key: str):
    from ..friction import FIG4_SPATULA_PATH, FIG8_SETA_PATH, DisplacementPath
    if isinstance(v, str):
        presets = {"fig4": FIG4_SPATULA_PATH, "fig8": FIG8_SETA_PATH}
        if v not in presets:
            raise SceneError(f"{v!r} is not allowed; allowed: 'fig4', 'fig8' or a table {{t, d_par, d_perp}}", key=key)
        return presets[v]
    if not isinstance(v, dict):
        raise SceneError(f"need 'fig4', 'fig8' or a table {{t, d_par, d_perp}}; got {_tname(v)}", key=key)
    _check_keys(v, ["t", "d_par", "d_perp"], key)
    cols = []
    for c in ("t", "d_par", "d_perp"):
        if c not in v:
            raise SceneError(f"missing key {c!r}", key=key)
        col = v[c]
        if not isinstance(col, list) or len(col) < 2:
            raise SceneError("need a list of at least two numbers", key=f"{key}.{c}")
        cols.append(tuple(_number(x, f"{key}.{c}[{i}]", {}) for i, x in enumerate(col)))
    if len({len(c) for c in cols}) != 1:
        raise SceneError("t, d_par and d_perp must have the same length", key=key)
    if any(b <= a for a, b in zip(cols[0], cols[0][1:])) or not all(math.isfinite(x) for c in cols for x in c):
        raise SceneError("t must be finite and strictly increasing", key=f"{key}.t")
    return DisplacementPath(*cols)


def _resolve(pending: Dict[str, str], vals: Dict[str, Any], model: Model, key: str) -> None:
    """Evaluate expression-valued names in dependency order (a cycle is an error)."""
    while pending:
        progressed = False
        for n, text in list(pending.items()):
            section = "parameters" if model.param(n) else "variables"
            deps = expr.names_in(text, f"{key}.{section}.{n}")
            if deps & set(pending):
                continue
            env = {k: v for k, v in vals.items() if isinstance(v, float)}
            known = set(env) | {p.name for p in model.params}
            vals[n] = expr.evaluate(text, env, f"{key}.{section}.{n}", allowed=known)
            del pending[n]
            progressed = True
        if not progressed:
            raise SceneError("expressions refer to each other in a cycle: " + ", ".join(sorted(pending)),
                             key=f"{key}.parameters")


def _defaults_from_preset(model: Model, vals: Dict[str, Any]) -> None:
    if model.param("preset") is None:  # steady_sliding and the models sharing its parameters
        return
    from ..friction import FIG6_PLASTIC, FIG6_VISCOELASTIC, EyringDetachment
    preset = FIG6_VISCOELASTIC if vals.get("preset", "viscoelastic") == "viscoelastic" else FIG6_PLASTIC
    law = preset.law
    base = {"N": preset.N, "K": tuple(map(tuple, preset.K)), "f_par1": preset.f_par1,
            "f_perp1": preset.f_perp1,
            "law": "eyring" if isinstance(law, EyringDetachment) else "viscoelastic",
            "G0": law.G0, "V_star": law.V_star, "n": getattr(law, "n", 1.0)}
    for k, v in base.items():
        if vals.get(k) is None:
            vals[k] = float(v) if isinstance(v, (int, float)) else v


def _cross_check(model: Model, v: Dict[str, Any]) -> Optional[str]:
    """Checks across parameters, worded like the kernels' own errors."""
    if model.name == "two_level_seta":
        if v["alpha1"] + v["alpha2"] >= math.pi / 2:
            return (f"alpha1 + alpha2 = {_fmt('alpha1', v['alpha1'] + v['alpha2'])} is out of range: "
                    "need alpha1 + alpha2 < pi/2")
        from ..seta import TwoLevelSeta
        try:
            TwoLevelSeta(**{p.name: v[p.name] for p in model.params})
        except ValueError as exc:
            return str(exc)
    return None


def _parse_plot(p, key: str, studies: List[Study]) -> PlotSpec:
    if not isinstance(p, dict):
        raise SceneError(f"need a table; got {_tname(p)}", key=key)
    _check_keys(p, PLOT_KEYS, key)
    kind = p.get("kind")
    if kind not in PLOT_KINDS:
        raise SceneError(f"{'missing key kind' if kind is None else repr(kind) + ' is not allowed'}; "
                         "allowed kinds: " + ", ".join(PLOT_KINDS), key=f"{key}.kind")
    name = p.get("name", kind)
    if not isinstance(name, str) or not name or not all(c.isalnum() or c in "-_." for c in name) or name[0] == ".":
        raise SceneError(f"{name!r} is not allowed: need a file-name stem of letters, digits, '-', '_', '.'",
                         key=f"{key}.name")
    from .limits import check_name
    check_name(name, f"{key}.name", "plot name")
    wanted = PLOT_KINDS[kind]
    names = p.get("studies")
    if names is None:
        chosen = [s for s in studies if any(o in s.model.outputs for o in wanted)]
        if not chosen:
            raise SceneError(f"no study can give what a {kind!r} plot draws ({' or '.join(wanted)}); "
                             "models that can: " + ", ".join(m for m, M in MODELS.items()
                                                            if any(o in M.outputs for o in wanted)), key=key)
    else:
        if not (isinstance(names, list) and names and all(isinstance(n, str) for n in names)):
            raise SceneError("need a non-empty list of study names", key=f"{key}.studies")
        by = {s.name: s for s in studies}
        chosen = []
        for i, n in enumerate(names):
            if n not in by:
                raise SceneError(f"unknown study {n!r}; studies in this scene: " + ", ".join(by), key=f"{key}.studies[{i}]")
            if not any(o in by[n].model.outputs for o in wanted):
                raise SceneError(f"study {n!r} (model {by[n].model.name!r}) cannot give "
                                 f"{' or '.join(wanted)} for a {kind!r} plot", key=f"{key}.studies[{i}]")
            chosen.append(by[n])
    spec = PlotSpec(name, kind, key, [s.name for s in chosen])
    # plots are requests: switch on the outputs they draw (with default settings) when absent
    for s in chosen:
        if not any(o in s.outputs for o in wanted):
            out = wanted[0] if wanted[0] in s.model.outputs else wanted[-1]
            # a characteristic plot asks only for its y quantities (checked below), not for all
            request = [] if kind == "characteristic" else True
            s.outputs[out] = (OutputSpec(out, {"which": request}) if kind == "characteristic"
                              else parse_output(s.model, out, request, f"{s.key}.outputs.{out}"))
    if kind == "characteristic":
        x = p.get("x")
        y = p.get("y")
        if not isinstance(x, str):
            raise SceneError("a characteristic plot needs x = the swept name on the horizontal axis", key=f"{key}.x")
        if isinstance(y, str):
            y = [y]
        if not (isinstance(y, list) and y and all(isinstance(v, str) for v in y)):
            raise SceneError("need y = a characteristic name or a list of them: " + ", ".join(CHARACTERISTIC_LABELS),
                             key=f"{key}.y")
        for s in chosen:
            if x not in s.swept_names:
                raise SceneError(f"x = {x!r} is not swept in study {s.name!r}; swept there: "
                                 + (", ".join(s.swept_names) or "nothing"), key=f"{key}.x")
            for i, yy in enumerate(y):
                if yy not in s.model.characteristics:
                    raise SceneError(f"unknown characteristic {yy!r} for model {s.model.name!r}; allowed: "
                                     + ", ".join(s.model.characteristics), key=f"{key}.y[{i}]")
            have = s.outputs["characteristics"].options["which"]
            for yy in y:
                if yy not in have:
                    have.append(yy)
        spec.x, spec.y = x, list(y)
        warn_renamed(y, f"scene {key}.y")
    elif "x" in p or "y" in p:
        raise SceneError(f"x and y are only for 'characteristic' plots; a {kind!r} plot draws fixed quantities",
                         key=key)
    opts: Dict[str, Any] = {}
    for lim in ("xlim", "ylim"):
        if lim in p:
            v = p[lim]
            if not (isinstance(v, list) and len(v) == 2):
                raise SceneError("need [min, max]", key=f"{key}.{lim}")
            lo, hi = (_number(x, f"{key}.{lim}[{i}]", {}) for i, x in enumerate(v))
            if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
                raise SceneError(f"[{lo:g}, {hi:g}] is out of range: need finite min < max", key=f"{key}.{lim}")
            opts[lim] = (lo, hi)
    for sc in ("xscale", "yscale"):
        if sc in p:
            if p[sc] not in ("linear", "log"):
                raise SceneError(f"{p[sc]!r} is not allowed; allowed: 'linear', 'log'", key=f"{key}.{sc}")
            opts[sc] = p[sc]
    for t in ("title", "xlabel", "ylabel"):
        if t in p:
            if not isinstance(p[t], str):
                raise SceneError(f"need a string; got {_tname(p[t])}", key=f"{key}.{t}")
            opts[t] = p[t]
    if "legend" in p:
        v = p["legend"]
        if not isinstance(v, (bool, str)):
            raise SceneError("need true, false or a matplotlib location such as 'lower left'", key=f"{key}.legend")
        opts["legend"] = v
    if "arrows" in p:
        if not isinstance(p["arrows"], bool):
            raise SceneError("need true or false", key=f"{key}.arrows")
        opts["arrows"] = p["arrows"]
    if "size" in p:
        v = p["size"]
        if not (isinstance(v, list) and len(v) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                           and 0.5 <= x <= 40 for x in v)):
            raise SceneError("need [width, height] in inches, each in [0.5, 40]", key=f"{key}.size")
        opts["size"] = (float(v[0]), float(v[1]))
    formats = p.get("formats", ["png"])
    if isinstance(formats, str):
        formats = [formats]
    if not (isinstance(formats, list) and formats and all(f in FORMATS for f in formats)):
        raise SceneError(f"{formats!r} is not allowed; need a list from: " + ", ".join(FORMATS), key=f"{key}.formats")
    spec.options = opts
    spec.formats = list(dict.fromkeys(formats))
    return spec
