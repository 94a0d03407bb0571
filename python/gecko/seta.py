"""gecko.seta — the two-level seta of directional adhesion and the classical peel lines.

docs/theory/two_level_seta.md. ``TwoLevelSeta`` holds a design (defaults: the paper's reference scene) and computes
its exact critical line of adhesion in C++ (Carlson forms of the elastica lengths, turning points
and folds included, the GIL released)::

    import gecko, numpy as np
    seta = gecko.TwoLevelSeta()                       # EI1=5, EI2=2, EA1=inf, EA2=50, ...
    line = seta.critical_line(Ft=np.linspace(0, 9.9, 1000))
    line.Fn, line.theta_joint, line.status            # numpy arrays, NaN where status != 0

Status codes (``line.status``): 0 converged; 1 Newton did not converge; 2 no critical state on the
line followed from Ft = 0 (beyond a fold, |Ft| > (Ft)max; critical states on branches that line
never reaches may exist there, and an independent scan finds them at negative Ft); 3 state outside the model's forms
(also: the line left them before reaching this Ft, or already the homotopy to its natural state did,
so that there is no line); 4 singular (Ft exactly at a fold); 5 bad input
under ``errors="nan"``; 6 not reached: the continuation gave up before this Ft (point budget, step
collapse, corrector failure; ``critical_line().end`` says which), so whether a critical state
exists there is unknown, unlike 2; 7 inadmissible: the state solves the equations (paper 001 eq
(15)) but the deformed seta crosses the substrate before the contact edge (``min_z < 0``: the
joint or the beam below it), or a segment is compressed to zero length or beyond somewhere
(``min_stretch <= 0``: the linear law's stretch 1 + T/EA is not positive there, a rod turned inside
out), or its largest axial strain exceeds ``strain_limit``. A followed critical line ends at its
first state compressed so (end "left the model"), and the Ft beyond it are status 3. Status-7 states
keep their ``Fn``, ``theta_joint`` and the rest (for drawing); they are no state of a real seta.
A status-7 state whose ``min_z`` is NaN is one whose height check could not be made (its
quadrature did not close; 5 of the 60,000 states of the project's stress campaign): it is not
confirmed admissible, and not known to cross either.

Every solved state reports ``min_z`` (its lowest height above the substrate over the seta, 0 when
the contact edge is the lowest point), ``min_z_at`` (the arc length s of that point),
``max_axial_strain`` (the largest |T|/EA along the seta) and ``min_stretch`` (the lowest stretch
1 + T/EA along it).

Bad input raises ``ValueError`` naming the parameter and its allowed range (or, with
``errors="nan"``, marks the element with status 5).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from . import _core
from ._vectorize import error_code as _error_code, vectorised as _vectorised, with_index as _with_index
from ._vectorize import check_count as _check_count, check_tolerance as _check_tolerance
from ._vectorize import real_array as _real_array
from ._renamed import warn_renamed

__all__ = [
    "TwoLevelSeta", "SingleFiber", "CriticalLine", "SetaCharacteristics", "kendall_fn", "rivlin_fn",
    "critical_line_batch", "STATUS", "DESIGN_FIELDS", "SetaDesign", "CriticalStatus", "LineEnd",
    "MinimumStatus", "ContactState", "ContactStatus", "CriticalState", "SmallDeformation",
]

# The domain comes from C++ (src/bindings/seta_types.cpp): the design type with its fields, defaults
# and admissible ranges, and the status codes as IntEnums (equal to the plain integers in arrays).
SetaDesign = _core.SetaDesign
#: the nine design fields in the order of every flat design array
DESIGN_FIELDS = tuple(SetaDesign.fields)
CriticalStatus = _core.CriticalStatus
LineEnd = _core.LineEnd
MinimumStatus = _core.MinimumStatus
# Result types bound from the C++ structs (read-only attributes, readable repr). Indexing them like
# the dicts they replace (state["Fn"], dict(state)) still works but is deprecated.
CriticalState = _core.CriticalState
SmallDeformation = _core.SmallDeformation

STATUS = {
    0: "converged",
    1: "not converged",
    2: "no critical state on the line followed from Ft = 0 (states off that line may exist)",
    3: "unsupported state (outside the model: past the edge of its forms, or past the followed line's "
       "first state compressed to zero length)",
    4: "singular (at a fold)",
    5: "invalid input",
    6: "not reached (the followed line was given up before this Ft)",
    7: "inadmissible (solves the equations but the seta crosses the substrate, is compressed to zero length "
       "somewhere, or exceeds the strain limit)",
}

_LINE_END = {
    0: "reached the requested end of the Ft range",
    1: "reached (Ft)max = sqrt(2 EA2 w)",
    2: "turned back after a fold",
    3: "no convergence (singular point)",
    4: "left the model (axial load comparable to EA: a segment compressed to zero length, or the edge of the forms)",
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

def _flat(x, name="Ft"):
    a = _real_array(x, name)
    return a.shape, np.ascontiguousarray(a).reshape(-1)


@dataclass
class CriticalLine:
    """The critical line at requested Ft values, or the traced line.

    With requested ``Ft`` every array has the shape of ``Ft`` and is NaN where ``status != 0``
    (see :data:`gecko.STATUS`). For the traced line (``critical_line()`` without ``Ft``) every node
    has values: status 0 marks a node re-solved by Newton to the state tolerance (1e-12), status 1
    one that could not be (its values are the continuation's, accurate to about the line tolerance
    1e-10 only; drawn, not to be used as a result).

    Attributes
    ----------
    Ft, Fn : numpy.ndarray
        Shear force and critical normal force (Fn < 0: a pull-off force).
    theta_joint : numpy.ndarray
        The spatula's angle at the joint, beta = theta2(l1), from the substrate normal.
    status : numpy.ndarray of int
        0 converged; other codes in :data:`gecko.STATUS`.
    iterations : numpy.ndarray of int
        Evaluations of the equations by the solver: with their Jacobian in Newton's
        iterations, the residual alone in the chord steps that read a state off the traced
        line (which reuse a node's Jacobian).
    theta_rate_joint, theta_rate_base : numpy.ndarray
        theta2'(l1) and theta1'(0), the signed end rates of the solver's unknowns.
    turning_points_beam, turning_points_spatula : numpy.ndarray of int
        Sign changes of theta' inside each segment.
    folds : list
        Traced line only: where it folds back.
    end : str or None
        Traced line only: why it stopped.
    branch : numpy.ndarray or None
        Traced line only: the branch index of each node.
    end_code : LineEnd or None
        Traced line only: ``end`` as a :class:`LineEnd` member (compare these in code).
    min_z, min_z_at, max_axial_strain, min_stretch : numpy.ndarray or None
        Admissibility of each solved state (status 0 or 7; NaN otherwise): the lowest height of the
        seta above the substrate (0: the contact edge; < 0: it crosses the substrate, status 7), the
        arc length s where it is, the largest axial strain abs(T)/EA along the seta, and the lowest
        stretch 1 + T/EA along it (<= 0: compressed to zero length somewhere, status 7).

    Examples
    --------
    >>> import gecko
    >>> line = gecko.TwoLevelSeta().critical_line(Ft=[0.0, 5.0])
    >>> line.Fn.round(6), line.status
    (array([ 0.249904, -2.448406]), array([0, 0], dtype=int32))
    """

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
    end_code: Optional[LineEnd] = None   # ``end`` as a LineEnd member (code compares these)
    min_z: Optional[np.ndarray] = None
    min_z_at: Optional[np.ndarray] = None
    max_axial_strain: Optional[np.ndarray] = None
    min_stretch: Optional[np.ndarray] = None

    def __len__(self) -> int:
        return int(np.size(self.Ft))


@dataclass
class SetaCharacteristics:
    """Characteristic quantities of a seta, with their small-deformation counterparts.

    See docs/theory/two_level_seta.md, "The critical line of adhesion" and "Small-deformation
    approximations" (paper 001 eqs 16, 18-22).

    Attributes
    ----------
    fn0 : float
        (Fn)0, the critical Fn at Ft = 0 (> 0: not sticky at rest).
    slope_k : float
        Deprecated alias of ``slope_at_zero`` (it is not the paper's k; see ``paper_k``): a
        read-only property that raises a DeprecationWarning; not a field of the dataclass.
    min_fn, ft_at_min_fn : float
        The minimum of Fn along the line followed from Ft = 0, and where it occurs.
    min_fn_interior : bool
        Whether the minimum is an interior stationary point.
    min_status : str
        "stationary", "range_start", "range_end", "line_incomplete", "not_certified" (NaN values),
        "admissible_end" (at the end of the admissible part) or "no_admissible_state" (NaN values).
    slope_at_min_fn : float
        dFn/dFt at the minimum (about 0 for "stationary").
    max_pull_off : float
        max(0, -min_fn) over the admissible part of the line; NaN where the minimum sits at the end
        of the followed range and that end is not (Ft)max (see ``max_pull_off_is_bound``).
    ft_max : float
        (Ft)max = sqrt(2 EA2 w).
    ft_at_line_end, fn_at_line_end : float
        Where the followed line ended.
    sticky_at_rest : bool
        (Fn)0 < 0.
    end : str
        Why the line ended.
    folds : list
        Folds met along the line.
    small_fn0, small_slope_k, small_contact_length : float
        The small-deformation theory's (Fn)0, k and contact length at rest (paper 001 eqs 7, 19-21).
    small_non_sticky : bool
        Its non-sticky criterion (paper 001 eq 22).
    end_code : LineEnd or None
        ``end`` as a :class:`LineEnd` member.
    min_status_code : MinimumStatus or None
        ``min_status`` as a :class:`MinimumStatus` member.
    admissible_to_end : bool
        The whole followed line is admissible (the seta never crosses the substrate on it).
    admissible_end_ft, admissible_end_fn : float
        Where the admissible part of the line ends: the first state, from Ft = 0, where the seta
        crosses the substrate (or exceeds the strain limit). The max pull-off is taken before it.
    slope_at_zero : float
        dFn/dFt at Ft = 0, the exact tangent of the line at the natural state.
    paper_k : float
        The paper's k (paper 001 eq (16), Fn = (Fn)0 + k Ft, "the slope of the straight line" of the
        lower, bending-dominated part): the least-squares slope of a straight line through
        (0, (Fn)0) fitted to the critical line over 0 <= Ft <= ft_at_min_fn (the lower part ends at
        the max pull-off, where the axial-dominated part begins). NaN without a lower part.
    max_pull_off_is_bound, max_pull_off_bound : bool, float
        True where the minimum sits at the end of the followed range and that end is not the line's
        own ((Ft)max): EA2 = inf (no (Ft)max), or a line given up early; ``max_pull_off`` is then
        NaN and ``max_pull_off_bound`` the max pull-off over the followed range (a lower bound).

    Examples
    --------
    >>> import gecko
    >>> c = gecko.TwoLevelSeta().characteristics()
    >>> round(c.fn0, 4), round(c.max_pull_off, 4), c.min_status
    (0.2499, 2.8024, 'stationary')
    """

    fn0: float
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
    end_code: Optional[LineEnd] = None              # ``end`` as a LineEnd member
    min_status_code: Optional[MinimumStatus] = None  # ``min_status`` as a MinimumStatus member
    admissible_to_end: bool = False
    admissible_end_ft: float = math.nan
    admissible_end_fn: float = math.nan
    slope_at_zero: float = math.nan
    paper_k: float = math.nan
    max_pull_off_is_bound: bool = False
    max_pull_off_bound: float = math.nan

    @property
    def slope_k(self) -> float:
        warn_renamed(["slope_k"], "SetaCharacteristics")  # issue 13: it is not the paper's k
        return self.slope_at_zero


#: Status of a contact state (``TwoLevelSeta.contact_state``), bound from C++
#: (gecko/seta/contact_state.hpp, an IntEnum equal to the integers in the result arrays): CONVERGED
#: (0, one equilibrium with its edge on the spatula), NOT_CONVERGED (1), NO_CONTACT (2, below the
#: critical line), UNSUPPORTED_STATE (3), BEYOND_JOINT (4, the edge would pass onto the beam),
#: INVALID_INPUT (5), SEVERAL_EQUILIBRIA (6), INADMISSIBLE (7, values kept for drawing).
ContactStatus = _core.ContactStatus


@dataclass
class ContactState:
    """The forward problem's result (``TwoLevelSeta.contact_state``): arrays in the broadcast
    shape of (Fn, Ft), NaN (or -1 for counts) where there is no single admissible equilibrium
    (``status`` other than 0 and 7).

    With ``all_equilibria=True`` every per-state field has one more trailing axis, one entry per
    equilibrium (padded with NaN / -1), and ``state_status`` gives each entry's status (-1:
    padding); ``status`` and ``equilibria`` keep the load's shape.

    Attributes
    ----------
    Fn, Ft : numpy.ndarray
        The loads (broadcast).
    a : numpy.ndarray
        Non-contact length in the convected coordinate, l1 < a <= l1 + l2.
    contact_length : numpy.ndarray
        l1 + l2 - a.
    theta_joint : numpy.ndarray
        theta2(l1), the spatula's angle at the joint, from the substrate normal.
    theta_rate_joint, theta_rate_base : numpy.ndarray
        theta2'(l1) and theta1'(0).
    turning_points, turning_points_beam, turning_points_spatula : numpy.ndarray of int
        Sign changes of theta' inside the free length (beam + spatula), and per segment.
    max_axial_strain : numpy.ndarray
        Largest |T|/EA over the free length.
    min_stretch : numpy.ndarray
        Lowest stretch 1 + T/EA over the free length (<= 0: a segment compressed to zero length
        somewhere, inadmissible).
    energy_release_rate : numpy.ndarray
        Left side of eq (3) at the edge; equals w at every equilibrium (a check of the state).
    min_z : numpy.ndarray
        Lowest height of the seta above the substrate before the edge (< 0: inadmissible).
    equilibria : numpy.ndarray of int
        How many equilibria the load has with its edge on the spatula (admissible or not).
    status : numpy.ndarray of int
        :class:`ContactStatus` values; inadmissible states (7) keep their values, for drawing.
    state_status : numpy.ndarray of int or None
        With ``all_equilibria=True``: the status of each equilibrium.

    Examples
    --------
    >>> import gecko
    >>> st = gecko.TwoLevelSeta().contact_state([-1.0, 0.0, 3.0], 2.0)
    >>> st.a.round(6), st.status
    (array([1.091284, 1.006882,      nan]), array([0, 0, 4], dtype=int32))
    >>> st.status_names()
    array(['CONVERGED', 'CONVERGED', 'BEYOND_JOINT'], dtype=object)
    """

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
    min_stretch: np.ndarray
    energy_release_rate: np.ndarray
    min_z: np.ndarray
    equilibria: np.ndarray
    status: np.ndarray
    state_status: Optional[np.ndarray] = None

    def status_names(self) -> np.ndarray:
        """``status`` as names (e.g. "NO_CONTACT")."""
        names = np.array([m.name for m in ContactStatus], dtype=object)
        return names[np.asarray(self.status)]


_CONTACT_FLOAT = ("a", "contact_length", "theta_joint", "theta_rate_joint", "theta_rate_base",
                  "max_axial_strain", "min_stretch", "energy_release_rate", "min_z")
_CONTACT_INT = ("turning_points", "turning_points_beam", "turning_points_spatula")


class TwoLevelSeta:
    """A two-level seta design; the defaults are the paper's reference scene.

    A beam (level 1) clamped at the base angle ``alpha1`` carries a spatula (level 2) kinked by
    ``alpha2``; the spatula is in side contact with a rigid substrate (docs/theory/two_level_seta.md,
    paper 001). Non-dimensional defaults: w = 1, l1 = 1.

    Parameters
    ----------
    EI1, EI2 : float, optional
        Bending stiffnesses of beam and spatula (defaults 5 and 2), > 0.
    EA1, EA2 : float, optional
        Axial stiffnesses (defaults inf and 50), > 0; ``math.inf`` is the inextensible limit.
    l1, l2 : float, optional
        Lengths of beam and spatula (defaults 1 and 0.1), > 0.
    alpha1 : float, optional
        Base angle from the substrate normal, in (0, pi/2) (default pi/6).
    alpha2 : float, optional
        Kink at the joint, >= 0 with alpha1 + alpha2 < pi/2 (default pi/6).
    w : float, optional
        Work of adhesion per unit length, > 0 (default 1).

    Raises
    ------
    ValueError
        If a parameter is out of its range; the message names it and the range.

    Examples
    --------
    >>> import gecko
    >>> seta = gecko.TwoLevelSeta(alpha2=0.3)
    >>> seta.ft_max
    10.0
    >>> gecko.TwoLevelSeta(EI1=-1)
    Traceback (most recent call last):
    ...
    ValueError: gecko.TwoLevelSeta: EI1 = -1 is out of range: need 0 < EI1 < infinity
    """

    _FIELDS = DESIGN_FIELDS

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

        Parameters
        ----------
        Ft : array_like, optional
            Shear forces, any shape. Each state is the first crossing of that Ft on the line followed
            from Ft = 0 (negative Ft: along the line followed towards negative Ft), solved by Newton.
            Without ``Ft``: the nodes of the continuation itself, through folds.
        errors : {"raise", "nan"}, optional
            Bad input raises ``ValueError`` (default) or gives status 5 and NaN for that element.
        tolerance : float, optional
            Tolerance on the solver's scaled step (default 1e-12): each state's last step (a chord
            step from the traced line, or Newton's) is below it.
        ft_end : float, optional
            Traced line only: where to stop (default (Ft)max, or 3 sqrt(EI1 w)/l1 for EA2 = inf).
        resolve_nodes : bool, optional
            Traced line only: re-solve every node to the state tolerance (default True); False returns
            the continuation's raw nodes (status 1, for drawing).
        strain_limit : float, optional
            States whose largest axial strain abs(T)/EA exceeds it get status 7 (default: no limit;
            the reference design reaches 20 % at (Ft)max). Every solved state is also checked for
            crossing the substrate (status 7, ``min_z < 0``).

        Returns
        -------
        CriticalLine
            Arrays of the shape of ``Ft`` (or one entry per node), with a status for every state.

        Raises
        ------
        ValueError
            If an Ft is out of range (beyond (Ft)max) with ``errors="raise"``, or ``resolve_nodes=False``
            is combined with ``Ft``.

        Examples
        --------
        >>> import gecko
        >>> seta = gecko.TwoLevelSeta()
        >>> seta.critical_line(Ft=[0.0, 5.0]).Fn.round(6)
        array([ 0.249904, -2.448406])
        >>> seta.critical_line().end
        'reached (Ft)max = sqrt(2 EA2 w)'
        >>> seta.critical_line(Ft=[11.0], errors="nan").status
        array([5], dtype=int32)
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
                                branch=d["branch"], end_code=LineEnd(d["end"]), min_z=d["min_z"],
                                min_z_at=d["min_z_at"], max_axial_strain=d["max_axial_strain"],
                                min_stretch=d["min_stretch"])
        if not resolve_nodes:
            raise ValueError("resolve_nodes=False applies to the traced line only (critical_line() without Ft); "
                             "states at requested Ft are always solved to the tolerance")
        shape, flat = _flat(Ft)
        d = _core.seta_critical_line_at(params, flat, _error_code(errors), _check_tolerance(tolerance), limit)

        def shaped(a):
            return a.reshape(shape)

        return CriticalLine(Ft=flat.reshape(shape), Fn=shaped(d["Fn"]), theta_joint=shaped(d["theta_joint"]),
                            status=shaped(d["status"]), iterations=shaped(d["iterations"]),
                            theta_rate_joint=shaped(d["theta_rate_joint"]),
                            theta_rate_base=shaped(d["theta_rate_base"]),
                            turning_points_beam=shaped(d["turning_points_beam"]),
                            turning_points_spatula=shaped(d["turning_points_spatula"]),
                            min_z=shaped(d["min_z"]), min_z_at=shaped(d["min_z_at"]),
                            max_axial_strain=shaped(d["max_axial_strain"]), min_stretch=shaped(d["min_stretch"]))

    def contact_state(self, Fn, Ft, *, all_equilibria: bool = False, errors: str = "raise",
                      scan_points: Optional[int] = None, threads: int = 0,
                      strain_limit: Optional[float] = None) -> ContactState:
        """The forward problem (paper 001 after eq 15): the contact state at the load (Fn, Ft).

        ``Fn`` and ``Ft`` broadcast like numpy arrays. For each load the joint angle theta2(l1) is
        solved from the beam's length equation along the spatula's orbit through the contact edge
        (every root bracketed by a scan and refined to full precision), then a from the spatula's.
        Status 0 only where exactly one equilibrium has its contact edge on the spatula; loads below
        the critical line (no side contact), loads that would push the edge onto the beam, and loads
        with several equilibria get their own ``ContactStatus``. ``all_equilibria=True`` returns every
        equilibrium (see ``ContactState``). ``scan_points``: scan nodes per monotone piece of the
        orbit (default 6). ``threads``: 0 automatic. An equilibrium whose seta crosses the substrate
        before the edge, or whose largest axial strain exceeds ``strain_limit`` (default: no
        limit), is inadmissible (status 7, values kept).

        Bad input (NaN or infinite loads, Ft > (Ft)max = sqrt(2 EA2 w), shapes that do not
        broadcast) raises ``ValueError`` naming the argument and its index; with ``errors="nan"`` such
        elements get status ``INVALID_INPUT`` instead. Ft < -(Ft)max is valid input: no edge can be
        in equilibrium there (status ``NO_CONTACT``).

        Parameters
        ----------
        Fn, Ft : float or array_like
            Normal force (< 0 pulls off) and shear force (> 0 grips), broadcast together.
        all_equilibria : bool
            Return every equilibrium on a trailing axis (see :class:`ContactState`).
        errors : {"raise", "nan"}
            Bad elements raise ``ValueError``, or get status ``INVALID_INPUT``.
        scan_points : int, optional
            Scan nodes per monotone piece of the spatula's orbit, 3 to 64 (default 6).
        threads : int
            Threads of the one pool (0: automatic).
        strain_limit : float, optional
            Largest admissible axial strain |T|/EA (default: no limit).

        Returns
        -------
        ContactState

        Examples
        --------
        >>> import gecko
        >>> st = gecko.TwoLevelSeta().contact_state(-1.0, 2.0)
        >>> round(float(st.a), 9), int(st.status), int(st.turning_points)
        (1.091283999, 0, 0)
        """
        code = _error_code(errors)
        fn_a, ft_a = _real_array(Fn, "Fn"), _real_array(Ft, "Ft")
        try:
            fn_b, ft_b = np.broadcast_arrays(fn_a, ft_a)
        except ValueError:
            raise ValueError(f"contact_state: Fn and Ft do not broadcast (shapes {np.shape(Fn)} and "
                             f"{np.shape(Ft)}): need shapes that broadcast together") from None
        shape = fn_b.shape
        fn = np.ascontiguousarray(fn_b).reshape(-1)
        ft = np.ascontiguousarray(ft_b).reshape(-1)
        sp = 0 if scan_points is None else int(scan_points)
        if scan_points is not None and not 3 <= sp <= 64:
            raise ValueError(f"scan_points = {scan_points!r} is not allowed: need 3 <= scan_points <= 64")
        if strain_limit is not None and not float(strain_limit) >= 0:
            raise ValueError(f"strain_limit = {strain_limit!r} is not allowed: need strain_limit >= 0")
        if int(threads) < 0:
            raise ValueError(f"threads = {threads!r} is not allowed: need threads >= 0 (0: automatic)")
        try:
            d = _core.seta_contact_state(self._params(), fn, ft, code, bool(all_equilibria), sp, int(threads),
                                         math.nan if strain_limit is None else float(strain_limit))
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

    def solve(self, Ft: float, guess=None, *, tolerance: Optional[float] = None, max_iterations: int = 40,
              strain_limit: Optional[float] = None) -> CriticalState:
        """One critical state at ``Ft``.

        Parameters
        ----------
        Ft : float
            The shear force.
        guess : sequence of float, optional
            (Fn, theta_joint), or (Fn, theta_joint, theta_rate_joint, theta_rate_base). Without it the
            line is followed from Ft = 0 to Ft.
        tolerance : float, optional
            Newton's tolerance on the scaled step (default 1e-12).
        max_iterations : int, optional
            Newton's iteration budget with a guess (default 40).
        strain_limit : float, optional
            A state above this axial strain gets status 7 (default: no limit).

        Returns
        -------
        CriticalState
            Attributes ``Ft, Fn, theta_joint, theta_rate_joint, theta_rate_base, status``
            (:class:`CriticalStatus`; 7, values kept: the seta crosses the substrate, is
            compressed to zero length somewhere, or exceeds ``strain_limit``),
            ``turning_points_beam, turning_points_spatula, min_z, min_z_at, max_axial_strain,
            min_stretch, iterations``. Indexing it like the dict it replaces
            (``state["Fn"]``, statuses as ints) still works but is deprecated.

        Raises
        ------
        ValueError
            If ``Ft`` is out of range.

        Examples
        --------
        >>> import gecko
        >>> state = gecko.TwoLevelSeta().solve(5.0, guess=(-2.4, 1.49))
        >>> round(state.Fn, 6), state.status.name
        (-2.448406, 'converged')
        """
        tol = _check_tolerance(tolerance)
        max_iterations = _check_count(max_iterations, "max_iterations")
        limit = _strain_limit(strain_limit)
        if guess is None:
            return _core.seta_solve(self._params(), float(Ft), tolerance=tol, max_iterations=max_iterations,
                                    strain_limit=limit)
        g = [float(x) for x in guess] + [math.nan] * (4 - len(guess))
        return _core.seta_solve(self._params(), float(Ft), g[0], g[1], g[2], g[3], tol, max_iterations, limit)

    def characteristics(self, ft_end: Optional[float] = None, *,
                        strain_limit: Optional[float] = None) -> SetaCharacteristics:
        """(Fn)0, slope k, maximum pull-off and its Ft, (Ft)max, stickiness at rest.

        The small-deformation values (paper 001 eqs 7, 18-22) come alongside. ``min_status`` says where
        the minimum of Fn lies and whether it was verified ("stationary": dFn/dFt = 0 at
        ``ft_at_min_fn``; "not_certified": NaN values, never a traced node's Fn). The minimum is
        taken over the admissible part of the line only (up to ``admissible_end_ft``, where the seta
        first crosses the substrate or exceeds ``strain_limit``).

        Parameters
        ----------
        ft_end : float, optional
            Follow the line only up to this Ft (default (Ft)max); 0 solves the natural state only.
        strain_limit : float, optional
            States above this axial strain are inadmissible (default: no limit).

        Returns
        -------
        SetaCharacteristics

        Raises
        ------
        ValueError
            If ``ft_end`` is out of range.

        Examples
        --------
        >>> import gecko
        >>> c = gecko.TwoLevelSeta().characteristics()
        >>> round(c.fn0, 4), round(c.slope_at_zero, 4), round(c.ft_at_min_fn, 4), c.sticky_at_rest
        (0.2499, -0.7414, 7.1232, False)
        """
        d = _core.seta_characteristics(self._params(), _ft_end(ft_end), _strain_limit(strain_limit))
        d = dict(d)
        d["end_code"], d["min_status_code"] = LineEnd(d["end"]), MinimumStatus(d["min_status"])
        d["end"] = _LINE_END.get(d["end"], str(d["end"]))
        d["min_status"] = _MIN_STATUS.get(d["min_status"], str(d["min_status"]))
        d["folds"] = list(d["folds"])
        del d["slope_k"]  # the same value as slope_at_zero, which the deprecated property returns
        return SetaCharacteristics(**d)

    def sensitivities(self, Ft) -> dict:
        """Exact derivatives of the critical state with respect to the design.

        By implicit differentiation of the converged equations (no finite differences), with Ft held
        fixed.

        Parameters
        ----------
        Ft : array_like
            Shear forces (flattened).

        Returns
        -------
        dict
            ``dFn`` and ``dtheta_joint`` of shape (len(Ft), 9), columns in the order of ``parameters``
            (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w); ``Fn`` and ``status``; NaN rows where
            ``status != 0``, and at states recovered on a segment's separatrix whose distance from
            it is below the state's digits (a segment tens of elastic lengths long: the length
            equations cannot be differentiated there).

        Examples
        --------
        >>> import gecko
        >>> d = gecko.TwoLevelSeta().sensitivities([0.0, 5.0])
        >>> d["dFn"].shape, d["parameters"][7]
        ((2, 9), 'alpha2')
        """
        ft = np.atleast_1d(_real_array(Ft, "Ft"))
        if ft.ndim != 1:
            raise ValueError(f"Ft must be a number or a 1-D array (got shape {ft.shape})")
        ft = np.ascontiguousarray(ft)
        d = dict(_core.seta_sensitivities(self._params(), ft))
        d["parameters"] = list(self._FIELDS)
        return d

    def shape(self, Ft: float, steps: int = 200) -> dict:
        """The deformed shape of the critical state at ``Ft``, computed only when asked for.

        Adaptive RK4 integration (step doubling) of the governing equations (paper 001 eqs (1)-(2))
        from the solved base state, accurate to 1e-12 at any sampling.

        Parameters
        ----------
        Ft : float
            The shear force.
        steps : int, optional
            Output points per segment (default 200), >= 1.

        Returns
        -------
        dict
            Arrays ``s, x, z, theta`` from the base (s = 0) to the contact edge (z = 0);
            ``closing_error`` = theta(a) - pi/2; ``max_closing_error``, the largest mismatch against
            the solved state (joint angle and rate, edge angle, Griffith edge rate);
            ``error_estimate``, the summed local error estimates; ``shape_status`` 0 when both are
            within 1e-10 (1 not, 2 step collapse, 3 no state); the state's ``Fn``, ``status`` (7:
            drawn, but the seta crosses the substrate or is compressed to zero length somewhere),
            ``min_z``, ``max_axial_strain`` and ``min_stretch``.

        Examples
        --------
        >>> import gecko
        >>> sh = gecko.TwoLevelSeta().shape(2.0)
        >>> float(sh["z"][-1]), sh["shape_status"], sh["max_closing_error"] < 1e-10
        (0.0, 0, True)
        """
        return dict(_core.seta_shape(self._params(), float(Ft), int(steps)))

    def small_deformation(self) -> dict:  # a dict of the bound SmallDeformation
        """The small-deformation (linear) theory, paper 001 eqs 7 and 18-22.

        Qualitative by the paper's own account: at the reference scene (Fn)0 = 0.34 against the exact
        0.2499.

        Returns
        -------
        dict
            ``fn0``, ``slope_k``, ``contact_length`` (at rest; outside [0, l2]: no contact at rest),
            ``non_sticky`` (eq 22).

        Examples
        --------
        >>> import gecko
        >>> d = gecko.TwoLevelSeta().small_deformation()
        >>> round(d["fn0"], 4), d["non_sticky"]
        (0.3396, True)
        """
        return dict(_core.seta_small_deformation(self._params()))

    def small_deformation_fn(self, Ft):
        """Fn on the linear critical line (paper 001 eq 18), Fn = (Fn)0 + k Ft.

        Parameters
        ----------
        Ft : float or array_like
            Shear forces.

        Returns
        -------
        float or numpy.ndarray
            Of the shape of ``Ft``.

        Examples
        --------
        >>> import gecko
        >>> round(gecko.TwoLevelSeta().small_deformation_fn(1.0), 4)
        -1.0686
        """
        d = self.small_deformation()
        ft = _real_array(Ft, "Ft")
        if not np.all(np.isfinite(ft)):
            i = int(np.flatnonzero(~np.isfinite(ft.reshape(-1)))[0])
            raise ValueError(f"Ft[{i}] = {ft.reshape(-1)[i]!r}: must be finite")
        out = d["fn0"] + d["slope_k"] * ft
        return float(out) if np.ndim(out) == 0 else out


class SingleFiber:
    """The single-level fiber of He et al. 2013 (paper 001 Fig 4).

    One segment of length ``l``, bending stiffness ``EI``, axial stiffness ``EA``, base angle
    ``alpha``, in side contact with the substrate (docs/theory/two_level_seta.md, "Single-level
    fiber").

    Parameters
    ----------
    EI : float, optional
        Bending stiffness (default 1/2), > 0.
    EA : float, optional
        Axial stiffness (default 50), > 0; ``math.inf``: inextensible.
    l : float, optional
        Length (default 1), > 0.
    alpha : float, optional
        Base angle in (0, pi/2) (default pi/3, the reference seta's alpha1 + alpha2).
    w : float, optional
        Work of adhesion (default 1), > 0.

    Raises
    ------
    ValueError
        If a parameter is out of its range.

    Examples
    --------
    >>> import gecko
    >>> fiber = gecko.SingleFiber()
    >>> fiber.critical_line([0.0, 1.0]).Fn.round(5)
    array([-1.62417, -1.9766 ])
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
        """The fiber's critical line at ``Ft``, followed from Ft = 0.

        Parameters
        ----------
        Ft : array_like
            Shear forces, any shape.
        errors : {"raise", "nan"}, optional
            Bad input raises ``ValueError`` (default) or gives status 5 and NaN.
        tolerance : float, optional
            Tolerance on the solver's scaled step (default 1e-12), as
            :meth:`TwoLevelSeta.critical_line`.

        Returns
        -------
        CriticalLine
            ``theta_joint`` is NaN (no joint); the fiber's turning points are in
            ``turning_points_beam``.

        Raises
        ------
        ValueError
            If an Ft is out of range with ``errors="raise"``.

        Examples
        --------
        >>> import gecko
        >>> line = gecko.SingleFiber(EI=1.0).critical_line([0.0])
        >>> bool(line.status[0] == 0)
        True
        """
        shape, flat = _flat(Ft)
        d = _core.fiber_critical_line_at(self._params(), flat, _error_code(errors), _check_tolerance(tolerance))
        return CriticalLine(Ft=flat.reshape(shape), **{k: v.reshape(shape) for k, v in d.items()})


def critical_line_batch(designs, Ft, *, threads: int = 1, errors: str = "raise",
                        tolerance: Optional[float] = None, strain_limit: Optional[float] = None) -> CriticalLine:
    """Many designs x many Ft in one call, on several threads (the GIL released).

    Parameters
    ----------
    designs : sequence of TwoLevelSeta or array_like of shape (n, 9)
        The designs; arrays in the field order (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w).
    Ft : array_like
        Shear forces, 1-D.
    threads : int, optional
        Threads (default 1); the result does not depend on it.
    errors : {"raise", "nan"}, optional
        Bad input raises ``ValueError`` (default) or gives status 5 in its entries.
    tolerance : float, optional
        Tolerance on the solver's scaled step (default 1e-12), as
        :meth:`TwoLevelSeta.critical_line`.
    strain_limit : float, optional
        States above this axial strain get status 7 (default: no limit; status 7 also where the
        seta crosses the substrate).

    Returns
    -------
    CriticalLine
        Arrays of shape (n, len(Ft)).

    Raises
    ------
    ValueError
        If a design or an Ft is invalid with ``errors="raise"``.

    Examples
    --------
    >>> import gecko
    >>> designs = [gecko.TwoLevelSeta(), gecko.TwoLevelSeta(alpha2=0.3)]
    >>> gecko.critical_line_batch(designs, [0.0, 2.0], threads=2).Fn.round(4)
    array([[ 0.2499, -1.0829],
           [ 2.3606,  1.382 ]])
    """
    if isinstance(designs, TwoLevelSeta):
        designs = [designs]
    if len(designs) and isinstance(designs[0], TwoLevelSeta):
        arr = np.stack([d._params() for d in designs])
    else:
        arr = _real_array(designs, "designs")
        if arr.ndim == 1 and arr.size == 9:  # one design
            arr = arr.reshape(1, 9)
        if arr.ndim != 2 or arr.shape[1] != 9:  # never reinterpret a table of another width
            raise ValueError(f"designs: need a table of width 9 (EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w), "
                             f"one row per design; got shape {arr.shape} (width "
                             f"{arr.shape[-1] if arr.ndim else 0})")
    ft = _real_array(Ft, "Ft")
    if ft.ndim > 1:  # never flatten a table of Ft silently
        raise ValueError(f"Ft must be a number or a 1-D array (got shape {ft.shape})")
    ft = np.ascontiguousarray(ft.reshape(-1))
    d = _core.seta_batch(np.ascontiguousarray(arr.reshape(-1)), ft, _error_code(errors),
                         _check_count(threads, "threads", 4096), _check_tolerance(tolerance),
                         _strain_limit(strain_limit))
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
                        max_axial_strain=shaped(d["max_axial_strain"]), min_stretch=shaped(d["min_stretch"]))


def kendall_fn(Ft, EA, w, *, errors: str = "raise"):
    """Kendall's peel line (paper 001 eq 17): the tensile critical Fn of an extensible film.

    Solves sqrt(Fn^2 + Ft^2) + (Fn^2 + Ft^2)/(2 EA) - Ft - w = 0 for Fn <= 0; broadcasts like a
    numpy ufunc.

    Parameters
    ----------
    Ft : array_like
        Shear force, -2w/(2 + sqrt(4 + 2w/EA)) <= Ft <= sqrt(2 EA w).
    EA : array_like
        Axial stiffness of the film, > 0; inf gives Rivlin's line.
    w : array_like
        Work of adhesion, > 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises (default) or gives NaN.

    Returns
    -------
    float or numpy.ndarray
        The critical normal force (<= 0).

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``.

    Examples
    --------
    >>> import gecko
    >>> gecko.kendall_fn([0.0, 10.0], 50.0, 1.0).round(6)
    array([-0.990195,  0.      ])
    """
    return _vectorised(_core.kendall_fn, Ft, EA, w, errors=errors)


def rivlin_fn(Ft, w, *, errors: str = "raise"):
    """Rivlin's peel line (paper 001 eq 17): Fn = -sqrt(w^2 + 2 w Ft) for an inextensible film.

    Parameters
    ----------
    Ft : array_like
        Shear force, Ft >= -w/2.
    w : array_like
        Work of adhesion, > 0.
    errors : {"raise", "nan"}, optional
        Out-of-range input raises (default) or gives NaN.

    Returns
    -------
    float or numpy.ndarray
        The critical normal force (<= 0).

    Raises
    ------
    ValueError
        If an argument is out of range with ``errors="raise"``.

    Examples
    --------
    >>> import gecko
    >>> float(gecko.rivlin_fn(4.0, 1.0))
    -3.0
    >>> gecko.rivlin_fn(-1.0, 1.0)
    Traceback (most recent call last):
    ...
    ValueError: gecko::rivlin_fn: Ft = -1 is out of range: need -w/2 <= Ft < infinity
    """
    return _vectorised(_core.rivlin_fn, Ft, w, errors=errors)
