"""gecko.progress — a one-line progress bar for long runs (scenes, sweeps).

Imports nothing from the rest of the package, so every layer may use it.
"""
from __future__ import annotations

import time
from typing import Callable, Optional

__all__ = ["Progress", "format_duration"]


def format_duration(seconds: float) -> str:
    """``seconds`` as ``M:SS`` (or ``H:MM:SS`` from an hour on); ``--:--`` when not known."""
    if not (seconds >= 0 and seconds < 1e8):  # NaN, inf, negative: no estimate yet
        return "--:--"
    s = int(round(seconds))
    h, rem = divmod(s, 3600)
    m, s = divmod(rem, 60)
    return f"{h}:{m:02d}:{s:02d}" if h else f"{m}:{s:02d}"


class Progress:
    """A one-line progress bar on a terminal, shown only for work longer than ``delay`` seconds.

    The line reads ``label [####....] done/total what  rate/s  ETA m:ss``: the rate is the mean
    over the whole run so far (items per second), the ETA the remaining items at that rate.
    ``clock`` (default ``time.monotonic``) is the time source, replaceable for tests."""

    def __init__(self, total: int, label: str = "", stream=None, enabled: Optional[bool] = None,
                 delay: float = 1.0, clock: Callable[[], float] = time.monotonic):
        import sys
        self.stream = stream if stream is not None else sys.stderr
        if enabled is None:
            enabled = bool(getattr(self.stream, "isatty", lambda: False)())
        self.enabled, self.total, self.label, self.delay = enabled, max(total, 1), label, delay
        self.clock = clock
        self.done, self.start, self.shown = 0, clock(), False
        self._width = 0

    def rate(self) -> float:
        """Items per second since the start (NaN before any time has passed)."""
        elapsed = self.clock() - self.start
        return self.done / elapsed if elapsed > 0 else float("nan")

    def eta(self) -> float:
        """Seconds left at the mean rate so far (NaN while the rate is not known, 0 when done)."""
        left = max(self.total - self.done, 0)
        if left == 0:
            return 0.0
        r = self.rate()
        return left / r if r > 0 else float("nan")

    def line(self, what: str = "") -> str:
        """The bar's text (without the carriage return)."""
        frac = min(self.done / self.total, 1.0)
        bar = "#" * int(30 * frac) + "." * (30 - int(30 * frac))
        r = self.rate()
        rate = f"{r:.3g}/s" if r == r else "--/s"
        return (f"{self.label} [{bar}] {self.done}/{self.total} {what[:30]:<30} "
                f"{rate}  ETA {format_duration(self.eta())}")

    def advance(self, n: int = 1, what: str = "") -> None:
        self.done += n
        if not self.enabled or self.clock() - self.start < self.delay:
            return
        text = self.line(what)
        self._width = max(self._width, len(text))
        self.stream.write("\r" + text.ljust(self._width))
        self.stream.flush()
        self.shown = True

    def close(self) -> None:
        if self.shown:
            self.stream.write("\r" + " " * self._width + "\r")
            self.stream.flush()
