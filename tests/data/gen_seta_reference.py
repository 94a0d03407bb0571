#!/usr/bin/env python3
"""High-precision reference data for the two-level seta critical line of adhesion (docs/theory/two_level_seta.md).

Regenerate (from the repository root; 3-5 min on 2 busy cores, 2 worker processes;
SETA_REF_PROCS=1 for a single process):

    python3 tests/data/gen_seta_reference.py            # writes tests/data/seta_reference*.csv/json

Outputs
  seta_reference.csv          one critical state per row (see COLUMNS); inputs printed with repr()
                              (exact doubles, read back bit-identically), results with 25 significant
                              digits.
  seta_reference_beyond_ftmax.csv  same columns + theta2p_a: the continuation of the zero set past
                              the line end at (Ft)max, where theta2'(a) < 0 (unphysical, see
                              below; branch = 1) at Ft = 0.99, 0.95, 0.9 (Ft)max, for checking that
                              a solver rejects these states (or reproduces them if asked to).
  seta_reference_designs.csv  per-design characteristics ((Fn)0, (Ft)max, max pull-off and its Ft,
                              the end of the line at (Ft)max, folds, sticky_at_rest).
  seta_reference_meta.json    seed, settings and the verification statistics of this run.

Model (docs/theory/two_level_seta.md, paper eqs 1-5).  s is the undeformed arc length, angles from the substrate
normal.  Segment i: EI_i theta'' = -(Fn sin theta + Ft cos theta)(1 + T/EA_i),
T = Ft sin theta - Fn cos theta;  base theta1(0) = alpha1;  joint theta2(l1) = theta1(l1) + alpha2,
EI2 theta2'(l1) = EI1 theta1'(l1);  contact edge at the critical state a = l1 + l2: theta2(a) = pi/2
and 1/2 EI2 theta2'(a)^2 + Ft^2/(2 EA2) = w.  EA = inf drops the axial terms.

Sign convention at the contact edge.  The first integral 1/2 EI theta'^2 = M - N sin(theta - phi)
- N^2 sin^2(theta - phi)/(2EA) (differentiated: EI theta' theta'' = -theta' N cos(theta - phi)
(1 + N sin(theta - phi)/EA) = -theta' (Fn sin + Ft cos)(1 + T/EA), i.e. eq 1 times theta') only fixes
theta2'(a)^2, so the sign is geometric: the height of the spatula above the substrate plane obeys
h'(s) = cos theta, so theta2'(a) < 0 would put theta > pi/2 just before the edge and the spatula
*behind* the substrate (interpenetration).  Hence theta2'(a) = +sqrt(2 (w - Ft^2/(2EA2))/EI2) >= 0,
which vanishes at Ft = (Ft)max = sqrt(2 EA2 w): the physical critical line ends there, with
dFn/dFt infinite (Fn - Fn_end proportional to sqrt((Ft)max - Ft)); the zero set of the same equations
continues past it with Ft decreasing again and theta2'(a) < 0 - this is the "bend back near
(Ft)max" of docs/theory/two_level_seta.md, and it is not a physical critical state.  In none of the 37 designs does
the line fold (d Ft/ds = 0) before (Ft)max; on the Ft < 0 side, three designs fold (the tracking
stops there, targets beyond are not reached).  The first integrals then give M2 = Ft + w.

Routes (both in arbitrary precision, neither uses Carlson R_F, closed forms or the C++ code):
  1. ODE ("ode", seta_taylor.py): Taylor-series integration (order 40, 124-bit fixed point, local
     truncation < 2^-106) of the equations above.  Solve: shoot backwards from the contact edge
     (where theta2 and theta2' are known) to the base; the only unknown is Fn, residual
     theta1(0) - alpha1, secant iteration to |dFn| < 1e-27 max(1,|Fn|).  Verify: shoot forwards from
     the base with theta1(0) = alpha1 and the recorded theta1'(0) (the brief's formulation, unknowns
     (Fn, theta1'(0))) and require both tip residuals < 1e-24.  Digits: every state is solved again
     with 170-bit arithmetic, order 50, truncation < 2^-150; the max |dFn| between the two settings
     is reported in the meta file (typically ~1e-32).
  2. Quadrature ("quad", seta_quad.py): the first integrals and the two length equations (docs/theory/two_level_seta.md
     "First integrals", "Lengths") solved for (Fn, beta) by 2-D Newton at mp.dps = 30 with
     tanh-sinh quadrature, started from the double-precision guess (not from the ODE result).
     Segments with turning points are split at the turning angles (exact roots of the radicand),
     each piece integrated in the distance from the turning angle with a cancellation-free
     factorised radicand.  route = "quad+ode" when both routes agree to 1e-20 (relative to
     max(1,|Fn|) for Fn, absolute for beta), "ode" when only the ODE route gave a verified state.
Result of the committed run: 37 designs, 403 states (116 with turning points), 78 beyond-(Ft)max
states; every state "quad+ode"; max |Fn_quad - Fn_ode| / max(1,|Fn|) = 3.2e-28, max |beta_quad -
beta_ode| = 9.1e-29; max 124-bit vs 170-bit ODE difference 2.3e-31; forward residuals <= 8.7e-26;
turning-point counts of the mp and double stages agree on every state.
Accuracy claim: every row is correct to better than 1e-20 (the digits beyond that in the files are
those of the ODE route); the 1e-11 test tolerance of the C++ solver is 9 orders above.

Turning points: theta'(s) is sampled at 16 points of every Taylor step and at each segment start;
turning_points_seg1/2 = number of sign changes of theta' strictly inside [0, l1] / [l1, a].  The
double-precision stage (scipy DOP853) counts them independently on a 400-point grid; the two counts
are compared and disagreements reported in the meta file.

Finding the states (double precision, seta_double.py, guesses only):
  * natural state at Ft = 0 by homotopy from the small-deformation limit (paper 001 eq 18, docs/theory/two_level_seta.md);
  * continuation of the zero contour g(Fn, tau) = 0 (pseudo-arclength), tau = (Ft)max
    asin(Ft/(Ft)max) for finite EA2 (smooth through the line end) or tau = Ft for EA2 = inf; folds
    (d tau/ds changing sign) increment the `branch` index of the states found after them;
  * target Ft values: fractions 0, .15, .3, .5, .7, .85, .95, .99 of F_scale and -0.1, -0.3 of
    F_scale, with F_scale = (Ft)max, or 3 sqrt(EI1 w)/l1 for EA2 = inf (stated choice); the
    reference scene uses Ft = 0, 0.25, ..., 9.75, 9.9 and -0.5, -1, -2, -3.  Targets closer than
    1% of F_scale to a fold are skipped (ill-conditioned in Fn).  A target where the polished state
    cannot be verified is excluded, never guessed.
Max pull-off: the interior minimum of Fn along the line, refined in mp by a secant iteration on
dFn/dFt (central differences, h = 1e-10 F_scale, on ODE-route Fn(Ft) values solved to 1e-32):
truncation ~ F^(3) h^2 / 6 ~ 1e-21 and rounding ~ 1e-30 / h ~ 1e-21 in the derivative, so Ft* is
good to ~1e-19 and min Fn to ~1e-28.  (Checked at the reference scene: with the earlier
h = 1e-7, central differences at the returned Ft* for h = 1e-6 ... 1e-8 gave F'(Ft*) = -1.2e-16,
i.e. Ft* off by 6e-16, exactly the predicted truncation for that h.)  If Fn has no interior
minimum on [0, F_end] the minimum at the end of the range is reported with
min_kind = "range_end" (EA2 = inf) or "line_end" (at (Ft)max).
"""
import csv
import json
import math
import multiprocessing as mpc
import os
import sys
import time

