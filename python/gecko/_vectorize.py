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
    element the caller wrote."""
    msg = str(error)
    m = _AT_ELEMENT.search(msg)
    if not m or len(shape) < 1:
        return error
    flat = int(m.group(1))
    idx = np.unravel_index(flat, shape)
    where = f"(at index {tuple(int(i) for i in idx)})" if len(shape) > 1 else f"(at index {int(idx[0])})"
    return ValueError(msg[:m.start()] + where)

_ERRORS = {"raise": 0, "nan": 1}


def error_code(errors: str) -> int:
    """The compiled modules' code for ``errors=``: "raise" -> 0 (ValueError), "nan" -> 1."""
    try:
        return _ERRORS[errors]
    except (KeyError, TypeError):
        raise ValueError(f"errors = {errors!r} is not allowed: need 'raise' or 'nan'") from None


def flat_args(args):
    """Broadcasts the arguments against each other; returns (shape, [flat contiguous arrays])."""
    arrays = np.broadcast_arrays(*(np.asarray(a, dtype=np.float64) for a in args))
    shape = arrays[0].shape
    return shape, [np.ascontiguousarray(a).reshape(-1) for a in arrays]


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


SCALAR_TYPES = frozenset((float, int, np.float64))
ERROR_CODES = _ERRORS


def ufunc_call(ufunc, scalar, args, errors, kwargs):
    """Calls a gecko ufunc (NaN outside the domain) with numpy's keywords (``out=``,
    ``where=``, ``dtype=``, ...), and with ``errors="raise"`` raises the ValueError of the first
    element (C order of the broadcast shape) that the ufunc turned into NaN from non-NaN inputs:
    the compiled ``scalar(*values, 0)`` names the argument, its value and the allowed range, and
    "(at index ...)" is appended. (The public functions call ``scalar`` directly for plain
    Python scalars: the ufunc machinery costs more than the kernel.)"""
    code = error_code(errors)
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
    where_txt = ""
    if len(bad.shape) > 1:
        where_txt = f" (at index {tuple(int(i) for i in idx)})"
    elif len(bad.shape) == 1:
        where_txt = f" (at index {int(idx[0])})"
    try:
        scalar(*values, 0)
    except ValueError as e:
        raise ValueError(str(e) + where_txt) from None
    # The double kernel accepts what the float32 loop did not (rounding at a domain edge).
    raise ValueError(f"gecko.{ufunc.__name__}: arguments {tuple(values)} are out of the domain "
                     f"in {np.dtype(dtype).name}{where_txt}")
