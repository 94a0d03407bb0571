#!/usr/bin/env python3
"""Inputs and mpmath references for the R_D and R_J rows of the run-time-against-error harness.

    python3 bench/tradeoff/gen_inputs.py [--n 4000] [--out DIR]     # ~10 s

Writes bench/tradeoff/data/{carlson_rd,carlson_rj}.bin (committed, ~0.3 MB together), in the
GECKOBENCH1 column format of bench/elliptic/gen_inputs.py (same writer, same reference split
ref = hi + float32 lo, same 40 digits at the exact double inputs), so the C++ side reads them with
bench/elliptic/data_file.hpp. The other kernels (F, E, R_F) reuse bench/elliptic/data.

Input sets, the same scale-free distribution as bench/elliptic's R_F set (fixed seed):
  carlson_rd : x, y, z independently log-uniform in [1e-6, 1e6]; in 5 % of the rows x or y
               (chosen at random) is exactly 0 (R_D allows one of x, y zero; z > 0).
  carlson_rj : x, y, z, p log-uniform in [1e-6, 1e6]; in 5 % of the rows one of x, y, z is 0.
               p > 0 only: the Cauchy principal value (p < 0) is ill-conditioned (its terms cancel,
               see tests/data/gen_elliptic.py) and GSL does not offer it, so it is no speed peer row.

Self-check (the script fails if it fails): a sample recomputed at 60 digits agrees with the
stored hi + lo to 1e-22 relative.
"""
import argparse
import importlib.util
import pathlib
import sys
import time

import mpmath as mp
import numpy as np

SEED = 20261122
DPS = 40
HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE / "data"

# Reuse the writer and the reference split of bench/elliptic (one file format for both benches).
_spec = importlib.util.spec_from_file_location("elliptic_gen", HERE.parent / "elliptic" / "gen_inputs.py")
_eg = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_eg)


def _log_uniform(rng, shape):
    return 10.0 ** rng.uniform(-6.0, 6.0, shape)


def make_inputs(n, rng):
    """(x, y, z) for R_D and (x, y, z, p) for R_J, as described in the module docstring."""
    xyz = _log_uniform(rng, (3, n))
    zero = np.nonzero(rng.random(n) < 0.05)[0]
    xyz[rng.integers(0, 2, zero.size), zero] = 0.0  # x or y
    rd = tuple(xyz)
    xyzp = _log_uniform(rng, (4, n))
    zero = np.nonzero(rng.random(n) < 0.05)[0]
    xyzp[rng.integers(0, 3, zero.size), zero] = 0.0  # x, y or z
    rj = tuple(xyzp)
    return rd, rj


def references(fn, args):
    mp.mp.dps = DPS
    pairs = [_eg._split(fn(*(mp.mpf(float(a)) for a in row))) for row in zip(*args)]
    hi, lo = zip(*pairs)
    return np.array(hi, dtype=np.float64), np.array(lo, dtype=np.float32)


def check(fn, args, hi, lo, rng, count=40):
    mp.mp.dps = 60
    bad = 0
    for i in rng.choice(len(hi), count, replace=False):
        want = fn(*(mp.mpf(float(a[i])) for a in args))
        got = mp.mpf(float(hi[i])) + mp.mpf(float(lo[i]))
        if abs(got - want) > mp.mpf("1e-22") * abs(want):
            bad += 1
            print("  60-digit mismatch", [a[i] for a in args], got, want)
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=4000, help="rows per input set (default 4000)")
    ap.add_argument("--out", type=pathlib.Path, default=DATA, help=f"output folder (default {DATA})")
    args = ap.parse_args()
    rng = np.random.default_rng(SEED)
    rd, rj = make_inputs(args.n, rng)
    args.out.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    print(f"mpmath {mp.__version__}, numpy {np.__version__}, {DPS} digits, seed {SEED}")
    crng = np.random.default_rng(SEED + 1)
    bad = 0
    for name, fn, cols, inputs in (("carlson_rd", mp.elliprd, "xyz", rd), ("carlson_rj", mp.elliprj, "xyzp", rj)):
        hi, lo = references(fn, inputs)
        key = "R" + name[-1].upper()
        columns = {c: a for c, a in zip(cols, inputs)}
        columns.update({key: hi, key + "_lo": lo})
        _eg._write(args.out / f"{name}.bin", columns)
        bad += check(fn, inputs, hi, lo, crng)
    print(f"self-checks: {'OK' if bad == 0 else f'{bad} FAILED'}; total {time.time() - t0:.0f} s")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
