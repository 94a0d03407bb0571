# Type stub of the compiled module gecko._core (private; use the gecko package).
# Each concern has its own section; array arguments are flat, contiguous float64 arrays of equal
# length, and `errors` is 0 (raise ValueError) or 1 (NaN).
import numpy as np
import numpy.typing as npt

__version__: str

_F64 = npt.NDArray[np.float64]

# ---- elliptic (src/bindings/elliptic.cpp) -------------------------------------------------
def ellint_f(phi: _F64, m: _F64, errors: int = 0) -> _F64: ...
def ellint_e(phi: _F64, m: _F64, errors: int = 0) -> _F64: ...
def ellint_k(m: _F64, errors: int = 0) -> _F64: ...
def ellint_ek(m: _F64, errors: int = 0) -> tuple[_F64, _F64]: ...
def carlson_rf(x: _F64, y: _F64, z: _F64, errors: int = 0) -> _F64: ...
def carlson_rd(x: _F64, y: _F64, z: _F64, errors: int = 0) -> _F64: ...
def carlson_rj(x: _F64, y: _F64, z: _F64, p: _F64, errors: int = 0) -> _F64: ...
def carlson_rc(x: _F64, y: _F64, errors: int = 0) -> _F64: ...

# ---- elliptic ufuncs (src/bindings/elliptic_ufuncs.cpp) ------------------------------------
# ufuncs.ellint_f, ufuncs.ellint_e, ufuncs.ellint_k, ufuncs.carlson_rf, ufuncs.carlson_rd,
# ufuncs.carlson_rj, ufuncs.carlson_rc, ufuncs.ellint_ek (two outputs, E and K): numpy ufuncs
# (float32 and float64 loops, NaN outside the domain). The scalar functions raise ValueError (errors = 0) or return NaN (errors = 1).
class ufuncs:
    ellint_f: np.ufunc
    ellint_e: np.ufunc
    ellint_k: np.ufunc
    carlson_rf: np.ufunc
    carlson_rd: np.ufunc
    carlson_rj: np.ufunc
    carlson_rc: np.ufunc
    ellint_ek: np.ufunc
def ellint_f_scalar(phi: float, m: float, errors: int) -> float: ...
def ellint_e_scalar(phi: float, m: float, errors: int) -> float: ...
def ellint_k_scalar(m: float, errors: int) -> float: ...
def carlson_rf_scalar(x: float, y: float, z: float, errors: int) -> float: ...
def carlson_rd_scalar(x: float, y: float, z: float, errors: int) -> float: ...
def carlson_rj_scalar(x: float, y: float, z: float, p: float, errors: int) -> float: ...
def carlson_rc_scalar(x: float, y: float, errors: int) -> float: ...
def set_ufunc_threads(threads: int) -> int: ...
# <name>_fast: as <name>_scalar for float, int and numpy float64 scalars (a float); a numpy float64
# when an argument is a 0-d float64 array; NotImplemented for anything else (arrays).
_Fast = float | np.float64 | npt.NDArray[np.float64]
def ellint_f_fast(phi: _Fast, m: _Fast, errors: int) -> object: ...
def ellint_e_fast(phi: _Fast, m: _Fast, errors: int) -> object: ...
def ellint_k_fast(m: _Fast, errors: int) -> object: ...
def carlson_rf_fast(x: _Fast, y: _Fast, z: _Fast, errors: int) -> object: ...
def carlson_rd_fast(x: _Fast, y: _Fast, z: _Fast, errors: int) -> object: ...
def carlson_rj_fast(x: _Fast, y: _Fast, z: _Fast, p: _Fast, errors: int) -> object: ...
def carlson_rc_fast(x: _Fast, y: _Fast, errors: int) -> object: ...
# SIMD level of the float64 F, E and R_F loops: "scalar", "sse", "avx2", "avx512",
# "avx512-sqrt-unit" ("auto": the best).
def set_simd_level(level: str) -> str: ...
def simd_level() -> str: ...
def simd_levels() -> list[str]: ...

# ---- friction and beam (src/bindings/friction.cpp) ------------------------------------------
# K and C are 2x2 matrices passed flat (4 entries, row-major); law kind 0 = viscoelastic
# (G0, V_star, n), 1 = Eyring (G0, V_star; n ignored).
from typing import Any, Callable, Optional

def castigliano_compliance(z: Callable[[Any], Any], dzdx: Optional[Callable[[float], float]],
                           L: float, EI: float, EA: float, tol: float = 0.0,
                           max_levels: int = 9) -> tuple[_F64, dict[str, Any]]: ...
def parabolic_beam_compliance(L: _F64, EI: _F64, errors: int = 0, rigidity: bool = False) -> _F64: ...
def rigidity(C: _F64, errors: int = 0) -> _F64: ...
def force_trace(K: _F64, t: _F64, d_par: _F64, d_perp: _F64, times: Optional[_F64] = None,
                samples_per_segment: int = 50) -> dict[str, _F64]: ...
