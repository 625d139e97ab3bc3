"""moik/warmup/beside.py: the ``"collision-leaves"`` child of a cold first collision-aware
solve (what it is given, and that a cold first collision-aware solve after it compiles none
of the distance kernels and gives the same answer)."""

import pickle

import numpy as np

import moik
from moik.collision import CollisionChecker
from moik.robots import get_robot
from moik.solver.collision import default_model
from moik.warmup.beside import beside_collision
from tests.warmup.test_beside import _run_cold


def test_starts_the_collision_leaves_child_with_the_solves_checker(fake_popen):
    checker = CollisionChecker(model=robot_model_of("panda"), self_collision=True)
    assert beside_collision(checker) is not None
    family, arguments = pickle.loads(fake_popen.started[0].written)
    assert family == "collision-leaves" and arguments["checker"].n_pairs == checker.n_pairs
    assert beside_collision("not a checker") is None


def robot_model_of(name: str):
    return default_model(get_robot(name))


COLD_COLLISION = """
import json, pickle, subprocess, sys, numpy as np, moik
from numba.core import event
from moik.solver.collision import collision_guard
from moik.warmup.beside import beside_collision
from moik.warmup import background
captured = []
background.start = lambda family, arguments, probes: captured.append((family, arguments))
robot = moik.get_robot("panda")
guard = collision_guard(robot, self_collision=True)
beside_collision(guard.checker)
child = subprocess.run([sys.executable, "-m", "moik.warmup"], input=pickle.dumps(captured[0]))
assert child.returncode == 0
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        f = ev.data["dispatcher"].py_func
        compiled.append(f"{f.__module__}.{f.__qualname__}")
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
res = moik.solve_ik(robot, np.array([0.4, 0.2, 0.5]), collision=guard.checker)
print(json.dumps({"q": res.q.tolist(), "kernels": sorted(set(compiled))}))
"""


def test_a_cold_first_collision_aware_solve_loads_the_distance_kernels_the_child_compiled(
        tmp_path):
    """The ``"collision-leaves"`` child's distance kernels have the solve's numba types: a
    cold first collision-aware solve after it compiles its start loop but none of them,
    and its answer is the warm one."""
    cold = _run_cold(COLD_COLLISION, tmp_path)
    assert "moik.solver.starts.run_starts" in cold["kernels"]  # the cache was cold
    distance = [k for k in cold["kernels"] if k.startswith((
        "moik.collision.kernels.", "moik.collision.gjk.", "moik.collision.box_distance.",
        "moik.collision.pairs."))]
    assert not distance, distance
    warm = moik.solve_ik("panda", np.array([0.4, 0.2, 0.5]), self_collision=True)
    np.testing.assert_array_equal(np.array(cold["q"]), warm.q)
