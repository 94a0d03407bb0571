"""Fault injection: result files that were edited, copied, truncated, half-written or unreadable;
two writers on one folder; Ctrl-C; a full disk and an unwritable folder; killed runs' litter.
Each fault is injected and must be detected: recomputed with a warning, or refused with a message
that says what happened, never reused silently and never an ArrowInvalid traceback.
Tiny sweeps (closed forms or the natural state only), so the file stays fast."""
import errno
import os
import shutil
import subprocess
import sys
import warnings

import numpy as np
import pytest

pd = pytest.importorskip("pandas", reason="gecko.sweep needs pandas (pip install \"gecko-adhesion[sweep]\")")
pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

import gecko  # noqa: E402
from gecko import _integrity, _locking, design_sweep  # noqa: E402
from gecko._integrity import ResultFileWarning  # noqa: E402

BOUNDS = {"EI1": (2.0, 8.0), "alpha2": (0.2, 0.8)}
OUTS = ["fn0", "ft_max"]


def designs(n=9, seed=5):
    return gecko.random_designs(BOUNDS, n, seed=seed)


def bitwise_equal(a, b):
    assert list(a.columns) == list(b.columns)
    for c in a.columns:
        assert a[c].to_numpy().tobytes() == b[c].to_numpy().tobytes(), c


class Stop(Exception):
    pass


def stop_after(k):
    def cb(done, total):
        if done >= k:
            raise Stop
    return cb


def key_of(d, outputs=OUTS, chunk=3):
    return design_sweep.sweep_key(design_sweep.design_matrix(d), outputs, chunk)


def partial_run(tmp_path, d, chunks_done=2, chunk=3):
    """A run stopped after ``chunks_done`` chunks: their files stay in sweep-<key>/."""
    with pytest.raises(Stop):
        gecko.sweep(d, outputs=OUTS, chunk_size=chunk, out=tmp_path, progress=stop_after(chunks_done * chunk))
    return tmp_path / f"sweep-{key_of(d, chunk=chunk)}"


def rerun(tmp_path, d, chunk=3, expect_warning=True):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        t = gecko.sweep(d, outputs=OUTS, chunk_size=chunk, out=tmp_path, progress=False)
    got = [x for x in w if issubclass(x.category, ResultFileWarning)]
    assert bool(got) == expect_warning, [str(x.message) for x in w]
    return t, [str(x.message) for x in got]


def rewrite(path, edit, keep_manifest=True):
    """Replaces a parquet file's table by ``edit(table)``; with ``keep_manifest=False`` also writes
    a fresh, valid manifest, so that only the content checks can catch the fault."""
    t = pq.read_table(path)
    pq.write_table(edit(t), path)
    if not keep_manifest:
        doc = __import__("json").loads(open(_integrity.manifest_path(str(path))).read())
        _integrity.write_manifest(str(path), doc["inputs"])


def set_col(t, name, values):
    return t.set_column(t.column_names.index(name), name, pa.array(values))


# ---- chunks ----------------------------------------------------------------------------------------

def test_every_result_file_has_a_manifest_with_hash_and_inputs_key(tmp_path):
    d = designs()
    folder = partial_run(tmp_path, d)
    for name in ("chunk-000000.parquet", "chunk-000001.parquet"):
        p = str(folder / name)
        assert _integrity.verify(p, "wrong inputs").startswith("written for other inputs")
        doc = __import__("json").loads(open(_integrity.manifest_path(p)).read())
        assert doc["sha256"] == _integrity.file_sha256(p) and len(doc["inputs"]) == 64
    t, _ = rerun(tmp_path, d, expect_warning=False)
    assert t.attrs["sweep"]["chunks_reused"] == 2
    final = t.attrs["sweep"]["path"]
    assert os.path.isfile(_integrity.manifest_path(final)) and not folder.exists()


def test_edited_chunk_is_computed_again(tmp_path):
    d = designs()
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    folder = partial_run(tmp_path, d)
    rewrite(folder / "chunk-000000.parquet", lambda t: set_col(t, "fn0", [1.0, 2.0, 3.0]))
    t, msgs = rerun(tmp_path, d)
    assert "chunk-000000" in msgs[0] and "content changed" in msgs[0]
    assert t.attrs["sweep"]["chunks_reused"] == 1 and t.attrs["sweep"]["chunks_computed"] == 2
    bitwise_equal(t, fresh)