def viscoelastic_detachment(V: _F64, G0: _F64, V_star: _F64, n: _F64, errors: int = 0) -> _F64: ...
def eyring_detachment(V: _F64, G0: _F64, V_star: _F64, errors: int = 0) -> _F64: ...
def detachment_stretch(K_par_par: _F64, f_par1: _F64, G: _F64, errors: int = 0) -> _F64: ...
def resonant_frequency(D: _F64, L: _F64, E: _F64, rho: _F64, errors: int = 0) -> _F64: ...
def steady_sliding_law(V: _F64, N: float, K: _F64, f_par1: float, f_perp1: float, kind: int,
                       G0: float, V_star: float, n: float, t_off: float = 0.0,
                       errors: int = 0, forces_only: bool = False
                       ) -> tuple[_F64, _F64, Optional[_F64], Optional[_F64]]: ...
def steady_sliding_energy(V: _F64, G: _F64, N: float, K: _F64, f_par1: float, f_perp1: float,
                          t_off: float = 0.0, errors: int = 0, forces_only: bool = False
                          ) -> tuple[_F64, _F64, Optional[_F64], Optional[_F64]]: ...
def simulate_spatulae(N: float, K: _F64, f_par1: float, f_perp1: float, V: float, G: float,
                      spatulae: int, duration: float, t_off: float, exponential: bool,
                      samples: int, seed: int, length: Optional[_F64] = None,
                      stiffness: Optional[_F64] = None,
                      G0: Optional[_F64] = None) -> dict[str, Any]: ...
def simulate_compliant_seta(N: float, K: _F64, f_par1: float, f_perp1: float, V: float, G: float,
                            spring: float, spatulae: int, duration: float, t_off: float,
                            exponential: bool, transient: float, samples: int, seed: int,
                            length: Optional[_F64] = None, stiffness: Optional[_F64] = None,
                            G0: Optional[_F64] = None) -> dict[str, Any]: ...
def fit_steady_sliding(V: _F64, F_par: _F64, F_perp: _F64, N: float, K: _F64, f_par1: float,
                       f_perp1: float, kind: int, G0: float, V_star: float, n: float,
                       fit_f_par1: Optional[bool] = None, fit_f_perp1: bool = True,
                       fit_coupling: bool = False, max_iterations: int = 200,
                       sigma_par: Optional[_F64] = None, sigma_perp: Optional[_F64] = None,
                       absolute_sigma: bool = True, profile: bool = False,
                       profile_delta: float = 1.0, max_condition: float = 1e10,
                       custom_G: Optional[Callable[[_F64, _F64], Any]] = None,
                       custom_names: list[str] = ..., custom_values: list[float] = ...,
                       custom_positive: list[bool] = ...) -> dict[str, Any]: ...

# ---- seta (src/bindings/seta.cpp) ------------------------------------------------------------
# A design is 9 float64: EI1, EI2, EA1, EA2, l1, l2, alpha1, alpha2, w. Column dicts hold float64
# arrays Fn, theta_joint, theta_rate_joint, theta_rate_base and int32 arrays status, iterations,
# turning_points_beam, turning_points_spatula.
def seta_validate(params: _F64, Ft: float = ...) -> float: ...
# Also min_z, min_z_at, max_axial_strain, min_stretch (admissibility; status 7 where the seta crosses
# the substrate, has a stretch <= 0 somewhere, or exceeds strain_limit).
def seta_critical_line_at(params: _F64, Ft: _F64, errors: int = 0, tolerance: float = ...,
                          strain_limit: float = ...) -> dict[str, Any]: ...
# The traced nodes: Ft, Fn, ... as above plus int32 branch and status (0 re-solved, 1 not), folds, end.
def seta_critical_line(params: _F64, ft_end: float = ..., resolve_nodes: bool = True,
                       strain_limit: float = ...) -> dict[str, Any]: ...
def seta_solve(params: _F64, Ft: float, Fn: float = ..., theta_joint: float = ...,
               theta_rate_joint: float = ..., theta_rate_base: float = ..., tolerance: float = ...,
               max_iterations: int = 40, strain_limit: float = ...) -> CriticalState: ...
def seta_characteristics(params: _F64, ft_end: float = ..., strain_limit: float = ...) -> SetaCharacteristicsResult: ...
def seta_batch(designs: _F64, Ft: _F64, errors: int = 0, threads: int = 1, tolerance: float = ...,
               strain_limit: float = ...) -> dict[str, Any]: ...
def seta_small_deformation(params: _F64) -> SmallDeformation: ...
# Design sweep (gecko.design_sweep): characteristics of n designs (flat n*9), depth 0 closed forms,
# 1 + natural state (fn0, slope_k, sticky_at_rest), 2 + the line to its end; flat columns of length
# n (float64; int8 sticky_at_rest, small_non_sticky, min_fn_interior; int32 status, line_end, folds).
def seta_characteristics_batch(designs: _F64, depth: int = 2, threads: int = 1) -> dict[str, Any]: ...
def seta_sensitivities(params: _F64, Ft: _F64) -> dict[str, Any]: ...
def seta_shape(params: _F64, Ft: float, steps: int = 200) -> dict[str, Any]: ...
def seta_contact_state(params: _F64, Fn: _F64, Ft: _F64, errors: int = 0, all: bool = False,
                       scan_points: int = 0, threads: int = 0, strain_limit: float = ...) -> dict[str, Any]: ...
