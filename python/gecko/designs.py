"""gecko.designs — two-level seta designs as tables: the design fields, their bounds, samplers.

The layer between the seta wrapper and its users (``gecko.design_sweep``, ``gecko.optimize``,
the scene sections): a grid, a random / Sobol / Latin-hypercube sample over bounds, or a table of
your own, as a pandas DataFrame with one column per design field (``FIELDS``, in the order of the
compiled kernels); ``parse_bounds`` checks bounds against each field's admissible range.
"""
from __future__ import annotations

import inspect
import itertools
import math
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from . import seta as _seta

__all__ = ["FIELDS", "DEFAULTS", "parse_bounds", "design_grid", "random_designs", "sobol_designs",
           "latin_hypercube_designs", "design_matrix"]

#: the design fields, in the order of the compiled kernels (from the bound C++ design type)
FIELDS = _seta.DESIGN_FIELDS
#: the reference scene (TwoLevelSeta's defaults): every field a table leaves out. (Python's
#: alpha defaults are math.pi / 6, one ulp below the C++ struct's correctly rounded pi/6.)
DEFAULTS = {f: float(inspect.signature(_seta.TwoLevelSeta).parameters[f].default) for f in FIELDS}


def _bound_text(v: float) -> str:
    return "inf" if v == math.inf else "pi/2" if v == math.pi / 2 else f"{v:g}"


def _domain_entry(name: str):
    """(lower, upper, lower inclusive, text) of a field for bounds: the C++ admissible range, with
    upper < inf even where EA = inf is allowed (a sample needs finite bounds)."""
    lo, hi, lo_incl, inf_ok, _ = _seta.SetaDesign.domain[name]
    text = f"{_bound_text(lo)} {'<=' if lo_incl else '<'} {name} < {_bound_text(hi)}"
    if inf_ok:
        text += " (inf: inextensible, fix it instead of sampling)"
    return (float(lo), float(hi), bool(lo_incl), text)


# allowed range of each field, for bounds: (lower, upper, lower inclusive, text)
_DOMAIN = {f: _domain_entry(f) for f in FIELDS}

_EXTRA = 'pip install "gecko-adhesion[sweep]"'


def _need(module: str, what: str):
    # [sweep] installs pandas, pyarrow and scipy; [dask] installs dask[distributed]
    from ._optional import require
    extra = "dask" if module.split(".")[0] in ("dask", "distributed") else "sweep"
    return require(module, what, extra)


# ---- designs --------------------------------------------------------------------------------------

def _check_fields(names: Iterable[str], what: str) -> None:
    for n in names:
        if n not in DEFAULTS:
            raise ValueError(f"{what}: unknown design parameter {n!r}; allowed: " + ", ".join(FIELDS))


def _fixed(fixed: Optional[Mapping[str, float]]) -> Dict[str, float]:
    fixed = dict(fixed or {})
    _check_fields(fixed, "fixed")
    return fixed


def parse_bounds(bounds: Mapping[str, Any]) -> List[Tuple[str, float, float, bool]]:
    """(name, lower, upper, log) per bound; ValueError naming the parameter and its allowed range."""
    if not isinstance(bounds, Mapping) or not bounds:
        raise ValueError("bounds: need a non-empty mapping {name: (lower, upper)} or "
                         "{name: (lower, upper, 'log')}; names: " + ", ".join(FIELDS))
    out = []
    for name, b in bounds.items():
        _check_fields([name], "bounds")
        lo_d, hi_d, lo_incl, text = _DOMAIN[name]
        log = False
        if isinstance(b, (list, tuple)) and len(b) == 3 and b[2] in ("log", "linear"):
            log = b[2] == "log"
            b = b[:2]
        if not (isinstance(b, (list, tuple)) and len(b) == 2):
            raise ValueError(f"bounds for {name}: need (lower, upper) or (lower, upper, 'log'); got {b!r}")
        try:
            lo, hi = float(b[0]), float(b[1])
        except (TypeError, ValueError):
            raise ValueError(f"bounds for {name}: need two numbers; got {b!r}") from None
        if not (lo < hi):
            raise ValueError(f"bounds for {name} = ({lo:g}, {hi:g}) are out of range: need lower < upper, "
                             f"both within {text}")
        ok_lo = lo >= lo_d if lo_incl else lo > lo_d
        if not (ok_lo and hi < hi_d and math.isfinite(lo) and math.isfinite(hi)):
            raise ValueError(f"bounds for {name} = ({lo:g}, {hi:g}) are out of range: need {text}")
        if log and not lo > 0:
            raise ValueError(f"bounds for {name} = ({lo:g}, {hi:g}, 'log') are out of range: a log scale "
                             "needs lower > 0")
        out.append((name, lo, hi, log))
    return out


