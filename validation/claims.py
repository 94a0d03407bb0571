#!/usr/bin/env python3
"""Independent check of the critical line's "no state" claims (status 2 and 3) on the stress
campaign's states (validation/data/stress_10000_states.npz), by a scan in Fn with the shooting
route of validation/verify.py (no gecko code in the scan).

What the claims say (include/gecko/seta/solve_critical.hpp, critical_line.hpp):

* status 2, no critical state: the critical line followed from Ft = 0 does not reach this Ft (it
  turned back at a fold before it, or |Ft| > (Ft)max, where Griffith's condition, paper 001 eq (3),
  holds at no edge).
* status 3, unsupported state: the critical state at this Ft lies outside the model's forms (the
  axial load comparable to EA: f4(u) = 1 + b4 u of a segment vanishes on [-1, 1], b4 >= 1), or the
  followed line left the forms before reaching this Ft.

The scan: every critical state at Ft is a root of the base mismatch R(Fn) = theta1(0) - alpha1 of
the backward shot from the contact edge (theta2 = pi/2, theta2' = +sqrt(2 (w - Ft^2/(2 EA2))/EI2))
across the joint to the base (paper 001 eqs 2-5, 15). R is sampled on a grid of Fn over a wide
range (sinh-spaced, dense near 0, out to +-S with S = 10 max(|Ft|, F, EI1/l1^2, w), F the
campaign's Ft scale), each sign change with both signs above the shot's own error estimate is
refined by bisection (30 halvings) and kept as a root only where |R| at the bracket's ends falls
as the bracket shrinks (a sign change across a jump of the shot, its beta switching branch, is
recorded apart as a jump, one the shot's accuracy cannot resolve as unresolved), and every root
is classified by the model's forms at that state (b4 < 1 and
1 + 2 c M > 0 for beam and spatula, with M from the first integrals, eqs 8 and 12: the spatula's
M2 = Ft + w, the beam's from the joint conditions, eq 4). Only theta1(0) = alpha1 itself is a
root (not alpha1 + 2 pi k: the solver's shortest-path convention).

Per state:

* ``no_root``: no root of R in the scanned range (no sign change, or only jumps): the claim is
  confirmed (there is no critical state at this Ft at all, in that range).
* ``roots_outside_forms``: every root leaves the model's forms: the claim is confirmed (no state
  the model can represent).
* ``root_in_forms``: a root inside the forms exists. A scan at one Ft cannot say whether it lies
  on the line followed from Ft = 0; the gecko trace (used only here, after the scan) says whether
  that line ended before this Ft as the claim states (``turned_back`` at a fold for status 2,
  ``unsupported_state`` for status 3: the root then lies on another branch, or beyond a stretch
  outside the forms, and the claim as stated holds: ``root_beyond_line_end``; for status 3 with
  no line at all, because the homotopy to the natural state ran into the edge of the forms:
  ``root_but_no_natural_state``), else
  ``contradicted``: the solver should have found the state. ``root_below_traced_range``: Ft < 0
  below every traced node (the trace runs from Ft = 0 towards (Ft)max): the claim "not reached"
  holds by construction, but a critical state exists there.
* ``undecided``: some grid signs are below the shot's error estimate, or a sign change could not
  be resolved as a root or a jump (stiff shots at large |Fn|).

    python3 -m validation.claims --sample 40 [--seed 1] [--grid 61] [--json validation/results/claims.json]
    python3 -m validation.claims --npz NEW.npz --since OLD.npz --json F.json   (every new claim)
    python3 -m validation.claims --npz NEW.npz --since OLD.npz --sample 12 --json F.json  (12 of them)
    python3 -m validation.claims --npz NEW.npz --since OLD.npz --column 1 --json F.json  (those at Ft = 0)
    python3 -m validation.claims --npz NEW.npz --since OLD.npz --status 3 --json F.json  (the new status 3)
    python3 -m validation.claims --redo F.json --json G.json  (the states of an earlier results file again)
"""
from __future__ import annotations

import argparse
import json
import math
import os
import time

