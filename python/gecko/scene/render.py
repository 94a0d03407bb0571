"""Draw a scene's plots with :mod:`gecko.plot` (imported here only: no plot, no matplotlib)."""
from __future__ import annotations

from pathlib import Path
from typing import Callable, Dict, List, Sequence

import numpy as np

from .models import CHARACTERISTIC_LABELS


def _figure(size):
    from .._optional import require
    # no pyplot: no GUI backend, no global state
    Figure = require("matplotlib.figure", "drawing a scene's plots (or run it without figures)",
                     "plot").Figure
    return Figure(figsize=size, layout="constrained") if _has_layout() else Figure(figsize=size)


def _has_layout() -> bool:
    import inspect
    from matplotlib.figure import Figure
    return "layout" in inspect.signature(Figure.__init__).parameters


_SYMBOLS = {"ratio": r"$EI_2/EI_1$", "EI2": r"$EI_2/(w l_1^2)$", "alpha2": r"$\alpha_2$ (rad)",
            "alpha1": r"$\alpha_1$ (rad)", "l2": r"$l_2/l_1$", "EA2": r"$EA_2/w$", "EA1": r"$EA_1/w$"}


#: plot kind -> (renderer(fig, plot, curves) -> the axes it drew on, default size in inches), for
#: kinds declared outside this module (e.g. gecko.scene.hierarchy)
PLOT_RENDERERS: Dict[str, Callable] = {}


def _render_sliding_fit(fig, plot, curves):
    """Data, fit and residuals of a sliding_fit study (three panels; gecko.plot.sliding_fit)."""
    from .. import plot as gp
    axes = list(fig.subplots(1, 3))
    gp.sliding_fit(axes, curves, xscale=plot.options.get("xscale", "log"))
    return axes


PLOT_RENDERERS["sliding_fit"] = (_render_sliding_fit, (13.0, 4.2))


