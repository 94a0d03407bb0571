"""gecko.design_optimize — gradient-based, multi-start design optimisation of the two-level seta.

models.md §1 (critical line of adhesion and its characteristic quantities); the paper's closing
discussion (001, §3.2 "Tunability", last paragraph) on optimising the structural parameters: first
keep the seta non-sticky at rest, (Fn)0 > 0 (eq 22), then make the maximum pull-off force large.

``optimize_seta(objective, bounds, constraints)`` maximises one of three built-in objectives over a
box of design parameters, subject to the built-in constraints and user callables:

* ``"max_pull_off"``: P = -min Fn over the critical line followed from Ft = 0 to its end
  (Ft)max = sqrt(2 EA2 w). (This is ``SetaCharacteristics.max_pull_off`` without the clip at 0, so
  a design with no tensile critical state has a negative value that still has a useful gradient.)
  Gradient by the envelope theorem: at an interior minimiser Ft*, dFn/dFt = 0, so
  dP/dp = -dFn/dp|Ft* (the solver's exact sensitivity at fixed Ft). A minimiser at Ft = 0 is the
  fixed lower end (the same formula holds). Stationarity at Ft* is checked with the exact slope of
  the line, which Euler's theorem gives from the same sensitivities (the equations are homogeneous
  in force units: Ft dFn/dFt = Fn - sum over EI1, EI2, EA1, EA2, w of p dFn/dp); where the trace's
  own refinement stopped short of dFn/dFt = 0, the minimiser is refined here (Brent on the exact
  slope) before the envelope theorem is used. A minimiser at the moving end Ft = (Ft)max would need
  the total derivative of Fn((Ft)max(p); p), whose two parts are each singular there (the edge
  rate vanishes like sqrt((Ft)max - Ft)); it is recorded as a failed evaluation, never fed on. In
  600 random designs (EI1 in [1, 20], EI2/EI1, l2 in [0.05, 0.5], EA2 in [10, 200], all angles)
  the line always rose steeply into its end, so the case was not met.
* ``"area"``: A = integral over Ft in [0, (Ft)max] of max(0, -Fn(Ft)) dFt, the area between the
  critical line and the Ft axis where the line is tensile (Fn < 0): the region of the (Ft, Fn) plane
  (gripping side Ft >= 0) in which a pulled seta stays attached. Computed by Gauss-Legendre on each
  tensile interval, with Ft = b - (b - a) u^2 on the interval that ends at (Ft)max (Fn has a
  sqrt((Ft)max - Ft) term there). Gradient by differentiating under the integral (the integrand's
  design derivative is the solver's exact sensitivity; its (Ft)max - Ft)^(-1/2) singularity is
  integrable and removed by the same substitution) plus the moving-end term
  max(0, -Fn((Ft)max)) d(Ft)max/dp; the ends where the line crosses Fn = 0 add nothing (the
  integrand vanishes there). Lines with a fold (Fn(Ft) not single-valued) are failed evaluations.
  A design with no tensile critical state has A = 0 and a zero gradient (a plateau): starts that
  begin there stay there, which is what the multi-start is for.
* ``"pull_off_at"``: -Fn(Ft) at a given Ft (``ft=``), gradient the direct sensitivity.
* A user ``Objective(name, fun, jac=None)`` or plain callable of the design dict (maximised).

Constraints (all of the form g(p) >= 0): ``"not_sticky"`` ((Fn)0 >= 0), ``("fn0_min", m)``
((Fn)0 >= m), ``Constraint(name, fun, jac=None)`` / a plain callable of the design dict; the bounds;
and, added automatically when the angles vary, alpha1 + alpha2 <= pi/2 - 1e-6 and alpha1 >= 1e-6.

Parameters that may vary (``bounds`` keys): the nine fields of ``TwoLevelSeta`` (EI1, EI2, EA1,
EA2, l1, l2, alpha1, alpha2, w) and three derived ones: ``"EI2/EI1"`` (sets EI2 = r EI1),
``"l2/l1"`` (sets l2 = r l1) and ``"alpha1+alpha2"`` (sets alpha1 = S - alpha2). A derived one may
also be held fixed through ``base`` (e.g. ``base={"alpha1+alpha2": pi/3}`` with ``alpha2`` varying:
the paper's Fig 3c split). The optimiser works in scaled variables z in [0, 1]: log scale between the
bounds for positive quantities (stiffnesses, lengths, ratios, w), linear for angles.

Multi-start: ``starts`` points of a scrambled Sobol sequence (scipy.stats.qmc, deterministic with
``seed``), the first replaced by ``base`` when it lies inside the bounds; SLSQP with exact gradients
(``jac``) from each. A design where the solver fails (line status != 0, fold, minimiser at the line
end, invalid design) is never passed on as a number: it is recorded in ``failures`` and returned to
SLSQP as a penalised value (worse than every successful one, zero gradient) so the line search backs
off; a start that ends on such a design is marked failed. The stopping rule is first-order
optimality, not SLSQP's change in the objective: each start's end point is checked by its KKT residual
(active constraints and bounds, non-negative multipliers by NNLS) and SLSQP is restarted there with a
smaller ftol until the residual is below 1e-9 relative (at most 4 restarts); a start is "converged"
only at a residual <= 1e-4. The optimum is re-evaluated and reports that check.
"""
from __future__ import annotations

import functools
import math
import time
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

import numpy as np

from .seta import CriticalLine, TwoLevelSeta

__all__ = ["optimize_seta", "optimize_from_scene", "SetaOptimum", "Constraint", "Objective",
           "OBJECTIVES", "seta_objective"]

