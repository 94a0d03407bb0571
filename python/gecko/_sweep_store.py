"""The files of one sweep with ``out=DIR``, verified on reuse (gecko._integrity).

    DIR/sweep-<key>.parquet                     the finished table (+ .manifest.json)
    DIR/sweep-<key>/chunk-NNNNNN.parquet        finished chunks while the sweep runs (+ manifests)
    DIR/sweep-<key>/chunk-NNNNNN.partial.parquet  the designs of a chunk finished before an interrupt
    DIR/sweep-<key>.lock                        held by the process writing them

A chunk's inputs key hashes its own slice of the designs, the outputs and the solver version, so a
chunk copied over another, or over the same chunk of another sweep, is refused even with its
manifest; its content is then checked too (row count, one numeric column per output, status codes,
no NaN in a solved row's numbers). Whatever fails is computed again with a ResultFileWarning.
"""
from __future__ import annotations

import hashlib
import os
import shutil
import warnings
from typing import Dict, List, Optional, Sequence

import numpy as np

from ._integrity import (ResultFileWarning, atomic_write, describe_os_error, remove_with_manifest, verify,
                         write_manifest)
from ._locking import FolderLock
from .seta import STATUS as _seta_status

# every status code of gecko.STATUS (a sweep uses 0, 1, 3, 5, 6 today; a code added to the solver
# must not make every stored chunk look damaged)
_STATUS = tuple(sorted(_seta_status))


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C during a sweep; the message says how far it got and how to resume. ``done``,
    ``total``: designs; ``folder``: where the finished work is kept (None without ``out=``)."""

    def __init__(self, message: str, done: int = 0, total: int = 0, folder: Optional[str] = None):
        super().__init__(message)
        self.done, self.total, self.folder = done, total, folder


def inputs_key(version: str, block: np.ndarray, outputs: Sequence[str], what: str) -> str:
    h = hashlib.sha256()
    h.update(f"gecko.sweep.{what}/2\0{version}\0{','.join(outputs)}\0{block.shape}\0".encode())
    h.update(np.ascontiguousarray(block, dtype="<f8").tobytes())
    return h.hexdigest()


def check_columns(cols: Dict[str, np.ndarray], rows: int, outputs: Sequence[str]) -> Optional[str]:
    """Why ``cols`` cannot be a sweep's result for ``rows`` designs, or None."""
    for c in list(outputs) + ["status"]:
        if c not in cols:
            return f"column {c!r} is missing"
        a = cols[c]
        if a.dtype.kind not in "biuf":
            return f"column {c!r} holds {a.dtype} values, not numbers"
        if a.shape != (rows,):
            return f"column {c!r} has {a.shape[0] if a.ndim else 0} rows, need {rows}"
    st = cols["status"]
    if not np.isin(st, _STATUS).all():
        return f"status codes outside {_STATUS}"
    ok = st == 0
    for c in outputs:
        a = cols[c]
        if a.dtype.kind == "f" and np.isnan(a[ok]).any():
            return f"NaN in column {c!r} of a row with status 0"
    return None


