"""gecko.design_optimize — deprecated alias of :mod:`gecko.optimize` (the optimiser now lives in the
package ``gecko.optimize``: objectives, space, problem, kkt, driver). Every old name, public and
private, is re-exported from here unchanged."""
from __future__ import annotations

import warnings

from .optimize import __all__  # noqa: F401
from .optimize.driver import (SetaOptimum, _jsonable, optimize_from_scene, optimize_seta,  # noqa: F401
                              _SCENE_KEYS)
from .optimize.kkt import (_ACTIVE_TOL, _BOUND_TOL, _KKT_TARGET, _KKT_TOL, _POLISH_ROUNDS,  # noqa: F401
                           _kkt, _kkt_at)
from .optimize.objectives import (FIELDS, OBJECTIVES, _FORCE_LIKE, _GOOD_ENDS, _INDEX,  # noqa: F401
                                  _OBJECTIVE_FUNCS, _STATIONARY, Objective, _area, _check_line_end,
                                  _design_seta, _dftmax, _EvaluationFailure, _finite_user_value, _gauss,
                                  _max_pull_off, _pull_off_at, _refine_minimum, _sens, _slope,
                                  seta_objective)
from .optimize.problem import Constraint, _parse_constraints, _Problem  # noqa: F401
from .optimize.space import (_ANGLE_MARGIN, _ANGLES, _DERIVED, _DOMAIN, _HALF_PI, _Space,  # noqa: F401
                             _base_dict)

warnings.warn("gecko.design_optimize is deprecated: import from gecko.optimize (or gecko) instead",
              DeprecationWarning, stacklevel=2)
