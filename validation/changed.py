#!/usr/bin/env python3
"""Verify every state whose answer changed between two solvers, with the independent shooting route
(validation/verify.py, no gecko code): the states a solver change newly solves (status 0 or 7 now,
another status before) and the states solved by both whose Fn or beta moved by more than 1e-12
relative. The unchanged states keep the verdict of the campaign that verified them.

Both inputs are ``python3 -m validation.recheck --save`` files over the same states (the old solver
and the new one):

    PYTHONPATH=<old gecko> python3 -m validation.recheck --save old.npz
    PYTHONPATH=<new gecko> python3 -m validation.recheck --save new.npz
    python3 -m validation.changed old.npz new.npz [--json out.json]

The old side may also be the committed record of the 10,000-design campaign
(validation/data/stress_10000_states.npz, statuses and digests, no Fn): then the newly solved states
(status 0 or 7 now, not 0 in the campaign) are verified, and "moved" is left to recheck, whose
``campaign_solved_bitwise_equal`` says whether every state the campaign solved and verified still
has its campaign's Fn and beta bit for bit.

Where both files have the admissibility check's lowest heights (``min_z``), ``heights`` compares
them on the states both solved (a change of the check itself shows there, not in Fn or beta).

"Silently wrong" uses the campaign's threshold and conclusiveness rule (campaign.classify), with
the new solver's turning-point counts: a verifier root with other turning points than the state
(another branch of the shot) is inconclusive, counted in ``other_branch``. It judges Fn and beta
(theta at the joint) separately: the shot can be conclusive in Fn and not in beta (its uncertainty
in beta grows with the joint's sensitivity), so ``verified_conclusive_beta`` and
``max_abs_dbeta_conclusive`` say how many of the checked states had beta judged and how far off the
largest was, and ``moved_states`` lists the moved ones with their change in both.
"""
from __future__ import annotations

import time

import numpy as np

from . import campaign
from .recheck import transitions

#: relative change in Fn (or absolute change in beta, rad) above which a solved state counts as changed
MOVED = 1e-12


def changed_states(old: dict, new: dict) -> dict:
    """Masks of the newly solved states and of the solved states whose values moved."""
    solved = campaign.solved
    newly = solved(new["status"]) & ~solved(old["status"])
    both = solved(new["status"]) & solved(old["status"])
    if "Fn" not in old:   # the campaign's record: its values are compared bitwise by recheck
        return dict(newly_solved=newly, moved=np.zeros_like(newly))
    with np.errstate(invalid="ignore"):
        moved_fn = np.abs(new["Fn"] - old["Fn"]) > MOVED * np.maximum(1.0, np.abs(old["Fn"]))
        moved_beta = np.abs(new["beta"] - old["beta"]) > MOVED
    return dict(newly_solved=newly, moved=both & (moved_fn | moved_beta))


def height_changes(old: dict, new: dict) -> dict | None:
    """The admissibility check's lowest heights (``min_z``) of the states both files solved:
    NaN (check not made) in one file only, the largest change relative to l1 + l2, how many changed
    at all, and the verdicts (crossing below -1e-12 (l1 + l2), the library's threshold) that flip.
    None when a file has no heights (the campaign's record)."""
    if "min_z" not in old or "min_z" not in new:
        return None
    both = campaign.solved(new["status"]) & campaign.solved(old["status"])
    L = (new["P"][:, 4] + new["P"][:, 5])[:, None] * np.ones(new["status"].shape)
    z0, z1 = old["min_z"][both], new["min_z"][both]
    L = L[both]
    finite = np.isfinite(z0) & np.isfinite(z1)
    d = np.abs(z1[finite] - z0[finite]) / L[finite]
    cross0, cross1 = z0[finite] < -1e-12 * L[finite], z1[finite] < -1e-12 * L[finite]
    return dict(solved_in_both=int(both.sum()), checked_in_both=int(finite.sum()),
                nan_in_one_only=int((np.isnan(z0) != np.isnan(z1)).sum()),
                max_rel_change=float(d.max()) if d.size else None, changed=int((d != 0).sum()),
                verdicts_flipped=int((cross0 != cross1).sum()))


