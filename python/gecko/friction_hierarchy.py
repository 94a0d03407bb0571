"""gecko.friction_hierarchy — the hierarchy argued in paper 000's Discussion.

The paper's spatulae stick and slip one by one while "the much stiffer seta level moves
smoothly". Two models test that here (docs/theory/frictional_adhesion.md, "Spatula populations"
and "Spatulae on a compliant seta"):

* :func:`spatula_population`: spatulae of different length, stiffness and G0, simulated in time
  (:func:`gecko.simulate_spatulae` with per-spatula factors) and compared with eqs 9-10 at the
  mean parameters and averaged over the population;
* :func:`compliant_seta`: the population at the end of a seta that a stage drags at V through a
  spring k_s; :func:`stick_slip_map` classifies each (k_s / collective stiffness, V) as smooth
  sliding or seta-level stick-slip from the simulated force trace.
"""
from __future__ import annotations

import math
from typing import NamedTuple, Optional, Sequence

import numpy as np

from . import _core, _population
from .friction import (FIG6_VISCOELASTIC, SlidingModel, SpatulaSimulation, _law_values, _matrix,
                       _resolve_t_off, _scalar, simulate_spatulae, steady_sliding)

__all__ = ["spatula_population", "CompliantSeta", "compliant_seta", "StickSlipMap", "stick_slip_map",
           "STICK_SLIP_THRESHOLD"]

#: a slip that releases at least this fraction of the seta's mean lateral force at once is a
#: seta-level slip (see :func:`compliant_seta`)
STICK_SLIP_THRESHOLD = 0.1


def spatula_population(V: float, model: SlidingModel = FIG6_VISCOELASTIC, *, length=None, stiffness=None,
                       G0=None, **options) -> SpatulaSimulation:
    """Spatulae of different length, stiffness and G0 dragged at ``V``.

    The same as :func:`gecko.simulate_spatulae` with a population (``length``, ``stiffness``,
    ``G0``: None, a number, one value per simulated spatula, or a distribution of mean 1
    ``{"dist": "lognormal", "sigma": s}`` / ``{"dist": "uniform", "width": h}``); the result's
    ``mean_par, mean_perp`` (the simulation, stationary from the start so the whole trace is
    steady) sit beside eqs 9-10 at the mean parameters (``mean_field_*``), averaged over the
    drawn spatulae (``population_*``: the limit of the simulation, within ``bound_*`` for fixed
    re-sticking) and averaged over the distributions (``expected_*``).

    Examples
    --------
    >>> import gecko.friction_hierarchy as fh
    >>> r = fh.spatula_population(1e-4, stiffness={"dist": "lognormal", "sigma": 0.5},
    ...                           spatulae=2000, seed=1)
    >>> bool(abs(r.mean_par - r.population_par) <= r.bound_par)
    True
    >>> bool(r.expected_par < r.mean_field_par)  # F ~ sqrt(K): the average is below the mean's
    True
    """
    return simulate_spatulae(V, model, length=length, stiffness=stiffness, G0=G0, **options)


class CompliantSeta(NamedTuple):
    """Result of :func:`compliant_seta` (forces of the N spatulae of the model, in N).

    Attributes
    ----------
    V, spring, stiffness_ratio : float
        Stage velocity, spring stiffness k_s and k_s over the collective stiffness N K_par_par.
    mean_par, mean_perp, std_par, std_perp : float
        Mean and standard deviation of the lateral (spring) and normal force, steady part.
    max_drop : float
        Largest drop of the lateral force in one slip (steady part).
    relative_drop : float
        max_drop / mean_par: the classifier.
    granularity : float
        The share of the mean force that one simulated spatula carries at detachment: the
        relative drop of a lone detachment, the floor of ``relative_drop``.
    max_slip_fraction : float
        The largest fraction of the simulated spatulae detaching in one slip (steady part).
    regime : str
        "stick-slip" if relative_drop >= threshold, else "smooth".
    spatulae, detachments, slips : int
    collective_stiffness, stretch, t_on, duration : float
    t, lag, F_par, F_perp : numpy.ndarray
        Sample times, the seta's lag behind the stage (minus its mean) and the forces.
    """

    V: float
    spring: float
    stiffness_ratio: float
    mean_par: float
    mean_perp: float
    std_par: float
    std_perp: float
    max_drop: float
    relative_drop: float
    granularity: float
    max_slip_fraction: float
    regime: str
    spatulae: int
    detachments: int
    slips: int
    collective_stiffness: float
    stretch: float
    t_on: float
    duration: float
    t: np.ndarray
    lag: np.ndarray
    F_par: np.ndarray
    F_perp: np.ndarray


