"""Position-Jacobian rank at solved configurations (moik.experiments.solution_sets)."""

import numpy as np
from scipy.optimize import least_squares

from moik.experiments.solution_sets import position_rank
from moik.robots import get_robot


def _solutions(name, target, n=6, seed=0):
    robot = get_robot(name)
    rng = np.random.default_rng(seed)
    out = []
    for q0 in robot.random_q(n, rng=rng):
        sol = least_squares(lambda q: robot.fk_position(q[None])[0] - target, q0,
                            xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if np.linalg.norm(sol.fun) < 1e-10:
            # the same configuration with each (revolute) joint in [-pi, pi): the
            # unbounded search may leave a joint turns away, which moik warns about
            out.append(np.angle(np.exp(1j * sol.x)))
    return robot, np.array(out)


def test_youbot5_and_sawyer7_solution_sets_are_continua_the_others_isolated():
    dims = {}
    for name, target in [("planar2", [0.35, 0.35, 0.0]), ("youbot5", [0.40, 0.20, 0.10]),
                         ("puma560", [0.40, 0.20, 0.50]), ("sawyer7", [0.80, 0.20, 0.60])]:
        robot, Q = _solutions(name, np.array(target))
        assert len(Q) >= 2, name
        sr = position_rank(robot, Q)
        dims[name] = (int(sr.continuum.max()), sr.static, int(sr.nullity.max()))
    assert dims["planar2"] == (0, (), 0)
    assert dims["youbot5"] == (1, (4,), 2)  # the wrist roll q5 does not move the end point
    assert dims["puma560"] == (0, (3, 4, 5), 3)  # the spherical wrist at the end point
    assert dims["sawyer7"] == (3, (6,), 4)
