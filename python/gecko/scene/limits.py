"""Limits checked before any work: a scene's size, its nesting, its names, its output folder.

A scene is refused at validation (``gecko validate``, ``gecko run``, ``load_scene``) when its
estimated work or memory is above the limits, which are set by environment variables:

    GECKO_MAX_DESIGNS     designs a scene may compute in all (studies and [sweep]); default 10^8
    GECKO_MAX_MEMORY_MB   estimated memory of the results, MiB; default half the machine's memory

Each must be an integer >= 1 (anything else is refused like a bad scene). The estimate counts
the designs of every study and of the [sweep], and the bytes of their results (a sweep holds its
design table, its chunks and the final table at once: 3 copies of (9 + outputs + 1) numbers per
design, plus the grid's combinations while it is built).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Optional

from .errors import SceneError

MAX_NESTING = 64          # tables and arrays inside each other; no scene needs more than a few
MAX_NAME_BYTES = 255      # a file name on every common file system
DEFAULT_MAX_DESIGNS = 10**8
ENV_MAX_DESIGNS = "GECKO_MAX_DESIGNS"
ENV_MAX_MEMORY = "GECKO_MAX_MEMORY_MB"


def env_int(name: str, default: int, lo: int = 1, hi: int = 10**15) -> int:
    """An integer environment variable in [lo, hi]; SceneError naming it otherwise."""
    raw = os.environ.get(name)
    if raw is None or raw.strip() == "":
        return default
    try:
        v = int(raw.strip())
    except ValueError:
        raise SceneError(f"environment variable {name} = {raw!r} is not allowed: need an integer in "
                         f"[{lo}, {hi}]") from None
    if not lo <= v <= hi:
        raise SceneError(f"environment variable {name} = {v} is out of range: need an integer in [{lo}, {hi}]")
    return v


def _default_memory_mb() -> int:
    try:
        total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
        return max(256, int(total // 2 // 2**20))
    except (ValueError, OSError, AttributeError):  # pragma: no cover - not POSIX
        return 8192


def max_designs() -> int:
    return env_int(ENV_MAX_DESIGNS, DEFAULT_MAX_DESIGNS)


def max_memory_mb() -> int:
    return env_int(ENV_MAX_MEMORY, _default_memory_mb())


def check_nesting(data, source: Optional[str] = None) -> None:
    """SceneError when tables/arrays are nested deeper than MAX_NESTING (iterative: no recursion)."""
    stack = [(data, 1, "")]
    while stack:
        v, depth, key = stack.pop()
        if isinstance(v, dict):
            items = [(f"{key}.{k}" if key else str(k), x) for k, x in v.items()]
        elif isinstance(v, list):
            items = [(f"{key}[{i}]", x) for i, x in enumerate(v)]
        else:
            continue
        if depth > MAX_NESTING:
            raise SceneError(f"tables and arrays are nested more than {MAX_NESTING} levels deep", key=key,
                             source=source)
        stack.extend((x, depth + 1, k) for k, x in items)


def check_name(name, key: str, what: str = "name") -> str:
    """A name that becomes part of a file name: a non-empty string, no control characters, no path
    separators, not '.' or '..', at most MAX_NAME_BYTES bytes in UTF-8."""
    if not isinstance(name, str) or not name:
        raise SceneError(f"need a non-empty string; got {name!r}", key=key)
    bad = next((i for i, c in enumerate(name) if ord(c) < 32 or ord(c) == 127 or 0x80 <= ord(c) < 0xA0), None)
    if bad is not None:
        raise SceneError(f"{what} {name!r} has a control character at position {bad}; it becomes a file name",
                         key=key)
    if any(c in name for c in "/\\") or name in (".", ".."):
        raise SceneError(f"{what} {name!r} is not allowed: no '/' or '\\', not '.' or '..' (it becomes a file name)",
                         key=key)
    try:
        n = len(name.encode("utf-8"))
    except UnicodeEncodeError:
        raise SceneError(f"{what} {name!r} is not valid Unicode text", key=key) from None
    if n > MAX_NAME_BYTES:
        raise SceneError(f"{what} is {n} bytes long in UTF-8: need at most {MAX_NAME_BYTES} (it becomes a file name)",
                         key=key)
    return name


@dataclass
class Work:
    designs: int
    points: int          # states solved or evaluated: designs x grid points, one per sweep design
    memory_bytes: int

    def describe(self) -> str:
        return f"{self.designs} designs, {self.points} points, about {_mb(self.memory_bytes)} of results"


def _mb(b: int) -> str:
    if b < 2**20:
        return f"{b / 2**10:.3g} KiB"
    return f"{b / 2**20:.3g} MiB" if b < 2**30 else f"{b / 2**30:.3g} GiB"


def estimate(scene) -> Work:
    """Designs, points and bytes of results a scene asks for (no grid or table is built)."""
    from .grids import DEFAULT_GRIDS
    designs, points, mem = 0, 0, 0
    for st in scene.studies:
        n = len(st.points)
        designs += n
        per_points = 0
        for name, spec in st.outputs.items():
            g = spec.options.get("grid") if hasattr(spec, "options") else None
            g = g if g is not None else DEFAULT_GRIDS.get(name)
            per_points += 1 if g is None else _grid_size(g, scene.resolution)
        points += n * per_points
        mem += n * (4 * 8 * per_points + 256)  # Ft, Fn, theta, status per point; a row per design
    sw = scene.sweep
    if sw is not None:
        n = sw.size if sw.designs != "table" else _table_rows(sw.table)
        designs += n
        points += n
        per = 3 * 8 * (9 + len(sw.outputs) + 1)  # the design table, the chunks, the final table
        if sw.designs == "grid":  # the combinations as Python tuples while the grid is built
            per += 64 + 32 * len(sw.grid)
        mem += n * per
    return Work(designs, points, mem)


def _grid_size(g, res: float) -> int:
    if isinstance(g, list):
        return len(g)
    if isinstance(g, dict):
        if isinstance(g.get("num"), (int, float)) and math.isfinite(g["num"]):
            return max(2, int(round(g["num"] * res)))  # as schema.eval_grid scales a range
        if isinstance(g.get("values"), list):
            return len(g["values"])
    return 100


def _table_rows(path: Optional[str]) -> int:
    """Rows of a design table without reading it: Parquet's metadata, or a CSV's size over the mean
    length of its first lines."""
    if not path:
        return 0
    try:
        if path.endswith(".parquet"):
            try:
                import pyarrow.parquet as pq
                return int(pq.read_metadata(path).num_rows)
            except Exception:  # unreadable here: reading it at run time gives the real error
                return 0
        size = os.path.getsize(path)
        with open(path, "rb") as f:
            head = f.read(1 << 16)
        lines = head.count(b"\n")
        return max(1, size * max(lines, 1) // max(len(head), 1)) if head else 0
    except OSError:
        return 0


def check_work(scene) -> Work:
    """The estimate, or SceneError when it is above GECKO_MAX_DESIGNS / GECKO_MAX_MEMORY_MB."""
    w = estimate(scene)
    lim_d, lim_m = max_designs(), max_memory_mb()
    key = "sweep" if scene.sweep is not None and scene.sweep.size * 2 > w.designs else "study"
    if w.designs > lim_d:
        raise SceneError(f"this scene would compute {w.designs} designs, above the limit of {lim_d} "
                         f"(set {ENV_MAX_DESIGNS} to raise it); nothing was computed", key=key)
    if w.memory_bytes > lim_m * 2**20:
        raise SceneError(f"this scene's results would need about {_mb(w.memory_bytes)} of memory, above the limit "
                         f"of {lim_m} MiB (set {ENV_MAX_MEMORY} to raise it); nothing was computed", key=key)
    return w


def check_file_names(scene) -> None:
    """Every file a run writes has a name of at most MAX_NAME_BYTES bytes."""
    from pathlib import Path
    stem = Path(scene.source).stem if scene.source not in (None, "<dict>") else ""
    names = []
    for i, p in enumerate(scene.plots):
        for fmt in list(getattr(p, "formats", ())) + ["csv", "svg"]:
            names.append((f"{p.name}.{fmt}", f"plot[{i}].name"))
    for st in scene.studies:
        for out in st.outputs:
            names.append((f"{stem}.{st.name}.{out}.csv" if stem else f"{st.name}.{out}.csv", f"{st.key}.name"))
    if scene.sweep is not None:
        names.append((f".gecko-sweep-{stem or 'scene'}.{scene.sweep.name}", "sweep.name"))
        names.append((f"{scene.sweep.name}.parquet", "sweep.name"))
    if scene.optimize is not None:
        names.append((f"{scene.optimize.name}.json", "optimize.name"))
    for n, key in names:
        b = len(n.encode("utf-8", "replace"))
        if b > MAX_NAME_BYTES:
            raise SceneError(f"the output file {n[:40]!r}... would have a {b}-byte name: need at most "
                             f"{MAX_NAME_BYTES}; use a shorter name", key=key, source=scene.source)
