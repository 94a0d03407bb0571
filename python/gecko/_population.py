"""Spatula populations: per-spatula factors on length, stiffness and G0 (see
:func:`gecko.simulate_spatulae` and :mod:`gecko.friction_hierarchy`).

A factor is given as

* ``None`` (every spatula 1),
* a number (every spatula that value),
* an array of one positive value per simulated spatula, or
* a distribution of mean 1: ``{"dist": "lognormal", "sigma": s}`` (log-width s, mean 1) or
  ``{"dist": "uniform", "width": h}`` (uniform on [1 - h, 1 + h], 0 <= h < 1), drawn with
  numpy's PCG64 generator from a seed (numpy keeps its streams stable across versions).

The distributions also come as quadrature rules (nodes, weights), for the average of a smooth
function over the distribution itself rather than over the drawn sample.
"""
from __future__ import annotations

import math
from typing import Optional, Tuple

import numpy as np

FACTORS = ("length", "stiffness", "G0")
_DISTS = {"lognormal": "sigma", "uniform": "width"}


def _check_spec(spec, name: str):
    if spec is None:
        return None
    if isinstance(spec, dict):
        dist = spec.get("dist")
        if dist not in _DISTS:
            raise ValueError(f"{name} = {spec!r} is not allowed: need dist = 'lognormal' (with sigma) or "
                             "'uniform' (with width)")
        key = _DISTS[dist]
        extra = set(spec) - {"dist", key}
        if extra or key not in spec:
            raise ValueError(f"{name} = {spec!r} is not allowed: a {dist} factor takes exactly "
                             f"dist and {key}")
        w = spec[key]
        if isinstance(w, bool) or not isinstance(w, (int, float)):
            raise ValueError(f"{name}.{key} = {w!r} is out of range: need a number")
        w = float(w)
        ok = (0 <= w < 5) if dist == "lognormal" else (0 <= w < 1)
        if not ok:
            rng = "0 <= sigma < 5" if dist == "lognormal" else "0 <= width < 1 (factors stay positive)"
            raise ValueError(f"{name}.{key} = {w!r} is out of range: need {rng}")
        return {"dist": dist, key: w}
    return spec


def draw(spec, M: int, rng: np.random.Generator, name: str) -> Optional[np.ndarray]:
    """The M factors of one spec (None: all 1). Arrays and numbers are checked here too."""
    spec = _check_spec(spec, name)
    if spec is None:
        return None
    if isinstance(spec, dict):
        if spec["dist"] == "lognormal":
            s = spec["sigma"]
            return np.exp(s * rng.standard_normal(M) - s * s / 2)
        h = spec["width"]
        return 1.0 + h * (2.0 * rng.random(M) - 1.0)
    a = np.asarray(spec, dtype=np.float64)
    if a.ndim == 0:
        a = np.full(M, float(a))
    if a.ndim != 1 or a.size != M:
        raise ValueError(f"{name} has {a.size} entries: need one per simulated spatula ({M}), a number "
                         "or a distribution")
    bad = np.flatnonzero(~((a > 0) & np.isfinite(a)))
    if bad.size:
        i = int(bad[0])
        raise ValueError(f"{name}[{i}] = {float(a[i])!r} is out of range: need 0 < factor < inf")
    return np.ascontiguousarray(a)


def quadrature(spec, n: int = 24) -> Optional[Tuple[np.ndarray, np.ndarray]]:
    """Nodes and weights of the distribution of a spec (None for arrays: no distribution known;
    a single node for None and numbers)."""
    spec = _check_spec(spec, "factor")
    if spec is None:
        return np.ones(1), np.ones(1)
    if isinstance(spec, dict):
        if spec["dist"] == "lognormal":
            x, w = np.polynomial.hermite_e.hermegauss(n)  # weight exp(-x^2/2)
            s = spec["sigma"]
            return np.exp(s * x - s * s / 2), w / math.sqrt(2 * math.pi)
        x, w = np.polynomial.legendre.leggauss(n)
        return 1.0 + spec["width"] * x, w / 2
    a = np.asarray(spec, dtype=np.float64)
    if a.ndim == 0:
        return np.full(1, float(a)), np.ones(1)
    return None


def mean_of(spec) -> Optional[float]:
    """The mean of a spec's distribution (1 for None and for both distributions)."""
    q = quadrature(spec)
    return None if q is None else float(np.dot(*q))


def expected_forces(specs, V: float, G: float, t_off: float, single, n: int = 24):
    """Eqs 9-10 per spatula, averaged over the distributions of the specs (length, stiffness,
    G0), or None when a spec is an array.

    ``single(Gp)``: (F_par, F_perp, stretch) of N spatulae of the base rigidity at t_off = 0 for
    an array of detachment energies. A spatula with factors (l, s, g) has c = s / l^3; it stretches
    as the base spatula with G' = g G / c (A2.6 with K, f1 scaled by c), carries c times its
    forces, and is attached a fraction dd / (dd + V l^2 t_off) of the time (eqs 5-6, eq 4)."""
    rules = [quadrature(specs.get(k), n) for k in FACTORS]
    if any(r is None for r in rules):
        return None
    (l, wl), (s, ws), (g, wg) = rules
    L, S, Gf = np.meshgrid(l, s, g, indexing="ij")
    W = (wl[:, None, None] * ws[None, :, None] * wg[None, None, :]).ravel()
    L, S, Gf = L.ravel(), S.ravel(), Gf.ravel()
    c = S / L ** 3
    F_par, F_perp, dd = (np.asarray(a, dtype=np.float64) for a in single(Gf * G / c))
    duty = dd / (dd + V * L * L * t_off) if t_off > 0 else 1.0
    return float(np.sum(W * c * F_par * duty)), float(np.sum(W * c * F_perp * duty))