FIELDS = TwoLevelSeta._FIELDS
_INDEX = {f: i for i, f in enumerate(FIELDS)}
OBJECTIVES = ("max_pull_off", "area", "pull_off_at")
_DERIVED = {"EI2/EI1": "EI2", "l2/l1": "l2", "alpha1+alpha2": "alpha1"}
_ANGLES = {"alpha1", "alpha2", "alpha1+alpha2"}
_HALF_PI = math.pi / 2
_ANGLE_MARGIN = 1e-6
# Allowed ranges of every variable (the model's domain, models.md §1), for the error messages.
_DOMAIN = {name: (0.0, math.inf, "(0, inf)") for name in ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "w",
                                                          "EI2/EI1", "l2/l1")}
_DOMAIN.update({"alpha1": (0.0, _HALF_PI, "(0, pi/2)"), "alpha2": (0.0, _HALF_PI, "[0, pi/2)"),
                "alpha1+alpha2": (0.0, _HALF_PI, "(0, pi/2)")})


class _EvaluationFailure(Exception):
    """The solver could not give a trustworthy value/gradient at a design."""


@dataclass
class Constraint:
    """A user constraint g(design) >= 0. ``fun(design: dict) -> float``; ``jac(design) ->`` dict of
    partial derivatives by parameter name (the nine fields; missing names count as 0) or a length-9
    array in ``TwoLevelSeta._FIELDS`` order. Without ``jac`` the gradient is a central difference of
    ``fun`` in the scaled variables (step 1e-6): exact gradients are used for everything gecko
    computes, a user function is the user's."""

    name: str
    fun: Callable[[dict], float]
    jac: Optional[Callable[[dict], Any]] = None


@dataclass
class Objective:
    """A user objective to maximise: ``fun(design: dict) -> float``, ``jac`` as for
    ``Constraint`` (without it: central differences of ``fun`` in the scaled variables). A
    non-finite value raises ``ValueError`` naming the objective and the design."""

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


@dataclass
class SetaOptimum:
    """Result of ``optimize_seta``.

    design: all nine parameters of the optimum; seta: it as a ``TwoLevelSeta``; value: the objective
    there (maximised); variables: the varied variables at the optimum (by name, derived ones
    included); gradient: d value / d variable there; line: its traced critical line;
    active_constraints: names of the constraints
    and bounds active at the optimum; constraints: every constraint's value g (>= 0 feasible);
    evaluations: critical-line evaluations in all starts; starts: per-start outcome dicts; status:
    "optimal" | "infeasible" | "failed" | "not_converged"; message: why; kkt: first-order check at
    the optimum in the scaled variables: grad f = sum lambda_i grad g_i over the active constraints
    and bounds with lambda >= 0 (NNLS), its residual, the residual relative to
    max(|grad f|, 1 + |value|) (above 1e-4 the status is "not_converged"), and the multipliers;
    failures: designs where the solver failed (penalised, never used as numbers)."""

    objective: str
    design: dict
    seta: Optional[TwoLevelSeta]
    value: float
    line: Optional[CriticalLine]
    active_constraints: list
    constraints: dict
    evaluations: int
    starts: list
    status: str
    message: str
    variables: dict = field(default_factory=dict)
    gradient: dict = field(default_factory=dict)
    kkt: dict = field(default_factory=dict)
    failures: list = field(default_factory=list)
    wall_time: float = 0.0

    @property
    def success(self) -> bool:
        return self.status == "optimal"

    def to_dict(self) -> dict:
        line = None
        if self.line is not None:
            line = {"Ft": self.line.Ft, "Fn": self.line.Fn, "theta_joint": self.line.theta_joint,
                    "end": self.line.end, "folds": self.line.folds}
        return _jsonable({
            "objective": self.objective, "design": self.design, "value": self.value,
            "status": self.status, "message": self.message, "variables": self.variables,
            "active_constraints": self.active_constraints, "constraints": self.constraints,
            "evaluations": self.evaluations, "gradient": self.gradient, "kkt": self.kkt,
            "starts": self.starts, "failures": self.failures, "wall_time": self.wall_time,
            "line": line})


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (float, np.floating)):
        x = float(x)
        if math.isnan(x):
            return None
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return x
    return x


# --------------------------------------------------------------------------------------------
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
    ok = (s["status"] == 0) | ((s["status"] == 7) if allow_inadmissible else False)
    if not np.all(ok) or not np.all(np.isfinite(s["dFn"])):
        bad = np.flatnonzero(~ok | ~np.all(np.isfinite(s["dFn"]), axis=1))
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


_GOOD_ENDS = ("reached (Ft)max = sqrt(2 EA2 w)", "reached the requested end of the Ft range")


def _check_line_end(end: str, ft_end: float, ft_max: float):
    # The default end of the trace is (Ft)max; the trace labels reaching it either way.
    if end not in _GOOD_ENDS or not abs(ft_end - ft_max) <= 1e-12 * ft_max:
        raise _EvaluationFailure(f"critical line trace ended with '{end}' at Ft = {ft_end!r} "
                                 f"((Ft)max = {ft_max!r})")


def _max_pull_off(seta: TwoLevelSeta, **_):
    if math.isinf(seta.EA2):
        raise _EvaluationFailure("max_pull_off is unbounded for EA2 = inf (Rivlin: no (Ft)max)")
    c = seta.characteristics()
    if not np.isfinite(c.min_fn):
        raise _EvaluationFailure(f"critical line not traced ({c.end})")
    _check_line_end(c.end, c.ft_at_line_end, seta.ft_max)
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
    slope = _slope(seta, ft_star, s["Fn"][0], s["dFn"][0]) if ft_star > 0 else c.slope_k
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
    i = int(np.argmin(np.where(line.status == 0, line.Fn, np.inf)))
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
# equations are homogeneous in force units with the lengths fixed, models.md §1), so by Euler's
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


