#!/usr/bin/env python3
"""Where and why the followed critical line stops short: the give-ups of issue 13, item 5.

A state is ``not_reached`` (status 6) when the line followed from Ft = 0 stopped before its Ft
without ending: the corrector failed at the smallest step (``LineEnd.no_convergence``), the step
collapsed (``LineEnd.stalled``: 1000 attempts advanced less than 1 % of the force scale), or the
point budget ran out (``LineEnd.max_points``). This takes a seeded sample of the designs of the
stress campaign's states (validation/data/stress_10000_states.npz) that have a status-6 state,
re-traces each line as the solver on PYTHONPATH does for those states (from Ft = 0 to the largest
requested Ft of the design, raw continuation nodes), and describes the last node, where the line
stopped, by the quantities that make the equations singular there (paper 001 eqs 2-5, 12, 15):

* each segment's distance from its separatrix, R(1) / (|M| + N): with the first integral
  EI/2 theta'^2 = R(u) = M - N u - c N^2 u^2 / 2, u = sin(theta - phi), phi = atan2(Fn, Ft)
  (eqs 8, 12; the beam's M from the joint, eq 4), R(1) = 0 is the orbit through the saddle (theta'
  = 0 with the segment aligned with the force), between libration and rotation. There a
  libration's period diverges (logarithmically in the distance), the solver's forms for the
  segment's length switch between the libration and the rotation kind, and the length equation's
  derivatives grow without bound; a path that runs close to the saddle has a length ~ log of the
  distance. Each segment's length in elastic lengths, l sqrt(N / EI), is reported beside it;
* the joint rate theta2'(l1) and the base rate theta1'(0), each relative to sqrt(2 w / EI) of its
  segment: 0 is a turning point on the segment's end, where its phase plan changes;
* 1 - u at the joint;
* the axial load relative to the axial rigidity, N / EA of each segment (N = hypot(Fn, Ft), 0 for
  EA = inf): the size of the forms' extensibility term c N;
* each segment's distance from the edge of the forms, 1 - b4: R(u) = f3(u) f4(u) with
  f4 = 1 + b4 u, b4 = c N / (1 + sqrt(1 + 2 c M)) (gecko/seta/elastica_segment.hpp), and the forms
  exist for b4 < 1 (f4's root -1/b4 outside [-1, 1]); b4 = 1 is R(-1) = 0 (1 for EA = inf);
* the beam's stretch 1 + T/EA1 at its joint end (T = N u, the axial force of eqs 1-2): <= 0 is a
  beam compressed by EA1 or more there, which the linear law maps to a length <= 0.

Mechanism per design (thresholds on the last node, in this order):

* ``spatula_separatrix``, ``beam_separatrix``: that segment within 1e-3 of its separatrix (the
  distances are reported in decades: most are far closer);
* ``beam_forms_edge``, ``spatula_forms_edge``: that segment within 1e-9 of the edge of the forms
  (1 - b4); ``on_forms_edge_since_ft`` says from which Ft the line ran along it to its end;
* ``joint_turning_point``: relative joint rate < 1e-2;
* ``base_turning_point``: relative base rate < 1e-2;
* ``other``: none of these;
* ``now_reached``: the line no longer stops short with this solver (the campaign's status 6 was
  an earlier solver's).

    PYTHONPATH=python:. python3 -m validation.line_ends [--sample 200] [--seed 0] [--control 200] [--json F.json]
    PYTHONPATH=python:. python3 -m validation.line_ends --lengths validation/rerun_10000.npz [--json F.json]

``--lengths`` takes no trace: it reports, by status, how many elastic lengths l sqrt(N / EI) the
longer segment of each state has (``lengths`` below), and, for a ``recheck --save`` file, how close
the solved states come to the edge of the forms (``forms_edge_solved``) and which have a stretch
<= 0 at a segment end (``end_stretch_solved``).

``--control N`` traces N designs whose lines reach every requested Ft and reports how close they
come to a separatrix anywhere along the line, for comparison with where the given-up lines stop
(validation/README.md gives the numbers).
"""
from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np

from .campaign import FIELDS, compliances
from .recheck import STATES

GIVEN_UP = ("no_convergence", "stalled", "max_points")


