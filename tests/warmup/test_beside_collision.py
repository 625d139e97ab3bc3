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
from tests.warmup.test_beside import COLD_SOLVE, _run_cold


def test_starts_the_collision_leaves_child_with_the_solves_checker(fake_popen):
    checker = CollisionChecker(model=robot_model_of("panda"), self_collision=True)
    assert beside_collision(checker) is not None
    family, arguments = pickle.loads(fake_popen.started[0].written)
    assert family == "collision-leaves" and arguments["checker"].n_pairs == checker.n_pairs
    assert beside_collision("not a checker") is None


def robot_model_of(name: str):
    return default_model(get_robot(name))


COLD_COLLISION = COLD_SOLVE.replace(
    "from moik.warmup.beside import beside_solve",
    "from moik.solver.collision import collision_guard\n"
    "from moik.warmup.beside import beside_collision").replace(
    'robot = moik.get_robot("puma560")\nbeside_solve(robot)',
    'robot = moik.get_robot("panda")\nguard = collision_guard(robot, self_collision=True)\n'
    "beside_collision(guard.checker)").replace(
    "moik.solve_ik(robot, np.array([0.4, 0.2, 0.3]))",
    "moik.solve_ik(robot, np.array([0.4, 0.2, 0.5]), collision=guard.checker)")


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
