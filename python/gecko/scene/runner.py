"""Run a planned scene: compute, collect the curves of every plot, write CSV and figures.

Nothing is written until everything is computed and every figure is drawn: files go to a
staging folder inside the output folder and are renamed into place at the end, so a failure
leaves no half-written file behind.
"""
from __future__ import annotations

import csv
import io
import os
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from ..progress import Progress  # noqa: F401  (moved to gecko.progress; old name kept)
from ..seta import DESIGN_FIELDS
from .adapters import ADAPTERS, _design, _grid, _key, _seta  # noqa: F401  (the kernels' helpers, moved)
from .errors import SceneError
from .models import CHARACTERISTIC_LABELS
from .planner import Plan, Step, plan_scene
from .schema import Point, Scene, Study, load_scene

#: the two-level seta design fields (from the bound C++ design type)
SETA_FIELDS = DESIGN_FIELDS


# ---- results ------------------------------------------------------------------------------------

@dataclass
class Curve:
    """One plotted curve, ready for CSV and for :mod:`gecko.plot`.

    Attributes
    ----------
    study, label : str
        The study it comes from and its legend label.
    x, y : numpy.ndarray
        The points.
    xname, yname : str
        Column names of x and y in the CSV file.
    role : str
        What it is: ``seta``, ``fiber``, ``kendall``, ``rivlin``, ``linear``, ``f_par``, ...
    panel : int
        Axes index for multi-panel plots.
    meta : dict
        Anything else the renderer needs.

    Examples
    --------
    >>> import numpy as np
    >>> from gecko.scene import Curve
    >>> c = Curve(study="s", label="line", x=np.zeros(2), y=np.ones(2), xname="Fn", yname="Ft")
    >>> c.role
    'line'
    """

    study: str
    label: str
    x: np.ndarray
    y: np.ndarray
    xname: str
    yname: str
    role: str = "line"        # seta, fiber, kendall, rivlin, linear, f_par, f_perp, shape, ...
    panel: int = 0            # axes index for multi-panel plots
    meta: Dict[str, Any] = field(default_factory=dict)


@dataclass
class RunResult:
    """What :func:`run_scene` computed.

    Attributes
    ----------
    scene : Scene
        The validated scene.
    plan : Plan
        The kernels that ran (:meth:`Plan.describe`).
    data : dict
        Study name -> one dict per design: output name -> its data (arrays, characteristics).
    curves : dict
        Plot name -> the :class:`Curve` objects behind the plot.
    files : list of pathlib.Path
        Files written (empty without ``out``).
    seconds : float
        Wall time of the run.
    sweep : pandas.DataFrame or None
        The table of a ``[sweep]`` section.
    optimum : gecko.SetaOptimum or None
        The result of an ``[optimize]`` section.

    Examples
    --------
    >>> from gecko.scene import run_scene
    >>> r = run_scene({"study": [{"name": "k", "model": "kendall", "outputs": {"characteristics": True}}]})
    >>> sorted(r.data)
    ['k']
    """
    scene: Scene
    plan: Plan
    data: Dict[str, List[Dict[str, Any]]]   # study name -> per design: output name -> data
    curves: Dict[str, List[Curve]]          # plot name -> curves
    files: List[Path] = field(default_factory=list)
    seconds: float = 0.0
    sweep: Any = None                       # the [sweep] table (a pandas DataFrame)
    optimum: Any = None                     # the [optimize] result (gecko.optimize.SetaOptimum)


class Cache(dict):
    """Results keyed by (kernel, design, grid); share one across runs to reuse them.

    Attributes
    ----------
    hits, misses : int
        Designs served from the cache, and designs computed.

    Examples
    --------
    >>> from gecko.scene import Cache, run_scene
    >>> scene = {"study": [{"name": "s", "model": "two_level_seta", "outputs": {"characteristics": ["fn0"]}}]}
    >>> cache = Cache()
    >>> _ = run_scene(scene, cache=cache); _ = run_scene(scene, cache=cache)
    >>> cache.misses, cache.hits
    (1, 1)
    """

    def __init__(self):
        super().__init__()
        self.hits = 0
        self.misses = 0