def beam_first_integral(EI1, EI2, c1, k2_sq, N, v):
    """The beam's first-integral constant M1 from the joint (eq 4): moment continuity gives
    theta1' = EI2 / EI1 theta2' there, at the beam's u = v = sin(theta_joint - alpha2 - phi)."""
    return EI1 / 2 * (EI2 / EI1) ** 2 * k2_sq + N * v + c1 * N * N * v * v / 2


def forms_edge_distance(c, N, M):
    """1 - b4 of a segment, b4 = c N / (1 + sqrt(1 + 2 c M)) (f4 = 1 + b4 u,
    gecko/seta/elastica_segment.hpp): the forms exist for b4 < 1."""
    return 1.0 - c * N / (1.0 + np.sqrt(1.0 + 2.0 * c * M))


def node_quantities(line, d: dict) -> dict:
    """The quantities of the module docstring at every node of a traced line (arrays)."""
    ft, fn, beta = (np.asarray(a, float) for a in (line.Ft, line.Fn, line.theta_joint))
    k2 = np.asarray(line.theta_rate_joint, float)
    phi = np.arctan2(fn, ft)
    N = np.hypot(fn, ft)
    c1 = 0.0 if math.isinf(d["EA1"]) else 1.0 / d["EA1"]
    c2 = 0.0 if math.isinf(d["EA2"]) else 1.0 / d["EA2"]
    # first integrals (eqs 8, 12): EI/2 theta'^2 = R(u) = M - N u - c N^2 u^2 / 2, u = sin(theta - phi);
    # R(1) = 0 is the separatrix (the saddle at u = 1 on the orbit)
    M2 = ft + d["w"]
    v = np.sin(beta - d["alpha2"] - phi)
    M1 = beam_first_integral(d["EI1"], d["EI2"], c1, k2 * k2, N, v)
    return {"Ft": ft, "Fn": fn, "beta": beta,
            "joint_rate_rel": np.abs(k2) / math.sqrt(2 * d["w"] / d["EI2"]),
            "base_rate_rel": np.abs(np.asarray(line.theta_rate_base, float)) / math.sqrt(2 * d["w"] / d["EI1"]),
            "one_minus_u": 1.0 - np.sin(beta - phi),
            "spatula_separatrix": (M2 - N - c2 * N * N / 2) / (np.abs(M2) + N),
            "beam_separatrix": (M1 - N - c1 * N * N / 2) / (np.abs(M1) + N),
            "spatula_elastic_lengths": d["l2"] * np.sqrt(N / d["EI2"]),
            "beam_elastic_lengths": d["l1"] * np.sqrt(N / d["EI1"]),
            "spatula_axial_load_rel": c2 * N, "beam_axial_load_rel": c1 * N,
            "spatula_forms_edge": forms_edge_distance(c2, N, M2),
            "beam_forms_edge": forms_edge_distance(c1, N, M1),
            # the beam's stretch 1 + T/EA1 at its joint end (theta1 = beta - alpha2), T = N u there
            "beam_joint_stretch": 1.0 + c1 * N * v}


def last_node(q: dict) -> dict:
    """node_quantities (q) at the last node, where the line stopped."""
    return {k: float(v[-1]) for k, v in q.items()}


#: a segment closer than this to the edge of the forms (1 - b4) counts as on it
FORMS_EDGE = 1e-9


def on_forms_edge_since(q: dict):
    """From a line's node_quantities (q): the Ft of the first node of its last stretch along the
    edge of the forms (either segment's 1 - b4 below FORMS_EDGE at every node from there to the
    end), None if the last node is not on it."""
    on = np.minimum(q["spatula_forms_edge"], q["beam_forms_edge"]) < FORMS_EDGE
    if not len(on) or not on[-1]:
        return None
    off = np.flatnonzero(~on)
    return float(q["Ft"][off[-1] + 1 if len(off) else 0])


def band(x: float) -> str:
    return "below 1e-12" if x < 1e-12 else "1e-12 to 1e-9" if x < 1e-9 else "1e-9 to 1e-6" if x < 1e-6 \
        else "1e-6 to 1e-3" if x < 1e-3 else "above 1e-3"


