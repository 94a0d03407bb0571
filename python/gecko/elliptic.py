"""gecko.elliptic — Legendre and Carlson elliptic integrals as numpy ufuncs.

The raw ufuncs are ``gecko.elliptic.ufuncs.ellint_f``, ``.ellint_e``, ``.ellint_k``,
``.carlson_rf``, ``.carlson_rd``, ``.carlson_rj``, ``.carlson_rc``: float64 and float32 loops,
numpy's broadcasting, ``out=``, ``where=``, ``dtype=``, and NaN for out-of-domain elements.
The functions below call them and take the same keywords; by default (``errors="raise"``) an
out-of-domain element raises ``ValueError`` naming the argument, its value, the allowed range and
its index in the broadcast shape; ``errors="nan"`` leaves the NaN. NaN input gives NaN. A plain
Python scalar call returns a float. Parameter convention: ``m = k**2`` (as in scipy.special, not
Boost or GSL). Large arrays run on several threads (``set_num_threads``); the results are
bitwise identical for any thread count.
"""
from __future__ import annotations

from typing import NamedTuple

from . import _core
from ._vectorize import error_code as _error_code, flat_args as _flat_args, shaped as _shaped
from ._vectorize import ERROR_CODES as _CODES, ufunc_call as _ufunc_call

ufuncs = _core.ufuncs

__all__ = [
    "ellint_f", "ellint_e", "ellint_k", "ellint_ek", "EK",
    "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc",
]


def set_num_threads(threads: int) -> int:
    """Threads per call of the ufunc loops.

    Parameters
    ----------
    threads : int
        0 (the default) picks by size (one thread below about 32,000 elements, at most the
        machine's logical CPUs); k > 0 uses exactly k. Results do not depend on it, bit for bit.

    Returns
    -------
    int
        The previous setting.

    Examples
    --------
    >>> from gecko import elliptic
    >>> before = elliptic.set_num_threads(1)
    >>> elliptic.set_num_threads(before)
    1
    """
    return _core.set_ufunc_threads(threads)


def set_simd_level(level: str) -> str:
    """Vector instruction set of the float64 loops of F, E and R_F (for tests and benchmarks).

    At import the best level the CPU offers is chosen, or the one named by the environment
    variable ``GECKO_SIMD`` (``scalar``, ``sse``, ``avx2``, ``avx512``, ``avx512-sqrt-unit``).
    Every level gives the same results, bit for bit: the vector loops repeat the scalar kernels'
    operations without contraction, and their square roots are correctly rounded. Results do not
    depend on the thread count either.

    The two AVX-512 levels are two schedules of the same loops: ``avx512`` computes half of its
    square roots on the FMA unit, which is faster where AVX-512 is native (Intel);
    ``avx512-sqrt-unit`` keeps them all on the square-root unit, which is faster on AMD's Zen 4
    (its 512-bit operations run as two 256-bit halves). ``auto`` picks ``avx512-sqrt-unit`` on
    AMD processors and ``avx512`` elsewhere.

    Parameters
    ----------
    level : {"scalar", "sse", "avx2", "avx512", "avx512-sqrt-unit", "auto"}
        ``scalar`` runs the one-element kernels; ``auto`` the best available level
        (see :func:`simd_levels`).

    Returns
    -------
    str
        The previous level.

    Raises
    ------
    ValueError
        If the level is unknown or not available on this machine.

    Examples
    --------
    >>> from gecko import elliptic
    >>> before = elliptic.set_simd_level("scalar")
    >>> elliptic.simd_level()
    'scalar'
    >>> elliptic.set_simd_level(before)
    'scalar'
    """
    return _core.set_simd_level(level)


def simd_level() -> str:
    """The vector instruction set the float64 loops of F, E and R_F use now.

    Returns
    -------
    str
        One of ``scalar``, ``sse``, ``avx2``, ``avx512``, ``avx512-sqrt-unit``.

    Examples
    --------
    >>> from gecko import elliptic
    >>> elliptic.simd_level() in elliptic.simd_levels()
    True
    """
    return _core.simd_level()


