"""Quadrature route of the seta reference generator: the two length equations of docs/theory/two_level_seta.md
("First integrals", "Lengths"; paper eqs 8-15) at the critical state a = l1 + l2, solved for
(Fn, beta = theta2(l1)) by a 2-D Newton iteration in mpmath (mp.dps = 30, tanh-sinh quadrature).

    1/2 EI_i theta'^2 = R_i(theta) = M_i - N u - N^2 u^2 c_i / 2,   u = sin(theta - phi)
    M2 = Ft + w
    M1 = (EI2/EI1) R2(beta) + N v + N^2 v^2 c1 / 2,   v = sin(beta - alpha2 - phi)
    l2 = int_{beta}^{pi/2} dtheta / |theta2'|,   l1 = int_{alpha1}^{beta - alpha2} dtheta / |theta1'|

This is independent of the ODE route (no integration of the elastica in s) and of the C++ solver
(no Carlson R_F, no closed form).  Where a segment has turning points (theta' = 0 inside, known
from the ODE route), the angle path of the segment is split at the turning angles theta*, which are
recomputed for every (Fn, beta) from the closed-form roots u* of R(u) = 0, and each piece is
integrated in the distance delta = |theta - theta*| from the turning angle with R written in the
factorised form R = N (u* - u) (c = 0) or R = (c N^2/2)(u* - u)(u - u**), where
u* - u = 2 cos((theta* + theta)/2 - phi) sin((theta* - theta)/2) has no cancellation; the
substitution delta = t^2 removes the 1/sqrt(delta) endpoint singularity.
"""
from mpmath import mp, mpf

DPS = 30


def _consts(d):
    c1 = 0 if d["EA1"] == mp.inf else 1 / d["EA1"]
    c2 = 0 if d["EA2"] == mp.inf else 1 / d["EA2"]
    return c1, c2


def _R(M, N, c, phi, th):
    u = mp.sin(th - phi)
    return M - N * u - N * N * u * u * c / 2


def _roots_u(M, N, c):
    if c == 0:
        return [M / N]
    disc = N * N + 2 * c * N * N * M
    if disc < 0:
        return []
    sq = mp.sqrt(disc)
    r1 = 2 * M / (N + sq)                      # root that tends to M/N as c -> 0 (no cancellation)
    r2 = (-N - sq) / (c * N * N)
    return [r1, r2]


def turning_angle(M, N, c, phi, guess):
    """Exact turning angle (R = 0) nearest to the rough guess; returns (theta*, u*, u**)."""
    roots = _roots_u(M, N, c)
    best = None
    for i, u in enumerate(roots):
        if abs(u) > 1:
            continue
        base = mp.asin(u)
        for th0 in (phi + base, phi + mp.pi - base):
            k = mp.nint((guess - th0) / (2 * mp.pi))
            th = th0 + 2 * mp.pi * k
            if best is None or abs(th - guess) < abs(best[0] - guess):
                other = roots[1 - i] if len(roots) == 2 else None
                best = (th, u, other)
    if best is None:
        raise ValueError("no turning angle")
    return best


def _piece_regular(EI, M, N, c, phi, ta, tb):
    lo, hi = (ta, tb) if ta < tb else (tb, ta)
    f = lambda th: 1 / mp.sqrt(2 * _R(M, N, c, phi, th) / EI)
    v, err = mp.quad(f, [lo, hi], error=True, maxdegree=10)
    return v, err


def _piece_turning(EI, M, N, c, phi, tstar, ustar, uother, tend):
    """Integral from the turning angle tstar to tend (|tend - tstar|), singular at tstar.
    With delta = t^2 the 1/sqrt(delta) singularity disappears: dtheta/|theta'| = 2 t dt / |theta'|
    = 2 dt / sqrt(2 (R/t^2) / EI), and R/t^2 is evaluated from the factorised form without
    cancellation (tanh-sinh alone truncates its node sum too early for a singular integrand)."""
    sig = 1 if tend > tstar else -1
    T = mp.sqrt(abs(tend - tstar))

    def f(t):
        t2 = t * t
        s_over = mp.sin(t2 / 2) / t2 if t2 != 0 else mpf(1) / 2
        du = 2 * mp.cos(tstar - phi + sig * t2 / 2) * (-sig) * s_over          # (u* - u) / t^2
        if c == 0:
            R = N * du
        else:
            u = mp.sin(tstar + sig * t2 - phi)
            R = c * N * N / 2 * du * (u - uother)
        return 2 / mp.sqrt(2 * R / EI)
    v, err = mp.quad(f, [0, T], error=True, maxdegree=10)
    return v, err