import numpy as np

from . import verify
from .campaign import FIELDS, ft_scale
from .recheck import STATES

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", "claims.json")


def fn_grid(S: float, n: int) -> np.ndarray:
    """n values of Fn in [-S, S], sinh-spaced (a tenth of the points within S/100 of 0)."""
    u = np.linspace(-1.0, 1.0, n)
    return S * np.sinh(6.0 * u) / math.sinh(6.0)


def scan_range(p: np.ndarray, ft: float) -> float:
    d = dict(zip(FIELDS, p))
    F = float(ft_scale(p[None, :])[0])
    return 10.0 * max(abs(ft), F, d["EI1"] / d["l1"] ** 2, d["w"])


def _design_rows(p, k):
    return {f: np.full(k, float(v)) for f, v in zip(FIELDS, p)}


N_SCAN_MAX = 1 << 10  # steps per segment of a scan shot (signs only: no step doubling to 1e-13)


def _shoot(p, ft, fn):
    """R = theta1(0) - alpha1 and beta for each Fn, with the shot's error estimate: one pass of
    verify's n- and 2n-step shots (order 8: the 2n error is ~|difference|/255), n from its a-priori
    estimate; a sign is trusted only where |R| exceeds that estimate."""
    fn = np.asarray(fn, float)
    k = fn.size
    d = _design_rows(p, k)
    ftv = np.full(k, float(ft))
    est = verify.step_estimate(d, ftv, fn)
    n = np.minimum(np.maximum(verify.N_MIN, 2.0 ** np.ceil(np.log2(np.maximum(1.0, 1.5 * est)))), N_SCAN_MAX)
    n = n.astype(np.int64)
    both = {key: np.concatenate([v, v]) for key, v in d.items()}
    th, be, _, _ = verify._shoot_fixed(both, np.concatenate([ftv, ftv]), np.concatenate([fn, fn]),
                                       np.concatenate([n, 2 * n]))
    err = (np.abs(th[k:] - th[:k]) + np.abs(be[k:] - be[:k])) / 255.0 + 1e-14 * (1 + np.abs(th[k:]))
    err = np.where(np.isfinite(err), err, np.inf)
    return th[k:] - d["alpha1"], be[k:], err


def forms(p, ft: float, fn: float, beta: float) -> dict:
    """The model's forms at a critical state (Ft, Fn, beta): b4 and 1 + 2 c M per segment."""
    d = dict(zip(FIELDS, map(float, p)))
    N = math.hypot(fn, ft)
    phi = math.atan2(fn, ft)
    c1 = 0.0 if math.isinf(d["EA1"]) else 1.0 / d["EA1"]
    c2 = 0.0 if math.isinf(d["EA2"]) else 1.0 / d["EA2"]
    M2 = ft + d["w"]  # eq (12) with Griffith's condition at the edge, eq (3)
    ub = math.sin(beta - phi)
    R2 = M2 - N * ub - c2 * N * N * ub * ub / 2  # 1/2 EI2 theta2'(l1)^2
    v = math.sin(beta - d["alpha2"] - phi)
    M1 = d["EI2"] / d["EI1"] * R2 + N * v + c1 * N * N * v * v / 2  # eq (4): EI1 theta1' = EI2 theta2'
    out = {}
    for name, c, M in (("beam", c1, M1), ("spatula", c2, M2)):
        q = 1.0 + 2.0 * c * M
        b4 = c * N / (1.0 + math.sqrt(q)) if q > 0 else math.inf
        out[name] = {"b4": b4, "one_plus_2cM": q, "in_forms": bool(q > 0 and b4 < 1.0)}
    out["in_forms"] = out["beam"]["in_forms"] and out["spatula"]["in_forms"]
    return out


SHRINK_STAGE = 5          # halvings per stage of the root test (the last two stages are tested)
SHRINK_PER_STAGE = 2.0 ** -1.5  # |R| ~ |Fn - root|^a falls by 2^(-5 a) per stage: a >= 0.3 passes


