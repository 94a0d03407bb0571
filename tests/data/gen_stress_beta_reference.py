#!/usr/bin/env python3
"""Generate tests/data/stress_beta_reference.csv: campaign states (validation/results/stress.md) whose
beta the double-precision verifier cannot confirm (strong tension: its tip-to-joint shot has
|dbeta/dFn| ~ 1e5..1e8), solved at 60 digits by the Taylor-series shooting of
validation/beta_conditioning.py (order 40, mpmath; root Fn* of theta1(0) = alpha1 by secant to
1e-30, beta* = theta2(l1) there; the same at twice the steps agrees to < 1e-40).

Input: validation/results/stress_beta.json (written by beta_conditioning.py --json) for the designs, Ft
and the starting Fn of the secant; the reference values are recomputed here.

    python3 tests/data/gen_stress_beta_reference.py
"""
import csv
import json
import os
import sys

import mpmath as mp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", ".."))  # a script: the repository root for the validation package
from validation import beta_conditioning  # noqa: E402

FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")


def main():
    mp.mp.dps = beta_conditioning.DPS
    with open(os.path.join(HERE, "..", "..", "bench", "results", "stress_beta.json")) as f:
        states = json.load(f)
    with open(os.path.join(HERE, "stress_beta_reference.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(FIELDS) + ["Ft", "Fn_star", "beta_star", "dbeta_dFn_tip_shot"])
        for s in states:
            d = dict(zip(FIELDS, s["design"]))
            fs, bs, cond, ierr = beta_conditioning.root(d, s["Ft"], s["Fn"])
            assert ierr < mp.mpf("1e-35"), ierr
            w.writerow([repr(float(x)) for x in s["design"]] + [repr(s["Ft"]), mp.nstr(fs, 25), mp.nstr(bs, 25),
                                                                 mp.nstr(cond, 6)])
            print(d, s["Ft"], mp.nstr(fs, 20), mp.nstr(bs, 20), flush=True)


if __name__ == "__main__":
    main()