def control(n: int, seed: int, npz: str = STATES) -> dict:
    """For comparison: lines that reach every requested Ft (designs without status 6 and with a
    solved state), traced the same way; the smallest separatrix distance of either segment over
    all their nodes, in the same bands."""
    import gecko
    z = np.load(npz)
    P, FT, ST = z["P"], z["FT"], z["status"]
    rows = np.flatnonzero(~(ST == 6).any(axis=1) & (ST == 0).any(axis=1))
    pick = np.sort(np.random.default_rng(seed).choice(rows, size=min(n, len(rows)), replace=False))
    bands = {}
    for i in pick:
        d = dict(zip(FIELDS, map(float, P[i])))
        line = gecko.TwoLevelSeta(**d).critical_line(ft_end=float(np.max(FT[i])), resolve_nodes=False, errors="nan")
        if not len(line.Ft):
            continue
        q = node_quantities(line, d)
        m = float(np.nanmin(np.minimum(np.abs(q["spatula_separatrix"]), np.abs(q["beam_separatrix"]))))
        bands[band(m)] = bands.get(band(m), 0) + 1
    return {"designs": int(len(pick)), "of_designs": int(len(rows)), "seed": seed, "closest_approach": bands}


def lengths(npz: str) -> dict:
    """Each state's longer segment in elastic lengths, l sqrt(N / EI), by status, over a states file.

    A tensioned segment many elastic lengths long is straight and aligned with the force except
    in boundary layers of about one elastic length at its ends: its path passes the saddle at a
    separatrix distance that shrinks like exp(-L sqrt(N / EI)) (about one elastic length per
    factor e), and the solver's unknowns (Fn, beta and the end rates) resolve that distance only
    down to the rounding of the first integral's constant, which they form by cancellation.
    N = hypot(Fn, Ft) where the file has Fn (a ``recheck --save`` file: the states the solver
    solved), else |Ft|, a lower bound (N >= |Ft|)."""
    z = np.load(npz)
    P, FT, ST = z["P"], z["FT"], z["status"]
    Fn = z["Fn"] if "Fn" in z.files else np.full(FT.shape, np.nan)
    N = np.where(np.isfinite(Fn), np.hypot(Fn, FT), np.abs(FT))
    e = np.maximum(P[:, 4:5] * np.sqrt(N / P[:, 0:1]), P[:, 5:6] * np.sqrt(N / P[:, 1:2]))
    out = {"npz": npz, "N": "hypot(Fn, Ft) where Fn is known, else |Ft| (a lower bound)", "by_status": {}}
    for s in np.unique(ST):
        v = e[ST == s]
        out["by_status"][str(int(s))] = {
            "states": int(v.size), "max": round(float(v.max()), 1),
            "percentiles_50_90_99": [round(float(x), 1) for x in np.percentile(v, [50, 90, 99])],
            "percent_above": {str(t): round(100.0 * float(np.mean(v > t)), 1) for t in (10, 20, 30, 40, 60, 100)}}
    if "Fn" in z.files and "beta" in z.files:
        out["forms_edge_solved"] = forms_edge_solved(P, FT, z["Fn"], z["beta"], ST)
        out["end_stretch_solved"] = end_stretch_solved(P, FT, z["Fn"], z["beta"], ST)
    return out


def end_stretch(P, FT, Fn, beta):
    """Each state's lowest stretch 1 + T/EA at the ends of its segments, T = Ft sin(theta) -
    Fn cos(theta) (the axial force of eqs 1-2): the base (theta1 = alpha1), the joint on either
    side (theta2 = beta, theta1 = beta - alpha2) and the contact edge (theta2 = pi/2). A value <= 0
    is a segment compressed by EA or more at that end, which the linear law maps to a length <= 0.
    Same arguments as forms_edge."""
    a1, a2 = P[:, 6:7], P[:, 7:8]
    c1, c2 = compliances(P)
    T = lambda theta: FT * np.sin(theta) - Fn * np.cos(theta)  # noqa: E731
    return np.minimum.reduce([1 + c1 * T(a1 + 0 * beta), 1 + c1 * T(beta - a2), 1 + c2 * T(beta),
                              1 + c2 * T(np.pi / 2 + 0 * beta)])