def seg_length(EI, M, N, c, phi, th_start, th_end, turn_guesses):
    """Length of a segment whose angle goes th_start -> turning angles (in order) -> th_end."""
    if not turn_guesses:
        return _piece_regular(EI, M, N, c, phi, th_start, th_end)
    ts = [turning_angle(M, N, c, phi, g) for g in turn_guesses]
    total, errt = mpf(0), mpf(0)
    v, e = _piece_turning(EI, M, N, c, phi, ts[0][0], ts[0][1], ts[0][2], th_start)
    total += v
    errt += e
    for (ta, ua, oa), (tb, ub, ob) in zip(ts[:-1], ts[1:]):
        mid = (ta + tb) / 2
        for t, u, o in ((ta, ua, oa), (tb, ub, ob)):
            v, e = _piece_turning(EI, M, N, c, phi, t, u, o, mid)
            total += v
            errt += e
    v, e = _piece_turning(EI, M, N, c, phi, ts[-1][0], ts[-1][1], ts[-1][2], th_end)
    return total + v, errt + e


def lengths(d, Fn, beta, Ft, turns1=(), turns2=()):
    c1, c2 = _consts(d)
    N = mp.sqrt(Fn * Fn + Ft * Ft)
    phi = mp.atan2(Fn, Ft)
    M2 = Ft + d["w"]
    v = mp.sin(beta - d["alpha2"] - phi)
    M1 = d["EI2"] / d["EI1"] * _R(M2, N, c2, phi, beta) + N * v + N * N * v * v * c1 / 2
    L2, e2 = seg_length(d["EI2"], M2, N, c2, phi, beta, mp.pi / 2, list(turns2))
    L1, e1 = seg_length(d["EI1"], M1, N, c1, phi, d["alpha1"], beta - d["alpha2"], list(turns1))
    return L1, L2, max(e1, e2)


def solve(d, Ft, Fn0, beta0, turns1=(), turns2=(), maxit=12):
    """2-D Newton (forward-difference Jacobian) on (l1 - L1, l2 - L2). Returns (Fn, beta, |res|, qerr)."""
    with mp.workdps(DPS):
        Ft = mpf(Ft)
        x = [mpf(Fn0), mpf(beta0)]

        def F(x):
            L1, L2, e = lengths(d, x[0], x[1], Ft, turns1, turns2)
            for L in (L1, L2):
                if not isinstance(L, type(mpf(0))):
                    raise ValueError("complex length: radicand < 0 (state not of the assumed shape)")
            return [L1 - d["l1"], L2 - d["l2"]], e
        r, e = F(x)
        for _ in range(maxit):
            h = [mpf("1e-13") * max(1, abs(x[0])), mpf("1e-13")]
            J = [[0, 0], [0, 0]]
            for j in range(2):
                xp = list(x)
                xp[j] += h[j]
                rp, _ = F(xp)
                for i in range(2):
                    J[i][j] = (rp[i] - r[i]) / h[j]
            det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
            dx0 = (r[0] * J[1][1] - r[1] * J[0][1]) / det
            dx1 = (J[0][0] * r[1] - J[1][0] * r[0]) / det
            x = [x[0] - dx0, x[1] - dx1]
            r, e = F(x)
            if abs(dx0) < mpf("1e-26") * max(1, abs(x[0])) and abs(dx1) < mpf("1e-26"):
                break
        return x[0], x[1], max(abs(r[0]), abs(r[1])), e
