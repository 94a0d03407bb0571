"""The multi-start driver (``optimize_seta``), its result (``SetaOptimum``) and the scene adapter
(``optimize_from_scene``)."""
from __future__ import annotations

import enum
import math
import time
import warnings
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..seta import CriticalLine, TwoLevelSeta
from .kkt import _BOUND_TOL, _KKT_TARGET, _KKT_TOL, _POLISH_ROUNDS, _kkt_at
from .objectives import _OBJECTIVE_FUNCS, FIELDS, OBJECTIVES, Objective
from .problem import _Problem, _parse_constraints
from .space import _DERIVED, _Space, _base_dict


class OptimumStatus(str, enum.Enum):
    """``SetaOptimum.status``: equal to its plain string (``status == "optimal"`` keeps working)."""

    optimal = "optimal"              # a converged start (KKT relative residual <= 1e-4) is the best
    not_converged = "not_converged"  # the best start ended feasible but above the KKT tolerance
    infeasible = "infeasible"        # no start reached a feasible design
    failed = "failed"                # the solver failed at the end point of every start


class StartOutcome(str, enum.Enum):
    """How one start ended (``SetaOptimum.starts[i]["outcome"]`` is its text, with the reason
    after "failed: ")."""

    converged = "converged"
    not_converged = "not converged"
    infeasible = "infeasible"
    failed = "failed"


@dataclass
class SetaOptimum:
    """Result of :func:`gecko.optimize_seta`.

    Attributes
    ----------
    objective : str
        The objective's name.
    design : dict
        All nine parameters of the optimum.
    seta : TwoLevelSeta or None
        The optimum as a design object.
    value : float
        The objective there (maximised).
    line : CriticalLine or None
        Its traced critical line.
    active_constraints : list of str
        The constraints and bounds active at the optimum.
    constraints : dict
        Every constraint's value g (>= 0: feasible).
    evaluations : int
        Critical-line evaluations in all starts.
    starts : list of dict
        The outcome of each start.
    status : str
        "optimal", "infeasible", "failed" or "not_converged".
    message : str
        Why.
    variables : dict
        The varied variables at the optimum, by name (derived ones included).
    gradient : dict
        d value / d variable there.
    kkt : dict
        First-order check in the scaled variables: grad f = sum lambda_i grad g_i over the active
        constraints and bounds with lambda >= 0 (NNLS), its residual, the residual relative to
        max(norm of grad f, 1 + abs(value)) (above 1e-4 the status is "not_converged"), and the
        multipliers.
    failures : list
        Designs where the solver failed (penalised, never used as numbers).
    wall_time : float
        Seconds.

    Examples
    --------
    >>> import gecko
    >>> best = gecko.optimize_seta("max_pull_off", {"alpha2": (0.05, 1.0)}, ["not_sticky"], starts=2)
    >>> best.status, sorted(best.variables), best.kkt["relative_residual"] < 1e-4
    ('optimal', ['alpha2'], True)
    """

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
        return self.status == OptimumStatus.optimal

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


