"""The two-level seta critical line the way a researcher would script it: scipy ``quad`` for the two
length integrals and ``fsolve`` for (Fn, beta), continued along Ft from the previous solution.

This is the benchmark's speed-and-accuracy peer (bench/seta/peer_scipy.py times it). It uses no
gecko code. Model: paper 001 eqs 8-15, as restated in docs/theory/two_level_seta.md: with
N = |(Fn, Ft)|, phi = atan2(Fn, Ft) and u = sin(theta - phi), the first integral of segment i is

    1/2 EI_i theta'^2 = M_i - N u - N^2 u^2 / (2 EA_i),

with M2 = Ft + w from Griffith's condition at the contact edge and M1 from continuity of the
moment at the joint. At the critical state a = l1 + l2, so the lengths l2 = int_beta^{pi/2}
dtheta/theta2' and l1 = int_{alpha1}^{beta - alpha2} dtheta/theta1' must both match the design.

Double precision, and it assumes theta grows monotonically along both segments: where the
elastica has a turning point (theta' = 0 inside a segment) the integrals are wrong and fsolve
reports failure or converges to a wrong state. The reference scene has none up to Ft = 9.9.

    python3 bench/seta/scipy_peer.py      # 200 points of the reference scene's line
"""
from __future__ import annotations

import math
from typing import Mapping, Sequence, Tuple

import numpy as np
from scipy.integrate import quad
from scipy.optimize import fsolve

#: the two-level seta paper's reference scene (non-dimensional: w = 1, l1 = 1)
REFERENCE = {"EI1": 5.0, "EI2": 2.0, "EA1": math.inf, "EA2": 50.0, "l1": 1.0, "l2": 0.1,
             "alpha1": math.pi / 6, "alpha2": math.pi / 6, "w": 1.0}

#: quadrature tolerances (absolute and relative) and fsolve's xtol
QUAD_TOL = 1e-13
XTOL = 1e-13


def _compliance(EA: float) -> float:
    """1/EA, with the inextensible limit EA = inf giving 0."""
    return 0.0 if math.isinf(EA) else 1.0 / EA


def _segment_length(EI: float, c: float, M: float, N: float, phi: float,
                    start: float, end: float) -> float:
    """Arc length over which theta runs from start to end: int dtheta / theta'(theta)."""
    def dtheta_ds_inverse(theta: float) -> float:
        u = math.sin(theta - phi)
        radicand = 2.0 / EI * (M - N * u - 0.5 * N * N * c * u * u)
        # A non-positive radicand means a turning point this peer does not handle: clamp so that
        # quad returns a (wrong, large) number and fsolve reports the failure.
        return 1.0 / math.sqrt(max(radicand, 1e-300))
    return quad(dtheta_ds_inverse, start, end, epsabs=QUAD_TOL, epsrel=QUAD_TOL)[0]


def length_mismatch(x: Sequence[float], Ft: float, p: Mapping[str, float]) -> Tuple[float, float]:
    """(spatula length - l2, beam length - l1) at the critical state for x = (Fn, beta)."""
    Fn, beta = float(x[0]), float(x[1])
    c1, c2 = _compliance(p["EA1"]), _compliance(p["EA2"])
    N = math.hypot(Fn, Ft)
    phi = math.atan2(Fn, Ft)
    M2 = Ft + p["w"]                                   # contact edge: theta2 = pi/2, Griffith
    u_joint2 = math.sin(beta - phi)                    # spatula side of the joint
    u_joint1 = math.sin(beta - p["alpha2"] - phi)      # beam side: theta1 = beta - alpha2
    # Moment continuity EI1 theta1' = EI2 theta2' at the joint, squared, through both first integrals.
    M1 = (p["EI2"] / p["EI1"] * (M2 - N * u_joint2 - 0.5 * N * N * c2 * u_joint2 ** 2)
          + N * u_joint1 + 0.5 * N * N * c1 * u_joint1 ** 2)
    spatula = _segment_length(p["EI2"], c2, M2, N, phi, beta, math.pi / 2)
    beam = _segment_length(p["EI1"], c1, M1, N, phi, p["alpha1"], beta - p["alpha2"])
    return spatula - p["l2"], beam - p["l1"]


def critical_line(p: Mapping[str, float], Ft: Sequence[float], guess=(0.25, 1.47)):
    """Natural continuation along Ft. Returns arrays (Fn, beta, converged)."""
    Ft = np.asarray(Ft, dtype=float)
    Fn = np.empty_like(Ft)
    beta = np.empty_like(Ft)
    ok = np.zeros(Ft.shape, dtype=bool)
    x = np.array(guess, dtype=float)
    for i, f in enumerate(Ft):
        sol, _info, ier, _msg = fsolve(length_mismatch, x, args=(float(f), p), xtol=XTOL,
                                       full_output=True)
        Fn[i], beta[i], ok[i] = sol[0], sol[1], ier == 1
        x = sol
    return Fn, beta, ok


if __name__ == "__main__":
    import os
    import sys
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, timing helper
    from _timing import timed_once

    grid = np.linspace(0.0, 9.6, 200)
    (Fn, beta, ok), dt = timed_once(lambda: critical_line(REFERENCE, grid))
    print(f"scipy peer: {grid.size} points in {dt:.3f} s = {dt / grid.size * 1e6:.0f} us/point")
    for i in range(0, grid.size, 40):
        print(f"Ft={grid[i]:.3f} Fn={Fn[i]:.12f} theta_joint={beta[i]:.12f} converged={ok[i]}")