def render_plot(scene, plot, curves, folder: Path, formats: Sequence[str]) -> List[str]:
    from .. import plot as gp
    opts = plot.options
    kind = plot.kind
    if kind in PLOT_RENDERERS:
        draw, size = PLOT_RENDERERS[kind]
        fig = _figure(opts.get("size", size))
        axes = draw(fig, plot, curves)
        return _finish(scene, plot, fig, axes, folder, formats)
    size = opts.get("size", (10.0, 4.2) if kind == "steady_sliding" else (6.4, 4.8))
    fig = _figure(size)
    if kind == "steady_sliding":
        axes = fig.subplots(1, 2)
    else:
        axes = [fig.add_subplot(1, 1, 1)]
    ax = axes[0]
    if kind == "critical_line":
        seta_i = 0
        for c in curves:
            if c.role in ("kendall", "rivlin"):
                style = dict(gp._PEEL_STYLE[c.role])
                ax.plot(c.x, c.y, label=c.label, **style)
            elif c.role == "linear":
                gp.linear_line(ax, c.x, c.y, label=c.label, color=f"C{max(seta_i - 1, 0)}")
            else:
                ax.plot(c.x, c.y, label=c.label, color=f"C{seta_i}",
                        linestyle="-" if c.role == "seta" else (0, (5, 1.5)), linewidth=1.6)
                seta_i += 1
        gp.force_space_axes(ax, xlim=opts.get("xlim", gp.FORCE_SPACE_XLIM), ylim=opts.get("ylim", gp.FORCE_SPACE_YLIM))
    elif kind == "characteristic":
        for i, c in enumerate(curves):
            gp.characteristic(ax, c.x, c.y, label=c.label, small=c.role == "small", color=f"C{i}")
        ax.set_xlabel(_SYMBOLS.get(plot.x, plot.x))
        ax.set_ylabel(", ".join(CHARACTERISTIC_LABELS.get(y, y).split(",")[0] for y in dict.fromkeys(
            y.replace("small_", "") for y in plot.y)))
        if any(c.yname.endswith("fn0") for c in curves):
            ax.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
    elif kind == "shapes":
        gp.deformed_shapes(ax, [c.x for c in curves], [c.y for c in curves], [c.label for c in curves])
    elif kind == "sensitivities":
        for c in curves:
            ax.plot(c.x, c.y, label=c.label)
        ax.set_xlabel(gp.FT_LABEL)
        ax.set_ylabel("sensitivity of the critical $F_n$")
        ax.grid(True, linewidth=0.4, alpha=0.5)
    elif kind == "force_trace":
        for c in curves:
            ax.plot(c.x, c.y, label=c.label, linestyle="-" if c.role == "f_par" else "--", linewidth=1.6)
        ax.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
        ax.set_xlabel("time $t$ (s)")
        ax.set_ylabel("force (arbitrary units)")
        ax.grid(True, linewidth=0.4, alpha=0.5)
    elif kind == "force_space":
        for c in curves:
            gp.force_space(ax, c.x, c.y, arrows=opts.get("arrows", True), label=c.label, linewidth=1.6)
    elif kind == "contact_contours":
        many = len(curves) > 1
        for i, c in enumerate(curves):
            shape = c.meta["shape"]
            gp.contact_contours(ax, c.x.reshape(shape), c.y.reshape(shape), c.meta["columns"]["a_over_l1"].reshape(shape),
                                status=c.meta["columns"]["status"].reshape(shape), levels=c.meta["levels"],
                                l2_over_l1=c.meta["l2"] / c.meta["l1"], filled=not many,
                                color=f"C{i}" if many else None, label=c.label or None,
                                colorbar=None if many else fig)
        ax.set_xlabel(gp.FN_LABEL)
        ax.set_ylabel(gp.FT_LABEL)
    elif kind == "steady_sliding":
        labels = {}
        for c in curves:
            a = axes[c.panel]
            color = labels.setdefault(c.label, f"C{len(labels)}")
            a.plot(c.x / 1e-6, c.y, label=c.label, color=color, linewidth=1.6)
        for a, name in zip(axes, (r"shear force $\bar F_\parallel$ (N)", r"normal force $\bar F_\perp$ (N)")):
            a.set_xlabel(r"drag velocity $V$ (µm/s)")
            a.set_ylabel(name)
            a.set_xscale(opts.get("xscale", "log"))
            a.grid(True, which="both", linewidth=0.4, alpha=0.5)
            a.axhline(0.0, color="0.6", linewidth=0.8, zorder=0)
    return _finish(scene, plot, fig, axes, folder, formats)


def _finish(scene, plot, fig, axes, folder: Path, formats: Sequence[str]) -> List[str]:
    """The options every plot kind shares (limits, scales, labels, legend, title), then the files."""
    opts = plot.options
    kind = plot.kind
    for a in axes:
        if kind not in ("critical_line", "steady_sliding"):
            if "xlim" in opts:
                a.set_xlim(*opts["xlim"])
            if "ylim" in opts:
                a.set_ylim(*opts["ylim"])
        if "xscale" in opts and kind != "steady_sliding":
            a.set_xscale(opts["xscale"])
        if "yscale" in opts:
            a.set_yscale(opts["yscale"])
        if "xlabel" in opts:
            a.set_xlabel(opts["xlabel"])
        if "ylabel" in opts:
            a.set_ylabel(opts["ylabel"])
        legend = opts.get("legend", True)
        if legend and a.get_legend_handles_labels()[0]:
            a.legend(loc=legend if isinstance(legend, str) else "best", fontsize="small", framealpha=0.85)
    title = opts.get("title", scene.title)
    if title:
        fig.suptitle(title, fontsize="medium")
    if not _has_layout():
        fig.tight_layout()
    written = []
    for fmt in formats:
        name = f"{plot.name}.{fmt}"
        fig.savefig(folder / name, dpi=150 if fmt == "png" else None, format=fmt)
        written.append(name)
    return written


