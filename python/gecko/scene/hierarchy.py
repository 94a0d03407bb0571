"""Scene models of the hierarchy in paper 000's Discussion (gecko.friction_hierarchy): spatula
populations and spatulae on a compliant seta. Registers its models, outputs, plot kinds, adapter
and renderers with the scene package on import (gecko.scene imports it).

Models (the steady_sliding parameters, Fig 6 presets included, plus):

* ``spatula_population``: ``V``, a ``distribution`` ("lognormal" or "uniform", mean 1) of the
  factors on length, stiffness and G0 with widths ``length_width``, ``stiffness_width``,
  ``G0_width`` (sigma, or half-width h), ``spatulae``, ``periods``, ``resticking``, ``seed``.
  Output ``population``: the simulated mean forces beside eqs 9-10 at the mean parameters,
  averaged over the spatulae and over the distribution. Plot kind ``spatula_population``: those
  against the study's first swept parameter.
* ``compliant_seta``: the same plus ``stiffness_ratio`` (k_s over N K_par_par) and
  ``threshold``. Output ``seta``: the force trace and the classification. Plot kinds
  ``seta_trace`` (force against time) and ``stick_slip_map`` (largest slip's relative force drop
  against the stiffness ratio, a curve per value of the other swept names).
"""
from __future__ import annotations

import csv
import io
from typing import Dict, List

import numpy as np

from . import render, schema
from .adapters import ADAPTERS, Adapter, Step, sliding_model
from .errors import SceneError
from .models import MODELS, OUTPUT_PARSERS, Model, OutputSpec, Param, _add, _bool_or_table, _positive


def _width(v):
    return None if 0 <= v < 1 else "need 0 <= width < 1 (lognormal: sigma; uniform: half-width h)"


def _count(v):
    return None if v == int(v) and 1 <= v <= 1e6 else "need an integer in [1, 1e6]"


def _seed(v):
    return None if v == int(v) and 0 <= v < 2 ** 53 else "need an integer in [0, 2^53)"


def _threshold(v):
    return None if 0 < v < 1 else "need 0 < threshold < 1"


_SLIDING = MODELS["steady_sliding"].params
_POPULATION = (
    Param("V", 1e-4, "drag (stage) velocity (m/s)", check=_positive, symbol="V"),
    Param("distribution", "lognormal", "distribution of the factors, mean 1", kind="choice",
          choices=("lognormal", "uniform"), symbol="distribution"),
    Param("length_width", 0.0, "width of the spatula-length factor", check=_width, symbol="σ_L"),
    Param("stiffness_width", 0.0, "width of the stiffness factor", check=_width, symbol="σ_K"),
    Param("G0_width", 0.0, "width of the G0 factor", check=_width, symbol="σ_G0"),
    Param("spatulae", 400.0, "simulated spatulae M", check=_count, symbol="M"),
    Param("periods", 30.0, "simulated time in spatula cycles t_on + t_off", check=_positive, symbol="periods"),
    Param("resticking", "fixed", "re-sticking time: fixed or exponential", kind="choice",
          choices=("fixed", "exponential"), symbol="re-sticking"),
    Param("seed", 1.0, "random seed", check=_seed, symbol="seed"),
)

_add(Model(
    "spatula_population", "spatula population", _SLIDING + _POPULATION, ("population", "csv"),
    "Spatulae of different length, stiffness and G0 against eqs 9-10 (paper 000; "
    "docs/theory/frictional_adhesion.md, Spatula populations); SI units."))
_add(Model(
    "compliant_seta", "spatulae on a compliant seta",
    _SLIDING + _POPULATION + (
        Param("stiffness_ratio", 1.0, "spring stiffness k_s over the collective N K_par_par", check=_positive,
              symbol="k_s/(N K∥∥)"),
        Param("threshold", 0.1, "relative force drop of a seta-level slip", check=_threshold, symbol="threshold")),
    ("seta", "csv"),
    "A seta dragged through a spring: smooth sliding or seta-level stick-slip (paper 000 Discussion; "
    "docs/theory/frictional_adhesion.md, Spatulae on a compliant seta); SI units."))


def _parse_flag(model, name, value, key):
    table = _bool_or_table(value, key, [])
    return None if table is None else OutputSpec(name, {})


OUTPUT_PARSERS["population"] = _parse_flag
OUTPUT_PARSERS["seta"] = _parse_flag
schema.PLOT_KINDS.update({"spatula_population": ("population",), "seta_trace": ("seta",),
                          "stick_slip_map": ("seta",)})


def _specs(v) -> Dict:
    key = "sigma" if v["distribution"] == "lognormal" else "width"
    return {f: ({"dist": v["distribution"], key: v[f"{f}_width"]} if v[f"{f}_width"] > 0 else None)
            for f in ("length", "stiffness", "G0")}


def _t_on_plus_off(model, v) -> float:
    from ..friction import steady_sliding
    return float(steady_sliding(v["V"], model, t_off=v["t_off"]).t_on) + v["t_off"]


