#!/usr/bin/env python3
"""Stress campaign of the two-level seta solver (issue 6, "Evidence"): random designs over a wide
box, every returned critical state verified by an independent ODE shooting route
(validation/verify.py, no gecko code), statuses histogrammed, worst cases kept.

    python3 -m validation.campaign --designs 10000 --workers 2 --out validation/stress_10000.npz
    python3 -m validation.report validation/stress_10000.npz

The designs are split into chunks (--chunk designs each); each chunk (gecko, then the verifier) runs
in its own process, --workers at once, and is saved to <out>_chunks/chunk_NNNNN.npz as soon as it
is done. Re-running the same command resumes: finished chunks are kept, the rest are run, then all
are merged into <out>. The designs depend only on --seed and --designs, never on the chunking.

Box (non-dimensional, w = 1, l1 = 1): EI1/(w l1^2) log-uniform 0.1..200, EI2/EI1 log-uniform
1e-3..1e3, l2/l1 log-uniform 1e-3..1, alpha1 uniform 0.01..pi/2-0.01, alpha2 uniform
0..pi/2-alpha1-0.01, EA1/w and EA2/w each log-uniform 2..1e8 or (probability 0.2) infinite.
Ft per design: -u0 F, 0, u1 F, u2 F, 0.9 F, 0.999 F with u_i uniform(0,1) and F = (Ft)max =
sqrt(2 EA2 w) (for EA2 = inf: F = 3 sqrt(EI1 w)/l1, the solver's default trace end).

gecko is called per design (TwoLevelSeta.critical_line(Ft=...), errors="nan") in a worker
process with a wall-clock limit per design (--timeout): a design that takes longer is recorded as
"timeout" (a finding in itself) and the worker restarted.  The thread check uses the batch call.

Silently wrong: status 0 and |Fn - Fn_verifier| > 1e-8 max(1, |Fn|), or a non-finite Fn/beta
with status 0, or a finite Fn with status != 0.
"""
from __future__ import annotations

import argparse
import json
import math
import multiprocessing as mp
import os
import sys
import time

import numpy as np

from . import verify  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # where "-m validation.campaign" runs
FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")
WRONG_REL = 1e-8
INADMISSIBLE = 7  # the critical status that keeps Fn and beta (gecko.CriticalStatus.inadmissible)


def solved(status):
    """Mask of the solved states: status 0, and 7 (inadmissible), which keeps its values."""
    return (status == 0) | (status == INADMISSIBLE)


def sample_designs(n, rng, p_inf=0.2):
    lu = lambda lo, hi, size: 10.0 ** rng.uniform(math.log10(lo), math.log10(hi), size)  # noqa: E731
    EI1 = lu(0.1, 200.0, n)
    EI2 = EI1 * lu(1e-3, 1e3, n)
    l2 = lu(1e-3, 1.0, n)
    a1 = rng.uniform(0.01, math.pi / 2 - 0.01, n)
    a2 = rng.uniform(0.0, 1.0, n) * np.maximum(0.0, math.pi / 2 - a1 - 0.01)
    EA1 = np.where(rng.random(n) < p_inf, np.inf, lu(2.0, 1e8, n))
    EA2 = np.where(rng.random(n) < p_inf, np.inf, lu(2.0, 1e8, n))
    return np.column_stack([EI1, EI2, EA1, EA2, np.ones(n), l2, a1, a2, np.ones(n)])


def seta(p):
    """The gecko.TwoLevelSeta of one design row p (FIELDS order)."""
    import gecko
    return gecko.TwoLevelSeta(**dict(zip(FIELDS, (float(x) for x in p))))


def compliances(P):
    """c = 1 / EA of each design's beam and spatula (0 for EA = inf), as columns (one row for a
    single design p)."""
    P = np.atleast_2d(P)
    EA1, EA2 = P[:, 2:3], P[:, 3:4]
    with np.errstate(divide="ignore"):
        return np.where(np.isinf(EA1), 0.0, 1.0 / EA1), np.where(np.isinf(EA2), 0.0, 1.0 / EA2)


