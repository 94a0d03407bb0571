#!/usr/bin/env python3
"""Verify a saved campaign (validation/campaign.py --out X.npz) with validation/verify.py,
check the batch call for 1 vs 2 threads, and write validation/results/stress.{md,json}.

    python3 -m validation.report validation/stress_10000.npz [--beta validation/results/stress_beta.json]
        [--fn-check validation/results/stress_fn.json] [--flagged-check validation/results/stress_flagged.json]
        [--recheck validation/results/stress_recheck.json]

--beta: the 60-digit check of the states whose beta the double verifier cannot confirm
(validation/beta_conditioning.py --json ...), summarised in the report.
--fn-check: the same 60-digit check of the states with the largest verified Fn differences
(beta_conditioning.py --by fn --json ...): whose error they are, gecko's or the verifier's.
--flagged-check: the 60-digit check of every state the double verifier flags as silently wrong
(beta_conditioning.py --by flagged --json ...); a flag stands unless the 60-digit root clears it.
--recheck: a later solver re-run on the campaign's states (validation/recheck.py --json ...).
"""
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
from . import campaign  # noqa: E402

RESULTS = os.path.join(HERE, "results")


def threads_check(P, n=None):
    import gecko
    ft = np.array([-1.0, -0.3, 0.0, 0.5, 1.0, 1.9])   # shared grid; beyond (Ft)max -> status 5
    sub = P[:n] if n else P
    t = time.time()
    a = gecko.critical_line_batch(sub, ft, threads=1, errors="nan")
    t1 = time.time() - t
    t = time.time()
    b = gecko.critical_line_batch(sub, ft, threads=2, errors="nan")
    t2 = time.time() - t
    same = all(getattr(a, k).tobytes() == getattr(b, k).tobytes()
               for k in ("Fn", "theta_joint", "status", "iterations", "turning_points_beam", "turning_points_spatula"))
    return dict(designs=int(sub.shape[0]), ft=ft.tolist(), bitwise_identical=bool(same), t1_s=t1, t2_s=t2)


