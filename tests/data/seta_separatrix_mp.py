"""Critical states next to a segment's separatrix in arbitrary precision, by two routes that share
nothing with the C++ solver (docs/theory/two_level_seta.md, "Long segments").

A segment many elastic lengths long passes the saddle of its first integral at the distance
delta = R(1) = M - N - c N^2/2 ~ exp(-l sqrt(N (1 + c N)/EI)); its state is fixed by delta to all digits, so a
solver in (Fn, beta) must carry delta's digits in Fn or beta. Both routes here do.

  * "quad": the length equations of seta_quad.py (tanh-sinh quadrature of dtheta/|theta'| split at
    the turning angles), with each long segment's unknown replaced by log(-delta) (a libration,
    delta < 0) or log(delta) (a rotation past the saddle, delta > 0): the
    spatula's delta2 = Ft + w - N - c2 N^2/2 gives N and so Fn; the beam's delta1 gives beta as the
    root of M1(beta) = N + c1 N^2/2 + delta1 (M1 of paper 001 eq (12)). Newton in (log(-delta2) or
    Fn, log(-delta1) or beta) at mp.dps = 40 + the segments' elastic lengths / 2.
  * "shoot": seta_taylor.py's fixed-point Taylor integration, the spatula shot back from the contact
    edge and the beam forward from the base with the state's theta1'(0), matched at the joint
    (theta1 + alpha2 = theta2, EI1 theta1' = EI2 theta2') by Newton in (Fn, theta1'(0)). The shots
    amplify an error by exp(elastic lengths), so only states up to about 40 of them in all.
  * "bracket": seta_taylor.py's backward shot alone, from the contact edge to the base, at a
    precision that covers its amplification: its residual g(Fn) = theta1(0) - alpha1 at fixed Ft
    is continuous in Fn, so a sign change on both sides of the state's Fn proves a root between;
    bisected, the root's beta, base rate and turning points are compared with the state's. No
    first integral and no path class is assumed (the quad route assumes one: a long segment with
    turning points librates, one without rotates, and it can converge to another path's root).

Elastic lengths are counted in the saddle's time constant, l sqrt(N (1 + N/EA) / EI)
(saddle_lengths): delta ~ exp(-that), and a shot amplifies by about as much.

The start (Fn, beta, the rates' signs, the turning points) is the state to be checked: it picks the
branch; the value is the routes' own. Used by gen_seta_separatrix_reference.py.
"""
import math
import os
import sys

from mpmath import mp, mpf, matrix, lu_solve

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seta_quad as sq    # noqa: E402
import seta_taylor as st  # noqa: E402


def _c(EA):
    return mpf(0) if EA == mp.inf or EA == math.inf else 1 / mpf(EA)


def _turn_guesses(M, N, c, phi, th_start, rising, count):
    """The first `count` turning angles met from th_start, theta rising first if `rising`."""
    roots = [u for u in sq._roots_u(M, N, c) if abs(u) <= 1]
    if not roots or count == 0:
        return []
    a = mp.asin(roots[0])
    out, th = [], th_start
    for _ in range(count):
        if rising:  # next maximum phi + a + 2 pi k above th
            k = mp.ceil((th - phi - a) / (2 * mp.pi))
            th = phi + a + 2 * mp.pi * k
        else:       # next minimum phi + pi - a + 2 pi k below th
            k = mp.floor((th - phi - mp.pi + a) / (2 * mp.pi))
            th = phi + mp.pi - a + 2 * mp.pi * k
        out.append(th)
        rising = not rising
    return out


