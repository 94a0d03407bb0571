#!/usr/bin/env python3
"""Independent verification of the *traced* critical line (``critical_line()`` without Ft): every
node carries a status (0: re-solved to the state tolerance; 1: not), and the status-0 nodes are
checked by the campaign's ODE-shooting verifier (verify.py, no gecko code).

The campaign (campaign.py) checks states at requested Ft; this checks the continuation's own nodes,
which before the re-solve (critical_line_options::resolve_nodes) were predictor-corrector points
accepted at the line tolerance and, on lines running along a form boundary, off by up to ~7e-9.

Nodes exactly at the line's end (|Ft| within 4 eps of (Ft)max) are left out of the double-precision
check: there theta2'(a) = 0 and the verifier's tip rate sqrt(2 (w - Ft^2/(2 EA2))/EI2), computed in
double, is ~1e-8 instead of 0 (an Ft an ulp below (Ft)max moves Fn by ~1e-7: the problem's
conditioning, tests/seta/near_singular.cpp). gecko maps such Ft to the end itself; its end states
are checked against mpmath in tests/seta/line_end.cpp.

    python3 -m validation.traced_nodes --designs 400 --seed 5 --per-line 8 [--hp 2] [--json out.json]

--hp N: the N nodes where the raw continuation node (resolve_nodes=False) differs most from the
re-solved one, both checked against the 60-digit Taylor shooting (beta_conditioning.py); and the
worst verified node at 60 digits, with the problem's condition number there (sum over the design
parameters p of |p dFn/dp| from the exact sensitivities, plus |Ft dFn/dFt|, over |Fn|): an error
far above condition x eps is the formulation's, not the problem's.
"""
from __future__ import annotations

import argparse
import collections
import time

import numpy as np

from . import campaign, verify  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--designs", type=int, default=400)
    ap.add_argument("--seed", type=int, default=5)
    ap.add_argument("--per-line", type=int, default=8, help="status-0 nodes verified per line (random)")
    ap.add_argument("--hp", type=int, default=0, help="60-digit check of the N largest raw-vs-re-solved differences")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    import gecko
    rng = np.random.default_rng(args.seed)
    P = campaign.sample_designs(args.designs, rng)
    t0 = time.time()
    lines = [gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, p))).critical_line() for p in P]
    t_trace = time.time() - t0
    status = np.concatenate([L.status for L in lines])
    ends = collections.Counter(L.end for L in lines)
    pick = np.random.default_rng(args.seed + 1)
    rows, ft, fn, be = [], [], [], []
    end_nodes = 0
    for i, L in enumerate(lines):
        ftm = np.sqrt(2 * P[i, 3] * P[i, 8])
        at_end = np.abs(L.Ft) >= ftm * (1 - 4 * np.finfo(float).eps)
        end_nodes += int(np.sum(at_end & (L.status == 0)))
        idx = np.nonzero((L.status == 0) & ~at_end)[0]
        if idx.size > args.per_line:
            idx = np.sort(pick.choice(idx, args.per_line, replace=False))
        for k in idx:
            rows.append(i)
            ft.append(L.Ft[k])
            fn.append(L.Fn[k])
            be.append(L.theta_joint[k])
    rows = np.array(rows, dtype=np.int64)
    FT, FN, BE = (np.array(x)[:, None] for x in (ft, fn, be))
    t0 = time.time()
    v = verify.verify(campaign.design_dict(P[rows]), FT[:, 0], FN[:, 0], BE[:, 0])
    t_ver = time.time() - t0
    c = campaign.classify(P[rows], FT, FN, BE, np.zeros(FT.shape, dtype=np.int64),
                          {k: np.asarray(x)[:, None] for k, x in v.items()})
    rel = c["rel"][:, 0]
    conc = ~c["inconclusive_fn"][:, 0]
    worst = int(np.argmax(np.where(conc, rel, -1.0))) if conc.any() else None
    out = dict(
        gecko_version=getattr(gecko, "__version__", "?"), designs=args.designs, seed=args.seed,
        line_ends={k: int(n) for k, n in ends.items()}, nodes=int(status.size),
        node_status={int(k): int(n) for k, n in collections.Counter(status.tolist()).items()},
        lines_with_status1_nodes=int(sum(bool((L.status != 0).any()) for L in lines)),
        end_nodes_left_out=end_nodes, verified=int(rows.size), conclusive=int(conc.sum()),
        wrong_fn=int(c["wrong_fn"].sum()), wrong_beta=int(c["wrong_beta"].sum()),
        worst_rel_dFn=float(rel[worst]) if worst is not None else None,
        median_rel_dFn=float(np.nanmedian(rel[conc])) if conc.any() else None,
        worst_state=dict(design=P[rows[worst]].tolist(), Ft=float(FT[worst, 0]), Fn=float(FN[worst, 0]))
        if worst is not None else None,
        seconds_trace=round(t_trace, 2), seconds_verify=round(t_ver, 1))
    if args.hp:
        out["raw_vs_resolved_60_digits"] = raw_vs_resolved(P, lines, args.hp)
        if worst is not None:
            out["worst_state_60_digits"] = worst_at_60_digits(P[rows[worst]], float(FT[worst, 0]), float(FN[worst, 0]))
    return campaign.print_json(out, args.json)