def simd_levels() -> list:
    """The levels :func:`set_simd_level` accepts on this machine, lowest first (the second
    AVX-512 schedule last).

    Returns
    -------
    list of str
        Always starts with ``scalar``.

    Examples
    --------
    >>> from gecko import elliptic
    >>> elliptic.simd_levels()[0]
    'scalar'
    """
    return _core.simd_levels()


# The kernel functions below are made by one template: plain Python scalars and 0-d float64
# arrays go to the compiled scalar kernel directly (the ufunc machinery costs more than the
# kernel; floats with the default errors are tested first, the cheapest test; _core.<name>_fast
# sorts the rest in C and answers NotImplemented for arrays), anything else goes through the ufunc.
# The source is generated (as collections.namedtuple does) so that each function keeps its named
# positional parameters and costs no more per call than a hand-written one; it is compiled in this
# module's namespace, so doctest and inspect see ordinary module functions.
_KERNEL_TEMPLATE = """
def _make(_ufunc, _scalar, _fast):
    def {name}({params}, *, errors: str = "raise", **kwargs):
        if {floats} and errors == "raise" and not kwargs:
            return _scalar({params}, 0)
        if not kwargs and errors in _CODES:
            r = _fast({params}, _CODES[errors])
            if r is not NotImplemented:
                return r
        return _ufunc_call(_ufunc, _scalar, ({params},), {names!r}, errors, kwargs)
    return {name}
"""


def _kernel_function(name, params, doc):
    """The public function `name`(*params, errors=, **kwargs) over ufuncs.<name> and the compiled
    scalar kernel <name>_scalar."""
    src = _KERNEL_TEMPLATE.format(
        name=name, params=", ".join(params), names=tuple(params),
        floats=" and ".join(f"type({p}) is float" for p in params))
    scope = {}
    exec(compile(src, f"<gecko.elliptic.{name}>", "exec"), globals(), scope)
    f = scope["_make"](getattr(ufuncs, name), getattr(_core, name + "_scalar"), getattr(_core, name + "_fast"))
    f.__doc__ = doc
    f.__module__ = __name__
    return f


ellint_f = _kernel_function(
    "ellint_f", ('phi', 'm'),
    """Incomplete elliptic integral of the first kind, F(phi | m) = int_0^phi dt / sqrt(1 - m sin^2 t).

    Broadcasts like a numpy ufunc; the loop runs in C++ without the GIL. Parameter convention
    m = k^2.

    Parameters
    ----------
    phi : array_like
        Amplitude, any real value (F(phi + pi) = F(phi) + 2 K(m)).
    m : array_like
        Parameter, m <= 1, or m > 1 where sin^2(phi) <= 1/m.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import numpy as np, gecko
    >>> round(float(gecko.ellint_f(np.pi / 2, 0.5)), 14)   # = K(0.5)
    1.85407467730137
    >>> bool(np.isclose(gecko.ellint_f(np.pi, 0.5), 2 * gecko.ellint_k(0.5), rtol=1e-15))
    True
    """)


ellint_e = _kernel_function(
    "ellint_e", ('phi', 'm'),
    """Incomplete elliptic integral of the second kind, E(phi | m) = int_0^phi sqrt(1 - m sin^2 t) dt.

    Parameters
    ----------
    phi : array_like
        Amplitude, any real value.
    m : array_like
        Parameter, m <= 1, or m > 1 where sin^2(phi) <= 1/m.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import numpy as np, gecko
    >>> round(float(gecko.ellint_e(np.pi / 2, 0.5)), 14)
    1.35064388104768
    """)


