"""What each scene model takes (parameters with the papers' defaults) and can give (outputs).

A model declares its parameters (:class:`Param`: default, kind, allowed range) and its outputs
(name -> parser of the output's table). Nothing here computes: the planner decides which kernels
run, the runner runs them. Defaults are the papers' reference values (docs/theory/two_level_seta.md reference
scene; §2 Figs 4, 6, 8).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Optional, Sequence, Tuple

from .._renamed import RENAMED, warn_renamed
from .errors import SceneError

# ---- parameter kinds and range checks ----------------------------------------------------------


def _positive(v):
    return None if v > 0 and v < math.inf else "need 0 < value < inf"


def _positive_or_inf(v):
    return None if v > 0 else "need 0 < value <= inf (inf: inextensible)"


def _nonnegative(v):
    return None if 0 <= v < math.inf else "need 0 <= value < inf"


def _finite(v):
    return None if math.isfinite(v) else "need a finite number"


def _open_right_angle(v):
    return None if 0 < v < math.pi / 2 else "need 0 < value < pi/2 (radians; write e.g. \"pi/6\" or \"deg(30)\")"


def _half_open_right_angle(v):
    return None if 0 <= v < math.pi / 2 else "need 0 <= value < pi/2 (radians; write e.g. \"pi/6\" or \"deg(30)\")"


@dataclass(frozen=True)
class Param:
    """One model parameter: ``kind`` is "float", "choice", "matrix" (2x2) or "path"."""

    name: str
    default: Any
    doc: str
    kind: str = "float"
    check: Optional[Callable[[float], Optional[str]]] = None
    choices: Tuple[str, ...] = ()
    symbol: str = ""  # how a legend writes it, e.g. "EA₂/w"


@dataclass(frozen=True)
class Model:
    name: str
    title: str
    params: Tuple[Param, ...]
    outputs: Tuple[str, ...]
    doc: str
    characteristics: Tuple[str, ...] = ()

    def param(self, name: str) -> Optional[Param]:
        for p in self.params:
            if p.name == name:
                return p
        return None


PI6 = math.pi / 6

def _seta_check(name: str):
    """The scene's range check of a design field, from its admissible range in C++."""
    from ..seta import SetaDesign
    lo, hi, lo_incl, inf_ok, _ = SetaDesign.domain[name]
    if inf_ok:
        return _positive_or_inf
    if hi == math.inf:
        return _nonnegative if lo_incl else _positive
    return _half_open_right_angle if lo_incl else _open_right_angle


def _unicode_symbol(name: str) -> str:
    """How a legend writes a design field: EI1 -> EI₁, alpha2 -> α₂."""
    sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
    return name.replace("alpha", "α").translate(sub)


def _seta_params() -> Tuple[Param, ...]:
    from ..designs import DEFAULTS, FIELDS
    from ..seta import SetaDesign
    return tuple(Param(f, DEFAULTS[f], SetaDesign.descriptions[f], check=_seta_check(f),
                       symbol=_unicode_symbol(f)) for f in FIELDS)


#: the two-level seta's parameters: the bound C++ design type's fields, defaults, ranges and texts
SETA_PARAMS = _seta_params()

#: characteristic quantities of the two-level seta; "small_*" are the linear theory (eqs 7, 18-22).
#: Two slopes (issue 13, docs/theory/two_level_seta.md): slope_at_zero, the tangent dFn/dFt at Ft = 0,
#: and paper_k, the paper's k of eq (16) (least squares over the lower part of the line).
SETA_EXACT = ("fn0", "slope_at_zero", "abs_slope_at_zero", "inv_abs_slope_at_zero", "paper_k", "abs_paper_k",
              "inv_abs_paper_k", "max_pull_off", "ft_at_max_pull_off", "min_fn", "ft_max", "sticky_at_rest",
              "ft_at_line_end", "fn_at_line_end") + tuple(RENAMED)  # the deprecated aliases last
SETA_SMALL = ("small_fn0", "small_slope_k", "small_abs_slope_k", "small_inv_abs_k", "small_contact_length",
              "small_non_sticky")

