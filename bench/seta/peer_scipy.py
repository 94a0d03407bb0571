#!/usr/bin/env python3
"""Times the scipy peer (bench/seta/scipy_peer.py, quad + fsolve) and the gecko Python call on the
same 1000-point reference-scene line as bench_seta, in the same run (bench/seta/run.sh), and
appends both rows to bench/results/seta.md / seta.csv.

The peer's error is measured against gecko's own line (tolerance 1e-14, itself within 4e-14 of the
mpmath references in tests/data/seta_reference.csv); the peer only handles monotone states, which
the reference scene has up to Ft = 9.9.
    python3 bench/seta/peer_scipy.py [--points 1000]
"""
import os
import sys

import numpy as np

import gecko

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))  # bench/, for the shared timing helper

import scipy_peer as peer  # noqa: E402  (bench/seta/scipy_peer.py, no gecko code)
from _timing import time_call, write_results  # noqa: E402


def main():
    n = 1000
    if "--points" in sys.argv:
        n = int(sys.argv[sys.argv.index("--points") + 1])
    Ft = np.linspace(0.0, 9.9, n)
    seta = gecko.TwoLevelSeta()
    ref = seta.critical_line(Ft=Ft, tolerance=1e-14).Fn
    tp = time_call(lambda: peer.critical_line(peer.REFERENCE, Ft), repeats=1)
    fn_peer, _beta, ok = tp.result
    dt_peer = tp.cpu_median / n * 1e6
    fn_peer = np.where(ok, fn_peer, np.nan)
    err_peer = np.nanmax(np.abs(fn_peer - ref) / np.maximum(1, np.abs(ref)))
    failed_peer = int(np.sum(~np.isfinite(fn_peer)))
    tg = time_call(lambda: seta.critical_line(Ft=Ft), repeats=7)
    g = tg.result
    dt_gecko = tg.cpu_median / n * 1e6
    err_gecko = np.max(np.abs(g.Fn - ref) / np.maximum(1, np.abs(ref)))
    rows = [("scipy peer (quad + fsolve)", "xtol 1e-13", dt_peer, err_peer, failed_peer),
            ("gecko Python TwoLevelSeta.critical_line", "default", dt_gecko, err_gecko, int(np.sum(g.status != 0)))]
    for r in rows:
        print(f"{r[0]:40s} {r[1]:12s} {r[2]:10.3f} us/point  err vs gecko 1e-14: {r[3]:.1e}  failed {r[4]}")
    out = os.path.join(ROOT, "bench", "results")
    write_results(os.path.join(out, "seta.csv"), "".join(f"{r[0]},{r[1]},{r[2]},{r[3]},{r[4]}\n" for r in rows),
                  append=True)
    md = ("\nPython, same grid, same run (process CPU time; the peer's error is against gecko at "
          "tolerance 1e-14, which matches the mpmath references to 4e-14):\n\n"
          "| method | setting | us/point | max rel. error of Fn | failed points |\n|---|---|---:|---:|---:|\n")
    md += "".join(f"| {r[0]} | {r[1]} | {r[2]:.3f} | {r[3]:.1e} | {r[4]} |\n" for r in rows)
    md += f"\nSpeed-up of the gecko Python call over the scipy peer on the same grid: {dt_peer / dt_gecko:.0f}x.\n"
    write_results(os.path.join(out, "seta.md"), md, append=True)


if __name__ == "__main__":
    main()