import numpy as np
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import seta_double as sd  # noqa: E402
import seta_quad as sq    # noqa: E402
import seta_taylor as st  # noqa: E402

SEED = 20261121
N_RANDOM = 36
INF = math.inf

REFERENCE = dict(EI1=5.0, EI2=2.0, EA1=INF, EA2=50.0, l1=1.0, l2=0.1,
                 alpha1=math.pi / 6, alpha2=math.pi / 6, w=1.0)
KEYS = ["EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w"]
COLUMNS = ["design_id"] + KEYS + ["Ft", "Fn", "theta_joint", "theta1p0", "turning_points_seg1",
                                  "turning_points_seg2", "branch", "route"]
FINE = dict(prec=170, tol_bits=150, order=50)
AGREE = mpf("1e-20")


def r6(x):
    return float(f"{x:.6g}")


def random_designs(n, seed):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        EI1 = r6(math.exp(rng.uniform(math.log(0.5), math.log(50.0))))
        ratio = math.exp(rng.uniform(math.log(0.05), math.log(2.0)))
        EI2 = r6(EI1 * ratio)
        l2 = r6(rng.uniform(0.02, 0.5))
        a1 = r6(rng.uniform(math.pi / 18, math.pi / 3))
        a2 = r6(rng.uniform(0.0, math.pi / 2 - 0.15 - a1))
        EA2 = INF if rng.uniform() < 0.2 else r6(math.exp(rng.uniform(math.log(10.0), math.log(1000.0))))
        EA1 = INF if rng.uniform() < 0.3 else r6(math.exp(rng.uniform(math.log(50.0), math.log(1000.0))))
        out.append(dict(EI1=EI1, EI2=EI2, EA1=EA1, EA2=EA2, l1=1.0, l2=l2, alpha1=a1, alpha2=a2, w=1.0))
    return out


