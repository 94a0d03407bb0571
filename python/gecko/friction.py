"""gecko.friction — frictional adhesion dynamics of the gecko spatula and seta.

Implements paper 000 (Yamaguchi, Gravish, Autumn, Creton, J. Phys. Chem. B 113, 3622 (2009)) as
restated in docs/theory/frictional_adhesion.md, plus two checks beyond it:

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
import math
from typing import Callable, NamedTuple, Optional

import numpy as np

from . import _core
from ._vectorize import error_code as _error_code, flat_args as _flat_args, shaped as _shaped
from ._vectorize import check_count as _check_count, real_array as _real_array
from ._vectorize import vectorised as _vectorised

#: outcome of a Levenberg-Marquardt fit, an IntEnum bound from C++ (gecko/friction/fit.hpp)
FitStatus = _core.FitStatus

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
    "SlidingModel", "PAPER_SPATULA", "FIG6_VISCOELASTIC", "FIG6_PLASTIC", "steady_sliding", "SteadySliding", "FitStatus",
    # beyond the paper
    "simulate_spatulae", "SpatulaSimulation", "fit_steady_sliding", "SteadySlidingFit",
    "ParametricLaw",
]

def _matrix(K, name: str = "K") -> np.ndarray:
    K = _real_array(K, name)
    if K.shape != (2, 2):
        raise ValueError(f"{name} must be a 2x2 matrix, got shape {K.shape}")
    return np.ascontiguousarray(K).reshape(-1)


def _scalar(x, name: str) -> float:
    a = _real_array(x, name)
    if a.shape != ():
        raise ValueError(f"{name} must be a scalar, got shape {a.shape}")
    return float(a)


# ---- curved beam (docs/theory/frictional_adhesion.md, Appendix 1) ------------------------------------------------

_MAX_LEVELS = 9          # tanh-sinh levels of the C++ table (graphs z(x))
_CURVE_MAX_LEVELS = 12   # levels of the numpy tanh-sinh for parametric curves


def _complex_step_lost(f, points, scale):
    """True if ``Im f(p + i h) / h`` disagrees with a central difference at ``points``: the
    callable drops the imaginary part (abs, np.real, a spline...), so the complex-step slope
    would silently be wrong."""
    h = 1e-30
    try:
        with np.errstate(all="ignore"):
            cs = np.imag(np.asarray(f(points + 1j * h), dtype=np.complex128)) / h
    except (TypeError, ValueError):
        return None   # refuses complex arguments: no silent loss, the caller decides
    d = 1e-6 * scale
    with np.errstate(all="ignore"):
        fd = (np.asarray(f(points + d), dtype=np.float64)
              - np.asarray(f(points - d), dtype=np.float64)) / (2 * d)
    if not (np.all(np.isfinite(cs)) and np.all(np.isfinite(fd))):
        return True
    return bool(np.any(np.abs(cs - fd) > 1e-5 * (np.abs(fd) + 1.0)))


def _fd_derivative(f, scale):
    """Five-point central difference (error ~ (h/scale)**4 + eps scale/h, about 1e-12)."""
    h = scale * np.finfo(float).eps ** 0.2

    def df(x):
        x = np.asarray(x, dtype=np.float64)
        return (8 * (np.asarray(f(x + h), float) - np.asarray(f(x - h), float))
                - (np.asarray(f(x + 2 * h), float) - np.asarray(f(x - 2 * h), float))) / (12 * h)
    return df


def _lost_warning(name):
    import warnings
    warnings.warn(f"gecko.castigliano_compliance: {name} drops the imaginary part of a complex "
                  "argument (abs, np.real, a spline, ...), so its complex-step derivative would be "
                  "wrong; using a five-point finite difference instead (relative accuracy about "
                  "1e-11). Pass the derivative explicitly to avoid this.", RuntimeWarning,
                  stacklevel=3)


def _tanh_sinh_nodes(level):
    """Nodes t in (0, 1), their complements 1 - t and weights dt/du of tanh-sinh level ``level``
    (level 0: u integer; level k: the odd multiples of 2**-k), dropping nodes where t or 1 - t
    rounds to 0."""
    h = 2.0 ** -level
    j = np.arange(0 if level == 0 else 1, int(4.0 / h) + 1, 1 if level == 0 else 2)
    u = j * h
    u = np.concatenate([-u[u > 0][::-1], u]) if level else np.concatenate([-u[1:][::-1], u])
    s = np.pi * np.sinh(u)
    with np.errstate(over="ignore"):
        t = 1.0 / (1.0 + np.exp(-s))
        c = 1.0 / (1.0 + np.exp(s))   # 1 - t, accurate near t = 1
        w = np.pi * np.cosh(u) * t * c
    keep = (t > 1e-300) & (c > 0) & (t < 1.0) & (w > 0)
    return t[keep], w[keep]


def _curve_compliance(curve, EI, EA, tol, max_levels, derivatives):
    """Compliance of a parametric centreline (x(t), z(t)), tip at t = 0, clamp at t = 1."""
    xs, zs = curve
    if callable(xs) != callable(zs):
        raise ValueError("curve must be two callables of t or two arrays of sampled points")
    if not callable(xs):
        x = np.asarray(xs, dtype=np.float64)
        z = np.asarray(zs, dtype=np.float64)
        if x.ndim != 1 or x.shape != z.shape or x.size < 4:
            raise ValueError("curve: sampled x and z must be 1-D arrays of equal length >= 4, got "
                             f"shapes {x.shape} and {z.shape}")
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(z))):
            raise ValueError("curve: sampled points must be finite")
        chord = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(z)))])
        if not np.all(np.diff(chord) > 0):
            i = int(np.flatnonzero(~(np.diff(chord) > 0))[0])
            raise ValueError(f"curve: points {i} and {i + 1} coincide")
        from scipy.interpolate import CubicSpline  # optional dependency, only for sampled curves
        tt = chord / chord[-1]
        sx, sz = CubicSpline(tt, x), CubicSpline(tt, z)
        fx, fz, dx, dz = sx, sz, sx.derivative(), sz.derivative()
    else:
        fx, fz = xs, zs
        dx, dz = derivatives if derivatives is not None else (None, None)
        probe = np.array([0.173, 0.5, 0.827])
        def derivative(f, d, name):
            if d is not None:
                return d
            if _complex_step_lost(f, probe, 1.0) is not False:   # lost, or refuses complex
                _lost_warning(name)
                return _fd_derivative(f, 1.0)
            return lambda t: np.imag(np.asarray(f(t + 1e-30j), np.complex128)) / 1e-30
        dx = derivative(fx, dx, "curve x(t)")
        dz = derivative(fz, dz, "curve z(t)")

    def vec(f, t, what):
        with np.errstate(all="ignore"):
            v = np.asarray(f(t), dtype=np.float64)
        if v.shape != t.shape:
            v = np.broadcast_to(v, t.shape) if v.shape == () else None
        if v is None:
            raise ValueError(f"curve: {what} must be numpy-vectorised (one value per t)")
        return v

    x0 = float(vec(fx, np.zeros(1), "x(t)")[0])
    z0 = float(vec(fz, np.zeros(1), "z(t)")[0])
    if not (np.isfinite(x0) and np.isfinite(z0)):
        raise ValueError(f"curve: the tip (x(0), z(0)) = ({x0}, {z0}) must be finite")

    def integral(level):
        t, w = _tanh_sinh_nodes(level)
        X, Z = vec(fx, t, "x(t)") - x0, vec(fz, t, "z(t)") - z0
        DX, DZ = vec(dx, t, "dx/dt"), vec(dz, t, "dz/dt")
        bad = ~(np.isfinite(X) & np.isfinite(Z) & np.isfinite(DX) & np.isfinite(DZ))
        if np.any(bad):
            raise ValueError(f"curve: not finite at t = {float(t[bad][0])!r}; need a finite "
                             "centreline and tangent for 0 < t < 1")
        ds = np.hypot(DX, DZ)
        wb = w * ds / EI
        c = np.array([np.sum(wb * Z * Z), np.sum(wb * Z * X), np.sum(wb * X * X)])
        if np.isfinite(EA):
            with np.errstate(invalid="ignore", divide="ignore"):
                wa = np.where(ds > 0, w / (EA * ds), 0.0)
            c += np.array([np.sum(wa * DX * DX), -np.sum(wa * DX * DZ), np.sum(wa * DZ * DZ)])
        return c, t.size

    tol = tol if tol > 0 else np.finfo(float).eps ** (2 / 3)
    total, evals = integral(0)
    prev = total
    err, level, converged = np.inf, 0, False
    for level in range(1, max_levels + 1):
        c, m = integral(level)
        evals += m
        cur = total / 2 + c * 2.0 ** -level   # the new level halves the step
        err = float(np.max(np.abs(cur - prev)))
        total, prev = cur, cur
        if level >= 3 and err <= tol * float(np.max(np.abs(cur))):
            converged = True
            break
    total = total * 1.0
    C = np.array([[total[0], total[1]], [total[1], total[2]]])
    info = {"error_estimate": err, "levels": level, "evaluations": int(evals),
            "converged": converged}
    if not converged:
        raise RuntimeError("gecko.castigliano_compliance: tanh-sinh quadrature of the curve did "
                           f"not converge (error estimate {err:.3g}); is it smooth on (0, 1)?")
    return C, info


def castigliano_compliance(z: Optional[Callable] = None, dzdx: Optional[Callable] = None, *,
                           L: float = 1.0, EI: float = 1.0, EA: float = np.inf, tol: float = 0.0,
                           max_levels: Optional[int] = None, report: bool = False, curve=None,
                           curve_derivatives=None):
    """Tip compliance C (2x2) of a planar curved beam, D = C F; :func:`rigidity` gives K.

    Castigliano's theorem on the bending energy (paper 000 Appendix 1, eq A1.1:
    M = -(z - z_tip) F_par - (x - x_tip) F_perp), plus the axial energy F_par t_x - F_perp t_z
    for a finite ``EA``. Tanh-sinh quadrature; for graphs after x = L t^2 (3 - 2t), which copes
    with a tip where ds/dx ~ x^-1/2 and with a vertical tangent at the clamp.

    Parameters
    ----------
    z : callable, optional
        A graph z(x), 0 <= x <= L, tip at x = 0, clamp at x = L: a Python function of one float.
    dzdx : callable, optional
        Its slope; default the complex step Im z(x + ih)/h (exact to rounding). A ``z`` that
        drops the imaginary part (abs, np.real, a spline) is detected at three probe points: a
        ``RuntimeWarning``, and a five-point finite difference (accuracy ~1e-11) replaces it.
    L : float, optional
        Horizontal extent of a graph (default 1).
    EI : float, optional
        Bending stiffness (default 1).
    EA : float, optional
        Axial stiffness (default inf: bending only).
    tol : float, optional
        Step between two quadrature levels that ends the refinement (0: eps^(2/3)).
    max_levels : int, optional
        Maximum tanh-sinh levels: 3..9 for graphs (default 9), 3..12 for curves (default 12);
        out of range is an error.
    report : bool, optional
        Also return a dict with the error estimate, levels and evaluations.
    curve : pair, optional
        A parametric centreline (x, z), tip at t = 0, clamp at t = 1: two numpy-vectorised
        callables of t (derivatives by the complex step, checked as for ``z``), or two arrays
        of sampled points interpolated by cubic splines in the normalised chord length (needs
        scipy). Any shape: vertical pillars, hooks, S-shapes. ``L`` is not used.
    curve_derivatives : pair of callables, optional
        (dx/dt, dz/dt) for a callable ``curve``.

    Returns
    -------
    numpy.ndarray of shape (2, 2), or (numpy.ndarray, dict) with ``report=True``

    Raises
    ------
    ValueError
        If L, EI, EA, tol or max_levels is out of range, or the energy integrals are not finite.

    Examples
    --------
    >>> import numpy as np, gecko
    >>> C = gecko.castigliano_compliance(lambda x: np.sqrt(x) / 2, L=1.0)
    >>> np.allclose(C, gecko.parabolic_beam_compliance(1.0, 1.0), rtol=1e-13)
    True
    >>> hook = gecko.castigliano_compliance(curve=(lambda t: np.sin(np.pi * t),
    ...                                            lambda t: 1 - np.cos(np.pi * t)))
    >>> np.allclose(hook, [[1.5 * np.pi, 2.0], [2.0, 0.5 * np.pi]], rtol=1e-14)
    True
    """
    EI_, EA_ = _scalar(EI, "EI"), _scalar(EA, "EA")
    tol = _scalar(tol, "tol")
    if not (tol >= 0) or not np.isfinite(tol):
        raise ValueError(f"tol = {tol!r} is out of range: need 0 <= tol < inf (0: default)")
    limit = _CURVE_MAX_LEVELS if curve is not None else _MAX_LEVELS
    levels = limit if max_levels is None else max_levels
    if isinstance(levels, bool) or int(levels) != levels or not (3 <= int(levels) <= limit):
        raise ValueError(f"max_levels = {max_levels!r} is out of range: need an integer "
                         f"3 <= max_levels <= {limit}")
    levels = int(levels)
    if curve is not None:
        if z is not None or dzdx is not None:
            raise ValueError("give either z (a graph z(x)) or curve=(x, z), not both")
        if not (isinstance(curve, (tuple, list)) and len(curve) == 2):
            raise ValueError("curve must be a pair (x, z) of callables of t or of sampled arrays")
        if not (EI_ > 0 and np.isfinite(EI_)):
            raise ValueError(f"gecko::castigliano_compliance: EI = {EI_!r} is out of range: "
                             "need 0 < EI < inf")
        if not EA_ > 0:
            raise ValueError(f"gecko::castigliano_compliance: EA = {EA_!r} is out of range: "
                             "need EA > 0 (inf: no axial term)")
        C, info = _curve_compliance(curve, EI_, EA_, tol, levels, curve_derivatives)
        return (C, info) if report else C
    if z is None or not callable(z):
        raise ValueError("z must be a callable z(x) (or pass curve=(x, z))")
    L_ = _scalar(L, "L")
    if dzdx is None and L_ > 0 and np.isfinite(L_):
        probe = L_ * np.array([0.173, 0.5, 0.827])
        zz = lambda x: np.array([complex(z(complex(v))) if np.iscomplexobj(x) else float(z(v))
                                 for v in np.atleast_1d(x)])
        # None (z refuses complex): the C++ slope raises a clear error naming dzdx.
        if _complex_step_lost(zz, probe, L_) is True:
            _lost_warning("z")
            fd = _fd_derivative(lambda x: np.array([float(z(float(v))) for v in np.atleast_1d(x)]),
                                L_)
            dzdx = lambda x: float(fd(np.array([x]))[0])
    C, info = _core.castigliano_compliance(z, dzdx, L_, EI_, EA_, float(tol), levels)
    return (C, info) if report else C


def _parabolic(L, EI, errors, rigid):
    shape, (fl, fe) = _flat_args((L, EI))
    out = _core.parabolic_beam_compliance(fl, fe, _error_code(errors), rigid)
    return out[0] if shape == () else out.reshape(shape + (2, 2))


def parabolic_beam_compliance(L=1.0, EI=1.0, *, errors: str = "raise"):
    """Closed-form compliance of the parabolic beam z = sqrt(L x)/2 (paper 000 eq A1.5).

    C = (L^3 / 2 EI) [[a11, a12], [a12, a22]], with the sign of a11 corrected
    (docs/theory/frictional_adhesion.md). Broadcasts over ``L`` and ``EI``.

    Parameters
    ----------
    L : array_like, optional
        Length along x (default 1), > 0.
    EI : array_like, optional
        Bending stiffness (default 1), > 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    numpy.ndarray
        Shape (..., 2, 2).

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> gecko.parabolic_beam_compliance(1.0, 1.0).round(6)
    array([[0.132362, 0.210044],
           [0.210044, 0.348521]])
    """
    return _parabolic(L, EI, errors, False)


def parabolic_beam_rigidity(L=1.0, EI=1.0, *, errors: str = "raise"):
    """Rigidity K = C^-1 of the parabolic beam (paper 000 Appendix 1, eqs 2 and 12).

    Normalised to K[0, 0] = 5 it is [[5, -3.0134], [-3.0134, 1.8989]], which the paper rounds to
    [[5, -3], [-3, 2]].

    Parameters
    ----------
    L : array_like, optional
        Length along x (default 1), > 0.
    EI : array_like, optional
        Bending stiffness (default 1), > 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    numpy.ndarray
        Shape (..., 2, 2).

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> K = gecko.parabolic_beam_rigidity()
    >>> (5 * K / K[0, 0]).round(4)
    array([[ 5.    , -3.0134],
           [-3.0134,  1.8989]])
    """
    return _parabolic(L, EI, errors, True)


def rigidity(C, *, errors: str = "raise"):
    """Rigidity K = C^-1 of symmetric positive definite 2x2 compliances.

    Parameters
    ----------
    C : array_like
        Compliances, shape (..., 2, 2).
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    numpy.ndarray
        Shape (..., 2, 2).

    Raises
    ------
    ValueError
        If ``C`` is not of shape (..., 2, 2), or not symmetric positive definite.

    Examples
    --------
    >>> import gecko
    >>> gecko.rigidity([[2.0, 1.0], [1.0, 1.0]])
    array([[ 1., -1.],
           [-1.,  2.]])
    """
    C = _real_array(C, "C")
    if C.shape[-2:] != (2, 2):
        raise ValueError(f"C must have shape (..., 2, 2), got {C.shape}")
    out = _core.rigidity(np.ascontiguousarray(C).reshape(-1), _error_code(errors))
    return out.reshape(C.shape)


# ---- paths and force traces (eqs 1-3, 11-13; Figs 4 and 8) -------------------------------

class DisplacementPath(NamedTuple):
    """Vertices of a piecewise-linear displacement path for :func:`force_trace`.

    At time ``t[i]`` the tip is at ``(d_par[i], d_perp[i])``; between vertices it moves linearly.

    Attributes
    ----------
    t : tuple of float
        Strictly increasing times.
    d_par, d_perp : tuple of float
        Lateral and normal displacements at those times.

    Examples
    --------
    >>> import gecko
    >>> gecko.FIG4_SPATULA_PATH.d_perp               # press in, then drag at fixed depth
    (0.0, 1.0, 1.0)
    """

    t: tuple
    d_par: tuple
    d_perp: tuple


#: Fig 4 / eq 3: (0,0) -> (0,1) by t = 0.5 s (load), -> (3,1) by t = 2 s (drag).
FIG4_SPATULA_PATH = DisplacementPath((0.0, 0.5, 2.0), (0.0, 0.0, 3.0), (0.0, 1.0, 1.0))
#: Fig 8 / eq 13: (0,0) -> (4,7) -> (6,7) -> (0,0) (load, drag, pull); one time unit per leg.
FIG8_SETA_PATH = DisplacementPath((0.0, 1.0, 2.0, 3.0), (0.0, 4.0, 6.0, 0.0), (0.0, 7.0, 7.0, 0.0))


def paper_rigidity() -> np.ndarray:
    """The paper's illustrative rigidity [[5, -3], [-3, 2]] (paper 000 eqs 2 and 12).

    Returns
    -------
    numpy.ndarray
        A new (2, 2) array.

    Examples
    --------
    >>> import gecko
    >>> gecko.paper_rigidity()
    array([[ 5., -3.],
           [-3.,  2.]])
    """
    return np.array([[5.0, -3.0], [-3.0, 2.0]])


class ForceTrace(NamedTuple):
    """A force trace from :func:`force_trace`, arrays ready to plot.

    Attributes
    ----------
    t : numpy.ndarray
        Sample times.
    d_par, d_perp : numpy.ndarray
        Displacements of the tip.
    f_par, f_perp : numpy.ndarray
        Forces f = K d (f_perp < 0: tensile).

    Examples
    --------
    >>> import gecko
    >>> tr = gecko.force_trace()
    >>> float(tr.f_perp.max()), float(tr.f_perp.min())   # compressive, then tensile
    (2.0, -7.0)
    """

    t: np.ndarray
    d_par: np.ndarray
    d_perp: np.ndarray
    f_par: np.ndarray
    f_perp: np.ndarray


def force_trace(K=None, path=FIG4_SPATULA_PATH, *, times=None, samples_per_segment: int = 50
                ) -> ForceTrace:
    """Forces f(t) = K d(t) along a piecewise-linear displacement path (paper 000 eqs 1-3, 11-13).

    Parameters
    ----------
    K : array_like, optional
        Rigidity (2, 2), symmetric positive definite; default :func:`paper_rigidity`.
    path : DisplacementPath or (t, d_par, d_perp), optional
        Vertices of the path, ``t`` strictly increasing; default :data:`FIG4_SPATULA_PATH`
        (paper 000 Fig 4). :data:`FIG8_SETA_PATH` is Fig 8's.
    times : array_like, optional
        Sample times inside the path; default ``samples_per_segment`` points per leg plus every
        vertex exactly.
    samples_per_segment : int, optional
        Default 50.

    Returns
    -------
    ForceTrace
        Arrays ``t, d_par, d_perp, f_par, f_perp``.

    Raises
    ------
    ValueError
        If K is not symmetric positive definite or the path is malformed.

    Examples
    --------
    >>> import gecko
    >>> tr = gecko.force_trace()                    # Fig 4: compression, then drag
    >>> float(tr.f_perp[-1]), float(tr.f_par[-1])   # tensile at the end of the drag
    (-7.0, 12.0)
    """
    K = paper_rigidity() if K is None else K
    t, d_par, d_perp = (np.ascontiguousarray(_real_array(a, f"path[{i}]").reshape(-1)) for i, a in enumerate(path))
    tt = None if times is None else np.ascontiguousarray(_real_array(times, "times").reshape(-1))
    r = _core.force_trace(_matrix(K), t, d_par, d_perp, tt, int(samples_per_segment))
    return ForceTrace(r["t"], r["d_par"], r["d_perp"], r["f_par"], r["f_perp"])


# ---- detachment (eqs 4, 7, 8, A2.6) --------------------------------------------------------

def viscoelastic_detachment(V, G0, V_star, n, *, errors: str = "raise"):
    """Viscoelastic detachment energy, paper 000 eq 7: G(V) = G0 (1 + (V/V*)^n).

    Parameters
    ----------
    V : array_like
        Drag velocity, >= 0.
    G0, V_star, n : array_like
        Threshold energy, characteristic velocity, exponent; all > 0. Broadcast together.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> float(gecko.viscoelastic_detachment(4.0, 1.0, 1.0, 0.5))
    3.0
    """
    return _vectorised(_core.viscoelastic_detachment, V, G0, V_star, n, errors=errors)


def eyring_detachment(V, G0, V_star, *, errors: str = "raise"):
    """Plastic (Eyring) detachment energy, paper 000 eq 8: G(V) = G0 asinh(V/V*).

    Parameters
    ----------
    V : array_like
        Drag velocity, >= 0.
    G0, V_star : array_like
        Threshold energy and characteristic velocity, > 0. Broadcast together.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.eyring_detachment(1.0, 1.0, 1.0)), 6)
    0.881374
    """
    return _vectorised(_core.eyring_detachment, V, G0, V_star, errors=errors)


@dataclasses.dataclass(frozen=True)
class ViscoelasticDetachment:
    """The viscoelastic law of paper 000 eq 7 as a callable, G = law(V).

    Parameters
    ----------
    G0, V_star, n : float
        See :func:`viscoelastic_detachment`.

    Examples
    --------
    >>> import gecko
    >>> law = gecko.ViscoelasticDetachment(G0=1.0, V_star=1.0, n=0.5)
    >>> float(law(4.0))
    3.0
    """

    G0: float
    V_star: float
    n: float

    def __call__(self, V, *, errors: str = "raise"):
        return viscoelastic_detachment(V, self.G0, self.V_star, self.n, errors=errors)


@dataclasses.dataclass(frozen=True)
class EyringDetachment:
    """The plastic (Eyring) law of paper 000 eq 8 as a callable, G = law(V).

    Parameters
    ----------
    G0, V_star : float
        See :func:`eyring_detachment`.

    Examples
    --------
    >>> import gecko
    >>> gecko.EyringDetachment(1.0, 1.0)([0.0, 1.0]).round(6)
    array([0.      , 0.881374])
    """

    G0: float
    V_star: float

    def __call__(self, V, *, errors: str = "raise"):
        return eyring_detachment(V, self.G0, self.V_star, errors=errors)


def detachment_stretch(K_par_par, f_par1, G, *, errors: str = "raise"):
    """Lateral stretch at detachment, paper 000 eq A2.6.

    Solves K dd^2/2 + f_par1 dd = G for the positive root, (-f1 + sqrt(f1^2 + 2 K G))/K, in a form
    without cancellation.

    Parameters
    ----------
    K_par_par : array_like
        Lateral rigidity, > 0.
    f_par1 : array_like
        Lateral force just after re-sticking, finite.
    G : array_like
        Detachment energy, >= 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> float(gecko.detachment_stretch(2.0, 0.0, 1.0))
    1.0
    """
    return _vectorised(_core.detachment_stretch, K_par_par, f_par1, G, errors=errors)


def resonant_frequency(D, L, E, rho, *, errors: str = "raise"):
    """Resonant frequency of a cantilevered spatula, paper 000 eq 4: 0.14 (D/L^2) sqrt(E/rho).

    The re-sticking time is about its inverse. For D = 100 nm, L = 1 um, E = 1.5 GPa,
    rho = 1000 kg/m^3 this is 17.1 MHz; the paper prints 34.3 MHz, twice what its own formula gives
    (docs/theory/frictional_adhesion.md).

    Parameters
    ----------
    D, L, E, rho : array_like
        Diameter, length, Young's modulus, density (SI), all > 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray
        In Hz for SI input.

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``; the message names it and the
        allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.resonant_frequency(100e-9, 1e-6, 1.5e9, 1000.0)) / 1e6, 1)
    17.1
    """
    return _vectorised(_core.resonant_frequency, D, L, E, rho, errors=errors)


# ---- steady sliding (eqs 5, 6, 9, 10) --------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class SlidingModel:
    """N spatulae of rigidity K that re-stick with forces (f_par1, f_perp1) and detach at law(V).

    K is symmetric positive definite: K[0,1] < 0 the paper's curved beam, K[0,1] = 0 a straight
    pillar, K[0,1] > 0 a beam dragged against its curvature (regular friction).

    Parameters
    ----------
    N : float
        Number of spatulae.
    K : tuple
        Rigidity ((K_par_par, K_par_perp), (K_perp_par, K_perp_perp)), symmetric positive
        definite with K[0][1] < 0.
    f_par1, f_perp1 : float
        Forces just after re-sticking.
    law : callable
        :class:`ViscoelasticDetachment`, :class:`EyringDetachment`, or any callable G(V) (called
        with the array of velocities first, element by element if that fails).

    Examples
    --------
    >>> import gecko
    >>> gecko.FIG6_VISCOELASTIC.replace(N=2e5).N
    200000.0
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
    """Mean forces of steady sliding, from :func:`steady_sliding`.

    Attributes
    ----------
    F_par, F_perp : float or numpy.ndarray
        Time-averaged lateral and normal force of the N spatulae (F_perp < 0: tensile).
    stretch : float or numpy.ndarray or None
        Lateral stretch at detachment (None with ``forces_only=True``).
    t_on : float or numpy.ndarray or None
        Attached time per cycle, stretch / V.

    Examples
    --------
    >>> import gecko
    >>> r = gecko.steady_sliding(1e-4)
    >>> round(float(r.F_par), 4), r.t_on > 0
    (0.0424, True)
    """

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


