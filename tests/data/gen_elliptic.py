#!/usr/bin/env python3
"""Reference tables for gecko's elliptic integrals (tests/elliptic/*.cpp read them).

Every input is a double, printed with repr() (shortest string that round-trips, i.e. the exact
double); mpmath evaluates the integral AT THAT EXACT DOUBLE (mpmath.mpf(float) is exact) at 40
significant digits of working precision (more for huge phi, whose reduction modulo pi needs the
extra digits) AND again at doubled precision until two successive precisions agree to 32
digits (stable() below: mpmath's Carlson routines lose digits for widely spread arguments).
The result is written with 30 significant digits, so the tables are correct to far below one
ulp of long double, and a kernel's error against them is its own.

Run from anywhere:  python3 tests/data/gen_elliptic.py [rf_rd rj rc legendre complete]
(fixed seed; writes next to itself; a few minutes for all tables)

Tables (CSV, one header line, a `region` column says which part of the domain a row probes):
  elliptic_rf.csv   x,y,z,rf          R_F   random 1e-12..1e12, 1e-100..1e100, one zero, nearly
                                          equal, R_C-like
  elliptic_rd.csv   x,y,z,rd          R_D   the same families (z > 0)
  elliptic_rj.csv   x,y,z,p,rj,pv_cancel  R_J   p > 0 families (incl. 1e-100..1e100 and
                                          p >> x, y, z); p < 0 as Cauchy principal value, with
                                          the cancellation factor of DLMF 19.20.14
  elliptic_rc.csv   x,y,rc            R_C   x < y, x > y, nearly equal, x = 0, y < 0 (p.v.)
  elliptic_legendre.csv phi,m,F,E,kappa_s  F(phi|m), E(phi|m) (regions: see legendre_rows);
                    kappa_s = |d ln F / d ln sin(phi)|, the conditioning near the m > 1 edge
  elliptic_legendre_edge.csv phi,m,F,E  F(phi|m), E(phi|m) for m > 1 next to the edge
                    sin^2 phi = 1/m (Delta^2 = 1 - m sin^2 phi down to 1e-16) and m -> 1 from
                    above, phi the exact double on the real domain (regions: see edge_rows)
  elliptic_complete.csv m,K,E         K(m), E(m)
"""
import csv
import math
import os
import random

import mpmath as mp

DPS = 40
OUT_DIGITS = 30
HERE = os.path.dirname(os.path.abspath(__file__))
SEED = 20261121
rng = random.Random(SEED)


def reseed(table):
    """Each table draws from its own stream, so regenerating one table leaves the others as
    they are (and a full run is reproducible)."""
    global rng
    rng = random.Random(f"{SEED}-{table}")


def out(v):
    """30 significant digits of a real mpmath value (imaginary part must vanish)."""
    if isinstance(v, mp.mpc):
        assert abs(v.imag) <= mp.mpf(10) ** (-DPS + 5) * max(1, abs(v.real)), v
        v = v.real
    return mp.nstr(v, OUT_DIGITS, min_fixed=1, max_fixed=0)


def stable(f, *args, dps=DPS):
    """f(*args) (args: exact doubles) evaluated at dps and at twice dps, increasing until two
    successive precisions agree to OUT_DIGITS + 2 digits. mpmath's Carlson functions lose
    digits when the arguments are spread over many orders of magnitude (at 40 digits
    elliprj(0.206, 8.2e37, 7.9e6, 4.5e-90) is off in the 5th digit), so no single working
    precision is trusted."""
    prev = None
    d = dps
    while True:
        with mp.workdps(d):
            v = f(*(mp.mpf(a) for a in args))
            v = +v
        if prev is not None:
            with mp.workdps(d):
                scale = max(abs(v), mp.mpf(10) ** (-d))
                if abs(v - prev) <= mp.mpf(10) ** (-(OUT_DIGITS + 2)) * scale:
                    return v
        prev = v
        d *= 2
        assert d <= 1280, (f, args)