def _seg_length(EI, M, N, c, phi, th_start, th_end, turns):
    """seta_quad.seg_length, with a path without turning points split where it crosses the saddle
    theta = phi + pi/2 (mod 2 pi): next to a separatrix the integrand peaks there with a width of
    sqrt(delta), which tanh-sinh resolves at an end of its interval, not inside it."""
    if turns:
        return sq.seg_length(EI, M, N, c, phi, th_start, th_end, turns)
    lo, hi = (th_start, th_end) if th_start < th_end else (th_end, th_start)
    k0 = mp.ceil((lo - phi - mp.pi / 2) / (2 * mp.pi))
    cuts = [lo]
    k = k0
    while phi + mp.pi / 2 + 2 * mp.pi * k < hi:
        cuts.append(phi + mp.pi / 2 + 2 * mp.pi * k)
        k += 1
    cuts.append(hi)
    total, errt = mpf(0), mpf(0)
    for a, b in zip(cuts[:-1], cuts[1:]):
        if b > a:
            v, e = sq._piece_regular(EI, M, N, c, phi, a, b)
            total += v
            errt += e
    return total, errt


def quad_route(d, Ft, Fn0, beta0, sign_p, sign_q, turns, long_seg, iterations=40, rotation=(False, False)):
    """d: design (floats, inf allowed); long_seg = (beam_long, spatula_long); turns = (beam, spatula);
    rotation: which long segments are rotations (delta > 0), the others librations (delta < 0).
    Returns (Fn, beta, residual, quadrature error estimate) in mp, or None."""
    side = [1 if r else -1 for r in rotation]  # the sign of delta of each long segment
    dm = {k: (mp.inf if v == math.inf else mpf(v)) for k, v in d.items()}
    c1, c2 = _c(d["EA1"]), _c(d["EA2"])
    Ft = mpf(Ft)
    M2 = Ft + dm["w"]
    sgn_fn = 1 if Fn0 >= 0 else -1

    def Fn_of(a):
        if not long_seg[1]:
            return a
        delta2 = side[1] * mp.exp(a)
        m = M2 - delta2
        N = m if c2 == 0 else 2 * m / (1 + mp.sqrt(1 + 2 * c2 * m))
        return sgn_fn * mp.sqrt((N - Ft) * (N + Ft))

    def beta_of(b, Fn, guess):
        if not long_seg[0]:
            return b
        N = mp.sqrt(Fn * Fn + Ft * Ft)
        phi = mp.atan2(Fn, Ft)
        target = N + c1 * N * N / 2 + side[0] * mp.exp(b)

        def g(beta):
            v = mp.sin(beta - dm["alpha2"] - phi)
            return dm["EI2"] / dm["EI1"] * sq._R(M2, N, c2, phi, beta) + N * v + c1 * N * N * v * v / 2 - target
        return mp.findroot(g, guess, tol=mpf(10) ** (-mp.dps + 5))

    def lengths(x, beta_guess):
        Fn = Fn_of(x[0])
        beta = beta_of(x[1], Fn, beta_guess)
        N = mp.sqrt(Fn * Fn + Ft * Ft)
        phi = mp.atan2(Fn, Ft)
        v = mp.sin(beta - dm["alpha2"] - phi)
        M1 = dm["EI2"] / dm["EI1"] * sq._R(M2, N, c2, phi, beta) + N * v + N * N * v * v * c1 / 2
        t1 = _turn_guesses(M1, N, c1, phi, dm["alpha1"], sign_q > 0, turns[0])
        t2 = _turn_guesses(M2, N, c2, phi, beta, sign_p > 0, turns[1])
        L1, e1 = _seg_length(dm["EI1"], M1, N, c1, phi, dm["alpha1"], beta - dm["alpha2"], t1)
        L2, e2 = _seg_length(dm["EI2"], M2, N, c2, phi, beta, mp.pi / 2, t2)
        err[0] = max(err[0], e1, e2)
        return [L1 - dm["l1"], L2 - dm["l2"]], Fn, beta

    # Start: the logarithms from the state's elastic lengths (Newton finds them: the lengths are
    # linear in log|delta| there), the natural unknowns from the state.
    N0 = math.hypot(Fn0, Ft)
    x = [mpf(0), mpf(0)]
    x[0] = mp.log(M2 + N0) - d["l2"] * math.sqrt(N0 / d["EI2"]) if long_seg[1] else mpf(Fn0)
    x[1] = mp.log(M2 + N0) - d["l1"] * math.sqrt(N0 / d["EI1"]) if long_seg[0] else mpf(beta0)
    beta_guess = mpf(beta0)
    h = mpf(10) ** (-mp.dps // 2)
    err = [mpf(0)]
    for _ in range(iterations):
        f, Fn, beta = lengths(x, beta_guess)
        beta_guess = beta
        J = matrix(2, 2)
        for j in range(2):
            y = list(x)
            hj = h * max(1, abs(x[j]))
            y[j] += hj
            fj, _, _ = lengths(y, beta_guess)
            for i in range(2):
                J[i, j] = (fj[i] - f[i]) / hj
        dx = lu_solve(J, matrix(f))
        # log(-delta) steps of at most 8 (the start may be far off)
        scale = max(1, max(abs(dx[0]), abs(dx[1])) / 8) if any(long_seg) else 1
        x = [x[0] - dx[0] / scale, x[1] - dx[1] / scale]
        if scale == 1 and abs(dx[0]) < mpf(10) ** (-mp.dps // 2 - 5) * max(1, abs(x[0])) and \
                abs(dx[1]) < mpf(10) ** (-mp.dps // 2 - 5) * max(1, abs(x[1])):
            err[0] = mpf(0)
            f, Fn, beta = lengths(x, beta_guess)
            return Fn, beta, max(abs(f[0]), abs(f[1])), err[0]
    return None


def shoot_route(d, Ft, Fn0, q0, bits=224):
    """Joint matching of the two shots; returns (Fn, beta) in mp, or None."""
    I = st.Integrator(prec=bits, tol_bits=bits - 24, order=40)
    dm = st.mp_design(d)
    with mp.workprec(I.mprec):
        Ft = mpf(Ft)

        def residual(Fn, q):
            f = st.design_fixed(I, dm, Fn, Ft)
            th, p, S, C = I.fix(mp.pi / 2), I.fix(st.kappa(dm, Ft)), 1 << I.P, 0
            th, p, S, C, _ = I.segment(th, p, S, C, -I.fix(dm["l2"]), f["Fn"], f["Ft"], f["c2"], f["i2"],
                                       I.fix(0.125), None)
            beta, p2 = I.unfix(th), I.unfix(p)
            a1 = dm["alpha1"]
            th, p, S, C = I.fix(a1), I.fix(q), I.fix(mp.sin(a1)), I.fix(mp.cos(a1))
            th, p, S, C, _ = I.segment(th, p, S, C, I.fix(dm["l1"]), f["Fn"], f["Ft"], f["c1"], f["i1"],
                                       I.fix(0.125), None)
            return [I.unfix(th) + dm["alpha2"] - beta, dm["EI1"] * I.unfix(p) - dm["EI2"] * p2], beta

        x = [mpf(Fn0), mpf(q0)]
        h = mpf(2) ** (-bits // 2)
        tol = mpf(2) ** (-bits // 3)
        for _ in range(12):
            f, beta = residual(*x)
            J = matrix(2, 2)
            for j in range(2):
                y = list(x)
                hj = h * max(1, abs(x[j]))
                y[j] += hj
                fj, _ = residual(*y)
                for i in range(2):
                    J[i, j] = (fj[i] - f[i]) / hj
            dx = lu_solve(J, matrix(f))
            x = [x[0] - dx[0], x[1] - dx[1]]
            if abs(dx[0]) < tol * max(1, abs(x[0])) and abs(dx[1]) < tol * max(1, abs(x[1])):
                return x[0], residual(*x)[1]
    return None


def saddle_lengths(d, N):
    """Each segment's length in units of its saddle's time constant, l sqrt(N (1 + N/EA) / EI)
    (gecko/seta/detail/separatrix_limit.hpp, separatrix_measures): delta ~ exp(-that), and a shot
    through the segment amplifies its start's error by about as much. Elementwise for numpy arrays
    of designs and N as well (validation/admissibility_mp.py picks its deep states with it)."""
    def one(l, EI, EA):
        c = 1.0 / EA  # 0 for EA = inf
        return l * (N * (1 + c * N) / EI) ** 0.5
    return one(d["l1"], d["EI1"], d["EA1"]), one(d["l2"], d["EI2"], d["EA2"])


def _bracket(d, Ft, Fn, length, span_rel):
    """The shot at the precision `length` needs (128 + 1.5 length bits: its amplification, about
    e^length = 2^(1.44 length), with 100 bits to spare) and the bracket Fn -+ span_rel max(1, |Fn|)
    with both ends shot: (shoot, lo, hi, end shots). shoot(x, track) returns (g, shot) with
    g = theta1(0) - alpha1; call it inside mp.workprec(shoot.prec)."""
    bits = 128 + int(1.5 * length)
    I = st.Integrator(prec=bits, tol_bits=bits - 20)
    dm = st.mp_design(d)

    def shoot(x, track=False, heights=False):
        r = st.shoot_back(dm, x, Ft, I, track=track, heights=heights)
        return r["theta10"] - dm["alpha1"], r

    shoot.prec = I.mprec
    with mp.workprec(I.mprec):
        span = mpf(span_rel) * max(1, abs(Fn))
        lo, hi = mpf(Fn) - span, mpf(Fn) + span
        return shoot, lo, hi, (shoot(lo), shoot(hi))


def _sign_change(ga, gb):
    return ga == 0 or gb == 0 or (ga > 0) != (gb > 0)


def bracket_route(d, Ft, Fn, length, span_rel=1e-11, halvings=None, heights=False):
    """The root of the backward shot's residual g(Fn) = theta1(0) - alpha1 at fixed Ft between
    Fn -+ span_rel max(1, |Fn|), where g changes sign there (g is continuous in Fn, so a root lies
    between), bisected `halvings` times: dict(Fn, beta, q = theta1'(0), turns = (beam, spatula)),
    in mp. None where g has one sign at both ends (the route decides nothing). `length`: both
    segments in saddle time constants (saddle_lengths; the precision follows it, see _bracket).
    The shot's path (its turning points, its base rate) is that of the root only within about
    e^-length of it, so the default bisects 40 + 1.5 length times. heights: also min_z, the lowest
    height of the seta on that shot (seta_taylor.shoot_back), which holds it on the root's path to
    about e^-length as well."""
    if halvings is None:
        halvings = 40 + int(1.5 * length)
    shoot, lo, hi, ((glo, _), (ghi, _)) = _bracket(d, Ft, Fn, length, span_rel)
    if not _sign_change(glo, ghi):
        return None
    with mp.workprec(shoot.prec):
        for _ in range(halvings):
            mid = (lo + hi) / 2
            gm = shoot(mid)[0]
            if (gm > 0) == (glo > 0):
                lo, glo = mid, gm
            else:
                hi = mid
        mid = (lo + hi) / 2
        r = shoot(mid, track=True, heights=heights)[1]
        out = dict(Fn=mid, beta=r["beta"], q=r["theta1p0"], turns=(r["turn1"], r["turn2"]))
        if heights:
            out["min_z"] = r["min_z"]
        return out


def bracket_ends(d, Ft, Fn, length, span_rel=1e-11):
    """The two shots of bracket_route alone, without the bisection (which costs 40 + 1.5 length
    shots): whether the residual changes sign between Fn -+ span_rel max(1, |Fn|) (then a root
    lies there, within span_rel of Fn), and beta at both ends (the spatula's shot from the contact
    edge; if both are within 1e-11 of a state's beta, so is the root's, up to beta's variation
    over the bracket, which the two ends show). The path at the root (its turning points) is not
    known this way: a segment that long has paths with loops more or fewer whose Fn and beta agree
    to O(delta). For segments whose bisection would take too long."""
    _, _, _, ((glo, rlo), (ghi, rhi)) = _bracket(d, Ft, Fn, length, span_rel)
    return dict(sign_change=bool(_sign_change(glo, ghi)), beta=(rlo["beta"], rhi["beta"]))