def main(path, beta_json=None, fn_json=None, flagged_json=None, recheck_json=None):
    z = np.load(path)
    P, FT, Fn, beta, status, secs = z["P"], z["FT"], z["Fn"], z["beta"], z["status"], z["secs"]
    t = time.time()
    if "v_beta_uncert" in z.files and "--reverify" not in sys.argv:
        # verified by the current verify.py in the campaign itself (chunked runs)
        v = {k[2:]: z[k].copy() for k in z.files if k.startswith("v_")}
        t_ver = float(z["t_ver"])
    elif "v_dFn" in z.files and "--reverify" not in sys.argv:
        # reuse the campaign's verification; re-verify (with the rounding-amplification bound of
        # verify.py) only the states that the saved one flags or that lack the bound
        v = {k[2:]: z[k].copy() for k in z.files if k.startswith("v_")}
        t_ver = float(z["t_ver"])
        scale = np.maximum(1.0, np.abs(Fn))
        flag = (status == 0) & ~((np.abs(v["dFn"]) / scale <= 1e-9) & (np.abs(v["dbeta"]) <= 1e-9))
        v.setdefault("beta_uncert", np.where(status == 0, 0.0, np.nan))
        if flag.any():
            r, c = np.nonzero(flag)
            st = np.full(status.shape, 1, dtype=status.dtype)
            st[r, c] = 0
            v2 = campaign.verify_states(P, FT, Fn, beta, st)
            for k in v:
                if k in v2:
                    v[k][r, c] = v2[k][r, c]
        t_ver += time.time() - t
    else:
        v = campaign.verify_states(P, FT, Fn, beta, status)
        t_ver = time.time() - t
    cl = campaign.classify(P, FT, Fn, beta, status, v)
    ok = status == 0
    scale = np.maximum(1.0, np.abs(Fn))
    vals, cnts = np.unique(status, return_counts=True)
    hist = {int(k): int(c) for k, c in zip(vals, cnts)}
    conc = ok & ~cl["inconclusive_fn"]
    rel = cl["rel"]
    tp = ok & ((z["tpb"] > 0) | (z["tps"] > 0))
    worst = []
    order = np.argsort(np.where(conc, rel, -1).ravel())[::-1][:10]
    for k in order:
        i, j = np.unravel_index(k, status.shape)
        worst.append(dict(design=P[i].tolist(), Ft=float(FT[i, j]), Fn=float(Fn[i, j]), beta=float(beta[i, j]),
                          rel_dFn=float(rel[i, j]), dbeta=float(v["dbeta"][i, j]),
                          fn_uncert=float(v["fn_uncert"][i, j] / scale[i, j])))
    timeouts = [P[i].tolist() for i in np.nonzero((status == -1).any(axis=1))[0]]
    wrong_idx = np.nonzero(cl["wrong_fn"] | cl["wrong_beta"] | cl["nonfinite_ok"] | cl["number_with_status"])
    wrong = [dict(design=P[i].tolist(), Ft=float(FT[i, j]), Fn=float(Fn[i, j]), beta=float(beta[i, j]),
                  status=int(status[i, j]), Fn_verifier=float(v["fn_root"][i, j]) if "fn_root" in v else None,
                  rel_dFn=float(rel[i, j]), dbeta=float(v["dbeta"][i, j]))
             for i, j in zip(*wrong_idx)]
    # A flag of the double verifier stands unless the 60-digit shooting clears it (gecko within
    # 1e-8 of the 60-digit root in Fn, relative, and in beta).
    flagged_hp = json.load(open(flagged_json)) if flagged_json else []
    cleared = [r for r in flagged_hp if r["gecko_rel_dFn"] <= campaign.WRONG_REL and r["gecko_dbeta"] <= campaign.WRONG_REL]
    tpagree = ok & conc & (v["turns_beam"] >= 0)
    out = dict(
        designs=int(P.shape[0]), designs_planned=int(designs_planned(path, z)), states=int(status.size), histogram=hist,
        solved_percent=float(100 * ok.mean()), verified_conclusive=int(conc.sum()),
        inconclusive_fn=int(cl["inconclusive_fn"].sum()), inconclusive_beta=int(cl["inconclusive_beta"].sum()),
        silently_wrong_fn=int(cl["wrong_fn"].sum()), silently_wrong_beta=int(cl["wrong_beta"].sum()),
        flagged_checked_60_digits=len(flagged_hp) if flagged_json else None,
        flagged_cleared_60_digits=len(cleared) if flagged_json else None,
        silently_wrong_after_60_digits=(len(wrong) - len(cleared)) if flagged_json else None,
        flagged_high_precision=flagged_hp or None,
        nonfinite_with_status0=int(cl["nonfinite_ok"].sum()), number_with_status_nonzero=int(cl["number_with_status"].sum()),
        turning_point_share=float(tp.sum() / max(1, ok.sum())),
        turning_point_count_agreement=float(np.mean((v["turns_beam"] == z["tpb"])[tpagree] & (v["turns_spatula"] == z["tps"])[tpagree])),
        max_rel_dFn_conclusive=float(np.nanmax(rel[conc])) if conc.any() else None,
        median_rel_dFn=float(np.nanmedian(rel[conc])) if conc.any() else None,
        max_verifier_fn_uncert=float(np.nanmax((v["fn_uncert"] / scale)[conc])) if conc.any() else None,
        max_abs_dbeta_conclusive=float(np.nanmax(np.abs(v["dbeta"])[ok & ~cl["inconclusive_beta"] & conc])),
        timeouts_designs=len(timeouts), timeout_examples=timeouts[:5],
        gecko_seconds=float(z["t_gecko"]), verifier_seconds=t_ver, slowest_design_s=float(secs.max()),
        worst=worst, wrong=wrong[:50], threads=threads_check(P),
        design_seconds_percentiles={str(q): float(np.percentile(secs, q)) for q in (50, 90, 99, 99.9, 100)},
        worst_dbeta=worst_dbeta(P, FT, Fn, beta, status, v, cl, scale),
        beta_high_precision=json.load(open(beta_json)) if beta_json else None,
        fn_high_precision=json.load(open(fn_json)) if fn_json else None,
        recheck=json.load(open(recheck_json)) if recheck_json else None,
    )
    with open(os.path.join(RESULTS, "stress.json"), "w") as f:
        json.dump(out, f, indent=1)
    print(json.dumps({k: v for k, v in out.items() if k not in ("worst", "wrong", "timeout_examples", "worst_dbeta", "beta_high_precision",
                                                              "fn_high_precision", "flagged_high_precision", "recheck")}, indent=1))
    write_md(out, path)
    return out