CHARACTERISTIC_LABELS = {
    "fn0": "$(\\bar F_n)_0$",
    "small_fn0": "$(\\bar F_n)_0$, small deformation (eq 19)",
    "slope_at_zero": "slope $d\\bar F_n/d\\bar F_t$ at $\\bar F_t = 0$",
    "paper_k": "paper's slope $k$ (eq 16)",
    "small_slope_k": "slope $k$, small deformation (eq 18)",
    # The paper's plots have Fn horizontal and show "1/|k|" (Fig 5b); the figure scene draws |dFn/dFt|
    # at Ft = 0 there (docs/theory/two_level_seta.md, "The slope k").
    "abs_slope_at_zero": "$|d\\bar F_n/d\\bar F_t|$ at $\\bar F_t = 0$ (the paper's $1/|k|$)",
    "abs_paper_k": "$|k|$, the paper's slope (eq 16)",
    "small_abs_slope_k": "$|d\\bar F_n/d\\bar F_t|$, small deformation (eq 21)",
    "inv_abs_slope_at_zero": "$1/|d\\bar F_n/d\\bar F_t|$ at $\\bar F_t = 0$",
    "inv_abs_paper_k": "$1/|k|$, the paper's slope (eq 16)",
    "small_inv_abs_k": "$1/|d\\bar F_n/d\\bar F_t|$, small deformation",
    "max_pull_off": "max pull-off $|\\bar F_n|$",
    "ft_at_max_pull_off": "$\\bar F_t$ at max pull-off",
    "min_fn": "min $\\bar F_n$",
    "ft_max": "$(\\bar F_t)_{max}$",
    "sticky_at_rest": "sticky at rest",
    "ft_at_line_end": "$\\bar F_t$ at line end",
    "fn_at_line_end": "$\\bar F_n$ at line end",
    "small_contact_length": "contact length $l_c$ (eq 7)",
    "small_non_sticky": "non-sticky at rest (eq 22)",
}
# the deprecated aliases are labelled as what they are now called (one text per quantity)
CHARACTERISTIC_LABELS.update({old: CHARACTERISTIC_LABELS[new] for old, new in RENAMED.items()})

DEFAULT_K = ((5.0, -3.0), (-3.0, 2.0))

#: default load grid of the contact_contours output (Fn x Ft)
CONTACT_GRID_FN = {"range": [-4.0, 2.0], "num": 121}
CONTACT_GRID_FT = {"range": [0.0, "0.99*ft_end"], "num": 100}

MODELS: Dict[str, Model] = {}

#: output name -> parser(model, name, value, key) of its table, for outputs declared outside this
#: module (models registered by other modules, e.g. gecko.scene.hierarchy)
OUTPUT_PARSERS: Dict[str, Callable[..., Optional["OutputSpec"]]] = {}


def _add(m: Model) -> None:
    MODELS[m.name] = m


_add(Model(
    "two_level_seta", "two-level seta", SETA_PARAMS,
    ("critical_line", "characteristics", "shapes", "sensitivities", "linear_line", "contact_contours", "csv"),
    "Two-level seta of directional adhesion (docs/theory/two_level_seta.md); defaults: the paper's reference scene.",
    characteristics=SETA_EXACT + SETA_SMALL))
_add(Model(
    "single_fiber", "single-level fiber",
    (Param("EI", 0.5, "bending stiffness", check=_positive, symbol="EI"),
     Param("EA", 50.0, "axial stiffness (inf: inextensible)", check=_positive_or_inf, symbol="EA"),
     Param("l", 1.0, "length", check=_positive, symbol="l"),
     Param("alpha", math.pi / 3, "base angle from the substrate normal", check=_open_right_angle, symbol="α"),
     Param("w", 1.0, "work of adhesion", check=_positive, symbol="w")),
    ("critical_line", "characteristics", "csv"),
    "Single-level fiber of He et al. 2013 (docs/theory/two_level_seta.md, Fig 4).", characteristics=("fn0",)))
_add(Model(
    "kendall", "Kendall model",
    (Param("EA", 50.0, "axial stiffness of the film (inf: Rivlin)", check=_positive_or_inf, symbol="EA/w"),
     Param("w", 1.0, "work of adhesion", check=_positive, symbol="w")),
    ("critical_line", "characteristics", "csv"),
    "Kendall's peel line of an extensible film (eq 17).",
    characteristics=("fn0", "max_pull_off", "ft_at_max_pull_off", "ft_max")))
_add(Model(
    "rivlin", "Rivlin model",
    (Param("w", 1.0, "work of adhesion", check=_positive, symbol="w"),),
    ("critical_line", "characteristics", "csv"),
    "Rivlin's peel line of an inextensible film (eq 17).", characteristics=("fn0",)))
_add(Model(
    "spatula", "spatula (curved beam)",
    (Param("K", DEFAULT_K, "rigidity matrix [[K_par_par, K_par_perp], [K_perp_par, K_perp_perp]]",
           kind="matrix", symbol="K"),
     Param("path", "fig4", "displacement path: \"fig4\", \"fig8\" or a table {t, d_par, d_perp}",
           kind="path", symbol="path")),
    ("force_trace", "csv"),
    "Spatula force trace f = K d(t) along a displacement path (paper 000 eqs 1-3, Fig 4)."))
