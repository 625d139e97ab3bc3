"""Names from data become file names only through one checked function, and writes and
deletes stay inside their folder without following links (moik/_paths.py)."""

import os
import signal

import pytest

from moik import _paths
from moik.exceptions import ConfigError, ResultsError


@pytest.mark.parametrize("name", ["../../x/y", "a/b", "a\\b", "..", ".", ".hidden", "", "a\x00b",
                                  "x" * 300, "tab\there", ["a"], None, 3])
def test_file_name_refuses_what_is_no_single_file_name(name):
    with pytest.raises(ResultsError, match="trial id"):
        _paths.file_name(name, "trial id")


def test_file_name_keeps_ordinary_names_and_takes_the_callers_error():
    assert _paths.file_name("eosma-table5", "name") == "eosma-table5"
    assert _paths.file_name("P1 (x: 0.5)", "name") == "P1 (x: 0.5)"
    with pytest.raises(ConfigError, match="at most|1 to 120"):
        _paths.file_name("a" * 121, "label", error=ConfigError)


def test_inside_refuses_links_and_parent_steps(tmp_path):
    (tmp_path / "real").mkdir()
    (tmp_path / "elsewhere").mkdir()
    os.symlink(tmp_path / "elsewhere", tmp_path / "real" / "arrays")
    with pytest.raises(ResultsError, match="symbolic link"):
        _paths.inside(tmp_path / "real", tmp_path / "real" / "arrays" / "x.npz")
    with pytest.raises(ResultsError, match="leaves|not inside"):
        _paths.inside(tmp_path / "real", tmp_path / "real" / ".." / "elsewhere" / "x")
    with pytest.raises(ResultsError, match="not inside"):
        _paths.inside(tmp_path / "real", tmp_path / "elsewhere" / "x")
    assert _paths.inside(tmp_path / "real", tmp_path / "real" / "new" / "x") is not None


def test_atomic_write_never_writes_through_a_link(tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    os.symlink(victim, tmp_path / "report.md")
    with pytest.raises(ResultsError, match="symbolic link"):
        _paths.atomic_write_bytes(tmp_path / "report.md", b"x")
    assert victim.read_text() == "keep"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.md", "victim.txt"]


def test_open_append_refuses_a_link(tmp_path):
    victim = tmp_path / "victim"
    victim.write_text("keep\n")
    os.symlink(victim, tmp_path / "results.jsonl")
    with pytest.raises(ResultsError, match="symbolic link"):
        _paths.open_append(tmp_path / "results.jsonl")
    assert victim.read_text() == "keep\n"


def test_atomic_write_removes_its_temporary_on_an_interrupt(tmp_path, monkeypatch):
    """Before: only OSError removed the temporary, Ctrl-C (KeyboardInterrupt) left it."""
    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        _paths.atomic_write_bytes(tmp_path / "meta.json", b"{}")
    assert list(tmp_path.iterdir()) == []


def test_atomic_write_removes_its_temporary_on_sigterm_raised_inside(tmp_path, monkeypatch):
    class Terminated(KeyboardInterrupt):
        pass

    monkeypatch.setattr(os, "replace", lambda a, b: (_ for _ in ()).throw(Terminated()))
    with pytest.raises(Terminated):
        _paths.atomic_write_bytes(tmp_path / "x.npz", b"data")
    assert list(tmp_path.iterdir()) == []
    assert signal.getsignal(signal.SIGTERM) is not None


def test_remove_deletes_a_link_not_its_target(tmp_path):
    victim = tmp_path / "victim.png"
    victim.write_text("keep")
    (tmp_path / "docs").mkdir()
    os.symlink(victim, tmp_path / "docs" / "a.png")
    _paths.remove(tmp_path / "docs", tmp_path / "docs" / "a.png")
    assert victim.read_text() == "keep" and not (tmp_path / "docs" / "a.png").is_symlink()