def end_stretch_solved(P, FT, Fn, beta, status) -> dict:
    """The solved states (status 0 or 7) whose stretch is <= 0 at a segment end (end_stretch), by
    status, and those with c N > 1 on a segment, where the stretch can reach 0 inside it (a
    stretch <= 0 anywhere makes a state inadmissible, gecko/seta/admissibility.hpp; it did not
    before the rule of validation/README.md, "States compressed to zero length")."""
    cN = np.maximum(*compliances(P)) * np.hypot(Fn, FT)
    low = end_stretch(P, FT, Fn, beta)
    solved = np.isin(status, (0, 7)) & np.isfinite(low)

    def by_status(m):
        return {str(int(s)): int(c) for s, c in zip(*np.unique(status[m], return_counts=True))}
    return {"solved": by_status(solved), "at_most_zero_at_an_end": by_status(solved & (low <= 0)),
            "c_N_above_1": by_status(solved & (cN > 1))}


def forms_edge(P, FT, Fn, beta):
    """Each state's distance from the edge of the forms, the smaller 1 - b4 of its two segments,
    from Fn and beta alone: the joint rate from the spatula's first integral at the joint
    (M2 = Ft + w, eq 12), the beam's M1 from the joint (eq 4), as node_quantities. P: one row of
    campaign.FIELDS per design; FT, Fn, beta: one row of states per design."""
    EI1, EI2, _, _, _, _, _, a2, w = (P[:, k:k + 1] for k in range(9))
    with np.errstate(divide="ignore", invalid="ignore"):
        N, phi = np.hypot(Fn, FT), np.arctan2(Fn, FT)
        c1, c2 = compliances(P)
        u, M2 = np.sin(beta - phi), FT + w
        k2_sq = 2 * (M2 - N * u - c2 * N * N * u * u / 2) / EI2
        v = np.sin(beta - a2 - phi)
        M1 = beam_first_integral(EI1, EI2, c1, k2_sq, N, v)
        return np.minimum(forms_edge_distance(c1, N, M1), forms_edge_distance(c2, N, M2))


def forms_edge_solved(P, FT, Fn, beta, status) -> dict:
    """How close the solved states (status 0 or 7) come to the edge of the forms (forms_edge): counts
    below 1e-12 ... 1e-3 by status, and the states within 1e-6."""
    edge = forms_edge(P, FT, Fn, beta)
    solved = np.isin(status, (0, 7)) & np.isfinite(edge)
    out = {"solved": int(solved.sum()), "below": {}}
    for t in (1e-12, 1e-9, 1e-6, 1e-3):
        m = solved & (edge < t)
        out["below"][f"{t:g}"] = {str(int(s)): int(c) for s, c in zip(*np.unique(status[m], return_counts=True))}
    out["within_1e-6"] = [{"design": int(i), "column": int(j), "Ft": float(FT[i, j]), "status": int(status[i, j]),
                           "one_minus_b4": float(edge[i, j])} for i, j in np.argwhere(solved & (edge < 1e-6))]
    return out


def mechanism(end: str, node: dict | None) -> str:
    if end not in GIVEN_UP:
        return "now_reached"
    if node is None:
        return "other"
    if abs(node["spatula_separatrix"]) < 1e-3:
        return "spatula_separatrix"
    if abs(node["beam_separatrix"]) < 1e-3:
        return "beam_separatrix"
    if node["beam_forms_edge"] < FORMS_EDGE:
        return "beam_forms_edge"
    if node["spatula_forms_edge"] < FORMS_EDGE:
        return "spatula_forms_edge"
    if node["joint_rate_rel"] < 1e-2:
        return "joint_turning_point"
    if node["base_rate_rel"] < 1e-2:
        return "base_turning_point"
    return "other"


