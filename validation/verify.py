"""Independent verification of two-level seta critical states by ODE shooting (docs/theory/two_level_seta.md).

Nothing here uses gecko: for a state (Ft, Fn, beta) returned by the solver, the governing equations

    EI_i theta'' = -(Fn sin theta + Ft cos theta) (1 + T(theta)/EA_i),   T = Ft sin theta - Fn cos theta

are integrated *backwards* from the contact edge s = a = l1 + l2, where theta2 = pi/2 and
theta2' = +sqrt(2 (w - Ft^2/(2 EA2)) / EI2) (Griffith, >= 0: see tests/data/gen_seta_reference.py),
across the joint (theta1 = theta2 - alpha2, EI1 theta1' = EI2 theta2') down to the base s = 0.
For the true critical Fn the base mismatch R(Fn) = theta1(0) - alpha1 vanishes and theta2(l1) = beta.

Integrator: fixed-step explicit Runge-Kutta of order 8 (the Dormand-Prince 8(5,3) tableau, used
with a fixed step and no error control), vectorised over states with numpy (up to SCALAR_STATES
states are stepped one by one in Python floats, where numpy's per-call overhead would dominate).
Each state is integrated with N and 2N steps; the difference (x 256/255) bounds the integration
error of the 2N result (order 8: the error of the 2N run is ~1/256 of the difference), and N is
quadrupled per state until that estimate is below 1e-13 rad, it stops shrinking (rounding), or 2N
reaches N_MAX = 2^12 (the last run has at most 2^13 steps); the estimate is reported either way,
and a state whose estimate stays large is inconclusive, not verified.

The mismatch is turned into an Fn error by one extra shot: S = dR/dFn by a forward difference,
dFn = -R/S.  Where |dFn| is not tiny (or S is small: a fold of the line), the verifier refines by
its own Newton/secant iteration from the returned Fn, so the reported error is the distance from
the returned Fn to the verifier's root near it.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate._ivp import dop853_coefficients as _dop

_NS = _dop.N_STAGES
_A = _dop.A[:_NS, :_NS]
_B = _dop.B
_C = _dop.C[:_NS]

THETA_TOL = 1e-13      # target integration error of theta1(0) (rad)
N_MIN = 16
N_MAX = 1 << 12
NOISE_REL = 1e-13     # rounding-level relative perturbation of the tip data (see verify())


def _rhs(theta, p, Fn, Ft, inv_ei, inv_ea):
    s, c = np.sin(theta), np.cos(theta)
    T = Ft * s - Fn * c
    return p, -(Fn * s + Ft * c) * (1.0 + T * inv_ea) * inv_ei


def _dop853_step(theta, p, h, Fn, Ft, inv_ei, inv_ea, heights=False):
    """One fixed DOP853 step of size h from (theta, p); with heights also the step's increment of the
    height z (dz/ds = _dz(theta), below) and dz/ds at the start. Returns (theta, p, dz, dz/ds)."""
    kt = [None] * _NS
    kp = [None] * _NS
    kz = [None] * _NS
    kt[0], kp[0] = _rhs(theta, p, Fn, Ft, inv_ei, inv_ea)
    if heights:
        kz[0] = _dz(theta, Fn, Ft, inv_ea)
    for i in range(1, _NS):
        dt = np.zeros_like(theta)
        dp = np.zeros_like(p)
        for j in range(i):
            a = _A[i, j]
            if a != 0.0:
                dt += a * kt[j]
                dp += a * kp[j]
        th_i = theta + h * dt
        kt[i], kp[i] = _rhs(th_i, p + h * dp, Fn, Ft, inv_ei, inv_ea)
        if heights:
            kz[i] = _dz(th_i, Fn, Ft, inv_ea)
    dt = np.zeros_like(theta)
    dp = np.zeros_like(p)
    dz = np.zeros_like(theta)
    for j in range(_NS):
        if _B[j] != 0.0:
            dt += _B[j] * kt[j]
            dp += _B[j] * kp[j]
            if heights:
                dz += _B[j] * kz[j]
    return theta + h * dt, p + h * dp, (h * dz if heights else None), kz[0]


# The tableau's nonzero coefficients per stage: as arrays for the stacked numpy step (summing
# a[j] * k[j] over axis 0 adds the terms in the order of j, as a scalar loop would) and as Python
# floats for the scalar route.
_A_NZ = [np.nonzero(_A[i, :i])[0] for i in range(_NS)]
_A_COL = [_A[i, idx][:, None, None] for i, idx in enumerate(_A_NZ)]
_B_NZ = np.nonzero(_B)[0]
_B_COL = _B[_B_NZ][:, None, None]
_A_ROWS = [[(int(j), float(_A[i, j])) for j in idx] for i, idx in enumerate(_A_NZ)]
_B_ROW = [(int(j), float(_B[j])) for j in _B_NZ]
# Up to this many states a step costs more in numpy's per-call overhead (about 240 array operations
# per DOP853 step, 0.43 ms for 4 to 16 states, 0.47 ms for 32) than in plain float arithmetic
# (18 us per state), and the states are stepped one by one. The arithmetic is the same, operation
# for operation (the results were the same to the bit on the 40 designs of the short campaign).
SCALAR_STATES = 24


def _rk8_scalar(theta, p, h, n, Fn, Ft, inv_ei, inv_ea, count_turns):
    """_rk8_uniform for one state, in Python floats: n steps of size h; returns (theta, p, turns)."""
    turns = 0
    sin, cos = math.sin, math.cos
    kt = [0.0] * _NS   # every stage is written before it is read, each step
    kp = [0.0] * _NS
    try:
        for _ in range(n):
            s, c = sin(theta), cos(theta)
            kt[0], kp[0] = p, -(Fn * s + Ft * c) * (1.0 + (Ft * s - Fn * c) * inv_ea) * inv_ei
            for i in range(1, _NS):
                dt = dp = 0.0
                for j, a in _A_ROWS[i]:
                    dt += a * kt[j]
                    dp += a * kp[j]
                th_i = theta + h * dt
                s, c = sin(th_i), cos(th_i)
                kt[i], kp[i] = p + h * dp, -(Fn * s + Ft * c) * (1.0 + (Ft * s - Fn * c) * inv_ea) * inv_ei
            dt = dp = 0.0
            for j, b in _B_ROW:
                dt += b * kt[j]
                dp += b * kp[j]
            theta_new, p_new = theta + h * dt, p + h * dp
            if count_turns and ((p_new > 0.0 and p < 0.0) or (p_new < 0.0 and p > 0.0)):
                turns += 1
            theta, p = theta_new, p_new
    except (ValueError, OverflowError):   # sin(inf): the shot blew up; numpy's route gives NaN too
        return math.nan, math.nan, turns
    return theta, p, turns


def _dop853_stacked(Y, h, Fn, Ft, inv_ei, inv_ea, K):
    """One fixed DOP853 step of size h from Y = (theta, p) stacked (shape (2, m)), the stages in the
    work array K (shape (NS, 2, m)); returns the new Y. The arithmetic of _dop853_step, with
    theta and p combined in one array operation each."""
    for i in range(_NS):
        Yi = Y if i == 0 else Y + h * (_A_COL[i] * K[_A_NZ[i]]).sum(axis=0)
        s, c = np.sin(Yi[0]), np.cos(Yi[0])
        K[i, 0] = Yi[1]
        K[i, 1] = -(Fn * s + Ft * c) * (1.0 + (Ft * s - Fn * c) * inv_ea) * inv_ei
    return Y + h * (_B_COL * K[_B_NZ]).sum(axis=0)


def _rk8_uniform(theta, p, h, n, Fn, Ft, inv_ei, inv_ea, count_turns=False):
    """n fixed DOP853 steps of size h (arrays) from (theta, p); returns (theta, p, sign changes of p)."""
    shape = np.shape(theta)
    cols = [np.broadcast_to(np.asarray(x, dtype=np.float64), shape).ravel()
            for x in (theta, p, h, Fn, Ft, inv_ei, inv_ea)]
    m = cols[0].size
    if m <= SCALAR_STATES:
        out = [_rk8_scalar(*(float(x[k]) for x in cols[:3]), n, *(float(x[k]) for x in cols[3:]), count_turns)
               for k in range(m)]
        th, pp, tu = (np.array([o[q] for o in out], dtype=dt).reshape(shape)
                      for q, dt in ((0, np.float64), (1, np.float64), (2, np.int64)))
        return th, pp, tu
    Y = np.stack(cols[:2])
    h, Fn, Ft, inv_ei, inv_ea = cols[2:]
    K = np.empty((_NS, 2, m))
    turns = np.zeros(m, dtype=np.int64)
    for _ in range(n):
        Y_new = _dop853_stacked(Y, h, Fn, Ft, inv_ei, inv_ea, K)
        if count_turns:
            turns += (np.sign(Y_new[1]) * np.sign(Y[1]) < 0)
        Y = Y_new
    return Y[0].reshape(shape), Y[1].reshape(shape), turns.reshape(shape)


def _rk8(theta, p, h, n, Fn, Ft, inv_ei, inv_ea, count_turns=False):
    """n[k] fixed DOP853 steps of size h[k] for state k (n: int or int array).

    States sorted by n (descending); step i advances the prefix of states with n > i, a view, so one
    pass serves every step count (the Python overhead per numpy call is paid once per step, not once
    per distinct n)."""
    K = theta.shape[0]
    if np.isscalar(n) or np.ndim(n) == 0:
        return _rk8_uniform(theta, p, h, int(n), Fn, Ft, inv_ei, inv_ea, count_turns)
    n = np.asarray(n, dtype=np.int64)
    order = np.argsort(-n, kind="stable")
    full = lambda x: np.broadcast_to(np.asarray(x, dtype=np.float64), (K,))[order].copy()  # noqa: E731
    th, pp, hh, fn, ft, ie, ia = (full(x) for x in (theta, p, h, Fn, Ft, inv_ei, inv_ea))
    ns = n[order]
    tu = np.zeros(K, dtype=np.int64)
    ns_asc = ns[::-1]
    step = 0
    nmax = int(ns.max()) if K else 0
    while step < nmax:
        m = K - int(np.searchsorted(ns_asc, step, side="right"))   # states with n > step
        # advance the active prefix up to the next step count where it shrinks
        nxt = int(ns[m - 1])
        a, b, t = _rk8_uniform(th[:m], pp[:m], hh[:m], nxt - step, fn[:m], ft[:m], ie[:m], ia[:m], count_turns)
        th[:m], pp[:m] = a, b
        tu[:m] += t
        step = nxt
    inv = np.empty(K, dtype=np.int64)
    inv[order] = np.arange(K)
    return th[inv], pp[inv], tu[inv]


def _inv(x):
    x = np.asarray(x, dtype=np.float64)
    with np.errstate(divide="ignore"):
        return np.where(np.isinf(x), 0.0, 1.0 / x)


def _shoot_fixed(d, Ft, Fn, n, count_turns=False, tip_rel=0.0):
    """Backward shot with n steps per segment. d: dict of design arrays. Returns theta1(0), beta, turns."""
    ei1, ei2 = d["EI1"], d["EI2"]
    iea1, iea2 = _inv(d["EA1"]), _inv(d["EA2"])
    rad = 2.0 * (d["w"] - Ft * Ft * iea2 * 0.5) / ei2
    theta = np.full(Ft.shape, math.pi / 2)
    p = np.sqrt(np.maximum(rad, 0.0)) * (1.0 + tip_rel)
    theta, p, t2 = _rk8(theta, p, -d["l2"] / n, n, Fn, Ft, 1.0 / ei2, iea2, count_turns)
    beta = theta
    theta1 = theta - d["alpha2"]
    p1 = ei2 * p / ei1
    theta1, p1, t1 = _rk8(theta1, p1, -d["l1"] / n, n, Fn, Ft, 1.0 / ei1, iea1, count_turns)
    return theta1, beta, t1, t2


def step_estimate(d, Ft, Fn):
    """A-priori steps per segment: (segment length) x (largest rate |theta'| or frequency) x const."""
    N = np.hypot(Fn, Ft)
    M2 = np.abs(Ft) + d["w"]
    out = np.zeros(Ft.shape)
    for ei, ea, L in ((d["EI2"], d["EA2"], d["l2"]), (d["EI1"], d["EA1"], d["l1"])):
        iea = _inv(ea)
        force = N * (1.0 + N * iea)
        # first integral bound on theta' (M1 <= (EI2/EI1) M2 + 2N + ...; crude but safe-ish)
        pmax = np.sqrt(2.0 * (M2 * np.maximum(1.0, d["EI2"] / ei) + 2.0 * force) / ei)
        freq = np.sqrt(force / ei)
        out = np.maximum(out, L * (pmax + freq))
    return out


def shoot(d, Ft, Fn, count_turns=False, tip_rel=0.0):
    """theta1(0) and beta for each state, with step doubling until the estimated error < THETA_TOL.

    Returns theta1_0, beta, err_estimate, n_used, turns_beam, turns_spatula."""
    K = Ft.shape[0]
    est = step_estimate(d, Ft, Fn)
    n0 = np.maximum(N_MIN, 2.0 ** np.ceil(np.log2(np.maximum(1.0, 1.5 * est)))).astype(np.int64)
    n0 = np.minimum(n0, N_MAX)
    th = np.full(K, np.nan)
    be = np.full(K, np.nan)
    er = np.full(K, np.inf)
    nu = np.zeros(K, dtype=np.int64)
    tb = np.zeros(K, dtype=np.int64)
    ts = np.zeros(K, dtype=np.int64)
    todo = np.ones(K, dtype=bool) & np.isfinite(Fn)
    n_cur = n0.copy()
    while todo.any():
        # all pending states at once, each with its own step count (see _rk8)
        idx = np.nonzero(todo)[0]
        n = n_cur[idx]
        # the n-step and the 2n-step shots in one pass
        m = idx.size
        sub = {k: np.concatenate([v[idx], v[idx]]) for k, v in d.items()}
        r_th, r_be, r_t1, r_t2 = _shoot_fixed(sub, np.concatenate([Ft[idx], Ft[idx]]), np.concatenate([Fn[idx], Fn[idx]]),
                                              np.concatenate([n, 2 * n]), count_turns, tip_rel)
        a_th, a_be = r_th[:m], r_be[:m]
        b_th, b_be, b_t1, b_t2 = r_th[m:], r_be[m:], r_t1[m:], r_t2[m:]
        # order-8 Richardson estimate of the 2n error (|diff|/255), with a rounding floor
        e = (np.abs(b_th - a_th) + np.abs(b_be - a_be)) / 255.0 + 1e-16 * (1 + np.abs(b_th))
        stagnant = np.isfinite(er[idx]) & (e > 0.25 * er[idx])   # rounding-limited: stop
        keep = ~stagnant | ~np.isfinite(er[idx])
        upd = idx[keep]
        th[upd], be[upd], er[upd], nu[upd], tb[upd], ts[upd] = (b_th[keep], b_be[keep], e[keep], 2 * n[keep],
                                                                b_t1[keep], b_t2[keep])
        ok = np.isfinite(e) & (e < THETA_TOL)
        done = ok | stagnant | (2 * n >= N_MAX)
        todo[idx[done]] = False
        n_cur[idx[~done]] = 4 * n[~done]   # next try: 4n and 8n
    return th, be, er, nu, tb, ts


def verify(d, Ft, Fn, beta, newton_iterations=5):
    """Verify states. d: dict of 1-D design arrays (one row per state), Ft, Fn, beta: arrays.

    Returns a dict of arrays: R (theta1(0) - alpha1), dFn (verifier root - returned Fn), dbeta,
    theta_err (integration error estimate), fn_uncert (verifier's own Fn uncertainty), steps,
    turns_beam, turns_spatula (turning points counted at the returned Fn), root_turns_beam,
    root_turns_spatula (counted at the verifier's own root; -1 where it found none), refined (bool),
    root_found (bool)."""
    Ft = np.asarray(Ft, float)
    Fn = np.asarray(Fn, float)
    beta = np.asarray(beta, float)
    th, be, er, nu, tb, ts = shoot(d, Ft, Fn, count_turns=True)
    R = th - d["alpha1"]
    delta = 1e-6 * np.maximum(1.0, np.abs(Fn))
    th2, be2, er2, _, _, _ = shoot(d, Ft, Fn + delta)
    S = (th2 - th) / delta
    Sb = (be2 - be) / delta
    dFn = -R / S
    fn_root = Fn + dFn
    # beta of the verifier's root (linearised): beta(Fn + dFn) ~ beta(Fn) + Sb dFn
    beta_root = be + Sb * dFn
    # Conditioning: the backward shot amplifies rounding of its initial data (strong tension makes
    # the elastica hyperbolic, growth ~ exp(L sqrt(N/EI))).  Perturb the tip rate by 1e-10
    # (relative) and scale the response down to a rounding-level perturbation of NOISE_REL to bound
    # the verifier's own noise.  NOISE_REL = 1e-13 (~500 eps, the rounding accumulated over up to
    # 2^12 steps): with 1e-14 the bound was 15x too small on the worst campaign state, measured
    # against a 60-digit Taylor-series shooting (validation/beta_conditioning.py).
    th3, be3, _, _, _, _ = shoot(d, Ft, Fn, tip_rel=1e-10)
    noise_th = np.abs(th3 - th) * (NOISE_REL / 1e-10)
    noise_be = np.abs(be3 - be) * (NOISE_REL / 1e-10)
    fn_uncert = (er + er2 + noise_th) / np.abs(S)
    beta_uncert = er + noise_be + np.abs(Sb) * fn_uncert
    refined = np.zeros(Fn.shape, dtype=bool)
    root_found = np.isfinite(dFn)
    scale = np.maximum(1.0, np.abs(Fn))
    # Refine where the linear estimate is not clearly tiny: Newton with the verifier itself.
    need = np.isfinite(Fn) & ~(np.abs(dFn) < 1e-9 * scale)
    if need.any():
        idx = np.nonzero(need)[0]
        sub = {k: v[idx] for k, v in d.items()}
        x = Fn[idx].copy()
        conv = np.zeros(idx.size, dtype=bool)
        last = np.full(idx.size, np.nan)
        b_last = np.full(idx.size, np.nan)
        for _ in range(newton_iterations):
            t0, b0, e0, _, _, _ = shoot(sub, Ft[idx], x)
            dx = 1e-7 * np.maximum(1.0, np.abs(x))
            t1, b1, e1, _, _, _ = shoot(sub, Ft[idx], x + dx)
            s = (t1 - t0) / dx
            step = -(t0 - sub["alpha1"]) / s
            # damp: never more than 10% of scale per iteration (stay near the returned point)
            lim = 0.1 * np.maximum(1.0, np.abs(Fn[idx]))
            step = np.clip(step, -lim, lim)
            x_new = np.where(conv, x, x + step)
            last = np.where(conv, last, np.abs(step))
            b_last = np.where(conv, b_last, b0 + (b1 - b0) / dx * step)
            conv |= np.abs(step) < 1e-13 * np.maximum(1.0, np.abs(x))
            x = x_new
            if conv.all():
                break
        fn_root[idx] = np.where(conv, x, np.nan)
        beta_root[idx] = np.where(conv, b_last, np.nan)
        root_found[idx] = conv
        refined[idx] = True
        dFn[idx] = fn_root[idx] - Fn[idx]
    # The turning points of the verifier's own root: a Newton root far from the returned Fn may lie
    # on another branch of the shot (another number of turns), and then it is no verdict on the
    # returned state. Where no refinement ran, the root is within 1e-9 relative of Fn and its
    # counts are those at Fn.
    root_tb, root_ts = tb.copy(), ts.copy()
    if refined.any():
        idx = np.nonzero(refined)[0]
        root_tb[idx] = -1
        root_ts[idx] = -1
        hit = idx[root_found[idx]]
        if hit.size:
            sub = {k: v[hit] for k, v in d.items()}
            _, _, _, _, rtb, rts = shoot(sub, Ft[hit], fn_root[hit], count_turns=True)
            root_tb[hit], root_ts[hit] = rtb, rts
    return dict(R=R, S=S, dFn=dFn, fn_root=fn_root, dbeta=beta - beta_root, theta_err=er,
                fn_uncert=fn_uncert, beta_uncert=beta_uncert, steps=nu, turns_beam=tb, turns_spatula=ts,
                root_turns_beam=root_tb, root_turns_spatula=root_ts, refined=refined,
                root_found=root_found)


# ---- heights: is the seta above the substrate? (issue 13, item 2: an independent check) ----------
# With theta measured from the substrate normal (theta = pi/2: parallel to it), x along the
# substrate towards the contact and z the height above it, the centreline of the stretched seta has
#     dz/ds = -(1 + T(theta)/EA) cos(theta)
# (the unit tangent (sin theta, -cos theta) times the stretch 1 + T/EA of the convected coordinate),
# and z = 0 at the contact edge s = a. The backward shot carries z along with theta and theta'; the
# lowest z is taken over every step and, between two steps, at the minimum of the cubic Hermite
# interpolant of (z, dz/ds) at both ends (exact to O(h^4), so no sampling error of order h^2).

HEIGHT_NOISE_REL = NOISE_REL   # rounding-level perturbation of the tip data (see verify())


def _dz(theta, Fn, Ft, inv_ea):
    return -(1.0 + (Ft * np.sin(theta) - Fn * np.cos(theta)) * inv_ea) * np.cos(theta)


def _hermite_min(z0, m0, z1, m1):
    """Smallest value of the cubic Hermite interpolant on t in [0, 1] (m = h dz/ds at the ends)."""
    a = 6.0 * z0 + 3.0 * m0 - 6.0 * z1 + 3.0 * m1
    b = -6.0 * z0 - 4.0 * m0 + 6.0 * z1 - 2.0 * m1
    c = m0
    lo = np.minimum(z0, z1)
    with np.errstate(invalid="ignore", divide="ignore"):
        disc = np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))
        q = -0.5 * (b + np.copysign(disc, b))
        cands = (q / a, np.where(q != 0.0, c / q, np.nan), np.where(a == 0.0, -c / b, np.nan))
    for t in cands:
        inside = np.isfinite(t) & (t > 0.0) & (t < 1.0)
        tt = np.where(inside, t, 0.0)
        t2, t3 = tt * tt, tt * tt * tt
        zt = (2 * t3 - 3 * t2 + 1) * z0 + (t3 - 2 * t2 + tt) * m0 + (-2 * t3 + 3 * t2) * z1 + (t3 - t2) * m1
        lo = np.where(inside, np.minimum(lo, zt), lo)
    return lo


