"""moik/_background.py: when a background compile starts, what the child is run with,
and when its parent goes on."""

import pickle
import subprocess
import sys
import time

import pytest

from moik import _background, _jit


def test_starts_the_module_with_its_arguments_and_no_grandchild(fake_popen):
    handle = _background.start("moik.some_module", {"a": (1, 2)}, probes=[object()])
    assert handle is not None and len(fake_popen.started) == 1
    child = fake_popen.started[0]
    assert child.argv == [sys.executable, "-m", "moik.some_module"]
    assert child.kwargs["env"][_background.ENV_SWITCH] == "0"
    assert pickle.loads(child.written) == {"a": (1, 2)}


def test_the_child_imports_its_parents_moik_from_any_working_folder(tmp_path, monkeypatch):
    """``python -m`` puts the working folder first on sys.path: a folder holding another
    moik (a checkout) must not give the child that one (it would compile its kernels)."""
    other = tmp_path / "moik"
    other.mkdir()
    (other / "__init__.py").write_text("")
    (other / "which.py").write_text("import sys; sys.stdout.write('other')")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(_jit, "is_cached", lambda kernel: False)
    monkeypatch.setattr(_background, "cpus", lambda: 2)
    monkeypatch.delenv(_background.ENV_SWITCH, raising=False)
    handle = _background.start("moik._jit", None, probes=[object()])
    assert handle is not None
    handle.process.wait(timeout=60)  # moik._jit run as a script: imports and ends
    assert handle.process.returncode == 0
    handle = _background.start("moik.which", None, probes=[object()])
    assert handle is not None
    handle.process.wait(timeout=60)
    assert handle.process.returncode != 0  # this moik has no moik.which: not the other one


@pytest.mark.parametrize("why", ["switched off", "one cpu", "cached", "unpicklable"])
def test_does_not_start_where_it_cannot_help(fake_popen, monkeypatch, why):
    arguments: object = (1,)
    if why == "switched off":
        monkeypatch.setenv(_background.ENV_SWITCH, "0")
    elif why == "one cpu":
        monkeypatch.setattr(_background, "cpus", lambda: 1)
    elif why == "cached":
        monkeypatch.setattr(_jit, "is_cached", lambda kernel: True)
    else:
        arguments = lambda: None  # noqa: E731 - a lambda cannot be pickled
    assert _background.start("moik.some_module", arguments, probes=[object()]) is None
    assert not fake_popen.started


def test_the_parent_goes_on_when_the_child_is_ready(monkeypatch):
    """wait() returns at the child's READY line while the child goes on (stop() ends it);
    a child that ends without the line releases it too."""
    monkeypatch.setattr(_background, "WAIT_LIMIT", 60.0)
    code = (f"import sys, time; sys.stdout.write({_background.READY!r}); sys.stdout.flush(); "
            "time.sleep(60)")
    for argv in ([sys.executable, "-c", code], [sys.executable, "-c", "pass"]):
        process = subprocess.Popen(argv, stdout=subprocess.PIPE)
        handle = _background.Background(process)
        t0 = time.perf_counter()
        handle.wait()
        assert time.perf_counter() - t0 < 30
        handle.stop()
        assert process.poll() is not None


def test_a_child_that_never_says_ready_is_stopped_after_the_wait_limit(monkeypatch):
    monkeypatch.setattr(_background, "WAIT_LIMIT", 0.5)
    process = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"],
                               stdout=subprocess.PIPE)
    _background.Background(process).wait()
    assert process.poll() is not None