def _save(fig, folder: Path, name: str, formats: Sequence[str]) -> List[str]:
    if not _has_layout():
        fig.tight_layout()
    written = []
    for fmt in formats:
        fig.savefig(folder / f"{name}.{fmt}", dpi=150 if fmt == "png" else None, format=fmt)
        written.append(f"{name}.{fmt}")
    return written


def render_sweep(scene, table, folder: Path, formats: Sequence[str]) -> List[str]:
    """[sweep.plot]: one output against another over the designs that solved (status 0),
    coloured by a third column when asked."""
    spec = scene.sweep
    p = spec.plot
    from ..seta import CriticalStatus
    ok = table[table["status"] == CriticalStatus.converged]
    fig = _figure((6.4, 4.8))
    ax = fig.add_subplot(1, 1, 1)
    kw = dict(s=6, linewidths=0)
    if "color" in p:
        sc = ax.scatter(ok[p["x"]], ok[p["y"]], c=ok[p["color"]].astype(float), cmap="viridis", **kw)
        fig.colorbar(sc, ax=ax, label=CHARACTERISTIC_LABELS.get(p["color"], _SYMBOLS.get(p["color"], p["color"])))
    else:
        ax.scatter(ok[p["x"]], ok[p["y"]], **kw)
    ax.set_xlabel(CHARACTERISTIC_LABELS.get(p["x"], _SYMBOLS.get(p["x"], p["x"])))
    ax.set_ylabel(CHARACTERISTIC_LABELS.get(p["y"], _SYMBOLS.get(p["y"], p["y"])))
    ax.set_xscale(p.get("xscale", "linear"))
    ax.set_yscale(p.get("yscale", "linear"))
    ax.grid(True, linewidth=0.4, alpha=0.5)
    failed = len(table) - len(ok)
    ax.set_title(f"{len(ok)} designs" + (f" ({failed} with status != 0 not drawn)" if failed else ""),
                 fontsize="small")
    if scene.title:
        fig.suptitle(scene.title, fontsize="medium")
    return _save(fig, folder, spec.name, formats)


def render_optimum(scene, opt, folder: Path, formats: Sequence[str]) -> List[str]:
    """[optimize]: the optimum's critical line (the paper's axes: Fn horizontal, Ft vertical) with
    the reference design's line for comparison and the optimum's maximum pull-off marked."""
    from .. import plot as gp
    from ..seta import TwoLevelSeta
    fig = _figure((6.4, 4.8))
    ax = fig.add_subplot(1, 1, 1)
    ref = TwoLevelSeta()
    gp.seta_critical_line(ax, ref, label="reference design", color="0.6", linestyle="--")
    if opt.seta is not None:
        gp.seta_critical_line(ax, opt.seta, color="C0", linewidth=1.8,
                              label=f"optimum ({opt.status}): {opt.objective} = {opt.value:.4g}")
        c = opt.seta.characteristics()
        if np.isfinite(c.min_fn) and c.min_fn < 0:
            ax.plot(c.min_fn, c.ft_at_min_fn, "o", color="C3", label=f"max pull-off {c.max_pull_off:.4g}")
    ax.set_xlabel(gp.FN_LABEL)
    ax.set_ylabel(gp.FT_LABEL)
    ax.axvline(0.0, color="0.6", linewidth=0.8, zorder=0)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(loc="best", fontsize="small", framealpha=0.85)
    d = opt.design
    derived = {"EI2/EI1": lambda: d["EI2"] / d["EI1"], "l2/l1": lambda: d["l2"] / d["l1"],
               "alpha1+alpha2": lambda: d["alpha1"] + d["alpha2"]}
    values = [(v, d[v] if v in d else derived[v]()) for v in opt.variables if v in d or v in derived]
    ax.set_title(f"{opt.status}: " + ", ".join(f"{k} = {v:.4g}" for k, v in values), fontsize="small")
    if scene.title:
        fig.suptitle(scene.title, fontsize="medium")
    return _save(fig, folder, scene.optimize.name, formats)
