"""gecko.elliptic — Legendre and Carlson elliptic integrals, vectorised like numpy ufuncs.

Every function broadcasts its arguments against each other (scalars, lists, arrays of any
shape), returns a float for all-scalar input and an array otherwise, and runs its loop in C++
without the GIL. Parameter convention: ``m = k**2`` (as in scipy.special, not Boost or GSL).

Domain errors raise ``ValueError`` naming the argument and the allowed range; with
``errors="nan"`` the offending elements become NaN instead (for batch work). NaN input gives NaN.
"""
from __future__ import annotations

from typing import NamedTuple

from . import _core
from ._vectorize import error_code as _error_code, flat_args as _flat_args, shaped as _shaped
from ._vectorize import vectorised as _vectorised

__all__ = [
    "ellint_f", "ellint_e", "ellint_k", "ellint_ek", "EK",
    "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc",
]


def ellint_f(phi, m, *, errors: str = "raise"):
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

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.ellint_f, phi, m, errors=errors)


def ellint_e(phi, m, *, errors: str = "raise"):
    """Incomplete elliptic integral of the second kind, E(phi | m) = int_0^phi sqrt(1 - m sin^2 t) dt.

    Parameters
    ----------
    phi : array_like
        Amplitude, any real value.
    m : array_like
        Parameter, m <= 1, or m > 1 where sin^2(phi) <= 1/m.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.ellint_e, phi, m, errors=errors)


def ellint_k(m, *, errors: str = "raise"):
    """Complete elliptic integral of the first kind, K(m) = F(pi/2 | m).

    Parameters
    ----------
    m : array_like
        Parameter, m <= 1 (K(1) = inf).
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.ellint_k, m, errors=errors)


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


def carlson_rf(x, y, z, *, errors: str = "raise"):
    """Carlson's symmetric integral R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)).

    Parameters
    ----------
    x, y, z : array_like
        >= 0, at most one of them zero. Broadcast together.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.carlson_rf, x, y, z, errors=errors)


def carlson_rd(x, y, z, *, errors: str = "raise"):
    """Carlson's R_D(x, y, z) = R_J(x, y, z, z) = 3/2 int_0^inf dt / ((t+z) sqrt((t+x)(t+y)(t+z))).

    Parameters
    ----------
    x, y : array_like
        >= 0, at most one of them zero.
    z : array_like
        > 0.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.carlson_rd, x, y, z, errors=errors)


def carlson_rj(x, y, z, p, *, errors: str = "raise"):
    """Carlson's R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))).

    Parameters
    ----------
    x, y, z : array_like
        >= 0, at most one of them zero.
    p : array_like
        Nonzero; p < 0 gives the Cauchy principal value.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.carlson_rj, x, y, z, p, errors=errors)


def carlson_rc(x, y, *, errors: str = "raise"):
    """Carlson's R_C(x, y) = R_F(x, y, y) = 1/2 int_0^inf dt / ((t+y) sqrt(t+x)).

    Parameters
    ----------
    x : array_like
        >= 0.
    y : array_like
        Nonzero; y < 0 gives the Cauchy principal value.
    errors : {"raise", "nan"}, optional
        Out-of-domain input raises ``ValueError`` (default) or gives NaN for that element.

    Returns
    -------
    float or numpy.ndarray

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
    return _vectorised(_core.carlson_rc, x, y, errors=errors)
