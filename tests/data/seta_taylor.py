"""ODE route of the seta reference generator: arbitrary-precision Taylor-series shooting of the
elastica of docs/theory/two_level_seta.md (governing equations, paper eqs 1-5), NOT its first integrals.

Per segment (EI, c = 1/EA, c = 0 for EA = inf):

    theta'' = -(Fn sin theta + Ft cos theta) (1 + c T) / EI,   T = Ft sin theta - Fn cos theta

Method: Taylor series of order K about each step start; the coefficients of theta, sin theta,
cos theta come from the exact recurrences  k S_k = sum_j j theta_j C_{k-j},
k C_k = -sum_j j theta_j S_{k-j}  (S' = C theta', C' = -S theta'), so sin/cos are propagated with
the series and only evaluated (by mpmath) at a segment start.  All arithmetic is binary fixed point
on Python integers with PREC fractional bits (default 124 bits, about 37 digits), which is ~12x
faster than mpmath mpf arithmetic at the same precision.  Step size: the largest step for which the
last two scaled coefficients |theta_{K-1} h^{K-1}|, |theta_K h^K| stay below TOL (Jorba-Zou
control); steps land exactly on s = l1 and s = a.

Shooting:
  * backward (used to solve): start at the contact edge s = a with theta2 = pi/2,
    theta2' = +sqrt(2 (w - Ft^2/(2 EA2)) / EI2), cross the joint (theta1 = theta2 - alpha2,
    EI1 theta1' = EI2 theta2'), integrate to s = 0; residual g(Fn) = theta1(0) - alpha1.
  * forward (used to verify, the formulation of the brief): start at s = 0 with theta1 = alpha1 and
    the theta1'(0) of the backward shot, integrate to s = a, residuals theta2(a) - pi/2 and
    1/2 EI2 theta2'(a)^2 + Ft^2/(2 EA2) - w.
Turning points (sign changes of theta' strictly inside a segment) are counted by sampling the
derivative polynomial of every step at 16 interior points (plus the step ends).
"""
import math

from mpmath import mp, mpf, libmp

PREC = 124
TOL_BITS = 106      # |last scaled coefficients| < 2^-106 ~ 1.2e-32
ORDER = 40


def _scaled(H, r):
    """int(H * r) for a fixed-point step H and a float factor r > 0; past about 1000 bits H itself
    does not fit a float, so there the product is taken exactly in integers (r's exact ratio)."""
    if H.bit_length() < 1000:
        return int(H * r)
    num, den = r.as_integer_ratio()
    q = abs(H) * num // den
    return q if H >= 0 else -q


def _root_ratio(tol, e, K):
    """(tol / e)^(1/K) for fixed-point integers; past about 1000 bits the float quotient would
    underflow to 0 (and the step with it), so there it goes through logarithms."""
    if e.bit_length() < 1000:
        return (tol / e) ** (1.0 / K)
    return 2.0 ** ((math.log2(tol) - math.log2(e)) / K)


