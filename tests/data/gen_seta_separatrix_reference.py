#!/usr/bin/env python3
"""High-precision references for critical states recovered past a followed line's stall, on a
segment's separatrix (docs/theory/two_level_seta.md, "Long segments"; gecko/seta/detail/separatrix_limit.hpp).

Regenerate (from the repository root, with the package importable; about 15 min on one core):

    PYTHONPATH=python python3 tests/data/gen_seta_separatrix_reference.py   # writes seta_separatrix_reference.csv
    PYTHONPATH=python python3 tests/data/gen_seta_separatrix_reference.py --only design_8038
                                               # recomputes that case's rows, keeps the others

Each case is a design of the 10,000-design stress campaign (validation/data/stress_10000_states.npz,
whose line the solver gives up next to a separatrix) or of tests/seta/stress_regressions.cpp, at
requested Ft beyond that stall. gecko gives the state to be checked: its Fn, beta, rate signs and
turning points pick the branch and start the routes of seta_separatrix_mp.py, which compute the
state on their own in arbitrary precision: "quad" for every row, and "shoot" as well where the two
segments together are at most 40 elastic lengths long (beyond, the shots amplify the start's
error past their linear range). A row is written only where the routes converge and agree with
each other to 1e-20; the file holds the references, not gecko's values (the C++ test compares).
Cases marked "bracket" take the bracketing shot instead (seta_separatrix_mp.bracket_route: a sign
change of the backward shot's residual on both sides of gecko's Fn, bisected to well below 1e-25), written
only where its root has gecko's turning points and base rate: design 8038's beam ends next to its
saddle, where the quad route's assumed path class found another path's root.

Columns: case, the design (EI1 ... w, repr), Ft (repr), Fn and theta_joint (25 digits), the routes,
the beam's and the spatula's elastic lengths at the state, l sqrt(N (1 + N/EA) / EI) (in the
saddle's time constant, as the solver counts them).
"""
import argparse
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
    # campaign design 8038 (EA1 = 13.2): the beam at 100 to 110 times EA1, 5 lengths sqrt(EI1/N)
    # but 51 and 56 of its saddle's time constant, ends next to its saddle with no turning point;
    # solved once the solver counted lengths in that time constant (the campaign's two last Ft)
    ("design_8038", dict(EI1=51.64284421592708, EI2=1418.8611105558543, EA1=13.201065462389026,
                         EA2=596731.1231598184, l1=1.0, l2=0.002092828007026851, alpha1=0.4479891778773195,
                         alpha2=0.7243847721473664, w=1.0),
     [983.2112791861705, 1091.3645198966492], "bracket"),
    # campaign design 5688: its line stalls before Ft = 70.71 next to the beam's separatrix (the
    # beam 12.5 saddle time constants long there), where the beam is not yet deep enough for the
    # logarithmic law; the state comes from the full system started from the law's estimate (the
    # campaign's Ft >= 0)
    ("design_5688", dict(EI1=1.0919394358566248, EI2=1059.5565825146696, EA1=50.04322963938513,
                         EA2=2504.9055709030563, l1=1.0, l2=0.19186767111458192, alpha1=1.26600942073139,
                         alpha2=0.020954959876545963, w=1.0),
     [0.0, 18.62275352217643, 26.90403349944308, 63.702017431655584, 70.70923934913769], "bracket"),
    # campaign designs 4533 and 7821: no natural state by the homotopy alone (every path stalls
    # with the beam next to its separatrix, beta within 1e-3 of pi/2); the natural state past that
    # stall on the separatrix limit followed in lambda (gecko/seta/detail/natural_state.hpp). 7821
    # is one of the designs the Fn scan of validation/claims.py had found without a root at Ft = 0.
    ("natural_4533", dict(EI1=0.5520388505895616, EI2=319.6123765558719, EA1=19.620994288817034,
                          EA2=432770.30098404747, l1=1.0, l2=0.0019325934497122748, alpha1=1.0332181001624257,
                          alpha2=0.15799372909846707, w=1.0),
     [0.0], "bracket"),
    ("natural_7821", dict(EI1=0.17974480488164182, EI2=37.517065355427604, EA1=99320206.7627823, EA2=INF,
                          l1=1.0, l2=0.0014686552569921631, alpha1=1.4768479628067168, alpha2=0.03127759152129335,
                          w=1.0),
     [0.0], "bracket"),
    # campaign design 3664: the natural state's beam is 43 elastic lengths long, on its
    # separatrix, and the followed line fails at its first step; the state is marched to from there
    ("single_3664", dict(EI1=0.29057066956441524, EI2=63.62438201208349, EA1=6.08428269541901,
                         EA2=37.36091311154138, l1=1.0, l2=0.0010364878387884408, alpha1=0.07932555321778109,
                         alpha2=0.4805687627432984, w=1.0),
     [8.635534569003983], "bracket"),
    # campaign design 1005: four states given up in double (status not_reached) and solved by the
    # retry in long double (gecko/seta/critical_line.hpp, retry_in_long_double); the campaign's Ft
    ("long_double_1005", dict(EI1=0.27838952633169495, EI2=1.270807598552047, EA1=34629.42471111142,
                              EA2=87772.04693377482, l1=1.0, l2=0.09695729933128887, alpha1=1.006282082105714,
                              alpha2=0.2716690124304871, w=1.0),
     [164.2456444511225, 210.259320846518, 377.08184261870156, 418.5608453067587]),
    # campaign design 3413 at the campaign's Ft (the line depends on what is asked together): at
    # Ft = 2194.64 given up in double, where a march at a looser tolerance had found it 3.2e-11 off
    # (validation/README.md); the long-double retry solves it
    ("long_double_3413", dict(EI1=2.1508951161933365, EI2=30.884354342568855, EA1=198769.69423187207,
                              EA2=2413040.361922214, l1=1.0, l2=0.00167315803842591, alpha1=1.5134430654372117,
                              alpha2=0.0072006546136923815, w=1.0),
     [-2022.0768647123527, 0.0, 1679.9933874470153, 2118.025592969333, 1977.1508253833308, 2194.637416175497],
     "bracket"),
    # campaign design 809 at its Ft >= 0: at Ft = 2354.11, 2272.87 and 2522.88 given up in double and
    # refused by the long-double retry while it measured its limit segments at double's distances
    # (2^-36, 2^-38 of the scale); solved since the retry measures them 11 binades deeper
    # (gecko/seta/detail/separatrix_scales.hpp, separatrix_resolved_exponent_of)
    ("ld_exponents_809", dict(EI1=2.541220947447112, EI2=0.8454396224007961, EA1=INF, EA2=3188845.4880448803,
                              l1=1.0, l2=0.40457611073471206, alpha1=1.0384787826742332,
                              alpha2=0.08361018232993746, w=1.0),
     [0.0, 2354.1102792027564, 977.5472359614504, 2272.8681639357587, 2522.883661968692]),
    # campaign design 7498 at its Ft >= 0: at Ft = 1204.43, 1647.95 and 1829.23 the long-double
    # retry's march in the separatrix limit stalled while it solved each step to the state tolerance;
    # solved since it marches at the line's corrector tolerance and solves the targets to the state's
    # (gecko/seta/detail/separatrix_extend.hpp)
    ("ld_march_7498", dict(EI1=7.146342192897248, EI2=26.421606639568665, EA1=132922.89136859676,
                           EA2=1676388.069185779, l1=1.0, l2=0.002700768250546619, alpha1=0.11378581360818,
                           alpha2=1.171091789828089, w=1.0),
     [0.0, 507.751025979041, 1204.4298422874951, 1647.9528731371422, 1829.2276891822278], "bracket"),
    # campaign design 4 at its Ft >= 0: past the stall the beam's joint end lies 1.4e-3 to 1.6e-3 rad
    # short of its saddle; the march jumped at Ft = 1484.6 to the limit system's mirror solution (the
    # joint as far past it), which no path joins, and the four targets beyond were refused; solved
    # since a march step must keep the ends joined (separatrix_limit.hpp, keep_ends_joined). Only the
    # Ft = 0 row is written (the design for tests/seta/separatrix_limit.cpp): beyond the stall the
    # bracketing shot's root (383 s at Ft = 2973.78) agrees with gecko's state to 3.4e-13 in Fn and
    # 8.4e-13 in beta, but counts 3 beam turning points where gecko has 1 (a beam 111 saddle time
    # constants long, along its dwell), so those rows are skipped
    ("mirror_4", dict(EI1=6.1814893563583, EI2=0.009226371881874163, EA1=121.6626539128651,
                      EA2=7304187.041320352, l1=1.0, l2=0.023379923162900548, alpha1=0.14168477925176245,
                      alpha2=0.20921904959409632, w=1.0),
     [0.0, 2973.778736877619, 3242.789375309997, 3439.8812489588895, 3818.268186344367], "bracket"),
    # campaign design 161 at its Ft >= 0: the march from the stall (Ft = 1398.4) passes the beam's base
    # through its saddle; it had left the line's sign of theta1'(0) (free in the limit) at its first
    # step and at the saddle carried it through zero to ends no path joins, reaching states with it
    # negative and 2 beam turning points at Ft = 5485.91 and 6089.36; the line traced in long double
    # passes the saddle with it going from negative to positive, and so does the march now
    # (keep_ends_joined)
    ("keep_sign_161", dict(EI1=12.376631898614459, EI2=78.90141459857232, EA1=9427.124080909207,
                           EA2=18577286.88917405, l1=1.0, l2=0.0032156233172321263, alpha1=1.1796087523064642,
                           alpha2=0.3203384356322046, w=1.0),
     [0.0, 1868.976729507951, 5485.909656607731, 6089.359718834582], "bracket"),
    # campaign design 1298 at its Ft >= 0: the march in Ft from the stall (Ft = 2480.5, the beam on its
    # separatrix) collapsed at Ft = 2588.6, in double and in the long-double retry, where Newton in
    # Ft no longer converges on the limit system; the retry's march goes on in arclength
    # (gecko/seta/detail/separatrix_arclength.hpp) and reaches the three targets beyond, given up
    # before (status 6)
    ("arclength_1298", dict(EI1=36.245267076835034, EI2=78.07600430546631, EA1=537.0914253154813,
                            EA2=8367569.608136437, l1=1.0, l2=0.007244529394974517, alpha1=0.93690330178437,
                            alpha2=0.4760023971554903, w=1.0),
     [0.0, 2766.188288194081, 3681.7744044388473, 4086.7695889271204], "bracket"),
    # campaign design 9080 at its Ft >= 0: the line stalls with the beam on its separatrix and the
    # limit system does not converge at its last node; the long-double retry starts the march from
    # a node before it (gecko/seta/detail/separatrix_extend.hpp) and solves Ft = 66.99, given up
    # before (status 6)
    ("back_9080", dict(EI1=0.25274405807769323, EI2=3.654208814250192, EA1=526.2736245309839,
                       EA2=2248.5938342403933, l1=1.0, l2=0.09695371858454302, alpha1=1.472203933340284,
                       alpha2=0.022471702581845002, w=1.0),
     [0.0, 66.99401309319731], "bracket"),
    # campaign design 3486 at its Ft < 0: the march in Ft collapsed at Ft = -35.06 at a fold of the
    # line in Ft; the long-double retry's march in arclength passes it and a second fold (Ft = -24.8), and first crosses
    # Ft = -35.1 and the campaign's -42.44 after that (the beam 110 saddle time constants long at
    # -42.44), given up before (status 6)
    ("arclength_fold_3486", dict(EI1=0.11546095077417291, EI2=16.247827063242536, EA1=2939.689102634065,
                                 EA2=1175.383240544916, l1=1.0, l2=0.015299552565151316,
                                 alpha1=1.4289756157007119, alpha2=0.13038104532825864, w=1.0),
     [0.0, -35.1, -42.44250662834663]),
    # campaign design 2840 at its Ft >= 0: the march in Ft from the stall reached Ft = 39.96 and its
    # state was refused; solved since the test whether a path joins a limit state's ends looks no
    # farther from the separatrix than a quarter of the nearer end's own f3, in long double
    # (gecko/seta/detail/separatrix_limit.hpp, joining_distance)
    ("joining_2840", dict(EI1=0.14451090840449854, EI2=0.8741230635762312, EA1=73850.32557084705,
                          EA2=799.8279841391821, l1=1.0, l2=0.0012128223780860626, alpha1=1.2215087896352859,
                          alpha2=0.3270547335484607, w=1.0),
     [0.0, 39.95570367291479], "bracket"),
]
AGREE = 1e-20