def _area(seta: TwoLevelSeta, nodes: int = 48, **_):
    if math.isinf(seta.EA2):
        raise _EvaluationFailure("area is unbounded for EA2 = inf (no (Ft)max)")
    line = seta.critical_line()
    if line.folds:
        raise _EvaluationFailure(f"area undefined: the critical line folds at Ft = {line.folds}")
    _check_line_end(line.end, float(line.Ft[-1]), seta.ft_max)
    ftm = seta.ft_max
    ft, fn = np.asarray(line.Ft, float), np.asarray(line.Fn, float)
    if np.any(np.diff(ft) <= 0):
        raise _EvaluationFailure("traced line not monotone in Ft")

    def fn_at(x):
        st = seta.critical_line(Ft=[x])
        if st.status[0] not in (0, 7):
            raise _EvaluationFailure(f"critical state not solved at Ft = {x!r}")
        return float(st.Fn[0])

    from scipy.optimize import brentq
    # Tensile intervals: sign changes of Fn between the trace's (adaptive) nodes, refined to Fn = 0
    # by Brent; a tensile dip entering and leaving between two adjacent nodes would be missed.
    ends = []
    neg = fn < 0
    for k in range(len(ft) - 1):
        if neg[k] != neg[k + 1]:
            ends.append(brentq(fn_at, ft[k], ft[k + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps))
    edges = [0.0, *ends, ftm]
    u, wq = _gauss(nodes)
    pts, wts, last = [], [], False
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
        else:
            pts.append(a + (b - a) * u)
            wts.append(wq * (b - a))
    if not pts:
        return 0.0, np.zeros(9), {"tensile_intervals": []}
    P, W = np.concatenate(pts), np.concatenate(wts)
    order = np.argsort(P)
    # The area is that under the equations' line up to (Ft)max, including a tail where the seta
    # crosses the substrate (status 7, e.g. the reference design beyond Ft ~ 9.9997).
    s = _sens(seta, P[order], allow_inadmissible=True)
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
    return area, grad, {"tensile_intervals": intervals}


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
    """Value and exact gradient of a built-in objective at one design: ``(value, grad)`` with
    ``grad`` a dict by parameter name (the nine fields). Raises ``RuntimeError`` where the solver
    cannot give a trustworthy value (the optimiser records those designs as failures)."""
    if objective not in _OBJECTIVE_FUNCS:
        raise ValueError(f"objective = {objective!r} is not allowed: need one of {OBJECTIVES}")
    try:
        v, g, _ = _OBJECTIVE_FUNCS[objective](seta, ft=ft, nodes=nodes)
    except _EvaluationFailure as e:
        raise RuntimeError(str(e)) from None
    return v, dict(zip(FIELDS, map(float, g)))


# --------------------------------------------------------------------------------------------
# Variables: scaled z in [0, 1] -> variables x -> the nine parameters p (with exact dp/dx).

class _Space:
    def __init__(self, bounds: dict, base: dict):
        if not isinstance(bounds, dict) or not bounds:
            raise ValueError("bounds must be a non-empty dict {parameter: (lower, upper)}; parameters: "
                             f"{FIELDS + tuple(_DERIVED)}")
        self.names = list(bounds)
        self.lo, self.hi, self.log = [], [], []
        for name in self.names:
            if name not in _DOMAIN:
                raise ValueError(f"bounds: unknown parameter {name!r}; allowed: {FIELDS + tuple(_DERIVED)}")
            dlo, dhi, text = _DOMAIN[name]
            try:
                lo, hi = (float(v) for v in bounds[name])
            except (TypeError, ValueError):
                raise ValueError(f"bounds[{name!r}] = {bounds[name]!r}: need (lower, upper) numbers "
                                 f"within {text}") from None
            if not (math.isfinite(lo) and math.isfinite(hi)):
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}): need finite lower < upper within {text}")
            if not lo < hi:
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}): lower must be < upper, within {text}")
            lo_ok = lo >= dlo if name == "alpha2" else lo > dlo
            if not (lo_ok and hi < dhi):
                raise ValueError(f"bounds[{name!r}] = ({lo!r}, {hi!r}) outside the allowed range {text}")
            self.lo.append(lo)
            self.hi.append(hi)
            self.log.append(name not in _ANGLES)
        self.lo, self.hi, self.log = np.array(self.lo), np.array(self.hi), np.array(self.log)
        # conflicts between a derived variable and the field it sets
        derived = {d: dep for d, dep in _DERIVED.items() if d in self.names or d in base}
        for d, dep in derived.items():
            if dep in self.names:
                raise ValueError(f"{d!r} sets {dep!r}: vary/fix one of them, not both")
        # the fixed values must lie in the model's domain too (EA may be inf: inextensible)
        dependent = set(derived.values())
        for k, v in base.items():
            if k in self.names or k in dependent:
                continue
            dlo, dhi, text = _DOMAIN[k]
            ok = (v >= dlo if k == "alpha2" else v > dlo) and (v < dhi or (k in ("EA1", "EA2") and v == math.inf))
            if not ok or math.isnan(v):
                allowed = text + (" or inf" if k in ("EA1", "EA2") else "")
                raise ValueError(f"fixed parameter {k} = {v!r} outside the allowed range {allowed}")
        self.base = dict(base)
        self.derived = derived
        self.d = len(self.names)

    def x_of(self, z):
        z = np.clip(np.asarray(z, float), 0.0, 1.0)
        out = self.lo + z * (self.hi - self.lo)
        lg = self.log
        out[lg] = self.lo[lg] * (self.hi[lg] / self.lo[lg]) ** z[lg]
        return out

    def z_of(self, x):
        x = np.asarray(x, float)
        z = (x - self.lo) / (self.hi - self.lo)
        lg = self.log
        with np.errstate(divide="ignore", invalid="ignore"):
            z[lg] = np.log(x[lg] / self.lo[lg]) / np.log(self.hi[lg] / self.lo[lg])
        return z

    def dx_dz(self, z):
        x = self.x_of(z)
        out = self.hi - self.lo
        lg = self.log
        out[lg] = x[lg] * np.log(self.hi[lg] / self.lo[lg])
        return out

    def params(self, z):
        """p (nine fields) and dp/dz (9 x d)."""
        x = self.x_of(z)
        dxdz = self.dx_dz(z)
        val = {}
        grad = {}
        d = self.d
        for f in FIELDS:
            val[f] = float(self.base[f])
            grad[f] = np.zeros(d)
        allv = dict(self.base)
        for i, n in enumerate(self.names):
            allv[n] = x[i]
            if n in _INDEX:
                val[n] = x[i]
                grad[n] = np.zeros(d)
                grad[n][i] = dxdz[i]

        def var_grad(name):
            g = np.zeros(d)
            if name in self.names:
                g[self.names.index(name)] = dxdz[self.names.index(name)]
            return g

        if "EI2/EI1" in self.derived:
            r = allv["EI2/EI1"]
            val["EI2"] = r * val["EI1"]
            grad["EI2"] = r * grad["EI1"] + val["EI1"] * var_grad("EI2/EI1")
        if "l2/l1" in self.derived:
            r = allv["l2/l1"]
            val["l2"] = r * val["l1"]
            grad["l2"] = r * grad["l1"] + val["l1"] * var_grad("l2/l1")
        if "alpha1+alpha2" in self.derived:
            S = allv["alpha1+alpha2"]
            val["alpha1"] = S - val["alpha2"]
            grad["alpha1"] = var_grad("alpha1+alpha2") - grad["alpha2"]
        p = np.array([val[f] for f in FIELDS])
        J = np.array([grad[f] for f in FIELDS])
        return p, J

    def variables(self, z):
        return dict(zip(self.names, map(float, self.x_of(z))))