def ft_scale(P):
    EI1, EA2, l1, w = P[:, 0], P[:, 3], P[:, 4], P[:, 8]
    return np.where(np.isfinite(EA2), np.sqrt(2 * EA2 * w), 3 * np.sqrt(EI1 * w) / l1)


def sample_ft(P, rng):
    F = ft_scale(P)
    u = rng.random((P.shape[0], 3))
    return np.column_stack([-u[:, 0] * F, np.zeros(len(F)), u[:, 1] * F, u[:, 2] * F, 0.9 * F, 0.999 * F])


# ----------------------------------------------------------------------------------- worker
def _worker(conn):
    while True:
        msg = conn.recv()
        if msg is None:
            return
        p, ft = msg
        L = seta(p).critical_line(Ft=np.asarray(ft), errors="nan")
        conn.send((L.Fn, L.theta_joint, L.status, L.turning_points_beam, L.turning_points_spatula,
                   L.iterations))


class Runner:
    def __init__(self, timeout):
        self.timeout = timeout
        self.ctx = mp.get_context("fork")
        self._start()

    def _start(self):
        self.conn, child = self.ctx.Pipe()
        self.proc = self.ctx.Process(target=_worker, args=(child,), daemon=True)
        self.proc.start()

    def call(self, p, ft):
        self.conn.send((list(map(float, p)), list(map(float, ft))))
        if self.conn.poll(self.timeout):
            return self.conn.recv()
        self.proc.kill()
        self.proc.join()
        self._start()
        return None

    def close(self):
        self.conn.send(None)
        self.proc.join(5)


def run_gecko(P, FT, timeout, progress=True):
    n, m = FT.shape
    Fn = np.full((n, m), np.nan)
    beta = np.full((n, m), np.nan)
    status = np.full((n, m), -1, dtype=np.int64)   # -1: timeout
    tpb = np.zeros((n, m), dtype=np.int64)
    tps = np.zeros((n, m), dtype=np.int64)
    secs = np.zeros(n)
    r = Runner(timeout)
    t0 = time.time()
    for i in range(n):
        t = time.time()
        out = r.call(P[i], FT[i])
        secs[i] = time.time() - t
        if out is not None:
            Fn[i], beta[i], status[i], tpb[i], tps[i], _ = out
        if progress and (i + 1) % 1000 == 0:
            print(f"  gecko {i + 1}/{n} designs, {time.time() - t0:.1f} s", flush=True)
    r.close()
    return Fn, beta, status, tpb, tps, secs


def design_dict(P):
    return {f: P[:, k].copy() for k, f in enumerate(FIELDS)}


def short_campaign_designs():
    """The designs and Ft of the short campaign (tests/python/test_stress_short.py): 40 designs,
    six Ft each, seed 6."""
    rng = np.random.default_rng(6)
    P = sample_designs(40, rng)
    return P, sample_ft(P, rng)


def verify_states(P, FT, Fn, beta, status, chunk=4000, verifier=None):
    """Verify every solved state (status 0, and 7, which keeps its values); returns per-state arrays
    (NaN where not verified). verifier: a module with verify.py's ``verify`` (default verify.py)."""
    n, m = FT.shape
    rows, cols = np.nonzero(solved(status))
    out = {k: np.full((n, m), np.nan) for k in ("dFn", "dbeta", "fn_uncert", "beta_uncert", "theta_err", "R", "S")}
    out["steps"] = np.zeros((n, m), dtype=np.int64)
    out["turns_beam"] = np.full((n, m), -1, dtype=np.int64)
    out["turns_spatula"] = np.full((n, m), -1, dtype=np.int64)
    out["root_turns_beam"] = np.full((n, m), -1, dtype=np.int64)
    out["root_turns_spatula"] = np.full((n, m), -1, dtype=np.int64)
    out["root_found"] = np.zeros((n, m), dtype=bool)
    for c0 in range(0, rows.size, chunk):
        r, c = rows[c0:c0 + chunk], cols[c0:c0 + chunk]
        d = design_dict(P[r])
        v = (verifier or verify).verify(d, FT[r, c], Fn[r, c], beta[r, c])
        for k in out:
            out[k][r, c] = v[k]
    return out


