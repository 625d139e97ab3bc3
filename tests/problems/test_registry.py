"""The registry of named IK benchmark problems and their reference fronts."""

import numpy as np
import pytest
from pymoo.indicators.gd import GD
from pymoo.indicators.hv import HV
from pymoo.indicators.igd import IGD
from pymoo.indicators.igd_plus import IGDPlus

from moik.exceptions import ParameterError, UnknownNameError
from moik.fronts.cache import DEFAULT_SETTINGS, SHIPPED, fingerprint
from moik.problems import BiObjectiveIK, PoseMotionIK, available, get_problem
from moik.problems.registry import ARMS

BI = [n for n in available() if not n.endswith("-motion")]


def test_names_cover_the_papers_and_every_arm():
    names = available()
    assert {"eosma-p1", "eosma-p2", "mpso-eq16", "eosma-p1-motion"} <= set(names)
    assert {f"{a}-{k}" for a in ARMS for k in ("reachable", "unreachable")} <= set(names)
    assert len(ARMS) == 6 and len(set(names)) == len(names)


def test_unknown_name_lists_the_valid_ones():
    with pytest.raises(UnknownNameError, match="eosma-p1"):
        get_problem("eosma-p9")


@pytest.mark.parametrize("name", BI)
def test_front_is_shipped_and_works_with_pymoo_indicators(name):
    problem = get_problem(name)
    assert isinstance(problem, BiObjectiveIK)
    key = fingerprint(problem.robot, problem.target.position, problem.target.rotation,
                      problem.orientation, DEFAULT_SETTINGS)
    assert (SHIPPED / f"{key}.npz").is_file(), "stale: run python -m studies.ik_fronts --write"
    pf = problem.pareto_front()
    assert pf.ndim == 2 and pf.shape[1] == 2 and np.all(np.isfinite(pf)) and np.all(pf >= 0)
    X = problem.robot.random_q(20, rng=np.random.default_rng(0))
    F = problem.evaluate(X)
    for indicator in (IGD(pf), IGDPlus(pf), GD(pf)):
        assert indicator(F) > 0  # random joint vectors are off the front
    assert IGD(pf)(pf) == 0
    box = F.max(axis=0) * 1.1
    assert HV(ref_point=box)(pf) >= HV(ref_point=box)(F)


def test_reachable_poses_have_the_ideal_point():
    for arm in ARMS:
        np.testing.assert_array_equal(get_problem(f"{arm}-reachable").pareto_front(),
                                      [[0.0, 0.0]])
    np.testing.assert_array_equal(get_problem("eosma-p2").pareto_front(), [[0.0, 0.0]])


def test_unreachable_poses_have_a_front_away_from_the_origin():
    for arm in ARMS:
        assert get_problem(f"{arm}-unreachable").pareto_front()[:, 0].min() > 0


def test_three_objective_variant():
    problem = get_problem("eosma-p1-motion")
    assert isinstance(problem, PoseMotionIK) and problem.n_obj == 3
    q = np.zeros((1, problem.n_var))
    F = problem.evaluate(q)
    pos, ori = problem.errors(q)
    np.testing.assert_allclose(F, [[pos[0], ori[0], 0.0]])
    pf = problem.pareto_front()  # the shipped three-objective front (tests/fronts/test_motion)
    assert pf.shape[1] == 3
    np.testing.assert_allclose(pf[pf[:, 2].argmin()], F[0], atol=1e-12)  # q = 0 moves by 0
    with pytest.raises(ParameterError, match="smooth orientation metric"):
        PoseMotionIK(problem.robot, problem.target, q_start=q[0],
                     orientation="zyx-euler").pareto_front()