def f_scale(dd):
    Fm = sd.ft_max(dd)
    return Fm if not math.isinf(Fm) else 3.0 * math.sqrt(dd["EI1"] * dd["w"]) / dd["l1"]


def nstr(x):
    return mp.nstr(x, 25, min_fixed=-5, max_fixed=5) if x is not None else ""


def fmt_in(x):
    return "inf" if math.isinf(x) else repr(float(x))


def polish(d, dd, Ft, Fn_guess, fine, ksign=1):
    """Verified mp state at exact double Ft near Fn_guess, or (None, reason).  ksign = -1 gives
    the continuation beyond (Ft)max with theta2'(a) < 0 (unphysical, separate file)."""
    info = {}
    kd = None if ksign > 0 else -sd.kappa_edge(dd, Ft)
    km = None if ksign > 0 else -st.kappa(d, mpf(Ft))
    Fn_d = sd.newton_fn(dd, Ft, Fn_guess, kappa=kd)
    if Fn_d is None:
        Fn_d = Fn_guess
    info["double_jump"] = abs(Fn_d - Fn_guess)
    Fn, g = st.solve_fn(d, Ft, Fn_d, kap=km)
    if Fn is None:
        return None, "ode_no_convergence"
    r = st.shoot_back(d, Fn, Ft, track=True, kap=km)
    r1, r2, pa = st.shoot_forward(d, Fn, Ft, r["theta1p0"])
    if (pa > 0) != (ksign > 0):
        return None, "wrong sign of theta2'(a)"
    info["fwd_res"] = float(max(abs(r1), abs(r2)))
    if info["fwd_res"] > 1e-24:
        return None, "forward_check_failed %.3g" % info["fwd_res"]
    Fn_f, _ = st.solve_fn(d, Ft, Fn, I=st.Integrator(**fine), rtol=mpf("1e-34"), kap=km)
    if Fn_f is None:
        return None, "fine_no_convergence"
    info["fine_diff"] = float(abs(Fn_f - Fn) / max(1, abs(Fn)))
    if info["fine_diff"] > 1e-22:
        return None, "fine_disagrees %.3g" % info["fine_diff"]
    try:
        t1d, t2d = sd.count_turning(dd, float(Fn), Ft, kappa=kd)
    except Exception:
        t1d, t2d = -1, -1
    info["turn_double"] = (t1d, t2d)
    # quadrature route, independent start from the double-precision state
    _, _, beta_d = sd.shoot_back(dd, Fn_d, Ft, kappa=kd)
    route = "ode"
    try:
        qFn, qbeta, qres, qerr = sq.solve(d, Ft, Fn_d, beta_d, r["turn_angles1"], r["turn_angles2"])
        dFn = abs(qFn - Fn) / max(1, abs(Fn))
        db = abs(qbeta - r["beta"])
        info["quad_dFn"], info["quad_dbeta"], info["quad_res"] = float(dFn), float(db), float(qres)
        if dFn <= AGREE and db <= AGREE:
            route = "quad+ode"
        else:
            info["quad_disagree"] = True
    except Exception as e:  # radicand < 0 on the assumed path, singular Jacobian, ...
        info["quad_error"] = repr(e)[:120]
    state = dict(Ft=Ft, Fn=Fn, beta=r["beta"], theta1p0=r["theta1p0"], t1=r["turn1"], t2=r["turn2"],
                 route=route, theta2pa=pa, turn_double=info["turn_double"])
    return (state, info), None


