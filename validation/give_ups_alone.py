#!/usr/bin/env python3
"""Give-ups that a call with their Ft alone solves: how a state depends on the other Ft asked for.

``recheck`` solves each design's six campaign Ft in one ``critical_line(Ft=...)`` call, as a user
would. The line towards positive (or negative) Ft is then followed up to the farthest of them, and
its continuation's scale is max(|farthest Ft|, sqrt(EI1 w)/l1) (gecko/seta/critical_line.hpp,
``critical_line_at_imp``): the step sizes and the stall test (1000 attempts that advance the line
by less than 1 % of the scale end it) grow with the farthest target. This re-solves every status-6
state of a ``recheck --save`` file in a call of its own, with that Ft alone, and counts what it
gets; a state solved that way is one the call with the design's other Ft gave up on.

    PYTHONPATH=<gecko>:. python3 -m validation.give_ups_alone validation/rerun_main.npz [--json F.json]

With ``--farther K`` each state is asked with one more Ft, K times its own, beside it instead: a
line scaled for a target K times farther (K > 1), to see whether the give-ups left depend on the
line's scale at all (the second Ft is held to (Ft)max).

The states found are not verified here (``validation.changed`` and ``validation.separatrix`` do
that for a solver that returns them).
"""
from __future__ import annotations

import argparse
import time
from collections import Counter

import numpy as np

from . import campaign


def run(path: str, farther: float | None = None) -> dict:
    t0 = time.time()
    z = np.load(path)
    P, FT, status = z["P"], z["FT"], z["status"]
    rows = []
    for i, j in np.argwhere(status == 6):
        ft = float(FT[i, j])
        seta = campaign.seta(P[i])
        # The second Ft stays inside (Ft)max (a farther one is an input error); where that leaves
        # it no farther than the state's own, the call is the state alone.
        far = None if farther is None else float(np.clip(farther * ft, -np.inf, seta.ft_max))
        r = seta.critical_line(Ft=[ft] if far is None or abs(far) <= abs(ft) else [ft, far])
        same_side = FT[i][np.sign(FT[i]) == np.sign(FT[i, j])]  # the targets of the same line
        rows.append({"design": int(i), "Ft": float(FT[i, j]), "alone_status": int(r.status[0]),
                     "alone_Fn": float(r.Fn[0]),
                     "farthest_on_its_line": float(same_side[np.argmax(np.abs(same_side))])})
    counts = Counter(r["alone_status"] for r in rows)
    solved = [r for r in rows if r["alone_status"] in (0, 7)]
    return {"npz": path, "farther": farther, "status_6": len(rows), "alone_statuses": {str(k): v for k, v in sorted(counts.items())},
            "solved_alone_designs": len({r["design"] for r in solved}),
            "seconds": round(time.time() - t0, 1), "states": rows}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz", help="a recheck --save file")
    ap.add_argument("--farther", type=float, default=None,
                    help="ask each state beside a second Ft, this many times its own (> 1)")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    if args.farther is not None and not args.farther > 1:
        ap.error(f"--farther must be > 1, got {args.farther}")
    return campaign.print_json(run(args.npz, args.farther), args.json, omit=("states",))


if __name__ == "__main__":
    main()
