"""Shared plumbing of the numpy-facing wrappers: the ``errors=`` keyword and ufunc-like
broadcasting. The compiled kernels take flat contiguous float64 arrays of equal length (and run
without the GIL); these helpers broadcast, flatten, and give the caller's shape back."""
from __future__ import annotations

import re

import numpy as np

_AT_ELEMENT = re.compile(r"\(at element (\d+)\)$")


def with_index(error: ValueError, shape) -> ValueError:
    """The compiled loops name a bad element by its flat index, "(at element 7)"; this names it by
    its index in the caller's (broadcast) shape, "(at index (1, 3))", so the message points at the
    element the caller wrote. A scalar (0-d) input has no index: the suffix is dropped (the
    message already names the argument and its value)."""
    msg = str(error)
    m = _AT_ELEMENT.search(msg)
    if not m:
        return error
    return ValueError(msg[:m.start()].rstrip() + _where(tuple(shape), int(m.group(1))))

_ERRORS = {"raise": 0, "nan": 1}


def error_code(errors: str) -> int:
    """The compiled modules' code for ``errors=``: "raise" -> 0 (ValueError), "nan" -> 1."""
    try:
        return _ERRORS[errors]
    except (KeyError, TypeError):
        raise ValueError(f"errors = {errors!r} is not allowed: need 'raise' or 'nan'") from None


class InputError(TypeError, ValueError):
    """An input of a type that a conversion would reinterpret (complex, None, text, dates,
    objects): a TypeError, and a ValueError like every other bad input of gecko."""


def _where(shape, flat: int) -> str:
    """The suffix naming flat index ``flat`` in ``shape``: " (at index i)" or " (at index (i, j))";
    "" for a scalar (0-d) shape, which has no index."""
    if not shape:
        return ""
    idx = np.unravel_index(flat, shape)
    return f" (at index {tuple(int(i) for i in idx)})" if len(shape) > 1 else f" (at index {int(idx[0])})"


def _is_real_scalar(v) -> bool:
    return isinstance(v, (int, float, np.integer, np.floating, np.bool_)) and not isinstance(v, (np.datetime64,
                                                                                                np.timedelta64))


def real_array(x, name: str) -> np.ndarray:
    """``x`` as a float64 array, refusing what a conversion would silently reinterpret: complex
    numbers (the imaginary part dropped), None and other objects, strings, dates and durations,
    and masked arrays (the mask dropped). InputError (a TypeError and a ValueError; ValueError for a
    masked array) naming the argument and, for one bad element, its index."""
    if np.ma.isMaskedArray(x):
        raise ValueError(f"{name}: a masked array is not accepted (its mask would be ignored); pass "
                         f"{name}.filled(np.nan) or {name}.compressed()")
    if x is None:
        raise InputError(f"{name} = None is not allowed: need real numbers")
    a = np.asarray(x)
    kind = a.dtype.kind
    if kind in "biuf":
        return a.astype(np.float64, copy=False)
    if kind == "c":
        bad = np.flatnonzero(np.ravel(a.imag) != 0)
        at = _where(a.shape, int(bad[0])) if bad.size else ""
        raise InputError(f"{name}: complex numbers are not allowed{at}: need real numbers")
    if kind in "mM":
        raise InputError(f"{name}: dates and durations ({a.dtype}) are not allowed: need real numbers")
    if kind in "US":
        raise InputError(f"{name}: text ({a.dtype}) is not allowed: need real numbers")
    flat = a.reshape(-1)
    for i, v in enumerate(flat):  # object arrays: name the first element that is not a real number
        if not _is_real_scalar(v):
            raise InputError(f"{name}: {v!r} ({type(v).__name__}) is not allowed{_where(a.shape, i)}: "
                            "need real numbers")
    return a.astype(np.float64)


def _caller_name(frame, value, fallback: str) -> str:
    """The name under which the caller of a public wrapper holds ``value`` (for messages only)."""
    while frame is not None:
        code = frame.f_code
        params = code.co_varnames[:code.co_argcount + code.co_kwonlyargcount]
        hits = [k for k in params if frame.f_locals.get(k, fallback) is value]
        if len(hits) == 1:  # a parameter of the public function; ambiguous (two None) -> fallback
            return hits[0]
        frame = frame.f_back if code.co_filename.endswith("_vectorize.py") else None
    return fallback


def flat_args(args, names=None):
    """Broadcasts the arguments against each other; returns (shape, [flat contiguous arrays]).
    Each argument is checked by ``real_array`` (named by ``names``, else by the caller's
    parameter name)."""
    import inspect
    checked = []
    for i, a in enumerate(args):
        try:
            checked.append(real_array(a, names[i] if names else f"argument {i + 1}"))
        except (TypeError, ValueError) as exc:
            if names:
                raise
            real_array(a, _caller_name(inspect.currentframe().f_back, a, f"argument {i + 1}"))
            raise exc  # pragma: no cover - the line above raises the same error, named
    arrays = np.broadcast_arrays(*checked)
    shape = arrays[0].shape
    return shape, [np.ascontiguousarray(a).reshape(-1) for a in arrays]


