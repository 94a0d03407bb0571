"""gecko.friction — frictional adhesion dynamics of the gecko spatula and seta.

Implements paper 000 (Yamaguchi, Gravish, Autumn, Creton, J. Phys. Chem. B 113, 3622 (2009)) as
restated in models.md §2, plus two checks beyond it:

* curved-beam compliance and rigidity by Castigliano for any centreline ``z(x)``
  (:func:`castigliano_compliance`), and the Appendix-1 parabola in closed form
  (:func:`parabolic_beam_compliance`, :func:`parabolic_beam_rigidity`), :func:`rigidity`;
* force traces ``f(t) = K d(t)`` along piecewise-linear displacement paths (:func:`force_trace`,
  presets :data:`FIG4_SPATULA_PATH`, :data:`FIG8_SETA_PATH`, rigidity :func:`paper_rigidity`);
* detachment laws :func:`viscoelastic_detachment` (eq 7), :func:`eyring_detachment` (eq 8), as
  law objects :class:`ViscoelasticDetachment`, :class:`EyringDetachment`, or any Python
  callable; :func:`detachment_stretch` (A2.6), :func:`resonant_frequency` (eq 4);
* steady sliding forces (eqs 5, 6, 9, 10) with finite ``t_off``: :func:`steady_sliding`, with the
  Fig 6 fits as :data:`FIG6_VISCOELASTIC` and :data:`FIG6_PLASTIC`;
* a stochastic simulation of independent spatulae (:func:`simulate_spatulae`) and a
  Levenberg–Marquardt fit of the model to data (:func:`fit_steady_sliding`).

Units are SI throughout (V in m/s, forces in N, G in J, K in N/m); the model only depends on
V/V*, so any consistent units work. Array arguments broadcast like numpy ufuncs; the loops run in
C++ without the GIL. Bad input raises ``ValueError`` naming the argument and the allowed range
(``errors="nan"`` gives NaN elements instead, for batch work).
"""
from __future__ import annotations

import dataclasses
from typing import Callable, NamedTuple, Optional

import numpy as np

from . import _core
from ._vectorize import error_code as _error_code, flat_args as _flat_args, shaped as _shaped

__all__ = [
    # beam
    "castigliano_compliance", "parabolic_beam_compliance", "parabolic_beam_rigidity", "rigidity",
    # paths and traces
    "DisplacementPath", "FIG4_SPATULA_PATH", "FIG8_SETA_PATH", "paper_rigidity", "force_trace",
    "ForceTrace",
    # detachment
    "viscoelastic_detachment", "eyring_detachment", "ViscoelasticDetachment", "EyringDetachment",
    "detachment_stretch", "resonant_frequency",
    # steady sliding
    "SlidingModel", "FIG6_VISCOELASTIC", "FIG6_PLASTIC", "steady_sliding", "SteadySliding",
    # beyond the paper
    "simulate_spatulae", "SpatulaSimulation", "fit_steady_sliding", "SteadySlidingFit",
    "ParametricLaw",
]

def _matrix(K, name: str = "K") -> np.ndarray:
    K = np.asarray(K, dtype=np.float64)
    if K.shape != (2, 2):
        raise ValueError(f"{name} must be a 2x2 matrix, got shape {K.shape}")
    return np.ascontiguousarray(K).reshape(-1)


def _scalar(x, name: str) -> float:
    a = np.asarray(x, dtype=np.float64)
    if a.shape != ():
        raise ValueError(f"{name} must be a scalar, got shape {a.shape}")
    return float(a)


# ---- curved beam (models.md §2, Appendix 1) ------------------------------------------------

def castigliano_compliance(z: Callable, dzdx: Optional[Callable] = None, *, L: float = 1.0,
                           EI: float = 1.0, EA: float = np.inf, tol: float = 0.0,
                           max_levels: int = 9, report: bool = False):
    """Tip compliance C (2x2) of a planar curved beam with centreline ``z(x)``, ``0 <= x <= L``.

    The tip (loaded by ``(F_par, F_perp)``) is at ``x = 0``, the clamp at ``x = L``; the moment is
    ``M = -(z - z(0)) F_par - x F_perp`` (paper 000 eq A1.1) and, for finite ``EA``, the axial
    force ``F_par t_x - F_perp t_z`` adds its energy. ``D = C F``; ``rigidity(C)`` gives K.

    ``z`` is a Python callable of one float. The slope comes from ``dzdx`` if given, else by the
    complex step ``Im z(x + i h) / h`` (exact to rounding; needs ``z`` to accept complex numbers,
    e.g. written with numpy functions). Tanh-sinh quadrature after ``x = L t**2`` copes with a
    tip where ``ds/dx ~ x**-1/2``; ``tol`` (0: eps**(2/3)) is the step between two quadrature
    levels, the result is then accurate to a few eps. With ``report=True`` returns
    ``(C, info)`` with the error estimate, levels and evaluations.
    """
    C, info = _core.castigliano_compliance(z, dzdx, _scalar(L, "L"), _scalar(EI, "EI"),
                                           _scalar(EA, "EA"), float(tol), int(max_levels))
    return (C, info) if report else C


