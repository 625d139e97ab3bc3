"""Results store: atomic writes, torn lines, resume after an interruption."""

import json
import os

import numpy as np
import pytest

import moik.experiments.runner as runner_mod
from moik.exceptions import ParameterError, ResultsError
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore, atomic_write_bytes


def test_atomic_write_replaces_whole_file(tmp_path):
    path = tmp_path / "f.bin"
    atomic_write_bytes(path, b"old")
    atomic_write_bytes(path, b"new content")
    assert path.read_bytes() == b"new content"
    assert [p.name for p in tmp_path.iterdir()] == ["f.bin"]  # no temporary left


def test_store_layout_and_metadata(tmp_path, tiny_config):
    s = run_experiment(tiny_config, out=tmp_path / "r")
    assert s.ran == 8 and s.failed == 0
    store = ResultStore.open(tmp_path / "r")
    meta = store.meta
    assert meta["experiment"] == "tiny-test" and meta["versions"]["pymoo"]
    assert meta["config"]["seed"] == 11 and len(meta["trials"]) == 8
    assert {"hostname", "cpu_count"} <= set(meta["machine"]) and "git_commit" in meta
    assert all("seed" in t and "spawn_key" in t for t in meta["trials"])
    recs = store.records()
    assert len(recs) == 8 and store.finished_ids() == {r["trial"] for r in recs}
    arrays = store.load_arrays(recs[0]["trial"])
    assert set(arrays) == {"convergence", "best_x"} and np.all(np.diff(arrays["convergence"]) <= 0)


def test_torn_last_line_is_ignored_and_repaired(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=3)
    with open(out / "results.jsonl", "ab") as fh:  # a crash in the middle of an append
        fh.write(b'{"trial": "pso/1/1", "sta')
    store = ResultStore.open(out)
    assert len(store.records()) == 3
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.skipped == 3 and s.ran == 5
    lines = (out / "results.jsonl").read_text().splitlines()
    assert len(lines) == 8 and all(json.loads(line) for line in lines)


def test_resume_skips_finished_trials_after_ctrl_c(tmp_path, tiny_config, monkeypatch):
    out = tmp_path / "r"
    real_execute = runner_mod.execute

    def interrupted(specs, **kw):
        for i, pair in enumerate(real_execute(specs, **kw)):
            if i == 3:
                raise KeyboardInterrupt
            yield pair

    monkeypatch.setattr(runner_mod, "execute", interrupted)
    with pytest.raises(KeyboardInterrupt):
        run_experiment(tiny_config, out=out)
    done = ResultStore.open(out).finished_ids()
    assert len(done) == 3
    monkeypatch.setattr(runner_mod, "execute", real_execute)
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.skipped == 3 and s.ran == 5
    store = ResultStore.open(out)
    assert len(store.records()) == 8 and len(store.meta["sessions"]) == 2


def test_existing_results_need_resume_and_same_config(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1)
    with pytest.raises(ResultsError, match="pass --resume"):
        run_experiment(tiny_config, out=out)
    with pytest.raises(ResultsError, match="another configuration"):
        run_experiment(tiny_config, out=out, quick=True, resume=True)
    with pytest.raises(ResultsError, match="not a moik results folder"):
        ResultStore.open(tmp_path / "nothing")


def test_failed_trials_are_stored_and_retried_on_resume(tmp_path, tiny_config, monkeypatch):
    out = tmp_path / "r"
    real = runner_mod.execute

    def failing(specs, **kw):
        for rec, arrays in real(specs, **kw):
            if rec["trial"] == "pso/0/0":
                rec, arrays = dict(rec, status="error", error="boom"), {}
            yield rec, arrays

    monkeypatch.setattr(runner_mod, "execute", failing)
    assert run_experiment(tiny_config, out=out).failed == 1
    monkeypatch.setattr(runner_mod, "execute", real)
    s = run_experiment(tiny_config, out=out, resume=True)
    assert s.ran == 1 and s.failed == 0
    assert all(r["status"] == "ok" for r in ResultStore.open(out).records())


def _damage(out, trials):
    """Empty the first trial's arrays, overwrite the second's with garbage, delete the third's."""
    paths = [out / "arrays" / ResultStore.array_name(t) for t in trials]
    paths[0].write_bytes(b"")
    paths[1].write_bytes(b"not an npz at all")
    paths[2].unlink()
    return paths


