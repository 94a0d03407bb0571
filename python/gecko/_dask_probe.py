"""Connecting to a Dask scheduler within a deadline, whatever listens at the address.

dask.distributed trusts the first bytes it reads: a silent TCP listener makes it wait far past its
own timeout, and an HTTP server's reply is read as a frame length of exabytes (MemoryError). So the
address is probed first with a plain socket under one deadline: connect, then read the greeting a
Dask listener sends at once on every connection (distributed.comm.tcp: an 8-byte total length, an
8-byte frame count, 8 bytes per frame length); anything else is a ConnectionError. The Client is
then created in a daemon thread and waited for until the same deadline.
"""
from __future__ import annotations

import socket
import struct
import threading
import time
from typing import Tuple
from urllib.parse import urlsplit

_MAX_GREETING = 1 << 20  # a scheduler's handshake is a few hundred bytes


def split_address(addr: str) -> Tuple[str, str, int]:
    """(scheme, host, port) of ``tcp://host:port`` / ``tls://host:port``; ValueError otherwise."""
    u = urlsplit(addr)
    try:
        port = u.port
    except ValueError:
        port = None
    if u.scheme not in ("tcp", "tls") or not u.hostname or port is None:
        raise ValueError(f"executor: {addr!r} is not an address host:port")
    return u.scheme, u.hostname, port


def _recv_exact(sock: socket.socket, n: int, deadline: float) -> bytes:
    buf = b""
    while len(buf) < n:
        left = deadline - time.monotonic()
        if left <= 0:
            raise socket.timeout("timed out")
        sock.settimeout(left)
        part = sock.recv(n - len(buf))
        if not part:
            raise ConnectionError("the peer closed the connection")
        buf += part
    return buf


def probe(addr: str, deadline: float) -> None:
    """Returns when a Dask TCP listener greets at ``addr`` before ``deadline`` (time.monotonic());
    raises ConnectionError saying what was found instead."""
    scheme, host, port = split_address(addr)
    left = deadline - time.monotonic()
    try:
        sock = socket.create_connection((host, port), timeout=max(left, 0.001))
    except OSError as exc:
        raise ConnectionError(f"cannot connect to {host}:{port} ({exc.strerror or exc})") from None
    try:
        if scheme == "tls":  # the greeting is encrypted: connecting is all we can check here
            return
        try:
            (total,) = struct.unpack("<Q", _recv_exact(sock, 8, deadline))
            if not 16 <= total <= _MAX_GREETING:
                raise ConnectionError(f"something that is not a Dask scheduler answers at {host}:{port} "
                                      f"(its first bytes are not a Dask message)")
            body = _recv_exact(sock, total, deadline)
            (nframes,) = struct.unpack("<Q", body[:8])
            if not 1 <= nframes <= 64 or 8 + 8 * nframes > total:
                raise ConnectionError(f"something that is not a Dask scheduler answers at {host}:{port}")
        except socket.timeout:
            raise ConnectionError(f"something listens at {host}:{port} but does not greet like a Dask "
                                  "scheduler (no handshake in time)") from None
        except OSError as exc:
            raise ConnectionError(f"{host}:{port}: {exc.strerror or exc}") from None
    finally:
        sock.close()


def client_within(make_client, deadline: float):
    """``make_client()`` run in a daemon thread; ConnectionError when it has not returned by
    ``deadline`` (the thread is left to end on its own)."""
    box = {}
    lock = threading.Lock()

    def run():
        try:
            box["client"] = make_client()
        except BaseException as exc:  # handed to the caller
            box["error"] = exc
            return
        with lock:
            close = getattr(box["client"], "close", None)
            if box.get("abandoned") and close is not None:  # the caller gave up: close the late client
                close()

    t = threading.Thread(target=run, name="gecko-dask-connect", daemon=True)
    t.start()
    t.join(max(deadline - time.monotonic(), 0.0))
    with lock:
        if "client" not in box and "error" not in box:
            box["abandoned"] = True
            raise ConnectionError("the Dask client did not connect in time")
    if "error" in box:
        raise box["error"]
    return box["client"]
