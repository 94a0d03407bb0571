#!/usr/bin/env python3
"""High-precision references for critical states recovered past a followed line's stall, on a
segment's separatrix (docs/theory/two_level_seta.md, "Long segments"; gecko/seta/detail/separatrix_limit.hpp).

Regenerate (from the repository root, with the package importable; about 15 min on one core):

    PYTHONPATH=python python3 tests/data/gen_seta_separatrix_reference.py   # writes seta_separatrix_reference.csv

Each case is a design of the 10,000-design stress campaign (validation/data/stress_10000_states.npz,
whose line the solver gives up next to a separatrix) or of tests/seta/stress_regressions.cpp, at
requested Ft beyond that stall. gecko gives the state to be checked: its Fn, beta, rate signs and
turning points pick the branch and start the routes of seta_separatrix_mp.py, which compute the
state on their own in arbitrary precision: "quad" for every row, and "shoot" as well where the two
segments together are at most 40 elastic lengths long (beyond, the shots amplify the start's
error past their linear range). A row is written only where the routes converge and agree with
each other to 1e-20; the file holds the references, not gecko's values (the C++ test compares).

Columns: case, the design (EI1 ... w, repr), Ft (repr), Fn and theta_joint (25 digits), the routes,
the beam's and the spatula's elastic lengths l sqrt(N/EI) at the state.
"""
import csv
import math
import os
import sys
import time

from mpmath import mp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import seta_separatrix_mp as ssm  # noqa: E402

import gecko  # noqa: E402

KEYS = ["EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w"]
INF = math.inf
CASES = [
    # campaign design 27: the spatula's line stalls at Ft = 145 (both segments next to their
    # separatrices); the campaign's Ft and two more
    ("design_27", dict(EI1=0.5076164033907399, EI2=0.06706270609618208, EA1=INF, EA2=39748588.326308906, l1=1.0,
                       l2=0.49011261393297356, alpha1=1.0891675965536387, alpha2=0.41266820231735746, w=1.0),
     [200.0, 1000.0, 6798.444063955389, 8024.507030878622]),
    # tests/seta/stress_regressions.cpp, the third crawl case
    ("crawl_81", dict(EI1=10.925496115802561, EI2=1447.2560672430527, EA1=12758778.242423614,
                      EA2=60395409.89601219, l1=1.0, l2=0.22048726230309484, alpha1=1.209227157850754,
                      alpha2=0.2526114036724534, w=1.0),
     [10979.497208126613]),
]
AGREE = 1e-20


def main():
    rows = []
    t0 = time.time()
    for name, d, fts in CASES:
        line = gecko.TwoLevelSeta(**d).critical_line(Ft=fts, errors="nan")
        for k, Ft in enumerate(fts):
            if int(line.status[k]) not in (0, 7):
                print(f"{name} Ft={Ft}: gecko status {int(line.status[k])}, skipped", flush=True)
                continue
            Fn, beta = float(line.Fn[k]), float(line.theta_joint[k])
            p, q = float(line.theta_rate_joint[k]), float(line.theta_rate_base[k])
            turns = (int(line.turning_points_beam[k]), int(line.turning_points_spatula[k]))
            N = math.hypot(Fn, Ft)
            L1, L2 = d["l1"] * math.sqrt(N / d["EI1"]), d["l2"] * math.sqrt(N / d["EI2"])
            mp.dps = int(40 + (L1 + L2) / 2)
            t = time.time()
            r = ssm.quad_route(d, Ft, Fn, beta, 1 if p > 0 else -1, 1 if q > 0 else -1, turns,
                               (L1 >= 15 and turns[0] > 0, L2 >= 15 and turns[1] > 0))
            if r is None:
                print(f"{name} Ft={Ft}: quad route did not converge, skipped", flush=True)
                continue
            if not r[3] < 1e-20:
                print(f"{name} Ft={Ft}: quadrature error estimate {float(r[3]):.1e}, skipped", flush=True)
                continue
            Fn_ref, beta_ref = r[0], r[1]
            route = "quad"
            if L1 + L2 <= 40:
                s = ssm.shoot_route(d, Ft, Fn, q)
                if s is None or abs(s[0] - Fn_ref) > AGREE * max(1, abs(Fn_ref)) or abs(s[1] - beta_ref) > AGREE:
                    print(f"{name} Ft={Ft}: shooting route disagrees or failed, skipped", flush=True)
                    continue
                route = "quad+shoot"
            print(f"{name} Ft={Ft}: {route}, lengths {L1:.1f} {L2:.1f}, gecko dFn "
                  f"{abs(float(Fn_ref) - Fn) / max(1, abs(Fn)):.2e} dbeta {abs(float(beta_ref) - beta):.2e} "
                  f"({time.time() - t:.0f} s)", flush=True)
            rows.append([name] + [repr(d[k]) for k in KEYS] +
                        [repr(Ft), mp.nstr(Fn_ref, 25), mp.nstr(beta_ref, 25), route, f"{L1:.1f}", f"{L2:.1f}"])
    with open(os.path.join(HERE, "seta_separatrix_reference.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case"] + KEYS + ["Ft", "Fn", "theta_joint", "route", "elastic_beam", "elastic_spatula"])
        w.writerows(rows)
    print(f"{len(rows)} rows, {time.time() - t0:.0f} s")


if __name__ == "__main__":
    main()
