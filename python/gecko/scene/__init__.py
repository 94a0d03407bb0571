"""gecko.scene — declarative studies: a model, its parameters (values or sweeps), the outputs.

    from gecko.scene import run_scene
    result = run_scene("examples/seta_fig2a_axial_stiffness.toml", out="figures/")
    result.curves["seta_fig2a"]     # the data behind the figure
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
from . import hierarchy as _hierarchy  # noqa: F401,E402  (registers the hierarchy models)

__all__ = ["SceneError", "Scene", "load_scene", "validate_scene", "Plan", "plan_scene", "run_scene",
           "RunResult", "Curve", "Cache", "MODELS", "figure_scenes", "FIGURES_DIR"]

#: the paper figures as scenes (the same files as the repository's examples/ folder)
FIGURES_DIR = Path(__file__).resolve().parent / "figures"


def validate_scene(scene, *, resolution=None) -> Scene:
    """Load and check a scene: every key, type and range, every sweep and grid.

    Parameters
    ----------
    scene : str, os.PathLike, dict or Scene
        A TOML file, or the same structure as a dict.
    resolution : float, optional
        Scales the number of points of every grid (overrides the file's ``resolution``).

    Returns
    -------
    Scene
        The validated scene; nothing is computed.

    Raises
    ------
    SceneError
        If the file cannot be read or parsed, or a key, type or value is not allowed; the message
        names the file, the key path and the allowed range.

    Examples
    --------
    >>> scene = {"title": "two angles", "study": [{"name": "seta", "model": "two_level_seta",
    ...          "parameters": {"alpha2": [0.3, 0.5]}, "outputs": {"characteristics": ["fn0"]}}]}
    >>> validate_scene(scene).studies[0].name
    'seta'
    >>> validate_scene({"study": [{"name": "s", "model": "two_level_seta",
    ...                             "parameters": {"EI1": -1}}]})
    Traceback (most recent call last):
    ...
    gecko.scene.errors.SceneError: <dict>: study[0].parameters.EI1: EI1 = -1 is out of range: need 0 < value < inf
    """
    return load_scene(scene, resolution=resolution)


def figure_scenes():
    """Paths of the packaged paper-figure scenes, sorted by name.

    The same files are in the repository's ``examples/`` folder; ``gecko figures --out DIR``
    renders them all.

    Returns
    -------
    list of pathlib.Path
        One TOML file per figure (and a few studies beyond the papers).

    Examples
    --------
    >>> from gecko.scene import figure_scenes
    >>> [p.name for p in figure_scenes()][:2]
    ['demo_reference_critical_line.toml', 'friction_fig4_spatula_force_trace.toml']
    """
    return sorted(FIGURES_DIR.glob("*.toml"))
