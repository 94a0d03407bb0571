#!/usr/bin/env python3
"""Steady-sliding curve of 1e6 velocities from Python (gecko.steady_sliding), wall time.

Also times the beam rigidity from Python (closed form, and Castigliano with a Python z(x)), and
checks every result against eqs 9-10 written out in numpy (max relative difference), so the
table shows run time and error side by side. Writes friction_python.md/.csv to --out.

    python3 bench/friction/bench_steady_sliding.py [--out bench/results] [--reps 15]
"""
import argparse
import pathlib
import sys

import numpy as np

import gecko

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))  # bench/, for the shared timing helper
from _timing import machine_note, time_call, write_results  # noqa: E402


def median_time(f, reps):
    """Median wall time; the process CPU time (all threads) of the same calls goes to CPU[]."""
    t = time_call(f, repeats=reps)
    CPU.append(t.cpu_median)
    return t.median


CPU = []


def eq9_10(V, m):
    K = np.asarray(m.K)
    q = np.sqrt(m.f_par1 ** 2 + 2 * K[0, 0] * m.law(V))
    return m.N / 2 * (m.f_par1 + q), m.N * (m.f_perp1 + K[1, 0] / (2 * K[0, 0]) * (q - m.f_par1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=".")
    ap.add_argument("--reps", type=int, default=15)
    a = ap.parse_args()
    V = np.logspace(-7, -1, 1_000_000)
    rows = []
    for name, model in [("FIG6_VISCOELASTIC", gecko.FIG6_VISCOELASTIC),
                        ("FIG6_PLASTIC", gecko.FIG6_PLASTIC)]:
        s = median_time(lambda: gecko.steady_sliding(V, model), a.reps)
        r = gecko.steady_sliding(V, model)
        Fp, Fq = eq9_10(V, model)
        err = float(np.max(np.abs(r.F_par / Fp - 1)))
        rows.append(("gecko.steady_sliding", name + " (built-in law, C++)", "1e6 velocities", s, err))
        s = median_time(lambda: gecko.steady_sliding(V, model, forces_only=True), a.reps)
        rows.append(("gecko.steady_sliding(forces_only=True)", name + " (built-in law, C++)",
                     "1e6 velocities", s, err))
        # A Python law: evaluated vectorised by numpy first, then the C++ kernel.
        law = model.law
        pym = model.replace(law=lambda v, law=law: np.asarray(law(v)))
        s = median_time(lambda: gecko.steady_sliding(V, pym), a.reps)
        rows.append(("gecko.steady_sliding", name + " law as a Python callable", "1e6 velocities", s,
                     float(np.max(np.abs(gecko.steady_sliding(V, pym).F_par / Fp - 1)))))
    # numpy written out, for comparison (no validation, no stable forms).
    s = median_time(lambda: eq9_10(V, gecko.FIG6_VISCOELASTIC), a.reps)
    rows.append(("numpy eqs 9-10 (reference)", "FIG6_VISCOELASTIC", "1e6 velocities", s, float("nan")))
    # Beam, from Python.
    ref = gecko.parabolic_beam_rigidity(1.0, 1.0)
    s = median_time(lambda: gecko.parabolic_beam_rigidity(1.0, 1.0), a.reps * 20)
    rows.append(("gecko.parabolic_beam_rigidity", "closed form", "scalar", s, 0.0))
    z = lambda x: np.sqrt(x) / 2  # noqa: E731
    s = median_time(lambda: gecko.rigidity(gecko.castigliano_compliance(z)), a.reps)
    K = gecko.rigidity(gecko.castigliano_compliance(z))
    rows.append(("gecko.castigliano_compliance + rigidity", "Python z(x), complex-step slope", "default tol", s,
                 float(np.max(np.abs(K / ref - 1)))))
    out = pathlib.Path(a.out)
    csv = ["function,case,size,seconds,cpu_seconds,rel_error"]
    csv += [f"{r[0]},{r[1]},{r[2]},{r[3]:.6g},{c:.6g},{r[4]:.3g}" for r, c in zip(rows, CPU)]
    write_results(out / "friction_python.csv", "\n".join(csv) + "\n")
    fmt = lambda x: f"{x * 1e3:.3g} ms" if x >= 1e-3 else f"{x * 1e6:.3g} us"  # noqa: E731
    md = [f"Python-level friction benchmarks (wall time and process CPU time of all threads, "
          f"median of {a.reps}; {machine_note()}; numpy {np.__version__})", "",
          "| function | case | size | wall time | CPU time | max rel. error vs eqs 9-10 / closed form |",
          "|---|---|---|---|---|---|"]
    for r, c in zip(rows, CPU):
        e = "-" if r[4] != r[4] else f"{r[4]:.2g}"
        md.append(f"| {r[0]} | {r[1]} | {r[2]} | {fmt(r[3])} | {fmt(c)} | {e} |")
    write_results(out / "friction_python.md", "\n".join(md) + "\n")
    print(machine_note())
    for r, c in zip(rows, CPU):
        print(f"{r[0]:42s} {r[1]:42s} {r[2]:15s} wall {r[3] * 1e3:8.3f} ms  cpu {c * 1e3:8.3f} ms  err {r[4]:.2g}")


if __name__ == "__main__":
    main()
