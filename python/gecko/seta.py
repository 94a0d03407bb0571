"""gecko.seta — the two-level seta of directional adhesion and the classical peel lines.

models.md §1. ``TwoLevelSeta`` holds a design (defaults: the paper's reference scene) and computes
its exact critical line of adhesion in C++ (Carlson forms of the elastica lengths, turning points
and folds included, the GIL released)::

    import gecko, numpy as np
    seta = gecko.TwoLevelSeta()                       # EI1=5, EI2=2, EA1=inf, EA2=50, ...
    line = seta.critical_line(Ft=np.linspace(0, 9.9, 1000))
    line.Fn, line.theta_joint, line.status            # numpy arrays, NaN where status != 0

Status codes (``line.status``): 0 converged; 1 Newton did not converge; 2 no critical state on the
line followed from Ft = 0 (beyond a fold, |Ft| > (Ft)max); 3 state outside the model's forms
(also: the line left them before reaching this Ft); 4 singular (Ft exactly at a fold); 5 bad input
under ``errors="nan"``; 6 not reached: the continuation gave up before this Ft (point budget, step
collapse, corrector failure; ``critical_line().end`` says which), so whether a critical state
exists there is unknown, unlike 2; 7 inadmissible: the state solves the equations (paper 001 eq
(15)) but the deformed seta crosses the substrate before the contact edge (``min_z < 0``: the
joint or the beam below it), or its largest axial strain exceeds ``strain_limit``. Status-7 states
keep their ``Fn``, ``theta_joint`` and the rest (for drawing); they are no state of a real seta.

Every solved state reports ``min_z`` (its lowest height above the substrate over the seta, 0 when
the contact edge is the lowest point), ``min_z_at`` (the arc length s of that point) and
``max_axial_strain`` (the largest |T|/EA along the seta).

Bad input raises ``ValueError`` naming the parameter and its allowed range (or, with
``errors="nan"``, marks the element with status 5).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from . import _core
from ._vectorize import error_code as _error_code, vectorised as _vectorised

__all__ = [
    "TwoLevelSeta", "SingleFiber", "CriticalLine", "SetaCharacteristics", "kendall_fn", "rivlin_fn",
    "critical_line_batch", "STATUS",
]

STATUS = {
    0: "converged",
    1: "not converged",
    2: "no critical state",
    3: "unsupported state",
    4: "singular (at a fold)",
    5: "invalid input",
    6: "not reached (the followed line was given up before this Ft)",
    7: "inadmissible (solves the equations but the seta crosses the substrate or the strain limit)",
}

_LINE_END = {
    0: "reached the requested end of the Ft range",
    1: "reached (Ft)max = sqrt(2 EA2 w)",
    2: "turned back after a fold",
    3: "no convergence (singular point)",
    4: "left the model (axial load comparable to EA)",
    5: "point budget exhausted",
    6: "natural state not found",
    7: "stalled (the step collapsed; given up)",
}

_MIN_STATUS = {
    0: "stationary",        # interior minimum, dFn/dFt = 0 verified there (slope_at_min_fn)
    1: "range_start",       # at Ft = 0
    2: "range_end",         # at the end of the followed range ((Ft)max or ft_end)
    3: "line_incomplete",   # the line stopped early (see end): minimum over the followed part
    4: "not_certified",     # a minimum could not be refined or verified: min_fn etc. are NaN
    5: "admissible_end",    # at the end of the admissible part of the line (admissible_end_ft)
    6: "no_admissible_state",  # the natural state itself is inadmissible: NaN values
}


def _strain_limit(strain_limit) -> float:
    if strain_limit is None:
        return math.inf
    v = float(strain_limit)
    if not v > 0:
        raise ValueError(f"strain_limit = {strain_limit!r}: must be > 0 (None: no limit)")
    return v

def _ft_end(ft_end) -> float:
    """None: the default end; a number must be finite (NaN is not silently the default)."""
    if ft_end is None:
        return math.nan
    v = float(ft_end)
    if not math.isfinite(v):
        raise ValueError(f"ft_end = {ft_end!r}: must be a finite shear force (None: the default end)")
    return v


def _flat(x):
    a = np.asarray(x, dtype=np.float64)
    return a.shape, np.ascontiguousarray(a).reshape(-1)


@dataclass
class CriticalLine:
    """The critical line at requested Ft values (same shape as ``Ft``); NaN where ``status != 0``.

    For the traced line (``critical_line()`` without ``Ft``) every node has values: status 0 marks a
    node re-solved by Newton to the state tolerance (1e-12), status 1 one that could not be (its
    values are the continuation's, accurate to about the line tolerance 1e-10 only; drawn, not to be
    used as a result)."""

    Ft: np.ndarray
    Fn: np.ndarray
    theta_joint: np.ndarray
    status: np.ndarray
    iterations: np.ndarray
    theta_rate_joint: np.ndarray
    theta_rate_base: np.ndarray
    turning_points_beam: np.ndarray
    turning_points_spatula: np.ndarray
    # Only for the traced line (Ft=None): fold locations, why it ended, branch index per point.
    folds: list = field(default_factory=list)
    end: Optional[str] = None
    branch: Optional[np.ndarray] = None
    # Admissibility of each solved state (status 0 or 7; NaN otherwise): lowest height above the
    # substrate (0: the contact edge), where it is (arc length s), largest axial strain |T|/EA.
    min_z: Optional[np.ndarray] = None
    min_z_at: Optional[np.ndarray] = None
    max_axial_strain: Optional[np.ndarray] = None

    def __len__(self) -> int:
        return int(np.size(self.Ft))


@dataclass
class SetaCharacteristics:
    """Characteristic quantities (models.md §1) and their small-deformation counterparts."""

    fn0: float
    slope_k: float
    min_fn: float
    ft_at_min_fn: float
    min_fn_interior: bool
    min_status: str
    slope_at_min_fn: float
    max_pull_off: float
    ft_max: float
    ft_at_line_end: float
    fn_at_line_end: float
    sticky_at_rest: bool
    end: str
    folds: list
    small_fn0: float
    small_slope_k: float
    small_contact_length: float
    small_non_sticky: bool
    # The admissible part of the line: from Ft = 0 to the first state where the seta crosses the
    # substrate (or exceeds the strain limit). The max pull-off is taken over this part only.
    admissible_to_end: bool = False
    admissible_end_ft: float = math.nan
    admissible_end_fn: float = math.nan
    #: dFn/dFt at Ft = 0, the exact tangent at the natural state (``slope_k`` is its deprecated
    #: alias, kept for existing code: it is not the paper's k)
    slope_at_zero: float = math.nan
    #: the paper's k (paper 001 eq (16), Fn = (Fn)0 + k Ft, "the slope of the straight line" of
    #: the lower, bending-dominated part): the least-squares slope of a straight line through
    #: (0, (Fn)0) fitted to the critical line over 0 <= Ft <= ft_at_min_fn (the lower part ends at
    #: the max pull-off, where the axial-dominated part begins). NaN without a lower part.
    paper_k: float = math.nan
    #: True where the minimum sits at the end of the followed range and that end is not the line's
    #: own ((Ft)max): e.g. EA2 = inf (no (Ft)max), or a line given up early. ``max_pull_off`` is
    #: then NaN and ``max_pull_off_bound`` the max pull-off over the followed range (a lower bound).
    max_pull_off_is_bound: bool = False
    max_pull_off_bound: float = math.nan


class TwoLevelSeta:
    """A two-level seta design (models.md §1); the defaults are the paper's reference scene.

    EI1, EI2: bending stiffnesses of beam and spatula; EA1, EA2: axial stiffnesses (``math.inf``:
    inextensible); l1, l2: lengths; alpha1: base angle in (0, pi/2); alpha2 >= 0: kink at the joint,
    alpha1 + alpha2 < pi/2; w: work of adhesion. Invalid values raise ``ValueError`` at construction.
    """

    _FIELDS = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")

    def __init__(self, EI1: float = 5.0, EI2: float = 2.0, EA1: float = math.inf, EA2: float = 50.0,
                 l1: float = 1.0, l2: float = 0.1, alpha1: float = math.pi / 6,
                 alpha2: float = math.pi / 6, w: float = 1.0):
        self.EI1, self.EI2, self.EA1, self.EA2 = float(EI1), float(EI2), float(EA1), float(EA2)
        self.l1, self.l2, self.alpha1, self.alpha2, self.w = (float(l1), float(l2), float(alpha1),
                                                               float(alpha2), float(w))
        self._ft_max = _core.seta_validate(self._params())

    def _params(self) -> np.ndarray:
        return np.array([getattr(self, f) for f in self._FIELDS], dtype=np.float64)

    def __repr__(self) -> str:
        args = ", ".join(f"{f}={getattr(self, f)!r}" for f in self._FIELDS)
        return f"TwoLevelSeta({args})"

    @property
    def ft_max(self) -> float:
        """(Ft)max = sqrt(2 EA2 w): the critical line ends there (inf for EA2 = inf)."""
        return math.sqrt(2 * self.EA2 * self.w)

    def critical_line(self, Ft=None, *, errors: str = "raise", tolerance: Optional[float] = None,
                      ft_end: Optional[float] = None, resolve_nodes: bool = True,
                      strain_limit: Optional[float] = None) -> CriticalLine:
        """The critical line of adhesion.

        With ``Ft`` (any shape): the state at each Ft, on the line followed from Ft = 0 (the first
        crossing; negative Ft along the line followed towards negative Ft), each solved by Newton to
        ``tolerance`` (default 1e-12, scaled step). Without ``Ft``: the nodes of the continuation from
        Ft = 0 to ``ft_end`` (default (Ft)max, or 3 sqrt(EI1 w)/l1 for EA2 = inf), through folds,
        with ``folds`` and ``end`` (why the line stopped); each node re-solved to the state tolerance
        (``status`` 0) or marked (1). ``resolve_nodes=False`` returns the continuation's raw nodes
        (status 1, accurate to its 1e-10 step test; faster, for drawing only).

        Every solved state is checked for admissibility: status 7 where the seta crosses the
        substrate or (with ``strain_limit``, default none) its largest axial strain exceeds the
        limit; ``min_z``, ``min_z_at``, ``max_axial_strain`` report the check.
        """
        params = self._params()
        limit = _strain_limit(strain_limit)
        if Ft is None:
            d = _core.seta_critical_line(params, _ft_end(ft_end), bool(resolve_nodes), limit)
            n = len(d["Ft"])
            return CriticalLine(Ft=d["Ft"], Fn=d["Fn"], theta_joint=d["theta_joint"],
                                status=d["status"], iterations=np.zeros(n, dtype=np.int32),
                                theta_rate_joint=d["theta_rate_joint"], theta_rate_base=d["theta_rate_base"],
                                turning_points_beam=d["turning_points_beam"],
                                turning_points_spatula=d["turning_points_spatula"],
                                folds=list(d["folds"]), end=_LINE_END.get(d["end"], str(d["end"])),
                                branch=d["branch"], min_z=d["min_z"], min_z_at=d["min_z_at"],
                                max_axial_strain=d["max_axial_strain"])
        if not resolve_nodes:
            raise ValueError("resolve_nodes=False applies to the traced line only (critical_line() without Ft); "
                             "states at requested Ft are always solved to the tolerance")
        shape, flat = _flat(Ft)
        d = _core.seta_critical_line_at(params, flat, _error_code(errors),
                                        math.nan if tolerance is None else float(tolerance), limit)

        def shaped(a):
            return a.reshape(shape)

        return CriticalLine(Ft=flat.reshape(shape), Fn=shaped(d["Fn"]), theta_joint=shaped(d["theta_joint"]),
                            status=shaped(d["status"]), iterations=shaped(d["iterations"]),
                            theta_rate_joint=shaped(d["theta_rate_joint"]),
                            theta_rate_base=shaped(d["theta_rate_base"]),
                            turning_points_beam=shaped(d["turning_points_beam"]),
                            turning_points_spatula=shaped(d["turning_points_spatula"]),
                            min_z=shaped(d["min_z"]), min_z_at=shaped(d["min_z_at"]),
                            max_axial_strain=shaped(d["max_axial_strain"]))

    def solve(self, Ft: float, guess=None, *, tolerance: Optional[float] = None, max_iterations: int = 40,
              strain_limit: Optional[float] = None) -> dict:
        """One critical state at ``Ft``. ``guess``: (Fn, theta_joint) or (Fn, theta_joint,
        theta_rate_joint, theta_rate_base); without it the line is followed from Ft = 0. Status 7
        (with ``Fn`` kept): the state crosses the substrate or exceeds ``strain_limit``."""
        tol = math.nan if tolerance is None else float(tolerance)
        limit = _strain_limit(strain_limit)
        if guess is None:
            return _core.seta_solve(self._params(), float(Ft), tolerance=tol, max_iterations=max_iterations,
                                    strain_limit=limit)
        g = [float(x) for x in guess] + [math.nan] * (4 - len(guess))
        return _core.seta_solve(self._params(), float(Ft), g[0], g[1], g[2], g[3], tol, max_iterations, limit)

    def characteristics(self, ft_end: Optional[float] = None, *,
                        strain_limit: Optional[float] = None) -> SetaCharacteristics:
        """(Fn)0, slope k, max pull-off and its Ft, (Ft)max, stickiness at rest, with the
        small-deformation (eqs 7, 18-22) values beside them. ``min_status`` says where the minimum
        of Fn lies and whether it was verified ("stationary": dFn/dFt = 0 at ``ft_at_min_fn``,
        ``slope_at_min_fn`` ~ 0; "not_certified": NaN values, never a traced node's Fn). The minimum
        is taken over the admissible part of the line only (``admissible_end_ft``: where the seta
        first crosses the substrate or exceeds ``strain_limit``; "admissible_end": the minimum
        sits there)."""
        d = _core.seta_characteristics(self._params(), _ft_end(ft_end), _strain_limit(strain_limit))
        d = dict(d)
        d["end"] = _LINE_END.get(d["end"], str(d["end"]))
        d["min_status"] = _MIN_STATUS.get(d["min_status"], str(d["min_status"]))
        d["folds"] = list(d["folds"])
        return SetaCharacteristics(**d)

    def sensitivities(self, Ft) -> dict:
        """Exact derivatives of the critical state with respect to the design, by implicit
        differentiation of the converged residual: ``dFn`` and ``dtheta_joint`` of shape
        (len(Ft), 9), columns in the order of ``TwoLevelSeta._FIELDS`` (EI1, EI2, EA1, EA2, l1, l2,
        alpha1, alpha2, w); Ft held fixed; NaN rows where ``status != 0``."""
        ft = np.atleast_1d(np.asarray(Ft, dtype=np.float64))
        if ft.ndim != 1:
            raise ValueError(f"Ft must be a number or a 1-D array (got shape {ft.shape})")
        ft = np.ascontiguousarray(ft)
        d = dict(_core.seta_sensitivities(self._params(), ft))
        d["parameters"] = list(self._FIELDS)
        return d

    def shape(self, Ft: float, steps: int = 200) -> dict:
        """Deformed shape of the critical state at ``Ft`` (computed only when asked for): arrays
        ``s, x, z, theta`` from the base (s = 0) to the contact edge (z = 0) at ``steps`` points per
        segment, by adaptive RK4 integration of the governing equations (paper 001 eqs (1)-(2))
        from the solved base state, accurate to 1e-12 at any sampling. ``closing_error`` =
        theta(a) - pi/2, ``max_closing_error`` the largest mismatch against the solved state
        (joint angle and rate, edge angle, Griffith edge rate), ``error_estimate`` the summed local
        error estimates; ``shape_status`` 0 when both are within 1e-10 (1 not, 2 step collapse,
        3 no state). ``status`` is the state's (7: drawn, but the seta crosses the substrate)."""
        return dict(_core.seta_shape(self._params(), float(Ft), int(steps)))

    def small_deformation(self) -> dict:
        """The linear theory (eqs 7, 18-22): fn0, slope_k, contact_length, non_sticky."""
        return dict(_core.seta_small_deformation(self._params()))

    def small_deformation_fn(self, Ft):
        """Fn on the linear critical line (eq 18). Ft must be finite (no silent NaN)."""
        d = self.small_deformation()
        ft = np.asarray(Ft, dtype=np.float64)
        if not np.all(np.isfinite(ft)):
            i = int(np.flatnonzero(~np.isfinite(ft.reshape(-1)))[0])
            raise ValueError(f"Ft[{i}] = {ft.reshape(-1)[i]!r}: must be finite")
        out = d["fn0"] + d["slope_k"] * ft
        return float(out) if np.ndim(out) == 0 else out


class SingleFiber:
    """The single-level fiber of He et al. 2013 (models.md §1, Fig 4): one segment of length l,
    bending stiffness EI, axial stiffness EA (``math.inf``: inextensible), base angle alpha in
    (0, pi/2), work of adhesion w. Defaults: EI = 1/2, EA = 50, l = 1, alpha = pi/3, w = 1.
    """

    _FIELDS = ("EI", "EA", "l", "alpha", "w")

    def __init__(self, EI: float = 0.5, EA: float = 50.0, l: float = 1.0, alpha: float = math.pi / 3,
                 w: float = 1.0):
        self.EI, self.EA, self.l, self.alpha, self.w = float(EI), float(EA), float(l), float(alpha), float(w)
        # validate now (an empty query raises for a bad design)
        _core.fiber_critical_line_at(self._params(), np.zeros(0))

    def _params(self) -> np.ndarray:
        return np.array([getattr(self, f) for f in self._FIELDS], dtype=np.float64)

    def __repr__(self) -> str:
        return "SingleFiber(" + ", ".join(f"{f}={getattr(self, f)!r}" for f in self._FIELDS) + ")"

    @property
    def ft_max(self) -> float:
        return math.sqrt(2 * self.EA * self.w)

    def critical_line(self, Ft, *, errors: str = "raise", tolerance: Optional[float] = None) -> CriticalLine:
        """The fiber's critical line at ``Ft`` (any shape), followed from Ft = 0; ``theta_joint`` is NaN
        (no joint) and the fiber's turning points are in ``turning_points_beam``."""
        shape, flat = _flat(Ft)
        d = _core.fiber_critical_line_at(self._params(), flat, _error_code(errors),
                                         math.nan if tolerance is None else float(tolerance))
        return CriticalLine(Ft=flat.reshape(shape), **{k: v.reshape(shape) for k, v in d.items()})


def critical_line_batch(designs, Ft, *, threads: int = 1, errors: str = "raise",
                        tolerance: Optional[float] = None, strain_limit: Optional[float] = None) -> CriticalLine:
    """Many designs x many Ft in one call, multithreaded (the GIL released).

    ``designs``: a sequence of ``TwoLevelSeta`` or an array of shape (n, 9) in the field order
    (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w). ``Ft``: 1-D. Returns arrays of shape
    (n, len(Ft)); the result does not depend on ``threads`` (each design is solved independently).
    """
    if isinstance(designs, TwoLevelSeta):
        designs = [designs]
    if len(designs) and isinstance(designs[0], TwoLevelSeta):
        arr = np.stack([d._params() for d in designs])
    else:
        arr = np.asarray(designs, dtype=np.float64)
        if arr.ndim == 1 and arr.size == 9:
            arr = arr.reshape(1, 9)
        if arr.ndim != 2 or arr.shape[1] != 9:
            raise ValueError(f"designs must be TwoLevelSeta objects or an array of shape (n, 9) "
                             f"(EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w); got shape {arr.shape}")
    ft = np.asarray(Ft, dtype=np.float64)
    if ft.ndim > 1:
        raise ValueError(f"Ft must be a number or a 1-D array (got shape {ft.shape})")
    ft = np.ascontiguousarray(ft.reshape(-1))
    d = _core.seta_batch(np.ascontiguousarray(arr.reshape(-1)), ft, _error_code(errors), int(threads),
                         math.nan if tolerance is None else float(tolerance), _strain_limit(strain_limit))
    shape = (arr.shape[0], ft.size)

    def shaped(a):
        return a.reshape(shape)

    return CriticalLine(Ft=np.broadcast_to(ft, shape).copy(), Fn=shaped(d["Fn"]),
                        theta_joint=shaped(d["theta_joint"]), status=shaped(d["status"]),
                        iterations=shaped(d["iterations"]), theta_rate_joint=shaped(d["theta_rate_joint"]),
                        theta_rate_base=shaped(d["theta_rate_base"]),
                        turning_points_beam=shaped(d["turning_points_beam"]),
                        turning_points_spatula=shaped(d["turning_points_spatula"]),
                        min_z=shaped(d["min_z"]), min_z_at=shaped(d["min_z_at"]),
                        max_axial_strain=shaped(d["max_axial_strain"]))


def kendall_fn(Ft, EA, w, *, errors: str = "raise"):
    """Kendall's peel line (eq 17): the tensile critical Fn (<= 0) of an extensible film at shear Ft.

    Defined for -2w/(2 + sqrt(4 + 2w/EA)) <= Ft <= sqrt(2 EA w); EA = inf gives Rivlin's line.
    """
    return _vectorised(_core.kendall_fn, Ft, EA, w, errors=errors)


def rivlin_fn(Ft, w, *, errors: str = "raise"):
    """Rivlin's peel line (eq 17): Fn = -sqrt(w^2 + 2 w Ft), Ft >= -w/2."""
    return _vectorised(_core.rivlin_fn, Ft, w, errors=errors)