def loguniform(lo, hi):
    return 10.0 ** rng.uniform(lo, hi)


def write(name, header, rows):
    path = os.path.join(HERE, name)
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    print(f"{name}: {len(rows)} rows")


def spread(base, lo, hi):
    """base * (1 + d) with |d| = 10^-U(lo, hi), random sign: nearly equal arguments."""
    return base * (1.0 + rng.choice((-1.0, 1.0)) * 10.0 ** -rng.uniform(lo, hi))


# ---------------------------------------------------------------- Carlson R_F, R_D
def carlson3_inputs(n_random, n_zero, n_close, n_pair, z_positive, n_wide=100):
    rows = []
    for _ in range(n_random):
        rows.append(("random", [loguniform(-12, 12) for _ in range(3)]))
    for _ in range(n_wide):
        # arguments spread over 200 orders of magnitude (rescaling, slow-convergence paths)
        rows.append(("wide", [loguniform(-100, 100) for _ in range(3)]))
    for _ in range(n_zero):
        a = [loguniform(-12, 12) for _ in range(3)]
        a[rng.randrange(2 if z_positive else 3)] = 0.0
        rows.append(("one_zero", a))
    for _ in range(n_close):
        b = loguniform(-6, 6)
        rows.append(("nearly_equal", [spread(b, 3, 15) for _ in range(3)]))
    for _ in range(n_pair):
        # two equal arguments (R_C-like) and a third anywhere
        b, c = loguniform(-12, 12), loguniform(-12, 12)
        a = [b, b, c]
        rng.shuffle(a)
        rows.append(("two_equal", a))
    return rows


def carlson_rf_rd():
    reseed("rf_rd")
    with mp.workdps(DPS):
        rows = []
        for region, (x, y, z) in carlson3_inputs(1000, 300, 300, 100, False):
            v = stable(mp.elliprf, x, y, z)
            rows.append([repr(x), repr(y), repr(z), out(v), region])
        write("elliptic_rf.csv", ["x", "y", "z", "rf", "region"], rows)
        rows = []
        for region, (x, y, z) in carlson3_inputs(1000, 300, 300, 100, True):
            v = stable(mp.elliprd, x, y, z)
            rows.append([repr(x), repr(y), repr(z), out(v), region])
        write("elliptic_rd.csv", ["x", "y", "z", "rd", "region"], rows)


# ---------------------------------------------------------------- R_J
def rj_terms(x, y, z, p):
    """DLMF 19.20.14 for p < 0 (x <= y <= z after sorting, q = -p): the three terms whose sum
    is (z + q) R_J(x, y, z, p). Their cancellation bounds how well any implementation of that
    formula can do; the tests allow for it."""
    a, b, c = sorted([x, y, z])
    q = -p
    pp = (c * (a + b + q) - a * b) / (c + q)
    return ((pp - c) * mp.elliprj(a, b, c, pp), -3 * mp.elliprf(a, b, c),
            3 * mp.sqrt(a * b * c / (a * b + pp * q)) * mp.elliprc(a * b + pp * q, pp * q)), c + q


def rj_principal_value(x, y, z, p):
    """Cauchy principal value of R_J for p < 0 as the real part of the integral taken with
    p -> p + i0 (the half-residue is purely imaginary); cross-checked against DLMF 19.20.14."""
    v = mp.elliprj(x, y, z, p)
    v = v.real if isinstance(v, mp.mpc) else v
    terms, zq = rj_terms(x, y, z, p)
    w = sum(terms) / zq
    assert abs(v - w) <= mp.mpf(10) ** (-mp.mp.dps + 8) * max(abs(v), abs(w)), (x, y, z, p, v, w)
    return v


