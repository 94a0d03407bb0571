"""Built-in objectives of the two-level seta with exact gradients over the nine design fields
(max_pull_off, area, pull_off_at), and the user ``Objective``."""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from ..designs import FIELDS
from ..seta import _LINE_END, CriticalStatus, LineEnd, MinimumStatus, TwoLevelSeta

_INDEX = {f: i for i, f in enumerate(FIELDS)}
OBJECTIVES = ("max_pull_off", "area", "pull_off_at")


class _EvaluationFailure(Exception):
    """The solver could not give a trustworthy value/gradient at a design."""


@dataclass
class Objective:
    """A user objective to maximise with :func:`gecko.optimize_seta`.

    Parameters
    ----------
    name : str
        Shown in the result.
    fun : callable
        ``fun(design: dict) -> float``; a non-finite value raises ``ValueError`` naming the
        objective and the design.
    jac : callable, optional
        As for :class:`Constraint`; without it, central differences of ``fun`` in the scaled
        variables.

    Examples
    --------
    >>> import gecko
    >>> stiff = gecko.Objective("-EI1", lambda d: -d["EI1"], jac=lambda d: {"EI1": -1.0})
    >>> stiff.fun({"EI1": 5.0})
    -5.0
    """

    name: str
    fun: Callable[[dict], float]
    jac: Optional[Callable[[dict], Any]] = None


def _finite_user_value(fun, design: dict, what: str) -> float:
    v = fun(dict(design))
    try:
        v = float(v)
    except (TypeError, ValueError):
        raise ValueError(f"{what} returned {v!r} at design {design}; it must return a finite float") from None
    if not math.isfinite(v):
        raise ValueError(f"{what} returned the non-finite value {v!r} at design {design}; it must "
                         "return a finite float")
    return v


# Objectives with exact gradients with respect to the nine parameters.

def _design_seta(p: np.ndarray) -> TwoLevelSeta:
    try:
        return TwoLevelSeta(**{f: float(v) for f, v in zip(FIELDS, p)})
    except ValueError as e:
        raise _EvaluationFailure(f"invalid design: {e}") from None


def _sens(seta: TwoLevelSeta, ft, allow_inadmissible: bool = False):
    # Status 7 (the seta crosses the substrate there) is refused unless asked for: a pull-off
    # never comes from an inadmissible state.
    s = seta.sensitivities(ft)
    solved = s["status"] == CriticalStatus.converged
    if allow_inadmissible:
        solved = solved | (s["status"] == CriticalStatus.inadmissible)
    if not np.all(solved) or not np.all(np.isfinite(s["dFn"])):
        bad = np.flatnonzero(~solved | ~np.all(np.isfinite(s["dFn"]), axis=1))
        raise _EvaluationFailure(f"critical state not solved at Ft = {np.atleast_1d(ft)[bad[0]]!r} "
                                 f"(status {int(s['status'][bad[0]])})")
    return s


def _dftmax(seta: TwoLevelSeta) -> np.ndarray:
    """d(Ft)max/dp, (Ft)max = sqrt(2 EA2 w)."""
    g = np.zeros(9)
    ftm = seta.ft_max
    g[_INDEX["EA2"]] = ftm / (2 * seta.EA2)
    g[_INDEX["w"]] = ftm / (2 * seta.w)
    return g


_GOOD_ENDS = (LineEnd.reached_ft_max, LineEnd.reached_ft_end)


def _check_line_end(end: LineEnd, ft_end: float, ft_max: float):
    # The default end of the trace is (Ft)max; the trace labels reaching it either way.
    if end not in _GOOD_ENDS or not abs(ft_end - ft_max) <= 1e-12 * ft_max:
        raise _EvaluationFailure(f"critical line trace ended with '{_LINE_END.get(end, str(end))}' at "
                                 f"Ft = {ft_end!r} ((Ft)max = {ft_max!r})")


