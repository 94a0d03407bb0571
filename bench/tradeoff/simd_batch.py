#!/usr/bin/env python3
"""Batch path of gecko's float64 ufuncs F, E and R_F per SIMD level and thread count, with
scipy.special beside it, in one run (issue 16, item 2); and the cost of one Python scalar call
against scipy.special's (issue 16, item 1).

    PYTHONPATH=python python3 bench/tradeoff/simd_batch.py          # ~1-2 min; writes bench/results/simd_batch.{csv,md}
    PYTHONPATH=python python3 bench/tradeoff/simd_batch.py --quick  # smoke test, prints only

Inputs: the bench/elliptic sets (phi ~ U(0, pi/2), m ~ U(0, 1); R_F: x, y, z log-uniform in
[1e-6, 1e6], 5 % one zero), repeated to 1e6 elements, each repetition in its own random order
(a plain tile repeats one sequence, which a branch predictor learns; bench/tradeoff/run.py,
shuffled_order). Every configuration (level x threads, and
scipy) runs once per round, rounds interleaved, so that the load of this shared machine falls on
all of them alike; the median wall time over the rounds is reported, and ratios within the run
(against scipy and against gecko's scalar loop on 1 thread) are the figures to compare.
Also called by bench/tradeoff/run.py, whose rows it appends to tradeoff.csv.
"""
import argparse
import datetime
import math
import os
import pathlib
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))
from run import make_row, read_column_file, rel_err_eps, shuffled_order, write_csv  # noqa: E402

CASES = [  # family, input set (as in bench/elliptic), data file, columns, reference, scipy name, gecko name
    ("F", "phi~U(0,pi/2), m~U(0,1)", "legendre_uniform.bin", ("phi", "m"), "F", "ellipkinc", "ellint_f"),
    ("E", "phi~U(0,pi/2), m~U(0,1)", "legendre_uniform.bin", ("phi", "m"), "E", "ellipeinc", "ellint_e"),
    ("R_F", "x,y,z log-U(1e-6,1e6), 5% one zero", "carlson_rf.bin", ("x", "y", "z"), "RF", "elliprf", "carlson_rf"),
]