def carlson_rj():
    reseed("rj")
    with mp.workdps(DPS):
        rows = []
        cases = []
        for _ in range(700):
            cases.append(("random", [loguniform(-12, 12) for _ in range(4)]))
        for _ in range(200):
            a = [loguniform(-12, 12) for _ in range(4)]
            a[rng.randrange(3)] = 0.0
            cases.append(("one_zero", a))
        for _ in range(200):
            b = loguniform(-6, 6)
            cases.append(("nearly_equal", [spread(b, 3, 15) for _ in range(4)]))
        for _ in range(100):
            # moderate spread, the range seen by the Legendre Pi and by seta code
            cases.append(("moderate", [loguniform(-3, 3) for _ in range(4)]))
        for _ in range(100):
            cases.append(("wide", [loguniform(-100, 100) for _ in range(4)]))
        for _ in range(100):
            # p far above x, y, z: the duplication alone stalls here (DLMF 19.21.11 route)
            a = [loguniform(-6, 6) for _ in range(3)]
            if rng.random() < 0.3:
                a[rng.randrange(3)] = 0.0
            cases.append(("large_p", a + [max(a) * loguniform(1.2, 60)]))
        for _ in range(200):
            a = [loguniform(-4, 4) for _ in range(3)] + [-loguniform(-4, 4)]
            cases.append(("pv", a))
        for region, (x, y, z, p) in cases:
            v = stable(rj_principal_value if p < 0 else mp.elliprj, x, y, z, p)
            cancel = mp.mpf(1)
            if p < 0:
                with mp.workdps(2 * DPS):
                    terms, zq = rj_terms(*(mp.mpf(t) for t in (x, y, z, p)))
                    cancel = sum(abs(t) for t in terms) / abs(sum(terms))
            rows.append([repr(x), repr(y), repr(z), repr(p), out(v), mp.nstr(cancel, 6), region])
        write("elliptic_rj.csv", ["x", "y", "z", "p", "rj", "pv_cancel", "region"], rows)


# ---------------------------------------------------------------- R_C
def carlson_rc():
    reseed("rc")
    with mp.workdps(DPS):
        cases = []
        for _ in range(400):
            cases.append(("random", [loguniform(-12, 12), loguniform(-12, 12)]))
        for _ in range(200):
            b = loguniform(-6, 6)
            cases.append(("nearly_equal", [spread(b, 1, 16), b]))
        for _ in range(50):
            cases.append(("x_zero", [0.0, loguniform(-12, 12)]))
        for _ in range(200):
            cases.append(("pv", [loguniform(-12, 12), -loguniform(-12, 12)]))
        for _ in range(20):
            cases.append(("pv", [0.0, -loguniform(-12, 12)]))
        rows = []
        for region, (x, y) in cases:
            v = stable(rc_reference, x, y)
            rows.append([repr(x), repr(y), out(v), region])
        write("elliptic_rc.csv", ["x", "y", "rc", "region"], rows)


def rc_reference(X, Y):
    """R_C, with the Cauchy principal value for Y < 0 from DLMF 19.2.20; mpmath's pv=True
    agrees except at X = 0, where the principal value is 0 (it returns the imaginary
    half-residue there)."""
    if Y < 0:
        v = mp.sqrt(X / (X - Y)) * mp.elliprc(X - Y, -Y)
        if X != 0:
            w = mp.elliprc(X, Y, pv=True)
            assert abs(v - w) <= mp.mpf(10) ** (-mp.mp.dps + 8) * abs(v), (X, Y, v, w)
        return v
    return mp.elliprc(X, Y)


# ---------------------------------------------------------------- Legendre F, E
HALF_PI = math.pi / 2  # the double just below pi/2