def classify(P, FT, Fn, beta, status, v, turns=None):
    """Silently wrong: status 0 and the verifier, where it is conclusive (its own uncertainty below a
    tenth of the threshold), disagrees by more than WRONG_REL; NaN or a number where the status
    says otherwise.

    turns: optional (tpb, tps), gecko's turning-point counts of each state. Given, the verifier is
    conclusive only where the shot at the returned Fn and the shot at its own root both count these
    turning points: a root on another branch of the shot (other turns) is not a verdict on the state.
    The states excluded by this rule alone are returned as ``other_branch``."""
    scale = np.maximum(1.0, np.abs(Fn))
    # 7 (inadmissible: the seta crosses the substrate) is a solved state with its values kept, so
    # it is verified like 0
    ok = solved(status)
    rel = np.abs(v["dFn"]) / scale
    conclusive_fn = v["fn_uncert"] / scale < 0.1 * WRONG_REL
    conclusive_beta = v["beta_uncert"] < 0.1 * WRONG_REL
    # NaN dFn: the verifier's damped Newton found no root near the returned Fn -> inconclusive
    # (reported separately; every such case so far is a huge-force, rounding-amplifying state)
    conclusive_fn &= np.isfinite(rel)
    other_branch = np.zeros(np.shape(status), dtype=bool)
    if turns is not None:
        tpb, tps = turns
        same = ((v["turns_beam"] == tpb) & (v["turns_spatula"] == tps) &
                (v["root_turns_beam"] == tpb) & (v["root_turns_spatula"] == tps))
        other_branch = ok & conclusive_fn & ~same
        conclusive_fn &= same
    wrong_fn = ok & conclusive_fn & ~(rel <= WRONG_REL)
    wrong_beta = ok & conclusive_fn & conclusive_beta & ~(np.abs(v["dbeta"]) <= WRONG_REL)
    nonfinite_ok = ok & ~(np.isfinite(Fn) & np.isfinite(beta))
    number_with_status = ~ok & (np.isfinite(Fn) | np.isfinite(beta))
    return dict(rel=rel, wrong_fn=wrong_fn, wrong_beta=wrong_beta, nonfinite_ok=nonfinite_ok,
                number_with_status=number_with_status, inconclusive_fn=ok & ~conclusive_fn,
                inconclusive_beta=ok & ~conclusive_beta, other_branch=other_branch)


def run_chunk(P, FT, timeout):
    """gecko (watchdog per design) + verification of one chunk of designs; a dict of arrays."""
    t = time.time()
    Fn, beta, status, tpb, tps, secs = run_gecko(P, FT, timeout, progress=False)
    t_gecko = time.time() - t
    t = time.time()
    v = verify_states(P, FT, Fn, beta, status)
    t_ver = time.time() - t
    return dict(P=P, FT=FT, Fn=Fn, beta=beta, status=status, tpb=tpb, tps=tps, secs=secs,
                t_gecko=np.float64(t_gecko), t_ver=np.float64(t_ver), **{"v_" + k: x for k, x in v.items()})


def print_json(out, path=None, omit=()):
    """Print a result dict (without the keys in omit), and write all of it to path (JSON) when
    given (the study scripts' output)."""
    print(json.dumps({k: v for k, v in out.items() if k not in omit}, indent=1))
    if path:
        with open(path, "w") as f:
            json.dump(out, f, indent=1)
    return out


