"""The one timing helper of the Python benchmarks (bench/*/ scripts; the C++ benches share
bench/harness.hpp).

Every script times the same way: optional warm-up calls (not timed), then ``repeats`` timed calls,
each measured in wall time (``time.perf_counter``) and in process CPU time of all threads
(``time.process_time``); it reports the median (and the best and every sample), writes what it
measured through :func:`write_results`, and notes the machine with :func:`machine_note` (the
machine is shared, so the load average goes beside the numbers).

A script in bench/<name>/ imports it with its folder's parent on the path::

    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # bench/, for _timing
    from _timing import time_call, write_results, machine_note
"""
from __future__ import annotations

import json
import os
import platform
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, List, Tuple, Union

__all__ = ["Timing", "time_call", "timed_once", "machine_note", "machine_info", "write_results"]


@dataclass
class Timing:
    """Samples of one timed call: wall and CPU seconds per repeat."""

    wall: List[float] = field(default_factory=list)
    cpu: List[float] = field(default_factory=list)
    result: Any = None  # what the last timed call returned

    @property
    def median(self) -> float:
        """Median wall time (s)."""
        return statistics.median(self.wall)

    @property
    def best(self) -> float:
        """Shortest wall time (s)."""
        return min(self.wall)

    @property
    def cpu_median(self) -> float:
        """Median process CPU time of all threads (s)."""
        return statistics.median(self.cpu)


def time_call(fn: Callable[[], Any], repeats: int = 5, warmup: int = 0) -> Timing:
    """Call ``fn()`` ``warmup`` times untimed, then ``repeats`` times timed (wall and CPU)."""
    if repeats < 1:
        raise ValueError(f"repeats = {repeats}: must be >= 1")
    for _ in range(warmup):
        fn()
    t = Timing()
    for _ in range(repeats):
        w0, c0 = time.perf_counter(), time.process_time()
        t.result = fn()
        t.wall.append(time.perf_counter() - w0)
        t.cpu.append(time.process_time() - c0)
    return t


def timed_once(fn: Callable[[], Any]) -> Tuple[Any, float]:
    """``(fn(), wall seconds)`` of one call (for runs too long to repeat)."""
    t = time_call(fn, repeats=1)
    return t.result, t.wall[0]


def machine_info() -> dict:
    """CPUs, 1-minute load average, platform and Python: what goes beside every timing."""
    return {"cpu_count": os.cpu_count(), "load_average": os.getloadavg()[0], "machine": platform.machine(),
            "platform": platform.platform(), "python": platform.python_version()}


def machine_note() -> str:
    """One line for a results table's caption."""
    m = machine_info()
    return f"{m['cpu_count']} CPUs, load average {m['load_average']:.1f}, {m['machine']}, Python {m['python']}"


def write_results(path: Union[str, Path], content: Union[str, dict, list], append: bool = False) -> Path:
    """Write a results file (text as is; a dict or list as indented JSON), creating its folder;
    ``append=True`` adds to what a run of the C++ bench wrote there before."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    text = content if isinstance(content, str) else json.dumps(content, indent=1) + "\n"
    with p.open("a" if append else "w", encoding="utf-8") as f:
        f.write(text)
    return p
