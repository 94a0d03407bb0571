"""gecko.sweep on a real dask.distributed LocalCluster (2 worker processes): the table equals the
local one row for row (bitwise), through client= and executor="dask://...", with resuming; an
address where no scheduler answers fails clearly within the stated timeout. About 15-30 s."""
import socket
import time

import pytest

pd = pytest.importorskip("pandas", reason="gecko.sweep needs pandas (pip install \"gecko-adhesion[sweep]\")")
distributed = pytest.importorskip("distributed", reason="the Dask executor needs dask.distributed "
                                                         "(pip install \"gecko-adhesion[dask]\")")

import gecko  # noqa: E402

BOUNDS = {"EI1": (2.0, 8.0), "EI2": (0.5, 4.0, "log"), "alpha2": (0.2, 0.8), "EA2": (20.0, 200.0, "log")}
OUTPUTS = ["fn0", "slope_at_zero", "max_pull_off", "ft_at_max_pull_off", "ft_max", "sticky_at_rest", "line_end"]


def bitwise_equal(a, b):
    assert list(a.columns) == list(b.columns)
    for c in a.columns:
        x, y = a[c].to_numpy(), b[c].to_numpy()
        assert x.dtype == y.dtype and x.tobytes() == y.tobytes(), c


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None,
                                  worker_dashboard_address=None) as c:
        yield c


def test_dask_table_equals_local_row_for_row(cluster):
    d = gecko.sobol_designs(BOUNDS, 96, seed=5)
    d.loc[7, "alpha1"] = 1.3  # an invalid design travels as status 5 too
    local = gecko.sweep(d, outputs=OUTPUTS, chunk_size=10, threads=2, errors="nan", progress=False)
    with distributed.Client(cluster) as client:
        remote = gecko.sweep(d, outputs=OUTPUTS, chunk_size=10, client=client, errors="nan", progress=False)
        # the chunks really ran on both worker processes
        workers = client.run(lambda: __import__("os").getpid())
        assert len(set(workers.values())) == 2
    assert remote.attrs["sweep"]["executor"].startswith("dask")
    assert local["status"].tolist().count(5) == 1
    bitwise_equal(remote, local)


def test_executor_address_and_resume(cluster, tmp_path):
    pytest.importorskip("pyarrow")
    d = gecko.latin_hypercube_designs(BOUNDS, 40, seed=2)
    local = gecko.sweep(d, outputs=["fn0", "max_pull_off"], chunk_size=8, progress=False)
    address = "dask://" + cluster.scheduler_address[len("tcp://"):]

    class Stop(Exception):
        pass

    def stop(done, total):
        if done >= 16:
            raise Stop

    with pytest.raises(Stop):
        gecko.sweep(d, outputs=["fn0", "max_pull_off"], chunk_size=8, out=tmp_path, executor=address,
                    progress=stop)
    t = gecko.sweep(d, outputs=["fn0", "max_pull_off"], chunk_size=8, out=tmp_path, executor=address,
                    progress=False)
    a = t.attrs["sweep"]
    assert a["chunks_reused"] >= 2 and a["chunks_reused"] + a["chunks_computed"] == 5
    bitwise_equal(t, local)


def _closed_port() -> int:
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()  # nothing listens there now
    return port


def test_unreachable_scheduler_fails_clearly_within_the_timeout():
    port = _closed_port()
    t0 = time.monotonic()
    with pytest.raises(ConnectionError, match=rf"no Dask scheduler answered at tcp://127.0.0.1:{port} within 2 s"):
        gecko.sweep({"EI1": [5.0]}, outputs=["fn0"], executor=f"dask://127.0.0.1:{port}", connect_timeout=2,
                    progress=False)
    assert time.monotonic() - t0 < 2 + 10  # the timeout, plus the slack of a loaded machine


def test_bad_connect_timeout():
    with pytest.raises(ValueError, match=r"connect_timeout = -1 is out of range"):
        gecko.sweep({"EI1": [5.0]}, executor="dask://127.0.0.1:1", connect_timeout=-1, progress=False)
