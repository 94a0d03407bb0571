#!/usr/bin/env python3
"""mpmath reference for the max-pull-off regression designs of tests/seta/characteristics.cpp.

Regenerate (from the repository root; about 2 min on a busy core):

    python3 tests/data/gen_seta_min_regression.py      # writes tests/data/seta_min_regression.csv

For each design: the interior minimum of Fn along the critical line (docs/theory/two_level_seta.md), by the ODE
route of gen_seta_reference.py (arbitrary-precision Taylor shooting, seta_taylor.py; no Carlson
forms, no C++ code): secant iteration on dFn/dFt = 0 with central differences of Fn(Ft) solved
to 1e-32 (refine_min, h = 1e-10 F_scale), started from the double-precision guess given below
(a dense double-precision sample of the line, seta_double.py).  Error budget as in
gen_seta_reference.py: Ft* to ~1e-19, min Fn to ~1e-28; the 25 digits written are therefore
correct to far better than the 1e-13 relative tolerance of the test.

Design 0: the design where characteristics() returned the traced node -6.589516 at Ft = 9.62
(slope 0.016) instead of the minimum -6.591953 at Ft = 9.31: the beam's turning point leaves and
re-enters the segment between the nodes around the minimum, and the refinement used the plan of
the middle node across the whole bracket.
"""
import csv
import math
import os
import sys

import numpy as np
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import gen_seta_reference as gen  # noqa: E402
import seta_double as sd          # noqa: E402
import seta_taylor as st          # noqa: E402

DESIGNS = [
    dict(EI1=16.248074011412644, EI2=2.073266411055929, EA1=math.inf, EA2=158.40954057083513, l1=1.0,
         l2=0.2956123183806999, alpha1=0.9518127924448841, alpha2=0.5104088538263943, w=1.0),
]


def dense_guess(dd, lo, hi, n=401):
    """Double-precision Fn on a grid of Ft (Newton from the previous point), its argmin."""
    Fts = np.linspace(lo, hi, n)
    Fn = sd.natural_state(dd)
    Fn_prev, best = None, None
    # march from Ft = 0 to lo with the same Newton continuation
    for Ft in np.linspace(0.0, lo, 50):
        Fn = sd.newton_fn(dd, float(Ft), Fn)
    for Ft in Fts:
        Fn = sd.newton_fn(dd, float(Ft), Fn)
        if best is None or Fn < best[1]:
            best = (float(Ft), Fn)
        Fn_prev = Fn
    del Fn_prev
    return best


def main():
    mp.dps = 30
    out = os.path.join(HERE, "seta_min_regression.csv")
    rows = []
    for i, dd in enumerate(DESIGNS):
        S = gen.f_scale(dd)
        Ft_g, Fn_g = dense_guess(dd, 0.3 * S, 0.8 * S)
        d = st.mp_design(dd)
        Ft_s, Fn_s = gen.refine_min(d, dd, Ft_g, Fn_g, S)
        print(i, "guess", Ft_g, Fn_g, "mp", mp.nstr(Ft_s, 20), mp.nstr(Fn_s, 25), flush=True)
        rows.append([i] + [gen.fmt_in(dd[k]) for k in gen.KEYS] + [gen.nstr(Fn_s), gen.nstr(Ft_s)])
    with open(out, "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["design_id"] + gen.KEYS + ["min_Fn", "Ft_at_min"])
        wr.writerows(rows)


if __name__ == "__main__":
    main()
