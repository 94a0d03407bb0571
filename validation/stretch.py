#!/usr/bin/env python3
"""States compressed to zero length: an independent check of what the stretch rule changed.

A state of the extensible seta whose axial force reaches T <= -EA somewhere has a stretch
1 + T/EA <= 0 there: the linear law maps a piece of the rod to zero or negative length. gecko
calls such a state inadmissible (status 7, ``min_stretch <= 0``), and a followed critical line
ends at its first node compressed so (end ``unsupported_state``, "left the model"): the Ft beyond
it are status 3. This compares two ``recheck --save`` files (before and after that rule, the same
campaign) and checks every state whose status changed, with no gecko code in the check itself:

* a state that became status 7: its lowest stretch from a dense ODE shot (below) with gecko's
  Fn; ``inverted_confirmed`` where the shot's lowest stretch is <= 0, ``contradicted`` where it is
  clearly positive;
* a state that became status 3: gecko's traced line towards it (``critical_line(ft_end=Ft)``)
  must end "left the model" with its last node compressed to zero length and the node before it
  not, both confirmed by the shot, and the target must lie beyond the nodes' running range in Ft
  (``beyond_first_inverted_node``); ``contradicted`` where the shot finds a positive stretch at the
  last node or none at the node before, or the line covers the target's Ft.

The shot (``shot_min_stretch``): the governing ODE of paper 001 eqs (1)-(2), theta'' = -(Fn sin
theta + Ft cos theta)(1 + c T)/EI with T = Ft sin theta - Fn cos theta, integrated backwards from
the contact edge (theta = pi/2, EI2 theta'^2/2 = w - c2 Ft^2/2 by Griffith's condition, eq 3)
over the spatula, across the joint (theta1 = theta2 - alpha2, EI1 theta1' = EI2 theta2', eq 4) and
over the beam (scipy's DOP853, rtol = atol = 1e-12, dense output on 4,000 points per segment and a
parabola through the lowest sample and its neighbours). Of the two signs of the edge rate the one
whose joint angle meets gecko's beta is kept; the shot's own closing error, |theta1(0) - alpha1|,
is reported (``base_miss``). A segment end with a stretch <= 0 decides a state from its boundary
values alone (``lowest_end_stretch``); otherwise the shot decides where it misses the base by at most
1e-6 rad and its lowest stretch lies farther from 0 than max(1e-8, c N x base_miss). Where it does
not, the same ODE shot forwards from the base with the state's own theta1'(0) decides the same way,
with its miss at the contact edge (``shot_min_stretch_from_base``); else the state is ``undecided``
(``stretch_verdict``). A status-7 state is re-solved as the campaign solves it, with all the
design's Ft in one call.

    PYTHONPATH=<gecko>:. python3 -m validation.stretch validation/rerun_base.npz validation/rerun_main.npz \\
        [--json F.json]
"""
from __future__ import annotations

import math
import time
from collections import Counter

import numpy as np
from scipy.integrate import solve_ivp

from . import campaign
from .line_ends import end_stretch

SAMPLES = 4000     # dense-output samples per segment
MISS_LIMIT = 1e-6  # largest closing error of a shot that decides (rad)
DECIDE = 1e-8      # a lowest stretch within this of 0 decides nothing


def _segment_min_stretch(sol, s0, s1, c, Fn, Ft):
    """Lowest 1 + c T over the dense output of one segment (s from s0 to s1)."""
    if not c > 0:
        return 1.0
    s = np.linspace(s0, s1, SAMPLES)
    th = sol.sol(s)[0]
    v = 1 + c * (Ft * np.sin(th) - Fn * np.cos(th))
    i = int(np.argmin(v))
    lo = float(v[i])
    if 0 < i < len(v) - 1:  # an interior minimum: the parabola through the neighbours
        a, b, e = v[i - 1], v[i], v[i + 1]
        den = a - 2 * b + e
        if den > 0:
            lo = min(lo, float(b - (e - a) ** 2 / (8 * den)))
    return lo


def _rhs(Fn, Ft, EI, c):
    """theta'' of paper 001 eqs (1)-(2) on one segment, as a first-order system in (theta, theta')."""
    def f(_s, y):
        th, om = y
        T = Ft * math.sin(th) - Fn * math.cos(th)
        return [om, -(Fn * math.sin(th) + Ft * math.cos(th)) * (1 + c * T) / EI]
    return f


def _run(Fn, Ft, EI, c, s0, s1, y0):
    return solve_ivp(_rhs(Fn, Ft, EI, c), (s0, s1), y0, method="DOP853", rtol=1e-12, atol=1e-12,
                     dense_output=True)