def refine(shoot, lo, hi, r_lo, r_hi, bisections: int = 30):
    """Bisect sign-change brackets [lo, hi] of R (values r_lo, r_hi there; arrays) and tell roots
    from sign changes that are not roots.

    ``shoot(x)`` returns (R, beta, err) at the points x. Bisection converges to a sign change
    whether R passes through 0 there or jumps across it (the shot's beta switching branch), and
    it follows the shot's noise where the shot is not accurate. What tells them apart is the
    spread |R(lo)| + |R(hi)| at the bracket's ends: at a root it falls with the bracket's width
    (by 2^-5 per five halvings at a simple root, by 2^(-5 a) where |R| ~ |Fn - root|^a); across a
    jump it settles at the jump; in noise it wanders. Kinds, from the spreads s20, s25, s30 after
    bisections - 10, - 5 and all halvings:

    * ``root``: the spread fell by SHRINK_PER_STAGE in each of the last two stages, or it is within
      ten times the shot's error estimate at the midpoint (a root resolved to the shot's noise);
    * ``jump``: not a root, and R at each end moved by less than 1 % of s30 (plus ten error
      estimates) over the last ten halvings (R settled on the limits of both sides);
    * ``unresolved``: neither (the shot is not accurate enough there to say).

    Returns the midpoints x, R, beta and err there, the final spread and the kinds (an array of
    strings).
    """
    lo, hi = np.array(lo, float), np.array(hi, float)
    r_lo, r_hi = np.array(r_lo, float), np.array(r_hi, float)
    spreads, ends20 = {}, (r_lo, r_hi)
    for k in range(bisections + 1):
        left = bisections - k
        if left in (2 * SHRINK_STAGE, SHRINK_STAGE, 0):
            spreads[left] = np.abs(r_lo) + np.abs(r_hi)
        if left == 2 * SHRINK_STAGE:
            ends20 = (r_lo, r_hi)
        if left == 0:
            break
        mid = 0.5 * (lo + hi)
        rm, _, _ = shoot(mid)
        same = np.sign(rm) == np.sign(r_lo)
        lo, r_lo = np.where(same, mid, lo), np.where(same, rm, r_lo)
        hi, r_hi = np.where(same, hi, mid), np.where(same, r_hi, rm)
    s20 = spreads.get(2 * SHRINK_STAGE, spreads[0])
    s25 = spreads.get(SHRINK_STAGE, spreads[0])
    s30 = spreads[0]
    x = 0.5 * (lo + hi)
    rx, bx, ex = shoot(x)
    falls = (s25 <= SHRINK_PER_STAGE * s20) & (s30 <= SHRINK_PER_STAGE * s25)
    is_root = falls | (s30 <= 10.0 * ex)  # the second: both ends at the shot's noise
    # a jump: R at each end settled on its side's limit over the last ten halvings
    moved = np.abs(r_lo - ends20[0]) + np.abs(r_hi - ends20[1])
    settled = moved <= 0.01 * s30 + 10.0 * ex
    kind = np.where(is_root, "root", np.where(settled, "jump", "unresolved"))
    return x, rx, bx, ex, s30, kind


def scan_state(p, ft: float, grid: int = 61, bisections: int = 30) -> dict:
    """The scan of one state (design p, Ft): grid signs, refined roots and their forms, and the
    sign changes that are jumps of the shot or that its accuracy cannot resolve (see ``refine``)."""
    S = scan_range(p, ft)
    fn = fn_grid(S, grid)
    R, _, er = _shoot(p, ft, fn)
    reliable = np.isfinite(R) & (np.abs(R) > er)
    sign = np.where(reliable, np.sign(R), 0.0)
    ks = [k for k in range(grid - 1) if sign[k] != 0 and sign[k + 1] != 0 and sign[k] != sign[k + 1]]
    roots, jumps, unresolved = [], [], []
    if ks:
        ks = np.array(ks)
        x, Rx, bx, ex, spread, kind = refine(lambda v: _shoot(p, ft, v), fn[ks], fn[ks + 1], R[ks], R[ks + 1],
                                             bisections)
        for k in range(x.size):
            entry = {"Fn": float(x[k]), "beta": float(bx[k]), "R": float(Rx[k]), "R_err": float(ex[k]),
                     "bracket_R": float(spread[k])}
            if kind[k] != "root":
                (jumps if kind[k] == "jump" else unresolved).append(entry)
                continue
            f = forms(p, ft, float(x[k]), float(bx[k]))
            roots.append({**entry, "in_forms": f["in_forms"], "b4_beam": f["beam"]["b4"],
                          "b4_spatula": f["spatula"]["b4"]})
    return {"S": S, "grid": grid, "unreliable_nodes": int((~reliable).sum()), "roots": roots, "jumps": jumps,
            "unresolved": unresolved}