def fiber_critical_line_at(params: _F64, Ft: _F64, errors: int = 0, tolerance: float = ...) -> dict[str, Any]: ...
def kendall_fn(Ft: _F64, EA: _F64, w: _F64, errors: int = 0) -> _F64: ...
def rivlin_fn(Ft: _F64, w: _F64, errors: int = 0) -> _F64: ...

# ---- seta domain types (src/bindings/seta_types.cpp) -----------------------------------------
import enum

class SetaDesign:
    """A two-level seta design, validated on construction (ValueError naming the field and range)."""
    fields: tuple[str, ...]
    defaults: dict[str, float]
    # name -> (lower, upper, lower inclusive, infinity allowed, the range as the error states it)
    domain: dict[str, tuple[float, float, bool, bool, str]]
    descriptions: dict[str, str]
    def __init__(self, *, EI1: float = ..., EI2: float = ..., EA1: float = ..., EA2: float = ...,
                 l1: float = ..., l2: float = ..., alpha1: float = ..., alpha2: float = ...,
                 w: float = ...) -> None: ...
    @staticmethod
    def admissible(name: str, value: float) -> bool: ...
    @property
    def EI1(self) -> float: ...
    @property
    def EI2(self) -> float: ...
    @property
    def EA1(self) -> float: ...
    @property
    def EA2(self) -> float: ...
    @property
    def l1(self) -> float: ...
    @property
    def l2(self) -> float: ...
    @property
    def alpha1(self) -> float: ...
    @property
    def alpha2(self) -> float: ...
    @property
    def w(self) -> float: ...
    @property
    def ft_max(self) -> float: ...
    def check_ft(self, Ft: float) -> None: ...
    def to_array(self) -> _F64: ...

class CriticalStatus(enum.IntEnum):
    converged = 0
    not_converged = 1
    no_critical_state = 2
    unsupported_state = 3
    singular = 4
    invalid_input = 5
    not_reached = 6
    inadmissible = 7

class ContactStatus(enum.IntEnum):
    CONVERGED = 0
    NOT_CONVERGED = 1
    NO_CONTACT = 2
    UNSUPPORTED_STATE = 3
    BEYOND_JOINT = 4
    INVALID_INPUT = 5
    SEVERAL_EQUILIBRIA = 6
    INADMISSIBLE = 7

class LineEnd(enum.IntEnum):
    reached_ft_end = 0
    reached_ft_max = 1
    turned_back = 2
    no_convergence = 3
    unsupported_state = 4
    max_points = 5
    no_natural_state = 6
    stalled = 7

class MinimumStatus(enum.IntEnum):
    stationary = 0
    range_start = 1
    range_end = 2
    line_incomplete = 3
    not_certified = 4
    admissible_end = 5
    no_admissible_state = 6

class FitStatus(enum.IntEnum):
    converged = 0
    max_iterations = 1
    singular = 2
    not_identifiable = 3
    no_progress = 4
    non_finite = 5

# ---- seta result types (src/bindings/seta.cpp, src/bindings/result_types.hpp) ----------------
# Read-only attributes named in `fields`; dict-style access (keys, items, values, get, [], in,
# iter, len; enums as plain ints) is kept for code written when these were dicts (deprecated).
class _Result:
    fields: tuple[str, ...]
    def __getitem__(self, key: str) -> Any: ...
    def keys(self) -> list[str]: ...
    def items(self) -> list[tuple[str, Any]]: ...
    def values(self) -> list[Any]: ...
    def get(self, key: str, default: Any = None) -> Any: ...
    def __contains__(self, key: object) -> bool: ...
    def __len__(self) -> int: ...

class CriticalState(_Result):
    Ft: float
    Fn: float
    theta_joint: float
    theta_rate_joint: float
    theta_rate_base: float
    status: CriticalStatus
    turning_points_beam: int
    turning_points_spatula: int
    min_z: float
    min_z_at: float
    max_axial_strain: float
    min_stretch: float
    iterations: int

class SetaCharacteristicsResult(_Result):
    fn0: float
    slope_k: float
    min_fn: float
    ft_at_min_fn: float
    min_fn_interior: bool
    max_pull_off: float
    ft_max: float
    ft_at_line_end: float
    fn_at_line_end: float
    sticky_at_rest: bool
    small_fn0: float
    small_slope_k: float
    small_contact_length: float
    small_non_sticky: bool
    admissible_to_end: bool
    admissible_end_ft: float
    admissible_end_fn: float
    slope_at_zero: float
    paper_k: float
    max_pull_off_is_bound: bool
    max_pull_off_bound: float
    min_status: MinimumStatus
    slope_at_min_fn: float
    end: LineEnd
    folds: list[float]

class SmallDeformation(_Result):
    fn0: float
    slope_k: float
    contact_length: float
    non_sticky: bool
