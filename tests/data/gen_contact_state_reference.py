#!/usr/bin/env python3
"""Reference data for the forward problem of the two-level seta (contact state at a given load).

Regenerate (from the repository root, with the package importable; about 1-3 min):

    PYTHONPATH=python python3 tests/data/gen_contact_state_reference.py

Output: tests/data/contact_state_reference.csv, one equilibrium per row: the design (9 numbers),
the load (Fn, Ft), a class label (exact / near_singular / random), and the ODE's a, theta2(l1),
theta2'(l1), theta1'(0) and turning points, inputs with repr() (exact doubles), results with 17
significant digits.

Route: ODE shooting of the governing equations (paper 001 eqs 1-2 with the joint conditions eq 4,
the base eq 5 and Griffith's condition eq 3 at the edge), with no first integral and no elliptic
integral: from the base, theta1(0) = alpha1 and an unknown theta1'(0), integrate
    EI_i theta'' = -(Fn sin theta + Ft cos theta)(1 + (Ft sin theta - Fn cos theta)/EA_i)
in the convected coordinate s (scipy DOP853, rtol = 2.5e-14, atol = 1e-16) over the beam, apply
theta2 = theta1 + alpha2 and EI2 theta2' = EI1 theta1' at s = l1, and integrate the spatula until
theta2 first reaches pi/2 going up (the contact edge s = a; going down there would put the spatula
behind the substrate). The shot is right when Griffith's condition holds there:
    1/2 EI2 theta2'(a)^2 + Ft^2/(2 EA2) - w = 0,
solved for theta1'(0) by Brent's method to full precision. The library is used only to choose the
loads (and a starting bracket for theta1'(0)); the numbers in the table are the ODE's.
"""
from __future__ import annotations

import csv
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "contact_state_reference.csv")
RTOL, ATOL = 2.5e-14, 1e-16  # near the floor of DOP853 in double (rtol 1e-13 left 2e-11 in a at Ft = 9)
FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")


def rhs_factory(EI, EA, Fn, Ft):
    c = 0.0 if math.isinf(EA) else 1.0 / EA

    def rhs(s, y):
        th, om = y
        T = Ft * math.sin(th) - Fn * math.cos(th)
        return [om, -(Fn * math.sin(th) + Ft * math.cos(th)) * (1 + c * T) / EI]
    return rhs


def shoot(d, Fn, Ft, k0, s_max_extra=2.0):
    """Integrates from the base with theta1'(0) = k0. Returns (griffith residual, a, beta, rate_joint,
    sign changes of theta') or None when the spatula never reaches pi/2 going up."""
    r1 = rhs_factory(d["EI1"], d["EA1"], Fn, Ft)
    sol1 = solve_ivp(r1, (0.0, d["l1"]), [d["alpha1"], k0], method="DOP853", rtol=RTOL, atol=ATOL,
                     dense_output=False)
    th, om = sol1.y[0, -1], sol1.y[1, -1]
    ch1 = int(np.sum(np.diff(np.sign(sol1.y[1])) != 0))
    beta, omj = th + d["alpha2"], d["EI1"] / d["EI2"] * om
    r2 = rhs_factory(d["EI2"], d["EA2"], Fn, Ft)

    def edge(s, y):
        return y[0] - math.pi / 2
    edge.terminal = True
    edge.direction = 1
    s_end = d["l1"] + s_max_extra * d["l2"]
    if beta >= math.pi / 2 and omj >= 0:  # already past the edge orientation going up: not a state here
        return None
    sol2 = solve_ivp(r2, (d["l1"], s_end), [beta, omj], method="DOP853", rtol=RTOL, atol=ATOL, events=edge)
    if not len(sol2.t_events[0]):
        return None
    a = sol2.t_events[0][0]
    oma = sol2.y_events[0][0][1]
    c2 = 0.0 if math.isinf(d["EA2"]) else 1.0 / d["EA2"]
    g = 0.5 * d["EI2"] * oma * oma + c2 * Ft * Ft / 2 - d["w"]
    ch2 = int(np.sum(np.diff(np.sign(sol2.y[1])) != 0))
    return g, a, beta, omj, ch1 + ch2


def solve_state(d, Fn, Ft, k_guess):
    """theta1'(0) near k_guess where the shot satisfies Griffith's condition."""
    def g(k):
        r = shoot(d, Fn, Ft, k)
        return math.nan if r is None else r[0]
    for width in (1e-6, 1e-4, 1e-3, 1e-2, 1e-1):
        h = width * (1 + abs(k_guess))
        lo, hi = k_guess - h, k_guess + h
        glo, ghi = g(lo), g(hi)
        if glo == glo and ghi == ghi and glo * ghi < 0:
            k = brentq(g, lo, hi, xtol=1e-16, rtol=4 * np.finfo(float).eps, maxiter=200)
            return k, shoot(d, Fn, Ft, k)
    return None, None


