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

__all__ = [
    "ellint_f", "ellint_e", "ellint_k", "ellint_ek", "EK",
    "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc",
]


def set_num_threads(threads: int) -> int:
    """Threads per ufunc loop call: 0 (the default) picks by size (one thread below about 32,000
    elements), k > 0 uses exactly k. Returns the previous setting."""
    return _core.set_ufunc_threads(threads)



def ellint_f(phi, m, *, errors: str = "raise", **kwargs):
    """Incomplete elliptic integral of the first kind F(phi | m) = int_0^phi dt / sqrt(1 - m sin^2 t).

    Any real phi (F(phi + pi) = F(phi) + 2K(m)); m <= 1, or m > 1 where sin^2(phi) <= 1/m.
    """
    if not kwargs and type(phi) in _S and type(m) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.ellint_f_scalar(phi, m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_f, _core.ellint_f_scalar, (phi, m), errors, kwargs)


def ellint_e(phi, m, *, errors: str = "raise", **kwargs):
    """Incomplete elliptic integral of the second kind E(phi | m) = int_0^phi sqrt(1 - m sin^2 t) dt."""
    if not kwargs and type(phi) in _S and type(m) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.ellint_e_scalar(phi, m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_e, _core.ellint_e_scalar, (phi, m), errors, kwargs)


def ellint_k(m, *, errors: str = "raise", **kwargs):
    """Complete elliptic integral of the first kind K(m) = F(pi/2 | m); m <= 1, K(1) = inf."""
    if not kwargs and type(m) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.ellint_k_scalar(m, _CODES[errors])
    return _ufunc_call(ufuncs.ellint_k, _core.ellint_k_scalar, (m,), errors, kwargs)


class EK(NamedTuple):
    """Both complete elliptic integrals at the same parameter."""

    E: object
    K: object


def ellint_ek(m, *, errors: str = "raise") -> EK:
    """Complete integrals (E(m), K(m)) together, sharing their work; returns the named pair EK(E, K)."""
    code = _error_code(errors)
    shape, (flat,) = _flat_args((m,))
    e, k = _core.ellint_ek(flat, code)
    return EK(_shaped(e, shape), _shaped(k, shape))


def carlson_rf(x, y, z, *, errors: str = "raise", **kwargs):
    """Carlson R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)); x, y, z >= 0, at most one zero."""
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.carlson_rf_scalar(x, y, z, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rf, _core.carlson_rf_scalar, (x, y, z), errors, kwargs)


def carlson_rd(x, y, z, *, errors: str = "raise", **kwargs):
    """Carlson R_D(x, y, z) = R_J(x, y, z, z); x, y >= 0 with at most one zero, z > 0."""
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.carlson_rd_scalar(x, y, z, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rd, _core.carlson_rd_scalar, (x, y, z), errors, kwargs)


def carlson_rj(x, y, z, p, *, errors: str = "raise", **kwargs):
    """Carlson R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z)))."""
    if not kwargs and type(x) in _S and type(y) in _S and type(z) in _S and type(p) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.carlson_rj_scalar(x, y, z, p, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rj, _core.carlson_rj_scalar, (x, y, z, p), errors, kwargs)


def carlson_rc(x, y, *, errors: str = "raise", **kwargs):
    """Carlson R_C(x, y) = R_F(x, y, y); x >= 0, y != 0 (Cauchy principal value for y < 0)."""
    if not kwargs and type(x) in _S and type(y) in _S and errors in _CODES:  # plain scalars: no ufunc machinery
        return _core.carlson_rc_scalar(x, y, _CODES[errors])
    return _ufunc_call(ufuncs.carlson_rc, _core.carlson_rc_scalar, (x, y), errors, kwargs)
