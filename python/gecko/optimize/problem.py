"""The optimisation problem SLSQP sees: constraints, and one cached evaluation per scaled point
(objective, constraints and their gradients in z; solver failures penalised, never used)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional, Any

import numpy as np

from .objectives import (_EvaluationFailure, _finite_user_value, _INDEX, _OBJECTIVE_FUNCS, _design_seta, _sens,
                         FIELDS)
from .space import _ANGLE_MARGIN, _HALF_PI, _Space


@dataclass
class Constraint:
    """A user constraint g(design) >= 0 for :func:`gecko.optimize_seta`.

    Parameters
    ----------
    name : str
        Shown in ``SetaOptimum.active_constraints`` and in messages.
    fun : callable
        ``fun(design: dict) -> float``, with the nine design fields by name.
    jac : callable, optional
        ``jac(design) ->`` dict of partial derivatives by parameter name (missing names count as 0)
        or a length-9 array in the order of the design fields. Without it the gradient is a central
        difference of ``fun`` in the scaled variables (step 1e-6): exact gradients are used for
        everything gecko computes, a user function is the user's.

    Examples
    --------
    >>> import gecko
    >>> short = gecko.Constraint("l2 <= 0.15", lambda d: 0.15 - d["l2"], jac=lambda d: {"l2": -1.0})
    >>> short.fun({"l2": 0.1}) > 0
    True
    """

    name: str
    fun: Callable[[dict], float]
    jac: Optional[Callable[[dict], Any]] = None


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
