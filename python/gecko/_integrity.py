"""Result files that can be trusted on reuse: atomic writes and a sidecar manifest.

Every result file ``F`` (a sweep's chunk, its final table) gets ``F.manifest.json``, written
atomically *after* ``F``: the sha256 of F's bytes, its size, and the key of its inputs (a hash of
the designs it holds, the outputs asked for and the solver version). A file is reused only when the
manifest is there, names the same inputs, and the bytes still hash to the recorded value; a file
edited by hand, copied over another, truncated, or left without a manifest (a run killed between
the two renames, an older gecko) is refused with the reason, and the caller computes it again.
"""
from __future__ import annotations

import errno
import hashlib
import json
import os
import secrets
from typing import Any, Callable, Dict, Optional

MANIFEST_SUFFIX = ".manifest.json"
_FORMAT = "gecko.result/1"


class ResultFileWarning(RuntimeWarning):
    """A result file on disk could not be trusted (changed, for other inputs, unreadable) and its
    content is computed again."""


def owner_tag() -> str:
    """``PID@HOST`` of this process, for names of temporary files and folders (host: letters,
    digits and '-' only), so that a later run can tell whether their owner still lives."""
    import socket
    host = "".join(c if c.isalnum() or c == "-" else "-" for c in socket.gethostname())[:40]
    return f"{os.getpid()}@{host}"


def tmp_name(path: str) -> str:
    """A unique temporary name next to ``path`` (same folder: the rename is atomic)."""
    return f"{path}.tmp-{owner_tag()}-{secrets.token_hex(4)}"


def file_sha256(path: str) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def atomic_write(path: str, write: Callable[[str], None]) -> None:
    """``write(tmp)`` then rename over ``path``: ``path`` is either the old file or the complete new
    one. The temporary file is removed when writing fails (a full disk, an interrupt)."""
    tmp = tmp_name(path)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_text_atomic(path: str, text: str) -> None:
    def w(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
    atomic_write(path, w)


def manifest_path(path: str) -> str:
    return path + MANIFEST_SUFFIX


def write_manifest(path: str, inputs: str, **extra: Any) -> None:
    """Records ``path``'s hash and the key of its inputs; call it after ``path`` is in place."""
    doc = {"format": _FORMAT, "sha256": file_sha256(path), "bytes": os.path.getsize(path),
           "inputs": inputs, **extra}
    write_text_atomic(manifest_path(path), json.dumps(doc, sort_keys=True) + "\n")


def remove_with_manifest(path: str) -> None:
    # the manifest first: a file without one is never trusted
    for p in (manifest_path(path), path):
        try:
            os.unlink(p)
        except FileNotFoundError:
            pass


def verify(path: str, inputs: str) -> Optional[str]:
    """None when ``path`` is exactly what its manifest recorded for these ``inputs``; else why not."""
    if not os.path.exists(path):
        return "missing"
    try:
        with open(manifest_path(path), "rb") as f:
            doc: Dict[str, Any] = json.loads(f.read().decode("utf-8"))
    except FileNotFoundError:
        return "no manifest (written by an interrupted run or an older gecko)"
    except (OSError, ValueError) as exc:
        return f"unreadable manifest ({exc})"
    if not isinstance(doc, dict) or doc.get("format") != _FORMAT:
        return "unknown manifest format"
    if doc.get("inputs") != inputs:
        return "written for other inputs (designs, outputs or gecko version differ)"
    try:
        size = os.path.getsize(path)
        if size != doc.get("bytes"):
            return f"content changed since written ({size} bytes, the manifest says {doc.get('bytes')})"
        if file_sha256(path) != doc.get("sha256"):
            return "content changed since written (sha256 differs from the manifest)"
    except OSError as exc:
        return f"unreadable ({exc.strerror or exc})"
    return None


def describe_os_error(exc: OSError, path: str) -> str:
    what = "no space left on the device" if exc.errno == errno.ENOSPC else (exc.strerror or str(exc))
    return f"cannot write {path!r}: {what}"


def check_writable(folder: str) -> None:
    """Creates ``folder`` (with parents) and a temporary file in it; OSError naming the folder when
    either fails, so that a run finds out before it computes."""
    os.makedirs(folder, exist_ok=True)
    probe = os.path.join(folder, f".gecko-write-test-{owner_tag()}-{secrets.token_hex(4)}")
    fd = os.open(probe, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o600)
    os.close(fd)
    os.unlink(probe)
