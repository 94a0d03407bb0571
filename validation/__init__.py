"""Validation of the two-level seta solver, apart from the timing benchmarks (bench/).

An importable package at the repository root (the tests import it: pytest puts the root on its
pythonpath); run its scripts from the root as ``python3 -m validation.<name>``:

* ``verify``: the independent verification route (backward ODE shooting, no gecko code);
* ``campaign``: the stress campaign (random designs, every state verified), chunked and resumable;
* ``beta_conditioning``: 60-digit Taylor-series shooting of the states the double verifier flags;
* ``recheck``: a later solver on the campaign's states, bitwise (the committed states file
  ``data/stress_10000_states.npz`` is enough);
* ``report``, ``status1_floor``, ``traced_nodes``, ``add_regressions``: the studies and summaries
  (``results/``).
"""
