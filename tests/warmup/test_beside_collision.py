"""moik/warmup/beside.py: the ``"collision-leaves"`` child of a cold first collision-aware
solve (what it is given, and that a cold first collision-aware solve after it compiles none
of the distance kernels and gives the same answer)."""

import pickle

import numba
import numpy as np
import pytest

import moik
from moik.collision import Box, CollisionChecker, HalfSpace, Scene
from moik.robots import get_robot
from moik.robots.transforms import translation
from moik.solver.collision import collision_guard, default_model
from moik.warmup.beside_collision import (
    beside_collision,
    beside_collision_early,
    collision_stand_in,
    stand_in_set,
)
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
    "from moik.warmup.beside_collision import beside_collision").replace(
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


SCENE = Scene({"table": HalfSpace.plane([0, 0, 1], -1.0),
               "box": Box(size=(0.1, 0.1, 0.1), pose=translation(0.5, 0.0, 0.3))})


@pytest.mark.parametrize(("arm", "scene"), [("panda", None), ("panda", SCENE), ("ur5", None),
                                            ("eosma7", None), ("eosma7", SCENE)])
def test_the_stand_in_set_has_the_numba_type_of_the_guessed_checker(arm, scene):
    """The ``"collision-stand-in"`` child's set is of the solve's own numba type where the
    guess (self pairs alone: CompoundSet; a scene: CollisionSet) holds, as it does for these:
    the kernels it compiles are the ones the solve loads (a cold first solve after a child
    on a set of the solve's type compiles none: the test above)."""
    robot = get_robot(arm)
    real = collision_guard(robot, self_collision=True, scene=scene).checker.compiled
    stand_in = stand_in_set(robot, scene is None)
    assert numba.typeof(stand_in) == numba.typeof(real)
    collision_stand_in(robot, scene is None)  # runs (compiled once, for the tests above)


def test_the_early_child_is_kept_for_its_type_and_replaced_for_the_other(fake_popen):
    robot = get_robot("iiwa14")
    early = beside_collision_early(robot, scene=False)
    assert early is not None and early.compound
    family, arguments = pickle.loads(fake_popen.started[0].written)
    assert family == "collision-stand-in" and arguments["compound"] is True
    own = collision_guard(robot, self_collision=True).checker  # a CompoundSet: kept
    assert beside_collision(own, early=early) is early.child and len(fake_popen.started) == 1
    # iiwa14 with a scene is a CompoundSet too (all its pairs are compounds' bounds): the
    # guess says CollisionSet, so that child is stopped and one on the checker started
    wrong = beside_collision_early(robot, scene=True)
    assert wrong is not None and not wrong.compound
    with_scene = collision_guard(robot, self_collision=True, scene=SCENE).checker
    assert beside_collision(with_scene, early=wrong) is not wrong.child
    assert pickle.loads(fake_popen.started[-1].written)[0] == "collision-leaves"
