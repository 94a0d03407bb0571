"""gecko.design_sweep — characteristics of many two-level seta designs as one table.

A sweep takes many designs (a grid, a random / Sobol / Latin-hypercube sample over bounds, or a
table of your own) and returns a pandas DataFrame with one row per design, in the order of the
designs: the nine design fields, the outputs asked for, and ``status``::

    import gecko
    designs = gecko.sobol_designs({"EI1": (1, 10), "alpha2": (0, 0.5)}, n=4096, seed=1)
    table = gecko.sweep(designs, outputs=["fn0", "slope_k", "max_pull_off"], out="runs/")

Only what the outputs need is solved (models.md §1, gecko/seta/characteristics.hpp):

* ``ft_max`` and the ``small_*`` quantities are closed forms: no solver runs;
* ``fn0``, ``slope_k``, ``sticky_at_rest`` need the natural state at Ft = 0 (one homotopy solve
  and one linear solve for the slope), no line is traced;
* ``max_pull_off``, ``ft_at_max_pull_off``, ``min_fn``, ``ft_at_line_end``, ``fn_at_line_end``,
  ``line_end``, ``folds``, ``admissible_end_ft``, ``admissible_to_end`` follow the critical line to
  its end. The minimum (``max_pull_off`` and its Ft) is taken over the admissible part of the line
  only: from Ft = 0 to ``admissible_end_ft``, the first state where the deformed seta crosses the
  substrate (``admissible_to_end``: the whole followed line is admissible). Where the minimum sits
  at the end of the followed range and that end is not (Ft)max (EA2 = inf; a line given up),
  ``max_pull_off`` is NaN, as in ``TwoLevelSeta.characteristics()``, and ``max_pull_off_bound``
  (with ``max_pull_off_is_bound``) gives the bound over the followed range;
* ``slope_at_zero`` is the tangent dFn/dFt at Ft = 0 (``slope_k`` its deprecated alias); ``paper_k``
  is the paper's k (eq (16): the least-squares slope through (0, (Fn)0) over the lower part of the
  line, see ``SetaCharacteristics.paper_k``).

Designs are computed in chunks by the compiled batch call ``_core.seta_characteristics_batch``
(C++ threads, the GIL released), or as Dask tasks on a ``dask.distributed`` cluster
(``client=`` or ``executor="dask://host:port"``). Every design is solved on its own, so the table
is bitwise the same for any chunk size, thread count and executor. With ``out=DIR`` each chunk is
written to ``DIR/sweep-<key>/chunk-NNNNNN.parquet`` as soon as it is done (``<key>``: a hash of the
designs, the outputs, the chunk size and the gecko version) and the finished table to
``DIR/sweep-<key>.parquet``; a run that was interrupted resumes from the chunks already written.

Status codes (``status``, as ``gecko.STATUS``): 0 solved; 1 natural state not found; 3 the
natural state is outside the model's forms; 5 invalid design (only with ``errors="nan"``; the
default ``errors="raise"`` refuses the whole sweep before computing, naming the first bad row);
6 the line's minimum was not established: the line was given up before its end (no convergence at
a singular point, point budget, stalled: ``line_end`` says which; the minimum over the followed part
would only be a bound) or the minimum could not be refined, so ``max_pull_off``,
``ft_at_max_pull_off`` and ``min_fn`` are NaN, while ``fn0``, ``slope_k`` and where the line
stopped (``ft_at_line_end``, ``fn_at_line_end``) are kept. ``line_end`` says why the followed
line stopped (``gecko.design_sweep.LINE_END``; "left the model" is an end of the model's line, not
a failure; -1 for an invalid design). An output is NaN where its solve failed.

On a Dask cluster (gecko must be installed on the workers, the same version as the client)::

    $ dask scheduler                          # on one machine: listens on tcp://HOST:8786
    $ dask worker tcp://HOST:8786 --nthreads 1 --nworkers 4    # on each machine with cores

    from dask.distributed import Client
    table = gecko.sweep(designs, client=Client("tcp://HOST:8786"), out="runs/")
    # or, without a client of your own (also a scene's [sweep] executor = "dask://HOST:8786"):
    table = gecko.sweep(designs, executor="dask://HOST:8786", connect_timeout=10)

Each chunk is one task (its designs travel with it, its columns come back); chunk files are
written where ``sweep`` runs, so the workers need no shared disk. An address where no scheduler
answers raises ConnectionError after ``connect_timeout`` seconds.

pandas (and pyarrow for ``out=``, dask.distributed for clusters) are optional dependencies:
``pip install gecko[sweep]``.
"""
from __future__ import annotations

