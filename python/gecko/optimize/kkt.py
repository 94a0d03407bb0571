"""First-order optimality (KKT) check at an evaluated point: NNLS multipliers over the active
constraints and bounds."""
from __future__ import annotations

import numpy as np

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