# ---- kernels ------------------------------------------------------------------------------------

class _Executor:
    def __init__(self, scene: Scene, cache: Cache, progress: Progress, threads: int):
        self.scene, self.cache, self.progress, self.threads = scene, cache, progress, threads
        self.data: Dict[str, List[Dict[str, Any]]] = {s.name: [dict() for _ in s.points] for s in scene.studies}

    def cached(self, key, fn):
        if key in self.cache:
            self.cache.hits += 1
            return self.cache[key]
        self.cache.misses += 1
        val = fn()
        self.cache[key] = val
        return val

    def run(self, step: Step) -> None:
        st = self.scene.study(step.study)
        ADAPTERS[st.model.name].run(self, st, step)


# ---- curves of each plot -------------------------------------------------------------------------

def _tex_symbol(name: str) -> str:
    """TeX of a design field: EI1 -> EI_1, alpha2 -> \\alpha_2."""
    head, digit = (name[:-1], name[-1]) if name[-1:].isdigit() else (name, "")
    head = "\\" + head if head == "alpha" else head
    return f"{head}_{digit}" if digit else head


_TEX = {f: _tex_symbol(f) for f in SETA_FIELDS}


def plot_curves(scene: Scene, plot, data) -> List[Curve]:
    """The data behind one plot, as curves (no matplotlib needed)."""
    curves: List[Curve] = []
    studies = [scene.study(n) for n in plot.studies]
    # name the model in a legend only when two studies sweep (their labels alone could clash)
    many = sum(bool(s.swept_names) for s in studies) > 1
    for st in studies:
        rows = data[st.name]
        w_of = lambda p: float(p.values.get("w", 1.0))  # noqa: E731
        if plot.kind == "critical_line":
            for p in st.points:
                d = rows[p.index]
                if "critical_line" in d:
                    c = d["critical_line"]
                    curves.append(Curve(st.name, st.label_for(p, many), np.asarray(c["Fn"]) / w_of(p),
                                        np.asarray(c["Ft"]) / w_of(p), "Fn_bar", "Ft_bar",
                                        ADAPTERS[st.model.name].role,
                                        meta={"status": np.asarray(c["status"]), "values": p.values}))
                if "linear_line" in d:
                    c = d["linear_line"]
                    curves.append(Curve(st.name, st.label_for(p, many) + " (small deformation, eq 18)"
                                        if st.swept_names else "small deformation (eq 18)",
                                        np.asarray(c["Fn"]) / w_of(p), np.asarray(c["Ft"]) / w_of(p),
                                        "Fn_bar", "Ft_bar", "linear", meta={"values": p.values}))
        elif plot.kind == "characteristic":
            others = [n for n in st.swept_names if n != plot.x]
            groups: Dict[tuple, List[Point]] = {}
            for p in st.points:
                groups.setdefault(tuple(_key(p.swept[n]) for n in others), []).append(p)
            for pts in groups.values():
                pts = sorted(pts, key=lambda p: p.swept[plot.x])
                x = np.array([float(p.swept[plot.x]) for p in pts])
                for yname in plot.y:
                    y = np.array([float(rows[p.index]["characteristics"][yname]) for p in pts])
                    lab = CHARACTERISTIC_LABELS.get(yname, yname)
                    if others:
                        from .schema import _fmt, _symbol
                        lab += ", " + ", ".join(f"{_symbol(st.model, n)} = {_fmt(n, pts[0].swept[n])}" for n in others)
                    if len(studies) > 1:
                        lab = f"{st.name}: {lab}"
                    curves.append(Curve(st.name, lab, x, y, plot.x, yname,
                                        "small" if yname.startswith("small_") else "exact"))
        elif plot.kind == "shapes":
            for p in st.points:
                s = rows[p.index]["shapes"]
                for j, ft in enumerate(s["Ft"]):
                    base = st.label_for(p, many) if st.swept_names else ""
                    lab = (base + ", " if base else "") + f"$\\bar F_t$ = {ft / w_of(p):.3g}"
                    curves.append(Curve(st.name, lab, s["x"][j], s["z"][j], "x", "z", "shape",
                                        meta={"Ft": float(ft), "Fn": float(s["Fn"][j]),
                                              "closing_error": float(s["closing_error"][j]),
                                              "status": int(s["status"][j])}))
        elif plot.kind == "sensitivities":
            for p in st.points:
                s = rows[p.index]["sensitivities"]
                base = st.label_for(p, many) + ": " if st.swept_names else ""
                for name, arr in s["dFn"].items():
                    sym = _TEX.get(name, name)
                    curves.append(Curve(st.name, f"{base}$\\partial F_n/\\partial {sym}$", np.asarray(s["Ft"]), np.asarray(arr),
                                        "Ft", f"dFn_d{name}", "sensitivity"))
        elif plot.kind in ("force_trace", "force_space"):
            for p in st.points:
                tr = rows[p.index]["force_trace"]
                base = st.label_for(p, many) if (st.swept_names or st.label) else ""
                pre = base + ": " if base else ""
                if plot.kind == "force_trace":
                    curves.append(Curve(st.name, pre + "$f_\\parallel$", tr.t, tr.f_par, "t", "f", "f_par"))
                    curves.append(Curve(st.name, pre + "$f_\\perp$", tr.t, tr.f_perp, "t", "f", "f_perp"))
                else:
                    curves.append(Curve(st.name, base or st.model.title, tr.f_par, tr.f_perp, "F_par", "F_perp",
                                        "force_space", meta={"t": tr.t}))
        elif plot.kind == "contact_contours":
            for p in st.points:
                c = rows[p.index]["contact_contours"]
                w, l1 = w_of(p), float(p.values["l1"])
                FN, FT = np.meshgrid(np.asarray(c["Fn"]) / w, np.asarray(c["Ft"]) / w)
                a = np.asarray(c["a"]) / l1
                curves.append(Curve(st.name, st.label_for(p, many) if (st.swept_names or st.label) else "",
                                    FN.ravel(), FT.ravel(), "Fn_bar", "Ft_bar", "contact_contours",
                                    meta={"columns": {"a_over_l1": a.ravel(), "status": np.asarray(c["status"]).ravel()},
                                          "shape": a.shape, "levels": st.outputs["contact_contours"].options["levels"],
                                          "l1": l1, "l2": float(p.values["l2"]), "values": p.values}))
        elif plot.kind == "steady_sliding":
            for p in st.points:
                f = rows[p.index]["forces"]
                base = st.label_for(p, many)
                curves.append(Curve(st.name, base, f["V"], f["F_par"], "V", "F_par", "F_par", panel=0))
                curves.append(Curve(st.name, base, f["V"], f["F_perp"], "V", "F_perp", "F_perp", panel=1))
        else:  # a plot kind its model's adapter draws
            curves.extend(ADAPTERS[st.model.name].plot_curves(plot, st, rows, many, Curve))
    return curves