import hashlib
import inspect
import itertools
import math
import os
import time
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from . import seta as _seta

__all__ = ["sweep", "SWEEP_OUTPUTS", "DEFAULT_SWEEP_OUTPUTS", "design_grid", "random_designs",
           "sobol_designs", "latin_hypercube_designs"]

#: the design fields, in the order of the compiled kernels
FIELDS = _seta.TwoLevelSeta._FIELDS
#: the reference scene (models.md §1, TwoLevelSeta's defaults): every field a table leaves out
DEFAULTS = {f: float(inspect.signature(_seta.TwoLevelSeta).parameters[f].default) for f in FIELDS}

#: output -> solver depth it needs (0: closed forms, 1: natural state at Ft = 0, 2: the line)
SWEEP_OUTPUTS: Dict[str, int] = {
    "ft_max": 0, "small_fn0": 0, "small_slope_k": 0, "small_contact_length": 0, "small_non_sticky": 0,
    "fn0": 1, "slope_k": 1, "slope_at_zero": 1, "sticky_at_rest": 1,
    "max_pull_off": 2, "ft_at_max_pull_off": 2, "min_fn": 2, "ft_at_line_end": 2, "fn_at_line_end": 2,
    "line_end": 2, "folds": 2, "admissible_end_ft": 2, "admissible_to_end": 2, "paper_k": 2,
    "max_pull_off_bound": 2, "max_pull_off_is_bound": 2,
}
DEFAULT_SWEEP_OUTPUTS = ("fn0", "slope_k", "max_pull_off", "ft_at_max_pull_off", "ft_max", "sticky_at_rest")
# column name in the table -> key in the compiled call's result
_SOURCE = {"ft_at_max_pull_off": "ft_at_min_fn"}
_BOOL = ("sticky_at_rest", "small_non_sticky", "admissible_to_end", "max_pull_off_is_bound")

#: ``line_end`` codes -> why the followed line stopped (gecko/seta/detail/continuation.hpp; the
#: same table as ``TwoLevelSeta.characteristics().end``)
LINE_END = _seta._LINE_END

# allowed range of each field, for bounds: (lower, upper, lower inclusive, text)
_DOMAIN = {
    "EI1": (0.0, math.inf, False, "0 < EI1 < inf"), "EI2": (0.0, math.inf, False, "0 < EI2 < inf"),
    "EA1": (0.0, math.inf, False, "0 < EA1 < inf (inf: inextensible, fix it instead of sampling)"),
    "EA2": (0.0, math.inf, False, "0 < EA2 < inf (inf: inextensible, fix it instead of sampling)"),
    "l1": (0.0, math.inf, False, "0 < l1 < inf"), "l2": (0.0, math.inf, False, "0 < l2 < inf"),
    "alpha1": (0.0, math.pi / 2, False, "0 < alpha1 < pi/2"),
    "alpha2": (0.0, math.pi / 2, True, "0 <= alpha2 < pi/2"),
    "w": (0.0, math.inf, False, "0 < w < inf"),
}

_EXTRA = "pip install gecko[sweep]"


def _need(module: str, what: str):
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(f"{what} needs the optional package {module.split('.')[0]!r} "
                          f"({_EXTRA} installs pandas, pyarrow, dask[distributed] and scipy): {exc}") from None