class PopulationAdapter(Adapter):
    models = ("spatula_population",)

    def plan(self, st) -> List[Step]:
        if "population" not in st.outputs:
            return []
        return [Step(st.name, "population", [p.index for p in st.points],
                     "event-driven simulation of the spatulae in C++, eqs 9-10 per spatula and by quadrature")]

    def k_population(self, ex, st, step: Step) -> None:
        from ..friction_hierarchy import spatula_population
        for i in step.points:
            v = st.points[i].values

            def fn(v=v):
                model = sliding_model(v)
                r = spatula_population(v["V"], model, spatulae=int(v["spatulae"]),
                                       duration=v["periods"] * _t_on_plus_off(model, v), t_off=v["t_off"],
                                       resticking=v["resticking"], seed=int(v["seed"]), **_specs(v))
                return {k: getattr(r, k) for k in (
                    "mean_par", "mean_perp", "population_par", "population_perp", "mean_field_par",
                    "mean_field_perp", "expected_par", "expected_perp", "bound_par", "bound_perp")}
            ex.data[st.name][i]["population"] = ex.cached(("population", _key_of(v)), fn)
            ex.progress.advance(1, st.name)

    def plot_curves(self, plot, st, rows, many, Curve) -> list:
        if plot.kind != "spatula_population":
            return []
        x_name = st.swept_names[0] if st.swept_names else None
        x = np.array([float(p.swept[x_name]) if x_name else float(p.index) for p in st.points])
        order = np.argsort(x, kind="stable")
        pre = f"{st.label or st.name}: " if many or len(plot.studies) > 1 else ""
        out = []
        for panel, comp in enumerate(("par", "perp")):
            for role, what in (("simulated", "mean"), ("population", "population"),
                               ("mean_field", "mean_field"), ("expected", "expected")):
                y = np.array([rows[p.index]["population"][f"{what}_{comp}"] for p in st.points])
                bound = np.array([rows[p.index]["population"][f"bound_{comp}"] for p in st.points])
                out.append(Curve(st.name, pre + role.replace("_", " "), x[order], y[order], x_name or "design",
                                 f"F_{comp}", role, panel=panel, meta={"bound": bound[order]}))
        return out

    def study_csv(self, st, rows) -> Dict[str, str]:
        if not any("population" in r for r in rows):
            return {}
        cols = ("mean_par", "mean_perp", "population_par", "population_perp", "mean_field_par", "mean_field_perp",
                "expected_par", "expected_perp", "bound_par", "bound_perp")
        return {f"{st.name}.population.csv": _table(st, rows, "population", cols)}


class CompliantSetaAdapter(Adapter):
    models = ("compliant_seta",)

    def plan(self, st) -> List[Step]:
        if "seta" not in st.outputs:
            return []
        return [Step(st.name, "seta", [p.index for p in st.points],
                     "mass-less seta on a spring, slips resolved event by event in C++; classified from the trace")]

    def k_seta(self, ex, st, step: Step) -> None:
        from ..friction_hierarchy import compliant_seta
        for i in step.points:
            v = st.points[i].values

            def fn(v=v):
                try:
                    r = compliant_seta(v["V"], sliding_model(v), stiffness_ratio=v["stiffness_ratio"],
                                       spatulae=int(v["spatulae"]), periods=v["periods"], t_off=v["t_off"],
                                       resticking=v["resticking"], seed=int(v["seed"]),
                                       threshold=v["threshold"], samples=1000, **_specs(v))
                except ValueError as exc:
                    raise SceneError(str(exc), key=f"{st.key}.parameters") from None
                d = r._asdict()
                d["stick_slip"] = r.regime == "stick-slip"
                return d
            ex.data[st.name][i]["seta"] = ex.cached(("seta", _key_of(v)), fn)
            ex.progress.advance(1, st.name)

    def plot_curves(self, plot, st, rows, many, Curve) -> list:
        out = []
        if plot.kind == "seta_trace":
            for p in st.points:
                s = rows[p.index]["seta"]
                lab = ", ".join([st.label or st.name] + [f"{schema._symbol(st.model, n)} = {schema._fmt(n, p.swept[n])}"
                                                         for n in st.swept_names])
                out.append(Curve(st.name, f"{lab}: {s['regime']}", s["t"], s["F_par"], "t", "F_par", "seta_trace",
                                 meta={"regime": s["regime"]}))
        elif plot.kind == "stick_slip_map":
            if "stiffness_ratio" not in st.swept_names:
                raise SceneError("a stick_slip_map plot needs stiffness_ratio swept in study "
                                 f"{st.name!r}", key=f"{plot.key}.studies")
            others = [n for n in st.swept_names if n != "stiffness_ratio"]
            groups: Dict[tuple, list] = {}
            for p in st.points:
                groups.setdefault(tuple(repr(p.swept[n]) for n in others), []).append(p)
            for pts in groups.values():
                pts = sorted(pts, key=lambda p: p.swept["stiffness_ratio"])
                x = np.array([p.swept["stiffness_ratio"] for p in pts], dtype=float)
                y = np.array([rows[p.index]["seta"]["relative_drop"] for p in pts])
                ss = np.array([rows[p.index]["seta"]["stick_slip"] for p in pts])
                lab = ", ".join(f"{schema._symbol(st.model, n)} = {schema._fmt(n, pts[0].swept[n])}" for n in others)
                out.append(Curve(st.name, lab or st.name, x, y, "stiffness_ratio", "relative_drop", "stick_slip_map",
                                 meta={"stick_slip": ss, "threshold": float(pts[0].values["threshold"]),
                                       "columns": {"stick_slip": ss.astype(int)}}))
        return out

    def study_csv(self, st, rows) -> Dict[str, str]:
        if not any("seta" in r for r in rows):
            return {}
        cols = ("stiffness_ratio", "spring", "mean_par", "mean_perp", "std_par", "std_perp", "max_drop",
                "relative_drop", "granularity", "max_slip_fraction", "regime", "detachments", "slips", "duration")
        out = {f"{st.name}.seta.csv": _table(st, rows, "seta", [c for c in cols if c not in st.swept_names])}
        buf = io.StringIO()
        wr = csv.writer(buf, lineterminator="\n")
        wr.writerow(["design"] + st.swept_names + ["t", "lag", "F_par", "F_perp"])
        for p, r in zip(st.points, rows):
            s = r["seta"]
            for vals in zip(s["t"], s["lag"], s["F_par"], s["F_perp"]):
                wr.writerow([p.index] + [p.swept[n] for n in st.swept_names] + [repr(float(v)) for v in vals])
        out[f"{st.name}.seta_trace.csv"] = buf.getvalue()
        return out