def _table(columns: Dict[str, np.ndarray], n: int, fixed: Dict[str, float]):
    pd = _need("pandas", "gecko design tables")
    data = {}
    for f in FIELDS:
        if f in columns:
            data[f] = np.asarray(columns[f], dtype=np.float64)
        else:
            data[f] = np.full(n, float(fixed.get(f, DEFAULTS[f])))
    return pd.DataFrame(data)


def _scale(unit: np.ndarray, parsed) -> Dict[str, np.ndarray]:
    cols = {}
    for j, (name, lo, hi, log) in enumerate(parsed):
        u = unit[:, j]
        cols[name] = np.exp(np.log(lo) + u * (np.log(hi) - np.log(lo))) if log else lo + u * (hi - lo)
    return cols


def _count(n, what="n") -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"{what} = {n!r} is out of range: need an integer >= 1")
    return int(n)


def design_grid(axes: Mapping[str, Sequence[float]], *, fixed: Optional[Mapping[str, float]] = None):
    """Every combination of the values in ``axes``; the first name varies slowest.

    Parameters
    ----------
    axes : mapping
        {name: values} over the design fields.
    fixed : mapping, optional
        Values of fields not sampled; the rest take the reference scene's values.

    Returns
    -------
    pandas.DataFrame
        One row per design, one column per design field (``FIELDS``).

    Raises
    ------
    ValueError
        If a name is not a design field or a list of values is empty.

    Examples
    --------
    >>> import gecko
    >>> g = gecko.design_grid({"EI1": [1, 2], "alpha2": [0.1, 0.2]}, fixed={"EA2": 100})
    >>> g[["EI1", "alpha2", "EA2"]]
       EI1  alpha2    EA2
    0  1.0     0.1  100.0
    1  1.0     0.2  100.0
    2  2.0     0.1  100.0
    3  2.0     0.2  100.0
    """
    if not isinstance(axes, Mapping) or not axes:
        raise ValueError("axes: need a non-empty mapping {name: [values]}; names: " + ", ".join(FIELDS))
    _check_fields(axes, "axes")
    vals = []
    for name, v in axes.items():
        a = np.atleast_1d(np.asarray(v, dtype=np.float64))
        if a.ndim != 1 or a.size == 0:
            raise ValueError(f"axes[{name!r}]: need a non-empty 1-D list of values")
        vals.append(a)
    combos = np.array(list(itertools.product(*vals)), dtype=np.float64).reshape(-1, len(vals))
    return _table({n: combos[:, j] for j, n in enumerate(axes)}, combos.shape[0], _fixed(fixed))


def random_designs(bounds: Mapping[str, Any], n: int, *, seed: Optional[int] = None,
                   fixed: Optional[Mapping[str, float]] = None):
    """``n`` designs drawn independently and uniformly within ``bounds``.

    Parameters
    ----------
    bounds : mapping
        {name: (lower, upper)}, or (lower, upper, "log") for a log-uniform scale, over the design
        fields; each range inside the field's admissible range.
    n : int
        Number of designs, >= 1.
    seed : int, optional
        Seed of numpy's default generator.
    fixed : mapping, optional
        Values of fields not sampled; the rest take the reference scene's values.

    Returns
    -------
    pandas.DataFrame
        One row per design, one column per design field (``FIELDS``).

    Raises
    ------
    ValueError
        If a name is not a design field, a range is outside the field's domain, or ``n`` < 1.

    Examples
    --------
    >>> import gecko
    >>> d = gecko.random_designs({"EI2": (0.5, 4.0, "log"), "l2": (0.05, 0.2)}, n=3, seed=1)
    >>> d[["EI2", "l2"]].round(4)
          EI2      l2
    0  1.4494  0.1926
    1  0.6748  0.1923
    2  0.9563  0.1135
    """
    parsed = parse_bounds(bounds)
    n = _count(n)
    unit = np.random.default_rng(seed).random((n, len(parsed)))
    return _table(_scale(unit, parsed), n, _fixed(fixed))


def _qmc(kind: str, d: int, seed, **kw):
    qmc = _need("scipy.stats.qmc", "Sobol and Latin-hypercube designs")
    cls = {"sobol": qmc.Sobol, "lhs": qmc.LatinHypercube}[kind]
    try:
        return cls(d, rng=np.random.default_rng(seed), **kw)
    except TypeError:  # scipy < 1.15 names it seed
        return cls(d, seed=np.random.default_rng(seed), **kw)


