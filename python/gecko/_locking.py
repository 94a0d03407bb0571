"""One writer per result folder, and no litter from killed runs.

``FolderLock``: an advisory lock (``fcntl.flock``) on a lock file; the kernel drops it when its
owner dies, so a killed run never blocks the next one. The file holds the owner's pid and host
for the message another process gets.

``make_staging`` / ``clean_stale``: temporary folders named ``PREFIX<pid>@<host>-<random>``; those
whose owner (same host) is no longer running are removed by the next run.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import socket
import tempfile
import time
from typing import Optional

from ._integrity import owner_tag

try:
    import fcntl
except ImportError:  # pragma: no cover - Windows: O_EXCL lock files instead
    fcntl = None  # type: ignore[assignment]


class FolderLocked(RuntimeError):
    """Another live process holds the lock of a result folder."""


def pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    if os.name == "nt":  # pragma: no cover - os.kill(pid, 0) would end the process there
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process: alive
        return True
    return True


def _host() -> str:
    return owner_tag().split("@", 1)[1]


_OWNED = re.compile(r"(\d+)@([A-Za-z0-9-]*)-")


#: an entry named without an owner (an older gecko's PREFIX<random>) counts as stale after this
LEGACY_STALE_SECONDS = 24 * 3600


def owner_dead(name: str, prefix: str, folder: Optional[str] = None) -> bool:
    """True when ``name`` (PREFIX<pid>@<host>-...) belongs to a process of this host that is gone,
    or (with ``folder``) has no owner in its name and was last changed over a day ago."""
    if not name.startswith(prefix):
        return False
    m = _OWNED.match(name[len(prefix):])
    if m:
        return m.group(2) == _host() and not pid_alive(int(m.group(1)))
    if folder is None:
        return False
    try:
        return time.time() - os.stat(os.path.join(folder, name)).st_mtime > LEGACY_STALE_SECONDS
    except OSError:
        return False


def clean_stale(folder: str, prefix: str) -> int:
    """Removes ``folder``'s entries named PREFIX<pid>@<host>-... whose owner is dead; returns how many."""
    n = 0
    try:
        names = os.listdir(folder)
    except OSError:
        return 0
    for name in names:
        if owner_dead(name, prefix, folder):
            p = os.path.join(folder, name)
            if os.path.isdir(p) and not os.path.islink(p):
                shutil.rmtree(p, ignore_errors=True)
            else:
                try:
                    os.unlink(p)
                except OSError:
                    pass
            n += 1
    return n


def make_staging(folder: str, prefix: str) -> str:
    """A fresh folder ``PREFIX<pid>@<host>-XXXX`` in ``folder``, after removing stale ones."""
    clean_stale(folder, prefix)
    return tempfile.mkdtemp(prefix=f"{prefix}{owner_tag()}-", dir=folder)


class FolderLock:
    """``with FolderLock(path):`` holds ``path`` (a lock file) or raises FolderLocked naming the
    owner; ``timeout`` > 0 waits that many seconds for it first."""

    def __init__(self, path: str, what: str = "this folder", timeout: float = 0.0):
        self.path, self.what, self.timeout = path, what, float(timeout)
        self.fd: Optional[int] = None

    def _owner(self) -> str:
        try:
            with open(self.path, encoding="utf-8") as f:
                d = json.loads(f.read() or "{}")
            return f"pid {d.get('pid')} on {d.get('host')}"
        except (OSError, ValueError):
            return "another process"

    def _try(self) -> bool:
        if fcntl is None:  # pragma: no cover
            try:
                self.fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_RDWR, 0o644)
                return True
            except FileExistsError:
                return False
        fd = os.open(self.path, os.O_CREAT | os.O_RDWR, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            return False
        try:  # the file we locked must still be the one at self.path (the last owner unlinks it)
            if os.fstat(fd).st_ino != os.stat(self.path).st_ino:
                raise FileNotFoundError
        except FileNotFoundError:
            os.close(fd)
            return self._try()
        self.fd = fd
        return True

    def acquire(self) -> "FolderLock":
        deadline = time.monotonic() + self.timeout
        while not self._try():
            if time.monotonic() >= deadline:
                raise FolderLocked(f"{self.what} is in use by {self._owner()} (lock file {self.path}); "
                                   "wait for that run to finish, or write to another folder")
            time.sleep(0.05)
        info = json.dumps({"pid": os.getpid(), "host": socket.gethostname(), "since": time.time()})
        os.ftruncate(self.fd, 0)
        os.write(self.fd, info.encode())
        return self

    def release(self) -> None:
        if self.fd is None:
            return
        try:
            os.unlink(self.path)  # while still holding it (see _try's inode check)
        except OSError:
            pass
        os.close(self.fd)
        self.fd = None

    def __enter__(self) -> "FolderLock":
        return self.acquire()

    def __exit__(self, *exc) -> None:
        self.release()


def held_by_other(path: str) -> bool:
    """True when a live process holds the lock file ``path`` (used before removing a folder)."""
    if not os.path.exists(path):
        return False
    lk = FolderLock(path)
    if lk._try():
        os.close(lk.fd)  # not ours to unlink
        lk.fd = None
        return False
    return True


def remove_unless_locked(folder) -> bool:
    """Removes ``folder`` unless a live process holds a ``*.lock`` file in it (a second run still
    writing there); True when removed."""
    folder = os.fspath(folder)
    try:
        names = os.listdir(folder)
    except OSError:
        return False
    if any(n.endswith(".lock") and held_by_other(os.path.join(folder, n)) for n in names):
        return False
    shutil.rmtree(folder, ignore_errors=True)
    return True