def shot_min_stretch(p, Fn, Ft, beta):
    """(lowest stretch over the seta, the shot's |theta1(0) - alpha1|) for the design p (campaign
    FIELDS order) at the forces (Fn, Ft), shot back from the contact edge; beta picks the sign of
    the edge rate."""
    EI1, EI2, _, _, l1, l2, a1, a2, w = (float(x) for x in p)
    c1, c2 = (c.item() for c in campaign.compliances(p))
    radicand = 2 * (w - c2 * Ft * Ft / 2) / EI2
    if not radicand >= 0:
        return math.nan, math.inf
    best = (math.nan, math.inf, math.inf)  # (min stretch, joint miss, base miss)
    for sign in (1.0, -1.0):
        sp = _run(Fn, Ft, EI2, c2, l1 + l2, l1, [math.pi / 2, sign * math.sqrt(radicand)])
        if not sp.success:
            continue
        thj, omj = sp.y[0, -1], sp.y[1, -1]
        joint_miss = abs(thj - beta)
        sb = _run(Fn, Ft, EI1, c1, l1, 0.0, [thj - a2, omj * EI2 / EI1])
        if not sb.success:
            continue
        lo = min(_segment_min_stretch(sp, l1 + l2, l1, c2, Fn, Ft),
                 _segment_min_stretch(sb, l1, 0.0, c1, Fn, Ft))
        if joint_miss < best[1]:
            best = (lo, joint_miss, abs(sb.y[0, -1] - a1))
    return best[0], best[2]


def shot_min_stretch_from_base(p, Fn, Ft, rate_base):
    """(lowest stretch, the shot's |theta2(a) - pi/2|): the same ODE shot forwards from the base
    with the state's own theta1'(0), for states whose shot from the edge does not close (a beam
    compressed far past EA1 is a libration about its compressed orientation, stable forwards)."""
    EI1, EI2, _, _, l1, l2, a1, a2, _ = (float(x) for x in p)
    c1, c2 = (c.item() for c in campaign.compliances(p))
    sb = _run(Fn, Ft, EI1, c1, 0.0, l1, [a1, float(rate_base)])
    if not sb.success:
        return math.nan, math.inf
    sp = _run(Fn, Ft, EI2, c2, l1, l1 + l2, [sb.y[0, -1] + a2, sb.y[1, -1] * EI1 / EI2])
    if not sp.success:
        return math.nan, math.inf
    lo = min(_segment_min_stretch(sb, 0.0, l1, c1, Fn, Ft), _segment_min_stretch(sp, l1, l1 + l2, c2, Fn, Ft))
    return lo, abs(sp.y[0, -1] - math.pi / 2)


def lowest_end_stretch(p, Fn, Ft, beta):
    """The lowest stretch 1 + c T at the four segment ends (line_ends.end_stretch: base, the joint
    on either side, contact edge) from the forces and the angles alone."""
    one = lambda x: np.array([[float(x)]])  # noqa: E731
    return float(end_stretch(np.asarray(p, dtype=float)[None, :], one(Ft), one(Fn), one(beta))[0, 0])


def stretch_verdict(p, Fn, Ft, beta, rate_base=None):
    """Is the state's lowest stretch <= 0 ("nonpositive"), > 0 ("positive"), or not decided?

    An end with a stretch <= 0 decides it from the boundary values alone. Otherwise the shot from
    the edge does, where its own base miss is at most 1e-6 rad and its lowest stretch lies farther
    from 0 than max(1e-8, c N x miss), c N x miss bounding the stretch's change for an angle that
    far off (d(1 + c T)/dtheta = c N cos(theta - phi)). Where that shot does not decide and the
    state's theta1'(0) is given, the shot from the base decides the same way with its miss at the
    contact edge (``by`` says which)."""
    end = lowest_end_stretch(p, Fn, Ft, beta)
    row = {"lowest_end_stretch": end}
    if end <= 0:
        row["stretch"] = "nonpositive"
        row["by"] = "segment_end"
        return row
    c = max(c.item() for c in campaign.compliances(p))

    def decide(lo, miss):
        margin = max(DECIDE, c * math.hypot(Fn, Ft) * miss)
        if not (miss <= MISS_LIMIT and math.isfinite(lo)) or abs(lo) <= margin:
            return "undecided"
        return "nonpositive" if lo < 0 else "positive"
    lo, miss = shot_min_stretch(p, Fn, Ft, beta)
    row.update({"shot_min_stretch": lo, "base_miss": miss, "by": "shot"})
    row["stretch"] = decide(lo, miss)
    if row["stretch"] == "undecided" and rate_base is not None:
        lo_b, miss_b = shot_min_stretch_from_base(p, Fn, Ft, rate_base)
        row.update({"base_shot_min_stretch": lo_b, "edge_miss": miss_b})
        row["stretch"] = decide(lo_b, miss_b)
        if row["stretch"] != "undecided":
            row["by"] = "shot_from_base"
    return row


