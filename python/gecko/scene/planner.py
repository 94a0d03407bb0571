"""Plan a scene: pick the kernels from the requested outputs, and only those. Each model's adapter
(gecko.scene.adapters) plans its own studies; for the two-level seta:

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

from dataclasses import dataclass
from typing import List

from .adapters import ADAPTERS, Step
from .schema import Scene


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


def plan_scene(scene: Scene) -> Plan:
    """Decide which kernels a scene needs, from the outputs it asks for, and nothing more: every
    model's adapter (:mod:`gecko.scene.adapters`) plans its own studies.

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
        steps.extend(ADAPTERS[st.model.name].plan(st))
    return Plan(scene, steps)
