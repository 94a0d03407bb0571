#!/usr/bin/env python3
"""Reference table for the corner phi -> pi/2, m -> 1 of F(phi|m) and E(phi|m), where F has its
logarithmic singularity (F(pi/2|1) = inf) and 1 - m sin^2 phi cancels (tests/elliptic/near_singular.cpp).

elliptic_legendre.csv (gen_elliptic.py, region near_pole) samples phi down to pi/2 - 1e-12 and m up to
1 - 1e-16 at random. This table adds, deterministically, what it leaves out:
  ulps_below   phi = the last doubles below pi/2 (the double nearest pi/2, which is below it, and the
               5 before it), with m = 1 - 2^-j (j = 1..53), 1 - k 2^-53 (k = 1..4) and m = 1;
  gap          phi = pi/2 - 10^-x for x = 12.5 .. 15.5 (the gap between the old table and the ulps),
               same m;
  above        phi = the first doubles above pi/2 (1..4 ulps) and pi/2 + 10^-x (x = 8..15): the
               quadrant seam of the angle reduction (F = K + (K - F(pi/2 - r))), m < 1 only
               (F(phi|1) = inf beyond pi/2);
  diagonal     phi = pi/2 - d/2, m = 1 - d for d = 10^-x, x = 1..16 in steps of 1/2: the joint
               approach to the corner.
Inputs are exact doubles written with repr(); mpmath evaluates at the exact inputs with 40 digits,
doubling the precision until two successive precisions agree to 32 digits (as gen_elliptic.py),
and the values are written with 30 significant digits.

    python3 tests/data/gen_elliptic_near_singular.py     # writes elliptic_near_singular.csv here
"""
import csv
import math
import os

import mpmath as mp

DPS = 40
OUT_DIGITS = 30
HERE = os.path.dirname(os.path.abspath(__file__))
HALF_PI = math.pi / 2  # the double nearest pi/2, which is below pi/2


def stable(f, *args, dps=DPS):
    prev = None
    d = dps
    while True:
        with mp.workdps(d):
            v = +f(*(mp.mpf(a) for a in args))
        if prev is not None:
            with mp.workdps(d):
                if abs(v - prev) <= mp.mpf(10) ** (-(OUT_DIGITS + 2)) * max(abs(v), mp.mpf(10) ** (-d)):
                    return v
        prev = v
        d *= 2
        assert d <= 1280, (f, args)


def out(v):
    if isinstance(v, mp.mpc):
        assert abs(v.imag) <= mp.mpf(10) ** (-DPS + 5) * max(1, abs(v.real)), v
        v = v.real
    return mp.nstr(v, OUT_DIGITS, min_fixed=1, max_fixed=0)


def m_values():
    ms = [1.0 - 2.0 ** -j for j in range(1, 54)]
    ms += [1.0 - k * 2.0 ** -53 for k in range(1, 5)]
    ms.append(1.0)
    return sorted(set(ms))


def cases():
    rows = []
    phis = [HALF_PI]
    for _ in range(5):
        phis.append(math.nextafter(phis[-1], 0.0))
    for phi in phis:
        for m in m_values():
            rows.append(("ulps_below", phi, m))
    for x in (12.5, 13.0, 13.5, 14.0, 14.5, 15.0, 15.5):
        phi = HALF_PI - 10.0 ** -x
        for m in m_values():
            rows.append(("gap", phi, m))
    above = [math.nextafter(HALF_PI, 4.0)]
    for _ in range(3):
        above.append(math.nextafter(above[-1], 4.0))
    above += [HALF_PI + 10.0 ** -x for x in range(8, 16)]
    for phi in above:
        assert phi > math.pi / 2 or mp.mpf(phi) > mp.pi / 2
        for m in m_values():
            if m < 1:
                rows.append(("above", phi, m))
    for k in range(2, 33):
        d = 10.0 ** (-k / 2)
        rows.append(("diagonal", HALF_PI - d / 2, 1.0 - d))
    return rows


def main():
    table = []
    for region, phi, m in cases():
        F = stable(mp.ellipf, phi, m)
        E = stable(mp.ellipe, phi, m)
        with mp.workdps(DPS):
            table.append([repr(phi), repr(m), out(F), out(E), region])
    path = os.path.join(HERE, "elliptic_near_singular.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["phi", "m", "F", "E", "region"])
        w.writerows(table)
    print(f"elliptic_near_singular.csv: {len(table)} rows")


if __name__ == "__main__":
    main()