def worst_at_60_digits(p, ft, fn):
    """gecko's error at one state against the 60-digit root, and the problem's condition number."""
    import gecko
    import mpmath as mp
    import beta_conditioning as bc
    mp.mp.dps = bc.DPS
    s = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, p)))
    fs = bc.root(dict(zip(campaign.FIELDS, map(float, p))), ft, fn)[0]
    sens = s.sensitivities([ft])
    terms = np.abs(np.asarray(p) * sens["dFn"][0])
    h = 1e-6 * abs(ft)
    a = s.critical_line(Ft=[ft - h, ft + h]).Fn
    cond = (np.sum(terms[np.isfinite(terms)]) + abs(ft * (a[1] - a[0]) / (2 * h))) / abs(fn)
    return dict(design=list(map(float, p)), Ft=ft, Fn=fn, Fn_60_digits=mp.nstr(fs, 25),
                rel_err_60_digits=float(abs(fn - fs) / max(1.0, abs(float(fs)))),
                condition_number=float(cond), condition_times_eps=float(cond * np.finfo(float).eps))


def raw_vs_resolved(P, lines, top):
    """The largest |raw - re-solved| Fn differences (same node, same Ft), both against 60 digits."""
    import gecko
    import mpmath as mp
    import beta_conditioning as bc
    mp.mp.dps = bc.DPS
    cand = []
    for i, L in enumerate(lines):
        R = gecko.TwoLevelSeta(**dict(zip(campaign.FIELDS, P[i]))).critical_line(resolve_nodes=False)
        same = (L.status == 0) & (R.Ft == L.Ft)
        if not same.any():
            continue
        d = np.where(same, np.abs(R.Fn - L.Fn) / np.maximum(1.0, np.abs(L.Fn)), -1.0)
        k = int(np.argmax(d))
        cand.append((float(d[k]), i, k, float(R.Fn[k])))
    rows = []
    for diff, i, k, raw in sorted(cand, reverse=True)[:top]:
        L = lines[i]
        d = dict(zip(campaign.FIELDS, map(float, P[i])))
        fs = bc.root(d, float(L.Ft[k]), float(L.Fn[k]))[0]
        scale = max(1.0, abs(float(fs)))
        rows.append(dict(design=P[i].tolist(), Ft=float(L.Ft[k]), Fn_resolved=float(L.Fn[k]), Fn_raw=raw,
                         raw_vs_resolved=diff, raw_rel_err_60_digits=float(abs(raw - fs) / scale),
                         resolved_rel_err_60_digits=float(abs(float(L.Fn[k]) - fs) / scale)))
    return rows


if __name__ == "__main__":
    main()
