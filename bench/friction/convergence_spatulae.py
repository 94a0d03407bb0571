#!/usr/bin/env python3
"""Observed convergence rate of simulate_spatulae to the mean field (steady_sliding, eqs 9-10
with finite t_off): RMS error of the time-averaged lateral force over R seeds, for a grid of
spatula counts M and durations T, and the least-squares exponents of RMS ~ M^a T^b.

    python3 bench/friction/convergence_spatulae.py [--seeds 100]
"""
import argparse

import numpy as np

import gecko


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=100)
    a = ap.parse_args()
    V, t_off = 1e-4, 1e-3
    mf = gecko.steady_sliding(V, t_off=t_off)
    P = mf.t_on + t_off
    for resticking in ("exponential", "fixed"):
        rows = []
        for M in (25, 100, 400):
            for k in (10.5, 42.5, 170.5):  # durations in periods; the half keeps T/P non-integer
                e = np.array([gecko.simulate_spatulae(V, spatulae=M, duration=k * P, t_off=t_off,
                                                      resticking=resticking, samples=2,
                                                      seed=1 + s + 100000 * M + int(10 * k)).mean_par
                              for s in range(a.seeds)]) - mf.F_par
                rows.append((M, k, np.sqrt(np.mean(e ** 2)) / mf.F_par, np.mean(e) / mf.F_par))
        A = np.array([[1, np.log(M), np.log(k)] for M, k, _, _ in rows])
        y = np.log([r[2] for r in rows])
        coef, *_ = np.linalg.lstsq(A, y, rcond=None)
        print(f"{resticking} re-sticking (t_off = {t_off:g} s, t_on = {mf.t_on:.3g} s):")
        for M, k, rms, bias in rows:
            print(f"  M = {M:4d}  T = {k:6.1f} periods  RMS rel. error {rms:.3e}  mean {bias:+.1e}")
        print(f"  fit: RMS ~ M^{coef[1]:.3f} T^{coef[2]:.3f}")


if __name__ == "__main__":
    main()
