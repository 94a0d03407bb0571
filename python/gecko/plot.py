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

__all__ = [
    "FN_LABEL", "FT_LABEL", "FORCE_SPACE_XLIM", "FORCE_SPACE_YLIM",
    "force_space_axes", "critical_line", "seta_critical_line", "fiber_critical_line",
    "kendall_line", "rivlin_line", "linear_line", "characteristic", "deformed_shapes",
    "force_trace", "force_space", "steady_sliding", "sensitivities",
]

FN_LABEL = r"$\bar F_n = F_n/w$"
FT_LABEL = r"$\bar F_t = F_t/w$"
#: the paper's axis ranges (two-level seta paper, Figs 2, 3, 4, 6a)
FORCE_SPACE_XLIM = (-5.0, 2.0)
FORCE_SPACE_YLIM = (0.0, 10.5)

_PEEL_STYLE = {"kendall": dict(color="k", linestyle="--", linewidth=1.2),
               "rivlin": dict(color="0.35", linestyle=":", linewidth=1.5)}


def force_space_axes(ax, *, xlim=FORCE_SPACE_XLIM, ylim=FORCE_SPACE_YLIM, grid: bool = True):
    """Label ``ax`` as the paper's force space (F̄n horizontal, F̄t vertical) with its ranges."""
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
    """Draw a critical line given in forces (Fn, Ft), non-dimensionalised by ``w``."""
    Fn = np.asarray(Fn, dtype=np.float64) / w
    Ft = np.asarray(Ft, dtype=np.float64) / w
    return ax.plot(Fn, Ft, label=label, **kw)


def seta_critical_line(ax, seta, Ft=None, *, label: Optional[str] = None, **kw):
    """Compute and draw the critical line of a :class:`gecko.TwoLevelSeta` (default grid: 200
    points from 0 to (Ft)max, or to 10 w when EA2 is infinite)."""
    if Ft is None:
        end = seta.ft_max if math.isfinite(seta.ft_max) else 10.0 * seta.w
        Ft = np.linspace(0.0, end, 200)
    line = seta.critical_line(Ft=np.asarray(Ft, dtype=np.float64), errors="nan")
    return critical_line(ax, line.Fn, line.Ft, w=seta.w, label=label, **kw)


def fiber_critical_line(ax, fiber, Ft=None, *, label: Optional[str] = None, **kw):
    """Compute and draw the critical line of a :class:`gecko.SingleFiber`."""
    if Ft is None:
        end = fiber.ft_max if math.isfinite(fiber.ft_max) else 10.0 * fiber.w
        Ft = np.linspace(0.0, end, 200)
    line = fiber.critical_line(np.asarray(Ft, dtype=np.float64), errors="nan")
    return critical_line(ax, line.Fn, line.Ft, w=fiber.w, label=label, **kw)


def kendall_line(ax, EA: float = 50.0, w: float = 1.0, Ft=None, *, label: Optional[str] = None, **kw):
    """Kendall's peel line (eq 17) from Ft = 0 to (Ft)max = sqrt(2 EA w)."""
    from .seta import kendall_fn
    if Ft is None:
        end = math.sqrt(2 * EA * w) if math.isfinite(EA) else 10.0 * w
        Ft = np.linspace(0.0, end, 400)
    Ft = np.asarray(Ft, dtype=np.float64)
    style = dict(_PEEL_STYLE["kendall"], **kw)
    return critical_line(ax, kendall_fn(Ft, EA, w, errors="nan"), Ft, w=w,
                         label="Kendall model" if label is None else label, **style)


def rivlin_line(ax, w: float = 1.0, Ft=None, *, label: Optional[str] = None, **kw):
    """Rivlin's peel line (eq 17) from Ft = 0 to 10 w."""
    from .seta import rivlin_fn
    Ft = np.linspace(0.0, 10.0 * w, 400) if Ft is None else np.asarray(Ft, dtype=np.float64)
    style = dict(_PEEL_STYLE["rivlin"], **kw)
    return critical_line(ax, rivlin_fn(Ft, w, errors="nan"), Ft, w=w,
                         label="Rivlin model" if label is None else label, **style)


def linear_line(ax, Fn, Ft, *, w: float = 1.0, label: Optional[str] = "small deformation (eq 18)", **kw):
    """The linear (small-deformation) critical line, dash-dotted."""
    kw.setdefault("linestyle", "-.")
    kw.setdefault("linewidth", 1.0)
    return critical_line(ax, Fn, Ft, w=w, label=label, **kw)


def characteristic(ax, x, y, *, label: Optional[str] = None, xlabel: Optional[str] = None,
                   ylabel: Optional[str] = None, small: bool = False, **kw):
    """A characteristic quantity against a design parameter; ``small=True`` draws it dashed
    with open markers (the small-deformation formula)."""
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
    """Centre lines of setae at their critical states (``TwoLevelSeta.shape``: x along the
    substrate towards the contact, z the height above it, contact edge at z = 0). The
    substrate is drawn at z = 0 and each clamp is marked with a square."""
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
    """Fig 4 of the frictional adhesion paper: f∥(t) and f⊥(t) of a :class:`gecko.ForceTrace`."""
    a = ax.plot(trace.t, trace.f_par, label=labels[0], **kw)
    b = ax.plot(trace.t, trace.f_perp, label=labels[1], linestyle="--", **kw)
    ax.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("force (arbitrary units)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return a + b


def force_space(ax, f_par, f_perp, *, arrows: bool = True, label: Optional[str] = None, t=None, **kw):
    """Fig 8: the path in force space, F⊥ against F∥, with arrows showing the direction of time."""
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
    """Fig 6: time-averaged F∥ and F⊥ against the drag velocity (V in m/s, shown in µm/s).

    ``axes``: a pair (F∥ axes, F⊥ axes) or one Axes for both (F⊥ dashed)."""
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
    """dFn/d(parameter) along the critical line, one curve per parameter."""
    arts = []
    for name, arr in dFn.items():
        arts += ax.plot(np.asarray(Ft) / w, np.asarray(arr), label=rf"$\partial F_n/\partial {name}$", **kw)
    ax.set_xlabel(FT_LABEL)
    ax.set_ylabel("sensitivity of the critical $F_n$")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return arts


def contact_contours(ax, Fn, Ft, a, *, status=None, levels=9, l2_over_l1: Optional[float] = None,
                     filled: bool = True, color=None, label: Optional[str] = None, colorbar=None, **kw):
    """Contours of the non-contact length a (in units of l1) over a grid of loads: ``Fn``, ``Ft``,
    ``a`` 2-D arrays of one shape (rows: Ft; ``TwoLevelSeta.contact_state`` on a mesh), NaN where
    there is no single equilibrium on the spatula. ``levels``: a number of levels between l1 and
    l1 + l2, or the a/l1 values. ``filled``: shade between the levels (one design), else lines
    only in ``color`` (several designs). With ``status``, loads with several equilibria are
    hatched. ``colorbar``: a figure to draw the colour bar on. Returns the contour set."""
    a = np.asarray(a, dtype=np.float64)
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
