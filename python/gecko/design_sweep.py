"""gecko.design_sweep — characteristics of many two-level seta designs as one table.

A sweep takes many designs (a grid, a random / Sobol / Latin-hypercube sample over bounds, or a
table of your own) and returns a pandas DataFrame with one row per design, in the order of the
designs: the nine design fields, the outputs asked for, and ``status``::

    import gecko
    designs = gecko.sobol_designs({"EI1": (1, 10), "alpha2": (0, 0.5)}, n=4096, seed=1)
    table = gecko.sweep(designs, outputs=["fn0", "slope_at_zero", "max_pull_off"], out="runs/")

Only what the outputs need is solved (docs/theory/two_level_seta.md, gecko/seta/characteristics.hpp):

* ``ft_max`` and the ``small_*`` quantities are closed forms: no solver runs;
* ``fn0``, ``slope_at_zero``, ``sticky_at_rest`` need the natural state at Ft = 0 (one homotopy solve
  and one linear solve for the slope), no line is traced;
* ``max_pull_off``, ``ft_at_max_pull_off``, ``min_fn``, ``ft_at_line_end``, ``fn_at_line_end``,
  ``line_end``, ``folds``, ``admissible_end_ft``, ``admissible_to_end`` follow the critical line to
  its end. The minimum (``max_pull_off`` and its Ft) is taken over the admissible part of the line
  only: from Ft = 0 to ``admissible_end_ft``, the first state where the deformed seta crosses the
  substrate (``admissible_to_end``: the whole followed line is admissible). Where the minimum sits
  at the end of the followed range and that end is not (Ft)max (EA2 = inf; a line given up),
  ``max_pull_off`` is NaN, as in ``TwoLevelSeta.characteristics()``, and ``max_pull_off_bound``
  (with ``max_pull_off_is_bound``) gives the bound over the followed range;
* ``slope_at_zero`` is the tangent dFn/dFt at Ft = 0 (``slope_k``: its deprecated alias, the same
  column with a DeprecationWarning); ``paper_k`` is the paper's k (eq (16): the least-squares slope
  through (0, (Fn)0) over the lower part of the line, see ``SetaCharacteristics.paper_k``).

Designs are computed in chunks by the compiled batch call ``_core.seta_characteristics_batch``
(C++ threads, the GIL released), or as Dask tasks on a ``dask.distributed`` cluster
(``client=`` or ``executor="dask://host:port"``). Every design is solved on its own, so the table
is bitwise the same for any chunk size, thread count and executor. With ``out=DIR`` each chunk is
written to ``DIR/sweep-<key>/chunk-NNNNNN.parquet`` as soon as it is done (``<key>``: a hash of the
designs, the outputs, the chunk size and the gecko version) and the finished table to
``DIR/sweep-<key>.parquet``; a run that was interrupted resumes from the chunks already written.
Every file carries ``FILE.manifest.json`` (its sha256 and the hash of its designs, outputs and the
gecko version) and is verified before reuse; a file that fails (edited, copied over another,
truncated, unreadable) is computed again with a ``gecko._integrity.ResultFileWarning``. One
process at a time writes a sweep (``DIR/sweep-<key>.lock``; a second one gets
``gecko._locking.FolderLocked``). Ctrl-C keeps the finished blocks of the current chunk and raises
KeyboardInterrupt saying where the run stopped.

Status codes (``status``, as ``gecko.STATUS``): 0 solved; 1 natural state not found; 3 the
natural state is outside the model's forms; 5 invalid design (only with ``errors="nan"``; the
default ``errors="raise"`` refuses the whole sweep before computing, naming the first bad row);
6 the line's minimum was not established: the line was given up before its end (no convergence at
a singular point, point budget, stalled: ``line_end`` says which; the minimum over the followed part
would only be a bound) or the minimum could not be refined, so ``max_pull_off``,
``ft_at_max_pull_off`` and ``min_fn`` are NaN, while ``fn0``, ``slope_at_zero`` and where the line
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
``pip install "gecko-adhesion[sweep]"`` (a Dask cluster: ``pip install "gecko-adhesion[dask]"``).
"""
from __future__ import annotations

import hashlib
import os
import time
from typing import Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _core
from ._renamed import warn_renamed
from . import seta as _seta
# sampling and bounds live in gecko.designs; the old names stay importable from here
from .designs import (DEFAULTS, FIELDS, _DOMAIN, _EXTRA, _check_fields, _count, _fixed, _need,  # noqa: F401
                      _qmc, _scale, _table, design_grid, design_matrix, latin_hypercube_designs,
                      parse_bounds, random_designs, sobol_designs)
from .designs import parse_bounds as _parse_bounds  # noqa: F401  (the old private name)
from ._sweep_store import SweepInterrupted as _SweepInterrupted
from ._vectorize import check_table as _check_table
from ._sweep_store import SweepStore as _SweepStore
from ._sweep_store import compute_resumable as _compute_resumable

__all__ = ["sweep", "SWEEP_OUTPUTS", "DEFAULT_SWEEP_OUTPUTS", "design_grid", "random_designs",
           "sobol_designs", "latin_hypercube_designs"]