def _max_pull_off(seta: TwoLevelSeta, **_):
    if math.isinf(seta.EA2):
        raise _EvaluationFailure("max_pull_off is unbounded for EA2 = inf (Rivlin: no (Ft)max)")
    c = seta.characteristics()
    if not np.isfinite(c.min_fn):
        raise _EvaluationFailure(f"critical line not traced ({c.end})")
    _check_line_end(c.end_code, c.ft_at_line_end, seta.ft_max)
    if c.min_status == "admissible_end":
        raise _EvaluationFailure(f"max pull-off at the end of the admissible part of the line, Ft = "
                                 f"{c.admissible_end_ft!r} (beyond it the seta crosses the substrate): "
                                 "not stationary")
    ft_star = c.ft_at_min_fn
    scale = max(1.0, abs(c.min_fn))
    if not c.min_fn_interior and ft_star != 0.0:
        raise _EvaluationFailure("minimum of Fn at the end of the line, Ft = (Ft)max (sensitivities "
                                 "singular there)")
    s = _sens(seta, [ft_star])
    min_fn = c.min_fn
    # The state the sensitivities describe must be the minimiser (after a fold, the first crossing
    # at Ft* could be another branch).
    if abs(s["Fn"][0] - min_fn) > 1e-9 * scale:
        raise _EvaluationFailure(f"minimiser at Ft = {ft_star!r} lies on another branch of a folded "
                                 f"line (Fn {s['Fn'][0]!r} vs {min_fn!r})")
    slope = _slope(seta, ft_star, s["Fn"][0], s["dFn"][0]) if ft_star > 0 else c.slope_at_zero
    if ft_star > 0 and not abs(slope) <= _STATIONARY * (1.0 + abs(min_fn) / ft_star):
        # The envelope theorem needs dFn/dFt = 0 at Ft*; the trace's own refinement can stop short
        # (seen where the elastica's turning points change within the bracket). Refine here: root
        # of the exact slope between the traced nodes around the smallest Fn.
        ft_star, s, slope = _refine_minimum(seta, scale)
        min_fn = float(s["Fn"][0])
        if not min_fn <= c.min_fn + 1e-12 * scale:
            raise _EvaluationFailure(f"refined minimum {min_fn!r} above the traced {c.min_fn!r}")
    if ft_star == 0 and not slope >= 0:
        raise _EvaluationFailure(f"minimum of Fn at Ft = 0 with slope {slope!r} < 0")
    return -min_fn, -s["dFn"][0], {"ft_at_max_pull_off": ft_star, "slope_at_minimum": slope}


_STATIONARY = 1e-7


def _refine_minimum(seta: TwoLevelSeta, scale: float):
    from scipy.optimize import brentq
    line = seta.critical_line()
    if line.folds:
        raise _EvaluationFailure("minimum not stationary and the line folds")
    # only admissible, re-solved nodes (status 0) can hold the minimum
    i = int(np.argmin(np.where(line.status == CriticalStatus.converged, line.Fn, np.inf)))
    if not 0 < i < len(line.Ft) - 1:
        raise _EvaluationFailure("smallest traced Fn at an end of the line")

    def slope_at(ft):
        d = _sens(seta, [ft])
        return _slope(seta, ft, d["Fn"][0], d["dFn"][0])

    a, b = float(line.Ft[i - 1]), float(line.Ft[i + 1])
    if not (slope_at(a) < 0 < slope_at(b)):
        raise _EvaluationFailure(f"no sign change of dFn/dFt around the traced minimum in [{a!r}, {b!r}]")
    ft = brentq(slope_at, a, b, xtol=1e-13 * b, rtol=4 * np.finfo(float).eps, maxiter=100)
    d = _sens(seta, [ft])
    slope = _slope(seta, ft, d["Fn"][0], d["dFn"][0])
    if not abs(slope) <= _STATIONARY * (1.0 + abs(d["Fn"][0]) / ft):
        raise _EvaluationFailure(f"minimum of Fn at Ft = {ft!r} not stationary (dFn/dFt = {slope!r})")
    return ft, d, slope


# Force-like parameters: Fn(l Ft; l p_F, p_L) = l Fn(Ft; p) for the stiffnesses and w (the governing
# equations are homogeneous in force units with the lengths fixed, docs/theory/two_level_seta.md), so by Euler's
# theorem Ft dFn/dFt = Fn - sum_F p_F dFn/dp_F: the exact slope of the line from the exact design
# sensitivities. EA = inf drops out (its term is 0 x inf, and it stays inf under the scaling).
_FORCE_LIKE = [_INDEX[f] for f in ("EI1", "EI2", "EA1", "EA2", "w")]


