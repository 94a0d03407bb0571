"""Optional dependencies: import them on demand, and when one is missing say which extra installs it.

gecko's core needs numpy only. Plotting, design tables, Parquet output, Dask clusters and the
optimiser pull in larger packages, declared as extras of the ``gecko-adhesion`` distribution
(pyproject.toml). Every place that needs one calls :func:`require`, so the error a user sees names
the package, what needed it, and the exact command that installs it.
"""
from __future__ import annotations

import importlib
from types import ModuleType
from typing import Optional

__all__ = ["DISTRIBUTION", "EXTRAS", "MissingOptionalDependency", "install_hint", "require"]

#: the name on the package index (the import name stays ``gecko``)
DISTRIBUTION = "gecko-adhesion"

#: the extra that installs each optional top-level module (scipy is in two; callers say which)
EXTRAS = {
    "matplotlib": "plot",
    "pandas": "sweep",
    "pyarrow": "sweep",
    "scipy": "optimize",
    "dask": "dask",
    "distributed": "dask",
    "tomli": None,  # a plain dependency on Python < 3.11; missing only in a hand-made environment
}


class MissingOptionalDependency(ModuleNotFoundError):
    """An optional package is not installed; the message names the extra that installs it.

    A subclass of :class:`ModuleNotFoundError` (hence of :class:`ImportError`), so code that
    catches either keeps working.
    """


def install_hint(extra: Optional[str], package: Optional[str] = None) -> str:
    """The shell command that installs an extra (or, with ``extra=None``, a package).

    Parameters
    ----------
    extra : str or None
        Name of an extra of the ``gecko-adhesion`` distribution, e.g. ``"sweep"``.
    package : str, optional
        Used when ``extra`` is None: the package to install directly.

    Returns
    -------
    str
        A command line, quoted for a POSIX shell.

    Examples
    --------
    >>> install_hint("sweep")
    'pip install "gecko-adhesion[sweep]"'
    >>> install_hint(None, "tomli")
    'pip install tomli'
    """
    if extra is None:
        if package is None:
            raise ValueError("install_hint needs an extra or a package name")
        return f"pip install {package}"
    return f'pip install "{DISTRIBUTION}[{extra}]"'


def require(module: str, what: str, extra: Optional[str] = None) -> ModuleType:
    """Import ``module``, or raise an error that says what needed it and how to install it.

    Parameters
    ----------
    module : str
        Dotted module name, e.g. ``"pyarrow.parquet"``.
    what : str
        What needs it, for the message, e.g. ``"gecko.sweep(out=...)"``.
    extra : str, optional
        The extra to name; default: the one :data:`EXTRAS` lists for the top-level package.

    Returns
    -------
    module
        The imported module.

    Raises
    ------
    MissingOptionalDependency
        If the module (or a module it imports) cannot be imported.

    Examples
    --------
    >>> require("math", "this example").sqrt(4.0)
    2.0
    >>> import sys
    >>> saved = sys.modules.get("pandas")
    >>> sys.modules["pandas"] = None  # pretend pandas is not installed
    >>> try:
    ...     require("pandas", "gecko design tables")
    ... except ImportError as exc:
    ...     print(exc)
    gecko design tables needs the optional package 'pandas', which is not installed: pip install "gecko-adhesion[sweep]"
    >>> if saved is None: del sys.modules["pandas"]
    ... else: sys.modules["pandas"] = saved
    """
    top = module.split(".")[0]
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        if extra is None:
            extra = EXTRAS.get(top)
        hint = install_hint(extra, top)
        missing = getattr(exc, "name", None) or top
        if missing.split(".")[0] == top:
            msg = f"{what} needs the optional package {top!r}, which is not installed: {hint}"
        else:  # the package is there but one of its own dependencies is not (or is broken)
            msg = f"{what} needs the optional package {top!r}, which failed to import ({exc}): {hint}"
        raise MissingOptionalDependency(msg, name=top) from None
