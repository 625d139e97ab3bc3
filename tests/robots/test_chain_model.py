"""moik/robots/chain_model.py: the arm as one compiled record, built once per Robot."""

import copy
import pickle

import numpy as np

from moik._jit import jit
from moik.robots import get_robot


@jit
def _fields(model):
    return (model.origins.shape[0], model.link_frames.shape[0], model.base[0, 3],
            model.joint_types.size, model.lower[0], model.upper[-1], model.inv_reach)


def test_fields_are_the_robots():
    robot = get_robot("panda")
    chain = robot.kinematic_chain
    n_origins, n_links, base_x, dof, lo, hi, inv_reach = _fields(robot.chain_model)
    assert (n_origins, n_links, dof) == (robot.dof + 1, robot.dof, robot.dof)
    assert (base_x, lo, hi) == (robot.base[0, 3], robot.lower[0], robot.upper[-1])
    assert inv_reach == 1.0 / robot.reach
    assert chain.origins.shape == (robot.dof + 1, 4, 4)


def test_built_once_per_robot():
    robot = get_robot("ur5")
    assert robot.chain_model is robot.chain_model


def test_a_robot_pickles_and_copies_without_it():
    """A StructRef does not pickle: the robot drops its record and builds it again."""
    robot = get_robot("iiwa14")
    model = robot.chain_model
    for twin in (pickle.loads(pickle.dumps(robot)), copy.deepcopy(robot)):
        assert "chain_model" not in twin.__dict__
        assert twin.chain_model is not model
        assert _fields(twin.chain_model) == _fields(model)
        q = np.zeros(robot.dof)
        np.testing.assert_array_equal(twin.fk(q), robot.fk(q))
