"""States recovered past a followed line's stall, checked in arbitrary precision (issue 13, item 5).

The solver follows a line that stalls next to a segment's separatrix on in the separatrix limit
(gecko/seta/detail/separatrix_limit.hpp, docs/theory/two_level_seta.md "Long segments"). Those
states lie tens to hundreds of elastic lengths deep, where a shot in double precision amplifies
its start's rounding past any use (validation/verify.py is inconclusive there), so a seeded sample
of them is checked in arbitrary precision by two routes of tests/data/seta_separatrix_mp.py.
First the bracketing shot (`bracket_route`): the backward Taylor shot of seta_taylor.py, at a
precision that covers its amplification, on both sides of gecko's Fn (1e-11 relative); a sign
change of the base angle's residual proves a root between, which is bisected and decides the
state where it has gecko's turning points and base rate (beta compared to 1e-11); for segments
longer than 100 saddle time constants, whose bisection takes too long, the two bracketing shots
alone (`bracket_ends`) decide Fn (within the bracket) and beta, not the path. Else the
quadrature route (`quad_route`: length equations by tanh-sinh quadrature, each long segment's
unknown replaced by the logarithm of its separatrix distance), started from gecko's state (which
picks the branch) and compared. The quadrature route assumes a path class (a long segment with
turning points librates, one without rotates) and can converge to another path's root: for
design 8038 at Ft = 1091.36 it converged 0.3 % away, on a path with 3 beam turning points, where
the bracketing shot confirms gecko's state (0 turning points) to 1.6e-13.

    PYTHONPATH=<gecko> python3 -m validation.separatrix validation/rerun_10000.npz --sample 24 --seed 0 \\
        --json validation/results/separatrix_sample.json

Sampled: states whose campaign status was 1 or 6 (given up) and that the re-run solves (0 or 7);
with ``--since OLD.npz`` (an earlier re-run's ``recheck --save`` file) only those that OLD had not
solved either, i.e. the states a solver change newly recovers; with ``--moved OLD.npz`` instead the
states both solve with Fn more than 1e-10 apart (relative), i.e. the states a solver change moved
(the re-run's, that is the gecko on PYTHONPATH, are checked); with ``--turned OLD.npz`` the states
both solve with Fn within 1e-10 and other turning-point counts (a path changed in place). A state
the route cannot settle in ``--time-limit`` seconds (300 by default) counts as undecided.
"""
from __future__ import annotations

import argparse
import json
import math
import multiprocessing as mpc
import os
import signal
import sys
import time

import numpy as np

from validation import campaign

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "data"))


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout()


def time_limited(limit, fn, *args, **kwargs):
    """fn(*args, **kwargs), or raise TimeLimit after `limit` seconds (0 or None: no limit; SIGALRM,
    so in the main thread of a worker process)."""
    if limit:
        signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(max(1, int(limit)))
    try:
        return fn(*args, **kwargs)
    finally:
        if limit:
            signal.alarm(0)


TimeLimit = _Timeout


def check(job):
    import gecko
    from mpmath import mp
    import seta_separatrix_mp as ssm

    i, j, p, fts, limit = job
    d = dict(zip(campaign.FIELDS, map(float, p)))
    line = gecko.TwoLevelSeta(**d).critical_line(Ft=list(map(float, fts)), errors="nan")
    Ft = float(fts[j])
    Fn, beta = float(line.Fn[j]), float(line.theta_joint[j])
    rp, rq = float(line.theta_rate_joint[j]), float(line.theta_rate_base[j])
    turns = (int(line.turning_points_beam[j]), int(line.turning_points_spatula[j]))
    N = math.hypot(Fn, Ft)
    L1, L2 = ssm.saddle_lengths(d, N)
    out = dict(design=int(i), Ft=Ft, status=int(line.status[j]), Fn=Fn, beta=beta, turning=list(turns),
               elastic_lengths=[round(L1, 1), round(L2, 1)], min_z=float(line.min_z[j]))
    if out["status"] not in (0, 7):
        out["verdict"] = "not_solved_now"
        return out
    t = time.time()
    # A state the route cannot settle within the time limit is undecided, not waited on (at
    # hundreds of digits its Newton can take hours where the quadrature does not converge).
    if limit:
        signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(max(1, int(limit)))
    try:
        # First the bracketing shot: conclusive where it finds the state's own root.
        b = ssm.bracket_route(d, Ft, Fn, L1 + L2) if L1 + L2 <= 100 else None
        if b is not None:
            out["shot_root"] = dict(dFn_rel=float(abs(b["Fn"] - Fn) / max(1, abs(Fn))),
                                    dbeta=float(abs(b["beta"] - beta)), q=float(b["q"]), turning=list(b["turns"]))
            same_path = (tuple(b["turns"]) == turns and abs(float(b["q"]) - rq) <= 1e-8 * max(1.0, abs(rq)))
            if same_path:
                out["route"] = "shot bracket"
                out["dFn_rel"] = out["shot_root"]["dFn_rel"]
                out["dbeta"] = out["shot_root"]["dbeta"]
                out["seconds"] = round(time.time() - t, 1)
                out["verdict"] = "correct" if out["dbeta"] <= 1e-11 else "wrong"
                return out
        elif L1 + L2 > 100:
            # No time for the bisection (40 + 1.5 length shots at 128 + 1.5 length bits): the two
            # bracketing shots decide Fn and beta, not the path (out["route"] says so).
            e = ssm.bracket_ends(d, Ft, Fn, L1 + L2)
            dbeta = max(float(abs(b_ - beta)) for b_ in e["beta"])
            out["bracket_ends"] = dict(sign_change=e["sign_change"], dbeta=dbeta)
            # beta that varies over the bracket by more than that (a long spatula) decides nothing
            if e["sign_change"] and dbeta <= 1e-11:
                out["route"] = "shot bracket ends (Fn, beta; path not compared)"
                out["dFn_rel"] = 1e-11  # a bound: the bracket's half-width, the root lies within it
                out["dFn_rel_is_bound"] = True
                out["dbeta"] = dbeta
                out["seconds"] = round(time.time() - t, 1)
                out["verdict"] = "correct"
                return out
        out["route"] = "quadrature"
        mp.dps = int(40 + (L1 + L2) / 2)
        # A long segment with turning points librates (they lie at the saddle); without, it
        # rotates past the saddle.
        r = ssm.quad_route(d, Ft, Fn, beta, 1 if rp > 0 else -1, 1 if rq > 0 else -1, turns,
                           (L1 >= 15, L2 >= 15), rotation=(turns[0] == 0, turns[1] == 0))
    except _Timeout:
        r = None
        out["error"] = f"time limit ({limit} s)"
    except Exception as e:  # a radicand < 0 on the assumed path, a singular Jacobian, ...
        r = None
        out["error"] = repr(e)[:160]
    finally:
        if limit:
            signal.alarm(0)
    out["seconds"] = round(time.time() - t, 1)
    if r is None:
        out["verdict"] = "undecided"
        return out
    out["dFn_rel"] = abs(float(r[0]) - Fn) / max(1.0, abs(Fn))
    out["dbeta"] = abs(float(r[1]) - beta)
    out["quad_error"] = float(r[3])
    if not r[3] < 1e-20:  # the quadrature's own error estimate: too large to decide at 1e-11
        out["verdict"] = "undecided"
    else:
        out["verdict"] = "correct" if out["dFn_rel"] <= 1e-11 and out["dbeta"] <= 1e-11 else "wrong"
    return out


