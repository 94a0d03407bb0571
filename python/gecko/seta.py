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
exists there is unknown, unlike 2.

Bad input raises ``ValueError`` naming the parameter and its allowed range (or, with
``errors="nan"``, marks the element with status 5).
"""
from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from . import _core
from ._vectorize import error_code as _error_code, vectorised as _vectorised, with_index as _with_index

__all__ = [
    "TwoLevelSeta", "SingleFiber", "CriticalLine", "SetaCharacteristics", "kendall_fn", "rivlin_fn",
    "critical_line_batch", "STATUS", "ContactState", "ContactStatus",
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
}

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


class ContactStatus(enum.IntEnum):
    """Status of a contact state (``TwoLevelSeta.contact_state``); the numbers shared with the
    critical line's ``STATUS`` mean the same."""

    CONVERGED = 0           #: one equilibrium, its contact edge on the spatula (l1 < a <= l1 + l2)
    NOT_CONVERGED = 1       #: a root could not be refined, or the scan could not decide
    NO_CONTACT = 2          #: below the critical line: no side contact at this load
    UNSUPPORTED_STATE = 3   #: outside the model's forms (axial load comparable to EA; l2 longer than
                            #: one period of the spatula's orbit)
    BEYOND_JOINT = 4        #: the contact edge would pass the joint onto the beam (outside the model)
    INVALID_INPUT = 5       #: bad input under ``errors="nan"``
    SEVERAL_EQUILIBRIA = 6  #: more than one equilibrium (count in ``equilibria``; all of them with
                            #: ``all_equilibria=True``)
    INADMISSIBLE = 7        #: reserved: the equilibrium crosses the substrate


@dataclass
class ContactState:
    """The forward problem's result (``TwoLevelSeta.contact_state``), arrays in the broadcast shape
    of (Fn, Ft); NaN (or -1 for counts) where ``status != 0``.

    ``a``: non-contact length in the convected coordinate, l1 < a <= l1 + l2; ``contact_length`` =
    l1 + l2 - a; ``theta_joint`` = theta2(l1); ``theta_rate_joint`` = theta2'(l1), ``theta_rate_base``
    = theta1'(0); ``turning_points`` (beam + spatula, also separately); ``max_axial_strain`` = max
    |T|/EA over the free length; ``energy_release_rate``: the left side of eq (3) at the edge (= w at
    every equilibrium, a check); ``equilibria``: how many equilibria the load has on the spatula;
    ``status``: ``ContactStatus`` values.

    With ``all_equilibria=True`` every per-state field has one more trailing axis, one entry per
    equilibrium (padded with NaN / -1), and ``state_status`` gives each entry's status (-1: padding);
    ``status`` and ``equilibria`` keep the load's shape."""

    Fn: np.ndarray
    Ft: np.ndarray
    a: np.ndarray
    contact_length: np.ndarray
    theta_joint: np.ndarray
    theta_rate_joint: np.ndarray
    theta_rate_base: np.ndarray
    turning_points: np.ndarray
    turning_points_beam: np.ndarray
    turning_points_spatula: np.ndarray
    max_axial_strain: np.ndarray
    energy_release_rate: np.ndarray
    equilibria: np.ndarray
    status: np.ndarray
    state_status: Optional[np.ndarray] = None

    def status_names(self) -> np.ndarray:
        """``status`` as names (e.g. "NO_CONTACT")."""
        names = np.array([m.name for m in ContactStatus], dtype=object)
        return names[np.asarray(self.status)]


_CONTACT_FLOAT = ("a", "contact_length", "theta_joint", "theta_rate_joint", "theta_rate_base",
                  "max_axial_strain", "energy_release_rate")