def _key_of(v) -> tuple:
    return tuple(sorted((k, repr(x)) for k, x in v.items()))


def _table(st, rows, output: str, cols) -> str:
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(["design"] + st.swept_names + list(cols))
    for p, r in zip(st.points, rows):
        d = r[output]
        wr.writerow([p.index] + [p.swept[n] for n in st.swept_names]
                    + [repr(float(d[c])) if isinstance(d[c], (float, int, np.floating)) else d[c] for c in cols])
    return buf.getvalue()


for _a in (PopulationAdapter(), CompliantSetaAdapter()):
    for _m in _a.models:
        ADAPTERS[_m] = _a


# ---- renderers ------------------------------------------------------------------------------------

def _render_population(fig, plot, curves):
    from .. import plot as gp
    axes = fig.subplots(1, 2)
    by: Dict[tuple, Dict[str, object]] = {}
    for c in curves:
        by.setdefault((c.study, c.panel), {})[c.role] = c
    for (study, panel), d in by.items():
        sim = d["simulated"]
        gp.population_forces(axes[panel], sim.x, sim.y, d["population"].y, d["mean_field"].y, d["expected"].y,
                             bound=sim.meta["bound"], label=study if len(plot.studies) > 1 else None,
                             xlabel=_axis_label(sim.xname))
    axes[0].set_ylabel(r"shear force $\bar F_\parallel$ (N)")
    axes[1].set_ylabel(r"normal force $\bar F_\perp$ (N)")
    return axes


def _axis_label(name: str) -> str:
    model = MODELS["spatula_population"]
    p = model.param(name)
    return f"{p.symbol} ({p.doc})" if p else name


def _render_trace(fig, plot, curves):
    """One panel per design, stacked: their time scales differ (a soft spring loads slowly)."""
    from .. import plot as gp
    if "size" not in plot.options:
        fig.set_size_inches(6.4, 1.2 + 1.9 * len(curves))
    axes = fig.subplots(len(curves), 1, squeeze=False)[:, 0]
    for i, (ax, c) in enumerate(zip(axes, curves)):
        gp.compliant_seta_trace(ax, c.x, c.y, label=c.label, color=f"C{i}")
        ax.set_ylabel("force (N)")
    return list(axes)


def _render_map(fig, plot, curves):
    from .. import plot as gp
    ax = fig.add_subplot(1, 1, 1)
    for i, c in enumerate(curves):
        gp.stick_slip_map(ax, c.x, np.maximum(c.y, 1e-6), c.meta["stick_slip"],
                          threshold=c.meta["threshold"] if i == 0 else None, label=c.label, color=f"C{i}")
    ax.set_title("filled: seta-level stick-slip; open: smooth sliding", fontsize="small")
    return [ax]


render.PLOT_RENDERERS.update({"spatula_population": (_render_population, (10.0, 4.2)),
                              "seta_trace": (_render_trace, (6.4, 4.8)), "stick_slip_map": (_render_map, (6.4, 4.8))})

__all__ = ["PopulationAdapter", "CompliantSetaAdapter"]