def _rk8_heights(theta, p, z, zmin, h, n, Fn, Ft, inv_ei, inv_ea):
    """n fixed DOP853 steps (common n) carrying z; returns theta, p, z and the running minimum of z."""
    for _ in range(n):
        theta_new, p_new, dz, dz0 = _dop853_step(theta, p, h, Fn, Ft, inv_ei, inv_ea, heights=True)
        z_new = z + dz
        zmin = np.minimum(zmin, _hermite_min(z, h * dz0, z_new, h * _dz(theta_new, Fn, Ft, inv_ea)))
        theta, p, z = theta_new, p_new, z_new
    return theta, p, z, zmin


def _heights_fixed(d, Ft, Fn, n, tip_rel):
    """Backward shot with n steps per segment (common n) carrying z: the lowest z over [0, a]."""
    iea1, iea2 = _inv(d["EA1"]), _inv(d["EA2"])
    rad = 2.0 * (d["w"] - Ft * Ft * iea2 * 0.5) / d["EI2"]
    theta = np.full(Ft.shape, math.pi / 2)
    p = np.sqrt(np.maximum(rad, 0.0)) * (1.0 + tip_rel)
    z = np.zeros(Ft.shape)
    zmin = np.zeros(Ft.shape)   # the contact edge itself
    theta, p, z, zmin = _rk8_heights(theta, p, z, zmin, -d["l2"] / n, n, Fn, Ft, 1.0 / d["EI2"], iea2)
    theta1 = theta - d["alpha2"]
    p1 = d["EI2"] * p / d["EI1"]
    _, _, _, zmin = _rk8_heights(theta1, p1, z, zmin, -d["l1"] / n, n, Fn, Ft, 1.0 / d["EI1"], iea1)
    return zmin