def legendre_rows():
    cases = []
    for _ in range(1200):
        cases.append(("bulk", rng.uniform(0, HALF_PI), rng.uniform(0, 1)))
    # m -> 1 together with phi -> pi/2: where 1 - m sin^2 phi cancels
    for _ in range(600):
        m = 1.0 - 10.0 ** -rng.uniform(0, 16)
        phi = HALF_PI - 10.0 ** -rng.uniform(0, 12)
        cases.append(("near_pole", phi, m))
    for k in range(0, 5):  # m within a few ulps of 1, and m = 1 itself
        for _ in range(20):
            phi = HALF_PI - 10.0 ** -rng.uniform(0, 12)
            cases.append(("near_pole", phi, 1.0 - k * 2.0 ** -53))
    for _ in range(200):
        cases.append(("tiny_phi", 10.0 ** -rng.uniform(1, 300), rng.uniform(-10, 1)))
    for _ in range(400):
        phi = 10.0 ** rng.uniform(math.log10(HALF_PI) + 1e-9, 6)
        r = rng.random()
        m = rng.uniform(0, 1) if r < 0.6 else (1.0 - 10.0 ** -rng.uniform(0, 12) if r < 0.8
                                               else -loguniform(-3, 6))
        cases.append(("large_phi", phi * rng.choice((-1.0, 1.0)), m))
    for phi in (3.0e6, 1.0e7, 1.0e10, 1.0e15, 2.0 ** 52 - 1, 2.0 ** 52, 1.0e16, 1.0e17, 1.0e20,
                1.0e100, 1.0e300):
        for m in (0.0, 0.3, 0.9, 1.0 - 1e-9, -5.0, -1e6):
            cases.append(("huge_phi", phi, m))
    for _ in range(400):
        cases.append(("negative_m", rng.uniform(0, HALF_PI), -loguniform(-3, 12)))
    for _ in range(20):
        cases.append(("negative_m", rng.uniform(0, HALF_PI), -loguniform(12, 30)))
    for _ in range(300):
        m = loguniform(1e-6, 6)
        cases.append(("m_above_one", rng.uniform(0, 1) * math.asin(1 / math.sqrt(m)), m))
    for _ in range(40):
        m = loguniform(1e-6, 6)
        phi = math.asin(1 / math.sqrt(m))
        with mp.workdps(60):  # step down until sin^2(phi) <= 1/m holds exactly
            while mp.sin(mp.mpf(phi)) ** 2 * mp.mpf(m) > 1:
                phi = math.nextafter(phi, 0)
        cases.append(("m_above_one_edge", phi, m))
    return cases


def legendre():
    reseed("legendre")
    rows = []
    for region, phi, m in legendre_rows():
        dps = DPS + max(0, int(math.log10(abs(phi)))) + 5
        F = stable(mp.ellipf, phi, m, dps=dps)
        E = stable(mp.ellipe, phi, m, dps=dps)
        with mp.workdps(dps):
            P, M = mp.mpf(phi), mp.mpf(m)
            # Sensitivity of F to a relative perturbation of sin(phi), |d ln F / d ln sin phi|
            # = tan(phi) / (Delta F): for m > 1 near the edge sin^2(phi) = 1/m, Delta -> 0 and a
            # correctly rounded sin(phi) alone moves F by kappa_s * eps/2 (the problem is
            # ill-conditioned there; the tests allow for it in that region only).
            kappa = abs(mp.tan(P) / (mp.sqrt(1 - M * mp.sin(P) ** 2) * F)) if F != 0 else mp.mpf(0)
        with mp.workdps(DPS):
            rows.append([repr(phi), repr(m), out(F), out(E), mp.nstr(kappa, 6), region])
    write("elliptic_legendre.csv", ["phi", "m", "F", "E", "kappa_s", "region"], rows)


def edge_phi(m, t):
    """The double phi nearest arcsin(sqrt(t/m)) (t = m sin^2 phi <= 1), stepped down until
    m sin^2 phi <= 1 holds exactly (so the row is on the real domain)."""
    with mp.workdps(60):
        phi = float(mp.asin(mp.sqrt(mp.mpf(t) / mp.mpf(m))))
        while mp.sin(mp.mpf(phi)) ** 2 * mp.mpf(m) > 1:
            phi = math.nextafter(phi, 0)
    return phi


