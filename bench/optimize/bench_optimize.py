#!/usr/bin/env python3
"""Benchmark and study of gecko.optimize_seta (python/gecko/optimize/).

Measures, for a set of design problems at the paper's reference scene, the wall time and the number
of critical-line evaluations to converge from 8 starts (median wall time of --repeats runs), and
runs the alpha2 study (paper 001, Sec. 3.2: "an approximately optimum angle for alpha2 is about
pi/6"), comparing the optimiser's alpha2 with pi/6 on the paper's objective (the maximum pull-off
force). Also compares each optimum with a random search given the same number of evaluations.
Writes bench/results/optimize.md and bench/results/optimize.json.

    PYTHONPATH=python python3 bench/optimize/bench_optimize.py [--repeats 3]
"""
import json
import math
import os
import platform
import sys
import time

import numpy as np
import scipy

import gecko
from gecko.optimize import optimize_seta, seta_objective

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, timing helper
from _timing import time_call, write_results  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(os.path.dirname(HERE), "results")
PI = math.pi
S = PI / 3  # alpha1 + alpha2 of the reference scene

PROBLEMS = [
    ("alpha2 (alpha1 = pi/6), not sticky", "max_pull_off", {"alpha2": (0.0, PI / 3 - 1e-3)},
     ["not_sticky"], {}, {}),
    ("alpha2 (alpha1 = pi/6), unconstrained", "max_pull_off", {"alpha2": (0.0, PI / 3 - 1e-3)},
     [], {}, {}),
    ("alpha2 (alpha1 + alpha2 = pi/3, Fig 3c split)", "max_pull_off", {"alpha2": (0.0, S - 0.01)},
     [], {"alpha1+alpha2": S}, {}),
    ("alpha1, alpha2, not sticky", "max_pull_off", {"alpha1": (0.05, 1.2), "alpha2": (0.0, 1.2)},
     ["not_sticky"], {}, {}),
    ("5-D: EI1, EI2/EI1, l2/l1, alpha1, alpha2, not sticky", "max_pull_off",
     {"EI1": (1.0, 20.0), "EI2/EI1": (0.05, 2.0), "l2/l1": (0.05, 0.5), "alpha1": (0.05, 1.2),
      "alpha2": (0.0, 1.2)}, ["not_sticky"], {}, {}),
    ("area: EI2/EI1, l2/l1, alpha2, (Fn)0 >= 0.1", "area",
     {"EI2/EI1": (0.05, 2.0), "l2/l1": (0.05, 0.5), "alpha2": (0.0, 0.9)}, [("fn0_min", 0.1)], {}, {}),
    ("pull-off at Ft = 5: EI2/EI1, l2/l1, alpha1, alpha2, not sticky", "pull_off_at",
     {"EI2/EI1": (0.05, 2.0), "l2/l1": (0.05, 0.5), "alpha1": (0.05, 1.2), "alpha2": (0.0, 1.2)},
     ["not_sticky"], {}, {"ft": 5.0}),
]


def random_search(objective, bounds, constraints, base, kw, budget, seed=1):
    """Best feasible value among `budget` uniform random designs (log-uniform for positive
    quantities, as the optimiser's scaling) over the same bounds."""
    rng = np.random.default_rng(seed)
    base_d = {f: getattr(gecko.TwoLevelSeta(), f) for f in gecko.TwoLevelSeta._FIELDS}
    best = -math.inf
    fn0_min = None
    for c in constraints:
        if c == "not_sticky":
            fn0_min = 0.0 if fn0_min is None else max(fn0_min, 0.0)
        elif isinstance(c, tuple) and c[0] == "fn0_min":
            fn0_min = c[1]
    for _ in range(budget):
        d = dict(base_d)
        x = {}
        for n, (lo, hi) in bounds.items():
            x[n] = (lo + rng.uniform() * (hi - lo) if n.startswith("alpha") else
                    lo * (hi / lo) ** rng.uniform())
        d.update({k: v for k, v in x.items() if k in d})
        if "EI2/EI1" in x:
            d["EI2"] = x["EI2/EI1"] * d["EI1"]
        if "l2/l1" in x:
            d["l2"] = x["l2/l1"] * d["l1"]
        if "alpha1+alpha2" in base:
            d["alpha1"] = base["alpha1+alpha2"] - d["alpha2"]
        if d["alpha1"] <= 0 or d["alpha1"] + d["alpha2"] >= PI / 2:
            continue
        s = gecko.TwoLevelSeta(**d)
        try:
            v, _ = seta_objective(objective, s, **kw)
        except RuntimeError:
            continue
        if fn0_min is not None and s.critical_line(Ft=[0.0]).Fn[0] < fn0_min:
            continue
        best = max(best, v)
    return best


