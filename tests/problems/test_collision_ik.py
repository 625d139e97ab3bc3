"""CollisionIK: the wrapped objectives unchanged, G from the compiled distances."""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.optimize import minimize

from moik import get_robot
from moik.collision import Box, CollisionChecker, HalfSpace, Scene
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.exceptions import GeometryError, UnknownNameError
from moik.problems import BiObjectiveIK, PositionIK
from moik.problems.collision_ik import CollisionIK


def _checker():
    scene = Scene({"table": HalfSpace.plane([0, 0, 1], -0.07),
                   "shelf": Box(size=(0.3, 0.6, 0.02), pose=rpy_pose([0.5, 0, 0.3]))})
    return CollisionChecker(model=collision_model("panda"), scene=scene, self_collision=True)


def test_objectives_unchanged_and_constraints_are_distances():
    robot = get_robot("panda")
    target = robot.fk(np.zeros(7) + 0.3)
    inner = BiObjectiveIK(robot, target)
    checker = _checker()
    X = robot.random_q(50, rng=np.random.default_rng(0))
    for groups in ("min", "links"):
        prob = CollisionIK(inner, checker=checker, clearance=0.01, groups=groups)
        F, G = prob.evaluate(X, return_values_of=["F", "G"])
        np.testing.assert_array_equal(F, inner.evaluate(X, return_values_of=["F"]))
        np.testing.assert_array_equal(G.max(axis=1), 0.01 - checker.min_distance(X))
    assert len(CollisionIK(inner, checker=checker, groups="links").group_names) > 1


def test_nsga2_returns_collision_free_members():
    robot = get_robot("panda")
    prob = CollisionIK(PositionIK(robot, [0.45, 0.2, 0.4]), checker=_checker(), clearance=0.0)
    res = minimize(prob, NSGA2(pop_size=40), ("n_gen", 30), seed=1)
    X = np.atleast_2d(res.X)
    assert np.all(prob.min_distance(X) >= 0.0)


def test_bad_arguments():
    robot = get_robot("ur5")
    with pytest.raises(GeometryError, match="for robot 'panda'"):
        CollisionIK(PositionIK(robot, [0.3, 0.2, 0.4]), checker=_checker())
    with pytest.raises(UnknownNameError):
        CollisionIK(PositionIK(get_robot("panda"), [0.3, 0.2, 0.4]), checker=_checker(),
                    groups="pairs")