def classify(scan: dict) -> str:
    if any(r["in_forms"] for r in scan["roots"]):
        return "root_in_forms"
    if scan["unreliable_nodes"] or scan["unresolved"]:
        return "undecided"
    return "roots_outside_forms" if scan["roots"] else "no_root"


def line_end_check(p, ft: float, status: int) -> str:
    """After the scan (gecko, for the in-forms roots only): did the line followed from Ft = 0 end
    before this Ft as the claim says (a fold for status 2, leaving the forms for status 3)?"""
    import gecko
    s = gecko.TwoLevelSeta(**dict(zip(FIELDS, map(float, p))))
    line = s.critical_line(errors="nan")
    if not len(line.Ft) and status == 3 and line.end_code == gecko.LineEnd.unsupported_state:
        # No line at all: the homotopy to the natural state ran into the edge of the forms, so the
        # line followed from Ft = 0 left them before it started. The root lies on a branch that
        # the homotopy from the small-deformation limit does not reach inside the forms.
        return "root_but_no_natural_state"
    if len(line.Ft) and ft < float(np.min(line.Ft)):
        # The trace runs from Ft = 0 towards (Ft)max: a negative Ft below its range is "not
        # reached" by construction, though a critical state exists there.
        return "root_below_traced_range"
    ended = line.end_code == (gecko.LineEnd.turned_back if status == 2 else gecko.LineEnd.unsupported_state)
    ft_end = float(line.Ft[-1]) if len(line.Ft) else 0.0
    return "root_beyond_line_end" if ended and ft > ft_end else "contradicted"