#: The paper's spatula for eq 4: D = 100 nm, L = 1 um, E = 1.5 GPa, rho = 1000 kg/m**3.
PAPER_SPATULA = {"D": 1e-7, "L": 1e-6, "E": 1.5e9, "rho": 1000.0}


def _resolve_t_off(t_off, spatula):
    """A number, or "eq4": t_off = 1 / nu_R of eq 4 for ``spatula`` (a dict D, L, E, rho;
    default :data:`PAPER_SPATULA`, 58.4 ns from the formula; the paper's printed 34.3 MHz would
    give 29.2 ns)."""
    if isinstance(t_off, str):
        if t_off != "eq4":
            raise ValueError(f"t_off = {t_off!r} is not allowed: need a number >= 0 or 'eq4' "
                             "(1 / the resonant frequency of eq 4)")
        geo = dict(PAPER_SPATULA)
        if spatula is not None:
            unknown = set(spatula) - set(geo)
            if unknown:
                raise ValueError(f"spatula has unknown keys {sorted(unknown)}: need D, L, E, rho")
            geo.update(spatula)
        return 1.0 / float(resonant_frequency(geo["D"], geo["L"], geo["E"], geo["rho"]))
    if spatula is not None:
        raise ValueError("spatula is only used with t_off='eq4'")
    return _scalar(t_off, "t_off")


