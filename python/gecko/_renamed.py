"""Output names kept as deprecated aliases (issue 13): "slope_k" does not say which slope it is.

The critical line has two slopes (docs/theory/two_level_seta.md, "The slope k"): ``slope_at_zero``,
the tangent dFn/dFt at Ft = 0, and ``paper_k``, the paper's k of eq (16) (paper 001), the
least-squares slope of the lower part of the line. The old names are the first one's, same values.
"""
from __future__ import annotations

import warnings

#: deprecated output name -> its replacement (the same values)
RENAMED = {"slope_k": "slope_at_zero", "abs_slope_k": "abs_slope_at_zero", "inv_abs_k": "inv_abs_slope_at_zero"}


def warn_renamed(names, where: str, stacklevel: int = 2) -> None:
    """One DeprecationWarning for the deprecated names among ``names`` (none if there are none),
    naming ``where`` they were asked for and each replacement."""
    old = [n for n in dict.fromkeys(names) if n in RENAMED]
    if old:
        warnings.warn(f"{where}: " + "; ".join(f"{n!r} is deprecated, use {RENAMED[n]!r} (the same values)"
                                               for n in old), DeprecationWarning, stacklevel=stacklevel + 1)