def run(n: int, seed: int = 0, npz: str = STATES, progress: bool = False) -> dict:
    import gecko
    z = np.load(npz)
    P, FT, ST = z["P"], z["FT"], z["status"]
    rows = np.flatnonzero((ST == 6).any(axis=1))
    rng = np.random.default_rng(seed)
    pick = np.sort(rng.choice(rows, size=min(n, len(rows)), replace=False))
    t0 = time.time()
    designs = []
    for i in pick:
        d = dict(zip(FIELDS, map(float, P[i])))
        s = gecko.TwoLevelSeta(**d)
        ft = FT[i]
        # the trace the solver makes for the positive requested Ft (critical_line_at_imp): from 0
        # to the largest of them; a design whose status-6 states are all negative is traced down
        neg_only = not np.any((ST[i] == 6) & (ft >= 0))
        end_ft = float(np.min(ft)) if neg_only else float(np.max(ft))
        line = s.critical_line(ft_end=end_ft, resolve_nodes=False, errors="nan")
        end = line.end_code.name if line.end_code is not None else str(line.end)
        q = node_quantities(line, d) if len(line.Ft) else None
        node = last_node(q) if q else None
        rec = {"design": int(i), "ft_end": end_ft, "end": end, "nodes": int(len(line.Ft)),
               "mechanism": mechanism(end, node), "last": node,
               "on_forms_edge_since_ft": on_forms_edge_since(q) if q else None}
        designs.append(rec)
        if progress:
            print(f"design {i}: {end} after {rec['nodes']} nodes, {rec['mechanism']}", flush=True)
    counts = {}
    for r in designs:
        counts.setdefault(r["end"], {})
        counts[r["end"]][r["mechanism"]] = counts[r["end"]].get(r["mechanism"], 0) + 1
    # how close: the separatrix distance of the segment named by the mechanism, in decades
    closeness = {}
    for r in designs:
        m = r["mechanism"]
        if m.endswith("_separatrix"):
            b = band(abs(r["last"][m]))
            closeness.setdefault(m, {})
            closeness[m][b] = closeness[m].get(b, 0) + 1
    return {"sample": len(designs), "of_designs": int(len(rows)), "seed": seed,
            "seconds": round(time.time() - t0, 1), "counts": counts, "separatrix_distance": closeness,
            "by_mechanism": by_mechanism(designs, ST), "designs": designs}


def by_mechanism(designs: list, status) -> dict:
    """Per mechanism: the designs, their status-6 states, how many were traced towards negative Ft,
    how many ended along the edge of the forms, and the beam's N / EA1 and stretch at its joint end
    at the last node (min, median, max)."""
    out = {}
    for m in sorted({r["mechanism"] for r in designs}):
        rs = [r for r in designs if r["mechanism"] == m]
        load = [r["last"]["beam_axial_load_rel"] for r in rs if r["last"] is not None]
        out[m] = {"designs": len(rs), "status6_states": int(sum((status[r["design"]] == 6).sum() for r in rs)),
                  "traced_to_negative_ft": sum(r["ft_end"] < 0 for r in rs),
                  "on_forms_edge": sum(r["on_forms_edge_since_ft"] is not None for r in rs),
                  "beam_axial_load_rel_min_median_max":
                      [float(f"{x:.3g}") for x in (np.min(load), np.median(load), np.max(load))] if load else [],
                  "beam_joint_stretch_min_median_max": spread([r["last"]["beam_joint_stretch"] for r in rs
                                                               if r["last"] is not None])}
    return out


def spread(x: list) -> list:
    return [float(f"{v:.3g}") for v in (np.min(x), np.median(x), np.max(x))] if x else []


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sample", type=int, default=200)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--npz", default=STATES)
    ap.add_argument("--json", default=None)
    ap.add_argument("--lengths", default=None, metavar="NPZ",
                    help="only: each state's longer segment in elastic lengths by status over the states "
                         "file NPZ (a recheck --save file, or the campaign's states)")
    ap.add_argument("--control", type=int, default=0, metavar="N",
                    help="also trace N designs without a status-6 state: their closest approach to a "
                         "separatrix over the whole line")
    args = ap.parse_args(argv)
    if args.lengths:
        res = lengths(args.lengths)
        for k, v in res["by_status"].items():
            print(f"status {k}: {v['states']} states, max {v['max']}, percent above {v['percent_above']}")
        if args.json:
            with open(args.json, "w") as f:
                json.dump(res, f, indent=1)
                f.write("\n")
        return
    res = run(args.sample, args.seed, args.npz)
    if args.control:
        res["control"] = control(args.control, args.seed + 1, args.npz)
    print(f"{res['sample']} of {res['of_designs']} designs with a status-6 state ({res['seconds']} s)")
    print(json.dumps(res["counts"], indent=1))
    print("separatrix distance |R(1)| / (|M| + N) at the last node:")
    print(json.dumps(res["separatrix_distance"], indent=1))
    if "control" in res:
        c = res["control"]
        print(f"control: {c['designs']} lines without a give-up, closest approach over all nodes:")
        print(json.dumps(c["closest_approach"], indent=1))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(res, f, indent=1, allow_nan=True)
            f.write("\n")


if __name__ == "__main__":
    main()