def _collective_stiffness(model: SlidingModel, factors: dict) -> float:
    K = float(_matrix(model.K)[0])
    c = 1.0
    if factors:
        length = factors.get("length")
        stiff = factors.get("stiffness")
        l3 = 1.0 if length is None else length ** 3
        c = float(np.mean((1.0 if stiff is None else stiff) / l3))
    return float(model.N) * K * c


def compliant_seta(V: float, model: SlidingModel = FIG6_VISCOELASTIC, *, stiffness_ratio: Optional[float] = None,
                   spring: Optional[float] = None, spatulae: int = 200, periods: float = 30.0,
                   duration: Optional[float] = None, t_off=0.0, spatula=None, resticking: str = "fixed",
                   transient: float = 0.5, samples: int = 2000, seed: int = 1, length=None, stiffness=None,
                   G0=None, threshold: float = STICK_SLIP_THRESHOLD) -> CompliantSeta:
    """The model's spatulae at the end of a mass-less seta, dragged by a stage at ``V`` through a
    spring: smooth sliding or seta-level stick-slip?

    The spring force k_s (V t - x) balances the attached spatulae's lateral force at every
    instant; each spatula stretches with the seta's motion x, detaches at its dd (A2.6, G at the
    stage speed V), re-sticks after t_off where the seta then is. A detachment makes the seta jump
    to its new balance and can take others with it: a slip (exact, event by event, in C++).

    **Classification.** Over the steady part (after the first ``transient`` fraction), the
    largest lateral force lost in one slip over the mean force, ``relative_drop``, is compared with
    ``threshold`` (default 0.1): "stick-slip" if at least 10% of the seta's force goes in one slip
    (a collective slip of many spatulae: the seta lets go macroscopically), else "smooth". With
    independent spatulae (a rigid drive) the largest drop is one spatula's force, a fraction
    ``granularity`` ~ 2 / (M duty) of the total; ``granularity >= threshold / 2`` is refused
    (too few simulated spatulae to tell a collective slip from a lone one).

    Parameters
    ----------
    V : float
        Stage velocity (> 0).
    model : SlidingModel, optional
        The spatulae (default :data:`gecko.FIG6_VISCOELASTIC`).
    stiffness_ratio, spring : float
        The spring: k_s / (N K_par_par) (the population's collective stiffness), or k_s in N/m;
        exactly one.
    spatulae : int, optional
        Simulated spatulae M (default 200), each standing for N / M.
    periods : float, optional
        Default duration: this many spatula cycles (t_on + t_off), times 1 / stiffness_ratio when
        that is below 1 (the spring then takes ~ cycles / ratio to load).
    duration : float, optional
        Simulated time, overriding ``periods``.
    t_off, spatula, resticking : optional
        Re-sticking as in :func:`gecko.simulate_spatulae`.
    transient : float, optional
        Fraction of the run left out of the statistics (default 0.5).
    samples, seed : int, optional
    length, stiffness, G0 : optional
        A population as in :func:`gecko.simulate_spatulae`.
    threshold : float, optional
        Relative force drop of a seta-level slip (default :data:`STICK_SLIP_THRESHOLD`).

    Returns
    -------
    CompliantSeta

    Examples
    --------
    >>> import gecko.friction_hierarchy as fh
    >>> fh.compliant_seta(1e-4, stiffness_ratio=100.0, t_off=1e-4, seed=1).regime
    'smooth'
    >>> fh.compliant_seta(1e-4, stiffness_ratio=0.01, t_off=1e-4, seed=1).regime
    'stick-slip'
    """
    if resticking not in ("fixed", "exponential"):
        raise ValueError(f"resticking = {resticking!r} is not allowed: need 'fixed' or 'exponential'")
    if (stiffness_ratio is None) == (spring is None):
        raise ValueError("give exactly one of stiffness_ratio (k_s / (N K_par_par)) and spring (k_s, N/m)")
    if isinstance(spatulae, bool) or not isinstance(spatulae, (int, np.integer)) or spatulae < 1:
        raise ValueError(f"spatulae = {spatulae!r} is out of range: need an integer >= 1")
    threshold = _scalar(threshold, "threshold")
    if not 0 < threshold < 1:
        raise ValueError(f"threshold = {threshold!r} is out of range: need 0 < threshold < 1")
    t_off = _resolve_t_off(t_off, spatula)
    V = _scalar(V, "V")
    G = float(_law_values(model.law, np.array([max(V, 0.0)]))[0])  # V <= 0 is refused in C++
    M = int(spatulae)
    specs = {"length": length, "stiffness": stiffness, "G0": G0}
    factors = {}
    if any(v is not None for v in specs.values()):
        rng = np.random.default_rng([int(seed), 0x5EA])
        factors = {k: _population.draw(v, M, rng, k) for k, v in specs.items()}
    K_col = _collective_stiffness(model, factors)
    if spring is None:
        ratio = _scalar(stiffness_ratio, "stiffness_ratio")
        if not (ratio > 0 and math.isfinite(ratio)):
            raise ValueError(f"stiffness_ratio = {ratio!r} is out of range: need 0 < stiffness_ratio < inf")
        spring = ratio * K_col
    spring = _scalar(spring, "spring")
    ratio = spring / K_col
    if duration is None:
        ss = steady_sliding(V, model, t_off=t_off) if V > 0 else None
        P = float(ss.t_on) + t_off if ss is not None else 1.0
        duration = _scalar(periods, "periods") * P * max(1.0, 1.0 / ratio) if ratio > 0 else math.inf
    r = _core.simulate_compliant_seta(float(model.N), _matrix(model.K), float(model.f_par1), float(model.f_perp1),
                                      V, G, float(spring), M, float(duration), float(t_off),
                                      resticking == "exponential", float(transient), int(samples), int(seed),
                                      **{k: v for k, v in factors.items()})
    mean = r["mean_par"]
    # one mean simulated spatula's force at detachment, N/M (f_par1 + K dd) scaled by its c
    c = K_col / (float(model.N) * float(_matrix(model.K)[0]))
    f_det = float(model.N) / M * c * (float(model.f_par1) + float(_matrix(model.K)[0]) * r["stretch"])
    granularity = abs(f_det / mean) if mean != 0 else math.inf
    if granularity >= threshold / 2:
        raise ValueError(f"spatulae = {M} is out of range for threshold = {threshold:g}: one simulated spatula "
                         f"carries {granularity:.3g} of the mean force at detachment; need a share below "
                         f"threshold / 2 (simulate more spatulae)")
    rel = r["max_drop"] / mean if mean != 0 else math.inf
    return CompliantSeta(V, float(spring), float(ratio), mean, r["mean_perp"], r["std_par"], r["std_perp"],
                         r["max_drop"], float(rel), float(granularity), r["max_slip_size"] / M,
                         "stick-slip" if rel >= threshold else "smooth", M, int(r["detachments"]),
                         int(r["slips"]), float(r["collective_stiffness"]), float(r["stretch"]), float(r["t_on"]),
                         float(duration), r["t"], r["lag"], r["F_par"], r["F_perp"])


