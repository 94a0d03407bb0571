"""Reading TOML: stdlib ``tomllib`` (Python >= 3.11), else the ``tomli`` package."""
from __future__ import annotations

from pathlib import Path

from .errors import SceneError

try:  # pragma: no cover - which branch runs depends on the interpreter
    import tomllib as _toml
except ModuleNotFoundError:  # pragma: no cover
    try:
        import tomli as _toml  # type: ignore[no-redef]
    except ModuleNotFoundError:
        _toml = None


def load_toml(path) -> dict:
    """Parse a TOML file with ``tomllib`` (Python >= 3.11) or ``tomli``.

    Parameters
    ----------
    path : str or os.PathLike
        The file.

    Returns
    -------
    dict
        The parsed document.

    Raises
    ------
    SceneError
        If the file is missing, unreadable, not UTF-8 or not valid TOML (naming it), or if no TOML
        reader is available (``pip install tomli`` on Python < 3.11).

    Examples
    --------
    >>> from pathlib import Path
    >>> from gecko.scene.toml import load_toml
    >>> _ = Path("s.toml").write_text('title = "demo"')
    >>> load_toml("s.toml")
    {'title': 'demo'}
    """
    source = str(path)
    if _toml is None:
        raise SceneError("reading TOML scenes needs Python >= 3.11 (tomllib) or the 'tomli' package "
                         "(pip install tomli); a scene can also be passed as a Python dict",
                         source=source)
    try:
        data = Path(path).read_bytes()
    except OSError as exc:
        raise SceneError(f"cannot read the file: {exc.strerror or exc}", source=source) from None
    try:
        return _toml.loads(data.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise SceneError(f"not UTF-8 text ({exc.reason} at byte {exc.start})", source=source) from None
    except _toml.TOMLDecodeError as exc:
        raise SceneError(f"not valid TOML: {exc}", source=source) from None
    except RecursionError:  # arrays or inline tables nested hundreds of levels deep
        raise SceneError("not a usable scene: tables and arrays are nested too deeply", source=source) from None
