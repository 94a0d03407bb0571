"""gecko.plot — figures of the papers, as functions that draw on a matplotlib ``Axes``.

Usable from notebooks::

    import matplotlib.pyplot as plt, gecko, gecko.plot as gp
    fig, ax = plt.subplots()
    gp.seta_critical_line(ax, gecko.TwoLevelSeta(), label="reference seta")
    gp.kendall_line(ax, EA=50)
    gp.rivlin_line(ax)
    gp.force_space_axes(ax)          # the paper's labels (F̄n = Fn/w, F̄t = Ft/w) and ranges
    ax.legend()

Axes follow the two-level seta paper: F̄n = Fn/w horizontal, F̄t = Ft/w vertical, ranges
F̄n in [-5, 2], F̄t in [0, 10.5]. Every function returns what it drew (matplotlib artists).
Importing this module imports matplotlib; nothing else in gecko does.
"""
from __future__ import annotations

import math
from typing import Optional, Sequence

import numpy as np

from ._optional import require

require("matplotlib", "gecko.plot", "plot")  # a clear install hint instead of a failure mid-drawing

__all__ = [
    "FN_LABEL", "FT_LABEL", "FORCE_SPACE_XLIM", "FORCE_SPACE_YLIM",
    "force_space_axes", "critical_line", "seta_critical_line", "fiber_critical_line",
    "kendall_line", "rivlin_line", "linear_line", "characteristic", "deformed_shapes",
    "force_trace", "force_space", "steady_sliding", "sensitivities", "sliding_fit",
]

FN_LABEL = r"$\bar F_n = F_n/w$"
FT_LABEL = r"$\bar F_t = F_t/w$"
#: the paper's axis ranges (two-level seta paper, Figs 2, 3, 4, 6a)
FORCE_SPACE_XLIM = (-5.0, 2.0)
FORCE_SPACE_YLIM = (0.0, 10.5)

_PEEL_STYLE = {"kendall": dict(color="k", linestyle="--", linewidth=1.2),
               "rivlin": dict(color="0.35", linestyle=":", linewidth=1.5)}


def force_space_axes(ax, *, xlim=FORCE_SPACE_XLIM, ylim=FORCE_SPACE_YLIM, grid: bool = True):
    """Label an Axes as the paper's force space, with its ranges.

    F̄n = Fn/w is horizontal and F̄t = Ft/w vertical, as in the two-level seta paper's Figs 2, 3,
    4 and 6a; a vertical line marks Fn = 0.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    xlim, ylim : (float, float) or None, optional
        Axis ranges; default the paper's, :data:`FORCE_SPACE_XLIM` and :data:`FORCE_SPACE_YLIM`.
        None leaves matplotlib's.
    grid : bool, optional
        Draw a light grid (default True).

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``, for chaining.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko.plot as gp
    >>> ax = gp.force_space_axes(Figure().add_subplot())
    >>> [float(v) for v in ax.get_xlim() + ax.get_ylim()]
    [-5.0, 2.0, 0.0, 10.5]
    """
    ax.set_xlabel(FN_LABEL)
    ax.set_ylabel(FT_LABEL)
    if xlim is not None:
        ax.set_xlim(*xlim)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.axvline(0.0, color="0.6", linewidth=0.8, zorder=0)
    if grid:
        ax.grid(True, linewidth=0.4, alpha=0.5)
    return ax


def critical_line(ax, Fn, Ft, *, w: float = 1.0, label: Optional[str] = None, **kw):
    """Draw a critical line given in forces, non-dimensionalised by ``w``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    Fn, Ft : array_like
        Normal and shear forces along the line (same length).
    w : float, optional
        Work of adhesion; the line is drawn as (Fn/w, Ft/w). Default 1.
    label : str, optional
        Legend label.
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko.plot as gp
    >>> ax = Figure().add_subplot()
    >>> (line,) = gp.critical_line(ax, [0.25, -1.0], [0.0, 2.0], w=2.0)
    >>> line.get_xdata().tolist()
    [0.125, -0.5]
    """
    Fn = np.asarray(Fn, dtype=np.float64) / w
    Ft = np.asarray(Ft, dtype=np.float64) / w
    return ax.plot(Fn, Ft, label=label, **kw)