def sobol_designs(bounds: Mapping[str, Any], n: int, *, seed: Optional[int] = None, scramble: bool = True,
                  fixed: Optional[Mapping[str, float]] = None):
    """``n`` designs from a (scrambled) Sobol sequence over ``bounds`` (scipy.stats.qmc).

    A power of two for ``n`` keeps the sequence's balance. Needs scipy (the ``[sweep]`` extra).

    Parameters
    ----------
    bounds : mapping
        {name: (lower, upper)}, or (lower, upper, "log") for a log-uniform scale, over the design
        fields; each range inside the field's admissible range.
    n : int
        Number of designs, >= 1.
    seed : int, optional
        Seed of the scrambling.
    scramble : bool, optional
        Scramble the sequence (default True).
    fixed : mapping, optional
        Values of fields not sampled; the rest take the reference scene's values.

    Returns
    -------
    pandas.DataFrame
        One row per design, one column per design field (``FIELDS``).

    Raises
    ------
    ValueError
        If a name is not a design field, a range is outside the field's domain, or ``n`` < 1.

    Examples
    --------
    >>> import gecko
    >>> gecko.sobol_designs({"alpha2": (0.0, 0.6)}, n=4, seed=1)["alpha2"].round(4).tolist()
    [0.1717, 0.5428, 0.3156, 0.0948]
    """
    parsed = parse_bounds(bounds)
    n = _count(n)
    eng = _qmc("sobol", len(parsed), seed, scramble=scramble)
    import warnings
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*balance properties.*")
        unit = eng.random(n)
    return _table(_scale(unit, parsed), n, _fixed(fixed))


def latin_hypercube_designs(bounds: Mapping[str, Any], n: int, *, seed: Optional[int] = None,
                            fixed: Optional[Mapping[str, float]] = None):
    """``n`` designs of a Latin hypercube over ``bounds`` (scipy.stats.qmc.LatinHypercube).

    Each parameter's range is cut into ``n`` equal strata, one design in each. Needs scipy.

    Parameters
    ----------
    bounds : mapping
        {name: (lower, upper)}, or (lower, upper, "log") for a log-uniform scale, over the design
        fields; each range inside the field's admissible range.
    n : int
        Number of designs, >= 1.
    seed : int, optional
        Seed of the sample.
    fixed : mapping, optional
        Values of fields not sampled; the rest take the reference scene's values.

    Returns
    -------
    pandas.DataFrame
        One row per design, one column per design field (``FIELDS``).

    Raises
    ------
    ValueError
        If a name is not a design field, a range is outside the field's domain, or ``n`` < 1.

    Examples
    --------
    >>> import gecko
    >>> d = gecko.latin_hypercube_designs({"alpha2": (0.0, 0.6)}, n=4, seed=1)
    >>> sorted((d["alpha2"] * 4 / 0.6).astype(int).tolist())    # one design per stratum
    [0, 1, 2, 3]
    """
    parsed = parse_bounds(bounds)
    n = _count(n)
    unit = _qmc("lhs", len(parsed), seed).random(n)
    return _table(_scale(unit, parsed), n, _fixed(fixed))


def design_matrix(designs) -> np.ndarray:
    """The designs as a C-contiguous (n, 9) float64 array in the order of ``FIELDS``.

    Parameters
    ----------
    designs : pandas.DataFrame, mapping, array_like of shape (n, 9), or sequence of TwoLevelSeta
        A table of some of the fields (the others take the reference scene's values), an array in
        the order of ``FIELDS``, or seta objects.

    Returns
    -------
    numpy.ndarray
        Shape (n, 9).

    Raises
    ------
    ValueError
        If a column is not a design field, the columns differ in length, or the shape is wrong.

    Examples
    --------
    >>> from gecko.designs import design_matrix
    >>> design_matrix({"EI1": [1.0, 2.0]})[:, :3]
    array([[ 1.,  2., inf],
           [ 2.,  2., inf]])
    """
    from .seta import TwoLevelSeta
    if isinstance(designs, TwoLevelSeta):
        designs = [designs]
    if hasattr(designs, "columns") and hasattr(designs, "to_numpy"):  # a DataFrame
        designs = {str(c): designs[c].to_numpy() for c in designs.columns}
    if isinstance(designs, Mapping):
        _check_fields(designs, "designs")
        if not designs:
            raise ValueError("designs: an empty table; need at least one of the columns " + ", ".join(FIELDS))
        cols = {k: np.asarray(v, dtype=np.float64).reshape(-1) for k, v in designs.items()}
        sizes = {v.size for v in cols.values()}
        if len(sizes) != 1:
            raise ValueError("designs: the columns have different lengths: "
                             + ", ".join(f"{k}: {v.size}" for k, v in cols.items()))
        n = sizes.pop()
        return np.ascontiguousarray(np.column_stack([cols.get(f, np.full(n, DEFAULTS[f])) for f in FIELDS]))
    if isinstance(designs, (list, tuple)) and designs and isinstance(designs[0], TwoLevelSeta):
        return np.ascontiguousarray(np.stack([d._params() for d in designs]))
    a = np.asarray(designs, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 9:
        raise ValueError(f"designs: need a table (DataFrame or {{name: column}}), TwoLevelSeta objects or an "
                         f"array of shape (n, 9) in the order {', '.join(FIELDS)}; got shape {a.shape}")
    return np.ascontiguousarray(a)