# --------------------------------------------------------------------------------------------

def _parse_constraints(constraints):
    """-> list of (name, kind, data): kind 'fn0' (data = margin) or 'user' (Constraint)."""
    out = []
    fn0 = None
    items = constraints
    if isinstance(items, dict):
        items = list(items.items())
    elif isinstance(items, (str, Constraint)) or callable(items):
        items = [items]
    for c in items:
        if isinstance(c, str):
            c = (c, True)
        if isinstance(c, Constraint):
            out.append((c.name, "user", c))
        elif callable(c):
            name = getattr(c, "__name__", "constraint")
            out.append((name, "user", Constraint(name, c)))
        elif isinstance(c, tuple) and len(c) == 2 and isinstance(c[0], str):
            key, v = c
            if key == "not_sticky":
                if not isinstance(v, (bool, np.bool_)):
                    raise ValueError(f"constraint not_sticky = {v!r}: need true/false")
                if v:
                    fn0 = 0.0 if fn0 is None else max(fn0, 0.0)
            elif key == "fn0_min":
                try:
                    m = float(v)
                except (TypeError, ValueError):
                    raise ValueError(f"constraint fn0_min = {v!r}: need a finite number") from None
                if not math.isfinite(m):
                    raise ValueError(f"constraint fn0_min = {v!r}: need a finite number")
                fn0 = m if fn0 is None else max(fn0, m)
            else:
                raise ValueError(f"unknown constraint {key!r}: allowed 'not_sticky', 'fn0_min', "
                                 "a Constraint or a callable")
        else:
            raise ValueError(f"constraint {c!r} not understood: allowed 'not_sticky', ('fn0_min', m), "
                             "a Constraint or a callable")
    if fn0 is not None:
        out.insert(0, (f"(Fn)0 >= {fn0:g}", "fn0", fn0))
    names = [n for n, _, _ in out]
    if len(set(names)) != len(names):
        raise ValueError(f"constraint names must be unique: {names}")
    return out


def _base_dict(base) -> dict:
    if base is None:
        return {f: getattr(TwoLevelSeta(), f) for f in FIELDS}
    if isinstance(base, TwoLevelSeta):
        return {f: getattr(base, f) for f in FIELDS}
    if isinstance(base, dict):
        d = {f: getattr(TwoLevelSeta(), f) for f in FIELDS}
        for k, v in base.items():
            if k not in _INDEX and k not in _DERIVED:
                raise ValueError(f"base: unknown parameter {k!r}; allowed: {FIELDS + tuple(_DERIVED)}")
            d[k] = float(v)
        return d
    raise ValueError(f"base = {base!r}: need None, a TwoLevelSeta or a dict of parameters")


