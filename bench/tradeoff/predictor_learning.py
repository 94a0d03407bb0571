#!/usr/bin/env python3
"""Why the Python rows of run.py time shuffled inputs: the same 1e6-element F call on the uniform
set tiled 50 times (one 20000-input sequence repeated) and repeated 50 times in 50 random orders
(run.shuffled_order), per SIMD level on 1 thread, and scipy.special.ellipkinc beside it.

    PYTHONPATH=python python3 bench/tradeoff/predictor_learning.py     # ~20 s, prints a table

Each cell is the median over 8 calls of the wall time per element. A branch predictor learns the
branches of a sequence it has seen before, so a kernel whose branches follow its inputs reads
fast on a tiled array; the C++ side of the same effect is `profile_ellint_f --learning`.
"""
import pathlib
import statistics
import sys
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from run import read_column_file, shuffled_order  # noqa: E402


def per_element_ns(fn, args, out, calls=8):
    t = []
    for _ in range(calls):
        t0 = time.perf_counter()
        fn(*args, out=out)
        t.append((time.perf_counter() - t0) / len(out) * 1e9)
    return statistics.median(t)


def main():
    import gecko
    import scipy.special as sp
    ell = gecko.elliptic
    d = read_column_file(HERE.parent / "elliptic" / "data" / "legendre_uniform.bin")
    phi, m = d["phi"], d["m"]
    n = len(phi)
    tiled = [np.tile(phi, 50), np.tile(m, 50)]
    idx = shuffled_order(n, 50 * n)
    shuffled = [phi[idx], m[idx]]
    out = np.empty(50 * n)
    print("| F, 1e6 elements, 1 thread | tiled (ns/element) | shuffled (ns/element) |")
    print("|---|--:|--:|")
    before_l, before_t = ell.set_simd_level(ell.simd_levels()[0]), ell.set_num_threads(1)
    try:
        for lv in ell.simd_levels():
            ell.set_simd_level(lv)
            a = per_element_ns(ell.ufuncs.ellint_f, tiled, out)
            b = per_element_ns(ell.ufuncs.ellint_f, shuffled, out)
            print(f"| gecko ufunc, SIMD {lv} | {a:.1f} | {b:.1f} |")
    finally:
        ell.set_simd_level(before_l)
        ell.set_num_threads(before_t)
    a = per_element_ns(sp.ellipkinc, tiled, out)
    b = per_element_ns(sp.ellipkinc, shuffled, out)
    print(f"| scipy.special.ellipkinc | {a:.1f} | {b:.1f} |")


if __name__ == "__main__":
    main()