def _parabolic(L, EI, errors, rigid):
    shape, (fl, fe) = _flat_args((L, EI))
    out = _core.parabolic_beam_compliance(fl, fe, _error_code(errors), rigid)
    return out[0] if shape == () else out.reshape(shape + (2, 2))


def parabolic_beam_compliance(L=1.0, EI=1.0, *, errors: str = "raise"):
    """Closed-form compliance of the parabola z = sqrt(L x)/2 (Appendix 1, a11 sign corrected).

    ``C = (L**3 / 2 EI) [[a11, a12], [a12, a22]]``; broadcasts over L and EI, shape (..., 2, 2).
    """
    return _parabolic(L, EI, errors, False)


def parabolic_beam_rigidity(L=1.0, EI=1.0, *, errors: str = "raise"):
    """K = C**-1 of the parabolic beam; normalised so K[0,0] = 5 it is [[5, -3.013], [-3.013, 1.899]]."""
    return _parabolic(L, EI, errors, True)


def rigidity(C, *, errors: str = "raise"):
    """K = C**-1 of symmetric positive definite 2x2 compliances C (shape (..., 2, 2))."""
    C = np.asarray(C, dtype=np.float64)
    if C.shape[-2:] != (2, 2):
        raise ValueError(f"C must have shape (..., 2, 2), got {C.shape}")
    out = _core.rigidity(np.ascontiguousarray(C).reshape(-1), _error_code(errors))
    return out.reshape(C.shape)


# ---- paths and force traces (eqs 1-3, 11-13; Figs 4 and 8) -------------------------------

class DisplacementPath(NamedTuple):
    """Vertices of a piecewise-linear path: at time ``t[i]`` the tip is at ``(d_par[i], d_perp[i])``."""

    t: tuple
    d_par: tuple
    d_perp: tuple


#: Fig 4 / eq 3: (0,0) -> (0,1) by t = 0.5 s (load), -> (3,1) by t = 2 s (drag).
FIG4_SPATULA_PATH = DisplacementPath((0.0, 0.5, 2.0), (0.0, 0.0, 3.0), (0.0, 1.0, 1.0))
#: Fig 8 / eq 13: (0,0) -> (4,7) -> (6,7) -> (0,0) (load, drag, pull); one time unit per leg.
FIG8_SETA_PATH = DisplacementPath((0.0, 1.0, 2.0, 3.0), (0.0, 4.0, 6.0, 0.0), (0.0, 7.0, 7.0, 0.0))


def paper_rigidity() -> np.ndarray:
    """The paper's illustrative rigidity [[5, -3], [-3, 2]] (eqs 2 and 12)."""
    return np.array([[5.0, -3.0], [-3.0, 2.0]])


class ForceTrace(NamedTuple):
    """A force trace, arrays ready to plot: time, displacement and force components."""

    t: np.ndarray
    d_par: np.ndarray
    d_perp: np.ndarray
    f_par: np.ndarray
    f_perp: np.ndarray


def force_trace(K=None, path=FIG4_SPATULA_PATH, *, times=None, samples_per_segment: int = 50
                ) -> ForceTrace:
    """``f(t) = K d(t)`` along a piecewise-linear path (default: Fig 4 with the paper's K).

    ``path`` is a :class:`DisplacementPath` or a tuple ``(t, d_par, d_perp)`` with strictly
    increasing ``t``. Sampled at ``times`` (inside the path) if given, else at
    ``samples_per_segment`` points per leg plus every vertex exactly.
    """
    K = paper_rigidity() if K is None else K
    t, d_par, d_perp = (np.ascontiguousarray(np.asarray(a, dtype=np.float64).reshape(-1))
                        for a in path)
    tt = None if times is None else np.ascontiguousarray(np.asarray(times, dtype=np.float64).reshape(-1))
    r = _core.force_trace(_matrix(K), t, d_par, d_perp, tt, int(samples_per_segment))
    return ForceTrace(r["t"], r["d_par"], r["d_perp"], r["f_par"], r["f_perp"])


