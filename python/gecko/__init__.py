"""gecko — mechanics of gecko-like adhesion.

Compiled kernels (the C++ header-only library, built here as ``gecko._core``), wrapped per concern:

* ``gecko.elliptic``: ``ellint_f``, ``ellint_e``, ``ellint_k``, ``ellint_ek`` and the Carlson
  symmetric forms ``carlson_rf``, ``carlson_rd``, ``carlson_rj``, ``carlson_rc``; all broadcast
  like numpy ufuncs and raise ``ValueError`` on a domain error (or give NaN with ``errors="nan"``).
* ``gecko.seta``: ``TwoLevelSeta`` and its exact critical line of adhesion, ``SingleFiber``,
  the Kendall and Rivlin peel lines, small-deformation formulas (docs/theory/two_level_seta.md).
* ``gecko.friction``: curved-beam rigidity, force traces, detachment laws, steady sliding,
  spatula simulation and fitting (docs/theory/frictional_adhesion.md).
* ``gecko.scene``: declarative scenes (TOML or dict) that compute only what they ask for.
  Plotting lives in ``gecko.plot`` and is not imported here (it imports matplotlib).

Each concern lists its public names in its own ``__all__``.
"""
from ._core import __version__
from . import elliptic as _elliptic
from .elliptic import *  # noqa: F401,F403
from . import seta as _seta
from .seta import *  # noqa: F401,F403
from . import friction as _friction
from .friction import *  # noqa: F401,F403
from .scene import SceneError, load_scene, run_scene, validate_scene
from . import design_sweep as _design_sweep
from .design_sweep import *  # noqa: F401,F403
from . import optimize as _optimize
from .optimize import *  # noqa: F401,F403

__all__ = ["__version__", *_elliptic.__all__, *_seta.__all__, *_friction.__all__,
           *_design_sweep.__all__, *_optimize.__all__,
           "SceneError", "load_scene", "run_scene", "validate_scene"]
