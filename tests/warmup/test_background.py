"""moik/warmup/background.py: when a background compile starts and what the child is run
with."""

import pickle
import subprocess
import sys

import pytest

from moik import _jit
from moik.warmup import background


def test_starts_the_warmup_module_with_the_family_and_no_grandchild(fake_popen):
    handle = background.start("some-family", {"a": (1, 2)}, probes=[object()])
    assert handle is not None and len(fake_popen.started) == 1
    child = fake_popen.started[0]
    assert child.argv == [sys.executable, "-m", "moik.warmup"]
    assert child.kwargs["env"][background.ENV_SWITCH] == "0"
    assert pickle.loads(child.written) == ("some-family", {"a": (1, 2)})


def test_the_child_imports_its_parents_moik_from_any_working_folder(tmp_path, monkeypatch):
    """``python -m`` puts the working folder first on sys.path: a folder holding another
    moik (a checkout) must not give the child that one (it would compile its kernels)."""
    other = tmp_path / "moik" / "warmup"
    other.mkdir(parents=True)
    (tmp_path / "moik" / "__init__.py").write_text("")
    (other / "__init__.py").write_text("")
    (other / "__main__.py").write_text("raise SystemExit(3)")  # the other moik's child
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(_jit, "is_cached", lambda kernel: False)
    monkeypatch.setattr(background, "available_cores", lambda: 2)
    monkeypatch.setattr(background, "idle_cpus", lambda: 2.0)
    monkeypatch.delenv(background.ENV_SWITCH, raising=False)
    handle = background.start("no-such-family", None, probes=[object()])
    assert handle is not None
    handle.process.wait(timeout=120)
    # this moik's child: it reads the family and fails on the unknown name (KeyError: 1)
    assert handle.process.returncode == 1


@pytest.mark.parametrize("why", ["switched off", "one cpu", "busy", "cached", "unpicklable"])
def test_does_not_start_where_it_cannot_help(fake_popen, monkeypatch, why):
    arguments: object = (1,)
    if why == "switched off":
        monkeypatch.setenv(background.ENV_SWITCH, "0")
    elif why == "one cpu":
        monkeypatch.setattr(background, "available_cores", lambda: 1)
    elif why == "busy":  # every CPU ran something else over the last minute
        monkeypatch.setattr(background, "idle_cpus", lambda: 0.3)
    elif why == "cached":
        monkeypatch.setattr(_jit, "is_cached", lambda kernel: True)
    else:
        arguments = lambda: None  # noqa: E731 - a lambda cannot be pickled
    assert background.start("some-family", arguments, probes=[object()]) is None
    assert not fake_popen.started


def test_the_switch_at_1_starts_a_child_on_a_busy_machine_too(fake_popen, monkeypatch):
    monkeypatch.setattr(background, "idle_cpus", lambda: 0.0)
    monkeypatch.setenv(background.ENV_SWITCH, "1")
    assert background.start("some-family", (1,), probes=[object()]) is not None


def test_idle_cpus_are_the_idle_share_of_the_last_tenth_of_a_second(monkeypatch, tmp_path):
    """Two readings of the system's CPU times (user nice system idle iowait irq softirq
    steal): 300 of 400 ticks between them idle or waiting, on 2 CPUs: 1.5 idle."""
    stat = tmp_path / "stat"
    readings = iter(["cpu  100 0 100 1000 0 0 0 0 0 0\n", "cpu  150 0 150 1250 50 0 0 0 0 0\n"])
    monkeypatch.setattr(background, "PROC_STAT", str(stat))
    monkeypatch.setattr(background.time, "sleep", lambda s: stat.write_text(next(readings)))
    stat.write_text(next(readings))
    monkeypatch.setattr(background, "available_cores", lambda: 2)
    monkeypatch.setattr(background.os, "getloadavg", lambda: (2.0, 0.0, 0.0))  # not read
    assert background.idle_cpus() == 1.5


def test_idle_cpus_fall_back_to_the_cpus_less_the_load(monkeypatch, tmp_path):
    monkeypatch.setattr(background, "PROC_STAT", str(tmp_path / "absent"))
    monkeypatch.setattr(background, "available_cores", lambda: 2)
    monkeypatch.setattr(background.os, "getloadavg", lambda: (1.5, 0.0, 0.0))
    assert background.idle_cpus() == 0.5


def test_a_child_still_running_at_stop_is_ended():
    process = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    background.Background(process).stop()
    assert process.poll() is not None
