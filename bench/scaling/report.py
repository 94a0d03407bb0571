#!/usr/bin/env python3
"""bench/scaling/report.py — turns the output of bench_scaling (C++) into bench/results/scaling.*,
and adds the Python-side memory of gecko.critical_line_batch.

    python3 bench/scaling/report.py RAW_CSV OUT_DIR [--python-memory/--no-python-memory]

Fits (numpy least squares):
  * power law: log t = log c + s log n, over all n and over n >= 1000 (the asymptotic range, where a
    fixed per-call cost no longer matters); s = 1 means the cost is linear in n;
  * affine: t = a + b n, minimising the RELATIVE residuals (t_fit - t) / t so that small n count as
    much as large n; b is the cost per point (per design), a the fixed cost per call.
Memory (Python): each size in a fresh interpreter (python3 -c ...), VmHWM of /proc/self/status
before and after one call, and tracemalloc's peak (numpy arrays are traced; the C++ buffers of the
binding are not, they show in VmHWM only).
"""
import csv
import json
import math
import os
import io
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, shared helper
from _timing import write_results  # noqa: E402


def read_raw(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def power_fit(n, t):
    x, y = np.log(np.asarray(n, float)), np.log(np.asarray(t, float))
    A = np.vstack([np.ones_like(x), x]).T
    coef, res, *_ = np.linalg.lstsq(A, y, rcond=None)
    dof = max(len(x) - 2, 1)
    r = y - A @ coef
    cov = (r @ r / dof) * np.linalg.inv(A.T @ A)
    return {"slope": float(coef[1]), "slope_stderr": float(math.sqrt(cov[1, 1])),
            "prefactor_s": float(math.exp(coef[0])), "n_min": int(min(n)), "n_max": int(max(n)),
            "points": len(n)}


def affine_fit(n, t):
    n, t = np.asarray(n, float), np.asarray(t, float)
    A = np.vstack([1 / t, n / t]).T  # (a + b n) / t - 1 -> min
    coef, *_ = np.linalg.lstsq(A, np.ones_like(t), rcond=None)
    rel = (coef[0] + coef[1] * n - t) / t
    return {"fixed_s": float(coef[0]), "per_unit_s": float(coef[1]), "max_rel_residual": float(np.max(np.abs(rel)))}


PY_CHILD = r"""
import json, sys, tracemalloc
import numpy as np
import gecko
def hwm():
    for line in open('/proc/self/status'):
        if line.startswith('VmHWM:'):
            return int(line.split()[1]) * 1024
n, p = int(sys.argv[1]), int(sys.argv[2])
rng = np.random.default_rng(7)
EI1 = np.exp(np.log(0.5) + rng.random(n) * np.log(100.0))
EI2 = EI1 * np.exp(np.log(0.05) + rng.random(n) * np.log(40.0))
a1 = np.pi / 18 + rng.random(n) * (np.pi / 3 - np.pi / 18)
designs = np.column_stack([EI1, EI2, np.full(n, np.inf), np.exp(np.log(10.0) + rng.random(n) * np.log(100.0)),
                           np.ones(n), 0.02 + 0.48 * rng.random(n), a1, rng.random(n) * (np.pi / 2 - 0.15 - a1),
                           np.ones(n)])
Ft = np.linspace(0, 0.99 * np.sqrt(20.0), p)
gecko.critical_line_batch(designs[:2], Ft[:2])  # warm-up: first call's lazy allocations
before = hwm()
tracemalloc.start()
line = gecko.critical_line_batch(designs, Ft, errors="nan")
cur, peak = tracemalloc.get_traced_memory()
tracemalloc.stop()
after = hwm()
result_bytes = sum(getattr(line, k).nbytes for k in ("Ft", "Fn", "theta_joint", "status", "iterations",
                   "theta_rate_joint", "theta_rate_base", "turning_points_beam", "turning_points_spatula"))
print(json.dumps({"designs": n, "points": p, "rss_delta": after - before, "tracemalloc_peak": peak,
                  "tracemalloc_current": cur, "result_bytes": result_bytes, "input_bytes": designs.nbytes,
                  "converged": int((line.status == 0).sum())}))
"""


def python_memory(root):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(root, "python") + (":" + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    rows = []
    for n, p in ((1000, 20), (10000, 20), (100000, 20), (1000, 1000), (10000, 1000)):
        out = subprocess.run([sys.executable, "-c", PY_CHILD, str(n), str(p)], env=env, check=True,
                             capture_output=True, text=True).stdout
        rows.append(json.loads(out.strip().splitlines()[-1]))
        print("python memory:", rows[-1], flush=True)
    return rows


def main():
    raw_path, out_dir = sys.argv[1], sys.argv[2]
    do_python = "--no-python-memory" not in sys.argv
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    rows = read_raw(raw_path)
    for r in rows:
        for k in ("threads", "n", "points", "designs", "reps"):
            r[k] = int(r[k])
        for k in ("median_s", "min_s"):
            r[k] = float(r[k])
    res = {"machine": {}, "throughput": [], "scaling": {}, "memory_cpp": [], "memory_python": []}
    try:
        res["machine"]["loadavg"] = open("/proc/loadavg").read().strip()
        res["machine"]["cpus"] = os.cpu_count()
        res["machine"]["cpu"] = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                                      if l.startswith("model name")), "")
    except OSError:
        pass
    for r in rows:
        if r["kind"] == "throughput":
            extra = dict(kv.split("=") for kv in r["extra"].split(";") if kv)
            res["throughput"].append({"case": r["case"], "threads": r["threads"], "designs": r["designs"],
                                      "points_per_line": r["points"], "median_s": r["median_s"],
                                      "lines_per_s": r["designs"] / r["median_s"],
                                      "us_per_point": 1e6 * r["median_s"] / (r["designs"] * r["points"]),
                                      "reps": r["reps"], **{k: (float(v) if k.endswith("_s") else int(v)) for k, v in extra.items()}})
    for kind, unit in (("points", "point"), ("designs", "design")):
        sel = [r for r in rows if r["kind"] == kind]
        if not sel:
            continue
        n = [r["n"] for r in sel]
        t = [r["median_s"] for r in sel]
        big = [(a, b) for a, b in zip(n, t) if a >= 1000]
        res["scaling"][kind] = {
            "unit": unit, "n": n, "median_s": t, "min_s": [r["min_s"] for r in sel], "reps": sel[0]["reps"],
            "power_all": power_fit(n, t),
            "power_n_ge_1000": power_fit(*zip(*big)) if len(big) >= 2 else None,
            "power_n_ge_10000": power_fit(*zip(*[(a, b) for a, b in big if a >= 10000]))
            if sum(a >= 10000 for a, _ in big) >= 2 else None,
            "affine": affine_fit(n, t),
        }
    for r in rows:
        if r["kind"] == "memory":
            extra = dict(kv.split("=") for kv in r["extra"].split(";") if kv)
            analytic = float(extra["analytic_bytes"])
            res["memory_cpp"].append({"designs": r["designs"], "points_per_line": r["points"],
                                      "peak_rss_delta_bytes": r["median_s"], "analytic_bytes": analytic,
                                      "rss_per_design": r["median_s"] / r["designs"],
                                      "analytic_per_design": analytic / r["designs"],
                                      "sizeof_design": int(extra["sizeof_design"]),
                                      "sizeof_state": int(extra["sizeof_state"])})
    if do_python:
        res["memory_python"] = python_memory(root)
        for r in res["memory_python"]:
            r["analytic_peak"] = r["designs"] * (72 + 104 * r["points"])

    write_results(os.path.join(out_dir, "scaling.json"), json.dumps(res, indent=1))
    with io.StringIO(newline="") as f:
        w = csv.writer(f)
        w.writerow(["kind", "case", "threads", "n", "points_per_line", "designs", "median_s", "min_s", "reps", "extra"])
        for r in rows:
            w.writerow([r["kind"], r["case"], r["threads"], r["n"], r["points"], r["designs"], r["median_s"],
                        r["min_s"], r["reps"], r["extra"]])
        for m in res["memory_python"]:
            w.writerow(["memory_python", "random", 1, m["designs"], m["points"], m["designs"], "", "", 1,
                        f"rss_delta={m['rss_delta']};tracemalloc_peak={m['tracemalloc_peak']};"
                        f"result_bytes={m['result_bytes']};input_bytes={m['input_bytes']}"])
        write_results(os.path.join(out_dir, "scaling.csv"), f.getvalue())
    write_md(res, os.path.join(out_dir, "scaling.md"))
    plot(res, os.path.join(out_dir, "scaling.png"))