def curves_csv(curves: Sequence[Curve]) -> str:
    """Every curve of a plot in one tidy table: study, curve, label, x, y (named columns)."""
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    xname = curves[0].xname if curves else "x"
    yname = curves[0].yname if curves else "y"
    same = all(c.xname == xname and c.yname == yname for c in curves)
    # values on the points beyond x and y (a contour's a and status), when every curve has them
    extra = list(curves[0].meta.get("columns", {})) if curves else []
    if not all(list(c.meta.get("columns", {})) == extra for c in curves):
        extra = []
    head = ["study", "curve", "label", "panel"] + ([xname, yname] if same else ["x_name", "x", "y_name", "y"]) + extra
    wr.writerow(head)
    for i, c in enumerate(curves):
        cols = [np.asarray(c.meta["columns"][k]).ravel() for k in extra]
        for j, (xv, yv) in enumerate(zip(np.asarray(c.x).ravel(), np.asarray(c.y).ravel())):
            row = [c.study, i, c.label, c.panel]
            row += [repr(float(xv)), repr(float(yv))] if same else [c.xname, repr(float(xv)), c.yname, repr(float(yv))]
            row += [repr(col[j].item()) for col in cols]
            wr.writerow(row)
    return buf.getvalue()


def study_csv(study: Study, rows: List[Dict[str, Any]]) -> Dict[str, str]:
    """The ``csv = true`` output: each computed output of a study as a table (file name -> text)."""
    out: Dict[str, str] = {}
    swept = study.swept_names
    chars = [r.get("characteristics") for r in rows]
    if any(chars):
        names = [n for n in study.model.characteristics if any(c and n in c for c in chars)]
        buf = io.StringIO()
        wr = csv.writer(buf, lineterminator="\n")
        wr.writerow(["design"] + swept + names)
        for p, c in zip(study.points, chars):
            wr.writerow([p.index] + [p.swept[n] for n in swept] + [("" if c is None else c.get(n, "")) for n in names])
        out[f"{study.name}.characteristics.csv"] = buf.getvalue()
    for output, cols in (("critical_line", ("Ft", "Fn", "status")), ("linear_line", ("Ft", "Fn")),
                         ("forces", ("V", "F_par", "F_perp"))):
        if any(output in r for r in rows):
            buf = io.StringIO()
            wr = csv.writer(buf, lineterminator="\n")
            wr.writerow(["design"] + swept + list(cols))
            for p, r in zip(study.points, rows):
                if output in r:
                    d = r[output]
                    for vals in zip(*(np.asarray(d[c]) for c in cols)):
                        wr.writerow([p.index] + [p.swept[n] for n in swept] + [repr(v.item()) for v in vals])
            out[f"{study.name}.{output}.csv"] = buf.getvalue()
    if any("contact_contours" in r for r in rows):
        buf = io.StringIO()
        wr = csv.writer(buf, lineterminator="\n")
        wr.writerow(["design"] + swept + ["Fn", "Ft", "a", "status", "equilibria"])
        for p, r in zip(study.points, rows):
            if "contact_contours" in r:
                c = r["contact_contours"]
                for jt, ft in enumerate(c["Ft"]):
                    for jn, fn in enumerate(c["Fn"]):
                        wr.writerow([p.index] + [p.swept[n] for n in swept] +
                                    [repr(float(fn)), repr(float(ft)), repr(float(c["a"][jt, jn])),
                                     int(c["status"][jt, jn]), int(c["equilibria"][jt, jn])])
        out[f"{study.name}.contact_contours.csv"] = buf.getvalue()
    if any("force_trace" in r for r in rows):
        buf = io.StringIO()
        wr = csv.writer(buf, lineterminator="\n")
        wr.writerow(["design"] + swept + ["t", "d_par", "d_perp", "f_par", "f_perp"])
        for p, r in zip(study.points, rows):
            tr = r["force_trace"]
            for vals in zip(tr.t, tr.d_par, tr.d_perp, tr.f_par, tr.f_perp):
                wr.writerow([p.index] + [p.swept[n] for n in swept] + [repr(float(v)) for v in vals])
        out[f"{study.name}.force_trace.csv"] = buf.getvalue()
    out.update(ADAPTERS[study.model.name].study_csv(study, rows))
    return out