class _Problem:
    def __init__(self, objective, space: _Space, cons, ft, nodes):
        self.objective, self.space, self.cons, self.ft, self.nodes = objective, space, cons, ft, nodes
        self.cache = {}
        self.evaluations = 0
        self.failures = []
        self.worst = None
        self.fscale = 1.0
        self.validity = self._validity()

    def _validity(self):
        """Linear-in-p angle conditions kept as constraints when the angles vary."""
        names = set(self.space.names)
        out = []
        if names & {"alpha1", "alpha2", "alpha1+alpha2"}:
            out.append(("alpha1+alpha2 <= pi/2", np.array([0, 0, 0, 0, 0, 0, -1, -1, 0.0]),
                        _HALF_PI - _ANGLE_MARGIN))
            out.append(("alpha1 > 0", np.eye(9)[_INDEX["alpha1"]], -_ANGLE_MARGIN))
        return out

    def valid(self, z) -> bool:
        p, _ = self.space.params(np.clip(np.asarray(z, float), 0.0, 1.0))
        return all(a[6] * p[6] + a[7] * p[7] + b >= 0 for _, a, b in self.validity)

    def evaluate(self, z):
        z = np.clip(np.asarray(z, float), 0.0, 1.0)
        key = z.tobytes()
        if key in self.cache:
            return self.cache[key]
        p, J = self.space.params(z)
        rec = {"z": z.copy(), "p": p, "ok": True}
        # validity constraints first (cheap; an invalid design is not sent to the solver)
        vals, grads, names = [], [], []
        for name, a, b in self.validity:
            # only the angle entries of a are non-zero (and p may hold EA = inf)
            vals.append(float(a[6] * p[6] + a[7] * p[7] + b))
            grads.append(a[6] * J[6] + a[7] * J[7])
            names.append(name)
        try:
            if any(v < 0 for v in vals):
                raise _EvaluationFailure("design outside the model's angle domain (alpha1 > 0, "
                                         "alpha1 + alpha2 < pi/2)")
            seta = _design_seta(p)
            self.evaluations += 1
            design = dict(zip(FIELDS, map(float, p)))
            if isinstance(self.objective, str):
                v, g, info = _OBJECTIVE_FUNCS[self.objective](seta, ft=self.ft, nodes=self.nodes)
                rec["value"], rec["info"] = float(v), info
                rec["grad_z"] = np.asarray(g, float) @ J
            else:
                # a user objective: its non-finite value is the caller's error, not a solver failure
                rec["value"] = _finite_user_value(self.objective.fun, design,
                                                  f"objective {self.objective.name!r}")
                rec["grad_z"] = self._user_grad(self.objective, z, "objective")
                rec["info"] = {}
            for name, kind, data in self.cons:
                if kind == "fn0":
                    s = _sens(seta, [0.0])
                    vals.append(float(s["Fn"][0]) - data)
                    grads.append(s["dFn"][0] @ J)
                else:
                    vals.append(_finite_user_value(data.fun, design, f"constraint {name!r}"))
                    grads.append(self._user_grad(data, z, "constraint"))
                names.append(name)
            if not (np.isfinite(rec["value"]) and np.all(np.isfinite(rec["grad_z"]))):
                raise _EvaluationFailure("non-finite objective or gradient")
        except _EvaluationFailure as e:
            rec["ok"] = False
            rec["reason"] = str(e)
            self.failures.append({"variables": self.space.variables(z), "reason": str(e)})
            vals = [v for v in vals[:len(self.validity)]] + [-1.0] * len(self.cons)
            grads = grads[:len(self.validity)] + [np.zeros(self.space.d)] * len(self.cons)
            names = [n for n, _, _ in self.validity] + [n for n, _, _ in self.cons]
        rec["cons"] = np.array(vals, float)
        rec["cons_grad"] = np.array(grads, float).reshape(len(vals), self.space.d)
        rec["cons_names"] = names
        if rec["ok"]:
            self.worst = rec["value"] if self.worst is None else min(self.worst, rec["value"])
        self.cache[key] = rec
        return rec

    def _user_grad(self, c, z, what):
        p, J = self.space.params(z)
        if c.jac is not None:
            g = c.jac(dict(zip(FIELDS, map(float, p))))
            if isinstance(g, dict):
                unknown = set(g) - set(FIELDS)
                if unknown:
                    raise ValueError(f"{what} {c.name!r}: jac returned unknown parameters {unknown}")
                g = np.array([float(g.get(f, 0.0)) for f in FIELDS])
            g = np.asarray(g, float).reshape(9)
            if not np.all(np.isfinite(g)):
                raise ValueError(f"{what} {c.name!r}: jac returned non-finite values at design "
                                 f"{dict(zip(FIELDS, map(float, p)))}")
            return g @ J
        h = 1e-6
        out = np.zeros(self.space.d)
        for i in range(self.space.d):
            zp, zm = np.array(z, float), np.array(z, float)
            zp[i] += h
            zm[i] -= h
            vp = _finite_user_value(c.fun, dict(zip(FIELDS, map(float, self.space.params(zp)[0]))),
                                    f"{what} {c.name!r}")
            vm = _finite_user_value(c.fun, dict(zip(FIELDS, map(float, self.space.params(zm)[0]))),
                                    f"{what} {c.name!r}")
            out[i] = (vp - vm) / (2 * h)
        return out

    # SLSQP callbacks (minimise f = -value / fscale)
    def _penalty(self):
        w = 0.0 if self.worst is None else self.worst
        return (-(w) + 10.0 * (1.0 + abs(w))) / self.fscale

    def f(self, z):
        r = self.evaluate(z)
        return -r["value"] / self.fscale if r["ok"] else self._penalty()

    def jac(self, z):
        r = self.evaluate(z)
        return -r["grad_z"] / self.fscale if r["ok"] else np.zeros(self.space.d)

    def c(self, z):
        return self.evaluate(z)["cons"]

    def cjac(self, z):
        return self.evaluate(z)["cons_grad"]


# First-order optimality is the stopping rule, not SLSQP's own test. SLSQP stops when the objective
# changes by less than ftol between iterations; how small the projected gradient is then depends on
# the rounding of its QP subproblem's BLAS calls (OpenBLAS's Haswell kernels stopped a 3-parameter
# area problem at a KKT residual of 1.4e-6, other kernels below 1e-6). So every start is checked
# by the KKT residual at its end point and, above _KKT_TARGET, SLSQP is restarted there with a
# 1000x smaller ftol (at most _POLISH_ROUNDS times). A start counts as converged only when the
# residual is at most _KKT_TOL; SLSQP's message is kept for the record.
_KKT_TOL = 1e-4
_KKT_TARGET = 1e-9
_POLISH_ROUNDS = 4
_ACTIVE_TOL = 1e-6     # a constraint value g <= this is active
_BOUND_TOL = 1e-9      # a scaled variable within this of 0 or 1 is at its bound


def _kkt_at(rec, z):
    """The KKT check at an evaluated point: active constraints and bounds, then ``_kkt``."""
    z = np.asarray(z, float)
    cons_active = rec["cons"] <= _ACTIVE_TOL
    return _kkt(rec, cons_active, z <= _BOUND_TOL, z >= 1 - _BOUND_TOL), cons_active