def _slope(seta: TwoLevelSeta, ft: float, fn: float, dfn: np.ndarray) -> float:
    p = seta._params()
    acc = fn
    for i in _FORCE_LIKE:
        if math.isfinite(p[i]):
            acc -= p[i] * dfn[i]
    return acc / ft


@functools.lru_cache(maxsize=8)
def _gauss(n):
    # Gauss-Legendre on [0, 1] (leggauss costs ~1.5 ms per call: computed once per n)
    x, w = np.polynomial.legendre.leggauss(n)
    u, wu = (x + 1) / 2, w / 2
    u.flags.writeable = False
    wu.flags.writeable = False
    return u, wu


def _admissible_end_gradient(seta: TwoLevelSeta) -> np.ndarray:
    """d b/dp of the end b of the admissible part of the critical line (where the seta first
    touches the substrate before the contact edge), by central differences of
    characteristics().admissible_end_ft, the same b the objective integrates to (refined along the
    line to ~1e-10 of its arclength: a step of 1e-4 relative keeps that noise below 1e-6)."""
    p = seta._params()
    g = np.zeros(9)
    for i, name in enumerate(FIELDS):
        if not math.isfinite(p[i]):
            continue
        hp = 1e-4 * max(1.0, abs(p[i]))
        ends = []
        for x in (p[i] + hp, p[i] - hp):
            q = dict(zip(FIELDS, map(float, p)))
            q[name] = x
            c = TwoLevelSeta(**q).characteristics()
            if c.admissible_to_end or not math.isfinite(c.admissible_end_ft):
                raise _EvaluationFailure(f"admissible end of the line not found at {name} = {x!r}")
            ends.append(float(c.admissible_end_ft))
        g[i] = (ends[0] - ends[1]) / (2 * hp)
    return g