def fn_of_ft(d, dd, Ft, guess):
    Fn_d = sd.newton_fn(dd, float(Ft), guess) or guess
    Fn, _ = st.solve_fn(d, Ft, Fn_d, rtol=mpf("1e-32"))
    return Fn


def refine_min(d, dd, Ft0, Fn_guess, scale):
    """Secant iteration on dFn/dFt = 0 (central differences of the ODE-route Fn(Ft))."""
    h = mpf("1e-10") * scale
    guess = [Fn_guess]

    def deriv(Ft):
        a = fn_of_ft(d, dd, Ft + h, guess[0])
        b = fn_of_ft(d, dd, Ft - h, guess[0])
        guess[0] = float((a + b) / 2)
        return (a - b) / (2 * h)
    x0 = mpf(Ft0)
    x1 = x0 + mpf("1e-4") * scale
    d0, d1 = deriv(x0), deriv(x1)
    for _ in range(30):
        if d1 == d0:
            break
        x2 = x1 - d1 * (x1 - x0) / (d1 - d0)
        x0, d0 = x1, d1
        x1 = x2
        d1 = deriv(x1)
        if abs(x1 - x0) < mpf("1e-19") * scale:
            break
    Fn = fn_of_ft(d, dd, x1, guess[0])
    return x1, Fn


def targets_for(design_id, dd):
    S = f_scale(dd)
    if design_id == 0:
        pos = [0.25 * k for k in range(40)] + [9.9]
        neg = [-0.5, -1.0, -2.0, -3.0]
    else:
        pos = [float(f"{f * S:.12g}") for f in (0.0, 0.15, 0.3, 0.5, 0.7, 0.85, 0.95, 0.99)]
        neg = [float(f"{f * S:.12g}") for f in (-0.1, -0.3)]
    return pos, neg


def crossings(dd, pts, Ft):
    """Guesses (Fn, branch, fold-distance ok) where the tracked contour crosses Ft."""
    tt = sd.tau_of_ft(dd, Ft)
    out = []
    folds = 0
    for k in range(len(pts) - 1):
        if k > 0 and pts[k][3] * pts[k - 1][3] < 0:
            folds += 1
        a, b = pts[k][1] - tt, pts[k + 1][1] - tt
        if a == 0:
            out.append((pts[k][0], folds))
        elif a * b < 0:
            if pts[k][3] * pts[k + 1][3] < 0:
                continue            # fold inside this interval: too close to the fold
            out.append((pts[k][0] + (pts[k + 1][0] - pts[k][0]) * a / (a - b), folds))
    if len(pts) and pts[-1][1] == tt and not out:
        out.append((pts[-1][0], folds))
    return out


def fold_points(dd, pts):
    res = []
    for k in range(1, len(pts)):
        if pts[k][3] * pts[k - 1][3] < 0:
            w = pts[k - 1][3] / (pts[k - 1][3] - pts[k][3])
            tau = pts[k - 1][1] + w * (pts[k][1] - pts[k - 1][1])
            Fn = pts[k - 1][0] + w * (pts[k][0] - pts[k - 1][0])
            res.append((sd.ft_of_tau(dd, tau), Fn))
    return res