# ---- the run ------------------------------------------------------------------------------------

def run_scene(scene, out: Optional[os.PathLike] = None, *, formats: Optional[Sequence[str]] = None,
              resolution: Optional[float] = None, progress: Optional[bool] = None, cache: Optional[Cache] = None,
              threads: Optional[int] = None, draw: bool = True, stream=None) -> RunResult:
    """Validate, plan, compute and (with ``out``) write a scene.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        A TOML file, the same structure as a dict, or a loaded scene.
    out : str or os.PathLike, optional
        Folder for the CSV files and figures; without it nothing is written and matplotlib is
        never imported.
    formats : sequence of str, optional
        Figure formats added to every plot's own (e.g. ``["svg"]``).
    resolution : float, optional
        Scales the number of points of every grid.
    progress : bool, optional
        Show a progress bar; None (default) shows one only on a terminal.
    cache : Cache, optional
        Results to reuse across runs (scenes that share designs reuse each other's lines).
    threads : int, optional
        Threads for the batched kernels (default: the CPU count).
    draw : bool, optional
        Draw the figures (default True); False writes the CSV files only.
    stream : file-like, optional
        Where the progress bar goes (default stderr).

    Returns
    -------
    RunResult
        The data of every study, the curves behind every plot, the files written, the time taken.

    Raises
    ------
    SceneError
        If the scene is not valid.
    gecko._optional.MissingOptionalDependency
        If drawing needs matplotlib (or a sweep pandas) and it is not installed; the message
        names the extra to install.

    Examples
    --------
    >>> from gecko.scene import run_scene
    >>> scene = {"title": "two angles", "study": [{"name": "seta", "model": "two_level_seta",
    ...          "parameters": {"alpha2": [0.3, 0.5]}, "outputs": {"characteristics": ["fn0"]}}]}
    >>> result = run_scene(scene)
    >>> [round(d["characteristics"]["fn0"], 4) for d in result.data["seta"]]
    [2.3606, 0.4935]
    >>> result.files
    []
    """
    t0 = time.perf_counter()
    sc = load_scene(scene, resolution=resolution)
    plan = plan_scene(sc)
    if out is not None:  # before computing: an unusable folder is found out now, not after the work
        _check_out(sc, Path(out))
    cache = cache if cache is not None else Cache()
    threads = threads or min(4, os.cpu_count() or 1)
    total = sum(s.size for s in plan.steps) + (len(sc.plots) if out is not None and draw else 0)
    bar = Progress(total, Path(sc.source).stem if sc.source != "<dict>" else "scene", stream=stream,
                   enabled=progress if progress is not None else None)
    ex = _Executor(sc, cache, bar, threads)
    try:
        for step in plan.steps:
            try:
                ex.run(step)
            except SceneError as err:
                raise err.at(source=sc.source) from None
            except ValueError as exc:  # a kernel refused a design: name the study
                raise SceneError(str(exc), key=sc.study(step.study).key, source=sc.source) from None
        curves = {p.name: plot_curves(sc, p, ex.data) for p in sc.plots}
        result = RunResult(sc, plan, ex.data, curves)
        if sc.sweep is not None:
            result.sweep = _run_sweep(sc, out, threads, progress)
        if sc.optimize is not None:
            result.optimum = _run_optimize(sc)
        if out is not None:
            result.files = _write(sc, result, Path(out), formats or (), draw, bar)
    finally:
        bar.close()
    result.seconds = time.perf_counter() - t0
    return result