def _area(seta: TwoLevelSeta, nodes: int = 48, **_):
    if math.isinf(seta.EA2):
        raise _EvaluationFailure("area is unbounded for EA2 = inf (no (Ft)max)")
    line = seta.critical_line()
    if line.folds:
        raise _EvaluationFailure(f"area undefined: the critical line folds at Ft = {line.folds}")
    _check_line_end(line.end_code, float(line.Ft[-1]), seta.ft_max)
    ftm = seta.ft_max
    # Only the admissible part of the line holds adhesion: from Ft = 0 to the first state where the
    # seta crosses the substrate before the edge (characteristics().admissible_end_ft). Beyond it
    # (status 7) the equations' states are no states of a real seta and add no area.
    c = seta.characteristics()
    if c.min_status_code == MinimumStatus.no_admissible_state:
        return 0.0, np.zeros(9), {"tensile_intervals": [], "admissible_end_ft": math.nan}
    ft_adm = ftm if c.admissible_to_end else float(c.admissible_end_ft)
    if not 0.0 < ft_adm <= ftm:
        raise _EvaluationFailure(f"admissible part of the line ends at Ft = {ft_adm!r}")
    ft, fn = np.asarray(line.Ft, float), np.asarray(line.Fn, float)
    if np.any(np.diff(ft) <= 0):
        raise _EvaluationFailure("traced line not monotone in Ft")

    def fn_at(x):
        st = seta.critical_line(Ft=[x])
        if st.status[0] not in (CriticalStatus.converged, CriticalStatus.inadmissible):
            raise _EvaluationFailure(f"critical state not solved at Ft = {x!r}")
        return float(st.Fn[0])

    from scipy.optimize import brentq
    # Tensile intervals: sign changes of Fn between the trace's (adaptive) nodes, refined to Fn = 0
    # by Brent; a tensile dip entering and leaving between two adjacent nodes would be missed.
    ends = []
    neg = fn < 0
    for k in range(len(ft) - 1):
        if neg[k] != neg[k + 1] and ft[k] < ft_adm:
            root = brentq(fn_at, ft[k], ft[k + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps)
            if root < ft_adm:  # a crossing beyond the admissible part bounds nothing
                ends.append(root)
    edges = [0.0, *ends, ft_adm]
    u, wq = _gauss(nodes)
    pts, wts, last, last_adm = [], [], False, False
    intervals = []
    for a, b in zip(edges[:-1], edges[1:]):
        if b <= a or fn_at(0.5 * (a + b)) >= 0:
            continue
        intervals.append((a, b))
        if b == ftm:
            # Ft = b - (b - a) u^2 removes the sqrt((Ft)max - Ft) behaviour at the end.
            pts.append(b - (b - a) * u ** 2)
            wts.append(wq * 2 * (b - a) * u)
            last = True
        elif b == ft_adm:
            # Ends just short of (Ft)max (the reference design: 3e-4 before it): Fn ~ sqrt((Ft)max - Ft)
            # there, so integrate in v = sqrt((Ft)max - Ft), where the integrand is smooth.
            last_adm = True
            va, vb = math.sqrt(ftm - a), math.sqrt(ftm - b)
            v = vb + (va - vb) * u
            pts.append(ftm - v ** 2)
            wts.append(wq * (va - vb) * 2 * v)
        else:
            pts.append(a + (b - a) * u)
            wts.append(wq * (b - a))
    if not pts:
        return 0.0, np.zeros(9), {"tensile_intervals": [], "admissible_end_ft": ft_adm}
    P, W = np.concatenate(pts), np.concatenate(wts)
    order = np.argsort(P)
    # Every node lies inside the admissible part: a status-7 state there is refused (_sens).
    s = _sens(seta, P[order])
    fnv = np.empty_like(P)
    dfn = np.empty((P.size, 9))
    fnv[order] = s["Fn"]
    dfn[order] = s["dFn"]
    area = float(np.sum(W * -fnv))
    grad = -(W @ dfn)
    if last:
        # Fn at (Ft)max from the traced line's end node (Newton at exactly (Ft)max, where the edge
        # rate vanishes, can stall at tight tolerances; the trace ends there by construction).
        if abs(ft[-1] - ftm) > 1e-12 * ftm:
            raise _EvaluationFailure("traced line does not end at (Ft)max")
        fn_end = float(fn[-1])
        grad = grad + max(0.0, -fn_end) * _dftmax(seta)
    if last_adm:
        # The end of the admissible part moves with the design: Leibniz's rule adds -Fn(b) db/dp.
        grad = grad + max(0.0, -fn_at(ft_adm)) * _admissible_end_gradient(seta)
    return area, grad, {"tensile_intervals": intervals, "admissible_end_ft": ft_adm}


def _pull_off_at(seta: TwoLevelSeta, ft: float = None, **_):
    if not (ft is not None and np.isfinite(ft)):
        raise ValueError("objective 'pull_off_at' needs a finite ft=")
    if abs(ft) >= seta.ft_max:
        raise _EvaluationFailure(f"Ft = {ft!r} beyond (Ft)max = {seta.ft_max!r}")
    s = _sens(seta, [ft])
    return -float(s["Fn"][0]), -s["dFn"][0], {}


_OBJECTIVE_FUNCS = {"max_pull_off": _max_pull_off, "area": _area, "pull_off_at": _pull_off_at}


def seta_objective(objective: str, seta: TwoLevelSeta, *, ft: Optional[float] = None,
                   nodes: int = 48):
    """Value and exact gradient of a built-in objective at one design.

    Parameters
    ----------
    objective : {"max_pull_off", "area", "pull_off_at"}
        The objective (``OBJECTIVES``).
    seta : TwoLevelSeta
        The design.
    ft : float, optional
        The shear force of "pull_off_at" (required there).
    nodes : int, optional
        Gauss nodes of "area" (default 48).

    Returns
    -------
    value : float
        The objective at the design.
    grad : dict
        Its derivative with respect to each of the nine design fields, by name.

    Raises
    ------
    ValueError
        If the objective is not one of ``OBJECTIVES``.
    RuntimeError
        Where the solver cannot give a trustworthy value (the optimiser records those designs as
        failures).

    Examples
    --------
    >>> import gecko
    >>> value, grad = gecko.seta_objective("max_pull_off", gecko.TwoLevelSeta())
    >>> round(value, 4), round(grad["alpha2"], 4)
    (2.8024, 15.0693)
    """
    if objective not in _OBJECTIVE_FUNCS:
        raise ValueError(f"objective = {objective!r} is not allowed: need one of {OBJECTIVES}")
    try:
        v, g, _ = _OBJECTIVE_FUNCS[objective](seta, ft=ft, nodes=nodes)
    except _EvaluationFailure as e:
        raise RuntimeError(str(e)) from None
    return v, dict(zip(FIELDS, map(float, g)))
