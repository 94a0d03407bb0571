"""gecko.scene — declarative studies: a model, its parameters (values or sweeps), the outputs.

    from gecko.scene import run_scene
    result = run_scene("examples/fig2a_axial_stiffness.toml", out="figures/")
    result.curves["fig2a"]          # the data behind the figure
    result.plan.describe()          # which kernels ran, and why

Scenes are TOML files or the same structure as a dict; ``examples/README.md`` is the reference.
The planner computes only what the outputs ask for; matplotlib is imported only to draw.
"""
from __future__ import annotations

from pathlib import Path

from .errors import SceneError
from .models import MODELS
from .planner import Plan, plan_scene
from .runner import Cache, Curve, RunResult, run_scene
from .schema import Scene, load_scene

__all__ = ["SceneError", "Scene", "load_scene", "validate_scene", "Plan", "plan_scene", "run_scene",
           "RunResult", "Curve", "Cache", "MODELS", "figure_scenes", "FIGURES_DIR"]

#: the paper figures as scenes (the same files as the repository's examples/ folder)
FIGURES_DIR = Path(__file__).resolve().parent / "figures"


def validate_scene(scene, *, resolution=None) -> Scene:
    """Load and check a scene (every key, type and range, every sweep and grid); raises SceneError."""
    return load_scene(scene, resolution=resolution)


def figure_scenes():
    """Paths of the packaged paper-figure scenes, sorted by name."""
    return sorted(FIGURES_DIR.glob("*.toml"))