# ---- detachment (eqs 4, 7, 8, A2.6) --------------------------------------------------------

def viscoelastic_detachment(V, G0, V_star, n, *, errors: str = "raise"):
    """Eq 7: G(V) = G0 (1 + (V/V*)**n); V >= 0, G0, V*, n > 0. Broadcasts."""
    shape, flat = _flat_args((V, G0, V_star, n))
    return _shaped(_core.viscoelastic_detachment(*flat, _error_code(errors)), shape)


def eyring_detachment(V, G0, V_star, *, errors: str = "raise"):
    """Eq 8 (plastic / Eyring): G(V) = G0 asinh(V/V*); V >= 0, G0, V* > 0. Broadcasts."""
    shape, flat = _flat_args((V, G0, V_star))
    return _shaped(_core.eyring_detachment(*flat, _error_code(errors)), shape)


@dataclasses.dataclass(frozen=True)
class ViscoelasticDetachment:
    """The law of eq 7 as a callable object, G = law(V)."""

    G0: float
    V_star: float
    n: float

    def __call__(self, V, *, errors: str = "raise"):
        return viscoelastic_detachment(V, self.G0, self.V_star, self.n, errors=errors)


@dataclasses.dataclass(frozen=True)
class EyringDetachment:
    """The law of eq 8 as a callable object, G = law(V)."""

    G0: float
    V_star: float

    def __call__(self, V, *, errors: str = "raise"):
        return eyring_detachment(V, self.G0, self.V_star, errors=errors)


def detachment_stretch(K_par_par, f_par1, G, *, errors: str = "raise"):
    """A2.6: lateral stretch at detachment, (-f1 + sqrt(f1**2 + 2 K G)) / K (cancellation-free)."""
    shape, flat = _flat_args((K_par_par, f_par1, G))
    return _shaped(_core.detachment_stretch(*flat, _error_code(errors)), shape)


def resonant_frequency(D, L, E, rho, *, errors: str = "raise"):
    """Eq 4: nu_R = 0.14 (D / L**2) sqrt(E / rho); t_off ~ 1 / nu_R.

    For D = 100 nm, L = 1 um, E = 1.5 GPa, rho = 1000 kg/m**3 this is 17.1 MHz; the paper prints
    34.3 MHz, twice what its own formula gives.
    """
    shape, flat = _flat_args((D, L, E, rho))
    return _shaped(_core.resonant_frequency(*flat, _error_code(errors)), shape)


# ---- steady sliding (eqs 5, 6, 9, 10) --------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class SlidingModel:
    """N spatulae of rigidity K (symmetric positive definite, K[0,1] < 0), re-sticking with
    forces (f_par1, f_perp1), detaching at the energy ``law(V)``.

    ``law``: :class:`ViscoelasticDetachment`, :class:`EyringDetachment`, or any callable of V
    (called with the array of velocities first, element by element if that fails).
    """

    N: float
    K: tuple
    f_par1: float
    f_perp1: float
    law: Callable

    def replace(self, **changes) -> "SlidingModel":
        return dataclasses.replace(self, **changes)


#: Fig 6, viscoelastic fit: f_par1 = 0, N sqrt(K G0/2) = 0.03 N, V* = 100 um/s, n = 0.45,
#: N f_perp1 = 0.02 N, sqrt(K_perp_par**2 G0 / (2 K f_perp1**2)) = 0.8. SI; N = 1e5, K = 6 N/m
#: chosen (only these combinations enter eqs 9-10).
FIG6_VISCOELASTIC = SlidingModel(N=1e5, K=((6.0, -3.2), (-3.2, 2.4)), f_par1=0.0, f_perp1=2e-7,
                                 law=ViscoelasticDetachment(G0=3e-14, V_star=1e-4, n=0.45))
#: Fig 6, plastic (Eyring) fit: f_perp1 = 0, N f_par1/2 = 0.03 N, 2 K G0 / f_par1**2 = 1,
#: V* = 600 um/s, N K_perp_par f_par1 / (2 K) = -0.025 N.
FIG6_PLASTIC = SlidingModel(N=1e5, K=((6.0, -5.0), (-5.0, 5.0)), f_par1=6e-7, f_perp1=0.0,
                            law=EyringDetachment(G0=3e-14, V_star=6e-4))