def process(job):
    design_id, dd = job
    mp.dps = 30
    t0 = time.time()
    d = st.mp_design(dd)
    S = f_scale(dd)
    Fm = sd.ft_max(dd)
    diag = dict(design_id=design_id, excluded=[])
    Fn0 = sd.natural_state(dd)
    lin = sd.linear_fn0(dd)
    scan = sd.roots_scan(dd, 0.0, lin - max(5.0, 2 * abs(lin)), lin + max(5.0, 2 * abs(lin)), n=120)
    diag["roots_at_Ft0"] = [float(x) for x in scan]
    if Fn0 is None:
        if not scan:
            return design_id, [], None, dict(diag, error="no natural state")
        Fn0 = min(scan, key=lambda x: abs(x - lin))
        diag["natural_from"] = "nearest_root"
    else:
        diag["natural_from"] = "homotopy"
    fn_lim = 10.0 * max(1.0, abs(Fn0), S)
    tau_end = S if math.isinf(Fm) else Fm * math.pi / 2
    pts_f, why_f = sd.track(dd, Fn0, +1, tau_end, fn_lim, 0.03 * S, s_max=12 * S)
    pts_b, why_b = sd.track(dd, Fn0, -1, sd.tau_of_ft(dd, -0.35 * S), fn_lim, 0.03 * S, stop_on_fold=True)
    diag["track"] = [len(pts_f), why_f, len(pts_b), why_b]
    folds = fold_points(dd, pts_f)
    folds_b = fold_points(dd, pts_b)
    diag["folds"] = folds
    diag["folds_neg"] = folds_b
    pos, neg = targets_for(design_id, dd)
    rows = []
    infos = []
    for Fts, pts, fl in ((pos, pts_f, folds), (neg, pts_b, folds_b)):
        for Ft in Fts:
            if any(abs(Ft - f[0]) < 0.01 * S for f in fl):
                diag["excluded"].append((Ft, "near fold"))
                continue
            cr = crossings(dd, pts, Ft) if Ft != 0.0 else [(Fn0, 0)]
            if not cr and Ft != 0.0:
                diag["excluded"].append((Ft, "line does not reach"))
            for Fg, br in cr:
                res, why = polish(d, dd, Ft, Fg, FINE)
                if res is None:
                    diag["excluded"].append((Ft, why))
                    continue
                state, info = res
                if abs(float(state["Fn"]) - Fg) > 0.05 * S:
                    diag["excluded"].append((Ft, "jumped off the tracked branch"))
                    continue
                state["branch"] = br
                rows.append(state)
                infos.append(dict(info, Ft=Ft))
    # continuation past the line end at (Ft)max: theta2'(a) < 0 (interpenetration, unphysical);
    # written to a separate file so that a solver can be checked to reject (or follow) it
    beyond = []
    if not math.isinf(Fm) and why_f == "tau_stop" and not folds:
        tau_hi = Fm * (math.pi - math.asin(0.85))
        p_end = pts_f[-1]
        pts_x, why_x = sd.track(dd, p_end[0], +1, tau_hi, fn_lim, 0.03 * S, stop_on_fold=True, tau0=p_end[1])
        diag["track_beyond"] = [len(pts_x), why_x]
        for fr in (0.99, 0.95, 0.9):
            Ft = float(f"{fr * S:.12g}")
            tt = Fm * (math.pi - math.asin(Ft / Fm))
            for k in range(len(pts_x) - 1):
                a, b = pts_x[k][1] - tt, pts_x[k + 1][1] - tt
                if a * b <= 0 and a != b:
                    Fg = pts_x[k][0] + (pts_x[k + 1][0] - pts_x[k][0]) * a / (a - b)
                    res, why = polish(d, dd, Ft, Fg, FINE, ksign=-1)
                    if res is None:
                        diag["excluded"].append((Ft, "beyond: " + why))
                    elif abs(float(res[0]["Fn"]) - Fg) > 0.05 * S:
                        diag["excluded"].append((Ft, "beyond: jumped off the tracked branch"))
                    else:
                        res[0]["branch"] = 1
                        beyond.append(res[0])
                        infos.append(dict(res[1], Ft=Ft, beyond=True))
                    break
    char = dict(design_id=design_id, Ft_max=Fm, F_scale=S)
    row0 = [r for r in rows if r["Ft"] == 0.0 and r["branch"] == 0]
    char["Fn0"] = row0[0]["Fn"] if row0 else None
    # line end at (Ft)max (theta2'(a) = 0)
    char["Fn_at_Ftmax"] = None
    if not math.isinf(Fm) and why_f == "tau_stop" and not folds:
        p, q = pts_f[-2], pts_f[-1]
        wgt = (tau_end - p[1]) / (q[1] - p[1])
        Fg = p[0] + wgt * (q[0] - p[0])
        Fn_end, _ = st.solve_fn(d, mp.sqrt(2 * d["EA2"] * d["w"]), Fg, kap=0)
        char["Fn_at_Ftmax"] = Fn_end
    # minimum of Fn along the line for Ft in [0, end]
    seq = [p for p in pts_f if p[1] <= tau_end]
    k = int(np.argmin([p[0] for p in seq]))
    char["folds"] = [(float(a), float(b)) for a, b in folds]
    if 0 < k < len(seq) - 1:
        Ft_g = sd.ft_of_tau(dd, seq[k][1])
        Ft_s, Fn_s = refine_min(d, dd, Ft_g, seq[k][0], S)
        char.update(min_Fn=Fn_s, Ft_at_min=Ft_s, min_kind="interior")
    elif k == 0:
        char.update(min_Fn=char["Fn0"], Ft_at_min=mpf(0), min_kind="Ft=0")
    else:
        if char["Fn_at_Ftmax"] is not None:
            char.update(min_Fn=char["Fn_at_Ftmax"], Ft_at_min=mp.sqrt(2 * d["EA2"] * d["w"]), min_kind="line_end")
        else:
            Fn_e = fn_of_ft(d, dd, mpf(S), seq[-1][0])
            char.update(min_Fn=Fn_e, Ft_at_min=mpf(S), min_kind="range_end")
    char["sticky_at_rest"] = None if char["Fn0"] is None else bool(char["Fn0"] < 0)
    diag["seconds"] = time.time() - t0
    diag["infos"] = infos
    diag["beyond"] = beyond
    return design_id, rows, char, diag


