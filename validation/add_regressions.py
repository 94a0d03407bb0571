#!/usr/bin/env python3
"""Append the worst cases of a campaign to tests/data/stress_regressions.csv (kind verify: the
largest verified Fn differences and the largest beta differences; kind bounded_time: the slowest
design and every timeout). Rows already in the file are not repeated.

    python3 -m validation.add_regressions validation/stress_10000.npz [--top 3]
"""
import csv
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
from . import campaign  # noqa: E402

CSV = os.path.join(HERE, "..", "tests", "data", "stress_regressions.csv")


def main(path, top=3):
    z = np.load(path)
    P, FT, Fn, status, secs = z["P"], z["FT"], z["Fn"], z["status"], z["secs"]
    v = {k[2:]: z[k] for k in z.files if k.startswith("v_")}
    cl = campaign.classify(P, FT, Fn, z["beta"], status, v)
    gi = z["design_index"] if "design_index" in z.files else np.arange(P.shape[0])
    conc = (status == 0) & ~cl["inconclusive_fn"]
    rows = []
    for k in np.argsort(np.where(conc, cl["rel"], -1).ravel())[::-1][:top]:
        i, j = np.unravel_index(k, status.shape)
        rows.append(("verify", P[i], FT[i, j], f"campaign design {gi[i]}: largest verified |dFn|/max(1,|Fn|) = "
                                               f"{cl['rel'][i, j]:.2e} (threshold 1e-8)"))
    db = np.where(conc, np.abs(v["dbeta"]), -1)
    for k in np.argsort(db.ravel())[::-1][:top]:
        i, j = np.unravel_index(k, status.shape)
        rows.append(("verify", P[i], FT[i, j], f"campaign design {gi[i]}: |dbeta| = {db[i, j]:.1e} where beta is "
                                               f"inconclusive (hyperbolic spatula)"))
    for i in sorted(set(np.nonzero((status == -1).any(axis=1))[0]) | {int(np.argmax(secs))}):
        j = int(np.argmax(np.abs(FT[i])))
        rows.append(("bounded_time", P[i], FT[i, j], f"campaign design {gi[i]}: {secs[i]:.2f} s"
                                                     + (" (timeout)" if (status[i] == -1).any() else " (slowest)")))
    with open(CSV) as f:
        have = {(r["kind"], r["EI1"], r["Ft"]) for r in csv.DictReader(f)}
    added = 0
    with open(CSV, "a", newline="") as f:
        w = csv.writer(f)
        for kind, p, ft, note in rows:
            key = (kind, repr(float(p[0])), repr(float(ft)))
            if key in have:
                continue
            have.add(key)
            w.writerow([kind] + [repr(float(x)) for x in p] + [repr(float(ft)), note])
            added += 1
    print(f"added {added} rows to {CSV}")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[sys.argv.index("--top") + 1]) if "--top" in sys.argv else 3)