def time_simd_batch(quick, gecko_mod, n_target=None, rounds=None):
    """Rows (bench/tradeoff/run.py FIELDS) for every family x {scipy, gecko level x threads}."""
    import numpy as np
    import scipy.special as sp
    ell = gecko_mod.elliptic
    n_target = n_target or (200_000 if quick else 1_000_000)
    rounds = rounds or (3 if quick else 9)
    levels = ell.simd_levels()
    rows = []
    for family, set_name, fname, argn, ref, sname, gname in CASES:
        data = read_column_file(ROOT / "bench" / "elliptic" / "data" / fname)
        idx = shuffled_order(len(data[ref]), n_target)  # each repetition of the set in its own order
        args = [np.ascontiguousarray(data[a][idx]) for a in argn]
        hi, lo = data[ref][idx], data[ref + "_lo"][idx]
        uf, sfn = getattr(ell.ufuncs, gname), getattr(sp, sname)
        configs = [(f"scipy.special.{sname}", "numpy array, 1 thread", None, None)]
        configs += [(f"gecko.elliptic.ufuncs.{gname}", f"SIMD {lv}, {t} thread{'s' if t > 1 else ''}", lv, t)
                    for lv in levels for t in (1, 2)]
        out = np.empty(n_target)

        def run(cfg):
            _, _, lv, t = cfg
            if lv is None:
                sfn(*args, out=out)
                return
            before_l, before_t = ell.set_simd_level(lv), ell.set_num_threads(t)
            try:
                uf(*args, out=out)
            finally:
                ell.set_simd_level(before_l)
                ell.set_num_threads(before_t)

        times = {c: [] for c in configs}
        errs = {}
        for c in configs:
            run(c)  # warm-up, and the error of this configuration's results
            errs[c] = rel_err_eps(out, hi, lo)
        for _ in range(rounds):
            for c in configs:
                t0 = time.perf_counter()
                run(c)
                times[c].append(time.perf_counter() - t0)
        med = {c: sorted(v)[len(v) // 2] for c, v in times.items()}
        t_scipy = med[configs[0]]
        t_scalar1 = med[next(c for c in configs if c[2] == "scalar" and c[3] == 1)]
        for c in configs:
            s = sorted(times[c])
            mx, rms, bad = errs[c]
            rows.append(make_row(
                family=family, method=c[0], setting=c[1], input_set=set_name, n=n_target,
                time_per_call_ns=med[c] / n_target * 1e9, time_q1_ns=s[len(s) // 4] / n_target * 1e9,
                time_q3_ns=s[(3 * len(s)) // 4] / n_target * 1e9, max_err=mx, rms_err=rms, unit="eps",
                failed=bad, source="simd_batch.py",
                note=f"batch of {n_target} elements, wall time, median of {rounds} interleaved rounds; "
                     f"speed-up vs scipy {t_scipy / med[c]:.2f}x, vs gecko scalar 1 thread {t_scalar1 / med[c]:.2f}x"))
    return rows


def time_scalar_calls(gecko_mod, reps=7, calls=20000):
    """Per-call time of a Python scalar call, gecko against scipy.special, interleaved; also 0-d
    numpy input. Returns [(what, gecko ns, scipy ns)]."""
    import numpy as np
    import scipy.special as sp
    g = gecko_mod
    cases = [("F(0.7, 0.4), floats", lambda: g.ellint_f(0.7, 0.4), lambda: sp.ellipkinc(0.7, 0.4)),
             ("E(0.7, 0.4), floats", lambda: g.ellint_e(0.7, 0.4), lambda: sp.ellipeinc(0.7, 0.4)),
             ("R_F(1, 2, 3), floats", lambda: g.carlson_rf(1.0, 2.0, 3.0), lambda: sp.elliprf(1.0, 2.0, 3.0))]
    p0, m0 = np.array(0.7), np.array(0.4)
    cases.append(("F, 0-d arrays", lambda: g.ellint_f(p0, m0), lambda: sp.ellipkinc(p0, m0)))
    res = []
    for what, gf, sf in cases:
        tg, ts = [], []
        for _ in range(reps):
            for fn, acc in ((gf, tg), (sf, ts)):
                t0 = time.perf_counter()
                for _ in range(calls):
                    fn()
                acc.append((time.perf_counter() - t0) / calls * 1e9)
        res.append((what, sorted(tg)[reps // 2], sorted(ts)[reps // 2]))
    return res


def markdown(rows, scalar, info):
    lines = ["# gecko float64 ufuncs per SIMD level against scipy.special (bench/tradeoff/simd_batch.py)", "",
             f"Generated by `{info['command']}` on {info['date']}.", "",
             f"- Machine: {info['cpu']} ({os.cpu_count()} logical CPUs); load average {info['load_start']} at start, "
             f"{info['load_end']} at end: shared, so compare ratios within this run.",
             "- Timing: wall time of one call over the whole batch, median of the interleaved rounds; "
             "ns per element. scipy.special runs on one thread.",
             f"- SIMD levels available here: {', '.join(info['levels'])}.", "",
             "| function | method | setting | ns/element | max err (eps) | vs scipy | vs gecko scalar, 1 thread |",
             "|---|---|---|---:|---:|---:|---:|"]
    for r in rows:
        note = r["note"]
        vs_s = note.split("vs scipy ")[1].split("x")[0]
        vs_g = note.split("1 thread ")[-1].rstrip("x")
        lines.append(f"| {r['family']} | {r['method']} | {r['setting']} | {r['time_per_call_ns']:.2f} | "
                     f"{r['max_err']:.2f} | {vs_s} | {vs_g} |")
    lines += ["", "Python scalar call (one call, interpreter included; median ns per call):", "",
              "| call | gecko | scipy.special | gecko / scipy |", "|---|---:|---:|---:|"]
    for what, tg, ts in scalar:
        lines.append(f"| {what} | {tg:.0f} | {ts:.0f} | {tg / ts:.2f} |")
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="smaller batch, fewer rounds, print only")
    ap.add_argument("--out", type=pathlib.Path, default=ROOT / "bench" / "results")
    args = ap.parse_args(argv)
    import gecko
    info = {"command": "PYTHONPATH=python python3 bench/tradeoff/simd_batch.py" + (" --quick" if args.quick else ""),
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "cpu": _cpu(), "load_start": " ".join(f"{x:.2f}" for x in os.getloadavg()),
            "levels": gecko.elliptic.simd_levels()}
    rows = time_simd_batch(args.quick, gecko)
    scalar = time_scalar_calls(gecko, reps=3 if args.quick else 7)
    info["load_end"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    text = markdown(rows, scalar, info)
    print(text)
    if not args.quick:
        args.out.mkdir(parents=True, exist_ok=True)
        write_csv(rows, args.out / "simd_batch.csv")
        (args.out / "simd_batch.md").write_text(text)
        print(f"wrote {args.out}/simd_batch.csv and simd_batch.md")
    return 0


def _cpu():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    import platform
    return platform.processor() or platform.machine()


if __name__ == "__main__":
    sys.exit(main())
