"""Worst cases found by the stress campaign (bench/stress, bench/results/stress.md), kept as
regression tests (tests/data/stress_regressions.csv).

kind = verify: the state at Ft is either solved (status 0) and agrees with the independent ODE
shooting route (bench/stress/verify.py) to 1e-8 max(1,|Fn|) in Fn and 1e-8 in beta (where the
verifier is conclusive), or reported unsolved (status != 0) with NaN Fn and beta.
kind = bounded_time: the solver must answer (any status) within 20 s.
"""
import csv
import math
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "stress"))
import campaign  # noqa: E402

gecko = pytest.importorskip("gecko")

with open(os.path.join(HERE, "..", "data", "stress_regressions.csv")) as _f:
    ROWS = list(csv.DictReader(_f))


def _design(r):
    return {k: float(r[k]) for k in campaign.FIELDS}


@pytest.mark.parametrize("row", [r for r in ROWS if r["kind"] == "verify"], ids=lambda r: r["note"][:40])
def test_worst_case_verified(row):
    p = np.array([[_design(row)[k] for k in campaign.FIELDS]])
    ft = np.array([[float(row["Ft"])]])
    line = gecko.TwoLevelSeta(**_design(row)).critical_line(Ft=ft[0], errors="nan")
    Fn, beta, status = line.Fn[None, :], line.theta_joint[None, :], line.status[None, :].astype(np.int64)
    v = campaign.verify_states(p, ft, Fn, beta, status)
    cl = campaign.classify(p, ft, Fn, beta, status, v)
    assert not cl["number_with_status"].any() and not cl["nonfinite_ok"].any()
    assert not cl["wrong_fn"].any(), (Fn, v["dFn"])
    assert not cl["wrong_beta"].any(), (beta, v["dbeta"])


@pytest.mark.parametrize("row", [r for r in ROWS if r["kind"] == "bounded_time"], ids=lambda r: r["note"][:40])
# Was a hang: the continuation handed R_F two zero arguments and the unchecked duplication never
# stopped; the Carlson loops are now bounded (gecko/elliptic/carlson_tolerance.hpp).
def test_solver_answers_in_bounded_time(row):
    code = ("import gecko, sys; d = eval(sys.argv[1]); "
            "print(gecko.TwoLevelSeta(**d).critical_line(Ft=[float(sys.argv[2])], errors='nan').status)")
    try:
        subprocess.run([sys.executable, "-c", code, repr(_design(row)), row["Ft"]], timeout=20, check=True,
                       capture_output=True)
    except subprocess.TimeoutExpired:
        pytest.fail(f"no answer within 20 s for Ft = {row['Ft']}")