def alpha2_study():
    """The paper's objective (maximum pull-off) at its reference scene: optimum alpha2 vs pi/6."""
    rows = []
    ref = gecko.TwoLevelSeta()
    at_pi6 = seta_objective("max_pull_off", ref)[0]
    cases = [
        ("alpha2 alone (alpha1 = pi/6), not sticky ((Fn)0 >= 0)", {"alpha2": (0.0, PI / 3 - 1e-3)},
         ["not_sticky"], None),
        ("alpha2 alone (alpha1 = pi/6), no constraint", {"alpha2": (0.0, PI / 3 - 1e-3)}, [], None),
        ("alpha2 with alpha1 + alpha2 = pi/3 fixed (Fig 3c)", {"alpha2": (0.0, S - 0.01)}, [],
         {"alpha1+alpha2": S}),
        ("alpha1 and alpha2, not sticky", {"alpha1": (0.05, 1.2), "alpha2": (0.0, 1.2)}, ["not_sticky"],
         None),
        ("alpha1 and alpha2, alpha1 >= pi/6 (normal stiffness no higher than the reference), "
         "not sticky", {"alpha1": (PI / 6, 1.2), "alpha2": (0.0, 1.2)}, ["not_sticky"], None),
    ]
    for name, bounds, cons, base in cases:
        r = optimize_seta("max_pull_off", bounds, cons, base=base, starts=8, seed=0)
        d = r.design
        rows.append({
            "case": name, "status": r.status, "alpha1": d["alpha1"], "alpha2": d["alpha2"],
            "value": r.value, "value_at_pi6": at_pi6, "gain_percent": 100 * (r.value / at_pi6 - 1),
            "fn0": float(r.seta.critical_line(Ft=[0.0]).Fn[0]), "fn0_at_pi6": float(ref.characteristics().fn0),
            "active": r.active_constraints, "gradient": r.gradient,
            "kkt_relative_residual": r.kkt["relative_residual"], "multipliers": r.kkt["multipliers"],
            "evaluations": r.evaluations})
    # Independent closed form of the not-sticky boundary (eq 22, exact at Fn = Ft = 0).
    eq22 = PI / 2 - ref.alpha1 - math.sqrt(2 * ref.EI2 * ref.w) * (ref.l1 / ref.EI1 + ref.l2 / ref.EI2)
    extra = {"eq22_alpha2": eq22, "optimum_minus_eq22": rows[0]["alpha2"] - eq22,
             "dP_dalpha2_at_pi6": seta_objective("max_pull_off", ref)[1]["alpha2"],
             "fn0_split_range": [float(gecko.TwoLevelSeta(alpha1=S - a2, alpha2=a2).characteristics().fn0)
                                 for a2 in (0.0, S - 0.01)]}
    return rows, extra