def compare_main(run, doc, argv=None, omit=()):
    """The command line of a study that compares two ``recheck --save`` files of one campaign:
    ``old new [--json F]``, run(old, new) printed (without omit) and saved by print_json."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old", help="recheck --save file before the change")
    ap.add_argument("new", help="recheck --save file after it")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    return print_json(run(args.old, args.new), args.json, omit)


def chunk_path(outdir, k):
    return os.path.join(outdir, f"chunk_{k:05d}.npz")


def merge_chunks(outdir, nchunks, chunk, partial=False):
    """Concatenate the chunk files (in order) into one campaign dict; None if one is missing,
    unless partial (then the finished ones, with their design indices in 'design_index')."""
    parts = []
    index = []
    for k in range(nchunks):
        f = chunk_path(outdir, k)
        if not os.path.exists(f):
            if partial:
                continue
            return None
        parts.append(np.load(f))
        index.append(np.arange(k * chunk, k * chunk + parts[-1]["P"].shape[0]))
    if not parts:
        return None
    out = {"design_index": np.concatenate(index)}
    for key in parts[0].files:
        if key in ("t_gecko", "t_ver"):
            out[key] = np.float64(sum(float(z[key]) for z in parts))
        else:
            out[key] = np.concatenate([z[key] for z in parts])
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--designs", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=20261121)
    ap.add_argument("--timeout", type=float, default=10.0, help="wall-clock limit per design (s)")
    ap.add_argument("--out", required=True, help="merged campaign file (.npz)")
    ap.add_argument("--workers", type=int, default=2, help="chunks run at once (separate processes)")
    ap.add_argument("--chunk", type=int, default=250, help="designs per chunk")
    ap.add_argument("--merge-only", action="store_true",
                    help="merge the chunks finished so far into --out (a partial campaign) and stop")
    ap.add_argument("--run-chunk", type=int, default=None, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    P = sample_designs(args.designs, rng)
    FT = sample_ft(P, rng)
    outdir = args.out[:-4] + "_chunks" if args.out.endswith(".npz") else args.out + "_chunks"
    os.makedirs(outdir, exist_ok=True)
    nchunks = (args.designs + args.chunk - 1) // args.chunk
    if args.run_chunk is not None:   # a worker: one chunk, written atomically
        k = args.run_chunk
        sl = slice(k * args.chunk, min(args.designs, (k + 1) * args.chunk))
        res = run_chunk(P[sl], FT[sl], args.timeout)
        tmp = chunk_path(outdir, k)[:-4] + ".tmp.npz"
        np.savez_compressed(tmp, **res)
        os.replace(tmp, chunk_path(outdir, k))
        return None
    if args.merge_only:
        res = merge_chunks(outdir, nchunks, args.chunk, partial=True)
        np.savez_compressed(args.out, **res)
        print(f"merged {res['P'].shape[0]} designs (of {args.designs}) into {args.out}", flush=True)
        return res
    # Driver: every missing chunk in a worker process (resumable: finished chunks are kept).
    import subprocess
    todo = [k for k in range(nchunks) if not os.path.exists(chunk_path(outdir, k))]
    print(f"{nchunks} chunks of {args.chunk} designs, {len(todo)} to run, {args.workers} workers -> {outdir}",
          flush=True)
    base = [sys.executable, "-m", "validation.campaign", "--designs", str(args.designs), "--seed", str(args.seed),
            "--timeout", str(args.timeout), "--out", os.path.abspath(args.out), "--chunk", str(args.chunk)]
    running = {}
    t0 = time.time()
    done = 0
    failed = []
    while todo or running:
        while todo and len(running) < args.workers:
            k = todo.pop(0)
            running[k] = subprocess.Popen(base + ["--run-chunk", str(k)], cwd=ROOT)
        time.sleep(0.5)
        for k, pr in list(running.items()):
            if pr.poll() is not None:
                del running[k]
                done += 1
                if pr.returncode != 0:
                    failed.append(k)
                print(f"  chunk {k} rc {pr.returncode} ({done} done, {time.time() - t0:.0f} s)", flush=True)
    if failed:
        raise SystemExit(f"chunks failed: {failed} (re-run the same command to retry them)")
    res = merge_chunks(outdir, nchunks, args.chunk)
    np.savez_compressed(args.out, **res)
    print(f"merged {nchunks} chunks into {args.out} ({time.time() - t0:.0f} s)", flush=True)
    return res


if __name__ == "__main__":
    main()