# ---- designs --------------------------------------------------------------------------------------

def _check_fields(names: Iterable[str], what: str) -> None:
    for n in names:
        if n not in DEFAULTS:
            raise ValueError(f"{what}: unknown design parameter {n!r}; allowed: " + ", ".join(FIELDS))


def _fixed(fixed: Optional[Mapping[str, float]]) -> Dict[str, float]:
    fixed = dict(fixed or {})
    _check_fields(fixed, "fixed")
    return fixed


def _parse_bounds(bounds: Mapping[str, Any]) -> List[Tuple[str, float, float, bool]]:
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
    """Every combination of the values in ``axes`` ({name: values}); the first name varies slowest.
    The other fields take ``fixed`` or the reference scene's values. Returns a DataFrame."""
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
    """``n`` designs drawn independently and uniformly within ``bounds`` ({name: (lower, upper)} or
    (lower, upper, "log") for log-uniform) by numpy's default generator seeded with ``seed``."""
    parsed = _parse_bounds(bounds)
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
    """``n`` designs from a (scrambled) Sobol sequence over ``bounds`` (scipy.stats.qmc); a power of
    two for ``n`` keeps the sequence's balance."""
    parsed = _parse_bounds(bounds)
    n = _count(n)
    eng = _qmc("sobol", len(parsed), seed, scramble=scramble)
    import warnings
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*balance properties.*")
        unit = eng.random(n)
    return _table(_scale(unit, parsed), n, _fixed(fixed))


def latin_hypercube_designs(bounds: Mapping[str, Any], n: int, *, seed: Optional[int] = None,
                            fixed: Optional[Mapping[str, float]] = None):
    """``n`` designs of a Latin hypercube over ``bounds`` (scipy.stats.qmc.LatinHypercube): each
    parameter's range is cut into n equal strata, one design in each."""
    parsed = _parse_bounds(bounds)
    n = _count(n)
    unit = _qmc("lhs", len(parsed), seed).random(n)
    return _table(_scale(unit, parsed), n, _fixed(fixed))


def design_matrix(designs) -> np.ndarray:
    """The designs as a C-contiguous (n, 9) float64 array in the order of ``FIELDS``.

    Accepts a DataFrame or a mapping of columns (a subset of the fields; the others take the
    reference scene's values), an array of shape (n, 9), or a sequence of ``TwoLevelSeta``."""
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


# ---- computing one chunk --------------------------------------------------------------------------

def _depth(outputs: Sequence[str]) -> int:
    return max((SWEEP_OUTPUTS[o] for o in outputs), default=0)


# line_end codes where the continuation gave up before the line's end (no convergence at a
# singular point, point budget, stalled): the minimum over the followed part is only a bound
_GIVEN_UP = (3, 5, 7)
# outputs that claim something of the whole line: NaN (and status 6) when it was given up
_WHOLE_LINE = ("max_pull_off", "ft_at_max_pull_off", "min_fn")


def compute_chunk(designs: np.ndarray, outputs: Sequence[str], threads: int = 1) -> Dict[str, np.ndarray]:
    """The requested outputs (and ``status``) of an (n, 9) block of designs: one GIL-free call.
    Module-level so that Dask workers can import it."""
    depth = _depth(outputs)
    d = _core.seta_characteristics_batch(np.ascontiguousarray(designs, dtype=np.float64).reshape(-1),
                                         depth, int(threads))
    status = np.asarray(d["status"], dtype=np.int8)
    given_up = np.zeros(status.shape, dtype=bool)
    if depth == 2:
        # given up before the line's end, or its minimum not established (NaN from the kernel)
        given_up = (status == 0) & (np.isin(np.asarray(d["line_end"]), _GIVEN_UP) | np.isnan(d["min_fn"]))
        status[given_up] = 6
    out = {"status": status}
    for o in outputs:
        a = np.asarray(d[_SOURCE.get(o, o)])
        if o in _WHOLE_LINE and given_up.any():
            a = np.where(given_up, np.nan, a)
        if o in _BOOL:
            a = a.astype(bool)
        elif o == "line_end":  # -1: not computed (invalid design)
            a = np.where(status == 5, -1, a).astype(np.int8)
        out[o] = a
    return out