def check_tolerance(tolerance, name: str = "tolerance", allow_none: bool = True) -> float:
    """None -> NaN (the kernel's default, where ``allow_none``); else a finite number > 0, or
    ValueError naming it."""
    if tolerance is None and allow_none:
        return float("nan")
    if isinstance(tolerance, bool) or not _is_real_scalar(tolerance) or not 0 < float(tolerance) < float("inf"):
        raise ValueError(f"{name} = {tolerance!r} is out of range: need a finite number > 0"
                         + (" (or None for the default)" if allow_none else ""))
    return float(tolerance)


def check_count(n, name: str = "max_iterations", hi: int = 10**7) -> int:
    """An integer in [1, hi] (not a bool, not a float), or ValueError naming it."""
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)) or not 1 <= n <= hi:
        raise ValueError(f"{name} = {n!r} is out of range: need an integer in [1, {hi}]")
    return int(n)


def shaped(out, shape):
    """A flat result in the caller's shape; a Python float for all-scalar input."""
    return float(out[0]) if shape == () else out.reshape(shape)


def vectorised(kernel, *args, errors):
    """Calls ``kernel(*flat_arrays, code)`` like a numpy ufunc over the broadcast arguments."""
    code = error_code(errors)
    shape, flat = flat_args(args)
    try:
        out = kernel(*flat, code)
    except ValueError as e:
        raise with_index(e, shape) from None
    return shaped(out, shape)


def check_table(table, name: str = "designs") -> None:
    """Every column of a design table (DataFrame, {name: column}, or array) through ``real_array``,
    so that a complex, text, date or missing (None, pd.NA) entry is named by column and row."""
    if hasattr(table, "columns") and hasattr(table, "to_numpy"):  # a DataFrame
        for c in table.columns:
            real_array(table[c].to_numpy(), f"{name}[{str(c)!r}]")
    elif isinstance(table, dict):
        for k, v in table.items():
            real_array(v, f"{name}[{k!r}]")
    elif isinstance(table, (list, tuple)) and table and all(hasattr(d, "_params") for d in table):
        return  # design objects: checked when they were made
    elif not hasattr(table, "_params"):
        real_array(table, name)


SCALAR_TYPES = frozenset((float, int, np.float64))
ERROR_CODES = _ERRORS


def _ufunc_input(a, name):
    """Real numpy arrays and scalars (float32 kept) as they are; anything else through
    ``real_array``, which names a complex, None, text, date or object element, or a masked array."""
    if type(a) in SCALAR_TYPES:
        return a
    if isinstance(a, (np.ndarray, np.generic)) and not isinstance(a, np.ma.MaskedArray) and a.dtype.kind in "biuf":
        return a
    return real_array(a, name)


def ufunc_call(ufunc, scalar, args, names, errors, kwargs):
    """Calls a gecko ufunc (NaN outside the domain) with numpy's keywords (``out=``,
    ``where=``, ``dtype=``, ...), and with ``errors="raise"`` raises the ValueError of the first
    element (C order of the broadcast shape) that the ufunc turned into NaN from non-NaN inputs:
    the compiled ``scalar(*values, 0)`` names the argument, its value and the allowed range, and
    "(at index ...)" is appended. Inputs are checked as everywhere (``real_array``), named by
    ``names``. (The public functions call ``scalar`` directly for plain Python scalars: the
    ufunc machinery costs more than the kernel.)"""
    code = error_code(errors)
    args = tuple(_ufunc_input(a, n) for a, n in zip(args, names))
    result = ufunc(*args, **kwargs)
    if code == 0:
        _raise_first_bad(ufunc, scalar, args, kwargs, result)
    return result


def _raise_first_bad(ufunc, scalar, args, kwargs, result):
    res = np.asarray(result)
    if res.dtype.kind != "f":
        return
    bad = np.isnan(res)
    if not bad.any():
        return
    inputs = np.broadcast_arrays(*(np.asarray(a) for a in args))
    for a in inputs:
        if a.dtype.kind in "fc":
            bad &= ~np.isnan(a)  # NaN in -> NaN out is not an error
    where = kwargs.get("where", True)
    if where is not True:
        bad &= np.broadcast_to(np.asarray(where, dtype=bool), bad.shape)
    if not bad.any():
        return
    flat = int(np.argmax(bad.reshape(-1)))
    idx = np.unravel_index(flat, bad.shape) if bad.shape else ()
    dtype = kwargs.get("dtype") or res.dtype
    values = [float(np.asarray(a[idx]).astype(dtype)) for a in inputs]
    where_txt = _where(bad.shape, flat)
    try:
        scalar(*values, 0)
    except ValueError as e:
        raise ValueError(str(e) + where_txt) from None
    # The double kernel accepts what the float32 loop did not (rounding at a domain edge).
    raise ValueError(f"gecko.{ufunc.__name__}: arguments {tuple(values)} are out of the domain "
                     f"in {np.dtype(dtype).name}{where_txt}")
