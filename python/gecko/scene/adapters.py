"""Scene model adapters: each model owns its planning (which kernels its requested outputs need)
and those kernels, so the planner and the runner never branch on a model's name.

An adapter's ``plan(study)`` returns the :class:`Step` list of one study; the runner calls
``run(executor, study, step)``, which dispatches to the adapter's ``k_<kernel>`` method. The
executor supplies the shared state: ``scene``, ``cache`` (with ``cached(key, fn)``), ``data``,
``progress`` and ``threads``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Tuple

import numpy as np

from .._renamed import RENAMED
from ..seta import DESIGN_FIELDS, CriticalStatus
from .errors import SceneError
from .grids import DEFAULT_GRIDS, eval_grid
from .models import SETA_EXACT, SETA_SMALL

FIBER_FIELDS = ("EI", "EA", "l", "alpha", "w")


@dataclass
class Step:
    """One kernel applied to some designs of a study."""

    study: str
    kernel: str
    points: List[int]
    detail: str = ""
    options: Dict = field(default_factory=dict)

    @property
    def size(self) -> int:
        return len(self.points)


# ---- helpers shared by the kernels --------------------------------------------------------------

def _key(*parts) -> tuple:
    out = []
    for p in parts:
        if isinstance(p, np.ndarray):
            out.append((p.shape, p.tobytes()))
        elif isinstance(p, dict):
            out.append(tuple(sorted((k, _key(v)) for k, v in p.items())))
        elif isinstance(p, (list, tuple)):
            out.append(tuple(_key(v) for v in p))
        else:
            out.append(p)
    return tuple(out)


def _design(p) -> tuple:
    """The design alone (model parameters, not the study's free variables): the cache key."""
    key = p.__dict__.get("_design_key")
    if key is None:
        key = p.__dict__["_design_key"] = _key({k: v for k, v in p.values.items() if k in p.params})
    return key


def _seta(values):
    from ..seta import TwoLevelSeta
    return TwoLevelSeta(**{k: values[k] for k in DESIGN_FIELDS})


def _grid(study, point, output: str, res: float) -> np.ndarray:
    spec = study.outputs[output].options.get("grid") or DEFAULT_GRIDS[output]
    gkey = study.outputs[output].options.get("grid_key", "Ft")
    return eval_grid(spec, study.env(point), f"{study.key}.outputs.{output}.{gkey}", res)


def _line_starts_at_zero(st) -> bool:
    spec = st.outputs["critical_line"].options.get("grid") or DEFAULT_GRIDS["critical_line"]
    try:
        return all(eval_grid(spec, st.env(p), "", 1.0)[0] == 0.0 for p in st.points)
    except Exception:  # a bad grid is reported by the runner, with its key
        return False


def _slopes(name: str, k: float, prefix: str = "", inv: str = "") -> dict:
    """A slope of the critical line with its magnitude and inverse magnitude (the paper plots 1/|k|,
    Fig 5b): name, abs_name, inv_abs_name (or ``inv``), each after ``prefix``."""
    return {prefix + name: k, prefix + "abs_" + name: abs(k),
            (inv or prefix + "inv_abs_" + name): 1.0 / abs(k) if k != 0 else math.inf}


def _set_fn0(ex, st, i: int, value: float) -> None:
    ex.data[st.name][i].setdefault("characteristics", {})["fn0"] = value


class Adapter:
    """A scene model's planning and kernels. ``models``: the model names it serves; ``role``: how
    its curves are drawn (gecko.plot)."""

    models: Tuple[str, ...] = ()
    role: str = "line"

    def plan(self, st) -> List[Step]:
        return []

    def run(self, ex, st, step: Step) -> None:
        getattr(self, "k_" + step.kernel)(ex, st, step)

    def plot_curves(self, plot, st, rows, many: bool, Curve) -> list:
        """The curves of a plot kind this adapter draws itself (``Curve``: the runner's class)."""
        return []

    def study_csv(self, st, rows) -> Dict[str, str]:
        """Tables of the outputs this adapter writes itself (``csv = true``): file name -> text."""
        return {}

    def k_fn0_from_line(self, ex, st, step: Step) -> None:
        for i in step.points:
            _set_fn0(ex, st, i, float(ex.data[st.name][i]["critical_line"]["Fn"][0]))


# ---- the two-level seta ---------------------------------------------------------------------------

class TwoLevelSetaAdapter(Adapter):
    models = ("two_level_seta",)
    role = "seta"

    @staticmethod
    def kernel_kind(st) -> str:
        kinds = set()
        for p in st.points:
            e1, e2 = math.isinf(p.values["EA1"]), math.isinf(p.values["EA2"])
            kinds.add("inextensible" if e1 and e2 else "extensible spatula" if e1 else
                      "extensible beam" if e2 else "extensible beam and spatula")
        return ", ".join(sorted(kinds))

    def plan(self, st) -> List[Step]:
        steps: List[Step] = []
        pts = [p.index for p in st.points]
        out = st.outputs
        n = len(pts)
        kk = self.kernel_kind(st)
        if "critical_line" in out:
            steps.append(Step(st.name, "critical_line", pts,
                              f"{n} design(s) x Ft grid, one C++ batch call per grid ({kk} kernel)"))
        which = set(out["characteristics"].options["which"]) if "characteristics" in out else set()
        exact = which & set(SETA_EXACT)
        if exact == {"fn0"}:
            if "critical_line" in out and _line_starts_at_zero(st):
                steps.append(Step(st.name, "fn0_from_line", pts, "(Fn)0 read off the critical line at Ft = 0"))
            else:
                steps.append(Step(st.name, "fn0", pts,
                                  f"(Fn)0 only: one solve at Ft = 0 per design, batched ({kk} kernel); no line traced"))
        elif exact:
            steps.append(Step(st.name, "characteristics", pts,
                              f"{', '.join(sorted(exact))}: line traced by continuation in C++ ({kk} kernel)"))
        if (which & set(SETA_SMALL)) or "linear_line" in out:
            steps.append(Step(st.name, "small_deformation", pts, "closed forms, eqs 7 and 18-22 (no solver)"))
        if "shapes" in out:
            o = out["shapes"].options
            steps.append(Step(st.name, "shapes", pts,
                              f"critical states at the requested Ft, then RK4 of the elastica in C++ "
                              f"({o['points'] - 1} steps per segment)"))
        if "contact_contours" in out:
            steps.append(Step(st.name, "contact_contours", pts,
                              "the forward problem (contact length a) on the Fn x Ft grid, one C++ call per "
                              f"design ({kk} kernel)"))
        if "sensitivities" in out:
            steps.append(Step(st.name, "sensitivities", pts,
                              "dFn/d(design) by the implicit function theorem (dual numbers in C++)"))
        return steps

    def k_critical_line(self, ex, st, step: Step) -> None:
        from ..seta import critical_line_batch
        res = ex.scene.resolution
        groups: Dict[tuple, list] = {}
        grids: Dict[tuple, np.ndarray] = {}
        for i in step.points:
            p = st.points[i]
            g = _grid(st, p, "critical_line", res)
            groups.setdefault(_key(g), []).append(p)
            grids[_key(g)] = g
        for gk, pts in groups.items():
            g = grids[gk]
            todo = list({_design(p): p for p in pts if ("line", _design(p), gk) not in ex.cache}.values())
            ex.cache.hits += len(pts) - len(todo)
            if todo:
                designs = np.array([[p.values[f] for f in DESIGN_FIELDS] for p in todo])
                ex.cache.misses += len(todo)
                line = critical_line_batch(designs, g, threads=ex.threads, errors="nan")
                for j, p in enumerate(todo):
                    ex.cache[("line", _design(p), gk)] = {
                        "Ft": g, "Fn": line.Fn[j].copy(), "status": line.status[j].copy(),
                        "theta_joint": line.theta_joint[j].copy()}
            for p in pts:
                ex.data[st.name][p.index]["critical_line"] = ex.cache[("line", _design(p), gk)]
                ex.progress.advance(1, st.name)

    def k_fn0(self, ex, st, step: Step) -> None:
        from ..seta import critical_line_batch
        pts = [st.points[i] for i in step.points]
        todo = list({_design(p): p for p in pts if ("fn0", _design(p)) not in ex.cache}.values())
        ex.cache.hits += len(pts) - len(todo)
        if todo:
            designs = np.array([[p.values[f] for f in DESIGN_FIELDS] for p in todo])
            line = critical_line_batch(designs, np.zeros(1), threads=ex.threads, errors="nan")
            ex.cache.misses += len(todo)
            for j, p in enumerate(todo):
                ex.cache[("fn0", _design(p))] = float(line.Fn[j, 0])
        for p in pts:
            _set_fn0(ex, st, p.index, ex.cache[("fn0", _design(p))])
            ex.progress.advance(1, st.name)

    def k_characteristics(self, ex, st, step: Step) -> None:
        # the deprecated aliases only where asked for (they would double the columns of csv = true)
        aliases = {o: RENAMED[o] for o in st.outputs["characteristics"].options["which"] if o in RENAMED}
        for i in step.points:
            p = st.points[i]

            def fn():
                c = _seta(p.values).characteristics()
                return {"fn0": c.fn0, **_slopes("slope_at_zero", c.slope_at_zero), **_slopes("paper_k", c.paper_k),
                        "max_pull_off": c.max_pull_off, "ft_at_max_pull_off": c.ft_at_min_fn,
                        "min_fn": c.min_fn, "ft_max": c.ft_max, "sticky_at_rest": bool(c.sticky_at_rest),
                        "ft_at_line_end": c.ft_at_line_end, "fn_at_line_end": c.fn_at_line_end,
                        "line_end": c.end, "folds": list(c.folds)}
            got = ex.cached(("chars", _design(p)), fn)
            ex.data[st.name][i].setdefault("characteristics", {}).update(
                {**got, **{old: got[new] for old, new in aliases.items()}})
            ex.progress.advance(1, st.name)

    def k_small_deformation(self, ex, st, step: Step) -> None:
        res = ex.scene.resolution
        for i in step.points:
            p = st.points[i]
            d = ex.cached(("small", _design(p)), lambda: _seta(p.values).small_deformation())
            k = d["slope_k"]
            small = {"small_fn0": d["fn0"], **_slopes("slope_k", k, prefix="small_", inv="small_inv_abs_k"),
                     "small_contact_length": d["contact_length"], "small_non_sticky": bool(d["non_sticky"])}
            ex.data[st.name][i].setdefault("characteristics", {}).update(small)
            if "linear_line" in st.outputs:
                g = _grid(st, p, "linear_line", res)
                ex.data[st.name][i]["linear_line"] = {"Ft": g, "Fn": d["fn0"] + k * g}
            ex.progress.advance(1, st.name)

    def k_shapes(self, ex, st, step: Step) -> None:
        opts = st.outputs["shapes"].options
        steps = opts["points"] - 1
        for i in step.points:
            p = st.points[i]
            g = eval_grid(opts["grid"], st.env(p), f"{st.key}.outputs.shapes.Ft", 1.0)

            def fn():
                seta = _seta(p.values)
                shapes = [seta.shape(float(ft), steps) for ft in g]
                return {"Ft": g, "Fn": np.array([float(d["Fn"]) for d in shapes]),
                        "x": [np.asarray(d["x"]) for d in shapes], "z": [np.asarray(d["z"]) for d in shapes],
                        "closing_error": np.array([float(d["closing_error"]) for d in shapes]),
                        "status": np.array([int(d["status"]) for d in shapes])}
            ex.data[st.name][i]["shapes"] = ex.cached(("shapes", _design(p), _key(g), steps), fn)
            ex.progress.advance(1, st.name)

    def k_sensitivities(self, ex, st, step: Step) -> None:
        from ..seta import TwoLevelSeta
        if not hasattr(TwoLevelSeta, "sensitivities"):  # an older build of gecko
            raise SceneError("sensitivities need gecko.TwoLevelSeta.sensitivities, which this build of gecko "
                             "does not have", key=f"{st.key}.outputs.sensitivities")
        opts = st.outputs["sensitivities"].options
        for i in step.points:
            p = st.points[i]
            g = _grid(st, p, "sensitivities", ex.scene.resolution)

            def fn():
                r = _seta(p.values).sensitivities(g)
                dFn = np.asarray(r["dFn"]).reshape(g.size, len(DESIGN_FIELDS))
                names = list(r.get("parameters", DESIGN_FIELDS))
                return {"Ft": g, "dFn": {f: dFn[:, names.index(f)] for f in DESIGN_FIELDS},
                        "status": np.asarray(r["status"])}
            d = ex.cached(("sens", _design(p), _key(g)), fn)
            ex.data[st.name][i]["sensitivities"] = {"Ft": d["Ft"], "dFn": {k: d["dFn"][k] for k in opts["wrt"]}}
            ex.progress.advance(1, st.name)

    def k_contact_contours(self, ex, st, step: Step) -> None:
        opts = st.outputs["contact_contours"].options
        res = ex.scene.resolution
        for i in step.points:
            p = st.points[i]
            key = f"{st.key}.outputs.contact_contours"
            gn = eval_grid(opts["Fn"], st.env(p), f"{key}.Fn", res)
            gt = eval_grid(opts["Ft"], st.env(p), f"{key}.Ft", res)

            def fn():
                # rows: Ft, columns: Fn (one row of the contour is one Ft)
                r = _seta(p.values).contact_state(gn[None, :], gt[:, None], errors="nan", threads=ex.threads)
                return {"Fn": gn, "Ft": gt, "a": r.a, "status": r.status, "equilibria": r.equilibria}
            ex.data[st.name][i]["contact_contours"] = ex.cached(("contact", _design(p), _key(gn), _key(gt)), fn)
            ex.progress.advance(1, st.name)


# ---- the single fiber -----------------------------------------------------------------------------

class SingleFiberAdapter(Adapter):
    models = ("single_fiber",)
    role = "fiber"

    def plan(self, st) -> List[Step]:
        steps: List[Step] = []
        pts = [p.index for p in st.points]
        out = st.outputs
        if "critical_line" in out:
            steps.append(Step(st.name, "critical_line", pts, f"{len(pts)} fiber(s), C++ continuation from Ft = 0"))
        if "characteristics" in out:
            if "critical_line" in out and _line_starts_at_zero(st):
                steps.append(Step(st.name, "fn0_from_line", pts, "(Fn)0 read off the critical line at Ft = 0"))
            else:
                steps.append(Step(st.name, "fn0", pts, "(Fn)0: one solve at Ft = 0 per fiber"))
        return steps

    @staticmethod
    def _fiber(values):
        from ..seta import SingleFiber
        return SingleFiber(**{k: values[k] for k in FIBER_FIELDS})

    def k_critical_line(self, ex, st, step: Step) -> None:
        res = ex.scene.resolution
        for i in step.points:
            p = st.points[i]
            g = _grid(st, p, "critical_line", res)

            def fn():
                line = self._fiber(p.values).critical_line(g, errors="nan")
                return {"Ft": g, "Fn": line.Fn, "status": line.status}
            ex.data[st.name][i]["critical_line"] = ex.cached(("fiber_line", _design(p), _key(g)), fn)
            ex.progress.advance(1, st.name)

    def k_fn0(self, ex, st, step: Step) -> None:
        for i in step.points:
            p = st.points[i]

            def fn():
                return float(self._fiber(p.values).critical_line(np.zeros(1), errors="nan").Fn[0])
            _set_fn0(ex, st, i, ex.cached(("fiber_fn0", _design(p)), fn))
            ex.progress.advance(1, st.name)


# ---- the peel lines (closed forms, eq 17) ---------------------------------------------------------

class _PeelAdapter(Adapter):
    def plan(self, st) -> List[Step]:
        steps: List[Step] = []
        pts = [p.index for p in st.points]
        if "critical_line" in st.outputs:
            steps.append(Step(st.name, "critical_line", pts, "closed form (eq 17), vectorised"))
        if "characteristics" in st.outputs:
            steps.append(Step(st.name, "characteristics", pts,
                              "closed form (eq 17); the maximum pull-off by golden-section search"))
        return steps

    def fn(self, ft, values):
        raise NotImplementedError

    def characteristics(self, values) -> Dict[str, float]:
        raise NotImplementedError

    def k_critical_line(self, ex, st, step: Step) -> None:
        res = ex.scene.resolution
        for i in step.points:
            p = st.points[i]
            g = _grid(st, p, "critical_line", res)
            Fn = np.atleast_1d(np.asarray(self.fn(g, p.values), dtype=np.float64))
            ex.data[st.name][i]["critical_line"] = {
                "Ft": g, "Fn": Fn,
                "status": np.where(np.isfinite(Fn), CriticalStatus.converged, CriticalStatus.invalid_input)}
            ex.progress.advance(1, st.name)

    def k_characteristics(self, ex, st, step: Step) -> None:
        for i in step.points:
            p = st.points[i]
            ex.data[st.name][i].setdefault("characteristics", {}).update(
                ex.cached(("peel_chars", st.model.name, _design(p)), lambda: self.characteristics(p.values)))
            ex.progress.advance(1, st.name)


class RivlinAdapter(_PeelAdapter):
    models = ("rivlin",)
    role = "rivlin"

    def fn(self, ft, values):
        from ..seta import rivlin_fn
        return rivlin_fn(ft, values["w"], errors="nan")

    def characteristics(self, values) -> Dict[str, float]:
        from ..seta import rivlin_fn
        return {"fn0": float(rivlin_fn(0.0, values["w"]))}


class KendallAdapter(_PeelAdapter):
    models = ("kendall",)
    role = "kendall"

    def fn(self, ft, values):
        from ..seta import kendall_fn
        return kendall_fn(ft, values["EA"], values["w"], errors="nan")

    def characteristics(self, values) -> Dict[str, float]:
        from ..seta import kendall_fn
        w, EA = values["w"], values["EA"]
        ft_max = math.sqrt(2 * EA * w)
        out = {"fn0": float(kendall_fn(0.0, EA, w)), "ft_max": ft_max}
        if not math.isfinite(ft_max):
            out.update(max_pull_off=math.inf, ft_at_max_pull_off=math.inf)
            return out
        # Fn(Ft) is smooth and unimodal on [0, ft_max]: bracket on a grid, then golden section.
        g = np.linspace(0.0, ft_max, 257)
        fn = np.asarray(kendall_fn(g, EA, w))
        j = int(np.argmin(fn))
        a, b = g[max(j - 1, 0)], g[min(j + 1, g.size - 1)]
        r = (math.sqrt(5) - 1) / 2
        c, d = b - r * (b - a), a + r * (b - a)
        fc, fd = float(kendall_fn(c, EA, w)), float(kendall_fn(d, EA, w))
        for _ in range(100):
            if b - a <= 1e-14 * max(1.0, abs(b)):
                break
            if fc < fd:
                b, d, fd = d, c, fc
                c = b - r * (b - a)
                fc = float(kendall_fn(c, EA, w))
            else:
                a, c, fc = c, d, fd
                d = a + r * (b - a)
                fd = float(kendall_fn(d, EA, w))
        ft = 0.5 * (a + b)
        out.update(max_pull_off=-float(kendall_fn(ft, EA, w)), ft_at_max_pull_off=ft)
        return out


# ---- frictional adhesion --------------------------------------------------------------------------

class ForceTraceAdapter(Adapter):
    models = ("spatula", "seta_force_space")

    def plan(self, st) -> List[Step]:
        if "force_trace" not in st.outputs:
            return []
        return [Step(st.name, "force_trace", [p.index for p in st.points], "f = K d(t) along the path (C++)")]

    def k_force_trace(self, ex, st, step: Step) -> None:
        from ..friction import force_trace
        sps = st.outputs["force_trace"].options["samples_per_segment"]
        sps = max(1, int(round(sps * ex.scene.resolution)))
        for i in step.points:
            p = st.points[i]
            ex.data[st.name][i]["force_trace"] = force_trace(np.array(p.values["K"]), p.values["path"],
                                                             samples_per_segment=sps)
            ex.progress.advance(1, st.name)


def sliding_model(v):
    """The gecko.SlidingModel of a design with the steady_sliding model's parameters (the law by
    name or as an expression: gecko.scene.sliding_fit)."""
    from .sliding_fit import sliding_model as model
    return model(v)


class SteadySlidingAdapter(Adapter):
    models = ("steady_sliding",)

    def plan(self, st) -> List[Step]:
        if "forces" not in st.outputs:
            return []
        return [Step(st.name, "forces", [p.index for p in st.points], "eqs 5-10 with the detachment law in C++")]

    def k_forces(self, ex, st, step: Step) -> None:
        from ..friction import steady_sliding
        for i in step.points:
            p = st.points[i]
            v = p.values
            model = sliding_model(v)
            V = _grid(st, p, "forces", ex.scene.resolution)
            r = steady_sliding(V, model, t_off=v["t_off"])
            ex.data[st.name][i]["forces"] = {"V": V, "F_par": np.atleast_1d(r.F_par),
                                             "F_perp": np.atleast_1d(r.F_perp)}
            ex.progress.advance(1, st.name)


class SlidingFitAdapter(Adapter):
    """Measured forces fitted by eqs 9-10 (the work is in gecko.scene.sliding_fit)."""
    models = ("sliding_fit",)

    def plan(self, st) -> List[Step]:
        if "fit" not in st.outputs:
            return []
        return [Step(st.name, "fit", [p.index for p in st.points], "Levenberg-Marquardt fit of eqs 9-10 (C++)")]

    def k_fit(self, ex, st, step: Step) -> None:
        from .sliding_fit import run_fit
        for i in step.points:
            ex.data[st.name][i]["fit"] = run_fit(st.points[i].values, st.outputs["fit"].options)
            ex.progress.advance(1, st.name)

    def plot_curves(self, plot, st, rows, many: bool, Curve) -> list:
        from .sliding_fit import fit_curves
        return [Curve(**kw) for kw in fit_curves(st, rows, many)] if plot.kind == "sliding_fit" else []

    def study_csv(self, st, rows) -> Dict[str, str]:
        from .sliding_fit import fit_csv
        return fit_csv(st, rows)


#: model name -> its adapter (every model of gecko.scene.models.MODELS has one)
ADAPTERS: Dict[str, Adapter] = {name: a for a in (TwoLevelSetaAdapter(), SingleFiberAdapter(), KendallAdapter(),
                                                  RivlinAdapter(), ForceTraceAdapter(), SteadySlidingAdapter(),
                                                  SlidingFitAdapter())
                                for name in a.models}


def adapter(model_name: str) -> Adapter:
    return ADAPTERS[model_name]


__all__ = ["Adapter", "ADAPTERS", "Step", "adapter"]
