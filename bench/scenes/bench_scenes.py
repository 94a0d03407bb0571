"""Planner benchmark: a scene that asks only for (Fn)0 over a sweep against the same sweep asking
for full critical lines, all characteristics and deformed shapes.

    python bench/scenes/bench_scenes.py [--designs 200] [--repeat 5]

Writes bench/results/scenes.md (and prints it). Each scene is run through gecko.scene.run_scene
with a fresh cache and no output folder (no drawing: the comparison is of the computation the
planner chooses). Best of --repeat runs; the machine is shared, so the ratio is the number to read.
"""
from __future__ import annotations

import argparse
import os
import platform
import sys
from pathlib import Path

import gecko
from gecko.scene import Cache, plan_scene, load_scene, run_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # bench/, for the shared timing helper
from _timing import time_call, write_results  # noqa: E402


def scene(outputs, designs):
    return {"title": "planner benchmark",
            "study": [{"name": "seta", "model": "two_level_seta",
                       "variables": {"ratio": {"logrange": [0.05, 1.0], "num": designs}},
                       "parameters": {"EI2": "ratio * EI1"}, "outputs": outputs}]}


CASES = [
    ("(Fn)0 only", {"characteristics": ["fn0"]}),
    ("small-deformation (Fn)0 only", {"characteristics": ["small_fn0"]}),
    ("critical line (200 Ft)", {"critical_line": {"Ft": {"range": [0, "ft_max"], "num": 200}}}),
    ("critical line + all characteristics",
     {"critical_line": {"Ft": {"range": [0, "ft_max"], "num": 200}}, "characteristics": True}),
    ("line + characteristics + shapes at 3 Ft",
     {"critical_line": {"Ft": {"range": [0, "ft_max"], "num": 200}}, "characteristics": True,
      "shapes": {"Ft": [0, "0.5*ft_max", "0.9*ft_max"], "points": 201}}),
]


def best_time(sc, repeat):
    return time_call(lambda: run_scene(sc, cache=Cache(), progress=False, threads=1), repeats=repeat).best


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--designs", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "results" / "scenes.md"))
    args = ap.parse_args()
    rows = []
    for name, outputs in CASES:
        sc = scene(outputs, args.designs)
        kernels = ", ".join(plan_scene(load_scene(sc)).kernels("seta"))
        rows.append((name, kernels, best_time(sc, args.repeat)))
    base = rows[0][2]
    full = rows[-1][2]
    lines = [
        "# Scene planner benchmark",
        "",
        f"`python bench/scenes/bench_scenes.py --designs {args.designs} --repeat {args.repeat}` — "
        f"gecko {gecko.__version__}, Python {platform.python_version()}, {platform.machine()}, "
        f"{os.cpu_count()} CPUs (shared machine), one thread, best of {args.repeat}.",
        "",
        f"A sweep of {args.designs} two-level seta designs (EI2/EI1 from 0.05 to 1, log-spaced), the rest at",
        "the reference design. Same sweep, different requested outputs; the planner picks the kernels.",
        "",
        "| requested outputs | kernels the planner ran | time (ms) | per design (µs) | vs (Fn)0 only |",
        "|---|---|---:|---:|---:|",
    ]
    for name, kernels, t in rows:
        lines.append(f"| {name} | {kernels} | {t * 1e3:.2f} | {t / args.designs * 1e6:.1f} | {t / base:.1f}x |")
    lines += ["", f"Asking only for (Fn)0 is **{full / base:.0f}x** faster than asking for full lines, "
              "characteristics and shapes over the same sweep "
              f"({base * 1e3:.1f} ms against {full * 1e3:.1f} ms).", ""]
    text = "\n".join(lines)
    write_results(args.out, text)
    print(text)


if __name__ == "__main__":
    main()
