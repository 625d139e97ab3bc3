"""moik/warmup/families.py: ``moik compile``'s kernel families by name, and that a family
compiles what its first use needs (a cold cache: the use then compiles nothing)."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import moik
from moik.exceptions import UnknownNameError
from moik.warmup.families import FAMILIES, compile_family


def test_the_families_are_named():
    assert list(FAMILIES) == ["solve", "solve-position", "unreachable", "pareto", "batch-path",
                              "collision", "algorithms-single", "algorithms-multi"]


def test_an_unknown_family_is_refused_with_the_known_names():
    with pytest.raises(UnknownNameError, match="kernel family 'solver'.*solve-position"):
        compile_family("solver")


COLD = """
import json, sys, numpy as np, moik, moik.problems
from numba.core import event
from moik.warmup.families import compile_family
name, seconds, count = compile_family("solve-position")
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        compiled.append(ev.data["dispatcher"].py_func.__name__)
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
for name in ("eosma7", "ur5"):
    arm = moik.get_robot(name)
    target = moik.problems.random_reachable_targets(arm, 1, seed=5)[0]
    assert moik.solve_ik(arm, target.position).success
print(json.dumps({"count": count, "after": compiled}))
"""


def test_a_family_compiles_every_kernel_its_first_use_needs(tmp_path):
    """In a fresh interpreter on an empty cache: ``solve-position`` compiles kernels, and a
    position solve on either kind of arm afterwards compiles none."""
    root = Path(moik.__file__).parent
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("NUMBA_", "MOIK_")) and k != "PYTHONPATH"}
    env.update(NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(root.parent),
               MOIK_BACKGROUND_COMPILE="0")
    out = subprocess.run([sys.executable, "-c", COLD], capture_output=True, text=True,
                         env=env, cwd=tmp_path, timeout=900)
    assert out.returncode == 0, out.stderr
    run = json.loads(out.stdout.splitlines()[-1])
    assert run["count"] > 0 and run["after"] == []