def steady_sliding(V, model: SlidingModel = FIG6_VISCOELASTIC, *, t_off=0.0, spatula=None,
                   errors: str = "raise", forces_only: bool = False) -> SteadySliding:
    """Steady-sliding mean forces of paper 000 eqs 9-10, with a finite re-sticking time.

    F = N t_on/(t_on + t_off) (f1 + K[:, 0] dd/2), t_on = dd/V, where the stretch dd solves
    K dd^2/2 + f_par1 dd = G(V) (eq A2.6). Built-in laws run entirely in C++.

    Parameters
    ----------
    V : array_like
        Drag velocities (any shape), >= 0.
    model : SlidingModel, optional
        Default :data:`FIG6_VISCOELASTIC`.
    t_off : float or "eq4", optional
        Re-sticking time (default 0, the paper's limit); "eq4": 1 / nu_R of eq 4 for
        ``spatula`` (a dict of D, L, E, rho; default :data:`PAPER_SPATULA`, 58.4 ns).
    spatula : dict, optional
        Geometry for ``t_off="eq4"``.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises (default) or gives NaN.
    forces_only : bool, optional
        Skip ``stretch`` and ``t_on`` (None): faster for long arrays.

    Returns
    -------
    SteadySliding
        ``F_par, F_perp, stretch, t_on`` of the shape of ``V``.

    Raises
    ------
    ValueError
        If V < 0 or the model is invalid, with ``errors="raise"``.

    Examples
    --------
    >>> import gecko
    >>> r = gecko.steady_sliding([1e-5, 1e-4, 1e-3])
    >>> r.F_par.round(4), r.F_perp.round(4)       # the normal force turns tensile as V grows
    (array([0.0349, 0.0424, 0.0586]), array([ 0.0014, -0.0026, -0.0113]))
    """
    code = _error_code(errors)
    t_off = _resolve_t_off(t_off, spatula)
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
    """Result of :func:`simulate_spatulae`: the force of N spatulae estimated from M simulated.

    Attributes
    ----------
    mean_par, mean_perp : float
        Time averages of F(t) over the simulated duration.
    std_par, std_perp : float
        Standard deviations of F(t) over the sample times (the fluctuation).
    stretch, t_on : float
        Stretch at detachment and attached time per cycle.
    detachments : int
        Detachments simulated.
    t, F_par, F_perp : numpy.ndarray
        Sample times (midpoints) and F(t) there.

    Examples
    --------
    >>> import gecko
    >>> sim = gecko.simulate_spatulae(1e-4, spatulae=200, seed=1)
    >>> sim.detachments > 0, sim.F_par.shape
    (True, (200,))
    """

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
    # eqs 9-10 (with the duty factor of eqs 5-6) at the mean parameters, averaged over the
    # simulated population, and the bound on |mean - population| (fixed re-sticking; inf else)
    mean_field_par: float = math.nan
    mean_field_perp: float = math.nan
    population_par: float = math.nan
    population_perp: float = math.nan
    bound_par: float = math.nan
    bound_perp: float = math.nan
    # eqs 9-10 averaged over the distributions themselves (NaN when a factor is an array)
    expected_par: float = math.nan
    expected_perp: float = math.nan
    factors: Optional[dict] = None  # the drawn per-spatula factors (None: all spatulae equal)


