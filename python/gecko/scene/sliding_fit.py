"""Scenes of frictional adhesion beyond the paper's two laws: a detachment law given by name or as
an expression, and the ``sliding_fit`` model (measured (V, F_par, F_perp) read from a CSV file and
fitted by eqs 9-10 of paper 000 with :func:`gecko.fit_steady_sliding`).

A law in a scene::

    law = "viscoelastic"                   # or "eyring": the built-in laws (eqs 7, 8)
    law = { G = "G0 * (1 + (V/V0)**n)", parameters = { G0 = 3e-14, V0 = 1e-4, n = { start = 0.45, bounds = [0, 2] } } }

The expression is read by :mod:`gecko.scene.expr` (numbers, names, + - * / ** and a whitelist of
numpy functions; nothing else runs); ``V`` is the velocity, every other name is a parameter with
its value (the start of a fit). A parameter is fitted as a logarithm when ``positive`` (default:
its start is > 0).

Measured data::

    data = "sliding_data.csv"              # columns V, F_par, F_perp [, sigma_par, sigma_perp]

relative to the scene file; SI units (m/s, N).
"""
from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np

from . import expr
from .errors import SceneError

BUILTIN_LAWS = ("viscoelastic", "eyring")
DATA_COLUMNS = ("V", "F_par", "F_perp")
SIGMA_COLUMNS = ("sigma_par", "sigma_perp")
MAX_DATA_ROWS = 100_000


def _kind(v) -> str:
    """How an error message names a TOML value's type."""
    if isinstance(v, bool):
        return "a boolean"
    return {int: "an integer", float: "a number", str: "a string", list: "a list", dict: "a table"}.get(
        type(v), type(v).__name__)


def _only(table: dict, allowed, key: str) -> None:
    """Every key of ``table`` is one of ``allowed`` (the error names the first that is not)."""
    extra = [k for k in table if k not in allowed]
    if extra:
        raise SceneError(f"unknown key {extra[0]!r}; allowed keys: " + ", ".join(allowed), key=f"{key}.{extra[0]}")


# ---- laws -----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LawExpression:
    """A detachment law G(V) written as an expression with named parameters."""

    G: str
    names: Tuple[str, ...]
    start: Tuple[float, ...]
    positive: Tuple[bool, ...]
    key: str = ""
    bounds: Tuple = ()  # (name, lower, upper) of the bounded parameters

    def __call__(self, V, **params):
        env = {"V": np.asarray(V, dtype=np.float64)}
        env.update(params)
        return np.broadcast_to(expr.evaluate_array(self.G, env, f"{self.key}.G"), np.shape(V)).copy()

    def parametric(self, values: Optional[Dict[str, float]] = None):
        """The law as a :class:`gecko.ParametricLaw` (start values unless ``values``)."""
        from ..friction import ParametricLaw
        params = dict(zip(self.names, self.start)) if values is None else dict(values)
        return ParametricLaw(self, params, tuple(n for n, p in zip(self.names, self.positive) if p),
                             {n: (lo, hi) for n, lo, hi in self.bounds} or None)

    def __repr__(self) -> str:  # shown in labels and tables
        return f"G(V) = {self.G}"