def _heights_grouped(d, Ft, Fn, n, tip_rel):
    """_heights_fixed with a step count per state (powers of two), one pass per distinct count."""
    out = np.full(Ft.shape, np.nan)
    for k in np.unique(n):
        idx = np.nonzero(n == k)[0]
        sub = {key: v[idx] for key, v in d.items()}
        out[idx] = _heights_fixed(sub, Ft[idx], Fn[idx], int(k), tip_rel[idx])
    return out


def heights(d, Ft, Fn):
    """The lowest height of the seta over [0, a] (0: the contact edge) for each state, by the shot.

    d: dict of 1-D design arrays (one row per state), Ft, Fn: arrays (Fn: the solver's).
    Returns (min_z, uncertainty): min_z from 2n steps per segment (n four times the a-priori count
    of ``step_estimate``, at least 64); the uncertainty adds the interpolation/integration error
    (the whole difference |min_z(2n) - min_z(n)|, though the O(h^4) Hermite term leaves the 2n
    result only ~1/15 of it), the amplification of rounding of the tip data (as in verify(): a 1e-10 tip
    perturbation scaled to HEIGHT_NOISE_REL) and the effect of an error of 1e-11 max(1, |Fn|) in Fn
    (a 1e-7 perturbation scaled down), the solver's state tolerance. The four shots of every state
    run in one pass per distinct step count."""
    Ft = np.asarray(Ft, float)
    Fn = np.asarray(Fn, float)
    K = Ft.size
    est = step_estimate(d, Ft, Fn)
    n = np.maximum(64, 2.0 ** np.ceil(np.log2(np.maximum(1.0, 6.0 * est)))).astype(np.int64)
    n = np.minimum(n, 4 * N_MAX)
    dF = 1e-7 * np.maximum(1.0, np.abs(Fn))
    # shots: n steps; 2n; 2n with the tip rate perturbed; 2n at Fn + dF
    dd = {k: np.tile(v, 4) for k, v in d.items()}
    tip = np.zeros(4 * K)
    tip[2 * K:3 * K] = 1e-10
    zz = _heights_grouped(dd, np.tile(Ft, 4), np.concatenate([Fn, Fn, Fn, Fn + dF]),
                          np.concatenate([n, 2 * n, 2 * n, 2 * n]), tip)
    z1, z2, z3, z4 = zz[:K], zz[K:2 * K], zz[2 * K:3 * K], zz[3 * K:]
    unc = np.abs(z2 - z1) + np.abs(z3 - z2) * (HEIGHT_NOISE_REL / 1e-10) + np.abs(z4 - z2) * 1e-4
    unc = np.where(np.isfinite(unc), unc, np.inf)
    return z2, unc