def _kkt(rec, active_mask, bounds_lo, bounds_hi):
    """NNLS multipliers for grad f = sum lambda_i grad g_i over the active set (f = -value)."""
    from scipy.optimize import nnls
    d = rec["grad_z"].size
    gf = -rec["grad_z"]
    cols, names = [], []
    for i in np.flatnonzero(active_mask):
        cols.append(rec["cons_grad"][i])
        names.append(rec["cons_names"][i])
    for j in range(d):
        if bounds_lo[j]:
            cols.append(np.eye(d)[j])
            names.append(f"lower bound {j}")
        if bounds_hi[j]:
            cols.append(-np.eye(d)[j])
            names.append(f"upper bound {j}")
    if cols:
        A = np.array(cols).T
        lam, res = nnls(A, gf)
    else:
        lam, res = np.zeros(0), float(np.linalg.norm(gf))
    norm = float(np.linalg.norm(gf))
    # Scale: |grad f| where the gradient is held by active constraints; at an interior optimum
    # (grad f -> 0) the natural scale of a gradient in the unit box of z is 1 + |value|.
    scale = max(norm, 1.0 + abs(rec["value"]))
    return {"residual": float(res), "relative_residual": float(res / scale),
            "gradient_norm": norm, "multipliers": dict(zip(names, map(float, lam)))}