# ---- the sweep ------------------------------------------------------------------------------------

def _version() -> str:
    return str(getattr(_core, "__version__", "0"))


def sweep_key(matrix: np.ndarray, outputs: Sequence[str], chunk_size: int) -> str:
    """Hash naming a sweep's chunk files: the designs (bytes), outputs, chunk size, gecko version."""
    h = hashlib.sha256()
    h.update(b"gecko.sweep/1\0")
    h.update(_version().encode() + b"\0")
    h.update(",".join(outputs).encode() + b"\0")
    h.update(str(int(chunk_size)).encode() + b"\0")
    h.update(str(matrix.shape).encode() + b"\0")
    h.update(np.ascontiguousarray(matrix, dtype="<f8").tobytes())
    return h.hexdigest()[:16]


class _ProgressAdapter:
    """``progress``: None (a bar on a terminal), True/False, or a callable(done, total) called
    after every chunk with the number of designs done."""

    def __init__(self, progress, total: int):
        self.callback = progress if callable(progress) else None
        self.bar = None
        if self.callback is None and progress is not False:
            from .scene.runner import Progress
            self.bar = Progress(total, "sweep", enabled=True if progress is True else None)
        self.total, self.done = total, 0

    def advance(self, n: int) -> None:
        self.done += n
        if self.bar is not None:
            self.bar.advance(n, f"{self.done} designs")
        if self.callback is not None:
            self.callback(self.done, self.total)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def _check_outputs(outputs) -> List[str]:
    if outputs is None:
        return list(DEFAULT_SWEEP_OUTPUTS)
    if isinstance(outputs, str):
        outputs = [outputs]
    outputs = list(dict.fromkeys(outputs))
    if not outputs:
        raise ValueError("outputs: need at least one of: " + ", ".join(SWEEP_OUTPUTS))
    for o in outputs:
        if o not in SWEEP_OUTPUTS:
            raise ValueError(f"outputs: unknown output {o!r}; allowed: " + ", ".join(SWEEP_OUTPUTS))
    return outputs


def _validate_rows(matrix: np.ndarray) -> None:
    """errors="raise": refuse the sweep before computing when a design is invalid, naming its row
    and (through the compiled validator) the parameter and its allowed range."""
    st = np.asarray(_core.seta_characteristics_batch(matrix.reshape(-1), 0, 1)["status"])
    bad = np.flatnonzero(st == 5)
    if bad.size:
        i = int(bad[0])
        try:
            _core.seta_validate(matrix[i])
            why = "invalid design"
        except ValueError as exc:
            why = str(exc)
        more = f" (and {bad.size - 1} more rows)" if bad.size > 1 else ""
        raise ValueError(f"designs: row {i}{more} is invalid: {why}; pass errors='nan' to keep invalid rows "
                         "with status 5")


def _connect(executor: Optional[str], client, timeout: float):
    """A dask.distributed Client from ``client`` or ``executor = "dask://host:port"``; (client,
    owned) where owned says that the sweep opened it and must close it."""
    if client is not None:
        return client, False
    if executor in (None, "threads", "local"):
        return None, False
    if not isinstance(executor, str) or not executor.startswith(("dask://", "tcp://", "tls://")):
        raise ValueError(f"executor = {executor!r} is not allowed: need 'threads' or 'dask://host:port' "
                         "(a dask.distributed scheduler)")
    distributed = _need("distributed", "running a sweep on a Dask cluster")
    addr = "tcp://" + executor[len("dask://"):] if executor.startswith("dask://") else executor
    try:
        return distributed.Client(addr, timeout=timeout, set_as_default=False), True
    except (OSError, TimeoutError) as exc:
        raise ConnectionError(f"executor = {executor!r}: no Dask scheduler answered at {addr} within "
                              f"{timeout:g} s ({type(exc).__name__}: {exc}). Start one with `dask scheduler` "
                              "and workers with `dask worker ADDRESS`, or use executor = 'threads'") from None