def parse_law(v, key: str):
    """A built-in law's name, or a :class:`LawExpression` from ``{G = "...", parameters = {...}}``."""
    if isinstance(v, str):
        if v not in BUILTIN_LAWS:
            raise SceneError(f"{v!r} is not allowed; allowed: " + ", ".join(map(repr, BUILTIN_LAWS))
                             + " or a table {G = \"expression in V\", parameters = {...}}", key=key)
        return v
    if not isinstance(v, dict):
        raise SceneError(f"need 'viscoelastic', 'eyring' or a table {{G, parameters}}; got {_kind(v)}", key=key)
    _only(v, ["G", "parameters"], key)
    text = v.get("G")
    if not isinstance(text, str):
        raise SceneError("need the law as an expression string in V, e.g. \"G0 * (1 + (V/V0)**n)\"",
                         key=f"{key}.G")
    names = expr.array_names(text, f"{key}.G")
    if "V" not in names:
        raise SceneError(f"the law {text!r} does not depend on the velocity V", key=f"{key}.G")
    params = v.get("parameters")
    if not isinstance(params, dict) or not params:
        raise SceneError("need a table of the law's parameters with their (start) values, e.g. "
                         "{G0 = 3e-14, V0 = 1e-4}", key=f"{key}.parameters")
    unknown = sorted(names - {"V"} - set(params))
    if unknown:
        raise SceneError(f"the law uses {', '.join(map(repr, unknown))} without a value; give each name "
                         "in G a value in parameters", key=f"{key}.parameters")
    out_names, start, positive, bounds = [], [], [], []
    for n, pv in params.items():
        k = f"{key}.parameters.{n}"
        if n == "V" or not n.isidentifier() or n in expr.CONSTANTS or n in expr.ARRAY_FUNCTIONS:
            raise SceneError(f"parameter name {n!r} is not allowed: need an identifier other than V, "
                             "a constant or a function name", key=k)
        if n not in names:
            raise SceneError(f"parameter {n!r} does not appear in G = {text!r}", key=k)
        pos = None
        box = None
        if isinstance(pv, dict):
            _only(pv, ["start", "positive", "bounds"], k)
            box = pv.get("bounds")
            pos = pv.get("positive")
            if pos is not None and not isinstance(pos, bool):
                raise SceneError(f"need true or false; got {_kind(pos)}", key=f"{k}.positive")
            if "start" not in pv:
                raise SceneError("missing key 'start' (the parameter's value)", key=k)
            pv, k = pv["start"], f"{k}.start"
        if isinstance(pv, bool) or not isinstance(pv, (int, float)) or not math.isfinite(pv):
            raise SceneError(f"need a finite number; got {pv!r}", key=k)
        if box is not None:
            bk = f"{key}.parameters.{n}.bounds"
            ok = isinstance(box, list) and len(box) == 2 and all(
                isinstance(b, (int, float)) and not isinstance(b, bool) and not math.isnan(b) for b in box)
            if not ok:
                raise SceneError("need [lower, upper], two numbers (inf or -inf for no bound on a side)", key=bk)
            lo, hi = float(box[0]), float(box[1])
            if not lo < hi or lo == math.inf or hi == -math.inf:
                raise SceneError(f"[{lo!r}, {hi!r}] is out of range: need lower < upper", key=bk)
            if not lo < pv < hi:
                raise SceneError(f"start {pv!r} is out of range: need it strictly inside the bounds "
                                 f"[{lo!r}, {hi!r}]", key=k)
            if math.isfinite(lo) or math.isfinite(hi):
                bounds.append((n, lo, hi))
                pos = False if pos is None else pos  # a bounded parameter is fitted through its bounds
        pos = (pv > 0) if pos is None else pos
        if pos and not pv > 0:
            raise SceneError(f"{pv!r} is out of range: a positive parameter (fitted as a logarithm) needs "
                             "a start > 0", key=k)
        out_names.append(n)
        start.append(float(pv))
        positive.append(bool(pos))
    law = LawExpression(text, tuple(out_names), tuple(start), tuple(positive), key, tuple(bounds))
    g = law(np.array([0.0, 1e-6, 1e-4, 1e-2]), **dict(zip(law.names, law.start)))
    if not np.all(np.isfinite(g[1:])):
        raise SceneError(f"the law {text!r} is not finite at its start values (G = {g.tolist()} at "
                         "V = 0, 1e-6, 1e-4, 1e-2 m/s)", key=f"{key}.G")
    return law


def make_law(v: Dict):
    """The detachment law of a design: built-in (from G0, V_star, n) or the expression's."""
    from ..friction import EyringDetachment, ViscoelasticDetachment
    law = v["law"]
    if isinstance(law, LawExpression):
        return law.parametric()
    if law == "viscoelastic":
        return ViscoelasticDetachment(v["G0"], v["V_star"], v["n"])
    return EyringDetachment(v["G0"], v["V_star"])


def sliding_model(v: Dict):
    from ..friction import SlidingModel
    return SlidingModel(N=v["N"], K=v["K"], f_par1=v["f_par1"], f_perp1=v["f_perp1"], law=make_law(v))


# ---- measured data --------------------------------------------------------------------------------

@dataclass(frozen=True)
class SlidingData:
    """Measured steady-sliding forces (a CSV file of a scene)."""

    path: str
    V: np.ndarray
    F_par: np.ndarray
    F_perp: np.ndarray
    sigma_par: Optional[np.ndarray] = None
    sigma_perp: Optional[np.ndarray] = None

    def __repr__(self) -> str:
        return f"SlidingData({Path(self.path).name!r}, {self.V.size} rows)"