def test_damaged_or_missing_arrays_run_again_on_resume(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out)
    trials = [r["trial"] for r in ResultStore.open(out).records()][:3]
    _damage(out, trials)
    store = ResultStore.open(out)
    assert set(store.check_arrays()) == set(trials)
    assert "an empty file" in store.check_arrays()[trials[0]]
    assert "not an .npz archive" in store.check_arrays()[trials[1]]
    assert "is missing" in store.check_arrays()[trials[2]]
    with pytest.raises(ResultsError, match="is damaged"):
        store.load_arrays(trials[0])
    assert store.finished_ids() == {r["trial"] for r in store.records()} - set(trials)
    s = run_experiment(tiny_config, out=out, resume=True)
    assert (s.ran, s.skipped, s.rerun_damaged, s.failed) == (3, 5, 3, 0)
    assert any("3 stored trial(s) have damaged or missing arrays" in n for n in s.notes)
    store = ResultStore.open(out, verify=True)
    assert store.damaged == {} and len(store.records()) == 8
    assert all(store.load_arrays(t)["convergence"].size for t in trials)


def test_a_flipped_byte_is_caught_by_the_zip_checksum(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1)
    trial = ResultStore.open(out).records()[0]["trial"]
    path = out / "arrays" / ResultStore.array_name(trial)
    data = bytearray(path.read_bytes())
    data[60] ^= 0xFF  # inside the first array's data
    path.write_bytes(bytes(data))
    store = ResultStore.open(out, verify=True)
    assert "CRC" in store.damaged[trial] and store.records() == []


def test_arrays_named_in_the_record_must_all_be_there(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1)
    rec = ResultStore.open(out).records()[0]
    assert rec["arrays"] == ["best_x", "convergence"]
    path = out / "arrays" / ResultStore.array_name(rec["trial"])
    np.savez(path, best_x=np.zeros(2))
    assert "lacks convergence" in ResultStore.open(out).check_arrays()[rec["trial"]]


def test_stale_temporaries_are_removed_at_the_start(tmp_path, tiny_config):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1)
    stale = [out / ".meta.json.4242.tmp", out / "arrays" / ".eosma__0__0.npz.4242.tmp"]
    for p in stale:
        p.write_bytes(b"half")
    keep = out / "notes.tmp"  # not a temporary of moik's (no leading dot): kept
    keep.write_text("mine")
    s = run_experiment(tiny_config, out=out, resume=True)
    assert not any(p.exists() for p in stale) and keep.exists()
    assert "removed 2 stale temporary file(s) of interrupted writes" in s.notes


def test_a_failed_start_leaves_no_folder(tmp_path, tiny_config, monkeypatch):
    def broken(*args, **kwargs):
        raise ResultsError("disk full")

    monkeypatch.setattr(ResultStore, "_prepare", classmethod(broken))
    with pytest.raises(ResultsError, match="disk full"):
        run_experiment(tiny_config, out=tmp_path / "new" / "r")
    assert not (tmp_path / "new").exists()
    (tmp_path / "old").mkdir()
    with pytest.raises(ResultsError, match="disk full"):
        run_experiment(tiny_config, out=tmp_path / "old")
    assert (tmp_path / "old").is_dir() and not any((tmp_path / "old").iterdir())


def test_an_unreachable_dask_scheduler_leaves_no_folder(tmp_path, tiny_config, monkeypatch):
    pytest.importorskip("distributed")
    real = runner_mod.connect_dask
    monkeypatch.setattr(runner_mod, "connect_dask", lambda a: real(a, timeout=1))
    with pytest.raises(ParameterError, match="cannot connect to the Dask scheduler"):
        run_experiment(tiny_config, out=tmp_path / "r", dask_scheduler="tcp://127.0.0.1:1")
    assert not (tmp_path / "r").exists()


# --- a full disk (issue 27 item 7) ---

def _full_after(monkeypatch, store, budget: int):
    """os.write on the store's results file writes at most ``budget`` bytes, then ENOSPC."""
    import errno
    import os
    real = os.write
    left = {"n": budget}

    def write(fd, data):
        if fd != store._fd:
            return real(fd, data)
        if left["n"] <= 0:
            raise OSError(errno.ENOSPC, "No space left on device")
        n = real(fd, bytes(data[: left["n"]]))
        left["n"] -= n
        return n

    monkeypatch.setattr(os, "write", write)