_add(Model(
    "seta_force_space", "seta force space",
    (Param("K", DEFAULT_K, "rigidity matrix of the seta", kind="matrix", symbol="K"),
     Param("path", "fig8", "displacement path: \"fig4\", \"fig8\" or a table {t, d_par, d_perp}",
           kind="path", symbol="path")),
    ("force_trace", "csv"),
    "Seta force space F = K_seta D along load-drag-pull (paper 000 eqs 11-13, Fig 8)."))
_add(Model(
    "steady_sliding", "steady sliding",
    (Param("preset", "viscoelastic", "Fig 6 fit the other parameters default to", kind="choice",
           choices=("viscoelastic", "plastic"), symbol="model"),
     Param("N", None, "number of spatulae", check=_positive, symbol="N"),
     Param("K", None, "rigidity matrix of one spatula (N/m)", kind="matrix", symbol="K"),
     Param("f_par1", None, "lateral force just after re-sticking (N)", check=_finite, symbol="f∥,1"),
     Param("f_perp1", None, "normal force just after re-sticking (N)", check=_finite, symbol="f⊥,1"),
     Param("law", None, "detachment law: \"viscoelastic\", \"eyring\" or {G = \"expression in V\", parameters = {...}}",
           kind="law", symbol="law"),
     Param("G0", None, "detachment energy scale (J)", check=_positive, symbol="G₀"),
     Param("V_star", None, "velocity scale V* (m/s)", check=_positive, symbol="V*"),
     Param("n", None, "exponent of the viscoelastic law", check=_positive, symbol="n"),
     Param("t_off", 0.0, "re-sticking time (s)", check=_nonnegative, symbol="t_off")),
    ("forces", "csv"),
    "Steady sliding of N spatulae (paper 000 eqs 5-10, Fig 6); SI units."))


# ---- output tables ------------------------------------------------------------------------------

GRID_FORMS = "a list of numbers, {range = [start, stop], num = N}, {logrange = [start, stop], num = N} or {values = [...]}"


@dataclass
class OutputSpec:
    """A parsed output request. ``options`` holds the (still symbolic) grids and settings."""

    name: str
    options: Dict[str, Any] = field(default_factory=dict)


def _check_keys(table: dict, allowed: Sequence[str], key: str) -> None:
    for k in table:
        if k not in allowed:
            raise SceneError(f"unknown key {k!r}; allowed keys: " + ", ".join(allowed),
                             key=f"{key}.{k}" if key else k)


def _bool_or_table(value, key: str, allowed: Sequence[str]) -> Optional[dict]:
    if isinstance(value, bool):
        return {} if value else None
    if isinstance(value, dict):
        _check_keys(value, allowed, key)
        return dict(value)
    raise SceneError(f"need true, false or a table with keys {', '.join(allowed)}; got {_tname(value)}",
                     key=key)


def _tname(v) -> str:
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string", list: "a list",
            dict: "a table"}.get(type(v), type(v).__name__)