class Integrator:
    def __init__(self, prec=PREC, tol_bits=TOL_BITS, order=ORDER):
        self.P = prec
        self.tol = 1 << (prec - tol_bits)
        self.K = order
        self.mprec = prec + 24

    def fix(self, x):
        with mp.workprec(self.mprec):
            return libmp.to_fixed(mpf(x)._mpf_, self.P)

    def unfix(self, i):
        return mpf((i, -self.P))

    def to_float(self, x):
        """A fixed-point int as a float; past P = 1000 by a shift first (1 << P itself overflows a
        float)."""
        P = self.P
        return x / float(1 << P) if P < 1000 else math.ldexp(x >> (P - 64), -64)

    def _coeffs(self, th, p, S0, C0, H, Fn, Ft, c, invEI):
        """Scaled Taylor coefficients Th_k = theta_k H^k, S_k H^k, C_k H^k, k = 0..K."""
        P, K = self.P, self.K
        Th = [th, (p * H) >> P]
        dT = [0, Th[1]]
        S = [S0]
        C = [C0]
        U = []
        V = []
        q = (((H * H) >> P) * invEI) >> P
        for k in range(K + 1):
            if k > 0:
                s_acc = 0
                c_acc = 0
                for j in range(1, k + 1):
                    s_acc += dT[j] * C[k - j]
                    c_acc += dT[j] * S[k - j]
                S.append((s_acc >> P) // k)
                C.append(-((c_acc >> P) // k))
            if k <= K - 2:
                U.append((Fn * S[k] + Ft * C[k]) >> P)
                V.append((Ft * S[k] - Fn * C[k]) >> P)
                W = U[k] + self._stretch_term(U, V, k, c)
                t = -(((q * W) >> P) // ((k + 1) * (k + 2)))
                Th.append(t)
                dT.append((k + 2) * t)
        return Th, dT, S, C

    def _stretch_term(self, A, B, k, c):
        """The k-th coefficient of c A B (fixed point; 0 for an inextensible segment, c = 0): the
        axial stretch's share of a series multiplied by (1 + c T)."""
        if not c:
            return 0
        acc = 0
        for j in range(k + 1):
            acc += A[j] * B[k - j]
        return (c * (acc >> self.P)) >> self.P

    def _height_step(self, S, C, H, Fn, Ft, c, hz):
        """Carry the height z over one step (hz: dict with the fixed-point z and the float zmin).
        dz/ds = -(1 + c T) cos(theta), T = Ft sin(theta) - Fn cos(theta) (validation/verify.py's
        convention: theta from the substrate normal, z = 0 at the contact edge); from the step's
        series of sin and cos, D_k = scaled coefficients of dz/ds, z(t H) = z0 + H sum D_k t^(k+1)/(k+1).
        The lowest z is taken at 16 points of the step, the step's end among them, and refined by a
        golden-section search of the step's polynomial between the neighbours of the lowest one."""
        P = self.P
        n = len(C)
        V = [(Ft * S[j] - Fn * C[j]) >> P for j in range(n)] if c else None  # the axial force T
        D = []
        for k in range(n):
            D.append(-(C[k] + self._stretch_term(V, C, k, c)))
        z0 = hz["z"]
        Hf, z0f = self.to_float(H), self.to_float(z0)
        Df = [self.to_float(x) for x in D]

        def zf(t):
            acc = 0.0
            for k in range(n - 1, -1, -1):
                acc = acc * t + Df[k] / (k + 1)
            return z0f + Hf * t * acc

        vals = [zf(m / 16.0) for m in range(17)]
        m = min(range(17), key=vals.__getitem__)
        lo, hi = max(0, m - 1) / 16.0, min(16, m + 1) / 16.0
        g = (math.sqrt(5) - 1) / 2
        for _ in range(40):
            a, b = hi - g * (hi - lo), lo + g * (hi - lo)
            if zf(a) < zf(b):
                hi = b
            else:
                lo = a
        hz["zmin"] = min(hz["zmin"], vals[m], zf((lo + hi) / 2))
        hz["z"] = z0 + ((H * sum(D[k] // (k + 1) for k in range(n))) >> P)

    def segment(self, th, p, S0, C0, L, Fn, Ft, c, invEI, h0, track, heights=None):
        """Integrate over signed length L (fixed ints). Returns th, p, S, C, last step, signs list.
        heights: None, or a dict carrying the height z and its lowest value (_height_step)."""
        P, K = self.P, self.K
        rem = L
        sgn = 1 if L > 0 else -1
        H = sgn * min(abs(h0), abs(L))
        fl = self.to_float

        if track is not None:
            track.append((fl(p), fl(th)))     # the segment's first point (a joint or an end)
        while rem != 0:
            if abs(H) > abs(rem):
                H = rem
            while True:
                Th, dT, S, C = self._coeffs(th, p, S0, C0, H, Fn, Ft, c, invEI)
                e = max(abs(Th[K - 1]), abs(Th[K]), 1)
                if e <= self.tol:
                    break
                r = 0.8 * _root_ratio(self.tol, e, K)
                H = _scaled(H, r)
            if track is not None:
                # sign of theta' along the step at 16 interior points and the end
                hf = fl(H)
                dTf = [fl(x) for x in dT]
                for m in range(1, 17):
                    tau = m / 16.0
                    acc = 0.0
                    for kk in range(K, 0, -1):
                        acc = acc * tau + dTf[kk]
                    # acc = sum k Th_k tau^(k-1) = theta'(tau H) * H
                    val = acc / hf
                    thf = sum(x * tau ** kk for kk, x in enumerate([fl(y) for y in Th[:12]]))
                    track.append((val, thf))
            if heights is not None:
                self._height_step(S, C, H, Fn, Ft, c, heights)
            th = sum(Th)
            p = (sum(dT) << P) // H
            S0 = sum(S)
            C0 = sum(C)
            rem -= H
            grow = min(2.0, 0.9 * _root_ratio(self.tol, max(abs(Th[K - 1]), abs(Th[K]), 1), K))
            H = _scaled(H, max(grow, 0.5))
            if H == 0:
                H = sgn
        return th, p, S0, C0, H


def design_fixed(I, d, Fn, Ft):
    def cfix(EA):
        return 0 if EA == mp.inf or mpf(EA) == mp.inf else I.fix(1 / mpf(EA))
    return dict(Fn=I.fix(Fn), Ft=I.fix(Ft), c1=cfix(d["EA1"]), c2=cfix(d["EA2"]),
                i1=I.fix(1 / mpf(d["EI1"])), i2=I.fix(1 / mpf(d["EI2"])))


def mp_design(d):
    return {k: (mp.inf if (isinstance(v, float) and v == float("inf")) else mpf(v)) for k, v in d.items()}


def kappa(d, Ft):
    """theta2'(a) > 0 from Griffith's condition (docs/theory/two_level_seta.md, contact edge)."""
    c2 = 0 if d["EA2"] == mp.inf else 1 / d["EA2"]
    return mp.sqrt(2 * (d["w"] - Ft * Ft * c2 / 2) / d["EI2"])


def _count(track):
    sg = [1 if v > 0 else -1 for v, _ in track if v != 0.0]
    n = sum(1 for i in range(1, len(sg)) if sg[i] != sg[i - 1])
    # turning angles (double, rough): theta at samples where the sign flips
    angles = [track[i][1] for i in range(1, len(track)) if track[i][0] * track[i - 1][0] < 0]
    return n, angles


def shoot_back(d, Fn, Ft, I=None, track=False, kap=None, heights=False):
    """d: design with mpf values. Returns dict(theta10, theta1p0, beta, [turn info], [min_z]).
    kap overrides theta2'(a) (used at Ft = (Ft)max where it is exactly 0). heights: also the lowest
    height of the seta over [0, a] (min_z, 0 at the contact edge; Integrator._height_step)."""
    I = I or Integrator()
    with mp.workprec(I.mprec):
        Fn, Ft = mpf(Fn), mpf(Ft)
        f = design_fixed(I, d, Fn, Ft)
        l1, l2 = I.fix(d["l1"]), I.fix(d["l2"])
        th = I.fix(mp.pi / 2)
        p = I.fix(kappa(d, Ft) if kap is None else kap)
        S, C = 1 << I.P, 0
        tr2 = [] if track else None
        hz = dict(z=0, zmin=0.0) if heights else None
        th, p, S, C, h = I.segment(th, p, S, C, -l2, f["Fn"], f["Ft"], f["c2"], f["i2"], I.fix(0.125), tr2, hz)
        beta = th
        # joint: theta1 = theta2 - alpha2, EI1 theta1' = EI2 theta2'
        a2 = mpf(d["alpha2"])
        ca, sa = I.fix(mp.cos(a2)), I.fix(mp.sin(a2))
        S, C = (S * ca - C * sa) >> I.P, (C * ca + S * sa) >> I.P
        th = th - I.fix(a2)
        p = I.fix(I.unfix(p) * d["EI2"] / d["EI1"])
        tr1 = [] if track else None
        th, p, S, C, h = I.segment(th, p, S, C, -l1, f["Fn"], f["Ft"], f["c1"], f["i1"], I.fix(0.125), tr1, hz)
        out = dict(theta10=I.unfix(th), theta1p0=I.unfix(p), beta=I.unfix(beta))
        if heights:
            out["min_z"] = hz["zmin"]
        if track:
            # tracks are recorded from s = a downwards; reverse so they run with s
            n2, ang2 = _count(tr2[::-1])
            n1, ang1 = _count(tr1[::-1])
            out.update(turn1=n1, turn2=n2, turn_angles1=ang1, turn_angles2=ang2)
    return out


def shoot_forward(d, Fn, Ft, theta1p0, I=None):
    """Forward shot from the base; returns the two tip residuals of the brief and theta2'(a)."""
    I = I or Integrator()
    with mp.workprec(I.mprec):
        Fn, Ft = mpf(Fn), mpf(Ft)
        f = design_fixed(I, d, Fn, Ft)
        a1 = mpf(d["alpha1"])
        th, p = I.fix(a1), I.fix(theta1p0)
        S, C = I.fix(mp.sin(a1)), I.fix(mp.cos(a1))
        th, p, S, C, h = I.segment(th, p, S, C, I.fix(d["l1"]), f["Fn"], f["Ft"], f["c1"], f["i1"], I.fix(0.125), None)
        a2 = mpf(d["alpha2"])
        ca, sa = I.fix(mp.cos(a2)), I.fix(mp.sin(a2))
        S, C = (S * ca + C * sa) >> I.P, (C * ca - S * sa) >> I.P
        th = th + I.fix(a2)
        p = I.fix(I.unfix(p) * d["EI1"] / d["EI2"])
        th, p, S, C, h = I.segment(th, p, S, C, I.fix(d["l2"]), f["Fn"], f["Ft"], f["c2"], f["i2"], I.fix(0.125), None)
        tha, pa = I.unfix(th), I.unfix(p)
        c2 = 0 if d["EA2"] == mp.inf else 1 / d["EA2"]
        r1 = tha - mp.pi / 2
        r2 = d["EI2"] * pa * pa / 2 + Ft * Ft * c2 / 2 - d["w"]
    return r1, r2, pa


def solve_fn(d, Ft, Fn_guess, I=None, rtol=mpf("1e-27"), maxit=40, kap=None):
    """Secant iteration in Fn (mp) on the backward-shooting residual at fixed Ft."""
    I = I or Integrator()
    with mp.workprec(I.mprec):
        Ft = mpf(Ft)
        x0 = mpf(Fn_guess)
        x1 = x0 + mpf("1e-7") * max(1, abs(x0))
        g0 = shoot_back(d, x0, Ft, I, kap=kap)["theta10"] - d["alpha1"]
        g1 = shoot_back(d, x1, Ft, I, kap=kap)["theta10"] - d["alpha1"]
        for _ in range(maxit):
            if g1 == g0:
                break
            x2 = x1 - g1 * (x1 - x0) / (g1 - g0)
            x0, g0 = x1, g1
            x1 = x2
            g1 = shoot_back(d, x1, Ft, I, kap=kap)["theta10"] - d["alpha1"]
            if abs(x1 - x0) < rtol * max(1, abs(x1)):
                return x1, g1
    return None, None