def simulate_spatulae(V: float, model: SlidingModel = FIG6_VISCOELASTIC, *, spatulae: int = 1000,
                      duration: Optional[float] = None, t_off=0.0, spatula=None,
                      resticking: str = "fixed", samples: int = 200, seed: int = 1,
                      length=None, stiffness=None, G0=None) -> SpatulaSimulation:
    """Simulate independent spatulae dragged at ``V``: a stochastic check of :func:`steady_sliding`.

    Each spatula sticks, stretches, detaches and re-sticks after ``t_off`` (fixed, or exponential
    with that mean), starting from a stationary random phase; seeded ``mt19937_64``, exact
    event-driven integration. The means converge to :func:`steady_sliding` with the same ``t_off``.

    Parameters
    ----------
    V : float
        Drag velocity, >= 0.
    model : SlidingModel, optional
        Default :data:`FIG6_VISCOELASTIC`.
    spatulae : int, optional
        Number M of simulated spatulae (default 1000); forces are scaled to the model's N.
    duration : float, optional
        Simulated time (default 100 cycles).
    t_off : float or "eq4", optional
        Re-sticking time (default 0); "eq4" as in :func:`steady_sliding`.
    spatula : dict, optional
        Geometry for ``t_off="eq4"``.
    resticking : {"fixed", "exponential"}, optional
    samples : int, optional
        Sample times of F(t) (default 200).
    seed : int, optional
        Random seed (default 1); a seed gives the same result everywhere.
    length, stiffness, G0 : optional
        A population: per-spatula factors on the spatula of ``model`` (None: all 1; a number;
        an array of one value per simulated spatula; or a distribution of mean 1,
        ``{"dist": "lognormal", "sigma": s}`` or ``{"dist": "uniform", "width": h}``, drawn
        from ``seed``). Spatula i has K_i = c_i K and re-sticking forces c_i f1 with
        c_i = stiffness_i / length_i**3 (K ~ EI / L**3, Appendix 1), G_i = G0_i G(V) and
        t_off_i = length_i**2 t_off (eq 4). The result then also carries eqs 9-10 at the mean
        parameters (``mean_field_*``), averaged over the drawn spatulae (``population_*``, what
        the simulation converges to) and over the distributions (``expected_*``).

    Returns
    -------
    SpatulaSimulation

    Raises
    ------
    ValueError
        If an argument is out of range.

    Examples
    --------
    >>> import gecko
    >>> sim = gecko.simulate_spatulae(1e-4, spatulae=2000, seed=1)
    >>> ref = gecko.steady_sliding(1e-4)
    >>> abs(sim.mean_par / float(ref.F_par) - 1) < 1e-3
    True
    """
    if resticking not in ("fixed", "exponential"):
        raise ValueError(f"resticking = {resticking!r} is not allowed: need 'fixed' or 'exponential'")
    t_off = _resolve_t_off(t_off, spatula)
    V = _scalar(V, "V")
    law = model.law
    G = float(_law_values(law, np.array([max(V, 0.0)]))[0])  # V < 0 is refused in C++
    if duration is None:
        ss = steady_sliding(V, model, t_off=t_off)
        duration = 100.0 * (ss.t_on + t_off)
    from . import _population
    specs = {"length": length, "stiffness": stiffness, "G0": G0}
    factors = None
    if any(v is not None for v in specs.values()):
        if isinstance(spatulae, bool) or not isinstance(spatulae, (int, np.integer)) or spatulae < 1:
            raise ValueError(f"spatulae = {spatulae!r} is out of range: need an integer >= 1")
        # the population's own stream, apart from the C++ phases' (a population seeded 1 is
        # the same population whatever the phases)
        rng = np.random.default_rng([int(seed), 0x5EA])
        factors = {k: _population.draw(v, int(spatulae), rng, k) for k, v in specs.items()}
    r = _core.simulate_spatulae(float(model.N), _matrix(model.K), float(model.f_par1),
                                float(model.f_perp1), V, G, int(spatulae), float(duration),
                                float(t_off), resticking == "exponential", int(samples), int(seed),
                                **(factors or {}))
    expected = (r["population_par"], r["population_perp"]) if factors is None else None
    if factors is not None and V > 0:
        def single(Gp):
            return _core.steady_sliding_energy(np.full(Gp.size, V), np.ascontiguousarray(Gp),
                                               float(model.N), _matrix(model.K),
                                               float(model.f_par1), float(model.f_perp1), 0.0, 0,
                                               False)[:3]
        expected = _population.expected_forces(specs, V, G, float(t_off), single)
    exp_par, exp_perp = expected if expected is not None else (math.nan, math.nan)
    return SpatulaSimulation(r["mean_par"], r["mean_perp"], r["std_par"], r["std_perp"],
                             r["stretch"], r["t_on"], int(r["detachments"]), r["t"], r["F_par"],
                             r["F_perp"], r["mean_field_par"], r["mean_field_perp"],
                             r["population_par"], r["population_perp"], r["bound_par"],
                             r["bound_perp"], exp_par, exp_perp, factors)