class StickSlipMap(NamedTuple):
    """Result of :func:`stick_slip_map`: arrays of shape (len(V), len(stiffness_ratio)).

    Attributes
    ----------
    stiffness_ratio, V : numpy.ndarray
        The axes (1-D).
    relative_drop, relative_std, max_slip_fraction : numpy.ndarray
        Per point: largest slip's force drop over the mean force, standard deviation of the
        lateral force over its mean, largest fraction of the spatulae in one slip.
    stick_slip : numpy.ndarray of bool
        relative_drop >= threshold.
    threshold : float
    """

    stiffness_ratio: np.ndarray
    V: np.ndarray
    relative_drop: np.ndarray
    relative_std: np.ndarray
    max_slip_fraction: np.ndarray
    stick_slip: np.ndarray
    threshold: float


def stick_slip_map(stiffness_ratio: Sequence[float], V: Sequence[float] = (1e-4,),
                   model: SlidingModel = FIG6_VISCOELASTIC, **options) -> StickSlipMap:
    """Smooth sliding or seta-level stick-slip over spring stiffness ratios and stage velocities.

    Runs :func:`compliant_seta` at every (V, stiffness_ratio) with the same ``options`` (and
    seed); see it for the model and the classification.

    Examples
    --------
    >>> import gecko.friction_hierarchy as fh
    >>> m = fh.stick_slip_map([0.01, 100.0], [1e-4], t_off=1e-4, seed=1)
    >>> m.stick_slip.tolist()
    [[True, False]]
    """
    ratios = np.atleast_1d(np.asarray(stiffness_ratio, dtype=np.float64))
    Vs = np.atleast_1d(np.asarray(V, dtype=np.float64))
    if ratios.ndim != 1 or Vs.ndim != 1 or not ratios.size or not Vs.size:
        raise ValueError("stiffness_ratio and V must be non-empty 1-D sequences")
    shape = (Vs.size, ratios.size)
    drop, rstd, frac = np.empty(shape), np.empty(shape), np.empty(shape)
    thr = options.get("threshold", STICK_SLIP_THRESHOLD)
    for i, v in enumerate(Vs):
        for j, q in enumerate(ratios):
            r = compliant_seta(float(v), model, stiffness_ratio=float(q), **options)
            drop[i, j] = r.relative_drop
            rstd[i, j] = r.std_par / r.mean_par
            frac[i, j] = r.max_slip_fraction
    return StickSlipMap(ratios, Vs, drop, rstd, frac, drop >= thr, float(thr))
