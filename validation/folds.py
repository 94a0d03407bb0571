"""The folds behind "turned back" claims, checked in arbitrary precision (issue 13, item 5).

The long-double retry's separatrix march goes on in arclength where its steps in Ft collapse
(gecko/seta/detail/separatrix_arclength.hpp). Where it comes back over the line's start after a
fold, the forces beyond the fold get status 2 (no critical state on the line). This script checks
the fold itself, with no gecko code in the check:

1. The fold's Ft from gecko's answers alone: bisection between the line's start (Ft = 0) and the
   claimed Ft on "solved (0 or 7)" against "not solved (2, or 6 since the march stops there
   instead, see below)", 30 halvings of the interval (any other status on the way: undecided).
2. Just short of the fold (by eta = 1e-3 of the scale max(1, |Ft_fold|) towards the start), gecko's
   state there is confirmed by the bracketing shot in arbitrary precision
   (tests/data/seta_separatrix_mp.bracket_route): a root of the base mismatch
   g(Fn) = theta1(0) - alpha1 within 1e-11 of its Fn.
3. Just past the fold (by eta), the same shot on a grid of Fn around that state's Fn (41 points,
   +-5 % of max(1, |Fn|)) must keep one sign: no critical state near the branch that folded.

Verdicts: ``fold_confirmed`` (2 and 3 hold), ``root_past_fold`` (3 fails: a sign change past the
fold near the branch, a root or a jump of the shot, which this count does not tell apart as
validation/claims.py's refine does; so the line may go on there and the claim is in doubt),
``undecided`` (bisection met another status, the shot found no root at gecko's state, or the time
limit).

4. The pair test (``fold_pair``, ``pair_verdict``; its own verdict ``pair_verdict``, which does not
   enter ``verdict``): a fold is two roots that merge. At 1e-4 and 1e-6 of the scale short of the
   fold, gecko's state A and the shot's nearest other root B; past the fold by as much, no sign
   change within two gaps |B - A| of the pair; and the gap shrinking as the square root of the
   distance. Next to a long segment the shot has a dense family of roots (paths with a loop more
   or fewer, their Fn within O(delta) of each other), and the nearest other root can be one of
   them rather than the fold's partner: then the gap does not follow the square root, and the
   verdict is undecided (validation/README.md, "Where the give-ups end").
5. The parabola test (``--parabola``, ``fold_parabola``, ``parabola_verdict``; instead of 2 to 4):
   gecko's states at 1e-3 to 1e-6 short of the fold follow the square-root law of a quadratic
   fold (their differences fall by sqrt(10) per decade), the shot confirms them at 1e-4 and 1e-6
   with their path, and at 1e-6 it finds the partner root on that path where the law puts it on
   the returning branch. It names the partner by its predicted place and its path, which the pair
   test's nearest other root could not.
That the line, past the fold, comes back over its start is gecko's march alone; this check
establishes the fold it turned at.

A first build's march gave the targets beyond such a fold status 2; at three of the first six
checked, the sign count (3 above) found sign changes past the fold, and the march stopped there
and left them status 6 (validation/README.md, "The separatrix march in arclength"), until the
parabola test (validation/README.md, "Targets past a turned-back march"). The states of a results
file are checked again with ``--redo`` (the bisection takes status 6 beyond the fold as it takes
2):

    PYTHONPATH=python:. python3 -m validation.folds NEW.npz --since OLD.npz --sample 6 --seed 0 \\
        --json validation/results/folds_sample.json          (claims: status 2 in NEW, 1 or 6 in OLD)
    PYTHONPATH=python:. python3 -m validation.folds --redo validation/results/folds_sample.json \\
        --json validation/results/folds_redo.json                (before the pair test)
    PYTHONPATH=python:. python3 -m validation.folds --redo validation/results/folds_sample.json \\
        --time-limit 240 --json validation/results/folds_pair_redo.json   (with it)
    PYTHONPATH=python:. python3 -m validation.folds validation/rerun_turned.npz \\
        --since validation/rerun_joining.npz --parabola --sample 12 --seed 0 --time-limit 120 \\
        --json validation/results/folds_parabola_sample.json      (the parabola test)
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

import numpy as np

from validation import campaign

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "data"))

from validation.separatrix import TimeLimit, time_limited  # noqa: E402


def fold_ft(seta, Ft_claim, halvings=30):
    """The fold's Ft between 0 and Ft_claim by bisection on gecko's status, or None."""
    lo, hi = 0.0, float(Ft_claim)
    for _ in range(halvings):
        mid = 0.5 * (lo + hi)
        st = int(seta.critical_line(Ft=[mid], errors="nan").status[0])
        if st in (0, 7):
            lo = mid
        elif st in (2, 6):
            hi = mid
        else:
            return None
    return lo, hi


PAIR_ETAS = (1e-4, 1e-6)  # distances from the fold of the pair test, relative to max(1, |Ft_fold|)


def _signs(shoot, xs):
    from mpmath import mp, mpf
    with mp.workprec(shoot.prec):
        return [1 if shoot(mpf(x))[0] > 0 else -1 for x in xs]


def fold_pair(d, seta, lo, hi, eta):
    """The fold as two roots that merge: eta (relative to max(1, |Ft_fold|)) short of the fold
    [lo, hi], gecko's state A and the shot's nearest other root B (windows around A growing by 4x
    from 1e-6 max(1, |A|), 21 points each, until a sign change outside A's cell); eta past it, the
    shot's sign changes on [m - 2 gap, m + 2 gap] (41 points), m = (A + B)/2, gap = |B - A|. At a
    quadratic fold gap ~ sqrt(eta) and past it no root is left near m. None where gecko has no
    state short of the fold."""
    import seta_separatrix_mp as ssm
    scale = max(1.0, abs(hi))
    sgn = 1.0 if hi > 0 else -1.0
    before, past = lo - sgn * eta * scale, hi + sgn * eta * scale
    line = seta.critical_line(Ft=[before], errors="nan")
    if int(line.status[0]) not in (0, 7):
        return None
    A = float(line.Fn[0])
    L1, L2 = ssm.saddle_lengths(d, math.hypot(A, before))
    shoot_before = ssm._bracket(d, before, A, L1 + L2, 1e-11)[0]
    shoot_past = ssm._bracket(d, past, A, L1 + L2, 1e-11)[0]
    out = dict(eta=eta, Ft_before=before, Ft_past=past, A=A, B=None)
    for j in range(14):
        w = 1e-6 * max(1.0, abs(A)) * 4.0 ** j
        xs = np.linspace(A - w, A + w, 21)
        sg = _signs(shoot_before, xs)
        others = [k for k in range(20) if sg[k] != sg[k + 1] and not xs[k] <= A <= xs[k + 1]]
        if others:
            k = min(others, key=lambda k: abs(0.5 * (xs[k] + xs[k + 1]) - A))
            out["B"] = float(0.5 * (xs[k] + xs[k + 1]))
            break
    if out["B"] is None:
        return out
    gap = abs(out["B"] - A)
    m = 0.5 * (A + out["B"])
    xs = np.linspace(m - 2 * gap, m + 2 * gap, 41)
    sp = _signs(shoot_past, xs)
    out.update(gap=gap, past_changes=sum(1 for a, c in zip(sp, sp[1:]) if a != c))
    return out


def pair_verdict(pairs):
    """fold_confirmed where at both distances a partner root was found, none is left past the fold
    near the pair, and the gap shrinks as sqrt(eta) (ratio within 2x of the square root of the
    distances' ratio); else root_past_fold (a root past the fold near the pair) or undecided."""
    if any(p is None or p["B"] is None for p in pairs):
        return "undecided"
    if any(p["past_changes"] for p in pairs):
        return "root_past_fold"
    want = math.sqrt(pairs[0]["eta"] / pairs[1]["eta"])
    ratio = pairs[0]["gap"] / pairs[1]["gap"]
    return "fold_confirmed" if want / 2 <= ratio <= want * 2 else "undecided"


PARABOLA_ETAS = (1e-3, 1e-4, 1e-5, 1e-6)  # distances short of the fold, relative to max(1, |Ft_fold|)
CONFIRM_ETAS = (1e-4, 1e-6)  # where the shot confirms gecko's state
PARTNER_ETA = 1e-6           # where it looks for the partner root the parabola predicts
PARTNER_GRID = 21            # shots across the partner's window, B -+ a tenth of the gap


def sqrt_law(A, etas):
    """The fold's local law from gecko's states A at the distances etas (a decade apart): at a
    quadratic fold Fn = Ff + c x + e x^2 + f x^3 + ... with x = sqrt(eta), so the successive
    differences of A fall by sqrt(10) = 3.16 per decade (by 10 where the line has a finite slope
    and goes on). Returns the ratios and (Ff, c, e, f) through the four states. The partner on the
    returning branch is Ff - c x + e x^2 - f x^3 (the even terms are the two branches' common
    part)."""
    diffs = [A[k] - A[k + 1] for k in range(len(A) - 1)]
    ratios = [diffs[k] / diffs[k + 1] if diffs[k + 1] != 0 else float("inf") for k in range(len(diffs) - 1)]
    x = np.sqrt(np.array(etas))
    M = np.stack([x ** k for k in range(len(A))], axis=1)
    return ratios, [float(v) for v in np.linalg.solve(M, np.array(A))]


def _root_path(r):
    return None if r is None else dict(Fn=float(r["Fn"]), q=float(r["q"]), turns=[int(t) for t in r["turns"]])


def partner_roots(d, Ft, B, gap, length, limit):
    """The shot's roots in B -+ gap/10 at Ft: signs on PARTNER_GRID points, each sign change
    bisected to its root with its path (bracket_route). Next to a long segment the shot's residual
    jumps by 2 pi where its path changes (a loop more or fewer), so a root can sit between two
    points of one sign; the grid takes those it sees."""
    import seta_separatrix_mp as ssm
    shoot = ssm._bracket(d, Ft, B, length, 1e-11)[0]
    xs = np.linspace(B - 0.1 * gap, B + 0.1 * gap, PARTNER_GRID)
    sg = time_limited(limit, _signs, shoot, xs)
    roots = []
    for k in range(len(xs) - 1):
        if sg[k] != sg[k + 1]:
            m, half = 0.5 * (xs[k] + xs[k + 1]), 0.5 * (xs[k + 1] - xs[k])
            r = time_limited(limit, ssm.bracket_route, d, Ft, m, length, span_rel=half / max(1.0, abs(m)))
            if r is not None:
                roots.append(_root_path(r))
    return roots


def fold_parabola(d, seta, lo, hi, limit):
    """The fold as a parabola of the line, with the partner on the returning branch where it
    predicts. gecko's states A at PARABOLA_ETAS short of the fold [lo, hi] (in units of
    max(1, |Ft_fold|)), one call each, and their square-root law (sqrt_law: ratios within 10 % of
    sqrt(10)); at CONFIRM_ETAS the bracketing shot in arbitrary precision confirms A (a root within
    1e-11 of it, with its path: turning points and base rate); at PARTNER_ETA it looks for the
    partner root where the parabola puts it (partner_roots). Where the line goes on past a point
    instead of folding, the differences fall by 10 per decade and nothing predicts a root there."""
    import seta_separatrix_mp as ssm
    scale = max(1.0, abs(hi))
    sgn = 1.0 if hi > 0 else -1.0
    Ff_t = 0.5 * (lo + hi)
    out = dict(etas=list(PARABOLA_ETAS), A=[], Ft_before=[])
    for eta in PARABOLA_ETAS:
        before = lo - sgn * eta * scale
        line = seta.critical_line(Ft=[before], errors="nan")
        if int(line.status[0]) not in (0, 7):
            out["why"] = f"no state at {eta:g} short of the fold"
            return out
        out["A"].append(float(line.Fn[0]))
        out["Ft_before"].append(before)
    etas = [abs(f - Ff_t) / scale for f in out["Ft_before"]]
    ratios, coef = sqrt_law(out["A"], etas)
    out.update(ratios=ratios, Fn_fold=coef[0], coefficients=coef)
    out["sqrt_law"] = all(abs(r / math.sqrt(10) - 1) <= 0.1 for r in ratios)
    out["confirm"] = []
    for eta in CONFIRM_ETAS:
        k = PARABOLA_ETAS.index(eta)
        Ft_b, A = out["Ft_before"][k], out["A"][k]
        L1, L2 = ssm.saddle_lengths(d, math.hypot(A, Ft_b))
        r = time_limited(limit, ssm.bracket_route, d, Ft_b, A, L1 + L2)
        out["confirm"].append(dict(eta=eta, Ft=Ft_b, A=A, lengths=[round(L1, 1), round(L2, 1)], A_root=_root_path(r)))
    k = PARABOLA_ETAS.index(PARTNER_ETA)
    Ft_b, A = out["Ft_before"][k], out["A"][k]
    x = math.sqrt(etas[k])
    B = coef[0] - coef[1] * x + coef[2] * x ** 2 - coef[3] * x ** 3
    gap = abs(A - B)
    L1, L2 = ssm.saddle_lengths(d, math.hypot(B, Ft_b))
    out["partner"] = dict(eta=PARTNER_ETA, Ft=Ft_b, B_predicted=B, gap=gap,
                          roots=partner_roots(d, Ft_b, B, gap, L1 + L2, limit))
    return out


def same_path(a, b):
    return a is not None and b is not None and a["turns"] == b["turns"] and (a["q"] > 0) == (b["q"] > 0)


def parabola_verdict(p):
    """fold_confirmed where gecko's states follow the square-root law, the shot confirms them at
    CONFIRM_ETAS, and at PARTNER_ETA it has a root on their path (turning points, sign of the base
    rate) within a twentieth of the gap from where the parabola puts the partner; no_fold where the
    differences fall as a finite slope's (ratios within 10 % of 10); else undecided."""
    if "ratios" not in p:
        return "undecided"
    if all(abs(r / 10 - 1) <= 0.1 for r in p["ratios"]):
        return "no_fold"
    if not p["sqrt_law"]:
        return "undecided"
    conf = p["confirm"]
    if not all(c["A_root"] is not None and abs(c["A_root"]["Fn"] - c["A"]) <= 1e-11 * max(1.0, abs(c["A"]))
               for c in conf):
        return "undecided"
    path = conf[-1]["A_root"]
    part = p["partner"]
    near = [r for r in part["roots"] if same_path(r, path) and abs(r["Fn"] - part["B_predicted"]) <= part["gap"] / 20]
    return "fold_confirmed" if near else "undecided"


def _fold_of(d, Ft_claim):
    """The claim's record, gecko's seta and the fold's bracket (None, the record saying why, where
    the bisection met another status)."""
    import gecko
    out = dict(Ft=float(Ft_claim))
    seta = gecko.TwoLevelSeta(**d)
    b = fold_ft(seta, Ft_claim)
    if b is None:
        out.update(verdict="undecided", why="bisection met a status other than 0, 7, 2 or 6")
    return out, seta, b


def check_parabola(d, Ft_claim, limit):
    """The parabola test alone (fold_parabola), after the fold's bisection on gecko's status."""
    t = time.time()
    out, seta, b = _fold_of(d, Ft_claim)
    if b is None:
        return out
    out["fold"] = list(b)
    try:
        p = fold_parabola(d, seta, b[0], b[1], limit)
    except TimeLimit:
        out.update(verdict="undecided", why=f"time limit ({limit} s)")
        return out
    out["parabola"] = p
    out["verdict"] = parabola_verdict(p)
    out["seconds"] = round(time.time() - t, 1)
    return out


def check(d, Ft_claim, limit):
    from mpmath import mp, mpf
    import seta_separatrix_mp as ssm

    t = time.time()
    out, seta, b = _fold_of(d, Ft_claim)
    if b is None:
        return out
    lo, hi = b
    scale = max(1.0, abs(hi))
    eta = 1e-3 * scale
    sgn = 1.0 if Ft_claim > 0 else -1.0
    before, past = lo - sgn * eta, hi + sgn * eta
    line = seta.critical_line(Ft=[before], errors="nan")
    Fn = float(line.Fn[0])
    out.update(fold=[lo, hi], Ft_before=before, Ft_past=past, Fn_before=Fn)
    if int(line.status[0]) not in (0, 7):
        out["verdict"] = "undecided"
        out["why"] = "no state short of the fold"
        return out
    L1, L2 = ssm.saddle_lengths(d, math.hypot(Fn, before))
    out["elastic_lengths"] = [round(L1, 1), round(L2, 1)]
    try:
        r = time_limited(limit, ssm.bracket_route, d, before, Fn, L1 + L2)
        if r is None:
            out["verdict"] = "undecided"
            out["why"] = "the bracketing shot has no root at gecko's state short of the fold"
            return out
        out["before_dFn_rel"] = float(abs(r["Fn"] - Fn) / max(1, abs(Fn)))
        shoot, _, _, _ = ssm._bracket(d, past, Fn, L1 + L2, 1e-11)
        span = 0.05 * max(1.0, abs(Fn))
        signs = []
        with mp.workprec(shoot.prec):
            for k in range(41):
                x = mpf(Fn) - span + 2 * span * k / mpf(40)
                g = time_limited(limit, shoot, x)[0]
                signs.append(1 if g > 0 else (-1 if g < 0 else 0))
        out["past_sign_changes"] = sum(1 for a, c in zip(signs, signs[1:]) if a != c)
        pairs = time_limited(limit, lambda: [fold_pair(d, seta, lo, hi, eta) for eta in PAIR_ETAS])
    except TimeLimit:
        out["verdict"] = "undecided"
        out["why"] = f"time limit ({limit} s)"
        return out
    out["pairs"] = pairs
    out["seconds"] = round(time.time() - t, 1)
    out["verdict"] = "fold_confirmed" if out["past_sign_changes"] == 0 else "root_past_fold"
    out["pair_verdict"] = pair_verdict(pairs)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz", nargs="?")
    ap.add_argument("--since", default=None, help="the earlier re-run (.npz) that gave these states up")
    ap.add_argument("--redo", default=None, help="check the states of an earlier results file again")
    ap.add_argument("--sample", type=int, default=6)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--time-limit", type=float, default=120.0)
    ap.add_argument("--json", default=None)
    ap.add_argument("--design", type=int, action="append", default=None,
                    help="only this campaign design's claims (repeatable)")
    ap.add_argument("--parabola", action="store_true",
                    help="the parabola test alone (fold_parabola), instead of the sign count and pair test")
    a = ap.parse_args(argv)
    if a.redo:
        with open(a.redo) as f:
            earlier = json.load(f)
        jobs = [(s["design"], s["Ft"]) for s in earlier["states"]]
        designs = np.load(earlier["npz"])["P"]  # the campaign's designs, the same in every re-run file
        claims_count = earlier["claims"]
        a.npz = earlier["npz"]
    else:
        new, old = np.load(a.npz), np.load(a.since)
        claims = (new["status"] == 2) & np.isin(old["status"], (1, 6))
        if a.design:
            claims &= np.isin(np.arange(len(claims)), a.design)[:, None]
        idx = np.argwhere(claims)
        rng = np.random.default_rng(a.seed)
        pick = idx[rng.choice(len(idx), size=min(a.sample, len(idx)), replace=False)] if len(idx) else idx
        jobs = [(int(i), float(new["FT"][i, j])) for i, j in pick]
        designs = new["P"]
        claims_count = int(claims.sum())
    t0 = time.time()
    states, verdicts, pair_verdicts = [], {}, {}
    for i, Ft in jobs:
        d = dict(zip(campaign.FIELDS, map(float, designs[i])))
        r = (check_parabola if a.parabola else check)(d, Ft, a.time_limit)
        r["design"] = int(i)
        states.append(r)
        verdicts[r["verdict"]] = verdicts.get(r["verdict"], 0) + 1
        if "pair_verdict" in r:
            pair_verdicts[r["pair_verdict"]] = pair_verdicts.get(r["pair_verdict"], 0) + 1
        print(json.dumps(r), flush=True)
    summary = dict(npz=a.npz, since=a.since, redo=a.redo, parabola=a.parabola, claims=claims_count, sample=len(states), seed=a.seed,
                   time_limit=a.time_limit, verdicts=verdicts, pair_verdicts=pair_verdicts, seconds=round(time.time() - t0, 1), states=states)
    text = json.dumps(summary, indent=1)
    if a.json:
        with open(a.json, "w") as f:
            f.write(text + "\n")
    print(json.dumps({k: v for k, v in summary.items() if k != "states"}, indent=1))


if __name__ == "__main__":
    main()