def edge_rows():
    """m > 1 next to the edge sin^2 phi = 1/m, where Delta^2 = 1 - m sin^2 phi cancels, and
    m -> 1 from above; t = m sin^2 phi is the distance to the edge."""
    cases = []
    for _ in range(300):  # large m, 1 - t from 0.3 down to 1e-16
        m = loguniform(0.3, 15)
        cases.append(("edge_large_m", edge_phi(m, 1.0 - 10.0 ** -rng.uniform(0.5, 16)), m))
    for _ in range(200):  # m -> 1 from above: phi near pi/2 and Delta^2 = c^2 - (m-1) s^2
        m = 1.0 + 10.0 ** -rng.uniform(1, 15.6)
        cases.append(("edge_m_near_one", edge_phi(m, 1.0 - 10.0 ** -rng.uniform(0.5, 16)), m))
    for _ in range(100):  # the last double phi on the domain
        m = loguniform(1e-9, 15) if rng.random() < 0.7 else 1.0 + 10.0 ** -rng.uniform(1, 15.6)
        cases.append(("edge_last", edge_phi(m, 1.0), m))
    for _ in range(40):  # m up to the largest doubles, phi anywhere on the domain
        m = loguniform(15, 308)
        cases.append(("edge_huge_m", edge_phi(m, rng.uniform(0.0, 1.0)), m))
    # the case: m = 1.46e5, m sin^2 phi = 0.9993
    cases.append(("edge_large_m", edge_phi(1.46e5, 0.9993), 1.46e5))
    for k in range(1, 5):  # m a few ulps above 1
        for _ in range(10):
            m = 1.0 + k * 2.0 ** -52
            cases.append(("edge_m_near_one", edge_phi(m, 1.0 - 10.0 ** -rng.uniform(0, 16)), m))
    return cases


def edge():
    reseed("edge")
    rows = []
    for region, phi, m in edge_rows():
        F = stable(mp.ellipf, phi, m)
        E = stable(mp.ellipe, phi, m)
        with mp.workdps(DPS):
            rows.append([repr(phi), repr(m), out(F), out(E), region])
    write("elliptic_legendre_edge.csv", ["phi", "m", "F", "E", "region"], rows)


def complete():
    reseed("complete")
    cases = []
    for _ in range(300):
        cases.append(("bulk", rng.uniform(0, 1)))
    for _ in range(300):
        cases.append(("near_one", 1.0 - 10.0 ** -rng.uniform(0, 16)))
    for k in range(1, 5):
        cases.append(("near_one", 1.0 - k * 2.0 ** -53))
    for _ in range(200):
        cases.append(("negative_m", -loguniform(-3, 12)))
    for _ in range(20):
        cases.append(("negative_m", -loguniform(12, 300)))
    for _ in range(50):
        cases.append(("tiny_m", rng.choice((-1.0, 1.0)) * loguniform(-300, -3)))
    # m -> -inf up to -DBL_MAX (appended last, so the rows above keep their random draws)
    for _ in range(10):
        cases.append(("negative_m", -loguniform(300, 308.25)))
    cases.append(("negative_m", -1.7976931348623157e308))
    rows = []
    with mp.workdps(DPS):
        for region, m in cases:
            rows.append([repr(m), out(stable(mp.ellipk, m)), out(stable(mp.ellipe, m)), region])
    write("elliptic_complete.csv", ["m", "K", "E", "region"], rows)


TABLES = {"rf_rd": carlson_rf_rd, "rj": carlson_rj, "rc": carlson_rc, "legendre": legendre,
          "edge": edge,
          "complete": complete}

if __name__ == "__main__":
    import sys
    # optional arguments: names of the tables to regenerate (default: all); each table has its
    # own random stream, so regenerating one leaves the others byte-identical.
    for name in (sys.argv[1:] or TABLES):
        TABLES[name]()