def _sweep_folder(sc: Scene, out: Path) -> Path:
    """Where a scene's sweep keeps its chunks while it runs (so that an interrupted run resumes);
    removed once the table is written."""
    stem = Path(sc.source).stem if sc.source != "<dict>" else "scene"
    return out / f".gecko-sweep-{stem}.{sc.sweep.name}"


def _run_sweep(sc: Scene, out: Optional[os.PathLike], threads: int, progress: Optional[bool]):
    from ..design_sweep import _sweep  # the scene warned of a deprecated output with its key when parsed
    spec = sc.sweep
    try:
        return _sweep(spec.design_table(), spec.outputs, out=None if out is None else _sweep_folder(sc, Path(out)),
                      chunk_size=spec.chunk_size, threads=threads, client=None,
                      executor=None if spec.executor == "threads" else spec.executor,
                      connect_timeout=spec.connect_timeout, errors=spec.errors, progress=progress)
    except ValueError as exc:  # a design the kernels refuse, a bad table: name the section
        raise SceneError(str(exc), key="sweep", source=sc.source) from None


def _run_optimize(sc: Scene):
    from ..optimize import optimize_from_scene
    try:
        return optimize_from_scene(dict(sc.optimize.table))
    except ValueError as exc:
        raise SceneError(str(exc), key="optimize", source=sc.source) from None