def _solved_in_both(old, now):
    """States both re-runs solve (status 0 or 7), and their Fn's relative change."""
    solved = np.isin(old["status"], (0, 7)) & np.isin(now["status"], (0, 7))
    with np.errstate(invalid="ignore"):
        rel = np.abs(old["Fn"] - now["Fn"]) / np.maximum(1.0, np.abs(old["Fn"]))
    return solved, rel


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz")
    ap.add_argument("--sample", type=int, default=24)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--json", default=None)
    ap.add_argument("--since", default=None, help="sample only states this earlier re-run (.npz) gave up on")
    ap.add_argument("--moved", default=None,
                    help="sample instead the states this earlier re-run (.npz) solved too (0 or 7), with Fn more "
                         "than 1e-10 (relative) from the re-run's: a solver change's moved states")
    ap.add_argument("--turned", default=None,
                    help="sample instead the states this earlier re-run (.npz) solved too, with Fn within 1e-10 "
                         "(relative) of the re-run's but other turning-point counts: a path changed in place")
    ap.add_argument("--time-limit", type=float, default=300,
                    help="seconds per state before it counts as undecided (0: none)")
    a = ap.parse_args(argv)
    camp = np.load(os.path.join(HERE, "data", "stress_10000_states.npz"))
    now = np.load(a.npz)
    given_up = np.isin(camp["status"], (1, 6)) & np.isin(now["status"], (0, 7))
    if a.since:
        given_up &= np.isin(np.load(a.since)["status"], (1, 6))
    if a.moved:
        old = np.load(a.moved)
        solved, rel = _solved_in_both(old, now)
        given_up = solved & (rel > 1e-10)
    if a.turned:
        old = np.load(a.turned)
        solved, rel = _solved_in_both(old, now)
        given_up = solved & (rel <= 1e-10) & ((old["tpb"] != now["tpb"]) | (old["tps"] != now["tps"]))
    idx = np.argwhere(given_up)
    rng = np.random.default_rng(a.seed)
    pick = idx[rng.choice(len(idx), size=min(a.sample, len(idx)), replace=False)]
    jobs = [(int(i), int(j), camp["P"][i], camp["FT"][i], a.time_limit) for i, j in pick]
    t0 = time.time()
    with mpc.Pool(a.workers) as pool:
        results = pool.map(check, jobs, chunksize=1)
    verdicts = {}
    for r in results:
        verdicts[r["verdict"]] = verdicts.get(r["verdict"], 0) + 1
    decided = [r for r in results if "dFn_rel" in r]
    summary = dict(npz=a.npz, since=a.since, moved=a.moved, turned=a.turned, time_limit=a.time_limit, recovered=int(given_up.sum()), sample=len(jobs), seed=a.seed, verdicts=verdicts,
                   max_dFn_rel=max((r["dFn_rel"] for r in decided), default=None),
                   max_dbeta=max((r["dbeta"] for r in decided), default=None),
                   longest_segment=max((max(r["elastic_lengths"]) for r in results), default=None),
                   seconds=round(time.time() - t0, 1), states=results)
    text = json.dumps(summary, indent=1)
    print(json.dumps({k: v for k, v in summary.items() if k != "states"}, indent=1))
    if a.json:
        with open(a.json, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