_CONTACT_INT = ("turning_points", "turning_points_beam", "turning_points_spatula")


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
                      ft_end: Optional[float] = None, resolve_nodes: bool = True) -> CriticalLine:
        """The critical line of adhesion.

        With ``Ft`` (any shape): the state at each Ft, on the line followed from Ft = 0 (the first
        crossing; negative Ft along the line followed towards negative Ft), each solved by Newton to
        ``tolerance`` (default 1e-12, scaled step). Without ``Ft``: the nodes of the continuation from
        Ft = 0 to ``ft_end`` (default (Ft)max, or 3 sqrt(EI1 w)/l1 for EA2 = inf), through folds,
        with ``folds`` and ``end`` (why the line stopped); each node re-solved to the state tolerance
        (``status`` 0) or marked (1). ``resolve_nodes=False`` returns the continuation's raw nodes
        (status 1, accurate to its 1e-10 step test; faster, for drawing only).
        """
        params = self._params()
        if Ft is None:
            d = _core.seta_critical_line(params, math.nan if ft_end is None else float(ft_end), bool(resolve_nodes))
            n = len(d["Ft"])
            return CriticalLine(Ft=d["Ft"], Fn=d["Fn"], theta_joint=d["theta_joint"],
                                status=d["status"], iterations=np.zeros(n, dtype=np.int32),
                                theta_rate_joint=d["theta_rate_joint"], theta_rate_base=d["theta_rate_base"],
                                turning_points_beam=d["turning_points_beam"],
                                turning_points_spatula=d["turning_points_spatula"],
                                folds=list(d["folds"]), end=_LINE_END.get(d["end"], str(d["end"])),
                                branch=d["branch"])
        if not resolve_nodes:
            raise ValueError("resolve_nodes=False applies to the traced line only (critical_line() without Ft); "
                             "states at requested Ft are always solved to the tolerance")
        shape, flat = _flat(Ft)
        d = _core.seta_critical_line_at(params, flat, _error_code(errors),
                                        math.nan if tolerance is None else float(tolerance))

        def shaped(a):
            return a.reshape(shape)

        return CriticalLine(Ft=flat.reshape(shape), Fn=shaped(d["Fn"]), theta_joint=shaped(d["theta_joint"]),
                            status=shaped(d["status"]), iterations=shaped(d["iterations"]),
                            theta_rate_joint=shaped(d["theta_rate_joint"]),
                            theta_rate_base=shaped(d["theta_rate_base"]),
                            turning_points_beam=shaped(d["turning_points_beam"]),
                            turning_points_spatula=shaped(d["turning_points_spatula"]))

    def contact_state(self, Fn, Ft, *, all_equilibria: bool = False, errors: str = "raise",
                      scan_points: Optional[int] = None, threads: int = 0) -> ContactState:
        """The forward problem (paper 001 after eq 15): the contact state at the load (Fn, Ft).

        ``Fn`` and ``Ft`` broadcast like numpy arrays. For each load the joint angle theta2(l1) is
        solved from the beam's length equation along the spatula's orbit through the contact edge
        (every root bracketed by a scan and refined to full precision), then a from the spatula's.
        Status 0 only where exactly one equilibrium has its contact edge on the spatula; loads below
        the critical line (no side contact), loads that would push the edge onto the beam, and loads
        with several equilibria get their own ``ContactStatus``. ``all_equilibria=True`` returns every
        equilibrium (see ``ContactState``). ``scan_points``: scan nodes per monotone piece of the
        orbit (default 8). ``threads``: 0 automatic.

        Bad input (NaN or infinite loads, Ft > (Ft)max = sqrt(2 EA2 w), shapes that do not
        broadcast) raises ``ValueError`` naming the argument and its index; with ``errors="nan"`` such
        elements get status ``INVALID_INPUT`` instead. Ft < -(Ft)max is valid input: no edge can be
        in equilibrium there (status ``NO_CONTACT``).
        """
        code = _error_code(errors)
        try:
            fn_b, ft_b = np.broadcast_arrays(np.asarray(Fn, dtype=np.float64), np.asarray(Ft, dtype=np.float64))
        except ValueError:
            raise ValueError(f"contact_state: Fn and Ft do not broadcast (shapes {np.shape(Fn)} and "
                             f"{np.shape(Ft)})") from None
        shape = fn_b.shape
        fn = np.ascontiguousarray(fn_b).reshape(-1)
        ft = np.ascontiguousarray(ft_b).reshape(-1)
        sp = 0 if scan_points is None else int(scan_points)
        if scan_points is not None and not 3 <= sp <= 64:
            raise ValueError(f"scan_points = {scan_points!r} is not allowed: need 3 <= scan_points <= 64")
        if int(threads) < 0:
            raise ValueError(f"threads = {threads!r} is not allowed: need threads >= 0 (0: automatic)")
        try:
            d = _core.seta_contact_state(self._params(), fn, ft, code, bool(all_equilibria), sp, int(threads))
        except ValueError as e:
            raise _with_index(e, shape) from None
        if not all_equilibria:
            fields = {k: d[k].reshape(shape) for k in _CONTACT_FLOAT + _CONTACT_INT + ("equilibria",)}
            return ContactState(Fn=fn.reshape(shape), Ft=ft.reshape(shape), status=d["status"].reshape(shape),
                                **fields)
        n = fn.size
        summary = d["summary_status"]
        element = d["element"]
        counts = np.bincount(element, minlength=n) if element.size else np.zeros(n, dtype=np.int64)
        k = max(int(counts.max()) if n else 0, 1)
        slot = np.zeros(element.size, dtype=np.int64)
        if element.size:
            starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
            slot = np.arange(element.size) - starts[element]
        fields = {}
        for name in _CONTACT_FLOAT:
            out = np.full((n, k), np.nan)
            out[element, slot] = d[name]
            fields[name] = out.reshape(shape + (k,))
        for name in _CONTACT_INT:
            out = np.full((n, k), -1, dtype=np.int32)
            out[element, slot] = d[name]
            fields[name] = out.reshape(shape + (k,))
        st = np.full((n, k), -1, dtype=np.int32)
        st[element, slot] = d["status"]
        return ContactState(Fn=fn.reshape(shape), Ft=ft.reshape(shape), status=summary.reshape(shape),
                            equilibria=counts.astype(np.int32).reshape(shape), state_status=st.reshape(shape + (k,)),
                            **fields)

    def solve(self, Ft: float, guess=None, *, tolerance: Optional[float] = None, max_iterations: int = 40) -> dict:
        """One critical state at ``Ft``. ``guess``: (Fn, theta_joint) or (Fn, theta_joint,
        theta_rate_joint, theta_rate_base); without it the line is followed from Ft = 0."""
        tol = math.nan if tolerance is None else float(tolerance)
        if guess is None:
            return _core.seta_solve(self._params(), float(Ft), tolerance=tol, max_iterations=max_iterations)
        g = [float(x) for x in guess] + [math.nan] * (4 - len(guess))
        return _core.seta_solve(self._params(), float(Ft), g[0], g[1], g[2], g[3], tol, max_iterations)

    def characteristics(self, ft_end: Optional[float] = None) -> SetaCharacteristics:
        """(Fn)0, slope k, max pull-off and its Ft, (Ft)max, stickiness at rest, with the
        small-deformation (eqs 7, 18-22) values beside them. ``min_status`` says where the minimum
        of Fn lies and whether it was verified ("stationary": dFn/dFt = 0 at ``ft_at_min_fn``,
        ``slope_at_min_fn`` ~ 0; "not_certified": NaN values, never a traced node's Fn)."""
        d = _core.seta_characteristics(self._params(), math.nan if ft_end is None else float(ft_end))
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
        ft = np.ascontiguousarray(np.atleast_1d(np.asarray(Ft, dtype=np.float64)).reshape(-1))
        d = dict(_core.seta_sensitivities(self._params(), ft))
        d["parameters"] = list(self._FIELDS)
        return d

    def shape(self, Ft: float, steps: int = 200) -> dict:
        """Deformed shape of the critical state at ``Ft`` (computed only when asked for): arrays
        ``s, x, z, theta`` from the base (s = 0) to the contact edge (z = 0), by RK4 integration
        of the governing equations from the solved base state (``steps`` per segment, O(h^4));
        ``closing_error`` = theta(a) - pi/2 of the integration."""
        return dict(_core.seta_shape(self._params(), float(Ft), int(steps)))

    def small_deformation(self) -> dict:
        """The linear theory (eqs 7, 18-22): fn0, slope_k, contact_length, non_sticky."""
        return dict(_core.seta_small_deformation(self._params()))

    def small_deformation_fn(self, Ft):
        """Fn on the linear critical line (eq 18)."""
        d = self.small_deformation()
        out = d["fn0"] + d["slope_k"] * np.asarray(Ft, dtype=np.float64)
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
                        tolerance: Optional[float] = None) -> CriticalLine:
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
        arr = np.asarray(designs, dtype=np.float64).reshape(-1, 9)
    ft = np.ascontiguousarray(np.asarray(Ft, dtype=np.float64).reshape(-1))
    d = _core.seta_batch(np.ascontiguousarray(arr.reshape(-1)), ft, _error_code(errors), int(threads),
                         math.nan if tolerance is None else float(tolerance))
    shape = (arr.shape[0], ft.size)

    def shaped(a):
        return a.reshape(shape)

    return CriticalLine(Ft=np.broadcast_to(ft, shape).copy(), Fn=shaped(d["Fn"]),
                        theta_joint=shaped(d["theta_joint"]), status=shaped(d["status"]),
                        iterations=shaped(d["iterations"]), theta_rate_joint=shaped(d["theta_rate_joint"]),
                        theta_rate_base=shaped(d["theta_rate_base"]),
                        turning_points_beam=shaped(d["turning_points_beam"]),
                        turning_points_spatula=shaped(d["turning_points_spatula"]))


def kendall_fn(Ft, EA, w, *, errors: str = "raise"):
    """Kendall's peel line (eq 17): the tensile critical Fn (<= 0) of an extensible film at shear Ft.

    Defined for -2w/(2 + sqrt(4 + 2w/EA)) <= Ft <= sqrt(2 EA w); EA = inf gives Rivlin's line.
    """
    return _vectorised(_core.kendall_fn, Ft, EA, w, errors=errors)


def rivlin_fn(Ft, w, *, errors: str = "raise"):
    """Rivlin's peel line (eq 17): Fn = -sqrt(w^2 + 2 w Ft), Ft >= -w/2."""
    return _vectorised(_core.rivlin_fn, Ft, w, errors=errors)