def sweep(designs, outputs: Optional[Sequence[str]] = None, *, out: Optional[Union[str, os.PathLike]] = None,
          chunk_size: int = 10000, threads: Optional[int] = None, client=None, executor: Optional[str] = None,
          connect_timeout: float = 10.0, errors: str = "raise",
          progress: Union[None, bool, Callable[[int, int], None]] = None):
    """Characteristics of many designs: a pandas DataFrame with one row per design, in order.

    ``designs``: a table (DataFrame or {name: column}; missing fields take the reference scene's
    values), an (n, 9) array or TwoLevelSeta objects; see ``design_grid``, ``random_designs``,
    ``sobol_designs``, ``latin_hypercube_designs``. ``outputs``: names from ``SWEEP_OUTPUTS``
    (default ``DEFAULT_SWEEP_OUTPUTS``); only what they need is solved. ``status`` is always there.

    ``out``: a folder; chunks go to ``out/sweep-<key>/`` as they finish and the table to
    ``out/sweep-<key>.parquet`` (pyarrow); an interrupted run with the same designs, outputs and
    ``chunk_size`` resumes from the chunks written. ``threads``: C++ threads per chunk (default:
    the CPU count). ``client``: a ``dask.distributed.Client``, or ``executor="dask://host:port"``
    (connecting waits at most ``connect_timeout`` seconds, then raises ConnectionError): chunks
    then run as Dask tasks (one thread each unless ``threads`` is given) and stream back.
    ``errors="raise"`` refuses a sweep with an invalid design (ValueError naming the row and
    parameter) before computing; ``errors="nan"`` keeps it as a row with status 5.
    ``progress``: None (a bar on a terminal), False, True, or a callable(done, total) called with
    the number of designs done: once at the start (the designs already on disk) and after each chunk.

    ``table.attrs["sweep"]``: key, path, chunks computed and reused, seconds.
    """
    pd = _need("pandas", "gecko.sweep")
    t0 = time.perf_counter()
    outputs = _check_outputs(outputs)
    if errors not in ("raise", "nan"):
        raise ValueError(f"errors = {errors!r} is not allowed: need 'raise' or 'nan'")
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, (int, np.integer)) or chunk_size < 1:
        raise ValueError(f"chunk_size = {chunk_size!r} is out of range: need an integer >= 1")
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or threads < 1):
        raise ValueError(f"threads = {threads!r} is out of range: need an integer >= 1")
    if isinstance(connect_timeout, bool) or not isinstance(connect_timeout, (int, float)) or not connect_timeout > 0:
        raise ValueError(f"connect_timeout = {connect_timeout!r} is out of range: need seconds > 0")
    matrix = design_matrix(designs)
    n = matrix.shape[0]
    if n == 0:
        raise ValueError("designs: an empty table; need at least one design")
    if errors == "raise":
        _validate_rows(matrix)
    chunk_size = int(chunk_size)
    key = sweep_key(matrix, outputs, chunk_size)
    starts = list(range(0, n, chunk_size))
    parts: List[Optional[Dict[str, np.ndarray]]] = [None] * len(starts)

    pq = _need("pyarrow.parquet", "gecko.sweep(out=...) (Parquet files)") if out is not None else None
    dask_client, owned = _connect(executor, client, connect_timeout)  # fails fast, before any file
    bar = None
    try:
        store = None
        final_path = None
        if out is not None:
            store = _ChunkStore(os.fspath(out), key, pq)
            final_path = store.final
            if os.path.exists(final_path):  # the whole sweep is already there
                table = pd.read_parquet(final_path)
                if len(table) == n:
                    table.attrs["sweep"] = {"key": key, "path": final_path, "chunks": len(starts),
                                            "chunks_computed": 0, "chunks_reused": len(starts),
                                            "seconds": time.perf_counter() - t0, "executor": "file"}
                    return table
            for i in range(len(starts)):
                parts[i] = store.load(i, min(chunk_size, n - starts[i]), outputs)
        reused = sum(p is not None for p in parts)
        todo = [i for i, p in enumerate(parts) if p is None]
        bar = _ProgressAdapter(progress, n)
        bar.advance(sum(min(chunk_size, n - starts[i]) for i in range(len(starts)) if parts[i] is not None))

        def done(i: int, res: Dict[str, np.ndarray]) -> None:
            parts[i] = res
            if store is not None:
                store.save(i, res)
            bar.advance(res["status"].size)

        if dask_client is None:
            nt = int(threads) if threads is not None else (os.cpu_count() or 1)
            for i in todo:
                done(i, compute_chunk(matrix[starts[i]:starts[i] + chunk_size], outputs, nt))
            how = f"threads ({nt})"
        else:
            from distributed import as_completed
            nt = int(threads) if threads is not None else 1
            futures = {dask_client.submit(compute_chunk, matrix[starts[i]:starts[i] + chunk_size], outputs, nt,
                                          pure=False): i for i in todo}
            try:
                for f, res in as_completed(list(futures), loop=dask_client.loop, with_results=True):
                    done(futures[f], res)
            finally:  # interrupted: the tasks not yet done are dropped, not left running
                if futures:
                    dask_client.cancel(list(futures))
            how = f"dask ({dask_client.scheduler.address})"
    finally:
        if bar is not None:
            bar.close()
        if owned:
            dask_client.close()

    cols = {f: matrix[:, j] for j, f in enumerate(FIELDS)}
    for c in outputs + ["status"]:
        cols[c] = np.concatenate([p[c] for p in parts])
    table = pd.DataFrame(cols)
    if store is not None:
        store.finish(table)
    table.attrs["sweep"] = {"key": key, "path": final_path, "chunks": len(starts), "chunks_computed": len(todo),
                            "chunks_reused": reused, "seconds": time.perf_counter() - t0, "executor": how}
    return table


