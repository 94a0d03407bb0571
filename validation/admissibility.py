#!/usr/bin/env python3
"""Check the solver's admissibility verdicts (status 0 against 7, and the lowest height min_z) with
the independent shooting route (validation/verify.py ``heights``, no gecko code).

A state with status 7 solves the equations but puts part of the seta below the substrate
(gecko reports min_z < -1e-12 (l1 + l2)); status 0 says it stays above. For every solved state of a
``python3 -m validation.recheck --save`` file (which records min_z), the backward shot from the
contact edge integrates the height z(s) with the seta's own Fn and Ft and takes its lowest value
over [0, a] (0 at the edge). Verdicts, with L = l1 + l2 and TOL = 1e-9 L (the campaign's 1e-8
threshold on Fn, tightened: heights are O(L) and well conditioned away from rounding-amplifying
states):

- conclusive: the shot's own uncertainty (integration, amplified rounding of the tip data, and an
  Fn error of 1e-11 max(1, |Fn|)) is below TOL / 10;
- silently wrong: conclusive, and status 0 while the shot's lowest z is below -TOL (the seta
  crosses), or status 7 with gecko's min_z below -TOL while the shot stays above -1e-12 L;
- flagged by sign: not conclusive, but the shot's sign is certain by ten times its
  uncertainty: status 0 while the shot lies below -(TOL + 10 u), or status 7 with gecko's min_z below
  -TOL while the shot lies above -1e-12 L + 10 u. A flag to be decided, not a verdict: past about
  15 saddle time constants the shot's uncertainty (from perturbed shots that diverge with it) does
  not bound its error, and every such flag that admissibility_mp.py decided in arbitrary precision
  was the shot's own (validation/README.md, "Admissibility of deep states in arbitrary precision");
- disagreeing value: conclusive and |min_z - shot| > TOL (what a user reads as min_z);
- borderline: status 7 with -TOL <= min_z < -1e-12 L (a touch the shot cannot tell from 0 at TOL);
- unchecked: status 7 with min_z = NaN, where gecko's check reported itself as not made
  (gecko/seta/admissibility.hpp) and the state, not confirmed admissible, got 7;
  split by the shot into those that stay above the substrate (the 7 claims a crossing that is not
  there) and those that cross.

    PYTHONPATH=<gecko> python3 -m validation.recheck --save now.npz
    python3 -m validation.admissibility now.npz [--workers 2] [--json out.json]
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import time

import numpy as np

from . import campaign, verify

TOL_REL = 1e-9          # of l1 + l2
GECKO_CROSSING_REL = 1e-12   # gecko's own threshold for status 7 (gecko/seta/admissibility.hpp)


def wrong_verdicts(status, min_z, shot, L):
    """The verdicts a lowest height ``shot`` (of an independent route, its own error below TOL)
    contradicts, elementwise: (status 0 while the shot lies below -TOL, status 7 with gecko's
    min_z below -TOL while the shot stays above -1e-12 L). The one statement of the rule, for the
    double shot here and the arbitrary-precision one of admissibility_mp.py."""
    status, min_z, shot, L = map(np.asarray, (status, min_z, shot, L))
    tol = TOL_REL * L
    with np.errstate(invalid="ignore"):
        wrong0 = (status == 0) & (shot < -tol)
        wrong7 = (status == campaign.INADMISSIBLE) & (min_z < -tol) & (shot > -GECKO_CROSSING_REL * L)
    return wrong0, wrong7


def _shot_heights(args):
    P, FT, Fn = args
    return verify.heights(campaign.design_dict(P), FT, Fn)


def check(P, FT, Fn, status, min_z, workers=1) -> dict:
    """Per-state shot heights and verdicts over the solved states (status 0 or 7); the states are
    shared out over ``workers`` processes (each shoots all its states at once, vectorised)."""
    n, m = FT.shape
    rows, cols = np.nonzero(campaign.solved(status))
    v = np.full((n, m), np.nan)
    unc = np.full((n, m), np.nan)
    parts = [(rows[k::workers], cols[k::workers]) for k in range(workers)]
    args = [(P[r], FT[r, c], Fn[r, c]) for r, c in parts]
    if workers > 1:
        with mp.get_context("fork").Pool(workers) as pool:
            res = pool.map(_shot_heights, args)
    else:
        res = [_shot_heights(a) for a in args]
    for (r, c), (z, u) in zip(parts, res):
        v[r, c] = z
        unc[r, c] = u
    L = (P[:, campaign.FIELDS.index("l1")] + P[:, campaign.FIELDS.index("l2")])[:, None]
    tol = TOL_REL * L
    conclusive = campaign.solved(status) & (unc < 0.1 * tol)
    with np.errstate(invalid="ignore"):
        wrong0, wrong7 = wrong_verdicts(status, min_z, v, L)
        wrong0, wrong7 = conclusive & wrong0, conclusive & wrong7
        certain_crossing = ~conclusive & (v + 10 * unc < -tol)
        certain_above = ~conclusive & (v - 10 * unc > -GECKO_CROSSING_REL * L)
        sign0 = campaign.solved(status) & (status == 0) & certain_crossing
        sign7 = (status == campaign.INADMISSIBLE) & (min_z < -tol) & certain_above
        differs = conclusive & ~(np.abs(min_z - v) <= tol)
        borderline = (status == campaign.INADMISSIBLE) & (min_z >= -tol)
        # status 7 with min_z = NaN: gecko's check was not made, and a state it cannot call
        # admissible gets 7; the shot says which it is
        unchecked = (status == campaign.INADMISSIBLE) & np.isnan(min_z)
        unchecked_above = unchecked & conclusive & (v >= -GECKO_CROSSING_REL * L)
        unchecked_crossing = unchecked & conclusive & (v < -tol)
    return dict(shot_min_z=v, uncertainty=unc, conclusive=conclusive, wrong=wrong0 | wrong7,
                wrong_admissible=wrong0, wrong_inadmissible=wrong7, flagged_by_sign=sign0 | sign7,
                flagged_admissible_by_sign=sign0, flagged_inadmissible_by_sign=sign7,
                sign_decided=campaign.solved(status) & (certain_crossing | certain_above),
                differs=differs, borderline=borderline,
                unchecked=unchecked, unchecked_above=unchecked_above, unchecked_crossing=unchecked_crossing,
                dev=np.where(conclusive, np.abs(min_z - v) / L, np.nan))


def run(path: str, workers: int = 2) -> dict:
    z = dict(np.load(path))
    if "min_z" not in z:
        raise ValueError(f"{path} has no min_z: save it with a current validation.recheck --save")
    t0 = time.time()
    P, FT, status, min_z = z["P"], z["FT"], z["status"], z["min_z"]
    r = check(P, FT, z["Fn"], status, min_z, workers)
    solved = campaign.solved(status)
    rows, cols = np.nonzero(r["wrong"] | r["flagged_by_sign"] | (r["differs"] & ~r["unchecked"]) | r["unchecked_above"])
    per = {}
    for s in (0, campaign.INADMISSIBLE):
        k = status == s
        per[str(s)] = dict(states=int(k.sum()), conclusive=int((r["conclusive"] & k).sum()),
                           inconclusive=int((~r["conclusive"] & k).sum()))
    return dict(file=path, states=int(status.size), solved=int(solved.sum()), by_status=per,
                silently_wrong=int(r["wrong"].sum()),
                wrong_admissible=int(r["wrong_admissible"].sum()),
                wrong_inadmissible=int(r["wrong_inadmissible"].sum()),
                inconclusive_sign_decided=int(r["sign_decided"].sum()),
                flagged_by_sign=int(r["flagged_by_sign"].sum()),
                flagged_admissible_by_sign=int(r["flagged_admissible_by_sign"].sum()),
                flagged_inadmissible_by_sign=int(r["flagged_inadmissible_by_sign"].sum()),
                min_z_differs=int(r["differs"].sum()), borderline_7=int(r["borderline"].sum()),
                unchecked_7=int(r["unchecked"].sum()), unchecked_7_shot_above=int(r["unchecked_above"].sum()),
                unchecked_7_shot_crossing=int(r["unchecked_crossing"].sum()),
                min_z_differs_where_checked=int((r["differs"] & ~r["unchecked"]).sum()),
                max_abs_dmin_z_over_L=float(np.nanmax(r["dev"])) if np.isfinite(r["dev"]).any() else None,
                examples=[dict(design=int(a), column=int(b), status=int(status[a, b]), min_z=float(min_z[a, b]),
                               shot=float(r["shot_min_z"][a, b]), uncertainty=float(r["uncertainty"][a, b]))
                          for a, b in zip(rows[:20], cols[:20])],
                seconds=round(time.time() - t0, 1))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz", help="a validation.recheck --save file (with min_z)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    return campaign.print_json(run(args.npz, args.workers), args.json)


if __name__ == "__main__":
    main()
