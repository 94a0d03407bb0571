"""Figures of the hierarchy models (:mod:`gecko.friction_hierarchy`), drawn on matplotlib Axes;
re-exported by :mod:`gecko.plot`. Every function returns what it drew."""
from __future__ import annotations

from typing import Optional

import numpy as np

__all__ = ["population_forces", "compliant_seta_trace", "stick_slip_map"]


def population_forces(ax, x, simulated, population, mean_field, expected=None, *, bound=None,
                      label: Optional[str] = None, color=None, xlabel: Optional[str] = None,
                      ylabel: Optional[str] = None):
    """A spatula population's mean force against a swept quantity ``x``: the simulation (dots,
    with ``bound`` as error bars), eqs 9-10 averaged over the population (solid), over the
    distribution (dotted) and at the mean parameters (dashed).

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt, gecko.plot as gp
    >>> fig, ax = plt.subplots()
    >>> out = gp.population_forces(ax, [0, 0.5], [1.0, 0.9], [1.0, 0.9], [1.0, 1.0])
    >>> len(out)
    3
    """
    x = np.asarray(x, dtype=float)
    pre = f"{label}: " if label else ""
    drawn = []
    line = ax.plot(x, population, "-", color=color, linewidth=1.6,
                   label=pre + "eqs 9-10 averaged over the spatulae")[0]
    color = line.get_color()
    drawn.append(line)
    drawn += ax.plot(x, mean_field, "--", color=color, linewidth=1.2, label=pre + "eqs 9-10 at the mean parameters")
    if expected is not None and np.any(np.isfinite(np.asarray(expected, dtype=float))):
        drawn += ax.plot(x, expected, ":", color=color, linewidth=1.4, label=pre + "averaged over the distribution")
    yerr = None if bound is None else np.where(np.isfinite(bound), bound, 0.0)
    drawn.append(ax.errorbar(x, simulated, yerr=yerr, fmt="o", color=color, markersize=4, capsize=2,
                             label=pre + "simulation"))
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return drawn


def compliant_seta_trace(ax, t, F, *, label: Optional[str] = None, time_unit: float = 1e-3, **kw):
    """The lateral force of a seta on its spring against time (in ``time_unit``, default ms).

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt, gecko.plot as gp
    >>> fig, ax = plt.subplots()
    >>> len(gp.compliant_seta_trace(ax, [0.0, 1e-3], [1.0, 2.0]))
    1
    """
    kw.setdefault("linewidth", 1.0)
    drawn = ax.plot(np.asarray(t) / time_unit, F, label=label, **kw)
    ax.set_xlabel("time (ms)" if time_unit == 1e-3 else f"time (x {time_unit:g} s)")
    ax.set_ylabel(r"seta lateral force $k_s (Vt - x)$ (N)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    return drawn


def stick_slip_map(ax, stiffness_ratio, relative_drop, stick_slip, *, threshold: Optional[float] = None,
                   label: Optional[str] = None, color=None):
    """The classifier of :func:`gecko.friction_hierarchy.compliant_seta` against the spring's
    stiffness ratio k_s / (N K_par_par): filled markers are seta-level stick-slip, open ones
    smooth sliding; a dotted line marks the threshold.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt, gecko.plot as gp
    >>> fig, ax = plt.subplots()
    >>> len(gp.stick_slip_map(ax, [0.01, 100], [1.0, 0.01], [True, False], threshold=0.1))
    4
    """
    r = np.asarray(stiffness_ratio, dtype=float)
    d = np.asarray(relative_drop, dtype=float)
    s = np.asarray(stick_slip, dtype=bool)
    order = np.argsort(r)
    line = ax.plot(r[order], d[order], "-", color=color, linewidth=1.2, label=label)[0]
    color = line.get_color()
    drawn = [line]
    drawn.append(ax.plot(r[s], d[s], "o", color=color, markersize=6)[0])
    drawn.append(ax.plot(r[~s], d[~s], "o", markerfacecolor="none", color=color, markersize=6)[0])
    if threshold is not None:
        drawn.append(ax.axhline(threshold, color="0.4", linestyle=":", linewidth=1.0))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"spring stiffness ratio $k_s / (N K_{\parallel\parallel})$")
    ax.set_ylabel("largest slip: force drop / mean force")
    ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    return drawn