def _int_in(value, key: str, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise SceneError(f"need an integer in [{lo}, {hi}]; got {_tname(value)}", key=key)
    if not lo <= value <= hi:
        raise SceneError(f"{value} is out of range: need an integer in [{lo}, {hi}]", key=key)
    return value


def parse_output(model: Model, name: str, value, key: str) -> Optional[OutputSpec]:
    """Validate one entry of a study's ``outputs`` table; None when switched off (false)."""
    if name not in model.outputs:
        raise SceneError(f"unknown output {name!r} for model {model.name!r}; allowed: "
                         + ", ".join(model.outputs), key=key)
    if name == "csv":
        if not isinstance(value, bool):
            raise SceneError(f"need true or false; got {_tname(value)}", key=key)
        return OutputSpec("csv") if value else None
    if name == "characteristics":
        if isinstance(value, bool):
            # true: every characteristic under its own name, not the deprecated aliases as well
            return OutputSpec(name, {"which": [c for c in model.characteristics if c not in RENAMED]}) if value else None
        if isinstance(value, list) and all(isinstance(v, str) for v in value) and value:
            for i, v in enumerate(value):
                if v not in model.characteristics:
                    raise SceneError(f"unknown characteristic {v!r}; allowed: " + ", ".join(model.characteristics),
                                     key=f"{key}[{i}]")
            warn_renamed(value, f"scene {key}")
            return OutputSpec(name, {"which": list(dict.fromkeys(value))})
        raise SceneError("need true, false or a non-empty list of names from: " + ", ".join(model.characteristics),
                         key=key)
    grid_key = {"critical_line": "Ft", "linear_line": "Ft", "sensitivities": "Ft", "forces": "V"}
    if name in grid_key:
        allowed = [grid_key[name]] + (["wrt"] if name == "sensitivities" else [])
        table = _bool_or_table(value, key, allowed)
        if table is None:
            return None
        opts: Dict[str, Any] = {"grid": table.get(grid_key[name]), "grid_key": grid_key[name]}
        if opts["grid"] is not None:
            check_grid(opts["grid"], f"{key}.{grid_key[name]}")
        if name == "sensitivities":
            names = [p.name for p in model.params]
            wrt = table.get("wrt", names)
            if not (isinstance(wrt, list) and wrt and all(isinstance(v, str) for v in wrt)):
                raise SceneError("need a non-empty list of parameter names from: " + ", ".join(names),
                                 key=f"{key}.wrt")
            for i, v in enumerate(wrt):
                if v not in names:
                    raise SceneError(f"unknown parameter {v!r}; allowed: " + ", ".join(names), key=f"{key}.wrt[{i}]")
            opts["wrt"] = list(wrt)
        return OutputSpec(name, opts)
    if name == "shapes":
        table = _bool_or_table(value, key, ["Ft", "points"])
        if table is None:
            return None
        ft = table.get("Ft", [0.0, "0.5*ft_end", "0.9*ft_end"])
        check_grid(ft, f"{key}.Ft")
        pts = _int_in(table.get("points", 101), f"{key}.points", 3, 100000)
        return OutputSpec(name, {"grid": ft, "points": pts, "grid_key": "Ft"})
    if name == "contact_contours":
        # The forward problem on a grid of loads: a (non-contact length) at every (Fn, Ft).
        table = _bool_or_table(value, key, ["Fn", "Ft", "levels"])
        if table is None:
            return None
        fn = table.get("Fn", CONTACT_GRID_FN)
        ft = table.get("Ft", CONTACT_GRID_FT)
        check_grid(fn, f"{key}.Fn")
        check_grid(ft, f"{key}.Ft")
        levels = table.get("levels", 9)
        if isinstance(levels, list):
            if not levels or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                                     for v in levels):
                raise SceneError("need a list of finite numbers (values of a/l1) or an integer", key=f"{key}.levels")
            levels = sorted(float(v) for v in levels)
        else:
            levels = _int_in(levels, f"{key}.levels", 1, 50)
        return OutputSpec(name, {"Fn": fn, "Ft": ft, "levels": levels})
    if name == "fit":
        from .sliding_fit import parse_fit_output
        opts = parse_fit_output(value, key)
        return None if opts is None else OutputSpec(name, opts)
    if name == "force_trace":
        table = _bool_or_table(value, key, ["samples_per_segment"])
        if table is None:
            return None
        sps = _int_in(table.get("samples_per_segment", 50), f"{key}.samples_per_segment", 1, 10**6)
        return OutputSpec(name, {"samples_per_segment": sps})
    if name in OUTPUT_PARSERS:
        return OUTPUT_PARSERS[name](model, name, value, key)
    raise SceneError(f"output {name!r} is not handled", key=key)  # pragma: no cover


def check_grid(spec, key: str) -> None:
    """Shape check of a grid (values are checked when evaluated per design)."""
    if isinstance(spec, list):
        if not spec:
            raise SceneError("need at least one value; allowed forms: " + GRID_FORMS, key=key)
        for i, v in enumerate(spec):
            if isinstance(v, bool) or not isinstance(v, (int, float, str)):
                raise SceneError(f"need a number or an expression string; got {_tname(v)}", key=f"{key}[{i}]")
        return
    if isinstance(spec, dict):
        forms = [k for k in ("range", "logrange", "values") if k in spec]
        if len(forms) != 1:
            raise SceneError("need exactly one of range, logrange, values; allowed forms: " + GRID_FORMS, key=key)
        _check_keys(spec, [forms[0], "num"] if forms[0] != "values" else ["values"], key)
        if forms[0] == "values":
            check_grid(spec["values"], f"{key}.values")
            return
        bounds = spec[forms[0]]
        if not (isinstance(bounds, list) and len(bounds) == 2):
            raise SceneError("need [start, stop]", key=f"{key}.{forms[0]}")
        check_grid(bounds, f"{key}.{forms[0]}")
        if "num" not in spec:
            raise SceneError("missing key 'num' (number of points, an integer >= 2)", key=key)
        _int_in(spec["num"], f"{key}.num", 2, 10**7)
        return
    raise SceneError(f"need {GRID_FORMS}; got {_tname(spec)}", key=key)


# ---- frictional adhesion fitted to measured data (gecko.scene.sliding_fit) -----------------------

_add(Model(
    "sliding_fit", "steady sliding fitted to data",
    (Param("data", None, "CSV file of measured V, F_par, F_perp [, sigma_par, sigma_perp] (SI)",
           kind="data", symbol="data"),)
    + tuple(p for p in MODELS["steady_sliding"].params if p.name != "t_off"),
    ("fit", "csv"),
    "Eqs 9-10 of paper 000 fitted to measured steady-sliding forces (gecko.fit_steady_sliding); "
    "the other parameters are the start of the fit."))
