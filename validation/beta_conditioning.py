#!/usr/bin/env python3
"""High-precision check of the campaign states where the double-precision verifier disagrees with
gecko in beta but not in Fn (validation/results/stress.md, "beta investigation"), or (--by fn) of the
states with the largest verified Fn differences.

Route (no gecko code, no double-precision step): the same backward shooting as verify.py (docs/theory/two_level_seta.md:
from the contact edge theta2 = pi/2, theta2' = +sqrt(2 (w - Ft^2/(2 EA2))/EI2), across the
joint, down to the base), but integrated by a Taylor-series method of order 40 in mpmath at 60
digits (series of sin/cos by the usual recurrences), so the rounding amplification exp(l sqrt(N/EI))
of the strongly tensioned, hyperbolic states (up to ~1e12 here) costs nothing.  The root Fn* of
theta1(0) = alpha1 is found by secant iteration to 1e-30 relative, and beta* = theta2(l1) at it.
Reported per state: gecko's errors |Fn - Fn*|/max(1,|Fn*|) and |beta - beta*|, the double
verifier's dbeta, and the condition number dbeta_shot/dFn of the tip-to-joint map that the
verifier uses (the amplification that makes its beta inconclusive).

    python3 -m validation.beta_conditioning validation/stress_2000.npz [--top 6] [--by fn] [--json out.json]
"""
from __future__ import annotations

import argparse
import json

import mpmath as mp
import numpy as np


DPS = 60
ORDER = 40


def _series_step(th, p, h, Fn, Ft, inv_ei, inv_ea):
    """One Taylor step of theta'' = -(Fn s + Ft c)(1 + T inv_ea) inv_ei, T = Ft s - Fn c."""
    K = ORDER
    t = [mp.mpf(0)] * (K + 1)
    s = [mp.mpf(0)] * (K + 1)
    c = [mp.mpf(0)] * (K + 1)
    g = [mp.mpf(0)] * (K + 1)
    t[0], t[1] = th, p
    s[0], c[0] = mp.sin(th), mp.cos(th)
    A = [mp.mpf(0)] * (K + 1)
    B = [mp.mpf(0)] * (K + 1)
    for k in range(0, K - 1):
        if k > 0:   # s_k, c_k from t_1..t_k
            ss = mp.mpf(0)
            cc = mp.mpf(0)
            for j in range(1, k + 1):
                ss += j * t[j] * c[k - j]
                cc -= j * t[j] * s[k - j]
            s[k] = ss / k
            c[k] = cc / k
        A[k] = Fn * s[k] + Ft * c[k]
        B[k] = Ft * s[k] - Fn * c[k]
        # g = -A (1 + B inv_ea) inv_ei, the k-th coefficient of the product
        prod = A[k]
        if inv_ea != 0:
            acc = mp.mpf(0)
            for j in range(k + 1):
                acc += A[j] * B[k - j]
            prod += inv_ea * acc
        g[k] = -prod * inv_ei
        t[k + 2] = g[k] / ((k + 1) * (k + 2))
    th_new = mp.mpf(0)
    p_new = mp.mpf(0)
    hk = mp.mpf(1)
    for k in range(K + 1):
        th_new += t[k] * hk
        if k >= 1:
            p_new += k * t[k] * hk / h
        hk *= h
    return th_new, p_new


def _segment(th, p, length, Fn, Ft, ei, ea, steps):
    h = -mp.mpf(length) / steps
    inv_ei = 1 / mp.mpf(ei)
    inv_ea = mp.mpf(0) if mp.isinf(ea) else 1 / mp.mpf(ea)
    for _ in range(steps):
        th, p = _series_step(th, p, h, Fn, Ft, inv_ei, inv_ea)
    return th, p


def shoot(d, Ft, Fn, refine=1):
    """theta1(0), beta = theta2(l1) at 60 digits (backward from the contact edge)."""
    Ft, Fn = mp.mpf(Ft), mp.mpf(Fn)
    ea2 = mp.mpf(d["EA2"])
    rad = 2 * (d["w"] - (0 if mp.isinf(ea2) else Ft ** 2 / (2 * ea2))) / mp.mpf(d["EI2"])
    p = mp.sqrt(rad)
    N = abs(mp.sqrt(Fn ** 2 + Ft ** 2))
    out = []
    th = mp.pi / 2
    for ei, ea, L in ((d["EI2"], d["EA2"], d["l2"]), (d["EI1"], d["EA1"], d["l1"])):
        ea_m = mp.inf if np.isinf(ea) else mp.mpf(ea)
        force = N * (1 + (0 if mp.isinf(ea_m) else N / ea_m))
        rate = mp.sqrt(force / ei) + abs(p) + 1
        steps = int(mp.ceil(L * rate / mp.mpf("0.15"))) * refine + 2
        if out:   # joint: theta1 = beta - alpha2, EI1 theta1' = EI2 theta2'
            th = th - d["alpha2"]
            p = mp.mpf(d["EI2"]) * p / mp.mpf(d["EI1"])
        th, p = _segment(th, p, L, Fn, Ft, ei, ea_m, steps)
        out.append(th)
    return out[1], out[0]