def test_a_short_write_leaves_no_torn_line_and_says_resume(tmp_path, tiny_config, monkeypatch):
    """Before: os.write's count was ignored, so a disk-full append left a torn line."""
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=2, progress=False)
    good = (out / "results.jsonl").read_bytes()
    store = ResultStore.open(out)
    store._fd = os.open(store.results_path, os.O_WRONLY | os.O_APPEND)
    _full_after(monkeypatch, store, 40)
    with pytest.raises(ResultsError, match=r"cannot append to '.*results.jsonl': No space left on "
                                           r"device; trial 'x/0/0' was not stored .* --resume "
                                           "to continue"):
        store.append({"trial": "x/0/0", "status": "ok"}, {})
    store.close()
    assert (out / "results.jsonl").read_bytes() == good  # cut back: no torn line


def test_a_short_write_that_goes_on_writes_the_whole_line(tmp_path, tiny_config, monkeypatch):
    import os
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, limit=1, progress=False)
    store = ResultStore.open(out)
    store._fd = os.open(store.results_path, os.O_WRONLY | os.O_APPEND)
    real = os.write
    monkeypatch.setattr(os, "write", lambda fd, data: real(fd, bytes(data[:7])))  # 7 at a time
    store.append({"trial": "x/0/0", "status": "ok", "algorithm": "x", "target": 0, "run": 0}, {})
    monkeypatch.setattr(os, "write", real)
    store.close()
    assert [r["trial"] for r in ResultStore.open(out).records()][-1] == "x/0/0"


def test_a_failed_atomic_write_leaves_no_temporary_and_names_the_file(tmp_path, monkeypatch):
    import os
    path = tmp_path / "meta.json"
    atomic_write_bytes(path, b"old")

    def full(fd):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(ResultsError, match=r"cannot write '.*meta.json': No space left on device"):
        atomic_write_bytes(path, b"new")
    monkeypatch.undo()
    assert path.read_bytes() == b"old" and [p.name for p in tmp_path.iterdir()] == ["meta.json"]


def test_a_full_disk_run_stops_with_the_file_and_the_resume_hint(tmp_path, tiny_config):
    """The real thing: a small tmpfs fills up mid-run (the smallest size, from 16 KiB up,
    that holds the metadata and at least one trial); the message names the file and says
    --resume, no .tmp is left, every stored line is whole, and resuming elsewhere works."""
    import shutil
    import subprocess
    mount = tmp_path / "small"
    mount.mkdir()
    for size in range(16, 100, 4):
        made = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}k", "tmpfs",
                               str(mount)], capture_output=True, text=True)
        if made.returncode != 0:
            pytest.skip(f"cannot mount a tmpfs here: {made.stderr.strip()}")
        try:
            try:
                run_experiment(tiny_config, out=mount / "r", progress=False)
            except ResultsError as exc:
                error = str(exc)
            else:
                pytest.fail(f"{size} KiB held the whole run")
            path = mount / "r" / "results.jsonl"
            lines = path.read_bytes() if path.exists() else b""
            if not lines:
                continue  # too small for even one trial: a bigger size
            assert "No space left on device" in error and str(mount / "r") in error
            assert "--resume to continue" in error
            assert not [p for p in (mount / "r").rglob("*.tmp")]
            assert lines.endswith(b"\n") and all(json.loads(x) for x in lines.splitlines())
            shutil.copytree(mount / "r", tmp_path / "moved")
            break
        finally:
            subprocess.run(["umount", str(mount)], capture_output=True)
    else:
        pytest.fail("no tmpfs size from 16 to 96 KiB held one trial and not all eight")
    n = len(lines.splitlines())
    s = run_experiment(tiny_config, out=tmp_path / "moved", resume=True, progress=False)
    assert s.skipped == n and s.ran == 8 - n


def test_a_meta_without_planned_trials_says_so(tmp_path, tiny_config):
    """Before: "8 of 0 planned trials finished"."""
    from moik.experiments.tables import Results
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out, progress=False)
    meta = json.loads((out / "meta.json").read_text())
    del meta["trials"]
    (out / "meta.json").write_text(json.dumps(meta))
    notes = Results(ResultStore.open(out)).notes()
    assert notes[0] == ("8 trials finished (the number planned is unknown: meta.json lists no "
                        "planned trials)")