#: output -> solver depth it needs (0: closed forms, 1: natural state at Ft = 0, 2: the line)
SWEEP_OUTPUTS: Dict[str, int] = {
    "ft_max": 0, "small_fn0": 0, "small_slope_k": 0, "small_contact_length": 0, "small_non_sticky": 0,
    "fn0": 1, "slope_k": 1, "slope_at_zero": 1, "sticky_at_rest": 1,
    "max_pull_off": 2, "ft_at_max_pull_off": 2, "min_fn": 2, "ft_at_line_end": 2, "fn_at_line_end": 2,
    "line_end": 2, "folds": 2, "admissible_end_ft": 2, "admissible_to_end": 2, "paper_k": 2,
    "max_pull_off_bound": 2, "max_pull_off_is_bound": 2,
}
DEFAULT_SWEEP_OUTPUTS = ("fn0", "slope_at_zero", "max_pull_off", "ft_at_max_pull_off", "ft_max", "sticky_at_rest")
# column name in the table -> key in the compiled call's result
_SOURCE = {"ft_at_max_pull_off": "ft_at_min_fn"}
_BOOL = ("sticky_at_rest", "small_non_sticky", "admissible_to_end", "max_pull_off_is_bound")

#: ``line_end`` codes -> why the followed line stopped (gecko/seta/detail/continuation.hpp; the
#: same table as ``TwoLevelSeta.characteristics().end``)
LINE_END = _seta._LINE_END

# ---- computing one chunk --------------------------------------------------------------------------

def _depth(outputs: Sequence[str]) -> int:
    return max((SWEEP_OUTPUTS[o] for o in outputs), default=0)


# line_end codes where the continuation gave up before the line's end (no convergence at a
# singular point, point budget, stalled): the minimum over the followed part is only a bound
_GIVEN_UP = (_seta.LineEnd.no_convergence, _seta.LineEnd.max_points, _seta.LineEnd.stalled)
# outputs that claim something of the whole line: NaN (and status 6) when it was given up
_WHOLE_LINE = ("max_pull_off", "ft_at_max_pull_off", "min_fn")


#: designs per thread in one compiled call within a chunk (Ctrl-C keeps the blocks finished)
_BLOCK_PER_THREAD = 64


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
        given_up = (status == _seta.CriticalStatus.converged) & (np.isin(np.asarray(d["line_end"]), _GIVEN_UP)
                                                                 | np.isnan(d["min_fn"]))
        status[given_up] = _seta.CriticalStatus.not_reached
    out = {"status": status}
    for o in outputs:
        a = np.asarray(d[_SOURCE.get(o, o)])
        if o in _WHOLE_LINE and given_up.any():
            a = np.where(given_up, np.nan, a)
        if o in _BOOL:
            a = a.astype(bool)
        elif o == "line_end":  # -1: not computed (invalid design)
            a = np.where(status == _seta.CriticalStatus.invalid_input, -1, a).astype(np.int8)
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
            from .progress import Progress
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
    bad = np.flatnonzero(st == _seta.CriticalStatus.invalid_input)
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
    from ._dask_probe import client_within, probe
    deadline = time.monotonic() + timeout  # one deadline for the probe and the client
    try:
        probe(addr, deadline)  # a bounded handshake of our own first: see gecko._dask_probe
        return client_within(lambda: distributed.Client(addr, timeout=max(deadline - time.monotonic(), 0.1),
                                                        set_as_default=False), deadline), True
    except ValueError as exc:
        raise ValueError(f"executor = {executor!r} is not allowed: need 'dask://host:port' ({exc})") from None
    except (OSError, TimeoutError) as exc:
        raise ConnectionError(f"executor = {executor!r}: no Dask scheduler answered at {addr} within "
                              f"{timeout:g} s ({type(exc).__name__}: {exc}). Start one with `dask scheduler` "
                              "and workers with `dask worker ADDRESS`, or use executor = 'threads'") from None