def test_chunk_copied_over_another_with_its_manifest_is_computed_again(tmp_path):
    d = designs()
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    folder = partial_run(tmp_path, d)
    for suffix in ("", _integrity.MANIFEST_SUFFIX):
        shutil.copyfile(folder / ("chunk-000000.parquet" + suffix), folder / ("chunk-000001.parquet" + suffix))
    t, msgs = rerun(tmp_path, d)
    assert "chunk-000001" in msgs[0] and "other inputs" in msgs[0]
    bitwise_equal(t, fresh)


@pytest.mark.parametrize("fault, why", [
    (lambda t: set_col(t, "fn0", [np.nan, 1.0, 2.0]), "NaN in column 'fn0' of a row with status 0"),
    (lambda t: set_col(t, "fn0", ["a", "b", "c"]), "not numbers"),
    (lambda t: t.slice(0, 2), "rows"),
    (lambda t: set_col(t, "status", pa.array([0, 42, 0], pa.int8())), "status codes"),
    (lambda t: t.drop(["ft_max"]), "missing"),
])
def test_chunk_with_bad_content_and_a_forged_manifest_is_computed_again(tmp_path, fault, why):
    d = designs()
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    folder = partial_run(tmp_path, d)
    rewrite(folder / "chunk-000000.parquet", fault, keep_manifest=False)
    t, msgs = rerun(tmp_path, d)
    assert why in msgs[0]
    bitwise_equal(t, fresh)


@pytest.mark.parametrize("damage", ["garbage", "truncated", "empty", "no_manifest", "bad_manifest"])
def test_unreadable_chunk_never_stops_the_run(tmp_path, damage):
    d = designs()
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    folder = partial_run(tmp_path, d)
    p = folder / "chunk-000001.parquet"
    if damage == "garbage":
        p.write_bytes(b"PAR1 not really parquet PAR1")
    elif damage == "truncated":
        p.write_bytes(p.read_bytes()[:40])
    elif damage == "empty":
        p.write_bytes(b"")
    elif damage == "no_manifest":
        os.unlink(_integrity.manifest_path(str(p)))
    else:
        open(_integrity.manifest_path(str(p)), "w").write("{not json")
    if damage in ("garbage", "truncated", "empty"):  # forge the manifest: the reader must cope
        _integrity.write_manifest(str(p), __import__("json").loads(
            open(_integrity.manifest_path(str(folder / "chunk-000000.parquet"))).read())["inputs"])
    t, msgs = rerun(tmp_path, d)
    assert "chunk-000001" in msgs[0]
    bitwise_equal(t, fresh)


# ---- the final table -------------------------------------------------------------------------------

def finished(tmp_path, d):
    t = gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    return t, t.attrs["sweep"]["path"]


@pytest.mark.parametrize("fault", ["edited", "truncated", "string_column", "garbage", "no_manifest",
                                   "design_changed_forged_manifest", "nan_forged_manifest"])