ellint_k = _kernel_function(
    "ellint_k", ('m',),
    """Complete elliptic integral of the first kind, K(m) = F(pi/2 | m).

    Parameters
    ----------
    m : array_like
        Parameter, m <= 1 (K(1) = inf).
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.ellint_k(0.5)), 14)
    1.85407467730137
    >>> gecko.ellint_k([0.5, 1.5], errors="nan")
    array([1.85407468,        nan])
    """)


class EK(NamedTuple):
    """Both complete elliptic integrals at the same parameter, as returned by :func:`ellint_ek`.

    Attributes
    ----------
    E, K : float or numpy.ndarray
        E(m) and K(m).

    Examples
    --------
    >>> import gecko
    >>> E, K = gecko.ellint_ek(0.0)
    >>> round(float(E), 14), round(float(K), 14)   # both pi/2 at m = 0
    (1.5707963267949, 1.5707963267949)
    """

    E: object
    K: object


def ellint_ek(m, *, errors: str = "raise") -> EK:
    """The complete integrals E(m) and K(m) together, sharing their work.

    Parameters
    ----------
    m : array_like
        Parameter, m <= 1.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    EK
        The named pair (E, K).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import gecko
    >>> ek = gecko.ellint_ek(0.5)
    >>> round(float(ek.E), 14), round(float(ek.K), 14)
    (1.35064388104768, 1.85407467730137)
    """
    code = _error_code(errors)
    shape, (flat,) = _flat_args((m,))
    e, k = _core.ellint_ek(flat, code)
    return EK(_shaped(e, shape), _shaped(k, shape))


carlson_rf = _kernel_function(
    "carlson_rf", ('x', 'y', 'z'),
    """Carlson's symmetric integral R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)).

    Parameters
    ----------
    x, y, z : array_like
        >= 0, at most one of them zero. Broadcast together.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.carlson_rf(1.0, 2.0, 0.0)), 13)     # Carlson's test value
    1.3110287771461
    """)


carlson_rd = _kernel_function(
    "carlson_rd", ('x', 'y', 'z'),
    """Carlson's R_D(x, y, z) = R_J(x, y, z, z) = 3/2 int_0^inf dt / ((t+z) sqrt((t+x)(t+y)(t+z))).

    Parameters
    ----------
    x, y : array_like
        >= 0, at most one of them zero.
    z : array_like
        > 0.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.carlson_rd(0.0, 2.0, 1.0)), 13)     # Carlson's test value
    1.7972103521034
    """)


carlson_rj = _kernel_function(
    "carlson_rj", ('x', 'y', 'z', 'p'),
    """Carlson's R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))).

    Parameters
    ----------
    x, y, z : array_like
        >= 0, at most one of them zero.
    p : array_like
        Nonzero; p < 0 gives the Cauchy principal value.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import gecko
    >>> round(float(gecko.carlson_rj(2.0, 3.0, 4.0, 5.0)), 14)  # Carlson's test value
    0.14297579667157
    """)


carlson_rc = _kernel_function(
    "carlson_rc", ('x', 'y'),
    """Carlson's R_C(x, y) = R_F(x, y, y) = 1/2 int_0^inf dt / ((t+y) sqrt(t+x)).

    Parameters
    ----------
    x : array_like
        >= 0.
    y : array_like
        Nonzero; y < 0 gives the Cauchy principal value.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.
    **kwargs
        numpy ufunc keywords (``out=``, ``where=``, ``dtype=``, ``casting=``, ...), passed to
        the ufunc in :data:`ufuncs`; float32 input (or ``dtype=np.float32``) gives float32.

    Returns
    -------
    float or numpy.ndarray
        A float for plain Python scalars, else what the ufunc returns (float64, or float32).

    Raises
    ------
    ValueError
        If an argument is outside the domain with ``errors="raise"``; the message names the
        argument, its value, the element index and the allowed range.

    Examples
    --------
    >>> import math, gecko
    >>> bool(math.isclose(gecko.carlson_rc(0.0, 0.25), math.pi, rel_tol=1e-15))
    True
    """)
