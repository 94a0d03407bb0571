#!/usr/bin/env python3
"""Which designs the status-1 give-ups ("no natural state found") come from, by three scales of the
design alone (no solving, seconds): where does the homotopy from the small-deformation limit have to
go that it does not reach?

    python3 -m validation.status1_designs validation/rerun_full.npz [--json out.json]
    python3 -m validation.status1_designs validation/rerun_full.npz --scan 16 [--seed 0]

--scan N also scans N of the designs without a natural state (half coiled beam, half the other
classes, drawn with --seed) at Ft = 0 with the independent shooting scan of validation/claims.py
(no gecko code): does a critical state exist there at all, and inside the model's forms? About 20 s
a design with roots. Its "no root" is not a proof next to a separatrix, where the residual can
change sign within a gap of its Fn grid (validation/README.md).

A design whose natural state at Ft = 0 is not found gives status 1 at every requested Ft; those
designs hold nearly all status-1 states. For each design (w, l1 as given), with the peel moment
M = sqrt(2 w EI2), the moment the spatula carries at an inextensible contact edge without load
(curvature jump sqrt(2 w / EI2), the left side of paper 001 eq 3 at Fn = Ft = 0):
  beam_turns      M l1 / (2 pi EI1): full turns of the beam under that moment alone. Forces at the
                  joint cancel part of it along the beam; where it is many turns they must be
                  large, and the beam becomes many elastic lengths l1 sqrt(|Fn| / EI1) long
                  (validation/README.md, "Where the status-1 give-ups come from").
  spatula_lengths l2 sqrt(2 w / EI2): the spatula's length in its peel boundary-layer lengths; a long
                  spatula is a segment next to its separatrix (docs "Long segments").
  strain_scale    max(w / EA1, w / EA2): the axial strain a peel force of order w gives; near 1 the
                  forms' edge (an axial load comparable to EA, paper 001 eq 15) is close.
Each design falls in the first class it meets (the names say which scale is large, not what the
state looks like): coiled beam (beam_turns > 1), long spatula
(spatula_lengths > 20), extensible (strain_scale > 0.1), else other. The same classes are counted
over the designs with at least one state solved (status 0 or 7), for comparison, and both are
counted by beam_turns (bins 0-1, 1-3, 3-10, over 10).
"""
from __future__ import annotations

import argparse
import os

import numpy as np

from . import campaign

CLASSES = ("coiled beam", "long spatula", "extensible", "other")
TURN_BINS = (0.0, 1.0, 3.0, 10.0, np.inf)


def design_scales(P):
    """beam_turns, spatula_lengths, strain_scale for each row of P (campaign.FIELDS order)."""
    EI1, EI2, EA1, EA2, l1, l2, _a1, _a2, w = np.asarray(P, dtype=float).T
    moment = np.sqrt(2 * w * EI2)
    beam_turns = moment * l1 / (2 * np.pi * EI1)
    spatula_lengths = l2 * np.sqrt(2 * w / EI2)
    strain_scale = np.maximum(w / EA1, w / EA2)  # w / inf = 0
    return beam_turns, spatula_lengths, strain_scale


def classify(P):
    """Index into CLASSES for each design."""
    turns, lengths, strain = design_scales(P)
    return np.select([turns > 1, lengths > 20, strain > 0.1], [0, 1, 2], default=3)


def summary(P, status):
    status = np.asarray(status)
    whole = (status == 1).all(axis=1)
    solved = ((status == 0) | (status == 7)).any(axis=1)
    cls = classify(P)
    turns, lengths, strain = design_scales(P)

    def counts(mask):
        return {name: int(((cls == k) & mask).sum()) for k, name in enumerate(CLASSES)}

    def quartiles(x, mask):
        return [float(v) for v in np.percentile(x[mask], [25, 50, 75])] if mask.any() else None

    by_turns = []
    for lo, hi in zip(TURN_BINS[:-1], TURN_BINS[1:]):
        m = (turns >= lo) & (turns < hi)
        by_turns.append(dict(beam_turns=[lo, hi if np.isfinite(hi) else None], designs=int(m.sum()),
                             without_natural_state=int((m & whole).sum()), with_a_solved_state=int((m & solved).sum())))
    return dict(
        status1_states=int((status == 1).sum()),
        status1_states_in_designs_without_natural_state=int((status == 1)[whole].sum()),
        designs_without_natural_state=int(whole.sum()),
        designs_with_a_solved_state=int(solved.sum()),
        classes_without_natural_state=counts(whole),
        classes_with_a_solved_state=counts(solved),
        by_beam_turns=by_turns,
        quartiles_without_natural_state=dict(beam_turns=quartiles(turns, whole),
                                             spatula_lengths=quartiles(lengths, whole),
                                             strain_scale=quartiles(strain, whole)),
        quartiles_with_a_solved_state=dict(beam_turns=quartiles(turns, solved),
                                           spatula_lengths=quartiles(lengths, solved),
                                           strain_scale=quartiles(strain, solved)))


def scan_sample(P, status, n, seed):
    """claims.scan_state at Ft = 0 for n designs without a natural state: per design its class, the
    scan's verdict (claims.classify) and its roots (Fn, beta, inside the forms)."""
    from . import claims
    whole = np.nonzero((np.asarray(status) == 1).all(axis=1))[0]
    cls = classify(P)
    rng = np.random.default_rng(seed)
    coiled, others = whole[cls[whole] == 0], whole[cls[whole] != 0]
    k = min(n // 2, coiled.size)
    pick = np.concatenate([rng.choice(coiled, k, replace=False),
                           rng.choice(others, min(n - k, others.size), replace=False)])
    out = []
    for i in pick:
        s = claims.scan_state(P[i], 0.0)
        out.append(dict(design=int(i), cls=CLASSES[cls[i]], verdict=claims.classify(s),
                        roots=[[r["Fn"], r["beta"], bool(r["in_forms"])] for r in s["roots"]],
                        unresolved=len(s["unresolved"]), unreliable_nodes=s["unreliable_nodes"]))
    verdicts = {}
    for r in out:
        verdicts.setdefault(r["cls"], {}).setdefault(r["verdict"], 0)
        verdicts[r["cls"]][r["verdict"]] += 1
    return dict(seed=seed, designs=out, verdicts=verdicts)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz")
    ap.add_argument("--json", default=None)
    ap.add_argument("--scan", type=int, default=0, help="scan this many designs without a natural state")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    z = np.load(args.npz)
    out = dict(campaign=os.path.relpath(args.npz), **summary(z["P"], z["status"]))
    if args.scan:
        out["scan_at_ft_0"] = scan_sample(z["P"], z["status"], args.scan, args.seed)
    return campaign.print_json(out, args.json)


if __name__ == "__main__":
    main()