def main():
    sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
    import gecko

    rng = np.random.default_rng(20261125)
    cases = []  # (label, design dict, Fn, Ft)

    ref = {f: getattr(gecko.TwoLevelSeta(), f) for f in FIELDS}
    inext = dict(ref, EA2=math.inf)
    ext1 = dict(ref, EA1=100.0)
    # Exact: the reference scene and its Fig 2 variants at loads between the critical line and
    # the joint.
    for d in (ref, inext, ext1):
        seta = gecko.TwoLevelSeta(**d)
        fts = [0.0, 1.0, 3.0, 5.0, 7.0, 9.0] if not math.isinf(d["EA2"]) else [0.0, 2.0, 6.0, 12.0]
        crit = seta.critical_line(Ft=np.array(fts))
        for ft, fn in zip(fts, crit.Fn):
            # loads with contact: just above the line at low Ft, just below it where the line has
            # turned (near (Ft)max the edge moves towards the joint as the pull grows)
            kept = 0
            for off in (0.5, 0.2, 0.05, -0.05, 0.01, -0.01, 1e-3, -1e-3):
                if kept < 3 and int(seta.contact_state(float(fn + off), ft, errors="nan").status) == 0:
                    cases.append(("exact", d, float(fn + off), ft))
                    kept += 1
    # Near-singular: a at l1 + l2 (Fn just above the critical line), Ft near (Ft)max (edge rate
    # -> 0), Ft near -(Ft)max, tiny loads.
    seta = gecko.TwoLevelSeta(**ref)
    for ft in (0.0, 7.0, 9.99, 9.9999):
        fn = float(seta.critical_line(Ft=np.array([ft])).Fn[0])
        for off in (1e-9, 1e-6, -1e-9, -1e-6):
            if int(seta.contact_state(fn + off, ft, errors="nan").status) == 0:
                cases.append(("near_singular", ref, fn + off, ft))
    for fn in (0.3, 1.0, 2.0):
        cases.append(("near_singular", ref, fn, -9.99))  # Ft near -(Ft)max
    sticky = dict(ref, EI1=4.0, EI2=1.5)  # sticky at rest (eq 22), a - l1 = 0.078 without load
    cases.append(("near_singular", sticky, 1e-9, 0.0))
    cases.append(("near_singular", sticky, 0.0, 1e-9))
    cases.append(("near_singular", sticky, -1e-9, -1e-9))
    # Random designs (the box of the critical-line tests), random Ft, Fn above the critical line.
    n_random = 0
    while n_random < 40:
        d = dict(EI1=float(rng.uniform(1, 10)), EI2=float(rng.uniform(0.2, 5)),
                 EA1=float(rng.choice([math.inf, rng.uniform(50, 500)])),
                 EA2=float(rng.choice([math.inf, rng.uniform(20, 200)])),
                 l1=1.0, l2=float(rng.uniform(0.05, 0.4)), alpha1=float(rng.uniform(0.1, 0.9)),
                 alpha2=0.0, w=1.0)
        d["alpha2"] = float(rng.uniform(0.0, 0.95) * (math.pi / 2 - d["alpha1"]))
        seta = gecko.TwoLevelSeta(**d)
        ftmax = seta.ft_max if math.isfinite(seta.ft_max) else 10.0
        ft = float(rng.uniform(-0.3, 0.9) * ftmax)
        crit = seta.critical_line(Ft=np.array([ft]), errors="nan")
        if crit.status[0] != 0:
            continue
        fn = float(crit.Fn[0] + rng.uniform(0.01, 1.5))
        r = seta.contact_state(fn, ft, errors="nan")
        if int(r.status) != 0:
            continue
        cases.append(("random", d, fn, ft))
        n_random += 1

    rows = []
    for label, d, Fn, Ft in cases:
        seta = gecko.TwoLevelSeta(**d)
        r = seta.contact_state(Fn, Ft, errors="nan")
        if int(r.status) != 0:
            print("skip (library status %d):" % int(r.status), label, Fn, Ft, file=sys.stderr)
            continue
        k, shot = solve_state(d, Fn, Ft, float(r.theta_rate_base))
        if shot is None:
            print("skip (no ODE root near the library's):", label, Fn, Ft, file=sys.stderr)
            continue
        g, a, beta, omj, changes = shot
        rows.append([label] + [repr(d[f]) for f in FIELDS] + [repr(Fn), repr(Ft)] +
                    ["%.17g" % v for v in (a, beta, omj, k)] + [str(changes), "%.3g" % g])
    with open(OUT, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["class"] + list(FIELDS) + ["Fn", "Ft", "a", "theta_joint", "theta_rate_joint",
                                                "theta_rate_base", "turning_points", "griffith_residual"])
        w.writerows(rows)
    print("wrote", len(rows), "rows to", OUT)


if __name__ == "__main__":
    main()