def seta_critical_line(ax, seta, Ft=None, *, label: Optional[str] = None, **kw):
    """Compute and draw the critical line of a two-level seta.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    seta : gecko.TwoLevelSeta
        The design.
    Ft : array_like, optional
        Shear forces; default 200 points from 0 to (Ft)max (to 10 w when EA2 is infinite).
    label : str, optional
        Legend label.
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn. Points where no critical state was found are NaN, hence gaps.

    Raises
    ------
    ValueError
        If ``Ft`` holds a value outside the line's domain, abs(Ft) > (Ft)max.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> ax = Figure().add_subplot()
    >>> (line,) = gp.seta_critical_line(ax, gecko.TwoLevelSeta(), label="reference seta")
    >>> round(float(line.get_xdata()[0]), 4)        # (Fn)0 / w
    0.2499
    """
    if Ft is None:
        end = seta.ft_max if math.isfinite(seta.ft_max) else 10.0 * seta.w
        Ft = np.linspace(0.0, end, 200)
    line = seta.critical_line(Ft=np.asarray(Ft, dtype=np.float64), errors="nan")
    return critical_line(ax, line.Fn, line.Ft, w=seta.w, label=label, **kw)


def fiber_critical_line(ax, fiber, Ft=None, *, label: Optional[str] = None, **kw):
    """Compute and draw the critical line of a single-level fiber.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    fiber : gecko.SingleFiber
        The fiber.
    Ft : array_like, optional
        Shear forces; default 200 points from 0 to (Ft)max (to 10 w when EA is infinite).
    label : str, optional
        Legend label.
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Raises
    ------
    ValueError
        If ``Ft`` holds a value outside the line's domain.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> ax = Figure().add_subplot()
    >>> (line,) = gp.fiber_critical_line(ax, gecko.SingleFiber(), label="fiber")
    >>> line.get_xdata().size
    200
    """
    if Ft is None:
        end = fiber.ft_max if math.isfinite(fiber.ft_max) else 10.0 * fiber.w
        Ft = np.linspace(0.0, end, 200)
    line = fiber.critical_line(np.asarray(Ft, dtype=np.float64), errors="nan")
    return critical_line(ax, line.Fn, line.Ft, w=fiber.w, label=label, **kw)


def kendall_line(ax, EA: float = 50.0, w: float = 1.0, Ft=None, *, label: Optional[str] = None, **kw):
    """Draw Kendall's peel line (paper 001 eq 17) from Ft = 0 to (Ft)max = sqrt(2 EA w).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    EA : float, optional
        Axial stiffness of the film (default 50, the reference spatula's); inf gives Rivlin's line.
    w : float, optional
        Work of adhesion (default 1).
    Ft : array_like, optional
        Shear forces; default 400 points over the line.
    label : str, optional
        Legend label (default "Kendall model").
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`, over a black dashed style.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko.plot as gp
    >>> (line,) = gp.kendall_line(Figure().add_subplot(), EA=50)
    >>> float(line.get_ydata()[-1])                 # (Ft)max = sqrt(2 * 50 * 1)
    10.0
    """
    from .seta import kendall_fn
    if Ft is None:
        end = math.sqrt(2 * EA * w) if math.isfinite(EA) else 10.0 * w
        Ft = np.linspace(0.0, end, 400)
    Ft = np.asarray(Ft, dtype=np.float64)
    style = dict(_PEEL_STYLE["kendall"], **kw)
    return critical_line(ax, kendall_fn(Ft, EA, w, errors="nan"), Ft, w=w,
                         label="Kendall model" if label is None else label, **style)


def rivlin_line(ax, w: float = 1.0, Ft=None, *, label: Optional[str] = None, **kw):
    """Draw Rivlin's peel line (paper 001 eq 17, inextensible film) from Ft = 0 to 10 w.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    w : float, optional
        Work of adhesion (default 1).
    Ft : array_like, optional
        Shear forces; default 400 points from 0 to 10 w.
    label : str, optional
        Legend label (default "Rivlin model").
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`, over a grey dotted style.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko.plot as gp
    >>> (line,) = gp.rivlin_line(Figure().add_subplot(), Ft=[0.0, 4.0])
    >>> line.get_xdata().tolist()                   # Fn = -sqrt(w^2 + 2 w Ft)
    [-1.0, -3.0]
    """
    from .seta import rivlin_fn
    Ft = np.linspace(0.0, 10.0 * w, 400) if Ft is None else np.asarray(Ft, dtype=np.float64)
    style = dict(_PEEL_STYLE["rivlin"], **kw)
    return critical_line(ax, rivlin_fn(Ft, w, errors="nan"), Ft, w=w,
                         label="Rivlin model" if label is None else label, **style)


