"""Targets: construction from every accepted form, random sets, circle path."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from moik.exceptions import NonFiniteError, ShapeError, TargetError, UnknownNameError
from moik.problems import Target, as_target, circle_path, random_reachable_targets
from moik.robots import get_robot


def test_as_target_forms():
    R = Rotation.from_rotvec([0.1, 0.2, 0.3]).as_matrix()
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, [1, 2, 3]
    for spec in (T, ([1, 2, 3], R), Target([1, 2, 3], R)):
        t = as_target(spec)
        np.testing.assert_array_equal(t.position, [1, 2, 3])
        np.testing.assert_allclose(t.rotation, R)
    assert as_target([1, 2, 3]).rotation is None
    np.testing.assert_allclose(as_target(T).pose, T)


def test_from_euler_degrees_flag():
    a = Target.from_euler([0, 0, 0], [0, -30, -23.8], degrees=True)
    b = Target.from_euler([0, 0, 0], np.radians([0, -30, -23.8]))
    np.testing.assert_allclose(a.rotation, b.rotation)
    with pytest.raises(TargetError, match="angles are radians"):
        Target.from_euler([0, 0, 0], [0, -30, -23.8])
    with pytest.raises(UnknownNameError, match="unknown Euler convention 'xyz'"):
        Target.from_euler([0, 0, 0], [0, 0, 0], convention="xyz")


def test_random_targets_reproducible_and_reachable():
    robot = get_robot("rokbani5")
    a = random_reachable_targets(robot, 10, seed=3)
    b = random_reachable_targets(robot, 10, seed=3)
    for ta, tb in zip(a, b, strict=True):
        np.testing.assert_array_equal(ta.position, tb.position)
        assert robot.within_limits(ta.q_source)[0]
        np.testing.assert_allclose(robot.fk(ta.q_source)[:3, 3], ta.position)


def test_circle_path_eq17():
    """MO-m-PSO Section 4.4: centre (15, 0, 12) cm, radius 8 cm, 50 points."""
    pts = np.array([t.position for t in circle_path([15, 0, 12], 8, 50)])
    assert pts.shape == (50, 3)
    np.testing.assert_allclose(pts[:, 0], 15)
    np.testing.assert_allclose(np.hypot(pts[:, 1], pts[:, 2] - 12), 8)
    np.testing.assert_allclose(pts[0], [15, 8, 12])


def test_bad_targets():
    with pytest.raises(ShapeError, match=r"target must be a 3-vector position, a \(4, 4\) pose"):
        as_target(np.zeros(5))
    with pytest.raises(NonFiniteError, match="target position must be finite"):
        Target([np.nan, 0, 0])
    with pytest.raises(TargetError, match="must be a rotation matrix"):
        Target([0, 0, 0], np.ones((3, 3)))
    with pytest.raises(TargetError, match=r"pose last row must be \[0, 0, 0, 1\]"):
        Target.from_pose(np.ones((4, 4)))
    with pytest.raises(TargetError, match="radius must be a positive"):
        circle_path([0, 0, 0], -1, 10)
    with pytest.raises(TargetError, match="n must be an integer >= 1"):
        random_reachable_targets(get_robot("planar2"), 0, seed=0)


def test_pose_fast_path_gives_private_contiguous_copies():
    """A valid pose (checked in one compiled pass) gives the same target as the checks one
    by one: contiguous copies, independent of the caller's array."""
    T = get_robot("eosma7").fk(np.zeros(7))
    target = as_target(T)
    assert np.array_equal(target.position, T[:3, 3])
    assert np.array_equal(target.rotation, T[:3, :3])
    assert target.rotation.flags.c_contiguous and target.position.flags.c_contiguous
    T[:3, :] = 0.0
    assert np.any(target.rotation != 0.0) and target.q_source is None


@pytest.mark.parametrize("where, value, error", [
    ((3, 0), np.nan, TargetError), ((0, 0), np.nan, NonFiniteError),
    ((0, 3), np.inf, NonFiniteError), ((3, 3), 2.0, TargetError), ((0, 1), 0.3, TargetError)])
def test_pose_fast_path_falls_back_to_the_named_check(where, value, error):
    T = np.eye(4)
    T[where] = value
    with pytest.raises(error):
        as_target(T)


def test_a_robot_of_zero_reach_is_refused_by_every_solver():
    """Every joint and the tool at the base's origin: FK works (the tool stays at the
    origin), every solver refuses it with a clear error (it divided by the reach: a raw
    ZeroDivisionError deep in the solver before)."""
    from moik import Robot, solve_ik, solve_path
    from moik.solver import solve_ik_batch, solve_ik_pareto

    robot = Robot(name="wrist", origins=np.broadcast_to(np.eye(4), (4, 4, 4)),
                  lower=[-1.0] * 3, upper=[1.0] * 3)
    assert robot.reach == 0.0
    np.testing.assert_array_equal(robot.fk(np.array([0.3, -0.2, 0.5]))[:3, 3], 0.0)
    for call in (lambda: solve_ik(robot, np.zeros(3)),
                 lambda: solve_ik_batch(robot, np.zeros((2, 3))),
                 lambda: solve_path(robot, np.zeros((2, 3))),
                 lambda: solve_ik_pareto(robot, np.zeros(3))):
        with pytest.raises(TargetError, match="zero reach"):
            call()
