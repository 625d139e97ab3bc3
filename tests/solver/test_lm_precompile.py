"""moik/solver/lm_precompile.py: the start loop's leaf kernels compiled in a child on a
cold first solve (when it starts, and that the parent then loads what it compiled)."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import moik
from moik import _background
from moik.solver import lm_precompile


@pytest.fixture()
def started(monkeypatch):
    calls = []
    monkeypatch.setattr(lm_precompile, "_started", False)
    monkeypatch.setattr(_background, "start", lambda *args, **kw: calls.append(args))
    return calls


def test_starts_once_per_process_with_the_robot(started, monkeypatch):
    monkeypatch.setattr(lm_precompile.run_starts, "overloads", {})
    robot = moik.get_robot("puma560")
    lm_precompile.precompile(robot, reachable=False)
    lm_precompile.precompile(robot)
    assert len(started) == 1
    module, arguments = started[0][:2]
    assert module == "moik.solver.lm_precompile" and arguments == (robot, False)


def test_not_started_once_the_start_loop_is_loaded(started, monkeypatch):
    moik.solve_ik("puma560", np.array([0.4, 0.2, 0.3]))  # loads (or compiles) run_starts
    assert lm_precompile.run_starts.overloads
    started.clear()
    monkeypatch.setattr(lm_precompile, "_started", False)
    lm_precompile.precompile(moik.get_robot("puma560"))
    assert started == []


def test_a_solve_with_a_collision_check_starts_none(started, monkeypatch):
    """Its context is another numba type: the child's kernels would not be its own."""
    monkeypatch.setattr(lm_precompile.run_starts, "overloads", {})
    moik.solve_ik("puma560", np.array([0.4, 0.2, 0.3]), self_collision=True)
    assert started == []


COLD = """
import json, pickle, subprocess, sys, numpy as np, moik
from numba.core import event
robot = moik.get_robot(sys.argv[1])
child = subprocess.run([sys.executable, "-m", "moik.solver.lm_precompile"],
                       input=pickle.dumps((robot, sys.argv[2] == "reachable")))
assert child.returncode == 0
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        compiled.append(ev.data["dispatcher"].py_func.__name__)
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
target = np.array([0.4, 0.2, 0.3]) if sys.argv[2] == "reachable" else np.array([9.0, 0, 0])
res = moik.solve_ik(robot, target)
print(json.dumps({"compiled": compiled, "status": res.status}))
"""


@pytest.mark.parametrize("case", ["reachable", "out of reach"])
def test_the_parent_loads_every_kernel_the_child_compiled(tmp_path, case):
    """In a fresh interpreter on an empty cache the child runs to its end first; the
    solve then compiles the FK, residual and LM kernels and none of the child's (its
    numba types are the solve's: a read-only limit array made writeable by pickling
    was once another type)."""
    root = Path(moik.__file__).parent
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("NUMBA_", "MOIK_")) and k != "PYTHONPATH"}
    env.update(NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(root.parent),
               MOIK_BACKGROUND_COMPILE="0")
    out = subprocess.run([sys.executable, "-c", COLD, "ur5", case.split()[0]],
                         capture_output=True, text=True, env=env, cwd=tmp_path, timeout=900)
    assert out.returncode == 0, out.stderr
    run = json.loads(out.stdout.splitlines()[-1])
    assert run["status"] == ("solved" if case == "reachable" else "unreachable")
    assert "residual" in run["compiled"]  # the cache was cold: LM compiled here
    childs = {"damped_step", "cholesky_solve", "into_limits", "fk_rotations_positions"}
    if case == "reachable":
        childs |= {"recheck", "geodesic_angle", "_keep", "is_new", "_improve"}
    assert not childs & set(run["compiled"]), run["compiled"]