def optimize_seta(objective, bounds: dict, constraints=(), *, base=None, starts: int = 8, seed: int = 0,
                  method: str = "SLSQP", ft: Optional[float] = None, maxiter: int = 100,
                  tol: float = 1e-10, feasibility_tol: float = 1e-6, include_base: bool = True,
                  quadrature_nodes: int = 48) -> SetaOptimum:
    """Maximise an objective of the two-level seta over a box of design parameters.

    SLSQP from several Sobol starts, with the exact gradient of the critical state with respect to
    the design (implicit differentiation, no finite differences). Each start's result is checked for
    first-order optimality (KKT residual); needs scipy (the ``[optimize]`` extra).

    Parameters
    ----------
    objective : str, Objective or callable
        "max_pull_off", "area" or "pull_off_at" (with ``ft``), an :class:`Objective`, or a callable
        of the design dict (a non-finite value raises ``ValueError``).
    bounds : dict
        {parameter: (lo, hi)} over the nine fields of ``TwoLevelSeta`` and "EI2/EI1", "l2/l1",
        "alpha1+alpha2"; lo < hi, finite, inside the model's domain.
    constraints : sequence, optional
        Any of "not_sticky", ("fn0_min", m), {"not_sticky": True, "fn0_min": m},
        :class:`Constraint` objects or callables g(design) >= 0.
    base : TwoLevelSeta or dict, optional
        The fixed parameters (may fix a derived one); default the paper's reference scene.
    starts : int, optional
        Number of Sobol starts (default 8); the first is ``base`` when inside the bounds and
        ``include_base``.
    seed : int, optional
        Seed of the starts (default 0): the result is deterministic.
    method : {"SLSQP"}, optional
        The only method: bounds, inequality constraints and ``jac`` together.
    ft : float, optional
        The shear force of "pull_off_at" (required there, not allowed otherwise).
    maxiter : int, optional
        SLSQP iterations per start (default 100), so an impossible problem ends "infeasible".
    tol, feasibility_tol : float, optional
        SLSQP's tolerance (default 1e-10) and the constraint violation accepted as feasible (1e-6).
    include_base : bool, optional
        Start from ``base`` too (default True).
    quadrature_nodes : int, optional
        Gauss nodes of the "area" objective (default 48).

    Returns
    -------
    SetaOptimum
        The optimum, its value, active constraints, status ("optimal", "infeasible", "failed",
        "not_converged") and the first-order check.

    Raises
    ------
    ValueError
        If the objective, a bound, a constraint or an option is not allowed (naming it and the
        allowed range).
    gecko._optional.MissingOptionalDependency
        If scipy is not installed.

    Examples
    --------
    >>> import gecko
    >>> best = gecko.optimize_seta("max_pull_off", {"alpha2": (0.05, 1.0)}, ["not_sticky"], starts=2)
    >>> best.status, round(best.design["alpha2"], 4), best.active_constraints
    ('optimal', 0.5472, ['(Fn)0 >= 0'])
    """
    t0 = time.perf_counter()
    from .._optional import require
    require("scipy.optimize", "gecko.optimize_seta", "optimize")
    require("scipy.stats", "gecko.optimize_seta", "optimize")
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
    from .._vectorize import check_tolerance
    tol = check_tolerance(tol, "tol", allow_none=False)
    feasibility_tol = check_tolerance(feasibility_tol, "feasibility_tol", allow_none=False)
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
            kind = StartOutcome.failed
        elif viol > feasibility_tol:
            kind = StartOutcome.infeasible
        elif kkt_res <= _KKT_TOL:
            kind = StartOutcome.converged
        else:
            kind = StartOutcome.not_converged
        out["outcome"] = kind.value + (": " + rec["reason"] if kind is StartOutcome.failed else "")
        out["_kind"] = kind
        out["_z"] = zf
        records.append(out)

    good = [r for r in records if r["_kind"] in (StartOutcome.converged, StartOutcome.not_converged)]
    best = None
    note = ""
    if good:
        # A converged start is preferred; a non-converged one that is better is mentioned.
        conv = [r for r in good if r["_kind"] is StartOutcome.converged]
        best = max(conv or good, key=lambda r: r["value"])
        better = [r for r in good if r["value"] > best["value"] + 1e-8 * (1 + abs(best["value"]))]
        if better:
            b = max(better, key=lambda r: r["value"])
            note = (f"; note: non-converged start {b['start']} ended higher ({b['value']!r}, "
                    f"{b['message']})")
    starts_out = [{k: v for k, v in r.items() if k not in ("_z", "_kind")} for r in records]
    wall = time.perf_counter() - t0
    if best is None:
        if all(r["_kind"] is StartOutcome.failed for r in records):
            status, msg = OptimumStatus.failed, "the solver failed at the end point of every start (see starts, failures)"
        else:
            viols = [r["max_violation"] for r in records if r["_kind"] is StartOutcome.infeasible]
            status = OptimumStatus.infeasible
            msg = (f"no start reached a feasible design: the constraints cannot be met inside the bounds "
                   f"(smallest violation {min(viols):.3g}; tolerance {feasibility_tol:g})")
        return SetaOptimum(objective=objective_name, design={}, seta=None, value=math.nan, line=None,
                           active_constraints=[], constraints={}, evaluations=prob.evaluations,
                           starts=starts_out, status=status.value, message=msg,
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
    status = OptimumStatus.optimal if best["_kind"] is StartOutcome.converged else OptimumStatus.not_converged
    if status is OptimumStatus.not_converged:
        note += f"; KKT relative residual {kkt['relative_residual']:.2g} > {_KKT_TOL:g}"
    if skipped:
        note += f"; {skipped} start candidates skipped (outside the angle domain or solver failure)"
    msg = (f"best of {starts} starts (start {best['start']}): KKT relative residual "
           f"{best['kkt_relative_residual']:.2g} after {best['polishes']} polish restarts "
           f"(SLSQP: {best['message']}); "
           f"{sum(r['_kind'] is StartOutcome.converged for r in records)} converged, "
           f"{sum(r['_kind'] is StartOutcome.infeasible for r in records)} infeasible, "
           f"{sum(r['_kind'] is StartOutcome.failed for r in records)} failed" + note)
    dxdz = space.dx_dz(zf)
    grad_x = {n: float(g / d) for n, g, d in zip(space.names, rec["grad_z"], dxdz)}
    return SetaOptimum(objective=objective_name, design=design, seta=seta, value=rec["value"], line=line,
                       active_constraints=active,
                       constraints=dict(zip(rec["cons_names"], map(float, rec["cons"]))),
                       evaluations=prob.evaluations, starts=starts_out, status=status.value, message=msg,
                       variables=space.variables(zf), gradient=grad_x, kkt=kkt, failures=prob.failures,
                       wall_time=time.perf_counter() - t0)


_SCENE_KEYS = {"objective", "ft", "vary", "constraints", "starts", "seed", "fixed", "method", "maxiter",
               "include_base", "quadrature_nodes"}


def optimize_from_scene(spec: dict) -> SetaOptimum:
    """Run :func:`optimize_seta` from a scene's ``[optimize]`` table given as a plain dict.

    Parameters
    ----------
    spec : dict
        Keys (anything else is a ``ValueError``):

        * ``objective`` (required): "max_pull_off", "area" or "pull_off_at";
        * ``ft``: the shear force of "pull_off_at" (required there, not allowed otherwise);
        * ``vary`` (required): {parameter: [lower, upper]}; parameters: EI1, EI2, EA1, EA2, l1, l2,
          alpha1, alpha2, w, "EI2/EI1", "l2/l1", "alpha1+alpha2";
        * ``constraints``: {"not_sticky": bool, "fn0_min": float};
        * ``fixed``: {parameter: value} for parameters not varied (default: the paper's reference
          scene); a parameter may also be given at the top level of the table (e.g. ``EA2 = 50``),
          but not in both places;
        * ``starts`` (default 8), ``seed`` (0), ``method`` ("SLSQP"), ``maxiter`` (100),
          ``include_base`` (true), ``quadrature_nodes`` (48, for "area").

    Returns
    -------
    SetaOptimum

    Raises
    ------
    ValueError
        If a key or a value is not allowed.

    Examples
    --------
    >>> from gecko.optimize import optimize_from_scene
    >>> opt = optimize_from_scene({"objective": "max_pull_off", "vary": {"alpha2": [0.05, 1.0]},
    ...                            "constraints": {"not_sticky": True}, "starts": 2})
    >>> opt.status, round(opt.design["alpha2"], 4)
    ('optimal', 0.5472)
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
