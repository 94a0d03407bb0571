#!/usr/bin/env python3
"""Re-run gecko (the one on PYTHONPATH) on a finished campaign's states and compare: Fn, beta and
status bitwise against what the campaign recorded, and the turning-point counts against the
verifier's sign changes of theta' (stored in the campaign). Shows that a later solver gives the
campaign's numbers, without re-running the verifier (~1.5 CPU-h for 10,000 designs).

    PYTHONPATH=<gecko> python3 bench/stress/recheck.py bench/stress/stress_10000.npz [--workers 2] [--json out.json]
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import campaign  # noqa: E402


def _solve(args):
    P, FT = args
    import gecko
    out = []
    for p, ft in zip(P, FT):
        L = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, p))).critical_line(Ft=ft, errors="nan")
        out.append((L.Fn, L.theta_joint, L.status, L.turning_points_beam, L.turning_points_spatula))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    z = np.load(args.npz)
    P, FT = z["P"], z["FT"]
    t0 = time.time()
    parts = [(P[k::args.workers], FT[k::args.workers]) for k in range(args.workers)]
    with mp.get_context("fork").Pool(args.workers) as pool:
        res = pool.map(_solve, parts)
    n = P.shape[0]
    cols = [np.empty((n, FT.shape[1]), dtype=t) for t in (np.float64, np.float64, np.int64, np.int64, np.int64)]
    for k, r in enumerate(res):
        for j, row in zip(range(k, n, args.workers), r):
            for c, x in zip(cols, row):
                c[j] = x
    Fn, beta, status, tpb, tps = cols
    v = {k[2:]: z[k] for k in z.files if k.startswith("v_")}
    cl = campaign.classify(P, FT, z["Fn"], z["beta"], z["status"], v)
    ok = z["status"] == 0
    checked = ok & ~cl["inconclusive_fn"] & (v["turns_beam"] >= 0)
    agree = checked & (v["turns_beam"] == tpb) & (v["turns_spatula"] == tps)
    out = dict(campaign=os.path.relpath(args.npz), designs=int(n), states=int(status.size),
               Fn_bitwise_equal=bool(Fn.tobytes() == z["Fn"].tobytes()),
               beta_bitwise_equal=bool(beta.tobytes() == z["beta"].tobytes()),
               status_equal=bool(np.array_equal(status, z["status"])),
               turning_counts_changed=int(((tpb != z["tpb"]) | (tps != z["tps"]))[ok].sum()),
               turning_counts_checked=int(checked.sum()), turning_counts_agree=int(agree.sum()),
               seconds=round(time.time() - t0, 1))
    return campaign.print_json(out, args.json)


if __name__ == "__main__":
    main()
