"""Batched Levenberg-Marquardt IK: same residuals as the single-start model, convergence, limits."""

import numpy as np
import pytest

from moik import load_urdf
from moik.problems import random_reachable_targets
from moik.problems.targets import Target
from moik.robots import get_robot
from moik.solver.batch_lm import _residuals, batch_lm
from moik.solver.polish import ResidualModel
from moik.solver.session import pose_errors


def _robots():
    from pathlib import Path
    urdf = Path(__file__).resolve().parents[3] / "shared" / "data" / "urdf"
    robots = [get_robot(n) for n in ("eosma7", "scara4", "puma560", "irb2600")]
    if (urdf / "lbr_iiwa_14_r820.urdf").exists():
        robots.append(load_urdf(urdf / "lbr_iiwa_14_r820.urdf", name="iiwa14"))
    return robots


@pytest.mark.parametrize("robot", _robots(), ids=lambda r: r.name)
@pytest.mark.parametrize("with_rotation", [True, False])
def test_batched_residuals_equal_the_single_start_model(robot, with_rotation):
    target = random_reachable_targets(robot, 1, seed=2, with_orientation=with_rotation)[0]
    Q = robot.random_q(5, rng=np.random.default_rng(4))
    r, J = _residuals(robot, target, robot.reach, Q)
    model = ResidualModel(robot, target, robot.reach)
    for i in range(5):
        np.testing.assert_allclose(r[i], model.residual(Q[i]), atol=1e-12)
        np.testing.assert_allclose(J[i], model.jacobian(Q[i]), atol=1e-12)


@pytest.mark.parametrize("name", ["eosma7", "puma560", "sawyer7", "scara4"])
def test_converges_from_a_nearby_start(name):
    """Start 0.2 rad (or 10 % of a prismatic stroke) from a known solution."""
    robot = get_robot(name)
    rng = np.random.default_rng(7)
    q_true = robot.random_q(1, rng=rng)[0]
    T = robot.fk(q_true)
    target = Target(T[:3, 3], T[:3, :3])
    Q0 = np.clip(q_true + 0.1 * (robot.upper - robot.lower).clip(max=2.0)
                 * rng.uniform(-1, 1, (3, robot.dof)), robot.lower, robot.upper)
    tol = 1e-12
    out = batch_lm(robot, target, Q0, length=robot.reach, stop_position=tol * robot.reach,
                   stop_orientation=tol, max_iter=50)
    assert out.converged.all()
    assert np.all(robot.within_limits(out.Q))
    pos, ori = pose_errors(robot, target, out.Q)
    assert pos.max() <= 1e-11 * robot.reach and ori.max() <= 1e-11
    np.testing.assert_allclose(out.position_error, pos, atol=1e-12 * robot.reach)


def test_stop_after_and_determinism():
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=9)[0]
    Q0 = robot.random_q(16, rng=np.random.default_rng(1))
    kwargs = dict(length=robot.reach, stop_position=1e-12 * robot.reach,
                  stop_orientation=1e-12, max_iter=40)
    full = batch_lm(robot, target, Q0, **kwargs)
    early = batch_lm(robot, target, Q0, stop_after=1, **kwargs)
    again = batch_lm(robot, target, Q0, stop_after=1, **kwargs)
    assert full.converged.sum() >= 2
    assert 1 <= early.converged.sum() <= full.converged.sum()
    assert early.n_eval < full.n_eval
    np.testing.assert_array_equal(early.Q, again.Q)
    assert np.all(robot.within_limits(full.Q))


def test_position_only_target_uses_three_rows():
    robot = get_robot("rokbani5")
    target = random_reachable_targets(robot, 1, seed=3, with_orientation=False)[0]
    out = batch_lm(robot, target, robot.random_q(8, rng=np.random.default_rng(0)),
                   length=robot.reach, stop_position=1e-12 * robot.reach,
                   stop_orientation=0.0, max_iter=40)
    assert out.converged.any()
    assert np.all(out.orientation_error == 0.0)
