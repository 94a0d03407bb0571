"""The one error type of the scene engine: names the file, the key path and what is allowed."""
from __future__ import annotations

from typing import Optional


class SceneError(ValueError):
    """A scene that cannot be read, is malformed, or asks for something out of range.

    ``str(err)`` reads ``FILE: KEY.PATH: message``, so a user can go straight to the line. A
    subclass of :class:`ValueError`.

    Parameters
    ----------
    reason : str
        What is wrong and what is allowed.
    key : str, optional
        Dotted key path, e.g. ``study[0].parameters.EI1``.
    source : str, optional
        The file, or ``<dict>``.

    Attributes
    ----------
    reason, key, source : str
        As given, for programs.

    Examples
    --------
    >>> from gecko.scene import SceneError
    >>> err = SceneError("need a number", key="study[0].parameters.EI1", source="a.toml")
    >>> str(err)
    'a.toml: study[0].parameters.EI1: need a number'
    >>> isinstance(err, ValueError)
    True
    """

    def __init__(self, reason: str, *, key: str = "", source: Optional[str] = None):
        self.reason = reason
        self.key = key
        self.source = source
        super().__init__(self._text())

    def _text(self) -> str:
        where = [p for p in (self.source, self.key) if p]
        return ": ".join(where + [self.reason])

    def at(self, source: Optional[str] = None, key_prefix: str = "") -> "SceneError":
        """The same error with the file name and/or an outer key path filled in."""
        key = self.key
        if key_prefix:
            key = key_prefix + ("." + key if key and not key.startswith("[") else key)
        return SceneError(self.reason, key=key, source=source if source is not None else self.source)

    def __str__(self) -> str:  # keep it current if attributes were changed
        return self._text()