class _ChunkStore:
    """Chunk files of one sweep: written atomically (temporary name, then rename), so a chunk file
    that exists is complete; removed once the whole table is written."""

    def __init__(self, out: str, key: str, pq):
        self.dir = os.path.join(out, f"sweep-{key}")
        self.final = os.path.join(out, f"sweep-{key}.parquet")
        self.pq = pq
        try:
            os.makedirs(self.dir, exist_ok=True)
        except OSError as exc:
            raise ValueError(f"out = {out!r}: cannot create the folder: {exc.strerror or exc}") from None

    def path(self, i: int) -> str:
        return os.path.join(self.dir, f"chunk-{i:06d}.parquet")

    def load(self, i: int, rows: int, outputs: Sequence[str]) -> Optional[Dict[str, np.ndarray]]:
        p = self.path(i)
        if not os.path.exists(p):
            return None
        try:
            t = self.pq.read_table(p)
        except Exception:  # unreadable: compute it again
            return None
        names = set(t.column_names)
        if t.num_rows != rows or not set(outputs) | {"status"} <= names:
            return None
        return {c: t.column(c).to_numpy() for c in list(outputs) + ["status"]}

    def save(self, i: int, res: Dict[str, np.ndarray]) -> None:
        import pyarrow as pa
        tmp = self.path(i) + f".tmp{os.getpid()}"
        self.pq.write_table(pa.table(res), tmp)
        os.replace(tmp, self.path(i))

    def finish(self, table) -> None:
        tmp = self.final + f".tmp{os.getpid()}"
        table.to_parquet(tmp, index=False)
        os.replace(tmp, self.final)
        import shutil
        shutil.rmtree(self.dir, ignore_errors=True)