def main():
    repeats = 3
    if "--repeats" in sys.argv:
        repeats = int(sys.argv[sys.argv.index("--repeats") + 1])
    optimize_seta("max_pull_off", {"alpha2": (0.1, 0.5)}, starts=1)  # imports, caches
    out = {"machine": f"{platform.node()} ({platform.processor() or platform.machine()}), shared with "
                      "other jobs: wall times are noisy",
           "python": platform.python_version(), "numpy": np.__version__, "scipy": scipy.__version__,
           "date_utc": time.strftime("%Y-%m-%d %H:%M", time.gmtime()), "repeats": repeats,
           "load_average_before": os.getloadavg(), "problems": []}
    out["alpha2_study"], out["alpha2_study_checks"] = alpha2_study()
    for name, obj, bounds, cons, base, kw in PROBLEMS:
        timing = time_call(lambda: optimize_seta(obj, bounds, cons, base=base or None, starts=8, seed=0, **kw),
                           repeats=repeats)
        r, times = timing.result, timing.wall
        rs = random_search(obj, bounds, cons, base, kw, r.evaluations)
        out["problems"].append({
            "problem": name, "objective": obj, "dimension": len(bounds), "status": r.status,
            "value": r.value, "variables": r.variables, "active": r.active_constraints,
            "kkt_relative_residual": r.kkt.get("relative_residual"),
            "wall_s_median": timing.median, "wall_s_all": times,
            "evaluations": r.evaluations,
            "evaluations_per_start": [s["evaluations"] for s in r.starts],
            "iterations_per_start": [s["iterations"] for s in r.starts],
            "outcomes": [s["outcome"] for s in r.starts],
            "starts_within_1e-6_of_best": sum(1 for s in r.starts if s["value"] is not None and
                                              abs(s["value"] - r.value) <= 1e-6 * (1 + abs(r.value))),
            "failures": len(r.failures),
            "random_search_same_budget": rs})
        print(f"{name}: {r.status} value {r.value:.8g} in {timing.median:.3f} s, "
              f"{r.evaluations} evaluations (random search: {rs:.6g})", flush=True)
    out["load_average_after"] = os.getloadavg()
    write_results(os.path.join(RESULTS, "optimize.json"), json.dumps(out, indent=1, default=str))
    write_md(out)


