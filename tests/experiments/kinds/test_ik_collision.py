"""The collision keys of an IK experiment: the problem wrapped, feasibility recorded."""

import numpy as np
import pytest

from moik import get_robot
from moik.experiments.kinds.ik_collision import feasibility, with_collision
from moik.problems import BiObjectiveIK
from moik.problems.collision_ik import CollisionIK

SCENE = {"obstacles": [{"name": "table", "type": "halfspace", "normal": [0, 0, 1]},
                       {"name": "wall", "type": "box", "size": [0.02, 2, 2], "xyz": [0.5, 0, 0]}],
         "allowed": [["table", "panda_link0"], ["table", "panda_link1"]]}


def test_wrapped_only_with_a_scene_and_feasibility_recorded():
    robot = get_robot("panda")
    ik = BiObjectiveIK(robot, robot.fk(np.full(7, 0.2)))
    assert with_collision(ik, {"kind": "bi-objective"}) is ik
    prob = with_collision(ik, {"kind": "bi-objective", "scene": SCENE, "clearance": 0.01})
    assert isinstance(prob, CollisionIK) and prob.clearance == 0.01
    X = robot.random_q(200, rng=np.random.default_rng(2))
    record: dict = {}
    ok = feasibility(prob, X, record)
    d = prob.min_distance(X)
    assert record["n_feasible"] == int((d >= 0.01).sum()) == int(ok.sum())
    assert 0 < record["n_feasible"] < 200 and record["min_distance"] == d.min()
    assert feasibility(ik, X, {}).all()


def test_the_geometry_is_the_one_solve_ik_checks():
    """One rule: the experiment's checker has the solver's default geometry (panda: its URDF's
    collision meshes as compounds and its fingers' boxes, not the shipped capsule model), and
    nothing to check is refused as the solver refuses it."""
    from moik.collision.catalog import collision_model
    from moik.collision.shapes import Box, Compound
    from moik.exceptions import GeometryError
    from moik.experiments.kinds.ik_collision import checker_of
    from moik.solver.collision import collision_guard, default_model

    robot = get_robot("panda")
    checker = checker_of(robot, {"scene": SCENE, "self_collision": True})
    assert checker.model is default_model(robot)
    kinds = {type(s) for _, s in checker.model.items}  # the fingers' boxes beside the meshes
    assert Compound in kinds and kinds <= {Compound, Box}
    guard = collision_guard(robot, scene=checker.scene, self_collision=True)
    X = robot.random_q(100, rng=np.random.default_rng(5))
    np.testing.assert_array_equal(checker.min_distance_batch(X), guard.distances(X))
    capsules = collision_model(robot)
    assert not any(isinstance(s, Compound) for _, s in capsules.items)
    with pytest.raises(GeometryError, match="nothing to check"):
        checker_of(robot, {"scene": {"obstacles": [], "allowed": []}})