class SteadySliding(NamedTuple):
    """Time-averaged forces of the N spatulae, stretch at detachment and t_on = stretch / V."""

    F_par: object
    F_perp: object
    stretch: object
    t_on: object


def _law_values(law, V_flat):
    """G(V) of a Python law: vectorised if it accepts arrays, else element by element."""
    try:
        G = np.asarray(law(V_flat), dtype=np.float64)
        if G.shape == V_flat.shape:
            return np.ascontiguousarray(G)
        if G.shape == () and V_flat.size == 1:
            return G.reshape(1)
    except (TypeError, ValueError) as exc:
        if isinstance(exc, ValueError) and "gecko" in str(exc):
            raise
    return np.fromiter((float(law(float(v))) for v in V_flat), dtype=np.float64,
                       count=V_flat.size)


def steady_sliding(V, model: SlidingModel = FIG6_VISCOELASTIC, *, t_off: float = 0.0,
                   errors: str = "raise", forces_only: bool = False) -> SteadySliding:
    """Steady-sliding forces F_par(V), F_perp(V) of eqs 9-10, with finite ``t_off`` (eqs 5-6):

        F = N t_on / (t_on + t_off) * (f1 + K[:,0] stretch / 2),  t_on = stretch / V,

    where the stretch at detachment solves K dd**2/2 + f_par1 dd = G(V) (A2.6). ``V`` broadcasts
    (any shape); built-in laws run entirely in C++, other callables are evaluated first.
    ``forces_only=True`` skips ``stretch`` and ``t_on`` (returned as None): faster for long arrays.
    """
    code = _error_code(errors)
    shape, (v,) = _flat_args((V,))
    K = _matrix(model.K)
    law = model.law
    if isinstance(law, ViscoelasticDetachment):
        out = _core.steady_sliding_law(v, float(model.N), K, float(model.f_par1),
                                       float(model.f_perp1), 0, float(law.G0), float(law.V_star),
                                       float(law.n), float(t_off), code, bool(forces_only))
    elif isinstance(law, EyringDetachment):
        out = _core.steady_sliding_law(v, float(model.N), K, float(model.f_par1),
                                       float(model.f_perp1), 1, float(law.G0), float(law.V_star),
                                       1.0, float(t_off), code, bool(forces_only))
    elif callable(law):
        if code == 0 and np.any(~(v >= 0)):
            bad = v[~(v >= 0)][0]
            raise ValueError(f"gecko::steady_sliding: V = {float(bad):.17g} is out of range: need "
                             "0 <= V < inf (drag velocity)")
        G = _law_values(law, np.where(v >= 0, v, 0.0))
        out = _core.steady_sliding_energy(v, G, float(model.N), K, float(model.f_par1),
                                          float(model.f_perp1), float(t_off), code,
                                          bool(forces_only))
    else:
        raise ValueError(f"law = {law!r} is not allowed: need a detachment law or a callable G(V)")
    return SteadySliding(*(None if a is None else _shaped(a, shape) for a in out))


# ---- beyond the paper: stochastic check and fit -------------------------------------------

class SpatulaSimulation(NamedTuple):
    """Result of :func:`simulate_spatulae`: the force of N spatulae estimated from M simulated."""

    mean_par: float      # time average of F_par(t) over [0, duration]
    mean_perp: float
    std_par: float       # standard deviation of F(t) over the sample times (fluctuation)
    std_perp: float
    stretch: float
    t_on: float
    detachments: int
    t: np.ndarray        # sample times (midpoints) and F(t) there
    F_par: np.ndarray
    F_perp: np.ndarray


def simulate_spatulae(V: float, model: SlidingModel = FIG6_VISCOELASTIC, *, spatulae: int = 1000,
                      duration: Optional[float] = None, t_off: float = 0.0,
                      resticking: str = "fixed", samples: int = 200, seed: int = 1
                      ) -> SpatulaSimulation:
    """Simulate ``spatulae`` independent spatulae dragged at ``V`` (stick, stretch, detach,
    re-stick after ``t_off`` — fixed, or exponential with that mean) from a stationary random
    phase; seeded ``mt19937_64``, exact event-driven integration. ``duration`` defaults to 100
    cycles. The means converge to :func:`steady_sliding` with the same ``t_off``: the error
    falls as (M T)**-1/2 for exponential re-sticking and as M**-1/2 T**-1 for a fixed t_off.
    """
    if resticking not in ("fixed", "exponential"):
        raise ValueError(f"resticking = {resticking!r} is not allowed: need 'fixed' or 'exponential'")
    V = _scalar(V, "V")
    law = model.law
    G = float(_law_values(law, np.array([max(V, 0.0)]))[0])  # V < 0 is refused in C++
    if duration is None:
        ss = steady_sliding(V, model, t_off=t_off)
        duration = 100.0 * (ss.t_on + t_off)
    r = _core.simulate_spatulae(float(model.N), _matrix(model.K), float(model.f_par1),
                                float(model.f_perp1), V, G, int(spatulae), float(duration),
                                float(t_off), resticking == "exponential", int(samples), int(seed))
    return SpatulaSimulation(r["mean_par"], r["mean_perp"], r["std_par"], r["std_perp"],
                             r["stretch"], r["t_on"], int(r["detachments"]), r["t"], r["F_par"],
                             r["F_perp"])


