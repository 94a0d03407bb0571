#!/usr/bin/env python3
"""mpmath reference for the line-end regressions of tests/seta/line_end.cpp.

Regenerate (from the repository root; about 1 min on a busy core):

    python3 tests/data/gen_seta_line_end.py      # writes tests/data/seta_line_end.csv

Each row: a design, a target (Ft = a given double, or "ft_max": the end of the critical line,
Ft = (Ft)max = sqrt(2 EA2 w) in mp with the edge rate theta2'(a) = 0) and the critical Fn there by
the ODE route of gen_seta_reference.py (arbitrary-precision Taylor shooting backwards from the
contact edge, seta_taylor.py; secant in Fn to 1e-27 relative; no Carlson forms, no C++ code). The
double-precision guess comes from marching seta_double.py's Newton along the line parameter
tau = (Ft)max asin(Ft/(Ft)max) from the natural state. Backward shooting is well conditioned in Fn
at the line end (the edge state is known there), so the 25 digits written are good to ~1e-25.

Designs: the lines that ended with no_convergence just short of (Ft)max, or where
critical_line_at reported no state just below it (see line_end.cpp for each one's story).
"""
import csv
import math
import os
import sys

from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import gen_seta_reference as gen  # noqa: E402
import seta_double as sd          # noqa: E402
import seta_taylor as st          # noqa: E402

INF = math.inf


def design(**kw):
    d = dict(EI1=5.0, EI2=2.0, EA1=INF, EA2=50.0, l1=1.0, l2=0.1, alpha1=math.pi / 6, alpha2=math.pi / 6, w=1.0)
    d.update(kw)
    return d


# (name, design, targets)
CASES = [
    ("critical_line_at_status2", design(EI2=1.25594322, l2=0.12247449, alpha1=0.57719755, alpha2=0.47),
     [9.99994, "ft_max"]),
    ("no_convergence_flat_end", design(EI1=1.7784969547876992, EI2=0.32850626876051325, EA2=164.52134544805176,
                                       l2=0.46074000977497476, alpha1=0.7825059404196725,
                                       alpha2=0.19357036447927514), ["ft_max"]),
    # Newton's step floor at (Ft)max above the corrector tolerance (turning point on the edge)
    ("sqrt_eps_floor", design(EI1=17.213023219163766, EI2=0.10691106261676941, EA2=481.39937290989201,
                              l2=0.49572309894677141, alpha1=0.313522669712262, alpha2=0.72174614704747442),
     ["ft_max"]),
    # the spatula's plans alternate at (Ft)max (turning point exactly on the contact edge)
    ("plan_boundary", design(EI1=18.256572915614299, EI2=0.10041451691810376, EA2=352.19192995474555,
                             l2=0.48369517241692828, alpha1=0.52646585202705465, alpha2=0.44324500512969128),
     ["ft_max"]),
    # sqrt(2 EA2 w) an ulp above / below sqrt(2 w / (1/EA2))
    ("ftmax_ulp_above", design(EA2=55.768574068568086), ["ft_max"]),
    ("ftmax_ulp_below", design(EA2=53.49324437076377), ["ft_max"]),
]


def march(dd, tau_target, n=400):
    """Double-precision Fn along the line at tau_target (Newton marching in tau from Ft = 0)."""
    Fn = sd.natural_state(dd)
    for k in range(1, n + 1):
        tau = tau_target * k / n
        Fn_new = sd.newton_fn(dd, sd.ft_of_tau(dd, tau), Fn, kappa=sd.kappa_of_tau(dd, tau))
        if Fn_new is None:
            raise RuntimeError(f"march failed at tau = {tau}")
        Fn = Fn_new
    return Fn


def main():
    mp.dps = 30
    rows = []
    for name, dd, targets in CASES:
        d = st.mp_design(dd)
        Fm = sd.ft_max(dd)
        for t in targets:
            if t == "ft_max":
                guess = march(dd, Fm * math.pi / 2)
                Fn, _ = st.solve_fn(d, mp.sqrt(2 * d["EA2"] * d["w"]), guess, rtol=mpf("1e-28"), kap=0)
            else:
                guess = march(dd, sd.tau_of_ft(dd, t))
                Fn, _ = st.solve_fn(d, mpf(t), guess, rtol=mpf("1e-28"))
            if Fn is None:
                raise RuntimeError(f"{name}: no mp solution at {t}")
            print(name, t, "guess", guess, "mp", mp.nstr(Fn, 25), flush=True)
            rows.append([name] + [gen.fmt_in(dd[k]) for k in gen.KEYS] + [t if t == "ft_max" else repr(t), gen.nstr(Fn)])
    with open(os.path.join(HERE, "seta_line_end.csv"), "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["case"] + gen.KEYS + ["Ft", "Fn"])
        wr.writerows(rows)


if __name__ == "__main__":
    main()