def designs_planned(path, z):
    """The campaign's --designs (a partial merge holds fewer): from the chunk directory's size."""
    if "design_index" not in z.files:
        return z["P"].shape[0]
    return int(os.environ.get("STRESS_DESIGNS_PLANNED", z["design_index"].max() + 1))


def worst_dbeta(P, FT, Fn, beta, status, v, cl, scale, k=5):
    """The largest |dbeta| among states conclusive in Fn (beta may be inconclusive there)."""
    conc = (status == 0) & ~cl["inconclusive_fn"]
    db = np.where(conc, np.abs(v["dbeta"]), -1)
    out = []
    for idx in np.argsort(db.ravel())[::-1][:k]:
        i, j = np.unravel_index(idx, status.shape)
        if db[i, j] <= 0:
            break
        out.append(dict(design=P[i].tolist(), Ft=float(FT[i, j]), Fn=float(Fn[i, j]), beta=float(beta[i, j]),
                        rel_dFn=float(cl["rel"][i, j]), dbeta=float(v["dbeta"][i, j]),
                        beta_uncert=float(v["beta_uncert"][i, j]), fn_uncert=float(v["fn_uncert"][i, j] / scale[i, j]),
                        conclusive_beta=bool(not cl["inconclusive_beta"][i, j])))
    return out


def high_precision_table(rows):
    """Markdown rows of beta_conditioning.py results: gecko and the double verifier against the
    60-digit root."""
    out = ["| design | Ft | Fn | gecko rel dFn | gecko dbeta | verifier rel dFn | verifier dbeta | dbeta/dFn (tip shot) |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {', '.join(f'{x:.6g}' for x in r['design'])} | {r['Ft']:.6g} | {r['Fn']:.8g} |"
                   f" {r['gecko_rel_dFn']:.1e} | {r['gecko_dbeta']:.1e} | {r['verifier_rel_dFn']:.1e} |"
                   f" {r['verifier_dbeta']:.1e} | {r['dbeta_dFn_tip_shot']:.2e} |")
    return out