def test_damaged_final_table_is_computed_again(tmp_path, fault):
    d = designs()
    fresh, final = finished(tmp_path, d)
    if fault == "edited":
        rewrite(final, lambda t: set_col(t, "ft_max", np.zeros(9)))
    elif fault == "truncated":
        b = open(final, "rb").read()
        open(final, "wb").write(b[:len(b) // 2])
    elif fault == "string_column":
        rewrite(final, lambda t: set_col(t, "fn0", [str(i) for i in range(9)]), keep_manifest=False)
    elif fault == "garbage":
        open(final, "wb").write(b"\0" * 100)
        _integrity.write_manifest(final, "x")
    elif fault == "no_manifest":
        os.unlink(_integrity.manifest_path(final))
    elif fault == "design_changed_forged_manifest":
        rewrite(final, lambda t: set_col(t, "EI1", np.full(9, 3.0)), keep_manifest=False)
    else:
        rewrite(final, lambda t: set_col(t, "fn0", np.full(9, np.nan)), keep_manifest=False)
    t, msgs = rerun(tmp_path, d)
    assert os.path.basename(final) in msgs[0]
    assert t.attrs["sweep"]["chunks_computed"] == 3
    bitwise_equal(t, fresh)
    t2, _ = rerun(tmp_path, d, expect_warning=False)  # and the table written now verifies
    assert t2.attrs["sweep"]["executor"] == "file"


def test_final_table_of_other_designs_is_not_reused(tmp_path):
    d1, d2 = designs(seed=1), designs(seed=2)
    _, f1 = finished(tmp_path, d1)
    _, f2 = finished(tmp_path, d2)
    for suffix in ("", _integrity.MANIFEST_SUFFIX):  # the table of d1 copied over that of d2
        shutil.copyfile(f1 + suffix, f2 + suffix)
    t, msgs = rerun(tmp_path, d2)
    assert "other inputs" in msgs[0]
    bitwise_equal(t, gecko.sweep(d2, outputs=OUTS, progress=False))


# ---- two writers, killed runs ------------------------------------------------------------------------

def test_second_writer_of_the_same_sweep_is_refused_clearly(tmp_path):
    d = designs()
    lock = tmp_path / f"sweep-{key_of(d)}.lock"
    with _locking.FolderLock(str(lock)):
        with pytest.raises(_locking.FolderLocked, match=rf"in use by pid {os.getpid()}"):
            gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    # released: the sweep runs, and leaves no lock file behind
    t = gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    assert len(t) == 9 and not lock.exists()


def test_a_writer_in_another_process_blocks_until_it_dies(tmp_path):
    d = designs()
    lock = tmp_path / f"sweep-{key_of(d)}.lock"
    holder = subprocess.Popen(
        [sys.executable, "-c", "import sys, time; from gecko._locking import FolderLock; "
         "FolderLock(sys.argv[1]).acquire(); print('held', flush=True); time.sleep(60)", str(lock)],
        stdout=subprocess.PIPE, text=True, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    try:
        assert holder.stdout.readline().strip() == "held"
        with pytest.raises(_locking.FolderLocked, match=rf"in use by pid {holder.pid} "):
            gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
        assert not (tmp_path / f"sweep-{key_of(d)}").exists() or not os.listdir(tmp_path / f"sweep-{key_of(d)}")
    finally:
        holder.kill()  # killed, not released: the kernel drops its lock
        holder.wait()
        holder.stdout.close()
    t = gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    assert len(t) == 9


def test_other_sweeps_in_the_same_folder_run_side_by_side(tmp_path):
    d1, d2 = designs(seed=1), designs(seed=2)
    with _locking.FolderLock(str(tmp_path / f"sweep-{key_of(d1)}.lock")):
        t = gecko.sweep(d2, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    assert len(t) == 9


def dead_pid():
    p = subprocess.Popen([sys.executable, "-c", "pass"])
    p.wait()
    return p.pid


def test_lock_and_temporaries_of_a_killed_run_do_not_block(tmp_path):
    d = designs()
    folder = partial_run(tmp_path, d)
    # a killed writer: its lock file (no flock held any more) and a half-written temporary
    (tmp_path / f"sweep-{key_of(d)}.lock").write_text('{"pid": %d, "host": "x"}' % dead_pid())
    tmp = folder / f"chunk-000002.parquet.tmp-{dead_pid()}@h-0000"
    tmp.write_bytes(b"half")
    old_tmp = folder / "chunk-000002.parquet.tmp4242"  # an older gecko's temporary
    old_tmp.write_bytes(b"half")
    t, _ = rerun(tmp_path, d, expect_warning=False)
    assert len(t) == 9 and not tmp.exists() and not old_tmp.exists()


def test_stale_staging_folders_of_dead_runs_are_removed(tmp_path):
    from gecko.scene import run_scene
    host = _integrity.owner_tag().split("@")[1]
    dead = tmp_path / f".gecko-staging-{dead_pid()}@{host}-abcd"
    alive = tmp_path / f".gecko-staging-{os.getpid()}@{host}-abcd"
    other_host = tmp_path / f".gecko-staging-{dead_pid()}@elsewhere-abcd"
    legacy_old = tmp_path / ".gecko-staging-k3j4h5"  # an older gecko's name, no owner in it
    legacy_new = tmp_path / ".gecko-staging-a1b2c3"
    for p in (dead, alive, other_host, legacy_old, legacy_new):
        p.mkdir()
        (p / "x.csv").write_text("1")
    two_days = __import__("time").time() - 2 * 86400
    os.utime(legacy_old, (two_days, two_days))
    scene = {"study": [{"model": "kendall", "parameters": {"EA": 50.0},
                        "outputs": {"critical_line": {"Ft": {"range": [0, 1], "num": 5}}}}],
             "plot": [{"kind": "critical_line", "name": "k"}]}
    run_scene(scene, tmp_path, draw=False, progress=False)
    assert not dead.exists() and alive.exists() and other_host.exists()
    assert not legacy_old.exists() and legacy_new.exists()
    assert (tmp_path / "k.csv").is_file()
    assert not [p for p in os.listdir(tmp_path) if p.startswith(".gecko-staging-") and str(os.getpid()) in p
                and p != alive.name]


# ---- Ctrl-C -------------------------------------------------------------------------------------------

def test_ctrl_c_keeps_the_finished_blocks_and_says_how_to_resume(tmp_path, monkeypatch):
    d = designs(12)
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    monkeypatch.setattr(design_sweep, "_BLOCK_PER_THREAD", 2)  # blocks of 2 designs, one thread
    real = design_sweep.compute_chunk
    calls = []

    def interrupted_at_the_fifth_block(block, outs, threads):
        calls.append(len(block))
        if len(calls) == 5:
            raise KeyboardInterrupt
        return real(block, outs, threads)

    monkeypatch.setattr(design_sweep, "compute_chunk", interrupted_at_the_fifth_block)
    with pytest.raises(KeyboardInterrupt) as ei:
        gecko.sweep(d, outputs=OUTS, chunk_size=5, out=tmp_path, threads=1, progress=False)
    msg = str(ei.value)
    folder = tmp_path / f"sweep-{key_of(d, chunk=5)}"
    # chunk 0 = blocks 2 + 2 + 1 finished; chunk 1: one block of 2 finished, then Ctrl-C
    assert "after 7 of 12 designs" in msg and str(folder) in msg and "again to resume" in msg
    assert (folder / "chunk-000000.parquet").is_file() and (folder / "chunk-000001.partial.parquet").is_file()
    calls.clear()
    monkeypatch.setattr(design_sweep, "compute_chunk", lambda b, o, t: (calls.append(len(b)), real(b, o, t))[1])
    t = gecko.sweep(d, outputs=OUTS, chunk_size=5, out=tmp_path, threads=1, progress=False)
    assert sum(calls) == 12 - 5 - 2  # only what had not finished
    bitwise_equal(t, fresh)
    assert not folder.exists()


def test_ctrl_c_without_out_says_nothing_was_kept(monkeypatch):
    def boom(block, outs, threads):
        raise KeyboardInterrupt
    monkeypatch.setattr(design_sweep, "compute_chunk", boom)
    with pytest.raises(KeyboardInterrupt, match="after 0 of 9 designs.*pass out=DIR"):
        gecko.sweep(designs(), outputs=OUTS, progress=False)


# ---- disk full, unwritable folder ------------------------------------------------------------------------

def test_disk_full_while_writing_a_chunk_is_an_oserror_and_keeps_earlier_chunks(tmp_path, monkeypatch):
    d = designs()
    fresh = gecko.sweep(d, outputs=OUTS, progress=False)
    real = pq.write_table
    n = []

    def full_disk(table, where, *a, **k):
        n.append(where)
        if len(n) == 2:
            with open(where, "wb") as f:  # half a file, then the disk is full
                f.write(b"PAR1")
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(table, where, *a, **k)

    monkeypatch.setattr(pq, "write_table", full_disk)
    with pytest.raises(OSError, match="no space left on the device.*run the same sweep again to resume") as ei:
        gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    assert ei.value.errno == errno.ENOSPC
    folder = tmp_path / f"sweep-{key_of(d)}"
    assert sorted(os.listdir(folder)) == ["chunk-000000.parquet", "chunk-000000.parquet.manifest.json"]
    monkeypatch.setattr(pq, "write_table", real)
    t, _ = rerun(tmp_path, d, expect_warning=False)
    assert t.attrs["sweep"]["chunks_reused"] == 1
    bitwise_equal(t, fresh)


def test_disk_full_while_writing_the_final_table(tmp_path, monkeypatch):
    d = designs()

    def full(self, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(pd.DataFrame, "to_parquet", full)
    with pytest.raises(OSError, match="no space left"):
        gecko.sweep(d, outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    monkeypatch.undo()
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".parquet") or ".tmp-" in p]
    t, _ = rerun(tmp_path, d, expect_warning=False)
    assert t.attrs["sweep"]["chunks_reused"] == 3


def test_unwritable_out_is_refused_before_computing(tmp_path, monkeypatch):
    f = tmp_path / "a_file"
    f.write_text("x")
    called = []
    monkeypatch.setattr(design_sweep, "compute_chunk", lambda *a: called.append(1))
    with pytest.raises(ValueError, match="out = .*cannot"):
        gecko.sweep(designs(), outputs=OUTS, out=f / "sub", progress=False)
    assert not called


def test_real_ctrl_c_on_gecko_run_exits_130_and_the_next_run_resumes(tmp_path):
    import signal
    import time
    scene = tmp_path / "sw.toml"
    scene.write_text('[sweep]\ndesigns = "random"\nn = 40\nseed = 1\noutputs = ["fn0", "ft_max"]\n'
                     'chunk_size = 10\n[sweep.bounds]\nEI1 = [2, 8]\nalpha2 = [0.2, 0.8]\n')
    # every block of designs takes 2 s more, so that the signal lands mid-run even on a loaded machine;
    # SIGINT gets Python's default handler back: a test run started in the background by a
    # non-interactive shell inherits SIGINT ignored, and Python then installs no KeyboardInterrupt
    slow = ("import signal; signal.signal(signal.SIGINT, signal.default_int_handler); "
            "import sys, time; import gecko.design_sweep as d; real = d.compute_chunk; "
            "d.compute_chunk = lambda b, o, t: (time.sleep(2.0), real(b, o, t))[1]; "
            "from gecko.cli import main; raise SystemExit(main(sys.argv[1:]))")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    argv = [sys.executable, "-c", slow, "run", str(scene), "--out", str(tmp_path / "o"), "--no-figures", "-q",
            "--threads", "1"]
    p = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    folder = tmp_path / "o" / ".gecko-sweep-sw.sweep"
    t_end = time.monotonic() + 60
    while not list(folder.glob("sweep-*/chunk-000000.parquet.manifest.json")) and time.monotonic() < t_end:
        time.sleep(0.02)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 130, err
    assert "interrupted after" in err and "sweep designs, which are kept in" in err and "Traceback" not in err
    assert not (tmp_path / "o" / "sweep.parquet").exists()
    r = subprocess.run(argv[:1] + ["-m", "gecko"] + argv[3:], env=env, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    t = pd.read_parquet(tmp_path / "o" / "sweep.parquet")
    fresh = gecko.sweep(gecko.random_designs({"EI1": (2, 8), "alpha2": (0.2, 0.8)}, 40, seed=1),
                        outputs=["fn0", "ft_max"], progress=False)
    bitwise_equal(t, fresh)
    assert not folder.exists()


def test_a_sweep_folder_in_use_by_another_run_is_not_removed(tmp_path):
    folder = tmp_path / ".gecko-sweep-s.sweep"
    folder.mkdir()
    with _locking.FolderLock(str(folder / "sweep-0123.lock")):
        assert not _locking.remove_unless_locked(folder) and folder.exists()
    assert _locking.remove_unless_locked(folder) and not folder.exists()


def test_disk_full_while_saving_the_finished_part_at_ctrl_c_still_reports_the_interrupt(tmp_path, monkeypatch):
    monkeypatch.setattr(design_sweep, "_BLOCK_PER_THREAD", 2)
    real = design_sweep.compute_chunk
    calls = []

    def second_block_interrupted(block, outs, threads):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(block, outs, threads)

    def full(table, where, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(design_sweep, "compute_chunk", second_block_interrupted)
    monkeypatch.setattr(pq, "write_table", full)
    with pytest.warns(ResultFileWarning, match="could not be kept.*no space left"):
        with pytest.raises(KeyboardInterrupt, match="after 0 of 9 designs"):
            gecko.sweep(designs(), outputs=OUTS, chunk_size=5, out=tmp_path, threads=1, progress=False)
    assert not [n for n in os.listdir(tmp_path / f"sweep-{key_of(designs(), chunk=5)}")]


def test_disk_full_while_writing_a_manifest_leaves_no_unverified_file(tmp_path, monkeypatch):
    real = _integrity.write_text_atomic

    def full(path, text):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(_integrity, "write_text_atomic", full)
    with pytest.raises(OSError, match="no space left"):
        gecko.sweep(designs(), outputs=OUTS, chunk_size=3, out=tmp_path, progress=False)
    assert os.listdir(tmp_path / f"sweep-{key_of(designs())}") == []
    monkeypatch.setattr(_integrity, "write_text_atomic", real)
    t, _ = rerun(tmp_path, designs(), expect_warning=False)
    assert t.attrs["sweep"]["chunks_computed"] == 3


def test_read_only_out_for_a_sweep_is_a_value_error(tmp_path, monkeypatch):
    ro = tmp_path / "ro"
    ro.mkdir()
    real_open = os.open

    def read_only(path, flags, *a):
        if str(path).startswith(str(ro)) and flags & os.O_CREAT:
            raise PermissionError(errno.EACCES, "Permission denied", path)
        return real_open(path, flags, *a)
    monkeypatch.setattr(_locking.os, "open", read_only)
    with pytest.raises(ValueError, match="out = .*cannot write there: Permission denied"):
        gecko.sweep(designs(), outputs=OUTS, out=ro, progress=False)