class SweepStore:
    def __init__(self, out: str, key: str, pq, version: str, matrix: np.ndarray, outputs: Sequence[str],
                 chunk_size: int):
        self.out, self.key, self.pq = out, key, pq
        self.version, self.matrix, self.outputs, self.chunk_size = version, matrix, list(outputs), chunk_size
        self.partial_rows = 0  # designs of the chunk interrupted by Ctrl-C, saved as a partial chunk
        self.dir = os.path.join(out, f"sweep-{key}")
        self.final = os.path.join(out, f"sweep-{key}.parquet")
        try:
            os.makedirs(out, exist_ok=True)
        except OSError as exc:
            raise ValueError(f"out = {out!r}: cannot create the folder: {exc.strerror or exc}") from None
        self.lock = FolderLock(os.path.join(out, f"sweep-{key}.lock"), f"out = {out!r} (sweep {key})")
        try:
            self.lock.acquire()
        except PermissionError as exc:
            raise ValueError(f"out = {out!r}: cannot write there: {exc.strerror or exc}") from None
        try:
            os.makedirs(self.dir, exist_ok=True)
            for name in os.listdir(self.dir):  # temporaries of a killed run (any gecko): we hold the lock
                if ".parquet.tmp" in name or ".json.tmp" in name:
                    os.unlink(os.path.join(self.dir, name))
        except OSError as exc:
            self.lock.release()
            raise ValueError(f"out = {out!r}: cannot create the folder: {exc.strerror or exc}") from None

    def close(self) -> None:
        self.lock.release()

    # ---- reading ---------------------------------------------------------------------------------
    def _warn(self, path: str, why: str) -> None:
        warnings.warn(f"gecko.sweep: {path}: {why}; computing it again", ResultFileWarning, stacklevel=4)

    def _read(self, path: str, inputs: str, rows: int, outputs: Sequence[str]):
        if not os.path.exists(path):
            return None
        why = verify(path, inputs)
        cols = None
        if why is None:
            try:
                t = self.pq.read_table(path)
                cols = {c: t.column(c).to_numpy() for c in t.column_names}
            except Exception as exc:  # any damage: compute it again, never stop the run
                why = f"unreadable ({type(exc).__name__}: {exc})"
        if why is None:
            why = check_columns(cols, rows, outputs)
        if why is not None:
            self._warn(path, why)
            remove_with_manifest(path)
            return None
        return cols

    def path(self, i: int, partial: bool = False) -> str:
        return os.path.join(self.dir, f"chunk-{i:06d}{'.partial' if partial else ''}.parquet")

    def block(self, i: int, rows: Optional[int] = None) -> np.ndarray:
        s = i * self.chunk_size
        return self.matrix[s:s + (self.chunk_size if rows is None else rows)]

    def load(self, i: int) -> Optional[Dict[str, np.ndarray]]:
        b = self.block(i)
        cols = self._read(self.path(i), inputs_key(self.version, b, self.outputs, "chunk"), len(b), self.outputs)
        return None if cols is None else {c: cols[c] for c in self.outputs + ["status"]}

    def load_partial(self, i: int) -> Optional[Dict[str, np.ndarray]]:
        p = self.path(i, True)
        if not os.path.exists(p):
            return None
        try:
            rows = int(self.pq.read_metadata(p).num_rows)
        except Exception:
            rows = 0
        if not 0 < rows < len(self.block(i)):
            self._warn(p, "unreadable or of the wrong size")
            remove_with_manifest(p)
            return None
        cols = self._read(p, inputs_key(self.version, self.block(i, rows), self.outputs, "chunk"), rows,
                          self.outputs)
        return None if cols is None else {c: cols[c] for c in self.outputs + ["status"]}

    def load_final(self, n: int, fields: Sequence[str]):
        """The finished table when it verifies, else None (with a warning when one was there)."""
        cols = self._read(self.final, inputs_key(self.version, self.matrix, self.outputs, "table"), n, self.outputs)
        if cols is None:
            return None
        for j, f in enumerate(fields):
            a = cols.get(f)
            if a is None or a.dtype != np.float64 or a.tobytes() != np.ascontiguousarray(self.matrix[:, j]).tobytes():
                self._warn(self.final, f"design column {f!r} differs from the designs asked for")
                remove_with_manifest(self.final)
                return None
        return cols

    # ---- writing ---------------------------------------------------------------------------------
    def _write(self, path: str, res: Dict[str, np.ndarray], inputs: str) -> None:
        import pyarrow as pa
        try:
            remove_with_manifest(path)
            atomic_write(path, lambda tmp: self.pq.write_table(pa.table(res), tmp))
            write_manifest(path, inputs)
        except OSError as exc:
            remove_with_manifest(path)
            raise OSError(exc.errno, describe_os_error(exc, path) + "; the chunks finished before are kept in "
                          f"{self.dir}: run the same sweep again to resume") from None

    def save(self, i: int, res: Dict[str, np.ndarray]) -> None:
        b = self.block(i)
        self._write(self.path(i), res, inputs_key(self.version, b, self.outputs, "chunk"))
        remove_with_manifest(self.path(i, True))

    def save_partial(self, i: int, res: Dict[str, np.ndarray]) -> None:
        rows = res["status"].size
        self._write(self.path(i, True), res, inputs_key(self.version, self.block(i, rows), self.outputs, "chunk"))

    def finish(self, table) -> None:
        try:
            remove_with_manifest(self.final)
            atomic_write(self.final, lambda tmp: table.to_parquet(tmp, index=False))
            write_manifest(self.final, inputs_key(self.version, self.matrix, self.outputs, "table"))
        except OSError as exc:
            remove_with_manifest(self.final)
            raise OSError(exc.errno, describe_os_error(exc, self.final) + "; the chunks are kept in "
                          f"{self.dir}: run the same sweep again to resume") from None
        shutil.rmtree(self.dir, ignore_errors=True)


def compute_resumable(store: Optional[SweepStore], i: int, block: np.ndarray, outputs: List[str], threads: int,
                      compute, step: int) -> Dict[str, np.ndarray]:
    """Chunk ``i`` in blocks of ``step`` designs; on Ctrl-C the designs finished so far are saved as a
    partial chunk (with ``out=``) and the next run starts after them."""
    pieces: List[Dict[str, np.ndarray]] = []
    k = 0
    if store is not None:
        got = store.load_partial(i)
        if got is not None:
            pieces.append(got)
            k = got["status"].size
    try:
        while k < len(block):
            pieces.append(compute(block[k:k + step], outputs, threads))
            k += step
    except KeyboardInterrupt:
        if store is not None and pieces:
            try:
                store.save_partial(i, concat(pieces))
                store.partial_rows = sum(p["status"].size for p in pieces)
            except OSError as exc:  # a full disk must not hide the interrupt: say so, go on stopping
                warnings.warn(f"gecko.sweep: the finished part of chunk {i} could not be kept: {exc}",
                              ResultFileWarning, stacklevel=2)
        raise
    return concat(pieces)


def concat(pieces: List[Dict[str, np.ndarray]]) -> Dict[str, np.ndarray]:
    if len(pieces) == 1:
        return pieces[0]
    return {c: np.concatenate([p[c] for p in pieces]) for c in pieces[0]}