def write_md(out):
    L = ["# Design optimisation (`gecko.optimize_seta`)", "",
         f"Generated by `PYTHONPATH=python python3 bench/optimize/bench_optimize.py` on {out['date_utc']} UTC; "
         f"Python {out['python']}, numpy {out['numpy']}, scipy {out['scipy']}. Machine: {out['machine']} "
         f"(2 cores shared by several concurrent jobs, so wall times are indicative only; median of "
         f"{out['repeats']} runs; 1-minute load average {out['load_average_before'][0]:.1f} before and "
         f"{out['load_average_after'][0]:.1f} after the run).", "",
         "SLSQP with the exact gradients (solver sensitivities), 8 Sobol starts (seed 0, the first "
         "the reference scene when inside the bounds). *Evaluations* = critical-line evaluations "
         "(each one objective value + gradient + constraints) over all 8 starts, start selection "
         "included (each start point is evaluated once when the starts are chosen; *per start* "
         "counts the evaluations of SLSQP's iterations after that, *iterations* its iterations). "
         "*Random search* = "
         "best feasible value among as many random designs over the same bounds.", "",
         "| problem | dim | status | value | wall (s) | evaluations | per start | iterations "
         "| starts at best | random search |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    for p in out["problems"]:
        L.append(f"| {p['problem']} | {p['dimension']} | {p['status']} | {p['value']:.8g} | "
                 f"{p['wall_s_median']:.3f} | {p['evaluations']} | {p['evaluations_per_start']} | "
                 f"{p['iterations_per_start']} | "
                 f"{p['starts_within_1e-6_of_best']}/8 | {p['random_search_same_budget']:.6g} |")
    L += ["", "Optimal variables and active constraints:", ""]
    for p in out["problems"]:
        v = ", ".join(f"{k} = {x:.6g}" for k, x in p["variables"].items())
        L.append(f"- {p['problem']}: {v}; active: {', '.join(p['active']) or 'none'}; "
                 f"KKT relative residual {p['kkt_relative_residual']:.1e}")
    L += ["", "## alpha2 study against the paper", "",
          "Paper 001, Sec. 3.2 (last paragraph): with alpha1 + alpha2 split between the two angles "
          "(Fig 3c), \"when choosing the optimal angle for alpha2, we should first guarantee the "
          "maximum (Fn)pull-off is maximized, and then decrease the normal stiffness ... For the "
          "calculated case, an approximately optimum angle for alpha2 is about pi/6, and an optimal "
          "angle must be at its neighborhood.\" The quantity is the **maximum pull-off force** "
          "(-min Fn along the critical line), subject to the paper's first requirement that the seta "
          "is not sticky at rest, (Fn)0 > 0 (eq 22), and traded against the normal stiffness "
          "Kn ~ 3EI/sin(alpha1). At the reference scene (alpha1 = alpha2 = pi/6) the maximum pull-off "
          f"is {out['alpha2_study'][0]['value_at_pi6']:.10g}.", "",
          "| case | alpha1 | alpha2 | alpha2 - pi/6 | max pull-off | at pi/6 | gain | (Fn)0 | active | KKT res. |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for r in out["alpha2_study"]:
        L.append(f"| {r['case']} | {r['alpha1']:.6f} | {r['alpha2']:.6f} | {r['alpha2'] - PI / 6:+.6f} | "
                 f"{r['value']:.8g} | {r['value_at_pi6']:.8g} | {r['gain_percent']:+.1f} % | "
                 f"{r['fn0']:.2e} | {', '.join(r['active']) or 'none'} | {r['kkt_relative_residual']:.1e} |")
    x = out["alpha2_study_checks"]
    L += ["", "What the optimiser finds:", "",
          "- The maximum pull-off force increases monotonically with alpha2 at the reference "
          "parameters (checked on 241- and 60-point grids in the tests), both with alpha1 = pi/6 "
          "fixed and with alpha1 + alpha2 = pi/3 fixed: without a "
          "constraint the optimum sits on the upper bound of alpha2 (derivative > 0 there), so pi/6 "
          "is not a stationary point of the pull-off alone.",
          "- With the paper's first requirement, not sticky at rest ((Fn)0 >= 0), and alpha1 = pi/6, "
          f"the optimum is where (Fn)0 = 0: alpha2* = {out['alpha2_study'][0]['alpha2']:.10f}, i.e. "
          f"pi/6 {out['alpha2_study'][0]['alpha2'] - PI / 6:+.4f} "
          f"({100 * (out['alpha2_study'][0]['alpha2'] / (PI / 6) - 1):+.1f} %), where the pull-off is "
          f"{out['alpha2_study'][0]['gain_percent']:.1f} % above its value at pi/6. That boundary is "
          "exactly eq 22 of the paper (at Fn = Ft = 0 the elastica has constant curvature, so the "
          "small-deformation criterion is exact there): alpha2* = pi/2 - alpha1 - sqrt(2 EI2 w)"
          f"(l1/EI1 + l2/EI2) = pi/3 - 1/2 = {x['eq22_alpha2']:.10f}; the optimiser's alpha2 differs "
          f"from it by {x['optimum_minus_eq22']:.1e}. This is the sense in which pi/6 is "
          "\"approximately optimum ... an optimal angle must be at its neighborhood\": alpha2 = pi/6 "
          f"sits just inside the not-sticky region, {x['eq22_alpha2'] - PI / 6:.4f} rad from its "
          "boundary, where the pull-off is largest. pi/6 is not a stationary point of the pull-off "
          f"(dP/dalpha2 = {x['dP_dalpha2_at_pi6']:.4g} there).",
          "- With the split alpha1 + alpha2 = pi/3 fixed (the paper's Fig 3c), (Fn)0 stays positive "
          f"({x['fn0_split_range'][0]:.2f} at alpha2 = 0 to {x['fn0_split_range'][1]:.2f} at "
          "alpha2 = pi/3 - 0.01), the not-sticky constraint is never active, and the pull-off "
          "keeps growing towards alpha1 -> 0. The paper's choice there comes from its second, "
          "unquantified criterion (keep the normal stiffness ~ 1/sin(alpha1) low, i.e. alpha1 not "
          "small), which the maximum pull-off alone does not contain. With alpha1 >= pi/6 as a "
          "stand-in for that stiffness limit, the optimum is alpha1 on that bound and alpha2 at "
          "(Fn)0 = 0 (last row).",
          "- Tests (tests/python/test_optimize.py) check that these optima are true local optima "
          "(KKT with non-negative multipliers, grid and random search over the same bounds), not that "
          "alpha2 equals pi/6.", ""]
    write_results(os.path.join(RESULTS, "optimize.md"), "\n".join(L))


if __name__ == "__main__":
    main()