def main():
    t_start = time.time()
    designs = [REFERENCE] + random_designs(N_RANDOM, SEED)
    jobs = list(enumerate(designs))
    nproc = int(os.environ.get("SETA_REF_PROCS", "2"))
    results = []
    if nproc > 1:
        with mpc.Pool(nproc) as pool:
            for res in pool.imap_unordered(process, jobs):
                results.append(res)
                print(f"design {res[0]}: {len(res[1])} states, {res[3].get('seconds', 0):.1f} s", flush=True)
    else:
        for j in jobs:
            res = process(j)
            results.append(res)
            print(f"design {res[0]}: {len(res[1])} states, {res[3].get('seconds', 0):.1f} s", flush=True)
    results.sort(key=lambda r: r[0])
    mp.dps = 30
    out_rows = os.path.join(HERE, "seta_reference.csv")
    out_des = os.path.join(HERE, "seta_reference_designs.csv")
    out_meta = os.path.join(HERE, "seta_reference_meta.json")
    stats = dict(states=0, designs=0, with_turning=0, sticky_designs=0, turning_in_sticky=0,
                 states_in_sticky=0, quad_ode=0, ode_only=0, max_quad_dFn=0.0, max_quad_dbeta=0.0,
                 max_fine_diff=0.0, max_fwd_res=0.0, turn_count_mismatch=0, branch_gt0=0, neg_Ft=0)
    with open(out_rows, "w", newline="") as f:
        wr = csv.writer(f, lineterminator="\n")
        wr.writerow(COLUMNS)
        for did, rows, char, diag in results:
            dd = designs[did]
            sticky = bool(char and char.get("sticky_at_rest"))
            for r in rows:
                wr.writerow([did] + [fmt_in(dd[k]) for k in KEYS] +
                            [repr(float(r["Ft"])), nstr(r["Fn"]), nstr(r["beta"]), nstr(r["theta1p0"]),
                             r["t1"], r["t2"], r["branch"], r["route"]])
                stats["states"] += 1
                tp = (r["t1"] + r["t2"]) > 0
                stats["with_turning"] += tp
                stats["states_in_sticky"] += sticky
                stats["turning_in_sticky"] += tp and sticky
                stats["quad_ode"] += r["route"] == "quad+ode"
                stats["ode_only"] += r["route"] == "ode"
                stats["branch_gt0"] += r["branch"] > 0
                stats["neg_Ft"] += r["Ft"] < 0
            for info in diag.get("infos", []):
                stats["max_quad_dFn"] = max(stats["max_quad_dFn"], info.get("quad_dFn", 0.0))
                stats["max_quad_dbeta"] = max(stats["max_quad_dbeta"], info.get("quad_dbeta", 0.0))
                stats["max_fine_diff"] = max(stats["max_fine_diff"], info.get("fine_diff", 0.0))
                stats["max_fwd_res"] = max(stats["max_fwd_res"], info.get("fwd_res", 0.0))
            stats["designs"] += 1 if rows else 0
            stats["sticky_designs"] += sticky
    out_bey = os.path.join(HERE, "seta_reference_beyond_ftmax.csv")
    stats["beyond_states"] = 0
    with open(out_bey, "w", newline="") as f:
        wr = csv.writer(f, lineterminator="\n")
        wr.writerow(COLUMNS + ["theta2p_a"])
        for did, rows, char, diag in results:
            dd = designs[did]
            for r in diag.get("beyond", []):
                wr.writerow([did] + [fmt_in(dd[k]) for k in KEYS] +
                            [repr(float(r["Ft"])), nstr(r["Fn"]), nstr(r["beta"]), nstr(r["theta1p0"]),
                             r["t1"], r["t2"], r["branch"], r["route"], nstr(r["theta2pa"])])
                stats["beyond_states"] += 1
    with open(out_des, "w", newline="") as f:
        wr = csv.writer(f, lineterminator="\n")
        wr.writerow(["design_id"] + KEYS + ["Fn0", "Ft_max", "F_scale", "min_Fn", "Ft_at_min", "min_kind",
                                            "Fn_at_Ftmax", "n_folds", "fold_Ft_approx", "sticky_at_rest"])
        for did, rows, char, diag in results:
            if not char:
                continue
            dd = designs[did]
            wr.writerow([did] + [fmt_in(dd[k]) for k in KEYS] +
                        [nstr(char["Fn0"]), "inf" if math.isinf(char["Ft_max"]) else nstr(mp.sqrt(2 * mpf(dd["EA2"]) * mpf(dd["w"]))),
                         repr(char["F_scale"]), nstr(char["min_Fn"]), nstr(char["Ft_at_min"]), char["min_kind"],
                         nstr(char["Fn_at_Ftmax"]), len(char["folds"]),
                         ";".join(f"{a:.6g}" for a, _ in char["folds"]), int(bool(char["sticky_at_rest"]))])
    diags = []
    for did, rows, char, diag in results:
        for r in rows + diag.get("beyond", []):
            if tuple(r["turn_double"]) != (r["t1"], r["t2"]):
                stats["turn_count_mismatch"] += 1
        dg = {k: v for k, v in diag.items() if k not in ("infos", "beyond")}
        dg["quad_failures"] = [(i["Ft"], i.get("quad_error", "disagree")) for i in diag.get("infos", [])
                               if "quad_error" in i or i.get("quad_disagree")]
        diags.append(dg)
    meta = dict(seed=SEED, n_random=N_RANDOM, fine_settings=FINE, agree=float(AGREE), stats=stats,
                seconds=time.time() - t_start, diagnostics=diags)
    with open(out_meta, "w") as f:
        json.dump(meta, f, indent=1, default=str)
    print(json.dumps(stats, indent=1))
    print(f"total {time.time() - t_start:.0f} s")


if __name__ == "__main__":
    main()