def run(old_path: str, new_path: str) -> dict:
    old, new = dict(np.load(old_path)), dict(np.load(new_path))
    if old["P"].shape != new["P"].shape or not (np.array_equal(old["P"], new["P"])
                                                and np.array_equal(old["FT"], new["FT"])):
        raise ValueError(f"{old_path} and {new_path} hold different states")
    masks = changed_states(old, new)
    check = masks["newly_solved"] | masks["moved"]
    t0 = time.time()
    status = np.where(check, new["status"], -1)   # verify only the changed states
    v = campaign.verify_states(new["P"], new["FT"], new["Fn"], new["beta"], status)
    cl = campaign.classify(new["P"], new["FT"], new["Fn"], new["beta"], status, v,
                           turns=(new["tpb"], new["tps"]))
    conclusive = check & ~cl["inconclusive_fn"]
    conclusive_beta = conclusive & ~cl["inconclusive_beta"]
    wrong = cl["wrong_fn"] | cl["wrong_beta"]
    rows, cols = np.nonzero(wrong)
    moved = []
    if "Fn" in old:
        for r, c in zip(*np.nonzero(masks["moved"])):
            moved.append(dict(design=int(r), column=int(c), Ft=float(new["FT"][r, c]),
                              rel_change_Fn=float(abs(new["Fn"][r, c] - old["Fn"][r, c]) / max(1.0, abs(old["Fn"][r, c]))),
                              change_beta=float(new["beta"][r, c] - old["beta"][r, c])))
    return dict(states=int(new["status"].size), transitions=transitions(old["status"], new["status"]),
                newly_solved=int(masks["newly_solved"].sum()), moved=int(masks["moved"].sum()) if "Fn" in old else None,
                verified_conclusive=int(conclusive.sum()),
                inconclusive=int((check & cl["inconclusive_fn"]).sum()),
                other_branch=int((check & cl["other_branch"]).sum()),
                other_branch_states=[dict(design=int(r), column=int(c), Ft=float(new["FT"][r, c]),
                                          Fn=float(new["Fn"][r, c]), rel_dFn=float(cl["rel"][r, c]),
                                          turns_state=[int(new["tpb"][r, c]), int(new["tps"][r, c])],
                                          turns_at_Fn=[int(v["turns_beam"][r, c]), int(v["turns_spatula"][r, c])],
                                          turns_at_root=[int(v["root_turns_beam"][r, c]),
                                                         int(v["root_turns_spatula"][r, c])])
                                     for r, c in zip(*np.nonzero(check & cl["other_branch"]))][:20],
                silently_wrong=int(wrong.sum()),
                wrong_states=[dict(design=int(r), column=int(c), Ft=float(new["FT"][r, c]),
                                   Fn=float(new["Fn"][r, c]), rel_dFn=float(cl["rel"][r, c]),
                                   dbeta=float(v["dbeta"][r, c]), wrong_in=[k for k in ("fn", "beta")
                                                                            if cl["wrong_" + k][r, c]])
                              for r, c in zip(rows[:20], cols[:20])],
                max_rel_dFn_conclusive=float(np.nanmax(np.where(conclusive, cl["rel"], np.nan)))
                if conclusive.any() else None,
                verified_conclusive_beta=int(conclusive_beta.sum()),
                max_abs_dbeta_conclusive=float(np.nanmax(np.where(conclusive_beta, np.abs(v["dbeta"]), np.nan)))
                if conclusive_beta.any() else None,
                moved_states=moved[:20],
                heights=height_changes(old, new),
                seconds=round(time.time() - t0, 1))


def main(argv=None):
    return campaign.compare_main(run, __doc__, argv)


if __name__ == "__main__":
    main()