def write_md(res, path):
    L = []
    L.append("# Throughput and scaling of the seta critical line (bench/scaling)\n")
    L.append("Generated by `bench/scaling/run.sh` (C++ `bench_scaling`, Release, then `report.py`). "
             "Every time is that of one whole `gecko::critical_line_batch` call (natural state, continuation "
             "and the solve of every point included), median of the repetitions: lines/s from the WALL "
             "time (process CPU time beside it); the scaling runs (1 thread) in the CPU time of the calling "
             "thread, which the other jobs on this shared machine disturb far less than wall time.\n")
    m = res["machine"]
    L.append(f"- Machine: {m.get('cpu', '?')}, {m.get('cpus', '?')} CPUs, **shared with other jobs** "
             f"(load average at the end: {m.get('loadavg', '?')}); timings are noisy, the 2-thread "
             "numbers most of all (a second core is often busy).\n")
    L.append("- Reference scene: docs/theory/two_level_seta.md defaults, Ft = linspace(0, 9.9, points). Random designs: the box "
             "of bench/seta (EI1 in [0.5, 50], EI2/EI1 in [0.05, 2], l2 in [0.02, 0.5], alpha1 in [pi/18, "
             "pi/3], alpha2 in [0, pi/2 - 0.15 - alpha1], EA2 in [10, 1000], EA1 = inf); the batch call "
             "shares one Ft grid, linspace(0, 0.99 sqrt(20), points) (0.99 of the smallest (Ft)max of the box).\n")
    L.append("\n## Lines per second (batch call)\n")
    L.append("| designs | points/line | threads | lines/s (wall) | us/point (wall) | process CPU (s) | lines per CPU-second | states converged | 1 vs 2 threads bitwise |")
    L.append("|---|---:|---:|---:|---:|---:|---:|---:|---|")
    conv = {}
    for t in res["throughput"]:
        if "converged" in t:
            conv[(t["case"], t["points_per_line"])] = t["converged"]
    for t in res["throughput"]:
        ident = t.get("bitwise_identical_1_vs_2")
        c = conv.get((t["case"], t["points_per_line"]), "")
        L.append(f"| {t['designs']} {t['case']} | {t['points_per_line']} | {t['threads']} | {t['lines_per_s']:.0f} | "
                 f"{t['us_per_point']:.2f} | {t.get('process_cpu_s', float('nan')):.3g} | "
                 f"{t['designs'] / t.get('process_cpu_s', float('nan')):.0f} | {c} / {t['designs'] * t['points_per_line']} | "
                 f"{'' if ident is None else ('yes' if ident else 'NO')} |")
    L.append("\nLines per CPU-second = designs / process CPU time (all threads): the work, whatever the load; "
             "equal for 1 and 2 threads means the threads add no overhead. The wall-time speed-up of 2 threads "
             "needs a second idle core, which this machine rarely has (see the load average above).\n")
    L.append("\nBitwise: every field of every `critical_state` (Fn, theta_joint, rates, status, iterations, "
             "turning points) compared with memcmp between the 1- and 2-thread results, in every repetition.\n")
    for kind, title in (("points", "Time against points per line (reference scene, one design, 1 thread)"),
                        ("designs", "Time against designs per batch (random designs, 20 points each, 1 thread)")):
        s = res["scaling"].get(kind)
        if not s:
            continue
        L.append(f"\n## {title}\n")
        L.append(f"| n | median CPU time (s) | min (s) | time / n (us) |\n|---:|---:|---:|---:|")
        for n, t, tm in zip(s["n"], s["median_s"], s["min_s"]):
            L.append(f"| {n} | {t:.4g} | {tm:.4g} | {1e6 * t / n:.3f} |")
        pa, pb, af = s["power_all"], s["power_n_ge_1000"], s["affine"]
        L.append(f"\n- Power-law fit log t = log c + s log n, all n ({pa['n_min']}..{pa['n_max']}): "
                 f"s = {pa['slope']:.3f} ± {pa['slope_stderr']:.3f}.")
        if pb:
            L.append(f"- Same fit for n >= 1000 ({pb['n_min']}..{pb['n_max']}): **s = {pb['slope']:.3f} ± "
                     f"{pb['slope_stderr']:.3f}** (1 = linear).")
        pc = s.get("power_n_ge_10000")
        if pc:
            L.append(f"- Same fit for n >= 10000 ({pc['n_min']}..{pc['n_max']}): s = {pc['slope']:.3f} ± "
                     f"{pc['slope_stderr']:.3f}.")
        L.append(f"- Affine fit t = a + b n (relative residuals): **b = {1e6 * af['per_unit_s']:.3f} us per "
                 f"{s['unit']}**, a = {1e6 * af['fixed_s']:.1f} us fixed per call; worst relative residual "
                 f"{af['max_rel_residual']:.2f}.")
    L.append("\n## Memory per design\n")
    L.append("C++: peak RSS (VmHWM) growth of a freshly exec'd process over one batch call, against the "
             "analytic bytes of the arrays that grow with the batch: the designs (sizeof(TwoLevelSeta<double>)) "
             "and the results (points x sizeof(critical_state<double>)). The solver's own working memory "
             "(the traced line of one design) is freed before the next design, so it does not grow with the batch.\n")
    L.append("| designs | points/line | peak RSS growth (MB) | analytic (MB) | RSS / design (bytes) | analytic / design (bytes) |")
    L.append("|---:|---:|---:|---:|---:|---:|")
    for r in res["memory_cpp"]:
        L.append(f"| {r['designs']} | {r['points_per_line']} | {r['peak_rss_delta_bytes'] / 1e6:.2f} | "
                 f"{r['analytic_bytes'] / 1e6:.2f} | {r['rss_per_design']:.0f} | {r['analytic_per_design']:.0f} |")
    if res["memory_python"]:
        L.append("\nPython, `gecko.critical_line_batch(designs (n, 9), Ft, errors='nan')`, one fresh interpreter per "
                 "size: VmHWM growth over the call, tracemalloc's peak (numpy arrays only; the binding's C++ "
                 "vectors are not traced), and the bytes of the returned arrays (9 arrays of shape (n, points): "
                 "Ft (a copy), Fn, theta_joint and the two rates in float64, status, iterations and the two "
                 "turning-point counts in int32: 56 bytes per point). During the call the binding also holds "
                 "a std::vector of critical_state (56 bytes per point) and the designs (72 bytes each).\n")
        L.append("Analytic peak: n (72 + 104 points) bytes (the 48-byte result columns and the 56-byte C++ "
                 "states alive together, plus the C++ copy of the designs).\n")
        L.append("| designs | points/line | RSS growth (MB) | analytic peak (MB) | tracemalloc peak (MB) | result arrays (MB) | RSS / design (bytes) | result / design (bytes) |")
        L.append("|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in res["memory_python"]:
            L.append(f"| {r['designs']} | {r['points']} | {r['rss_delta'] / 1e6:.2f} | {r['analytic_peak'] / 1e6:.2f} | "
                     f"{r['tracemalloc_peak'] / 1e6:.2f} | "
                     f"{r['result_bytes'] / 1e6:.2f} | {r['rss_delta'] / r['designs']:.0f} | "
                     f"{r['result_bytes'] / r['designs']:.0f} |")
    L.append("\n![log-log time against n](scaling.png)\n")
    write_results(path, "\n".join(L) + "\n")


def plot(res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    kinds = [k for k in ("points", "designs") if k in res["scaling"]]
    fig, axes = plt.subplots(1, len(kinds), figsize=(6 * len(kinds), 4.6), squeeze=False)
    labels = {"points": ("points per line (reference scene, 1 design)", "point"),
              "designs": ("designs per batch (random designs, 20 points each)", "design")}
    for ax, kind in zip(axes[0], kinds):
        s = res["scaling"][kind]
        n = np.asarray(s["n"], float)
        t = np.asarray(s["median_s"], float)
        ax.loglog(n, t, "o", color="C0", label="median CPU time")
        ax.loglog(n, np.asarray(s["min_s"], float), "_", color="C0", alpha=0.6, label="min")
        nn = np.logspace(np.log10(n.min()), np.log10(n.max()), 100)
        af = s["affine"]
        ax.loglog(nn, af["fixed_s"] + af["per_unit_s"] * nn, "-", color="C1",
                  label=f"fit t = a + b n: b = {1e6 * af['per_unit_s']:.2f} us/{labels[kind][1]}, a = {1e6 * af['fixed_s']:.0f} us")
        pb = s["power_n_ge_1000"] or s["power_all"]
        ax.loglog(nn, pb["prefactor_s"] * nn ** pb["slope"], "--", color="C2",
                  label=f"fit t = c n^s (n >= {pb['n_min']}): s = {pb['slope']:.3f}")
        ax.set_xlabel(labels[kind][0])
        ax.set_ylabel("CPU time of one batch call (s)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("gecko::critical_line_batch, 1 thread (shared 2-core machine, medians)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
