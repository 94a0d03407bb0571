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
from ._vectorize import ERROR_CODES as _CODES, SCALAR_TYPES as _S, ufunc_call as _ufunc_call

ufuncs = _core.ufuncs
_ellint_f_scalar = _core.ellint_f_scalar
_ellint_e_scalar = _core.ellint_e_scalar
_ellint_k_scalar = _core.ellint_k_scalar
_carlson_rf_scalar = _core.carlson_rf_scalar
_carlson_rd_scalar = _core.carlson_rd_scalar
_carlson_rj_scalar = _core.carlson_rj_scalar
_carlson_rc_scalar = _core.carlson_rc_scalar

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


# Each function: plain Python scalars go to the compiled scalar kernel directly (the ufunc
# machinery costs more than the kernel; floats with the default errors are tested first, the
# cheapest test), anything else goes through the ufunc.
def ellint_f(phi, m, *, errors: str = "raise", **kwargs):
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
    """
    if type(phi) is float and type(m) is float and errors == "raise" and not kwargs:
        return _ellint_f_scalar(phi, m, 0)
    if not kwargs and type(phi) in _S and type(m) in _S and errors in _CODES:
        return _ellint_f_scalar(phi, m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_f, _core.ellint_f_scalar, (phi, m), ("phi", "m"), errors, kwargs)


def ellint_e(phi, m, *, errors: str = "raise", **kwargs):
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
    """
    if type(phi) is float and type(m) is float and errors == "raise" and not kwargs:
        return _ellint_e_scalar(phi, m, 0)
    if not kwargs and type(phi) in _S and type(m) in _S and errors in _CODES:
        return _ellint_e_scalar(phi, m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_e, _core.ellint_e_scalar, (phi, m), ("phi", "m"), errors, kwargs)


def ellint_k(m, *, errors: str = "raise", **kwargs):
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
    """
    if type(m) is float and errors == "raise" and not kwargs:
        return _ellint_k_scalar(m, 0)
    if not kwargs and type(m) in _S and errors in _CODES:
        return _ellint_k_scalar(m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_k, _core.ellint_k_scalar, (m,), ("m",), errors, kwargs)


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


def carlson_rf(x, y, z, *, errors: str = "raise", **kwargs):
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
    """
    if type(x) is float and type(y) is float and type(z) is float and errors == "raise" and not kwargs:
        return _carlson_rf_scalar(x, y, z, 0)
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and errors in _CODES:
        return _carlson_rf_scalar(x, y, z, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rf, _core.carlson_rf_scalar, (x, y, z), ("x", "y", "z"), errors, kwargs)


def carlson_rd(x, y, z, *, errors: str = "raise", **kwargs):
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
    """
    if type(x) is float and type(y) is float and type(z) is float and errors == "raise" and not kwargs:
        return _carlson_rd_scalar(x, y, z, 0)
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and errors in _CODES:
        return _carlson_rd_scalar(x, y, z, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rd, _core.carlson_rd_scalar, (x, y, z), ("x", "y", "z"), errors, kwargs)


def carlson_rj(x, y, z, p, *, errors: str = "raise", **kwargs):
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
    """
    if type(x) is float and type(y) is float and type(z) is float and type(p) is float and errors == "raise" and not kwargs:
        return _carlson_rj_scalar(x, y, z, p, 0)
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and type(p) in _S and errors in _CODES:
        return _carlson_rj_scalar(x, y, z, p, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rj, _core.carlson_rj_scalar, (x, y, z, p), ("x", "y", "z", "p"), errors, kwargs)


def carlson_rc(x, y, *, errors: str = "raise", **kwargs):
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
    """
    if type(x) is float and type(y) is float and errors == "raise" and not kwargs:
        return _carlson_rc_scalar(x, y, 0)
    if not kwargs and type(x) in _S and type(y) in _S and errors in _CODES:
        return _carlson_rc_scalar(x, y, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rc, _core.carlson_rc_scalar, (x, y), ("x", "y"), errors, kwargs)