def _write_sections(sc: Scene, result: RunResult, staging: Path, formats: Sequence[str], draw: bool) -> List[str]:
    """The files of [sweep] (NAME.parquet or NAME.csv, NAME.png with [sweep.plot]) and [optimize]
    (NAME.json, NAME.csv with the optimum's critical line, NAME.png)."""
    import json
    names: List[str] = []
    if sc.sweep is not None:
        spec = sc.sweep
        if spec.format == "parquet":
            result.sweep.to_parquet(staging / f"{spec.name}.parquet", index=False)
        else:
            result.sweep.to_csv(staging / f"{spec.name}.csv", index=False, float_format="%.17g")
        names.append(f"{spec.name}.{spec.format}")
        if draw and spec.plot:
            from .render import render_sweep
            names += render_sweep(sc, result.sweep, staging, formats)
    if sc.optimize is not None:
        name = sc.optimize.name
        opt = result.optimum
        (staging / f"{name}.json").write_text(json.dumps(opt.to_dict(), indent=1, allow_nan=True) + "\n",
                                              encoding="utf-8")
        names.append(f"{name}.json")
        if opt.line is not None:
            buf = io.StringIO()
            wr = csv.writer(buf, lineterminator="\n")
            wr.writerow(["Ft", "Fn", "theta_joint"])
            for row in zip(opt.line.Ft, opt.line.Fn, opt.line.theta_joint):
                wr.writerow([repr(float(v)) for v in row])
            (staging / f"{name}.csv").write_text(buf.getvalue(), encoding="utf-8")
            names.append(f"{name}.csv")
        if draw:
            from .render import render_optimum
            names += render_optimum(sc, opt, staging, formats)
    return names


def _check_out(sc: Scene, out: Path) -> None:
    """SceneError (a bad command line or scene: exit status 2) when ``out`` cannot be created or
    written to."""
    from .._integrity import check_writable
    try:
        check_writable(str(out))
    except OSError as exc:
        raise SceneError(f"cannot write to the output folder {str(out)!r}: {exc.strerror or exc}",
                         source=sc.source) from None


def _write(sc: Scene, result: RunResult, out: Path, extra_formats, draw: bool, bar: Progress) -> List[Path]:
    _check_out(sc, out)
    from .._locking import make_staging
    staging = Path(make_staging(str(out), ".gecko-staging-"))  # also removes those of killed runs
    try:
        names: List[str] = []
        for p in sc.plots:
            (staging / f"{p.name}.csv").write_text(curves_csv(result.curves[p.name]), encoding="utf-8")
            names.append(f"{p.name}.csv")
        for st in sc.studies:
            if "csv" in st.outputs:
                for fname, text in study_csv(st, result.data[st.name]).items():
                    if sc.source != "<dict>":  # unique across scenes written to one folder
                        fname = f"{Path(sc.source).stem}.{fname}"
                    (staging / fname).write_text(text, encoding="utf-8")
                    names.append(fname)
        if draw and sc.plots:
            from .render import render_plot
            for p in sc.plots:
                fmts = list(dict.fromkeys(list(p.formats) + list(extra_formats)))
                for f in render_plot(sc, p, result.curves[p.name], staging, fmts):
                    names.append(f)
                bar.advance(1, p.name)
        names += _write_sections(sc, result, staging, list(dict.fromkeys(["png", *extra_formats])), draw)
        final = []
        for n in names:  # every file is complete: move them into place
            os.replace(staging / n, out / n)
            final.append(out / n)
        if sc.sweep is not None:  # the table is in place: its chunks are no longer needed
            from .._locking import remove_unless_locked
            remove_unless_locked(_sweep_folder(sc, out))
        return final
    finally:
        shutil.rmtree(staging, ignore_errors=True)