def optimize_seta(objective, bounds: dict, constraints=(), *, base=None, starts: int = 8, seed: int = 0,
                  method: str = "SLSQP", ft: Optional[float] = None, maxiter: int = 100,
                  tol: float = 1e-10, feasibility_tol: float = 1e-6, include_base: bool = True,
                  quadrature_nodes: int = 48) -> SetaOptimum:
    """Maximise a built-in objective of the two-level seta over a box of parameters (module docstring).

    objective: "max_pull_off" | "area" | "pull_off_at" (with ``ft``), or a user ``Objective`` /
    callable of the design dict (its non-finite value is a ``ValueError``). bounds: {parameter: (lo, hi)}
    over the nine fields of ``TwoLevelSeta`` and "EI2/EI1", "l2/l1", "alpha1+alpha2"; lo < hi, finite,
    inside the model's domain, else ``ValueError`` naming the parameter and its allowed range.
    constraints: any of "not_sticky", ("fn0_min", m), {"not_sticky": True, "fn0_min": m},
    ``Constraint(name, fun, jac)`` or callables g(design) >= 0. base: the fixed parameters (a
    ``TwoLevelSeta`` or a dict, may fix a derived one); default the paper's reference scene.
    starts: number of Sobol starts (deterministic with ``seed``; the first is ``base`` when inside
    the bounds and ``include_base``). method: "SLSQP" (the only one: bounds, inequality
    constraints and ``jac`` together). maxiter bounds SLSQP's iterations per start, so an
    impossible problem ends with status "infeasible", never a loop.
    """
    t0 = time.perf_counter()
    try:
        import scipy.optimize  # noqa: F401
        import scipy.stats  # noqa: F401
    except ImportError:  # pragma: no cover - scipy is in the test environment
        raise ImportError("gecko.optimize_seta needs scipy (pip install gecko[optimize])") from None
    if isinstance(objective, str):
        if objective not in _OBJECTIVE_FUNCS:
            raise ValueError(f"objective = {objective!r} is not allowed: need one of {OBJECTIVES}, "
                             "an Objective or a callable")
        objective_name = objective
    elif isinstance(objective, Objective):
        objective_name = objective.name
    elif callable(objective):
        objective = Objective(getattr(objective, "__name__", "objective"), objective)
        objective_name = objective.name
    else:
        raise ValueError(f"objective = {objective!r} is not allowed: need one of {OBJECTIVES}, "
                         "an Objective or a callable")
    if method != "SLSQP":
        raise ValueError(f"method = {method!r} is not allowed: need 'SLSQP'")
    if objective == "pull_off_at":
        if ft is None or not math.isfinite(float(ft)):
            raise ValueError(f"objective 'pull_off_at' needs a finite ft (got {ft!r})")
        ft = float(ft)
    elif ft is not None:
        raise ValueError(f"ft = {ft!r} is only used by objective 'pull_off_at'")
    if not (isinstance(starts, (int, np.integer)) and 1 <= starts <= 1024):
        raise ValueError(f"starts = {starts!r}: need an integer in [1, 1024]")
    if not (isinstance(maxiter, (int, np.integer)) and 1 <= maxiter <= 10000):
        raise ValueError(f"maxiter = {maxiter!r}: need an integer in [1, 10000]")
    if not (isinstance(quadrature_nodes, (int, np.integer)) and 4 <= quadrature_nodes <= 400):
        raise ValueError(f"quadrature_nodes = {quadrature_nodes!r}: need an integer in [4, 400]")
    base_d = _base_dict(base)
    space = _Space(bounds, base_d)
    cons = _parse_constraints(constraints)
    prob = _Problem(objective, space, cons, ft, int(quadrature_nodes))
    if (isinstance(objective, str) and objective in ("max_pull_off", "area") and math.isinf(base_d["EA2"])
            and "EA2" not in space.names):
        raise ValueError(f"objective {objective!r} needs a finite EA2 (EA2 = inf has no (Ft)max: "
                         "the pull-off grows without bound)")

    # Starts: Sobol in z, the base design first when inside the box.
    from scipy.stats import qmc
    from scipy.optimize import minimize
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # Sobol balance warning for n not a power of 2
        cand = qmc.Sobol(space.d, scramble=True, seed=seed).random(64 * starts)
    # Starts: the base design (when inside the box), then Sobol candidates in order, skipping those
    # outside the angle domain (a cheap linear check) and those where the solver fails (evaluated
    # once, recorded in failures): a start on a failed design could not move. When fewer usable
    # candidates exist than starts, the remaining starts are the rejected candidates in order
    # (they then end as failed starts).
    base_z = None
    if include_base:
        implied = {"EI2/EI1": base_d["EI2"] / base_d["EI1"], "l2/l1": base_d["l2"] / base_d["l1"],
                   "alpha1+alpha2": base_d["alpha1"] + base_d["alpha2"]}
        bx = np.array([base_d[n] if n in base_d else implied[n] for n in space.names], float)
        bz = space.z_of(bx)
        if np.all(np.isfinite(bz)) and np.all((bz >= 0) & (bz <= 1)):
            base_z = bz
    chosen, rejected, skipped = [], [], 0
    pool = ([base_z] if base_z is not None else []) + list(cand)
    for z in pool:
        if len(chosen) == starts:
            break
        if prob.valid(z) and prob.evaluate(z)["ok"]:
            chosen.append(z)
        else:
            rejected.append(z)
            skipped += 1
    Z = np.array((chosen + rejected)[:starts], float)
    from_base = base_z is not None and len(chosen) > 0 and chosen[0] is base_z
    # objective scale for SLSQP's absolute ftol: |value| at the first usable start
    if chosen:
        prob.fscale = max(1.0, abs(prob.evaluate(chosen[0])["value"]))

    cons_spec = {"type": "ineq", "fun": prob.c, "jac": prob.cjac}

    def slsqp(z_start, ftol):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            return minimize(prob.f, z_start, jac=prob.jac, bounds=[(0.0, 1.0)] * space.d,
                            constraints=[cons_spec] if (prob.cons or prob.validity) else [],
                            method="SLSQP", options={"maxiter": int(maxiter), "ftol": ftol})

    def violation(rec):
        return float(max(0.0, -np.min(rec["cons"]))) if rec["cons"].size else 0.0

    records = []
    for k, z0 in enumerate(Z):
        ev0, nf0 = prob.evaluations, len(prob.failures)
        res = slsqp(z0, tol)
        iterations = int(res.nit)
        zf = np.clip(res.x, 0.0, 1.0)
        rec = prob.evaluate(zf)
        kkt_res = _kkt_at(rec, zf)[0]["relative_residual"] if rec["ok"] else math.inf
        # Polish (see _KKT_TARGET): restart from the end point with a smaller ftol while the
        # first-order conditions do not hold; keep a restart only if it stays feasible and does
        # not lose value.
        polishes, ftol = 0, tol
        while (rec["ok"] and violation(rec) <= feasibility_tol and kkt_res > _KKT_TARGET
               and polishes < _POLISH_ROUNDS):
            polishes += 1
            ftol = max(ftol * 1e-3, 1e-300)
            res_p = slsqp(zf, ftol)
            iterations += int(res_p.nit)
            zp = np.clip(res_p.x, 0.0, 1.0)
            rec_p = prob.evaluate(zp)
            if not (rec_p["ok"] and violation(rec_p) <= feasibility_tol
                    and rec_p["value"] >= rec["value"] - 1e-12 * (1 + abs(rec["value"]))):
                break
            kkt_p = _kkt_at(rec_p, zp)[0]["relative_residual"]
            if not kkt_p < kkt_res:
                break
            res, zf, rec, kkt_res = res_p, zp, rec_p, kkt_p
        viol = violation(rec)
        out = {"start": k, "from_base": bool(from_base and k == 0),
               "start_variables": space.variables(z0), "variables": space.variables(zf),
               "value": rec["value"] if rec["ok"] else None, "slsqp_status": int(res.status),
               "message": str(res.message), "iterations": iterations, "polishes": polishes,
               "kkt_relative_residual": kkt_res if rec["ok"] else None,
               "evaluations": prob.evaluations - ev0, "failures": len(prob.failures) - nf0,
               "max_violation": viol}
        if not rec["ok"]:
            out["outcome"] = "failed: " + rec["reason"]
        elif viol > feasibility_tol:
            out["outcome"] = "infeasible"
        elif kkt_res <= _KKT_TOL:
            out["outcome"] = "converged"
        else:
            out["outcome"] = "not converged"
        out["_z"] = zf
        records.append(out)

    good = [r for r in records if r["outcome"] in ("converged", "not converged")]
    best = None
    note = ""
    if good:
        # A converged start is preferred; a non-converged one that is better is mentioned.
        conv = [r for r in good if r["outcome"] == "converged"]
        best = max(conv or good, key=lambda r: r["value"])
        better = [r for r in good if r["value"] > best["value"] + 1e-8 * (1 + abs(best["value"]))]
        if better:
            b = max(better, key=lambda r: r["value"])
            note = (f"; note: non-converged start {b['start']} ended higher ({b['value']!r}, "
                    f"{b['message']})")
    starts_out = [{k: v for k, v in r.items() if k != "_z"} for r in records]
    wall = time.perf_counter() - t0
    if best is None:
        if all(r["outcome"].startswith("failed") for r in records):
            status, msg = "failed", "the solver failed at the end point of every start (see starts, failures)"
        else:
            viols = [r["max_violation"] for r in records if r["outcome"] == "infeasible"]
            status = "infeasible"
            msg = (f"no start reached a feasible design: the constraints cannot be met inside the bounds "
                   f"(smallest violation {min(viols):.3g}; tolerance {feasibility_tol:g})")
        return SetaOptimum(objective=objective_name, design={}, seta=None, value=math.nan, line=None,
                           active_constraints=[], constraints={}, evaluations=prob.evaluations,
                           starts=starts_out, status=status, message=msg,
                           variables={n: math.nan for n in space.names}, failures=prob.failures,
                           wall_time=wall)
    zf = best["_z"]
    rec = prob.evaluate(zf)
    p = rec["p"]
    design = dict(zip(FIELDS, map(float, p)))
    seta = TwoLevelSeta(**design)
    line = seta.critical_line()
    kkt, cons_active = _kkt_at(rec, zf)
    active = [n for n, a in zip(rec["cons_names"], cons_active) if a]
    for j, n in enumerate(space.names):
        if zf[j] <= _BOUND_TOL:
            active.append(f"{n} >= {space.lo[j]:g} (lower bound)")
        if zf[j] >= 1 - _BOUND_TOL:
            active.append(f"{n} <= {space.hi[j]:g} (upper bound)")
    # name the bound multipliers by variable
    kkt["multipliers"] = {(k if not k.startswith(("lower bound", "upper bound")) else
                           f"{k.split()[0]} bound {space.names[int(k.split()[-1])]}"): v
                          for k, v in kkt["multipliers"].items()}
    # "converged" already means KKT relative residual <= _KKT_TOL at this very point
    status = "optimal" if best["outcome"] == "converged" else "not_converged"
    if status == "not_converged":
        note += f"; KKT relative residual {kkt['relative_residual']:.2g} > {_KKT_TOL:g}"
    if skipped:
        note += f"; {skipped} start candidates skipped (outside the angle domain or solver failure)"
    msg = (f"best of {starts} starts (start {best['start']}): KKT relative residual "
           f"{best['kkt_relative_residual']:.2g} after {best['polishes']} polish restarts "
           f"(SLSQP: {best['message']}); "
           f"{sum(r['outcome'] == 'converged' for r in records)} converged, "
           f"{sum(r['outcome'] == 'infeasible' for r in records)} infeasible, "
           f"{sum(r['outcome'].startswith('failed') for r in records)} failed" + note)
    dxdz = space.dx_dz(zf)
    grad_x = {n: float(g / d) for n, g, d in zip(space.names, rec["grad_z"], dxdz)}
    return SetaOptimum(objective=objective_name, design=design, seta=seta, value=rec["value"], line=line,
                       active_constraints=active,
                       constraints=dict(zip(rec["cons_names"], map(float, rec["cons"]))),
                       evaluations=prob.evaluations, starts=starts_out, status=status, message=msg,
                       variables=space.variables(zf), gradient=grad_x, kkt=kkt, failures=prob.failures,
                       wall_time=time.perf_counter() - t0)


