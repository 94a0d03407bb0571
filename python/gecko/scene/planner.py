"""Plan a scene: pick the kernels from the requested outputs, and only those.

* critical lines of a sweep go to one multithreaded C++ batch call per Ft grid;
* (Fn)0 alone costs one solve at Ft = 0 per design (no line is traced); with a critical line
  that starts at Ft = 0 it is read off the line's first point;
* the other exact characteristics trace the line in C++ (``TwoLevelSeta.characteristics``);
  the small-deformation ones are closed forms (eqs 7, 18-22) and never touch the solver;
* deformed shapes are integrated only when asked for, and only at the requested Ft;
* EA1 = EA2 = inf selects the inextensible kernel in C++ (compile-time dispatch on the design);
* results are cached by (kernel, design, grid), so a design that recurs in a sweep, or in
  another scene run with the same cache (``gecko figures``), is computed once.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List

from .models import SETA_EXACT, SETA_SMALL
from .schema import Scene, Study


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


@dataclass
class Plan:
    """What a scene will compute: the scene and its steps (:func:`plan_scene`).

    Attributes
    ----------
    scene : Scene
        The scene planned.
    steps : list of Step
        One kernel applied to some designs of a study each, in order.

    Examples
    --------
    >>> from gecko.scene import load_scene, plan_scene
    >>> plan = plan_scene(load_scene({"study": [{"name": "k", "model": "kendall",
    ...                                           "outputs": {"characteristics": True}}]}))
    >>> print(plan.describe())  # doctest: +ELLIPSIS
    scene: <dict>  (resolution 1)
      study 'k': kendall, 1 design(s)
        - ...
      no plots: matplotlib is not imported
    """
    scene: Scene
    steps: List[Step]

    def kernels(self, study: str) -> List[str]:
        return [s.kernel for s in self.steps if s.study == study]

    @property
    def needs_matplotlib(self) -> bool:
        sw = self.scene.sweep
        return bool(self.scene.plots) or bool(sw is not None and sw.plot) or self.scene.optimize is not None

    def describe(self) -> str:
        lines = [f"scene: {self.scene.title or self.scene.source}  (resolution {self.scene.resolution:g})"]
        for st in self.scene.studies:
            lines.append(f"  study {st.name!r}: {st.model.name}, {len(st.points)} design(s)"
                         + (f", sweeping {', '.join(st.swept_names)} ({st.combine})" if st.swept_names else ""))
            for s in self.steps:
                if s.study == st.name:
                    lines.append(f"    - {s.kernel}: {s.detail}")
        for p in self.scene.plots:
            lines.append(f"  plot {p.name!r}: {p.kind} of {', '.join(p.studies)} -> "
                         + ", ".join(f"{p.name}.{f}" for f in p.formats) + f", {p.name}.csv")
        for section in (self.scene.sweep, self.scene.optimize):
            if section is not None:
                lines.append("  " + section.describe())
        if not self.scene.plots and not (self.scene.sweep and self.scene.sweep.plot) and not self.scene.optimize:
            lines.append("  no plots: matplotlib is not imported")
        return "\n".join(lines)


def _kernel_kind(study: Study) -> str:
    if study.model.name != "two_level_seta":
        return ""
    kinds = set()
    for p in study.points:
        e1, e2 = math.isinf(p.values["EA1"]), math.isinf(p.values["EA2"])
        kinds.add("inextensible" if e1 and e2 else "extensible spatula" if e1 else
                  "extensible beam" if e2 else "extensible beam and spatula")
    return ", ".join(sorted(kinds))


def plan_scene(scene: Scene) -> Plan:
    """Decide which kernels a scene needs, from the outputs it asks for, and nothing more.

    No shapes unless shapes are asked for, no critical line when only (Fn)0 is, the inextensible
    kernel when EA is infinite; :meth:`Plan.describe` says what was chosen and why.

    Parameters
    ----------
    scene : Scene
        A validated scene (:func:`gecko.scene.load_scene`).

    Returns
    -------
    Plan
        The steps, one kernel applied to some designs of a study each.

    Examples
    --------
    >>> from gecko.scene import load_scene, plan_scene
    >>> scene = {"title": "two angles", "study": [{"name": "seta", "model": "two_level_seta",
    ...          "parameters": {"alpha2": [0.3, 0.5]}, "outputs": {"characteristics": ["fn0"]}}]}
    >>> plan = plan_scene(load_scene(scene))
    >>> plan.kernels("seta"), plan.needs_matplotlib
    (['fn0'], False)
    """
    steps: List[Step] = []
    for st in scene.studies:
        pts = [p.index for p in st.points]
        out = st.outputs
        m = st.model.name
        n = len(pts)
        if m == "two_level_seta":
            kk = _kernel_kind(st)
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
        elif m == "single_fiber":
            if "critical_line" in out:
                steps.append(Step(st.name, "critical_line", pts, f"{n} fiber(s), C++ continuation from Ft = 0"))
            if "characteristics" in out:
                if "critical_line" in out and _line_starts_at_zero(st):
                    steps.append(Step(st.name, "fn0_from_line", pts, "(Fn)0 read off the critical line at Ft = 0"))
                else:
                    steps.append(Step(st.name, "fn0", pts, "(Fn)0: one solve at Ft = 0 per fiber"))
        elif m in ("kendall", "rivlin"):
            if "critical_line" in out:
                steps.append(Step(st.name, "critical_line", pts, "closed form (eq 17), vectorised"))
            if "characteristics" in out:
                steps.append(Step(st.name, "characteristics", pts,
                                  "closed form (eq 17); the maximum pull-off by golden-section search"))
        elif m in ("spatula", "seta_force_space"):
            if "force_trace" in out:
                steps.append(Step(st.name, "force_trace", pts, "f = K d(t) along the path (C++)"))
        elif m == "steady_sliding":
            if "forces" in out:
                steps.append(Step(st.name, "forces", pts, "eqs 5-10 with the detachment law in C++"))
    return Plan(scene, steps)


def _line_starts_at_zero(st: Study) -> bool:
    from .schema import eval_grid, DEFAULT_GRIDS
    spec = st.outputs["critical_line"].options.get("grid") or DEFAULT_GRIDS["critical_line"]
    try:
        return all(eval_grid(spec, st.env(p), "", 1.0)[0] == 0.0 for p in st.points)
    except Exception:  # a bad grid is reported by the runner, with its key
        return False