def root(d, Ft, Fn0):
    """Secant on R(Fn) = theta1(0) - alpha1 from gecko's Fn; returns Fn*, beta*, dbeta/dFn."""
    a1 = mp.mpf(d["alpha1"])
    x0 = mp.mpf(Fn0)
    x1 = x0 * (1 + mp.mpf("1e-12")) + mp.mpf("1e-12")
    r0 = shoot(d, Ft, x0)[0] - a1
    r1 = shoot(d, Ft, x1)[0] - a1
    for _ in range(30):
        x2 = x1 - r1 * (x1 - x0) / (r1 - r0)
        x0, r0 = x1, r1
        x1 = x2
        r1 = shoot(d, Ft, x1)[0] - a1
        if abs(x1 - x0) < mp.mpf("1e-32") * max(1, abs(x1)):
            break
    th, beta = shoot(d, Ft, x1)
    dx = mp.mpf("1e-25") * max(1, abs(x1))
    _, beta2 = shoot(d, Ft, x1 + dx)
    # integration check: the same at twice the steps
    th_r, beta_r = shoot(d, Ft, x1, refine=2)
    return x1, beta, (beta2 - beta) / dx, max(abs(th_r - th), abs(beta_r - beta))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("npz")
    ap.add_argument("--top", type=int, default=6)
    ap.add_argument("--json", default=None)
    ap.add_argument("--by", choices=("beta", "fn", "flagged"), default="beta",
                    help="beta: states confirmed in Fn with |dbeta| > 1e-8 (default); fn: the largest verified"
                         " |dFn|/max(1,|Fn|), to tell gecko's own error from the verifier's; flagged: every state"
                         " the double verifier flags as silently wrong (campaign.classify)")
    args = ap.parse_args(argv)
    mp.mp.dps = DPS
    from . import campaign
    z = np.load(args.npz)
    P, FT, Fn, beta, status = z["P"], z["FT"], z["Fn"], z["beta"], z["status"]
    scale = np.maximum(1.0, np.abs(Fn))
    rel = np.abs(z["v_dFn"]) / scale
    dbeta = np.abs(z["v_dbeta"])
    conc_fn = (z["v_fn_uncert"] / scale < 1e-9) & np.isfinite(rel)
    if args.by == "beta":
        cand = (status == 0) & conc_fn & (dbeta > 1e-8)
        key = dbeta
    elif args.by == "flagged":
        v = {k[2:]: z[k] for k in z.files if k.startswith("v_")}
        cl = campaign.classify(P, FT, Fn, beta, status, v)
        cand = cl["wrong_fn"] | cl["wrong_beta"]
        key = np.maximum(rel, dbeta)
        args.top = max(args.top, int(cand.sum()))
    else:
        cand = (status == 0) & conc_fn & (rel > 1e-12)
        key = rel
    order = np.argsort(np.where(cand, key, -1).ravel())[::-1][: args.top]
    rows = []
    for k in order:
        i, j = np.unravel_index(k, status.shape)
        if not cand[i, j]:
            break
        d = dict(zip(campaign.FIELDS, map(float, P[i])))
        fs, bs, cond, ierr = root(d, float(FT[i, j]), float(Fn[i, j]))
        row = dict(design=P[i].tolist(), Ft=float(FT[i, j]), Fn=float(Fn[i, j]), beta=float(beta[i, j]),
                   Fn_star=float(fs), beta_star=float(bs),
                   gecko_rel_dFn=float(abs(Fn[i, j] - fs) / max(1, abs(fs))),
                   gecko_dbeta=float(abs(beta[i, j] - bs)),
                   verifier_rel_dFn=float(rel[i, j]), verifier_dbeta=float(z["v_dbeta"][i, j]),
                   dbeta_dFn_tip_shot=float(cond), integration_check=float(ierr),
                   beta_uncert=float(z["v_beta_uncert"][i, j]) if "v_beta_uncert" in z.files else None)
        rows.append(row)
        print(json.dumps(row), flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return rows


if __name__ == "__main__":
    main()
