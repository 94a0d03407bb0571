"""Fault injection for the Dask executor: whatever listens at the address that is not a Dask
scheduler (silent, HTTP, garbage, closing) gives ConnectionError within connect_timeout, never a
hang or a MemoryError. The time bound is the behaviour under test; it is checked with a wide
margin (before, a silent listener held the caller for over 60 s with connect_timeout = 5)."""
import http.server
import socket
import socketserver
import threading
import time

import pytest

pytest.importorskip("pandas")
pytest.importorskip("distributed")

import gecko  # noqa: E402
from gecko import _dask_probe  # noqa: E402

TIMEOUT = 1.0
MARGIN = 10.0


class _Listener:
    """A TCP server on 127.0.0.1 whose connections get ``reply`` (bytes, or None: silence) and are
    then held open (``close=False``) or closed."""

    def __init__(self, reply=None, close=False):
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.port = self.sock.getsockname()[1]
        self.reply, self.close, self.conns, self.stop = reply, close, [], False
        self.t = threading.Thread(target=self._serve, daemon=True)
        self.t.start()

    def _serve(self):
        self.sock.settimeout(0.1)
        while not self.stop:
            try:
                c, _ = self.sock.accept()
            except OSError:
                continue
            if self.reply:
                c.sendall(self.reply)
            if self.close:
                c.close()
            else:
                self.conns.append(c)

    def shutdown(self):
        self.stop = True
        self.t.join()
        for c in self.conns:
            c.close()
        self.sock.close()


@pytest.fixture
def listener(request):
    lst = _Listener(*request.param)
    yield lst
    lst.shutdown()


def sweep_at(port):
    t0 = time.monotonic()
    with pytest.raises(ConnectionError, match=rf"no Dask scheduler answered at tcp://127.0.0.1:{port}") as ei:
        gecko.sweep({"EI1": [5.0]}, outputs=["fn0"], executor=f"dask://127.0.0.1:{port}",
                    connect_timeout=TIMEOUT, progress=False)
    return time.monotonic() - t0, str(ei.value)


@pytest.mark.parametrize("listener, why", [
    ((None, False), "does not greet like a Dask scheduler"),
    ((b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n", False), "not a Dask scheduler"),
    ((b"\xff" * 64, False), "not a Dask scheduler"),
    ((None, True), "closed the connection"),
], indirect=["listener"])
def test_non_dask_listener_gives_connection_error_within_the_timeout(listener, why):
    elapsed, msg = sweep_at(listener.port)
    assert why in msg
    assert elapsed < TIMEOUT + MARGIN


def test_http_server_gives_connection_error_not_memory_error():
    class Quiet(http.server.BaseHTTPRequestHandler):
        def log_message(self, *a):
            pass

    srv = socketserver.TCPServer(("127.0.0.1", 0), Quiet)
    t = threading.Thread(target=srv.serve_forever, daemon=True)
    t.start()
    try:
        elapsed, msg = sweep_at(srv.server_address[1])
        assert "Dask" in msg and elapsed < TIMEOUT + MARGIN
    finally:
        srv.shutdown()
        srv.server_close()


def test_client_creation_is_bounded_too():
    release = threading.Event()
    t0 = time.monotonic()
    with pytest.raises(ConnectionError, match="did not connect in time"):
        _dask_probe.client_within(lambda: release.wait(30), time.monotonic() + 0.2)
    assert time.monotonic() - t0 < 0.2 + MARGIN
    release.set()


def test_a_dask_greeting_passes_the_probe():
    import struct
    body = struct.pack("<Q", 1) + struct.pack("<Q", 5) + b"hello"
    lst = _Listener(struct.pack("<Q", len(body)) + body)
    try:
        _dask_probe.probe(f"tcp://127.0.0.1:{lst.port}", time.monotonic() + TIMEOUT)
    finally:
        lst.shutdown()


@pytest.mark.parametrize("addr", ["tcp://127.0.0.1", "tcp://:80", "udp://h:1"])
def test_addresses_without_host_or_port_are_refused(addr):
    with pytest.raises(ValueError):
        _dask_probe.split_address(addr)