@dataclasses.dataclass(frozen=True)
class ParametricLaw:
    """A user detachment law ``G = func(V, **params)`` with named parameters.

    For :func:`steady_sliding`, :func:`simulate_spatulae` and :func:`fit_steady_sliding` (which fits
    its parameters by name).

    Parameters
    ----------
    func : callable
        ``func(V, **params)``; must accept an array of velocities (numpy-vectorised).
    params : dict
        The parameters by name, with their values (the starting values of a fit).
    positive : tuple of str, optional
        Parameters that must stay positive (fitted as logarithms); default: all of them.
    bounds : dict, optional
        ``{name: (lower, upper)}`` (either may be None or +-inf): a fit keeps the parameter
        strictly inside, fitting ``log((p - lo)/(hi - p))`` (both finite), ``log(p - lo)`` or
        ``log(hi - p)``; a bounded parameter is not also taken as positive. Its standard error is
        mapped by the derivative of that transform; where the fit ends at a bound it is NaN and
        the fit's ``reason`` says so.

    Examples
    --------
    >>> import numpy as np, gecko
    >>> law = gecko.ParametricLaw(lambda V, G0, a: G0 * (1 + a * np.log1p(V / 1e-4)),
    ...                           {"G0": 3e-14, "a": 0.5})
    >>> float(law(0.0))
    3e-14
    >>> law.replace(a=1.0).params
    {'G0': 3e-14, 'a': 1.0}
    """

    func: Callable
    params: dict
    positive: Optional[tuple] = None
    bounds: Optional[dict] = None

    def __call__(self, V):
        return self.func(V, **self.params)

    def replace(self, **params) -> "ParametricLaw":
        return dataclasses.replace(self, params={**self.params, **params})


