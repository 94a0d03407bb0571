#!/usr/bin/env python3
"""Inputs and mpmath references for the elliptic-kernel benchmark (bench/elliptic/).

Run from anywhere:   python3 bench/elliptic/gen_inputs.py [--jobs 2] [--n 20000] [--out DIR]
Writes bench/elliptic/data/{legendre_uniform,legendre_near1,carlson_rf}.bin (committed; about
80 s with 2 processes). Try a smaller --n only with --out elsewhere: it would replace the data.
Fixed seed: the output is bit-for-bit reproducible with the same numpy / mpmath versions.

Input sets (the issue's distributions):
  legendre_uniform : phi ~ U(0, pi/2),  m ~ U(0, 1)
  legendre_near1   : phi ~ U(0, pi/2),  m = 1 - 10**-U(0, 16)   (evaluated in double; m < 1 always,
                     since 10**-16 > 2**-54 = half the spacing of doubles just below 1)
  carlson_rf       : x, y, z independently log-uniform in [1e-6, 1e6]; in 5 % of the rows one of
                     the three (chosen at random) is set to exactly 0 (R_F allows one zero argument).
                     R_F gets its own arguments rather than the (cos^2 phi, 1 - m sin^2 phi, 1)
                     of the Legendre sets, so that it is measured over its whole scale-free domain,
                     independent of how gecko happens to reduce F to R_F.

References: mpmath at 40 significant digits evaluated at the *exact* double inputs, stored as a
double-double-like pair  ref = hi + lo  (hi = ref rounded to double, lo = float32(ref - hi)), so a
measured error is not blurred by the 0.5 ulp rounding of a plain double reference.

The peers (Boost, GSL, std::) take the modulus k instead of m. The benchmark passes them
k = sqrt(m) rounded to double (IEEE sqrt is correctly rounded, so C++ std::sqrt and numpy.sqrt agree
bit for bit), and k*k != m in general: near m = 1 this rounding alone costs a lot. To separate that
(an API cost a user with m pays) from the peer's own accuracy, the files also hold the reference at
the peer's actual input, m_k = k*k computed exactly, as a float32 delta  dFk = F(phi, m_k) - F(phi, m)
(checked to blur that reference by less than 0.01 eps).

Binary format (little-endian), one file per input set: one ASCII header line
    GECKOBENCH1 n=<rows> columns=<name>:<f8|f4>,...\\n
followed by the columns one after the other (column-major), each n values of its type.

Self-checks (printed, and the script fails if they fail): a sample recomputed at 60 digits must
agree with the stored hi + lo to 1e-22 relative; so must a sample of F and E recomputed by
independent numerical quadrature (mpmath.quad of the defining integrals at 34 digits).
"""
import argparse
import multiprocessing as mproc
import pathlib
import sys
import time

import mpmath as mp
import numpy as np

SEED = 20261121
DPS = 40
HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE / "data"


def _split(ref):
    hi = float(ref)  # mpmath rounds to nearest
    lo = np.float32(float(ref - mp.mpf(hi)))
    return hi, lo


def _legendre_rows(args):
    phis, ms = args
    mp.mp.dps = DPS
    out = []
    for phi, m in zip(phis, ms):
        P, M = mp.mpf(float(phi)), mp.mpf(float(m))
        k = float(np.sqrt(np.float64(m)))
        Mk = mp.mpf(k) ** 2  # exact: 106 bits fit in 40 digits (~133 bits)
        F = mp.ellipf(P, M)
        E = mp.ellipe(P, M)
        Fk = mp.ellipf(P, Mk) if Mk != M else F
        Ek = mp.ellipe(P, Mk) if Mk != M else E
        Fh, Fl = _split(F)
        Eh, El = _split(E)
        out.append((Fh, Fl, Eh, El, np.float32(float(Fk - F)), np.float32(float(Ek - E))))
    return out


def _rf_rows(args):
    xs, ys, zs = args
    mp.mp.dps = DPS
    return [_split(mp.elliprf(mp.mpf(float(x)), mp.mpf(float(y)), mp.mpf(float(z))))
            for x, y, z in zip(xs, ys, zs)]


def _chunks(arrays, nchunks):
    idx = np.array_split(np.arange(len(arrays[0])), nchunks)
    return [tuple(a[i] for a in arrays) for i in idx]


def _write(path, cols):
    n = len(next(iter(cols.values())))
    spec = ",".join(f"{name}:{'f8' if a.dtype == np.float64 else 'f4'}" for name, a in cols.items())
    with open(path, "wb") as f:
        f.write(f"GECKOBENCH1 n={n} columns={spec}\n".encode("ascii"))
        for a in cols.values():
            assert len(a) == n
            f.write(a.astype(a.dtype.newbyteorder("<")).tobytes())
    print(f"  wrote {path} ({path.stat().st_size / 1e6:.2f} MB)")