def parse_data(v, key: str, base_dir: Optional[str]) -> SlidingData:
    """Read and check a CSV file of (V, F_par, F_perp [, sigma_par, sigma_perp]); errors name the key,
    the row and the column."""
    if not isinstance(v, str) or not v:
        raise SceneError(f"need the path of a CSV file (relative to the scene); got {_kind(v)}", key=key)
    path = Path(v)
    if not path.is_absolute():
        path = Path(base_dir or ".") / path
    try:
        text = path.read_text()
    except OSError as exc:
        raise SceneError(f"cannot read {str(path)!r}: {exc.strerror or exc}", key=key) from None
    rows = [r for r in csv.reader(io.StringIO(text)) if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise SceneError(f"{path.name}: empty; need a header row with columns "
                         + ", ".join(DATA_COLUMNS) + " (optional " + ", ".join(SIGMA_COLUMNS) + ")", key=key)
    head = [h.strip() for h in rows[0]]
    allowed = DATA_COLUMNS + SIGMA_COLUMNS
    for h in head:
        if h not in allowed:
            raise SceneError(f"{path.name}: unknown column {h!r}; allowed: " + ", ".join(allowed), key=key)
    for h in DATA_COLUMNS:
        if h not in head:
            raise SceneError(f"{path.name}: missing column {h!r}; need " + ", ".join(DATA_COLUMNS), key=key)
    if len(set(head)) != len(head):
        raise SceneError(f"{path.name}: a column appears twice in the header {head}", key=key)
    body = rows[1:]
    if len(body) > MAX_DATA_ROWS:
        raise SceneError(f"{path.name}: {len(body)} rows is out of range: need at most {MAX_DATA_ROWS}", key=key)
    cols: Dict[str, List[float]] = {h: [] for h in head}
    for i, r in enumerate(body):
        if len(r) != len(head):
            raise SceneError(f"{path.name}, row {i + 2}: {len(r)} values for {len(head)} columns", key=key)
        for h, x in zip(head, r):
            try:
                val = float(x)
            except ValueError:
                raise SceneError(f"{path.name}, row {i + 2}, column {h}: {x.strip()!r} is not a number",
                                 key=key) from None
            bad = (not math.isfinite(val) or (h == "V" and val < 0)
                   or (h in SIGMA_COLUMNS and not val > 0))
            if bad:
                need = ("0 <= V < inf" if h == "V" else "0 < sigma < inf" if h in SIGMA_COLUMNS
                        else "a finite force (N)")
                raise SceneError(f"{path.name}, row {i + 2}, column {h}: {val!r} is out of range: need {need}",
                                 key=key)
            cols[h].append(val)
    if len(body) < 3:
        raise SceneError(f"{path.name}: {len(body)} data rows; need at least 3 to fit the model", key=key)
    arr = {h: np.asarray(c, dtype=np.float64) for h, c in cols.items()}
    return SlidingData(str(path), arr["V"], arr["F_par"], arr["F_perp"], arr.get("sigma_par"),
                       arr.get("sigma_perp"))


# ---- the fit output -------------------------------------------------------------------------------

FIT_OPTIONS = ("fit_f_par1", "fit_f_perp1", "fit_coupling", "profile", "profile_level", "curve_points")


def parse_fit_output(value, key: str) -> Optional[dict]:
    """The options of a ``fit`` output (true, false or a table of FIT_OPTIONS); None when off."""
    if value is False:
        return None
    if value is not True and not isinstance(value, dict):
        raise SceneError(f"need true, false or a table with keys {', '.join(FIT_OPTIONS)}; got {_kind(value)}",
                         key=key)
    table = {} if value is True else value
    _only(table, FIT_OPTIONS, key)
    opts = {"fit_f_par1": None, "fit_f_perp1": True, "fit_coupling": False, "profile": True,
            "profile_level": 0.6826894921370859, "curve_points": 200}
    for k, val in table.items():
        if k == "fit_f_par1":
            if not (isinstance(val, bool) or val == "auto"):
                raise SceneError(f"{val!r} is not allowed: need true, false or \"auto\" (fitted when G(0) = 0)",
                                 key=f"{key}.{k}")
            opts[k] = None if val == "auto" else val
        elif k in ("fit_f_perp1", "fit_coupling", "profile"):
            if not isinstance(val, bool):
                raise SceneError(f"need true or false; got {val!r}", key=f"{key}.{k}")
            opts[k] = val
        elif k == "profile_level":
            if isinstance(val, bool) or not isinstance(val, (int, float)) or not 0 < val < 1:
                raise SceneError(f"{val!r} is out of range: need 0 < level < 1 (0.683: one standard error)",
                                 key=f"{key}.{k}")
            opts[k] = float(val)
        elif isinstance(val, bool) or not isinstance(val, int) or not 2 <= val <= 100_000:
            raise SceneError(f"{val!r} is out of range: need an integer in [2, 100000]", key=f"{key}.{k}")
        else:
            opts[k] = val
    return opts


def run_fit(values: Dict, options: Dict) -> Dict:
    """Fit one design's data; the result, the fitted curve on a fine grid and the residuals."""
    from ..friction import fit_steady_sliding, steady_sliding
    d: SlidingData = values["data"]
    guess = sliding_model(values)
    sigma = None
    if d.sigma_par is not None or d.sigma_perp is not None:
        # a missing column: that component's sigma is unknown; take the other's scale
        sp = d.sigma_par if d.sigma_par is not None else d.sigma_perp
        sq = d.sigma_perp if d.sigma_perp is not None else d.sigma_par
        sigma = (sp, sq)
    fit = fit_steady_sliding(d.V, d.F_par, d.F_perp, guess, fit_f_par1=options["fit_f_par1"],
                             fit_f_perp1=options["fit_f_perp1"], fit_coupling=options["fit_coupling"],
                             sigma=sigma, profile=options["profile"], profile_level=options["profile_level"])
    lo, hi = float(d.V[d.V > 0].min()) if np.any(d.V > 0) else 1e-9, float(d.V.max())
    Vc = np.geomspace(lo, max(hi, lo * 1.0001), options["curve_points"])
    at = steady_sliding(d.V, fit.model, errors="nan", forces_only=True)
    curve = steady_sliding(Vc, fit.model, errors="nan", forces_only=True)
    return {"result": fit, "data": d, "V": Vc, "F_par": np.atleast_1d(curve.F_par),
            "F_perp": np.atleast_1d(curve.F_perp),
            "residual_par": d.F_par - np.atleast_1d(at.F_par),
            "residual_perp": d.F_perp - np.atleast_1d(at.F_perp)}


def fit_csv(study, rows) -> Dict[str, str]:
    """``{study}.fit.csv`` (one row per fitted parameter) and ``{study}.fit_residuals.csv``."""
    out: Dict[str, str] = {}
    if not any("fit" in r for r in rows):
        return out
    swept = study.swept_names
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(["design"] + swept + ["parameter", "value", "standard_error", "profile_lower",
                                      "profile_upper", "status", "reason", "chi2", "dof"])
    res_buf = io.StringIO()
    rw = csv.writer(res_buf, lineterminator="\n")
    rw.writerow(["design"] + swept + ["V", "F_par", "F_perp", "residual_par", "residual_perp"])
    for p, r in zip(study.points, rows):
        if "fit" not in r:
            continue
        f, d = r["fit"]["result"], r["fit"]["data"]
        for j, name in enumerate(f.names):
            wr.writerow([p.index] + [p.swept[n] for n in swept] +
                        [name, repr(float(f.values[j])), repr(float(f.standard_errors[j])),
                         repr(float(f.profile_lower[j])), repr(float(f.profile_upper[j])),
                         f.status, f.reason, repr(float(f.chi2)), f.dof])
        for vals in zip(d.V, d.F_par, d.F_perp, r["fit"]["residual_par"], r["fit"]["residual_perp"]):
            rw.writerow([p.index] + [p.swept[n] for n in swept] + [repr(float(x)) for x in vals])
    out[f"{study.name}.fit.csv"] = buf.getvalue()
    out[f"{study.name}.fit_residuals.csv"] = res_buf.getvalue()
    return out


def fit_curves(st, rows, many: bool) -> list:
    """The curves of the ``sliding_fit`` plot, as keyword arguments of :class:`Curve`: data (role
    data_par / data_perp), fit (fit_par / fit_perp), residuals (res_par / res_perp); panel 0
    lateral, 1 normal, 2 residuals."""
    def Curve(*a, **kw):
        names = ("study", "label", "x", "y", "xname", "yname", "role")
        return {**dict(zip(names, a)), **kw}
    curves = []
    for p in st.points:
        r = rows[p.index]["fit"]
        f, d = r["result"], r["data"]
        base = st.label_for(p, many) if (st.swept_names or st.label) else st.name
        meta = {"status": f.status, "names": f.names, "values": f.values, "errors": f.standard_errors}
        curves += [Curve(st.name, f"{base}: data", d.V, d.F_par, "V", "F_par", "data_par", panel=0,
                         meta={"sigma": d.sigma_par}),
                   Curve(st.name, f"{base}: fit ({f.status})", r["V"], r["F_par"], "V", "F_par", "fit_par",
                         panel=0, meta=meta),
                   Curve(st.name, f"{base}: data", d.V, d.F_perp, "V", "F_perp", "data_perp", panel=1,
                         meta={"sigma": d.sigma_perp}),
                   Curve(st.name, f"{base}: fit ({f.status})", r["V"], r["F_perp"], "V", "F_perp", "fit_perp",
                         panel=1, meta=meta),
                   Curve(st.name, f"{base}: lateral", d.V, r["residual_par"], "V", "residual", "res_par",
                         panel=2),
                   Curve(st.name, f"{base}: normal", d.V, r["residual_perp"], "V", "residual", "res_perp",
                         panel=2)]
    return curves