def linear_line(ax, Fn, Ft, *, w: float = 1.0, label: Optional[str] = "small deformation (eq 18)", **kw):
    """Draw the small-deformation (linear) critical line, dash-dotted.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    Fn, Ft : array_like
        Points of the line, e.g. from ``TwoLevelSeta.small_deformation_fn``.
    w : float, optional
        Work of adhesion (default 1).
    label : str, optional
        Legend label (default "small deformation (eq 18)").
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Examples
    --------
    >>> import numpy as np
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> seta = gecko.TwoLevelSeta()
    >>> Ft = np.linspace(0.0, 4.0, 5)
    >>> (line,) = gp.linear_line(Figure().add_subplot(), seta.small_deformation_fn(Ft), Ft)
    >>> line.get_linestyle()
    '-.'
    """
    kw.setdefault("linestyle", "-.")
    kw.setdefault("linewidth", 1.0)
    return critical_line(ax, Fn, Ft, w=w, label=label, **kw)


def characteristic(ax, x, y, *, label: Optional[str] = None, xlabel: Optional[str] = None,
                   ylabel: Optional[str] = None, small: bool = False, **kw):
    """Draw a characteristic quantity against a design parameter (paper 001 Fig 5).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    x, y : array_like
        The design parameter and the quantity.
    label, xlabel, ylabel : str, optional
        Legend label and axis labels.
    small : bool, optional
        Draw dashed with open markers, the style of the small-deformation formula (default False).
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        What was drawn.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> ratios = [0.1, 0.4, 1.0]
    >>> fn0 = [gecko.TwoLevelSeta(EI2=5 * r).characteristics(ft_end=0).fn0 for r in ratios]
    >>> (line,) = gp.characteristic(Figure().add_subplot(), ratios, fn0, xlabel="EI2/EI1")
    >>> line.get_xdata().tolist()
    [0.1, 0.4, 1.0]
    """
    if small:
        kw.setdefault("linestyle", "--")
        kw.setdefault("marker", "o")
        kw.setdefault("markerfacecolor", "none")
        kw.setdefault("markersize", 3)
    else:
        kw.setdefault("linestyle", "-")
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return ax.plot(np.asarray(x), np.asarray(y), label=label, **kw)


