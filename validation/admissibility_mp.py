"""Admissibility verdicts of deep states, checked in arbitrary precision (issue 13, items 2 and 5).

validation/admissibility.py judges gecko's status 0 / 7 and min_z with a double-precision backward
shot. Past about 15 saddle time constants l sqrt(N (1 + N/EA) / EI) that shot amplifies its
start's rounding like e^length, and its own uncertainty estimate (perturbed shots, which diverge
the same way) need not see it: there it flags verdicts as wrong that are its own
(validation/README.md, "Admissibility of deep states in arbitrary precision"). This module takes a
seeded sample of the solved states (status 0 or 7) with a segment at least ``--min-length``
saddle time constants long (with ``--flagged``, only those of them that the double shot calls
wrong, conclusively or by a sign ten times its uncertainty) and decides each with
the bracketing shot of tests/data/seta_separatrix_mp.py (``bracket_route`` with heights): the
backward Taylor shot of seta_taylor.py at 128 + 1.5 length bits, bisected on gecko's Fn to the
root, carrying the height z(s) (dz/ds = -(1 + T/EA) cos theta, z = 0 at the contact edge; lowest z
over every step by a golden-section search of its series). On the root's path (the shot's turning
points and base rate gecko's) the shot follows the state to about e^-length, so its lowest height
is the state's to far below the threshold. Verdicts, with L = l1 + l2 and TOL = 1e-9 L:

- correct: status 0 and the shot's lowest height >= -TOL, or status 7 and below -1e-12 L; and
  |min_z - shot| <= TOL where gecko's min_z is finite;
- differs: the status right, min_z more than TOL from the shot (what a user reads as the depth);
- wrong: status 0 while the shot lies below -TOL, or status 7 with min_z below -TOL while the shot
  stays above -1e-12 L;
- other_path: the bisected root has other turning points or another base rate than gecko's state
  (the bracket holds a root of another branch; nothing decided);
- undecided: no sign change over the bracket, an error, or the time limit.

    PYTHONPATH=<gecko> python3 -m validation.admissibility_mp now.npz [--sample 60] [--seed 0] \\
        [--min-length 15] [--max-length 120] [--time-limit 120] [--flagged] [--states D:C ...] [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import math
import multiprocessing as mpc
import time

import numpy as np

from validation import campaign
from validation.admissibility import TOL_REL, wrong_verdicts
from validation.separatrix import TimeLimit, time_limited

# tests/data (seta_separatrix_mp, seta_taylor) is on sys.path through validation.separatrix.


def verdict(status: int, min_z: float, shot: float, L: float) -> str:
    """The verdict on gecko's status and min_z against the shot's lowest height (module docstring)."""
    wrong0, wrong7 = wrong_verdicts(status, min_z, shot, L)
    if wrong0 or wrong7:
        return "wrong"
    if math.isfinite(min_z) and abs(min_z - shot) > TOL_REL * L:
        return "differs"
    return "correct"


def check(job):
    import gecko
    import seta_separatrix_mp as ssm

    i, j, p, fts, min_z, limit = job
    d = dict(zip(campaign.FIELDS, map(float, p)))
    line = gecko.TwoLevelSeta(**d).critical_line(Ft=list(map(float, fts)), errors="nan")
    Ft, Fn = float(fts[j]), float(line.Fn[j])
    rq = float(line.theta_rate_base[j])
    turns = (int(line.turning_points_beam[j]), int(line.turning_points_spatula[j]))
    L1, L2 = ssm.saddle_lengths(d, math.hypot(Fn, Ft))
    L = d["l1"] + d["l2"]
    out = dict(design=int(i), column=int(j), Ft=Ft, Fn=Fn, status=int(line.status[j]), min_z=float(line.min_z[j]),
               min_z_npz=float(min_z), turning=list(turns), elastic_lengths=[round(L1, 1), round(L2, 1)])
    if out["status"] not in (0, campaign.INADMISSIBLE):
        out["verdict"] = "not_solved_now"
        return out
    t = time.time()
    try:
        b = time_limited(limit, ssm.bracket_route, d, Ft, Fn, L1 + L2, heights=True)
    except TimeLimit:
        b, out["error"] = None, f"time limit ({limit} s)"
    except Exception as e:  # a shot that overflows its fixed point, ...
        b, out["error"] = None, repr(e)[:160]
    out["seconds"] = round(time.time() - t, 1)
    if b is None:
        out["verdict"] = "undecided"
        return out
    out["shot_min_z"] = float(b["min_z"])
    out["shot_turning"] = list(b["turns"])
    out["dFn_rel"] = float(abs(b["Fn"] - Fn) / max(1, abs(Fn)))
    if tuple(b["turns"]) != turns or abs(float(b["q"]) - rq) > 1e-8 * max(1.0, abs(rq)):
        out["verdict"] = "other_path"
        return out
    out["dmin_z_over_L"] = abs(out["min_z"] - out["shot_min_z"]) / L if math.isfinite(out["min_z"]) else None
    out["verdict"] = verdict(out["status"], out["min_z"], out["shot_min_z"], L)
    return out


def deep_states(npz: dict, min_length: float, max_length: float) -> np.ndarray:
    """(design, column) of the solved states whose longer segment is within [min_length, max_length]
    saddle time constants (and the two together at most 2 max_length: the shot's cost)."""
    import seta_separatrix_mp as ssm

    P, FT, Fn, status = npz["P"], npz["FT"], npz["Fn"], npz["status"]
    f = {k: P[:, n][:, None] for n, k in enumerate(campaign.FIELDS)}
    with np.errstate(invalid="ignore"):
        L1, L2 = ssm.saddle_lengths(f, np.hypot(Fn, FT))
        longer = np.maximum(L1, L2)
        ok = campaign.solved(status) & (longer >= min_length) & (longer <= max_length) & (L1 + L2 <= 2 * max_length)
    return np.argwhere(ok)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz", help="a validation.recheck --save file (with min_z)")
    ap.add_argument("--sample", type=int, default=60)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--min-length", type=float, default=15)
    ap.add_argument("--max-length", type=float, default=120)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--time-limit", type=float, default=120, help="seconds per state (0: none)")
    ap.add_argument("--flagged", action="store_true",
                    help="sample only the deep states that validation/admissibility.py's double shot calls wrong")
    ap.add_argument("--states", nargs="*", default=None, metavar="DESIGN:COLUMN",
                    help="check these states instead of a sample")
    ap.add_argument("--json", default=None)
    a = ap.parse_args(argv)
    z = dict(np.load(a.npz))
    idx = deep_states(z, a.min_length, a.max_length)
    flagged_by_double = None
    if a.flagged:
        from validation import admissibility
        rows = np.unique(idx[:, 0])
        only = np.full(z["status"].shape, 2)  # status 2: not shot
        only[idx[:, 0], idx[:, 1]] = z["status"][idx[:, 0], idx[:, 1]]
        r = admissibility.check(z["P"][rows], z["FT"][rows], z["Fn"][rows], only[rows], z["min_z"][rows], a.workers)
        bad = r["wrong"] | r["flagged_by_sign"]
        idx = np.array([(rows[k], j) for k, j in np.argwhere(bad)], dtype=np.int64).reshape(-1, 2)
        flagged_by_double = int(len(idx))
    rng = np.random.default_rng(a.seed)
    pick = idx[rng.choice(len(idx), size=min(a.sample, len(idx)), replace=False)] if len(idx) else idx
    if a.states is not None:
        pick = np.array([[int(x) for x in st.split(":")] for st in a.states], dtype=np.int64).reshape(-1, 2)
    jobs = [(int(i), int(j), z["P"][i], z["FT"][i], float(z["min_z"][i, j]), a.time_limit) for i, j in pick]
    t0 = time.time()
    with mpc.get_context("fork").Pool(a.workers) as pool:
        results = pool.map(check, jobs, chunksize=1)
    verdicts = {}
    for r in results:
        key = f"{r['verdict']} (status {r['status']})"
        verdicts[key] = verdicts.get(key, 0) + 1
    decided = [r for r in results if r.get("dmin_z_over_L") is not None and r["verdict"] in ("correct", "differs")]
    summary = dict(npz=a.npz, population=int(len(idx)), flagged_by_double=flagged_by_double, sample=len(jobs),
                   seed=a.seed, min_length=a.min_length,
                   max_length=a.max_length, time_limit=a.time_limit, verdicts=verdicts,
                   max_dmin_z_over_L=max((r["dmin_z_over_L"] for r in decided), default=None),
                   longest_segment=max((max(r["elastic_lengths"]) for r in results), default=None),
                   seconds=round(time.time() - t0, 1), states=results)
    print(json.dumps({k: v for k, v in summary.items() if k != "states"}, indent=1))
    if a.json:
        with open(a.json, "w") as f:
            f.write(json.dumps(summary, indent=1) + "\n")
    return summary


if __name__ == "__main__":
    main()
