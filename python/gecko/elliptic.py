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
    """Incomplete elliptic integral of the first kind F(phi | m) = int_0^phi dt / sqrt(1 - m sin^2 t).

    Any real phi (F(phi + pi) = F(phi) + 2K(m)); m <= 1, or m > 1 where sin^2(phi) <= 1/m.
    """
    return _vectorised(_core.ellint_f, phi, m, errors=errors)


def ellint_e(phi, m, *, errors: str = "raise"):
    """Incomplete elliptic integral of the second kind E(phi | m) = int_0^phi sqrt(1 - m sin^2 t) dt."""
    return _vectorised(_core.ellint_e, phi, m, errors=errors)


def ellint_k(m, *, errors: str = "raise"):
    """Complete elliptic integral of the first kind K(m) = F(pi/2 | m); m <= 1, K(1) = inf."""
    return _vectorised(_core.ellint_k, m, errors=errors)


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


def carlson_rf(x, y, z, *, errors: str = "raise"):
    """Carlson R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)); x, y, z >= 0, at most one zero."""
    return _vectorised(_core.carlson_rf, x, y, z, errors=errors)


def carlson_rd(x, y, z, *, errors: str = "raise"):
    """Carlson R_D(x, y, z) = R_J(x, y, z, z); x, y >= 0 with at most one zero, z > 0."""
    return _vectorised(_core.carlson_rd, x, y, z, errors=errors)


def carlson_rj(x, y, z, p, *, errors: str = "raise"):
    """Carlson R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z)))."""
    return _vectorised(_core.carlson_rj, x, y, z, p, errors=errors)


def carlson_rc(x, y, *, errors: str = "raise"):
    """Carlson R_C(x, y) = R_F(x, y, y); x >= 0, y != 0 (Cauchy principal value for y < 0)."""
    return _vectorised(_core.carlson_rc, x, y, errors=errors)