@dataclasses.dataclass(frozen=True)
class ParametricLaw:
    """A user detachment law ``G = func(V, **params)`` with named parameters, for
    :func:`steady_sliding`, :func:`simulate_spatulae` and :func:`fit_steady_sliding`.

    ``func`` must accept an array of velocities (numpy-vectorised). ``positive`` names the
    parameters that must stay positive (fitted as logarithms); default: all of them.
    Example: ``ParametricLaw(lambda V, G0, a: G0 * (1 + a * np.log1p(V / 1e-4)), {"G0": 3e-14,
    "a": 0.5})``.
    """

    func: Callable
    params: dict
    positive: Optional[tuple] = None

    def __call__(self, V):
        return self.func(V, **self.params)

    def replace(self, **params) -> "ParametricLaw":
        return dataclasses.replace(self, params={**self.params, **params})


class SteadySlidingFit(NamedTuple):
    """Result of :func:`fit_steady_sliding`.

    ``status``: "converged" (a first-order criterion holds at a finite chi**2; ``reason`` says
    which), "not_identifiable" (converged, but the data do not determine the directions listed in
    ``undetermined``; see the profile intervals), "max_iterations", "no_progress" or
    "non_finite" (the fitted values or rss overflow). ``profile_lower/upper``: profile-likelihood
    intervals (chi**2 rise ``profile_level`` quantile; NaN when not computed, +-inf where the
    profile never rises enough).
    """

    model: SlidingModel           # the fitted model
    names: tuple                  # free parameters
    values: np.ndarray            # their estimates
    standard_errors: np.ndarray   # and standard errors (delta method from the fit coordinates)
    covariance: np.ndarray
    rss: float                    # sum of squared unweighted residuals (N**2)
    iterations: int
    status: str
    reason: str = ""
    chi2: float = float("nan")    # sum of squared weighted residuals
    dof: int = 0
    condition: float = float("nan")   # of the column-scaled J^T J
    undetermined: tuple = ()
    profile_lower: Optional[np.ndarray] = None
    profile_upper: Optional[np.ndarray] = None
    sigma_known: bool = False


def _sigma_array(s, n, name):
    a = np.asarray(s, dtype=np.float64)
    if a.ndim > 1 or (a.ndim == 1 and a.size != n):
        raise ValueError(f"{name} must be a scalar or have one entry per velocity ({n}), got shape "
                         f"{a.shape}")
    a = np.ascontiguousarray(np.broadcast_to(a, (n,)), dtype=np.float64)
    bad = ~((a > 0) & np.isfinite(a))
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"gecko.fit_steady_sliding: {name}[{i}] = {float(a[i])!r} is out of range: need "
                         "0 < sigma < inf")
    return a