def sweep(designs, outputs: Optional[Sequence[str]] = None, *, out: Optional[Union[str, os.PathLike]] = None,
          chunk_size: int = 10000, threads: Optional[int] = None, client=None, executor: Optional[str] = None,
          connect_timeout: float = 10.0, errors: str = "raise",
          progress: Union[None, bool, Callable[[int, int], None]] = None):
    """Characteristic quantities of many seta designs: one pandas table, one row per design, in order.

    Only what the requested outputs need is solved (``SWEEP_OUTPUTS`` gives each output's depth:
    closed forms, the natural state, or the whole line). The table is bitwise the same for any chunk
    size, thread count and executor. Needs the ``[sweep]`` extra; a Dask cluster needs ``[dask]``.

    Parameters
    ----------
    designs : pandas.DataFrame, mapping, array_like of shape (n, 9), or sequence of TwoLevelSeta
        The designs; a table's missing fields take the reference scene's values. See
        :func:`design_grid`, :func:`random_designs`, :func:`sobol_designs`,
        :func:`latin_hypercube_designs`.
    outputs : sequence of str, optional
        Names from ``SWEEP_OUTPUTS`` (default ``DEFAULT_SWEEP_OUTPUTS``); ``status`` is always there.
    out : str or os.PathLike, optional
        A folder: chunks go to ``out/sweep-<key>/`` as they finish, the table to
        ``out/sweep-<key>.parquet``; the same call after an interruption computes only what is missing.
    chunk_size : int, optional
        Designs per chunk (default 10000).
    threads : int, optional
        C++ threads per chunk (default: the CPU count; one per Dask task unless given).
    client : dask.distributed.Client, optional
        Run the chunks as Dask tasks on this client.
    executor : str, optional
        ``"threads"`` (default) or ``"dask://host:port"`` to connect to a scheduler.
    connect_timeout : float, optional
        Seconds to wait for the scheduler before ``ConnectionError`` (default 10).
    errors : {"raise", "nan"}, optional
        Refuse a sweep with an invalid design before computing (default), or keep it as a row with
        status 5.
    progress : None, bool or callable, optional
        None: a bar on a terminal; True/False; or a callable(done, total), called with the number
        of designs done once at the start (the designs already on disk) and after each chunk.

    Returns
    -------
    pandas.DataFrame
        The design fields, the outputs and ``status``; ``table.attrs["sweep"]`` holds the key, path,
        chunks computed and reused, and the time taken.

    Raises
    ------
    ValueError
        If a design, an output name or an argument is invalid (naming the row and the parameter).
    ConnectionError
        If no Dask scheduler answers at ``executor``.
    gecko._optional.MissingOptionalDependency
        If pandas (or pyarrow for ``out``, distributed for a cluster) is not installed; the message
        names the extra that installs it.

    Examples
    --------
    >>> import gecko
    >>> designs = gecko.design_grid({"alpha2": [0.3, 0.5]})
    >>> table = gecko.sweep(designs, outputs=["fn0", "max_pull_off"], progress=False)
    >>> table[["alpha2", "fn0", "max_pull_off", "status"]].round(4)
       alpha2     fn0  max_pull_off  status
    0     0.3  2.3606        0.0000       0
    1     0.5  0.4935        2.4502       0
    """
    warn_renamed(_check_outputs(outputs), "gecko.sweep outputs")  # once per call, at the caller's line
    return _sweep(designs, outputs, out=out, chunk_size=chunk_size, threads=threads, client=client,
                  executor=executor, connect_timeout=connect_timeout, errors=errors, progress=progress)


def _sweep(designs, outputs, *, out, chunk_size, threads, client, executor, connect_timeout, errors, progress):
    """:func:`sweep` without its deprecation warning: for callers that warned of a renamed output in
    their own terms already (a scene warns with the key it was parsed from)."""
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
    _check_table(designs)  # no silent conversion of complex, text, dates, None (gecko._vectorize)
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
    store = None
    try:
        final_path = None
        if out is not None:
            store = _SweepStore(os.fspath(out), key, pq, _version(), matrix, outputs, chunk_size)
            final_path = store.final
            cached = store.load_final(n, FIELDS)  # verified: hash, inputs key, content
            if cached is not None:  # the whole sweep is already there
                table = pd.DataFrame({c: cached[c] for c in list(FIELDS) + outputs + ["status"]})
                table.attrs["sweep"] = {"key": key, "path": final_path, "chunks": len(starts),
                                        "chunks_computed": 0, "chunks_reused": len(starts),
                                        "seconds": time.perf_counter() - t0, "executor": "file"}
                return table
            for i in range(len(starts)):
                parts[i] = store.load(i)
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
            # depth >= 1: smaller blocks, so that Ctrl-C keeps what finished
            step = chunk_size if _depth(outputs) == 0 else _BLOCK_PER_THREAD * nt
            for i in todo:
                done(i, _compute_resumable(store, i, matrix[starts[i]:starts[i] + chunk_size], outputs, nt,
                                           compute_chunk, step))
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
        cols = {f: matrix[:, j] for j, f in enumerate(FIELDS)}
        for c in outputs + ["status"]:
            cols[c] = np.concatenate([p[c] for p in parts])
        table = pd.DataFrame(cols)
        if store is not None:
            store.finish(table)
    except KeyboardInterrupt:
        finished = sum(p["status"].size for p in parts if p is not None) + (store.partial_rows if store else 0)
        where = (f"; the finished work is kept in {store.dir}: run the same sweep (designs, outputs, chunk_size, "
                 "out=) again to resume" if store is not None else " (nothing kept: pass out=DIR to resume "
                 "an interrupted sweep)")
        raise _SweepInterrupted(f"sweep interrupted after {finished} of {n} designs (chunks of {chunk_size})"
                                + where, finished, n, store.dir if store is not None else None) from None
    finally:
        if bar is not None:
            bar.close()
        if owned:
            dask_client.close()
        if store is not None:
            store.close()

    table.attrs["sweep"] = {"key": key, "path": final_path, "chunks": len(starts), "chunks_computed": len(todo),
                            "chunks_reused": reused, "seconds": time.perf_counter() - t0, "executor": how}
    return table
