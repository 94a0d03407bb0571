"""Double-precision stage of the seta reference generator (see gen_seta_reference.py).

Only used to *find* critical states (initial guesses, continuation along the critical line); every
number that is written to the reference files is re-computed by the mpmath routes in
seta_taylor.py (ODE shooting) and seta_quad.py (first-integral quadrature).

The critical line is the zero set of the scalar function

    g(Fn, Ft) = theta1(0; Fn, Ft) - alpha1

where theta1(0) comes from integrating the elastica (docs/theory/two_level_seta.md, eqs 1-5) *backwards* from the
contact edge s = a = l1 + l2, at which every condition is known (theta2(a) = pi/2 and, from
Griffith's condition with theta2'(a) > 0, theta2'(a) = kappa(Ft) = sqrt(2 (w - Ft^2/(2 EA2)) / EI2)),
through the joint (theta1 = theta2 - alpha2, EI1 theta1' = EI2 theta2') down to the base.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp


def design_consts(d):
    c1 = 0.0 if math.isinf(d["EA1"]) else 1.0 / d["EA1"]
    c2 = 0.0 if math.isinf(d["EA2"]) else 1.0 / d["EA2"]
    return c1, c2


def ft_max(d):
    return math.inf if math.isinf(d["EA2"]) else math.sqrt(2.0 * d["EA2"] * d["w"])


def kappa_edge(d, Ft):
    """theta2'(a) from Griffith's condition, positive root (contact on the side theta < pi/2)."""
    c2 = design_consts(d)[1]
    r = 2.0 * (d["w"] - 0.5 * c2 * Ft * Ft) / d["EI2"]
    return math.sqrt(max(r, 0.0))


def _rhs(EI, c, Fn, Ft):
    def f(s, y):
        st, ct = math.sin(y[0]), math.cos(y[0])
        return [y[1], -(Fn * st + Ft * ct) * (1.0 + c * (Ft * st - Fn * ct)) / EI]
    return f


def shoot_back(d, Fn, Ft, dense=False, rtol=1e-12, atol=1e-13, kappa=None):
    """Backward shot; returns (theta1(0), theta1'(0), joint angle beta, [sol2, sol1] if dense)."""
    c1, c2 = design_consts(d)
    l1, l2 = d["l1"], d["l2"]
    a = l1 + l2
    k = kappa_edge(d, Ft) if kappa is None else kappa
    s2 = solve_ivp(_rhs(d["EI2"], c2, Fn, Ft), (a, l1), [math.pi / 2, k], method="DOP853",
                   rtol=rtol, atol=atol, dense_output=dense)
    beta, p2 = s2.y[0, -1], s2.y[1, -1]
    s1 = solve_ivp(_rhs(d["EI1"], c1, Fn, Ft), (l1, 0.0), [beta - d["alpha2"], d["EI2"] * p2 / d["EI1"]],
                   method="DOP853", rtol=rtol, atol=atol, dense_output=dense)
    out = (s1.y[0, -1], s1.y[1, -1], beta)
    if dense:
        out = out + ((s2, s1),)
    return out


def g_res(d, Fn, Ft, kappa=None):
    return shoot_back(d, Fn, Ft, kappa=kappa)[0] - d["alpha1"]


def count_turning(d, Fn, Ft, n=400, kappa=None):
    """Sign changes of theta' inside each segment (ends included in the sampled sequence), double."""
    _, _, _, (s2, s1) = shoot_back(d, Fn, Ft, dense=True, kappa=kappa)
    l1, l2 = d["l1"], d["l2"]
    res = []
    for sol, lo, hi in ((s1, 0.0, l1), (s2, l1, l1 + l2)):
        s = np.linspace(lo, hi, n + 1)
        p = sol.sol(s)[1]
        sg = np.sign(p)
        sg = sg[sg != 0]
        res.append(int(np.sum(sg[1:] != sg[:-1])))
    return tuple(res)


def linear_fn0(d):
    """Small-deformation (Fn)0 from docs/theory/two_level_seta.md eq 18 with Ft = 0 (qualitative only)."""
    EI1, EI2, l1, l2, w = d["EI1"], d["EI2"], d["l1"], d["l2"], d["w"]
    a1, a2 = d["alpha1"], d["alpha2"]
    Meq = math.sqrt(2 * EI2 * w)
    rhs = math.pi / 2 - (a1 + a2) - Meq * l2 / EI2 - Meq * l1 / EI1
    sP, sQ = math.sin(a1 + a2), math.sin(a1)
    coef = sP * l2 * l2 / (2 * EI2) + sQ * l1 * l1 / (2 * EI1) + sP * l2 * l1 / EI1
    return rhs / coef


def newton_fn(d, Ft, Fn0, tol=1e-12, maxit=30, kappa=None):
    """Secant iteration on g(., Ft) in Fn from Fn0; returns Fn or None."""
    x0 = Fn0
    h = 1e-6 * max(1.0, abs(Fn0))
    x1 = Fn0 + h
    g0, g1 = g_res(d, x0, Ft, kappa), g_res(d, x1, Ft, kappa)
    for _ in range(maxit):
        if g1 == g0:
            break
        x2 = x1 - g1 * (x1 - x0) / (g1 - g0)
        x0, g0 = x1, g1
        x1, g1 = x2, g_res(d, x2, Ft, kappa)
        if abs(x1 - x0) < tol * max(1.0, abs(x1)):
            return x1 if abs(g1) < 1e-9 else None
    return None


# ----------------------------------------------------------------------------------------------
# Continuation along the critical line: the zero contour of g in the (Fn, tau) plane, where
# Ft = Ftmax sin(tau / Ftmax) for finite EA2 (so that the edge curvature kappa ~ cos(tau/Ftmax)
# is smooth through Ft = (Ft)max) and Ft = tau for EA2 = inf.  Pseudo-arclength predictor along
# the contour tangent, chord-Newton corrector along the normal.
# ----------------------------------------------------------------------------------------------

def ft_of_tau(d, tau):
    Fm = ft_max(d)
    return tau if math.isinf(Fm) else Fm * math.sin(tau / Fm)


def tau_of_ft(d, Ft):
    Fm = ft_max(d)
    return Ft if math.isinf(Fm) else Fm * math.asin(Ft / Fm)


def kappa_of_tau(d, tau):
    """Edge curvature continued smoothly through Ft = (Ft)max (negative beyond: unphysical)."""
    Fm = ft_max(d)
    k0 = math.sqrt(2.0 * d["w"] / d["EI2"])
    return k0 if math.isinf(Fm) else k0 * math.cos(tau / Fm)


def _g2(d, z):
    return g_res(d, z[0], ft_of_tau(d, z[1]), kappa_of_tau(d, z[1]))


def _grad(d, z):
    out = np.empty(2)
    for i in range(2):
        h = 1e-6 * max(1.0, abs(z[i]))
        zp, zm = np.array(z, float), np.array(z, float)
        zp[i] += h
        zm[i] -= h
        out[i] = (_g2(d, zp) - _g2(d, zm)) / (2 * h)
    return out


def track(d, Fn0, direction, tau_stop, fn_limit, ds_max, max_pts=1500, stop_on_fold=False, s_max=math.inf,
          tau0=0.0):
    """Follow the contour from (Fn0, tau=0) with d(tau)/ds having the sign of `direction` at the
    start, until tau crosses tau_stop (signed), |Fn| > fn_limit, the arclength exceeds s_max,
    max_pts, or (stop_on_fold) d(tau)/ds changes sign.  Returns the list of
    points (Fn, tau, t_Fn, t_tau) and the reason it stopped."""
    z = np.array([Fn0, tau0])
    gr = _grad(d, z)
    t = np.array([gr[1], -gr[0]])
    t /= np.linalg.norm(t)
    if t[1] * direction < 0:
        t = -t
    pts = [(z[0], z[1], t[0], t[1])]
    ds = ds_max / 4
    arc = 0.0
    reason = "max_pts"
    while len(pts) < max_pts:
        ok = False
        for _ in range(30):
            zp = z + ds * t
            n = _grad(d, zp)
            nn = np.dot(n, n)
            zc = zp.copy()
            conv = False
            for it in range(8):
                gz = _g2(d, zc)
                stepn = gz / nn * n
                zc = zc - stepn
                # distance to the contour, not |g|: g can be steep (|grad g| ~ 1e3)
                if np.linalg.norm(stepn) < 1e-10 * max(1.0, np.linalg.norm(zc)):
                    conv = True
                    break
            if conv and np.linalg.norm(zc - zp) < 0.5 * ds:
                gr = _grad(d, zc)
                tn = np.array([gr[1], -gr[0]])
                tn /= np.linalg.norm(tn)
                if np.dot(tn, t) < 0:
                    tn = -tn
                if np.dot(tn, t) > math.cos(0.2):
                    ok = True
                    break
            ds /= 2
            if ds < 1e-9 * ds_max:
                break
        if not ok:
            reason = "corrector_failed"
            break
        arc += np.linalg.norm(zc - z)
        z, t = zc, tn
        pts.append((z[0], z[1], t[0], t[1]))
        if stop_on_fold and pts[-1][3] * pts[-2][3] < 0:
            reason = "fold"
            break
        if arc > s_max:
            reason = "s_max"
            break
        if direction > 0 and z[1] >= tau_stop or direction < 0 and z[1] <= tau_stop:
            reason = "tau_stop"
            break
        if abs(z[0]) > fn_limit:
            reason = "fn_limit"
            break
        if it <= 2:
            ds = min(ds * 1.5, ds_max)
    return pts, reason


def natural_state(d):
    """Critical Fn at Ft = 0 on the natural branch, by homotopy from the small-deformation limit:
    design(lam) has alpha2 + (1 - lam)(pi/2 - alpha1 - alpha2) and w lam^2, so that as lam -> 0 the
    required rotation and the adhesion moment both vanish like lam and paper 001 eq 18 (docs/theory/two_level_seta.md) becomes
    exact; the root in Fn is followed from lam = 1e-3 (started from eq 18) to lam = 1."""
    Delta = math.pi / 2 - d["alpha1"] - d["alpha2"]

    def dl(lam):
        e = dict(d)
        e["alpha2"] = d["alpha2"] + (1 - lam) * Delta
        e["w"] = d["w"] * lam * lam
        return e
    lam = 1e-3
    Fn = newton_fn(dl(lam), 0.0, linear_fn0(dl(lam)))
    if Fn is None:
        return None
    hist = [(lam, Fn)]
    step = 0.5e-3
    while lam < 1.0:
        lam_n = min(1.0, lam + step)
        if len(hist) >= 2:
            (l0, f0), (l1_, f1) = hist[-2], hist[-1]
            pred = f1 + (f1 - f0) / (l1_ - l0) * (lam_n - l1_)
        else:
            pred = Fn * lam_n / lam
        Fn_n = newton_fn(dl(lam_n), 0.0, pred)
        if Fn_n is None or abs(Fn_n - pred) > 0.05 * (abs(Fn_n - Fn) + 1e-3):
            step /= 2
            if step < 1e-7:
                return None
            continue
        lam, Fn = lam_n, Fn_n
        hist.append((lam, Fn))
        step = min(step * 1.6, 0.05)
    return Fn


def roots_scan(d, Ft, lo, hi, n=200):
    """All sign changes of g(., Ft) on [lo, hi] (diagnostic for the homotopy)."""
    xs = np.linspace(lo, hi, n + 1)
    gs = [g_res(d, x, Ft) for x in xs]
    out = []
    for i in range(n):
        if gs[i] * gs[i + 1] < 0:
            r = newton_fn(d, Ft, xs[i] - gs[i] * (xs[i + 1] - xs[i]) / (gs[i + 1] - gs[i]))
            if r is not None:
                out.append(r)
    return out
