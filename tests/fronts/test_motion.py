"""The three-objective reference front (moik.fronts.motion): position error, orientation
error and joint motion from ``q_start``.

Oracles: on the 2-DOF ``planar2`` (out-of-reach target, as tests/fronts/test_front.py) a
dense grid over both joints (every joint vector on a 0.005 rad grid, an independent
enumeration of the objective space) and a long NSGA-II run; on ``eosma-p1-motion`` (the
shipped front) a long NSGA-II run. No point of theirs may beat a reference point by more
than ``TOL`` of the front's range in every objective (:func:`moik.fronts.dominating_points`).
"""

import numpy as np
import pytest
from pymoo.algorithms.moo.nsga2 import NSGA2
from pymoo.indicators.igd import IGD
from pymoo.optimize import minimize

from moik.exceptions import ParameterError
from moik.fronts import dominating_points
from moik.fronts.cache import MOTION_SETTINGS, SHIPPED, fingerprint
from moik.fronts.motion import motion_front
from moik.problems import PoseMotionIK, get_problem
from moik.robots.catalog import get_robot

TOL = 1e-3  # a share of the front's range per objective (the grid's step is 0.005 rad)
D, PSI, PHI = 0.9, 0.8, -0.4
Q_START = np.array([-1.0, 2.0])


def _target():
    c, s = np.cos(PHI), np.sin(PHI)
    return (np.array([D * np.cos(PSI), D * np.sin(PSI), 0.0]),
            np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]))


@pytest.fixture(scope="module")
def planar():
    robot = get_robot("planar2")
    p, R = _target()
    front = motion_front(robot, p, R, Q_START, levels=8, motion_levels=8, starts=6,
                         rng=np.random.default_rng(5))
    return PoseMotionIK(robot, (p, R), q_start=Q_START), front


def test_planar_front_holds_q_start_and_is_non_dominated(planar):
    problem, front = planar
    F = front.F
    assert F.shape[1] == 3 and len(F) > 10 and np.all(F >= 0)
    np.testing.assert_allclose(F[F[:, 2].argmin()], problem.evaluate(Q_START[None])[0],
                               atol=1e-12)  # the only point that does not move
    assert len(dominating_points(F, F, 1e-9)) == 0
    # the least position error: pointing at the target, D - l1 - l2 (closed form)
    assert F[:, 0].min() == pytest.approx(D - 0.35 - 0.30, abs=1e-7)
    np.testing.assert_allclose(problem.evaluate(front.Q), F, atol=1e-12)


def test_no_grid_point_or_nsga2_point_beats_the_planar_front(planar):
    problem, front = planar
    grid = np.linspace(-np.pi, np.pi, 1257)
    Q = np.stack(np.meshgrid(grid, grid), axis=-1).reshape(-1, 2)
    F = problem.evaluate(Q)
    assert len(dominating_points(front.F, F, TOL)) == 0
    res = minimize(problem, NSGA2(pop_size=100), ("n_gen", 200), seed=3)
    assert len(dominating_points(front.F, res.F, TOL)) == 0


def test_eosma_p1_motion_front_is_shipped_and_not_beaten_by_nsga2():
    problem = get_problem("eosma-p1-motion")
    key = fingerprint(problem.robot, problem.target.position, problem.target.rotation,
                      problem.orientation, MOTION_SETTINGS, np.zeros(problem.n_var))
    assert (SHIPPED / f"{key}.npz").is_file(), "stale: run python -m studies.ik_fronts --write"
    pf = problem.pareto_front()
    assert pf.ndim == 2 and pf.shape[1] == 3 and np.all(np.isfinite(pf))
    res = minimize(problem, NSGA2(pop_size=100), ("n_gen", 300), seed=7)
    assert len(dominating_points(pf, res.F, 1e-6)) == 0
    assert IGD(pf)(res.F) > 0 and IGD(pf)(pf) == 0


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"metric": "zyx-euler"}, "smooth orientation metric"),
    ({"q_start": [4.0, 0.0]}, "within the limits"),
    ({"levels": 1}, "levels"),
])
def test_bad_settings_raise(kwargs, match):
    p, R = _target()
    args = {"q_start": Q_START, **kwargs}
    with pytest.raises(ParameterError, match=match):
        motion_front(get_robot("planar2"), p, R, rng=np.random.default_rng(0), **args)