def deformed_shapes(ax, xs: Sequence, zs: Sequence, labels: Sequence = (), *, substrate: bool = True, **kw):
    """Draw centre lines of setae at their critical states.

    The substrate is drawn at z = 0 and each clamp is marked with a square; the aspect ratio is
    equal, so angles look as they are.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    xs, zs : sequence of array_like
        One centre line per seta, as ``TwoLevelSeta.shape`` returns them: x along the substrate
        towards the contact, z the height above it, contact edge at z = 0.
    labels : sequence of str, optional
        Legend labels, one per centre line.
    substrate : bool, optional
        Draw the substrate (default True).
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        The centre lines.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> s = gecko.TwoLevelSeta().shape(2.0)
    >>> arts = gp.deformed_shapes(Figure().add_subplot(), [s["x"]], [s["z"]], ["Ft = 2"])
    >>> len(arts)
    1
    """
    arts = []
    for i, (x, z) in enumerate(zip(xs, zs)):
        lab = labels[i] if i < len(labels) else None
        x, z = np.asarray(x), np.asarray(z)
        arts += ax.plot(x, z, label=lab, **kw)
        if x.size:
            ax.plot([x[0]], [z[0]], marker="s", color=arts[-1].get_color(), markersize=5)
    if substrate:
        ax.axhline(0.0, color="0.4", linewidth=2.5, zorder=0)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$x/l_1$ (along the substrate)")
    ax.set_ylabel(r"$z/l_1$ (height above the substrate)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return arts


def force_trace(ax, trace, *, labels=(r"$f_\parallel$", r"$f_\perp$"), **kw):
    """Draw f∥(t) and f⊥(t) of a force trace (paper 000 Fig 4).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    trace : gecko.ForceTrace
        From :func:`gecko.force_trace`.
    labels : (str, str), optional
        Legend labels of the two components.
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        The two curves (f⊥ dashed).

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> arts = gp.force_trace(Figure().add_subplot(), gecko.force_trace())
    >>> print(*(a.get_label() for a in arts))
    $f_\\parallel$ $f_\\perp$
    """
    a = ax.plot(trace.t, trace.f_par, label=labels[0], **kw)
    b = ax.plot(trace.t, trace.f_perp, label=labels[1], linestyle="--", **kw)
    ax.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("force (arbitrary units)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return a + b


def force_space(ax, f_par, f_perp, *, arrows: bool = True, label: Optional[str] = None, t=None, **kw):
    """Draw a path in force space, F⊥ against F∥, with arrows along time (paper 000 Fig 8).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    f_par, f_perp : array_like
        Lateral and normal force along the path.
    arrows : bool, optional
        One arrow in the middle of each straight leg (default True).
    label : str, optional
        Legend label.
    t : array_like, optional
        Times of the samples (unused; accepted so that a trace's fields can be passed through).
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        The path.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> tr = gecko.force_trace(path=gecko.FIG8_SETA_PATH)
    >>> (path,) = gp.force_space(Figure().add_subplot(), tr.f_par, tr.f_perp)
    >>> float(path.get_ydata().min())               # the most tensile normal force
    -4.0
    """
    f_par = np.asarray(f_par, dtype=np.float64)
    f_perp = np.asarray(f_perp, dtype=np.float64)
    arts = ax.plot(f_par, f_perp, label=label, **kw)
    if arrows and f_par.size > 1:
        # one arrow in the middle of each straight leg (legs: runs of samples in one direction)
        color = arts[0].get_color()
        angle = np.arctan2(np.diff(f_perp), np.diff(f_par))
        breaks = np.flatnonzero(np.abs(np.diff(angle)) > 1e-9) + 1
        for leg in np.split(np.arange(angle.size), breaks):
            a, b = leg[0], leg[-1] + 1  # the leg runs from sample a to sample b
            mid = (np.array([f_par[a] + f_par[b], f_perp[a] + f_perp[b]])) / 2
            step = np.array([f_par[b] - f_par[a], f_perp[b] - f_perp[a]]) * 0.05
            ax.annotate("", xy=tuple(mid + step), xytext=tuple(mid - step),
                        arrowprops=dict(arrowstyle="-|>", color=color, lw=1.2, mutation_scale=16))
    ax.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
    ax.axvline(0.0, color="0.6", linewidth=0.8, zorder=0)
    ax.set_xlabel(r"$F_\parallel$ (lateral, arbitrary units)")
    ax.set_ylabel(r"$F_\perp$ (normal, arbitrary units; $<0$ tensile)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return arts


def steady_sliding(axes, V, F_par, F_perp, *, label: Optional[str] = None, velocity_unit: float = 1e-6, **kw):
    """Draw time-averaged F∥ and F⊥ against the drag velocity (paper 000 Fig 6).

    Parameters
    ----------
    axes : matplotlib.axes.Axes or (Axes, Axes)
        One Axes for both components (F⊥ dashed), or a pair (F∥ axes, F⊥ axes).
    V : array_like
        Drag velocities in m/s.
    F_par, F_perp : array_like
        The mean forces in N.
    label : str, optional
        Legend label.
    velocity_unit : float, optional
        Unit of the velocity axis in m/s (default 1e-6: µm/s).
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        The two curves.

    Examples
    --------
    >>> import numpy as np
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> V = np.logspace(-6, -3, 20)
    >>> r = gecko.steady_sliding(V, gecko.FIG6_VISCOELASTIC)
    >>> arts = gp.steady_sliding(Figure().add_subplot(), V, r.F_par, r.F_perp)
    >>> float(arts[0].get_xdata()[0])               # shown in µm/s
    1.0
    """
    V = np.asarray(V, dtype=np.float64) / velocity_unit
    if isinstance(axes, (list, tuple, np.ndarray)):
        ax1, ax2 = axes
    else:
        ax1 = ax2 = axes
    a = ax1.plot(V, F_par, label=label, **kw)
    kw2 = dict(kw)
    if ax1 is ax2:
        kw2.setdefault("linestyle", "--")
        kw2.setdefault("color", a[0].get_color())
    b = ax2.plot(V, F_perp, label=label if ax1 is not ax2 else None, **kw2)
    unit = "µm/s" if velocity_unit == 1e-6 else f"{velocity_unit:g} m/s"
    for ax, name in ((ax1, r"shear force $\bar F_\parallel$ (N)"), (ax2, r"normal force $\bar F_\perp$ (N)")):
        ax.set_xlabel(f"drag velocity $V$ ({unit})")
        ax.set_ylabel(name if ax1 is not ax2 else "force (N)")
        ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    return a + b


def sensitivities(ax, Ft, dFn: dict, *, w: float = 1.0, **kw):
    """Draw dFn/d(parameter) along the critical line, one curve per parameter.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes to draw on.
    Ft : array_like
        Shear forces along the line.
    dFn : dict
        Parameter name -> derivative of the critical Fn at each Ft, e.g. from
        ``TwoLevelSeta.sensitivities``.
    w : float, optional
        Work of adhesion; Ft is drawn as Ft/w (default 1).
    **kw
        Passed to :meth:`matplotlib.axes.Axes.plot`.

    Returns
    -------
    list of matplotlib.lines.Line2D
        One curve per parameter.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> import gecko.plot as gp
    >>> arts = gp.sensitivities(Figure().add_subplot(), [0.0, 1.0], {"alpha2": [0.1, 0.2]})
    >>> print(arts[0].get_label())
    $\\partial F_n/\\partial alpha2$
    """
    arts = []
    for name, arr in dFn.items():
        arts += ax.plot(np.asarray(Ft) / w, np.asarray(arr), label=rf"$\partial F_n/\partial {name}$", **kw)
    ax.set_xlabel(FT_LABEL)
    ax.set_ylabel("sensitivity of the critical $F_n$")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return arts


def contact_contours(ax, Fn, Ft, a, *, status=None, levels=9, l2_over_l1: Optional[float] = None,
                     filled: bool = True, color=None, label: Optional[str] = None, colorbar=None, **kw):
    """Contours of the non-contact length a (in units of l1) over a grid of loads.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    Fn, Ft, a : array_like
        2-D arrays of one shape (rows: Ft), e.g. ``TwoLevelSeta.contact_state`` on a mesh, a in
        units of l1; NaN where there is no single equilibrium on the spatula.
    status : array_like of int, optional
        The contact statuses: only status-0 loads are contoured, loads with several equilibria
        (status 6) are hatched.
    levels : int or sequence of float
        A number of levels between l1 and l1 + l2 (with ``l2_over_l1``), or the a/l1 values.
    l2_over_l1 : float, optional
        l2/l1, for the range of the levels (else the range of ``a``).
    filled : bool
        Shade between the levels (one design); else lines only, in ``color`` (several designs).
    color : optional
        Line colour when not filled.
    label : str, optional
        Legend label.
    colorbar : matplotlib.figure.Figure, optional
        A figure to draw the colour bar on.
    **kw
        Passed to :meth:`matplotlib.axes.Axes.contour`.

    Returns
    -------
    matplotlib.contour.QuadContourSet or None
        The contour lines (None when no load has a single equilibrium).

    Examples
    --------
    >>> import numpy as np
    >>> from matplotlib.figure import Figure
    >>> import gecko, gecko.plot as gp
    >>> Fn, Ft = np.meshgrid(np.linspace(-3, 1, 41), np.linspace(0, 9, 10))
    >>> st = gecko.TwoLevelSeta().contact_state(Fn, Ft)
    >>> cs = gp.contact_contours(Figure().add_subplot(), Fn, Ft, st.a, status=st.status, l2_over_l1=0.1)
    >>> len(cs.levels)
    9
    """
    a = np.asarray(a, dtype=np.float64)
    if status is not None:  # only loads with one admissible equilibrium (inadmissible ones keep a)
        a = np.where(np.asarray(status) == 0, a, np.nan)
    finite = a[np.isfinite(a)]
    if isinstance(levels, (int, np.integer)):
        if l2_over_l1 is not None:
            lo, hi = 1.0, 1.0 + float(l2_over_l1)
        elif finite.size:
            lo, hi = float(finite.min()), float(finite.max())
        else:
            lo, hi = 1.0, 2.0
        levels = np.linspace(lo, hi, int(levels) + 2)[1:-1] if hi > lo else [lo]
    levels = np.asarray(levels, dtype=np.float64)
    cs = None
    if finite.size:
        if filled:
            bounds = np.concatenate([[min(levels[0], finite.min())], levels, [max(levels[-1], finite.max())]])
            bounds = np.unique(bounds)
            if bounds.size >= 2:
                cf = ax.contourf(Fn, Ft, a, levels=bounds, cmap=kw.pop("cmap", "viridis"), alpha=0.85)
                if colorbar is not None:
                    colorbar.colorbar(cf, ax=ax, label=r"non-contact length $a/l_1$")
            cs = ax.contour(Fn, Ft, a, levels=levels, colors="k", linewidths=0.6, **kw)
        else:
            cs = ax.contour(Fn, Ft, a, levels=levels, colors=color, linewidths=1.0, **kw)
        if cs is not None and len(cs.levels):
            ax.clabel(cs, fmt="%.3g", fontsize="x-small")
    if status is not None:
        several = (np.asarray(status) == 6).astype(float)
        if several.any():
            ax.contourf(Fn, Ft, several, levels=[0.5, 1.5], colors="none", hatches=["///"])
    if label:
        ax.plot([], [], color=color or "k", label=label)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return cs


# ---- a fit of the steady-sliding model to measured data (gecko.scene.sliding_fit) ----------------

def sliding_fit(axes, curves, *, xscale: str = "log", velocity_unit: float = 1e-6):
    """Draw measured steady-sliding forces, the fitted eqs 9-10 and the residuals.

    Parameters
    ----------
    axes : sequence of three matplotlib.axes.Axes
        Lateral force, normal force, residuals.
    curves : sequence of gecko.scene.Curve
        From a ``sliding_fit`` plot: roles ``data_par``/``data_perp`` (points, with error bars
        where ``meta["sigma"]`` is given), ``fit_par``/``fit_perp`` (lines), ``res_par``/``res_perp``.
    xscale : str, optional
        Velocity axis scale (default "log").
    velocity_unit : float, optional
        Unit of the velocity axis in m/s (default 1e-6: µm/s).

    Returns
    -------
    list
        The artists drawn.

    Examples
    --------
    >>> import numpy as np
    >>> from matplotlib.figure import Figure
    >>> from gecko.scene import Curve
    >>> import gecko.plot as gp
    >>> V = np.array([1e-6, 1e-5, 1e-4])
    >>> cs = [Curve("s", "data", V, V * 0 + 0.03, "V", "F_par", "data_par", panel=0),
    ...       Curve("s", "fit", V, V * 0 + 0.03, "V", "F_par", "fit_par", panel=0),
    ...       Curve("s", "lateral", V, V * 0, "V", "residual", "res_par", panel=2)]
    >>> len(gp.sliding_fit(Figure().subplots(1, 3), cs))
    3
    """
    unit = "µm/s" if velocity_unit == 1e-6 else f"{velocity_unit:g} m/s"
    colors: dict = {}
    arts = []
    for c in curves:
        ax = axes[c.panel]
        x = np.asarray(c.x, dtype=np.float64) / velocity_unit
        color = colors.setdefault((c.study, c.role[-3:] if c.panel == 2 else ""), f"C{len(colors)}")
        if c.role.startswith("data"):
            sigma = c.meta.get("sigma")
            if sigma is not None:
                arts.append(ax.errorbar(x, c.y, yerr=sigma, fmt="o", ms=3.5, color="0.25",
                                        elinewidth=0.8, label=c.label))
            else:
                arts += ax.plot(x, c.y, "o", ms=3.5, color="0.25", label=c.label)
        elif c.role.startswith("fit"):
            arts += ax.plot(x, c.y, "-", linewidth=1.6, color="C0", label=c.label)
        else:
            arts += ax.plot(x, c.y, "o-" if c.role == "res_par" else "s--", ms=3, linewidth=0.8,
                            color=color, label=c.label)
    names = (r"shear force $\bar F_\parallel$ (N)", r"normal force $\bar F_\perp$ (N)",
             "residual, data − fit (N)")
    for ax, name in zip(axes, names):
        ax.set_xlabel(f"drag velocity $V$ ({unit})")
        ax.set_ylabel(name)
        ax.set_xscale(xscale)
        ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    axes[2].axhline(0.0, color="0.4", linewidth=0.8, zorder=0)
    return arts
# ---- the hierarchy of paper 000's Discussion (gecko.plot_hierarchy) -----------------------------
from .plot_hierarchy import compliant_seta_trace, population_forces, stick_slip_map  # noqa: E402

__all__ += ["population_forces", "compliant_seta_trace", "stick_slip_map"]
