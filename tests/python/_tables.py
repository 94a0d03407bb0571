"""Test helper: the reference tables of tests/data (written with mpmath by tests/data/gen_elliptic*.py)
as numpy arrays. The test modules import it by name: pytest puts tests/python on sys.path."""
import csv
import os

import numpy as np

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")


def table(name, cols, ref_cols=(), ref=np.longdouble):
    """The argument columns ``cols`` of tests/data/``name`` as float64 arrays, and its reference
    columns ``ref_cols`` converted by ``ref``: long double by default (64-bit significand on x86,
    so the reference's own error is below 2^-11 eps), or ``str`` to keep the decimal text for
    mpmath."""
    with open(os.path.join(DATA, name)) as f:
        rows = list(csv.DictReader(f))
    args = [np.array([float(r[c]) for r in rows]) for c in cols]
    refs = [np.array([ref(r[c]) for r in rows]) for c in ref_cols]
    return args, refs
