#!/usr/bin/env python3
"""Reference lengths of single elastica segments for tests/seta/elastica_segment.cpp.

    python3 tests/data/gen_seta_solver_segments.py     # writes tests/data/seta_solver_segments.csv

docs/theory/two_level_seta.md, first integral: 1/2 EI theta'^2 = R = M - N sin(theta - phi) - N^2 sin^2(theta - phi)/(2EA).
A case is (EI, EA, M, Fn, Ft, theta_start, theta_end, sign_start, sign_end): the elastica leaves
theta_start with theta' of sign_start and arrives at theta_end with sign_end, along the shortest
such path (theta reverses only at turning points, where R = 0). Its length
    L = sqrt(EI/2) * sum over monotone pieces of int dtheta / sqrt(R(theta))
is computed here by mpmath tanh-sinh quadrature at 40 digits, piece by piece, with the turning
angles found as roots of R to 40 digits; independent of the Carlson forms of the library (no R_F
here). Cases cover librations (turning points possible) and rotations, EA finite and infinite,
0, 1 and 2 turning points, paths through u = sin(theta - phi) = +-1, and long paths (more than
a quarter period, where the library switches from its direct form to its phase forms).
Columns are printed with repr() for inputs (exact doubles) and 25 digits for L.
"""
import csv
import math
import os
import random

from mpmath import mp, mpf

mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))


def radicand(M, N, c, phi, th):
    u = mp.sin(th - phi)
    return M - N * u - c * N * N * u * u / 2


def turning_angles(M, N, c, phi):
    """Turning angles (theta_max, theta_min) of the libration containing the window, or None."""
    s = mp.sqrt(1 + 2 * c * M)
    up = 2 * M / (N * (1 + s))
    if not (-1 < up < 1):
        return None
    a = mp.asin(up)
    return phi + a, phi - mp.pi - a


def path_length(EI, M, N, c, phi, pts):
    tot = mpf(0)
    for a, b in zip(pts[:-1], pts[1:]):
        lo, hi = (a, b) if a < b else (b, a)
        f = lambda t: 1 / mp.sqrt(abs(radicand(M, N, c, phi, t)))
        tot += mp.quad(f, [lo, (lo + hi) / 2, hi])
    return tot * mp.sqrt(mpf(EI) / 2)


def main():
    rnd = random.Random(20261121)
    rows = []
    kinds = {"lib0": 0, "lib1": 0, "lib2": 0, "rot": 0}
    tries = 0
    while len(rows) < 160 and tries < 100000:
        tries += 1
        EI = round(rnd.uniform(0.2, 8), 6)
        EA = rnd.choice([math.inf, round(rnd.uniform(20, 200), 4), round(rnd.uniform(5, 20), 4)])
        c = 0 if EA == math.inf else 1 / mpf(EA)
        M = round(rnd.uniform(-0.5, 6), 6)
        Fn = round(rnd.uniform(-4, 4), 6)
        Ft = round(rnd.uniform(-2, 8), 6)
        N = mp.sqrt(mpf(Fn) ** 2 + mpf(Ft) ** 2)
        if N < 0.05 or 1 + 2 * c * M <= 0:
            continue
        if c > 0 and c * N >= 1 + mp.sqrt(1 + 2 * c * M):
            continue
        phi = mp.atan2(Fn, Ft)
        tp = turning_angles(M, N, c, phi)
        if tp is None:
            # rotation (f3 > 0 on [-1, 1]) or no state at all
            s = mp.sqrt(1 + 2 * c * M)
            if 2 * M / (N * (1 + s)) <= -1:
                continue
            ts = rnd.uniform(-1, 3)
            te = ts + rnd.choice([1, -1]) * rnd.uniform(0.05, 3.5)
            sg = 1 if te > ts else -1
            pts = [mpf(ts), mpf(te)]
            kind = "rot"
            row_s = row_e = sg
        else:
            tmax, tmin = tp
            lo, hi = float(tmin), float(tmax)
            ts = rnd.uniform(lo, hi)
            te = rnd.uniform(lo, hi)
            ss = rnd.choice([1, -1])
            se = rnd.choice([1, -1])
            # shortest path: from ts with sign ss, turning at the turning angles, until te is
            # reached moving with sign se
            pts = [mpf(ts)]
            cur, sg, n = mpf(ts), ss, 0
            while True:
                if sg == se and ((sg > 0 and te >= cur) or (sg < 0 and te <= cur)):
                    pts.append(mpf(te))
                    break
                nxt = tmax if sg > 0 else tmin
                pts.append(nxt)
                cur, sg, n = nxt, -sg, n + 1
            want = n
            kind = "lib%d" % want
            row_s, row_e = ss, se
        # keep the ends away from the turning angles (sign there is ambiguous)
        if tp is not None and min(abs(mpf(ts) - tp[0]), abs(mpf(ts) - tp[1]), abs(mpf(te) - tp[0]),
                                  abs(mpf(te) - tp[1])) < 1e-3:
            continue
        if kinds[kind] >= 45:
            continue
        L = path_length(EI, M, N, c, phi, pts)
        kinds[kind] += 1
        rows.append([repr(EI), "inf" if EA == math.inf else repr(EA), repr(M), repr(Fn), repr(Ft),
                     repr(float(ts)), repr(float(te)), row_s, row_e, len(pts) - 2, mp.nstr(L, 25)])
    out = os.path.join(HERE, "seta_solver_segments.csv")
    with open(out, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["EI", "EA", "M", "Fn", "Ft", "theta_start", "theta_end", "sign_start", "sign_end",
                    "turning_points", "length"])
        w.writerows(rows)
    print("wrote", out, len(rows), "cases", kinds)


if __name__ == "__main__":
    main()