_SCENE_KEYS = {"objective", "ft", "vary", "constraints", "starts", "seed", "fixed", "method", "maxiter",
               "include_base", "quadrature_nodes"}


def optimize_from_scene(spec: dict) -> SetaOptimum:
    """Runs ``optimize_seta`` from a scene's ``[optimize]`` table given as a plain dict.

    Keys (anything else is a ValueError):

    * ``objective`` (required): "max_pull_off" | "area" | "pull_off_at".
    * ``ft``: float, the shear force of "pull_off_at" (required there, not allowed otherwise).
    * ``vary`` (required): {parameter: [lower, upper]}; parameters: EI1, EI2, EA1, EA2, l1, l2,
      alpha1, alpha2, w, "EI2/EI1", "l2/l1", "alpha1+alpha2".
    * ``constraints``: {"not_sticky": bool, "fn0_min": float}.
    * ``fixed``: {parameter: value} for parameters not varied (same names; default: the paper's
      reference scene). A parameter name may also be given at the top level of the table
      (e.g. ``EA2 = 50``); the same parameter in both places is an error.
    * ``starts`` (int, default 8), ``seed`` (int, default 0), ``method`` ("SLSQP"),
      ``maxiter`` (int, default 100), ``include_base`` (bool, default true),
      ``quadrature_nodes`` (int, default 48, for "area").
    """
    if not isinstance(spec, dict):
        raise ValueError(f"optimize table must be a dict, got {type(spec).__name__}")
    params = set(FIELDS) | set(_DERIVED)
    unknown = set(spec) - _SCENE_KEYS - params
    if unknown:
        raise ValueError(f"optimize: unknown keys {sorted(unknown)}; allowed {sorted(_SCENE_KEYS)} "
                         f"and parameter names {sorted(params)}")
    if "objective" not in spec:
        raise ValueError(f"optimize: 'objective' is required, one of {OBJECTIVES}")
    if "vary" not in spec or not isinstance(spec["vary"], dict):
        raise ValueError("optimize: 'vary' = {parameter: [lower, upper]} is required")
    fixed = dict(spec.get("fixed", {}) or {})
    if not isinstance(fixed, dict):
        raise ValueError("optimize: 'fixed' must be a table {parameter: value}")
    for k in set(spec) & params:
        if k in fixed:
            raise ValueError(f"optimize: parameter {k!r} given both at the top level and in 'fixed'")
        fixed[k] = spec[k]
    for k, v in fixed.items():
        if k not in params:
            raise ValueError(f"optimize.fixed: unknown parameter {k!r}; allowed {sorted(params)}")
        if k in spec["vary"]:
            raise ValueError(f"optimize: parameter {k!r} is both fixed and varied")
        if isinstance(v, str) and v.strip().lower() in ("inf", "+inf", "infinity"):
            fixed[k] = math.inf
    cons = spec.get("constraints", {}) or {}
    if not isinstance(cons, dict):
        raise ValueError("optimize: 'constraints' must be a table {not_sticky = bool, fn0_min = float}")
    bad = set(cons) - {"not_sticky", "fn0_min"}
    if bad:
        raise ValueError(f"optimize.constraints: unknown keys {sorted(bad)}; allowed 'not_sticky', 'fn0_min'")
    vary = {k: tuple(v) if isinstance(v, (list, tuple)) else v for k, v in spec["vary"].items()}
    kw = {k: spec[k] for k in ("starts", "seed", "method", "maxiter", "include_base", "quadrature_nodes")
          if k in spec}
    return optimize_seta(spec["objective"], vary, cons, base=fixed or None, ft=spec.get("ft"), **kw)