def bracket_row(name, d, Ft, Fn, beta, q, turns, L1, L2):
    """The row of a "bracket" case, or None where the bracketing shot does not confirm the branch."""
    t = time.time()
    b = ssm.bracket_route(d, Ft, Fn, L1 + L2)
    if b is None or tuple(b["turns"]) != turns or abs(float(b["q"]) - q) > 1e-8 * max(1, abs(q)):
        print(f"{name} Ft={Ft}: the bracketing shot found no root on gecko's branch, skipped", flush=True)
        return None
    print(f"{name} Ft={Ft}: shot bracket, lengths {L1:.1f} {L2:.1f}, gecko dFn "
          f"{abs(float(b['Fn']) - Fn) / max(1, abs(Fn)):.2e} dbeta {abs(float(b['beta']) - beta):.2e} "
          f"({time.time() - t:.0f} s)", flush=True)
    return [name] + [repr(d[k]) for k in KEYS] + [repr(Ft), mp.nstr(b["Fn"], 25), mp.nstr(b["beta"], 25),
                                                   "shot bracket", f"{L1:.1f}", f"{L2:.1f}"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", action="append", default=None,
                    help="recompute only this case's rows (repeatable); the file's other rows are kept")
    args = ap.parse_args(argv)
    path = os.path.join(HERE, "seta_separatrix_reference.csv")
    rows = []
    if args.only:
        with open(path, newline="") as f:
            rows = [r for r in list(csv.reader(f))[1:] if r[0] not in args.only]
    t0 = time.time()
    for name, d, fts, *how in CASES:
        if args.only and name not in args.only:
            continue
        line = gecko.TwoLevelSeta(**d).critical_line(Ft=fts, errors="nan")
        for k, Ft in enumerate(fts):
            if int(line.status[k]) not in (0, 7):
                print(f"{name} Ft={Ft}: gecko status {int(line.status[k])}, skipped", flush=True)
                continue
            Fn, beta = float(line.Fn[k]), float(line.theta_joint[k])
            p, q = float(line.theta_rate_joint[k]), float(line.theta_rate_base[k])
            turns = (int(line.turning_points_beam[k]), int(line.turning_points_spatula[k]))
            N = math.hypot(Fn, Ft)
            L1, L2 = ssm.saddle_lengths(d, N)
            if how == ["bracket"]:
                row = bracket_row(name, d, Ft, Fn, beta, q, turns, L1, L2)
                if row is not None:
                    rows.append(row)
                continue
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
    order = [c[0] for c in CASES]
    rows.sort(key=lambda r: order.index(r[0]) if r[0] in order else len(order))  # stable: Ft order kept
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case"] + KEYS + ["Ft", "Fn", "theta_joint", "route", "elastic_beam", "elastic_spatula"])
        w.writerows(rows)
    print(f"{len(rows)} rows, {time.time() - t0:.0f} s")


if __name__ == "__main__":
    main()