def sample_claims(z, n: int, seed: int):
    """n (design, column) pairs with status 2 or 3, half of each where there are enough."""
    rng = np.random.default_rng(seed)
    st = z["status"]
    picks = []
    for code in (2, 3):
        idx = np.argwhere(st == code)
        m = min(len(idx), n // 2 + (n % 2 if code == 2 else 0))
        picks += [tuple(map(int, idx[k])) for k in rng.choice(len(idx), size=m, replace=False)]
    return picks


def new_claims(z, old, column: int | None = None, status: int | None = None) -> list:
    """Every (design, column) whose status is 2 or 3 in ``z`` and was something else in ``old`` (a
    ``validation.recheck --save`` file of an earlier solver on the same states): the claims a
    solver change made, all of them rather than a sample; only those in ``column`` and of
    ``status`` where given."""
    st, so = z["status"], old["status"]
    if st.shape != so.shape or not np.array_equal(z["P"], old["P"]) or not np.array_equal(z["FT"], old["FT"]):
        raise SystemExit("--since: the two files hold different states (designs or Ft differ)")
    codes = (2, 3) if status is None else (status,)
    picks = [tuple(map(int, ij)) for ij in np.argwhere(np.isin(st, codes) & (st != so))]
    return picks if column is None else [(i, j) for i, j in picks if j == column]


def redo_claims(z, path: str) -> tuple:
    """The (design, column) pairs of an earlier results file, checked against ``z``: the same
    states scanned again (after a change to the scan) without the files that picked them."""
    with open(path) as f:
        old = json.load(f)
    picks = [(int(s["design"]), int(s["column"])) for s in old["states"]]
    for (i, j), s in zip(picks, old["states"]):
        if float(z["FT"][i, j]) != float(s["Ft"]):
            raise SystemExit(f"--redo: design {i} column {j} has Ft {float(z['FT'][i, j])!r} here, "
                             f"{s['Ft']!r} in {path}")
    return picks, [int(s["status"]) for s in old["states"]]


def run(n: int | None, seed: int = 1, grid: int = 61, npz: str = STATES, progress: bool = False,
        since: str = None, redo: str = None, column: int | None = None, status: int | None = None) -> dict:
    z = np.load(npz)
    P, FT, ST = z["P"], z["FT"], z["status"]
    t0 = time.time()
    states = []
    statuses = None
    if redo:
        picks, statuses = redo_claims(z, redo)
    elif since:
        picks = new_claims(z, np.load(since), column, status)
        if n is not None and n < len(picks):  # a seeded sample of them (a scan takes seconds to minutes)
            rng = np.random.default_rng(seed)
            picks = [picks[k] for k in sorted(rng.choice(len(picks), size=n, replace=False))]
    else:
        picks = sample_claims(z, 40 if n is None else n, seed)
    n = len(picks)
    for k, (i, j) in enumerate(picks):
        # --redo keeps the status the earlier file scanned (another solver's, for --since files)
        p, ft, status = P[i], float(FT[i, j]), int(ST[i, j]) if statuses is None else statuses[k]
        sc = scan_state(p, ft, grid)
        verdict = classify(sc)
        if verdict == "root_in_forms":
            verdict = line_end_check(p, ft, status)
        states.append({"design": i, "column": j, "Ft": ft, "status": status, "verdict": verdict, **sc})
        if progress:
            print(f"{k + 1}/{n}: design {i} Ft {ft:.6g} status {status}: {verdict} ({len(sc['roots'])} roots, "
                  f"{len(sc['jumps'])} jumps, {len(sc['unresolved'])} unresolved)",
                  flush=True)
    counts = {}
    for s in states:
        key = f"status_{s['status']}"
        counts.setdefault(key, {})
        counts[key][s["verdict"]] = counts[key].get(s["verdict"], 0) + 1
    out = {"sample": len(states), "seed": seed, "grid": grid, "seconds": round(time.time() - t0, 1)}
    if redo:
        out["redo_of"] = os.path.relpath(redo)  # the states were picked by that file's run
    elif since:
        out["npz"], out["since"] = os.path.relpath(npz), os.path.relpath(since)
        if column is not None:
            out["column"] = column
        if status is not None:
            out["status"] = status
    return {**out, "counts": counts, "states": states}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sample", type=int, default=None,
                    help="states to check: a seeded sample of the claims (default 40), or with "
                         "--since of the new claims (default: all of them)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--grid", type=int, default=61)
    ap.add_argument("--npz", default=STATES)
    ap.add_argument("--json", default=OUT)
    ap.add_argument("--since", default=None, metavar="OLD.npz",
                    help="check the states whose status became 2 or 3 since OLD.npz (both from "
                         "validation.recheck --save): all of them, or --sample N of them")
    ap.add_argument("--redo", default=None, metavar="EARLIER.json",
                    help="scan the states of an earlier results file again, with their statuses "
                         "from that file (designs and Ft from --npz)")
    ap.add_argument("--column", type=int, default=None,
                    help="with --since: only the new claims in this column of the campaign's Ft "
                         "(1: Ft = 0, the natural state)")
    ap.add_argument("--status", type=int, choices=(2, 3), default=None,
                    help="with --since: only the new claims of this status (a scan of a status-2 "
                         "claim past a fold at negative Ft can only say root_below_traced_range)")
    args = ap.parse_args(argv)
    if args.status is not None and not args.since:
        ap.error("--status applies with --since only")
    res = run(args.sample, args.seed, args.grid, args.npz, progress=True, since=args.since, redo=args.redo,
              column=args.column, status=args.status)
    print(json.dumps(res["counts"], indent=1))
    with open(args.json, "w") as f:
        json.dump(res, f, indent=1, allow_nan=True)
        f.write("\n")


if __name__ == "__main__":
    main()