class SteadySlidingFit(NamedTuple):
    """Result of :func:`fit_steady_sliding`.

    Attributes
    ----------
    model : SlidingModel
        The fitted model.
    names : tuple of str
        The free parameters.
    values, standard_errors : numpy.ndarray
        Their estimates and standard errors (delta method from the fit coordinates).
    covariance : numpy.ndarray
        Covariance of the estimates.
    rss : float
        Sum of squared unweighted residuals (N**2).
    iterations : int
        Levenberg-Marquardt iterations.
    status : str
        "converged" (a first-order criterion holds at a finite chi**2; ``reason`` says which),
        "not_identifiable" (converged, but the data do not determine the directions listed in
        ``undetermined``; see the profile intervals), "max_iterations", "no_progress" or
        "non_finite" (the fitted values or rss overflow).
    reason : str
        Why the fit stopped.
    chi2, dof, condition : float, int, float
        Weighted chi**2, degrees of freedom, condition number of the column-scaled J^T J.
    undetermined : tuple of str
        Directions the data cannot determine.
    profile_lower, profile_upper : numpy.ndarray or None
        Profile-likelihood intervals (chi**2 rise at the ``profile_level`` quantile; NaN when not
        computed, +-inf where the profile never rises enough).
    sigma_known : bool
        Whether the covariance takes sigma as known (not rescaled by the reduced chi**2).

    Examples
    --------
    >>> import numpy as np, gecko
    >>> V = np.logspace(-6, -2, 20)
    >>> r = gecko.steady_sliding(V)
    >>> fit = gecko.fit_steady_sliding(V, r.F_par, r.F_perp, fit_f_par1=False)
    >>> fit.status, len(fit.values) == len(fit.names)
    ('converged', True)
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

    @property
    def status_code(self) -> "FitStatus":
        """``status`` as a :class:`FitStatus` member (code compares these, not the text)."""
        return FitStatus[self.status]


def _sigma_array(s, n, name):
    a = _real_array(s, name)
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



def _fit_data(V, F_par, F_perp):
    """The three data arrays, flat float64, after the checks a fit needs (same shape, no
    broadcasting; finite forces, 0 <= V < inf), each error naming the argument and element."""
    arrays = [_real_array(a, name) for a, name in ((V, "V"), (F_par, "F_par"), (F_perp, "F_perp"))]
    for a, name in zip(arrays[1:], ("F_par", "F_perp")):
        if a.shape != arrays[0].shape:
            raise ValueError(f"gecko.fit_steady_sliding: {name} has shape {a.shape} and V has shape "
                             f"{arrays[0].shape}: need one measured force per velocity")
    out = [np.ascontiguousarray(a, dtype=np.float64).reshape(-1) for a in arrays]
    for a, name, need in ((out[0], "V", "0 <= V < inf (drag velocity)"),
                          (out[1], "F_par", "finite measured forces"),
                          (out[2], "F_perp", "finite measured forces")):
        bad = ~np.isfinite(a) if name != "V" else ~((a >= 0) & np.isfinite(a))
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(f"gecko.fit_steady_sliding: {name}[{i}] = {float(a[i])!r} is out of range: "
                             f"need {need}")
    return out


class _Bounds:
    """Bounds of a ParametricLaw's parameters and the transforms that keep a fit inside them:
    p = lo + (hi - lo)/(1 + exp(-t)) (both finite), lo + exp(t), hi - exp(t)."""

    def __init__(self, bounds, names, start):
        self.names, self.box = list(names), {}
        if bounds is None:
            self.bounded = ()
            return
        if not isinstance(bounds, dict):
            raise ValueError(f"guess.law.bounds = {bounds!r} is not allowed: need a dict {{name: (lower, upper)}}")
        for k, b in bounds.items():
            if k not in self.names:
                raise ValueError(f"guess.law.bounds names an unknown parameter {k!r}; parameters: "
                                 + ", ".join(self.names))
            if not (isinstance(b, (tuple, list)) and len(b) == 2):
                raise ValueError(f"guess.law.bounds[{k!r}] = {b!r} is not allowed: need (lower, upper)")
            lo = -math.inf if b[0] is None else _scalar(b[0], f"guess.law.bounds[{k!r}][0]")
            hi = math.inf if b[1] is None else _scalar(b[1], f"guess.law.bounds[{k!r}][1]")
            if math.isnan(lo) or math.isnan(hi) or not lo < hi or lo == math.inf or hi == -math.inf:
                raise ValueError(f"guess.law.bounds[{k!r}] = ({lo!r}, {hi!r}) is out of range: need "
                                 "lower < upper (either may be infinite)")
            p0 = start[self.names.index(k)]
            if not lo < p0 < hi:
                raise ValueError(f"guess.law.params[{k!r}] = {p0!r} is out of range: need a start strictly "
                                 f"inside its bounds ({lo!r}, {hi!r})")
            if math.isfinite(lo) or math.isfinite(hi):
                self.box[k] = (lo, hi)
        self.bounded = tuple(self.box)

    def _forward(self, k, t):
        lo, hi = self.box[k]
        if math.isfinite(lo) and math.isfinite(hi):
            return lo + (hi - lo) / (1.0 + math.exp(-t)) if t > -700 else lo
        return lo + math.exp(t) if math.isfinite(lo) else hi - math.exp(t)

    def _slope(self, k, p):
        lo, hi = self.box[k]
        if math.isfinite(lo) and math.isfinite(hi):
            return (p - lo) * (hi - p) / (hi - lo)
        return p - lo if math.isfinite(lo) else -(hi - p)

    def coordinates(self, start):
        out = []
        for k, p in zip(self.names, start):
            if k not in self.box:
                out.append(p)
                continue
            lo, hi = self.box[k]
            out.append(math.log((p - lo) / (hi - p)) if math.isfinite(lo) and math.isfinite(hi)
                       else math.log(p - lo) if math.isfinite(lo) else math.log(hi - p))
        return out

    def values(self, t):
        return [self._forward(k, float(x)) if k in self.box else float(x) for k, x in zip(self.names, t)]

    def map_result(self, r):
        """The C++ result in the transformed coordinates -> the parameters (delta method)."""
        vals = list(r["values"])
        d = np.ones(len(vals))
        at_bound = []
        for j, name in enumerate(r["names"]):
            if name not in self.box:
                continue
            t = vals[j]
            p = self._forward(name, t)
            d[j] = self._slope(name, p)
            vals[j] = p
            lo, hi = self.box[name]
            for side in ("profile_lower", "profile_upper"):
                tb = r[side][j]
                r[side][j] = (tb if math.isnan(tb) else lo if tb == -math.inf and d[j] > 0
                              else hi if tb == -math.inf else hi if tb == math.inf and d[j] > 0
                              else lo if tb == math.inf else self._forward(name, tb))
            if r["profile_lower"][j] > r["profile_upper"][j]:
                r["profile_lower"][j], r["profile_upper"][j] = r["profile_upper"][j], r["profile_lower"][j]
            span = (hi - lo) if math.isfinite(hi - lo) else max(abs(p), 1.0)
            if abs(d[j]) <= 1e-9 * span:  # the transform is flat: the fit sits on the bound
                at_bound.append(name)
        cov = np.asarray(r["covariance"]) * np.outer(d, d)
        se = np.abs(np.asarray(r["standard_errors"]) * d)
        for name in at_bound:
            se[r["names"].index(name)] = float("nan")
        r["values"], r["covariance"], r["standard_errors"] = vals, cov, list(se)
        if at_bound:
            r["reason"] = (r["reason"] + "; " + ", ".join(at_bound) + " ended at a bound: its standard "
                           "error is not defined (NaN)")


def _check_law_at_start(G, V, values):
    """A ParametricLaw must give one finite G per velocity at its starting values: otherwise the
    fit could not start; say so naming the law rather than failing inside the solver."""
    try:
        with np.errstate(all="ignore"):
            g = np.asarray(G(V, values), dtype=np.float64)
    except Exception as exc:  # noqa: BLE001 - reported with the law named
        raise ValueError(f"guess.law: calling the law at its starting parameters raised "
                         f"{type(exc).__name__}: {exc}") from exc
    if g.shape != V.shape:
        raise ValueError(f"guess.law returns shape {g.shape} for {V.size} velocities: need one G "
                         "per velocity (a numpy-vectorised function)")
    bad = ~np.isfinite(g)
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"guess.law gives G = {float(g[i])!r} at V[{i}] = {float(V[i])!r} with its "
                         "starting parameters: need a finite G at every measured velocity")


def fit_steady_sliding(V, F_par, F_perp, guess: SlidingModel = FIG6_VISCOELASTIC, *,
                       fit_f_par1: Optional[bool] = None, fit_f_perp1: bool = True,
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

    Parameters
    ----------
    V, F_par, F_perp : array_like
        Velocities and the two mean forces, same length, more data than parameters.
    guess : SlidingModel, optional
        Starting model; its law (viscoelastic, Eyring or a ParametricLaw) is the one fitted.
    fit_f_par1 : bool or None, optional
        Free f_par1. Default (None): free when the guess law has G(0) = 0 (Eyring: the
        low-speed lateral force is N f_par1 alone), held at ``guess.f_par1`` when G(0) > 0
        (viscoelastic: the plateau N sqrt(K G0/2) and f_par1 both set the low-speed force and
        only the curvature of the rise separates them; on Fig 6 data at 25 speeds and 0.5 mN
        noise its standard error exceeds the whole plateau / N, and 1 fit in 8 ends at the
        degenerate V* -> 0). ``names`` lists what was fitted.
    fit_f_perp1, fit_coupling : bool, optional
        Free f_perp1 (default True) and the coupling K[0,1] (default False).
    max_iterations : int, optional
        Default 200.
    sigma : tuple of (float or array_like), optional
        ``(sigma_par, sigma_perp)``, scalars or one per velocity.
    absolute_sigma : bool, optional
        Take sigma as known (default True when sigma is given).
    profile : bool, optional
        Compute profile-likelihood intervals.
    profile_level : float, optional
        Coverage of the profile intervals (default one standard deviation, 0.6827).
    max_condition : float, optional
        Condition number above which a direction counts as undetermined.

    Returns
    -------
    SteadySlidingFit
        Estimates, standard errors, covariance, rss, status and the reason it stopped.

    Raises
    ------
    ValueError
        If the data are not finite (the message names the array and element), of different
        shapes or too few, V < 0, sigma is not positive and finite, a flag is not a bool, or the
        law cannot be fitted (a ParametricLaw that raises, returns the wrong shape or a
        non-finite G at its starting values).

    Examples
    --------
    >>> import numpy as np, gecko
    >>> V = np.logspace(-6, -2, 40)
    >>> r = gecko.steady_sliding(V, gecko.FIG6_VISCOELASTIC)
    >>> fit = gecko.fit_steady_sliding(V, r.F_par, r.F_perp, fit_f_par1=False)
    >>> fit.status
    'converged'
    """
    from statistics import NormalDist

    v, fp, fq = _fit_data(V, F_par, F_perp)
    for flag, name in ((fit_f_par1, "fit_f_par1"), (fit_f_perp1, "fit_f_perp1"),
                       (fit_coupling, "fit_coupling"), (profile, "profile"),
                       (absolute_sigma, "absolute_sigma")):
        if not (isinstance(flag, (bool, np.bool_)) or (flag is None and name in ("fit_f_par1", "absolute_sigma"))):
            raise ValueError(f"{name} = {flag!r} is not allowed: need True or False"
                             + (" (or None: automatic)" if name == "fit_f_par1" else ""))
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
        start = [_scalar(law.params[k], f"guess.law.params[{k!r}]") for k in names]
        box = _Bounds(law.bounds, names, start)
        positive = tuple(k for k in positive if k not in box.bounded)

        def G(Vv, pv, _names=names, _func=func):
            return np.asarray(_func(Vv, **dict(zip(_names, map(float, pv)))), dtype=np.float64)

        _check_law_at_start(G, v, start)

        def Gt(Vv, tv, _G=G):  # the solver's coordinates: bounded parameters transformed
            return _G(Vv, box.values(tv))

        custom = dict(custom_G=Gt if box.bounded else G, custom_names=names,
                      custom_values=box.coordinates(start),
                      custom_positive=[k in positive for k in names])
        if fit_f_par1 is None:
            # the automatic choice of the C++ fit, decided here: a law that fails at V = 0
            # (log V, 1/V) has no finite plateau and f_par1 is fitted
            try:
                with np.errstate(all="ignore"):
                    g0 = float(np.asarray(G(np.zeros(1), start),
                                          dtype=np.float64).reshape(-1)[0])
            except Exception:  # noqa: BLE001 - any failure means "no finite G(0)"
                g0 = float("nan")
            fit_f_par1 = not (math.isfinite(g0) and g0 > 0)
    else:
        raise ValueError("guess.law must be a ViscoelasticDetachment, an EyringDetachment or a "
                         "ParametricLaw (a callable with named parameters)")
    if not (0 < profile_level < 1):
        raise ValueError(f"profile_level = {profile_level!r} is out of range: need 0 < level < 1")
    if not (max_condition > 1):
        raise ValueError(f"max_condition = {max_condition!r} is out of range: need > 1")
    max_iterations = _check_count(max_iterations, "max_iterations")  # an integer >= 1, not 2.5 or 0
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
                                 n, None if fit_f_par1 is None else bool(fit_f_par1), bool(fit_f_perp1),
                                 bool(fit_coupling),
                                 max_iterations, sp, sq, known,
                                 bool(profile), float(delta),
                                 float(max_condition), **custom)
    if kind == 2 and box.bounded:
        box.map_result(r)
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