def write_md(o, path):
    names = {-1: "timeout (no answer within the per-design limit)", 0: "converged", 1: "not converged",
             2: "no critical state", 3: "unsupported state", 4: "singular (at a fold)", 5: "invalid input",
             6: "not reached (the followed line was given up before this Ft)"}
    L = ["# Stress campaign of the two-level seta solver (issue 6)", "",
         "Generated by `validation/report.py` from `validation/campaign.py` (box, sampling and the",
         "definition of *silently wrong* are in the campaign's docstring and validation/README.md).", "",
         f"- designs: {o['designs']}" + (f" (a partial campaign: {o['designs']} of {o['designs_planned']} planned designs finished)"
                                         if o['designs'] < o['designs_planned'] else "") + f", states (design x Ft): {o['states']}",
         f"- solved (status 0): {o['solved_percent']:.2f} %",
         (f"- flagged by the double verifier (status 0, verifier conclusive, |dFn| > 1e-8 max(1,|Fn|)): {o['silently_wrong_fn']};"
          f" beta off by > 1e-8: {o['silently_wrong_beta']}" if o.get("flagged_checked_60_digits") is not None else
          f"- **silently wrong** (status 0, verifier conclusive, |dFn| > 1e-8 max(1,|Fn|)): **{o['silently_wrong_fn']}**;"
          f" beta off by > 1e-8: **{o['silently_wrong_beta']}**"),
         *([f"- of those, checked by the 60-digit shooting: {o['flagged_checked_60_digits']}; cleared"
            f" (gecko within 1e-8 of its root in Fn and beta): {o['flagged_cleared_60_digits']};"
            f" **silently wrong after that check: {o['silently_wrong_after_60_digits']}** (table below)"]
           if o.get("flagged_checked_60_digits") is not None else []),
         f"- status 0 with NaN: {o['nonfinite_with_status0']}; status != 0 with a number: {o['number_with_status_nonzero']}",
         f"- verified conclusively: {o['verified_conclusive']} states; verifier inconclusive in Fn (own uncertainty"
         f" > 1e-9 relative): {o['inconclusive_fn']}; in beta: {o['inconclusive_beta']}",
         f"- max |dFn|/max(1,|Fn|) over conclusive states: {o['max_rel_dFn_conclusive']:.3g} (median {o['median_rel_dFn']:.3g});"
         f" max verifier uncertainty there: {o['max_verifier_fn_uncert']:.3g}; max |dbeta|: {o['max_abs_dbeta_conclusive']:.3g}",
         f"- turning-point share among solved states: {100 * o['turning_point_share']:.1f} %; turning-point counts"
         f" agree with the verifier's sign changes of theta' in {100 * o['turning_point_count_agreement']:.2f} % of them",
         f"- designs with a timeout (no answer within the per-design wall-clock limit): {o['timeouts_designs']}"
         + (" (a finding: unbounded run time, see below)" if o['timeouts_designs'] else ""),
         f"- time: gecko {o['gecko_seconds']:.0f} s (per-design calls in a worker process, incl. timeouts),"
         f" verifier {o['verifier_seconds']:.0f} s; slowest design {o['slowest_design_s']:.2f} s", "",
         "## Status histogram", "", "| status | meaning | states |", "|---|---|---|"]
    for k, c in sorted(o["histogram"].items()):
        L.append(f"| {k} | {names.get(k, '?')} | {c} |")
    if o.get("recheck"):
        r = o["recheck"]
        L += ["", "## The campaign's states with the current solver (validation/recheck.py)", "",
              f"Fn bitwise equal: **{r['Fn_bitwise_equal']}**; beta bitwise equal: **{r['beta_bitwise_equal']}**;"
              f" statuses equal: **{r['status_equal']}** ({r['states']} states). Turning-point counts changed in"
              f" {r['turning_counts_changed']} solved states and now agree with the verifier in"
              f" {r['turning_counts_agree']} of {r['turning_counts_checked']}."]
    t = o["threads"]
    L += ["", "## 1 vs 2 threads (batch call)", "",
          f"`critical_line_batch` on the first {t['designs']} designs at Ft = {t['ft']}: bitwise identical"
          f" (Fn, theta_joint, status, iterations, turning points): **{t['bitwise_identical']}**"
          f" ({t['t1_s']:.2f} s with 1 thread, {t['t2_s']:.2f} s with 2, shared busy machine).", "",
          "## Worst verified cases (conclusive)", "", "| design (EI1, EI2, EA1, EA2, l1, l2, a1, a2, w) | Ft | Fn | rel dFn | dbeta | verifier unc. |",
          "|---|---|---|---|---|---|"]
    for w in o["worst"]:
        L.append(f"| {', '.join(f'{x:.6g}' for x in w['design'])} | {w['Ft']:.6g} | {w['Fn']:.8g} | {w['rel_dFn']:.2e} |"
                 f" {w['dbeta']:.2e} | {w['fn_uncert']:.1e} |")
    if o["wrong"]:
        L += ["", "## Silently wrong / inconsistent states", "", "```", json.dumps(o["wrong"][:20], indent=1), "```"]
    L += ["", "## Largest beta differences where Fn is verified", "",
          "The double-precision verifier reads beta off a backward shot from the contact edge over the spatula;",
          "in strongly tensioned (hyperbolic) states that shot amplifies any error in Fn by |dbeta/dFn| (up to",
          "~1e7 here), so beta is inconclusive there (its bound `beta unc.` below) even where Fn is conclusive.", "",
          "| design | Ft | Fn | rel dFn | dbeta | beta unc. | beta conclusive |", "|---|---|---|---|---|---|---|"]
    for w in o["worst_dbeta"]:
        L.append(f"| {', '.join(f'{x:.6g}' for x in w['design'])} | {w['Ft']:.6g} | {w['Fn']:.8g} | {w['rel_dFn']:.2e} |"
                 f" {w['dbeta']:.2e} | {w['beta_uncert']:.1e} | {w['conclusive_beta']} |")
    if o.get("beta_high_precision"):
        L += ["", "60-digit check (validation/beta_conditioning.py: Taylor-series shooting of order 40 in mpmath,",
              "root Fn* to 1e-30): gecko's errors against it, beside the double verifier's differences and the",
              "condition number dbeta/dFn of the tip-to-joint shot.", "",
              *high_precision_table(o["beta_high_precision"])]
    if o.get("flagged_high_precision"):
        L += ["", "## States flagged by the double verifier, checked at 60 digits", "",
              "Every state the double-precision verifier flags (status 0, |dFn| or |dbeta| > 1e-8 where it",
              "calls itself conclusive), solved by the 60-digit Taylor shooting (beta_conditioning.py --by flagged).", "",
              *high_precision_table(o["flagged_high_precision"])]
    if o.get("fn_high_precision"):
        L += ["", "## Largest Fn differences, checked at 60 digits", "",
              "The states with the largest verified |dFn| (beta_conditioning.py --by fn): gecko's error",
              "against the 60-digit root Fn*, beside the double verifier's difference.", "",
              *high_precision_table(o["fn_high_precision"])]
    q = o["design_seconds_percentiles"]
    L += ["", "## Run time per design (wall clock, incl. the worker round trip; shared busy machine)", "",
          "percentiles 50/90/99/99.9/100: " + ", ".join(f"{q[k]:.3g} s" for k in q)]
    L += ["", "## Timeouts (examples)", ""] + ([f"- {d}" for d in o["timeout_examples"]] or ["none"])
    L += ["", "## Command", "", "```",
          "python3 -m validation.campaign --designs 10000 --workers 2 --timeout 30 --out validation/stress_10000.npz",
          "# (resumable: the same command keeps the finished chunks in validation/stress_10000_chunks/)",
          *([f"python3 -m validation.beta_conditioning {os.path.relpath(path, os.path.join(HERE, '..'))}"
             f" --by {by} --json validation/results/stress_{by}.json"
             for by, key in (("flagged", "flagged_checked_60_digits"), ("fn", "fn_high_precision"),
                             ("beta", "beta_high_precision")) if o.get(key) is not None]),
          *([f"python3 -m validation.recheck {os.path.relpath(path, os.path.join(HERE, '..'))}"
             " --json validation/results/stress_recheck.json"] if o.get("recheck") else []),
          f"python3 -m validation.report {os.path.relpath(path, os.path.join(HERE, '..'))}"
          + (" --beta validation/results/stress_beta.json" if o.get("beta_high_precision") else "")
          + (" --fn-check validation/results/stress_fn.json" if o.get("fn_high_precision") else "")
          + (" --flagged-check validation/results/stress_flagged.json" if o.get("flagged_checked_60_digits") is not None else "")
          + (" --recheck validation/results/stress_recheck.json" if o.get("recheck") else ""),
          "```"]
    with open(os.path.join(RESULTS, "stress.md"), "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    beta = sys.argv[sys.argv.index("--beta") + 1] if "--beta" in sys.argv else None
    fn_check = sys.argv[sys.argv.index("--fn-check") + 1] if "--fn-check" in sys.argv else None
    flagged = sys.argv[sys.argv.index("--flagged-check") + 1] if "--flagged-check" in sys.argv else None
    recheck = sys.argv[sys.argv.index("--recheck") + 1] if "--recheck" in sys.argv else None
    main(args[0], beta, fn_check, flagged, recheck)
