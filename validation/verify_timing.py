#!/usr/bin/env python3
"""Time the shooting verifier (verify.py) on the short stress campaign's states, and compare the
outputs of two runs to the bit.

The states are those of tests/python/test_stress_short.py: 40 random designs of the campaign's
box (seed 6), six Ft each, solved by the gecko on PYTHONPATH with a 5 s timeout per design. They
are computed once and kept in the ``--states`` file, so that two verifiers (or two machines) are
timed on the same states. The verifier's output arrays (campaign.verify_states) can be saved and
compared with those of another run: the keys whose arrays differ anywhere are listed.

    PYTHONPATH=<gecko>:. python3 -m validation.verify_timing --states S.npz [--save V.npz] \\
        [--compare W.npz] [--module FILE] [--json F.json]

``--module FILE`` loads the verifier from FILE instead of validation/verify.py, for instance an
earlier commit's (``git show 118d050:validation/verify.py > /tmp/verify_118d050.py``).
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import os
import time

import numpy as np

from . import campaign


def short_campaign_states(path: str) -> dict:
    """The states of the short campaign, from ``path`` if it exists, else solved and saved there."""
    keys = ("P", "FT", "Fn", "beta", "status")
    if os.path.exists(path):
        z = np.load(path)
        return {k: z[k] for k in keys}
    P, FT = campaign.short_campaign_designs()
    Fn, beta, status, _, _, _ = campaign.run_gecko(P, FT, timeout=5.0, progress=False)
    out = dict(zip(keys, (P, FT, Fn, beta, status)))
    np.savez(path, **out)
    return out


def load_verifier(path: str | None):
    if path is None:
        return None   # verify_states' default, validation/verify.py
    spec = importlib.util.spec_from_file_location("verify_under_test", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def time_verifier(states: dict, module=None) -> tuple[dict, float]:
    """campaign.verify_states on the states with the given verifier module; (outputs, seconds)."""
    t0 = time.perf_counter()
    v = campaign.verify_states(states["P"], states["FT"], states["Fn"], states["beta"], states["status"],
                               verifier=module)
    return v, time.perf_counter() - t0


def differing_keys(a: dict, b) -> list:
    """The keys of a whose arrays differ from b's (NaN equal to NaN), or are missing from b."""
    out = []
    for k, x in a.items():
        if k not in b:
            out.append(k)
            continue
        y = np.asarray(b[k])
        same = x.shape == y.shape and (np.array_equal(x, y, equal_nan=True) if x.dtype.kind == "f"
                                       else np.array_equal(x, y))
        if not same:
            out.append(k)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--states", required=True, help="the states file (made on first use)")
    ap.add_argument("--module", default=None, help="the verifier's source file (default: validation/verify.py)")
    ap.add_argument("--save", default=None, help="write the verifier's output arrays here (.npz)")
    ap.add_argument("--compare", default=None, help="compare the outputs with this file's (.npz)")
    ap.add_argument("--json", default=None)
    a = ap.parse_args(argv)
    states = short_campaign_states(a.states)
    mod = load_verifier(a.module)
    v, secs = time_verifier(states, mod)
    rec = {"module": a.module or "validation/verify.py", "states_file": a.states,
           "states_verified": int(campaign.solved(states["status"]).sum()), "seconds": round(secs, 1)}
    if a.save:
        np.savez(a.save, **v)
    if a.compare:
        rec["compared_with"] = a.compare
        rec["differing_outputs"] = differing_keys(v, np.load(a.compare))
    print(json.dumps(rec, indent=1))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rec, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
