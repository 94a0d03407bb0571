"""Design-sweep benchmark: characteristics of many random two-level seta designs on local threads,
and the same sweep through a dask.distributed LocalCluster (overhead against local threads).

    PYTHONPATH=python python3 bench/sweep/bench_sweep.py [--designs 1000000] [--cores 2]
        [--chunk-size 10000] [--no-dask] [--depth-designs 20000]

Writes bench/results/sweep.md and bench/results/sweep.json (and prints the table).

* local: ``gecko.sweep(designs, threads=CORES)``: one GIL-free C++ batch call per chunk;
* dask: ``LocalCluster(n_workers=CORES, threads_per_worker=1, processes=True)``, then
  ``gecko.sweep(designs, client=client)``: each chunk a Dask task (cluster start-up timed apart);
  the two tables are compared bitwise;
* per output set (on the first --depth-designs designs, local): what "only the outputs asked for
  are computed" is worth: (Ft)max alone (closed form), (Fn)0 alone (natural state), the default
  outputs (the line followed to its end).

Designs: uniform random (seed 1) over EI1 in [1, 10], EI2 in [0.1, 5] (log), l2 in [0.05, 0.3],
alpha2 in [0, pi/4], EA2 in [10, 500] (log); alpha1 = pi/6, EA1 = inf, l1 = w = 1. The machine is
shared: the load average is recorded beside the times, and the ratio is the number to read.
"""
from __future__ import annotations

import argparse
import math
import os
import platform
import sys
from pathlib import Path

import gecko

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # bench/, for the shared timing helper
from _timing import timed_once, write_results  # noqa: E402

BOUNDS = {"EI1": (1.0, 10.0), "EI2": (0.1, 5.0, "log"), "l2": (0.05, 0.3), "alpha2": (0.0, math.pi / 4),
          "EA2": (10.0, 500.0, "log")}
RESULTS = Path(__file__).resolve().parents[1] / "results"


def timed(fn):
    return timed_once(fn)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--designs", type=int, default=1_000_000)
    ap.add_argument("--cores", type=int, default=2)
    ap.add_argument("--chunk-size", type=int, default=10_000)
    ap.add_argument("--no-dask", action="store_true")
    ap.add_argument("--depth-designs", type=int, default=20_000)
    ap.add_argument("--out", default=str(RESULTS), help="folder for sweep.md / sweep.json")
    a = ap.parse_args()

    designs, t_sample = timed(lambda: gecko.random_designs(BOUNDS, a.designs, seed=1))
    load0 = os.getloadavg()
    rows = []
    res = {"designs": a.designs, "cores": a.cores, "chunk_size": a.chunk_size, "gecko": gecko.__version__,
           "outputs": list(gecko.DEFAULT_SWEEP_OUTPUTS), "machine": platform.platform(),
           "cpu_count": os.cpu_count(), "sampling_seconds": t_sample, "load_before": load0}

    local, t_local = timed(lambda: gecko.sweep(designs, threads=a.cores, chunk_size=a.chunk_size, progress=False))
    res["local"] = {"seconds": t_local, "designs_per_second": a.designs / t_local,
                    "status_counts": {int(k): int(v) for k, v in local["status"].value_counts().items()},
                    "load_after": os.getloadavg()}
    rows.append(("local threads", a.cores, t_local, a.designs / t_local, "1.00"))
    print(f"local: {t_local:.1f} s, {a.designs / t_local:.0f} designs/s", flush=True)

    if not a.no_dask:
        from distributed import Client, LocalCluster
        (cluster, client), t_start = timed(lambda: (lambda c: (c, Client(c)))(
            LocalCluster(n_workers=a.cores, threads_per_worker=1, processes=True, dashboard_address=None)))
        try:
            client.run(lambda: __import__("gecko").__version__)  # import gecko on every worker first
            remote, t_dask = timed(lambda: gecko.sweep(designs, client=client, chunk_size=a.chunk_size,
                                                       progress=False))
        finally:
            client.close()
            cluster.close()
        same = all(local[c].to_numpy().tobytes() == remote[c].to_numpy().tobytes() for c in local.columns)
        res["dask"] = {"seconds": t_dask, "designs_per_second": a.designs / t_dask, "cluster_start_seconds": t_start,
                       "overhead_ratio": t_dask / t_local, "bitwise_equal_to_local": bool(same),
                       "load_after": os.getloadavg()}
        rows.append(("Dask LocalCluster", f"{a.cores} workers x 1 thread", t_dask, a.designs / t_dask,
                     f"{t_dask / t_local:.2f}"))
        print(f"dask: {t_dask:.1f} s (+{t_start:.1f} s cluster start), ratio {t_dask / t_local:.2f}, "
              f"bitwise equal: {same}", flush=True)

    m = min(a.depth_designs, a.designs)
    sub = designs.iloc[:m]
    depth_rows = []
    for label, outs in (("(Ft)max only: closed form", ["ft_max"]),
                        ("(Fn)0 only: natural state", ["fn0"]),
                        ("(Fn)0, k, sticky: natural state + slope", ["fn0", "slope_k", "sticky_at_rest"]),
                        ("default outputs: line to its end", list(gecko.DEFAULT_SWEEP_OUTPUTS))):
        _, t = timed(lambda: gecko.sweep(sub, outputs=outs, threads=a.cores, chunk_size=a.chunk_size,
                                         progress=False))
        depth_rows.append((label, t, m / t))
    res["per_outputs"] = [{"outputs": l, "designs": m, "seconds": t, "designs_per_second": r}
                          for l, t, r in depth_rows]

    out = Path(a.out)
    write_results(out / "sweep.json", res)
    md = [f"# Design sweep: characteristics of {a.designs:,} random designs", "",
          f"`PYTHONPATH=python python3 bench/sweep/bench_sweep.py --designs {a.designs} --cores {a.cores} "
          f"--chunk-size {a.chunk_size}`  (gecko {gecko.__version__}, {platform.machine()}, "
          f"{os.cpu_count()} CPUs, load average before {load0[0]:.1f}; a shared machine: timings are noisy)", "",
          f"Outputs: {', '.join(gecko.DEFAULT_SWEEP_OUTPUTS)} and status (every design's critical line followed "
          "to its end).", "",
          "| executor | cores | wall time (s) | designs/s | time / local |", "|---|---|---:|---:|---:|"]
    md += [f"| {r[0]} | {r[1]} | {r[2]:.1f} | {r[3]:,.0f} | {r[4]} |" for r in rows]
    counts = "; ".join(f"{k}: {v:,}" for k, v in sorted(res["local"]["status_counts"].items()))
    md += ["", f"Status of the designs ({counts}): 6 = the line was given up before its end or its minimum "
               "not established (max pull-off NaN, flagged, never a bound passed off as the value)."]
    if "dask" in res:
        md += ["", f"Dask cluster start-up (2 worker processes) {res['dask']['cluster_start_seconds']:.1f} s, not "
                   f"included. Dask table bitwise equal to the local one: {res['dask']['bitwise_equal_to_local']}."]
    md += ["", f"Only the outputs asked for are computed ({m:,} designs, local threads, {a.cores} cores):", "",
           "| outputs | wall time (s) | designs/s |", "|---|---:|---:|"]
    md += [f"| {l} | {t:.2f} | {r:,.0f} |" for l, t, r in depth_rows]
    write_results(out / "sweep.md", "\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