def _legendre(pool, out, name, phi, m, jobs):
    t = time.time()
    rows = [r for part in pool.map(_legendre_rows, _chunks((phi, m), 8 * jobs)) for r in part]
    F, Fl, E, El, dFk, dEk = (np.array(c) for c in zip(*rows))
    Fl, El = Fl.astype(np.float32), El.astype(np.float32)
    # The float32 deltas carry 24 bits: harmless while |delta/ref| stays tiny (here <= 2.2e-11, i.e.
    # < 0.01 eps of blur on the "own k" reference). Fail loudly if new inputs break that.
    blur = max(np.max(np.abs(dFk.astype(np.float64)) / np.abs(F)),
               np.max(np.abs(dEk.astype(np.float64)) / np.abs(E))) * 2.0**-24 / 2.0**-52
    assert blur < 0.01, f"{name}: float32 delta blurs the own-k reference by {blur:.3g} eps"
    _write(out / f"{name}.bin", {
        "phi": phi, "m": m,
        "F": F.astype(np.float64), "F_lo": Fl.astype(np.float32),
        "E": E.astype(np.float64), "E_lo": El.astype(np.float32),
        "dFk": dFk.astype(np.float32), "dEk": dEk.astype(np.float32)})
    print(f"  {name}: {time.time() - t:.0f} s")
    return (F, Fl), (E, El)


def _check(phi, m, F, E, x, y, z, RF, rng):
    """Independent checks of the stored references hi + lo on samples (see module docstring).

    The float32 lo carries ~24 bits below hi's last bit, so hi + lo is good to ~2^-77 relative:
    the tolerance 1e-22 checks every stored digit that matters for an error in units of 2^-52."""
    tol = mp.mpf("1e-22")
    bad = 0
    stored = lambda pair, i: mp.mpf(float(pair[0][i])) + mp.mpf(float(pair[1][i]))
    mp.mp.dps = 60
    for i in rng.choice(len(phi), 40, replace=False):
        for got, want in ((stored(F, i), mp.ellipf(phi[i], m[i])),
                          (stored(E, i), mp.ellipe(phi[i], m[i]))):
            if abs(got - want) > tol * abs(want):
                bad += 1
                print("  60-digit mismatch", phi[i], m[i], got, want)
    for i in rng.choice(len(x), 40, replace=False):
        want = mp.elliprf(x[i], y[i], z[i])
        if abs(stored(RF, i) - want) > tol * abs(want):
            bad += 1
            print("  60-digit mismatch RF", x[i], y[i], z[i], RF[i], want)
    # Quadrature of the defining integrals, t in [0, phi]; tanh-sinh copes with the near-singular
    # end point when m -> 1 and phi -> pi/2 once the interval is split geometrically towards phi.
    mp.mp.dps = 34
    for i in rng.choice(len(phi), 12, replace=False):
        P, M = mp.mpf(phi[i]), mp.mpf(m[i])
        pts = [0] + [P - (P / 2) ** j for j in range(1, 12) if P - (P / 2) ** j > 0] + [P]
        pts = sorted(set(pts))
        qf = mp.quad(lambda t: 1 / mp.sqrt(1 - M * mp.sin(t) ** 2), pts)
        qe = mp.quad(lambda t: mp.sqrt(1 - M * mp.sin(t) ** 2), pts)
        for got, want, what in ((stored(F, i), qf, "F"), (stored(E, i), qe, "E")):
            if abs(got - want) > tol * abs(want):
                bad += 1
                print(f"  quadrature mismatch {what}", phi[i], m[i], got, want)
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--jobs", type=int, default=2, help="worker processes (default 2)")
    ap.add_argument("--n", type=int, default=20000, help="rows per input set (default 20000)")
    ap.add_argument("--out", type=pathlib.Path, default=DATA, help=f"output folder (default {DATA})")
    args = ap.parse_args()
    out = args.out

    rng = np.random.default_rng(SEED)
    n = args.n
    half_pi = np.pi / 2
    phi_u = rng.uniform(0.0, half_pi, n)
    m_u = rng.uniform(0.0, 1.0, n)
    phi_1 = rng.uniform(0.0, half_pi, n)
    m_1 = 1.0 - 10.0 ** -rng.uniform(0.0, 16.0, n)
    assert np.all(m_1 < 1.0) and np.all(phi_u < half_pi) and np.all(phi_1 < half_pi)
    logs = rng.uniform(-6.0, 6.0, (3, n))
    xyz = 10.0 ** logs
    zero_row = rng.random(n) < 0.05
    zero_col = rng.integers(0, 3, n)
    xyz[zero_col[zero_row], np.nonzero(zero_row)[0]] = 0.0
    x, y, z = xyz

    out.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    print(f"mpmath {mp.__version__}, numpy {np.__version__}, {DPS} digits, seed {SEED}, {args.jobs} jobs")
    with mproc.Pool(args.jobs) as pool:
        F_u, E_u = _legendre(pool, out, "legendre_uniform", phi_u, m_u, args.jobs)
        F_1, E_1 = _legendre(pool, out, "legendre_near1", phi_1, m_1, args.jobs)
        t = time.time()
        rows = [r for part in pool.map(_rf_rows, _chunks((x, y, z), 8 * args.jobs)) for r in part]
        RF, RFl = (np.array(c) for c in zip(*rows))
        RFl = RFl.astype(np.float32)
        _write(out / "carlson_rf.bin", {"x": x, "y": y, "z": z,
                                        "RF": RF.astype(np.float64), "RF_lo": RFl.astype(np.float32)})
        print(f"  carlson_rf: {time.time() - t:.0f} s")
    crng = np.random.default_rng(SEED + 1)
    cat = lambda a, b: (np.concatenate([a[0], b[0]]), np.concatenate([a[1], b[1]]))
    bad = _check(np.concatenate([phi_u, phi_1]), np.concatenate([m_u, m_1]),
                 cat(F_u, F_1), cat(E_u, E_1), x, y, z, (RF, RFl), crng)
    print(f"self-checks: {'OK' if bad == 0 else f'{bad} FAILED'}; total {time.time() - t0:.0f} s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
