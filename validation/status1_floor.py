#!/usr/bin/env python3
"""What the campaign's status-1 states ("Newton did not converge") are: re-solve each at a looser
Newton tolerance (--tolerance, default 1e-10 scaled, the continuation's own) and verify the states
that then converge with the independent verifier (verify.py).

Newton at a fixed Ft accepts a state when its scaled step falls below the tolerance (1e-12 by
default); where the step's rounding floor lies above that (ill-conditioned Jacobians at large
forces) the damped iteration stalls and the state is reported as status 1 with NaN. This measures
how many of them converge at the looser tolerance and how far those are from the verifier's root,
and how many belong to designs whose natural state at Ft = 0 was not found at all (then every Ft of
the design is status 1).

    python3 -m validation.status1_floor validation/stress_10000.npz [--tolerance 1e-10] [--json out.json]
"""
from __future__ import annotations

import argparse
import os
import time

import numpy as np

from . import campaign, verify  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz")
    ap.add_argument("--tolerance", type=float, default=1e-10)
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    import gecko
    z = np.load(args.npz)
    P, FT, status = z["P"], z["FT"], z["status"]
    rows = np.nonzero((status == 1).any(axis=1))[0]
    t0 = time.time()
    st = np.full(status.shape, -1, dtype=np.int64)
    Fn = np.full(FT.shape, np.nan)
    beta = np.full(FT.shape, np.nan)
    for i in rows:
        s = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, P[i])))
        L = s.critical_line(Ft=FT[i], errors="nan", tolerance=args.tolerance)
        m = status[i] == 1
        st[i, m] = L.status[m]
        Fn[i, m] = L.Fn[m]
        beta[i, m] = L.theta_joint[m]
    t_solve = time.time() - t0
    # Which status-1 states belong to designs whose natural state at Ft = 0 was not found (the
    # homotopy of critical_line.hpp gave up: the traced line is empty, every Ft gets status 1)?
    no_natural = np.zeros(status.shape, dtype=bool)
    for i in rows:
        s = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, P[i])))
        if len(s.critical_line(ft_end=0.0).Ft) == 0:
            no_natural[i] = status[i] == 1
    ok = st == 0
    t0 = time.time()
    v = campaign.verify_states(P, FT, Fn, beta, np.where(ok, 0, 1))
    t_ver = time.time() - t0
    cl = campaign.classify(P, FT, Fn, beta, np.where(ok, 0, 1), v)
    conc = ok & ~cl["inconclusive_fn"]
    rel = cl["rel"]
    force = np.hypot(Fn, FT)
    out = dict(
        campaign=os.path.relpath(args.npz), tolerance=args.tolerance, status1_states=int((status == 1).sum()),
        status1_designs=int(rows.size), no_natural_state_designs=int(no_natural.any(axis=1).sum()),
        no_natural_state_states=int(no_natural.sum()),
        no_natural_state_design_medians={
            name: float(np.median(col[no_natural.any(axis=1)]))
            for name, col in (("EI2/EI1", P[:, 1] / P[:, 0]), ("EI1", P[:, 0]), ("l2", P[:, 5]), ("EA1", P[:, 2]))}
        if no_natural.any() else None,
        converged_at_tolerance=int(ok.sum()),
        still_status={int(k): int(c) for k, c in zip(*np.unique(st[status == 1], return_counts=True))},
        verified_conclusive=int(conc.sum()), beyond_1e_8=int(cl["wrong_fn"].sum()),
        max_rel_dFn=float(np.nanmax(rel[conc])) if conc.any() else None,
        median_rel_dFn=float(np.nanmedian(rel[conc])) if conc.any() else None,
        force_percentiles={str(q): float(np.nanpercentile(force[ok], q)) for q in (10, 50, 90)} if ok.any() else None,
        seconds_solve=round(t_solve, 1), seconds_verify=round(t_ver, 1))
    return campaign.print_json(out, args.json)


if __name__ == "__main__":
    main()