def fit_steady_sliding(V, F_par, F_perp, guess: SlidingModel = FIG6_VISCOELASTIC, *,
                       fit_f_par1: bool = True, fit_f_perp1: bool = True,
                       fit_coupling: bool = False, max_iterations: int = 200,
                       sigma=None, absolute_sigma: Optional[bool] = None, profile: bool = False,
                       profile_level: float = 0.6826894921370859,
                       max_condition: float = 1e10) -> SteadySlidingFit:
    """Weighted least-squares fit of eqs 9-10 to measured (V, F_par, F_perp).

    Free: the law's parameters ((G0, V*, n) viscoelastic, (G0, V*) Eyring, or the named
    parameters of a :class:`ParametricLaw`; positive ones as logarithms), and ``f_par1``,
    ``f_perp1`` and ``K[0,1]`` as chosen; ``N``, ``K[0,0]``, ``K[1,1]`` are held (only
    ``N f1``, ``N**2 K[0,0] G`` and ``K[0,1]/K[0,0]`` enter eqs 9-10). Solved by
    Levenberg-Marquardt with QR-factorised steps (C++).

    ``sigma = (sigma_par, sigma_perp)``: standard deviations of the two force components,
    scalars or one per velocity. With ``absolute_sigma`` (default when sigma is given) they are
    taken as known and the covariance is not rescaled; otherwise (and without sigma) it is
    rescaled by the reduced chi**2. ``profile=True`` adds profile-likelihood intervals at
    ``profile_level`` (always computed when the status is "not_identifiable").
    """
    from statistics import NormalDist

    shape, (v, fp, fq) = _flat_args((V, F_par, F_perp))
    if not isinstance(guess, SlidingModel):
        raise ValueError(f"guess = {guess!r} is not allowed: need a SlidingModel")
    law = guess.law
    custom = {}
    if isinstance(law, ViscoelasticDetachment):
        kind, n = 0, float(law.n)
    elif isinstance(law, EyringDetachment):
        kind, n = 1, 1.0
    elif isinstance(law, ParametricLaw):
        kind, n = 2, 1.0
        names = list(law.params)
        if not names:
            raise ValueError("guess.law.params must name at least one parameter")
        positive = tuple(names) if law.positive is None else tuple(law.positive)
        unknown = set(positive) - set(names)
        if unknown:
            raise ValueError(f"guess.law.positive names unknown parameters {sorted(unknown)}")
        func = law.func

        def G(Vv, pv, _names=names, _func=func):
            return np.asarray(_func(Vv, **dict(zip(_names, map(float, pv)))), dtype=np.float64)

        custom = dict(custom_G=G, custom_names=names,
                      custom_values=[_scalar(law.params[k], f"guess.law.params[{k!r}]")
                                     for k in names],
                      custom_positive=[k in positive for k in names])
    else:
        raise ValueError("guess.law must be a ViscoelasticDetachment, an EyringDetachment or a "
                         "ParametricLaw (a callable with named parameters)")
    if not (0 < profile_level < 1):
        raise ValueError(f"profile_level = {profile_level!r} is out of range: need 0 < level < 1")
    if not (max_condition > 1):
        raise ValueError(f"max_condition = {max_condition!r} is out of range: need > 1")
    if int(max_iterations) < 0:
        raise ValueError(f"max_iterations = {max_iterations!r} is out of range: need >= 0")
    delta = NormalDist().inv_cdf(0.5 + profile_level / 2) ** 2
    sp = sq = None
    if sigma is not None:
        if not (isinstance(sigma, (tuple, list)) and len(sigma) == 2):
            raise ValueError("sigma must be a pair (sigma_par, sigma_perp) of scalars or arrays")
        sp = _sigma_array(sigma[0], v.size, "sigma_par")
        sq = _sigma_array(sigma[1], v.size, "sigma_perp")
    known = sigma is not None and (True if absolute_sigma is None else bool(absolute_sigma))
    r = _core.fit_steady_sliding(v, fp, fq, float(guess.N), _matrix(guess.K), float(guess.f_par1),
                                 float(guess.f_perp1), kind,
                                 float(getattr(law, "G0", 1.0)), float(getattr(law, "V_star", 1.0)),
                                 n, bool(fit_f_par1), bool(fit_f_perp1), bool(fit_coupling),
                                 int(max_iterations), sp, sq, known, bool(profile), float(delta),
                                 float(max_condition), **custom)
    values = dict(zip(r["names"], r["values"]))
    if kind == 0:
        new_law = ViscoelasticDetachment(values["G0"], values["V_star"], values["n"])
    elif kind == 1:
        new_law = EyringDetachment(values["G0"], values["V_star"])
    else:
        new_law = law.replace(**{k: values[k] for k in law.params})
    K = np.asarray(r["K"])
    model = SlidingModel(N=guess.N, K=tuple(map(tuple, K.tolist())), f_par1=float(r["f_par1"]),
                         f_perp1=float(r["f_perp1"]), law=new_law)
    return SteadySlidingFit(model, tuple(r["names"]), np.asarray(r["values"]),
                            np.asarray(r["standard_errors"]), np.asarray(r["covariance"]),
                            float(r["rss"]), int(r["iterations"]), str(r["status"]),
                            str(r["reason"]), float(r["chi2"]), int(r["dof"]),
                            float(r["condition"]), tuple(r["undetermined"]),
                            np.asarray(r["profile_lower"]), np.asarray(r["profile_upper"]), known)