def check_inverted_state(p, fts, j):
    """A state that became status 7 (the j-th of the design's campaign Ft fts, solved in one
    call as the campaign does): is it compressed to zero length?"""
    st = campaign.seta(p).critical_line(Ft=[float(x) for x in fts])
    Fn, beta, gecko_min = float(st.Fn[j]), float(st.theta_joint[j]), float(st.min_stretch[j])
    row = {"gecko_min_stretch": gecko_min, "status": int(st.status[j])}
    row.update(stretch_verdict(p, Fn, float(fts[j]), beta, float(st.theta_rate_base[j])))
    if row["stretch"] == "undecided":
        row["verdict"] = "undecided"
    else:
        agree = (row["stretch"] == "nonpositive") == (gecko_min <= 0)
        row["verdict"] = "inverted_confirmed" if agree and gecko_min <= 0 else "contradicted"
    return row


def check_beyond_line(p, Ft):
    """A state that became status 3: does the line end at its first node compressed to zero
    length, short of this Ft?"""
    import gecko
    line = campaign.seta(p).critical_line(ft_end=float(Ft))
    row = {"end": int(line.end_code), "nodes": len(line.Ft)}
    if line.end_code != gecko.LineEnd.unsupported_state:
        row["verdict"] = "line_does_not_leave_the_model"
        return row
    nodes = []
    for k in ([-2, -1] if len(line.Ft) >= 2 else [-1]):
        v = stretch_verdict(p, float(line.Fn[k]), float(line.Ft[k]), float(line.theta_joint[k]),
                            float(line.theta_rate_base[k]))
        v.update({"Ft": float(line.Ft[k]), "gecko_min_stretch": float(line.min_stretch[k])})
        nodes.append(v)
    row["last"] = nodes[-1]
    row["before_last"] = nodes[0] if len(nodes) == 2 else None
    covered = float(np.min(line.Ft)) <= Ft <= float(np.max(line.Ft))
    row["target_covered"] = bool(covered)
    last_ok = nodes[-1]["stretch"] == "nonpositive" and nodes[-1]["gecko_min_stretch"] <= 0
    # A natural state compressed to zero length ends the line at its first node.
    before_ok = len(nodes) == 1 or (nodes[0]["stretch"] == "positive" and nodes[0]["gecko_min_stretch"] > 0)
    if covered or (nodes[-1]["stretch"] == "positive") or (len(nodes) == 2 and nodes[0]["stretch"] == "nonpositive"):
        row["verdict"] = "contradicted"
    elif last_ok and before_ok:
        row["verdict"] = "beyond_first_inverted_node"
    else:
        row["verdict"] = "undecided"
    return row


def run(before: str, after: str) -> dict:
    t0 = time.time()
    a, b = np.load(before), np.load(after)
    if not np.array_equal(a["P"], b["P"]) or not np.array_equal(a["FT"], b["FT"]):
        raise SystemExit("the two files are not re-runs of the same campaign")
    P, FT, sa, sb = b["P"], b["FT"], a["status"], b["status"]
    changed = np.argwhere(sa != sb)
    transitions = Counter(f"{int(sa[i, j])}->{int(sb[i, j])}" for i, j in changed)
    states = []
    for i, j in changed:
        new = int(sb[i, j])
        row = {"design": int(i), "Ft": float(FT[i, j]), "before": int(sa[i, j]), "after": new}
        if new == 7:
            row.update(check_inverted_state(P[i], FT[i], j))
        elif new == 3:
            row.update(check_beyond_line(P[i], FT[i, j]))
        else:
            row["verdict"] = "not_a_stretch_change"
        states.append(row)
    verdicts = Counter(r["verdict"] for r in states)
    return {"before": before, "after": after, "changed": len(states), "transitions": dict(transitions),
            "verdicts": dict(verdicts),
            "designs": len({r["design"] for r in states}),
            "seconds": round(time.time() - t0, 1), "states": states}


def main(argv=None):
    return campaign.compare_main(run, __doc__, argv, omit=("states",))


if __name__ == "__main__":
    main()
