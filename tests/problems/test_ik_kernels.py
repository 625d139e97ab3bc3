"""The compiled IK objectives (moik.problems.ik_kernels): a row at a time, from Python and
from compiled code (moik._jit.objectives_row), equal to the problems' evaluate."""

import numpy as np
import pytest

from moik._jit import objectives_row
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, random_reachable_targets
from moik.robots import get_robot


@pytest.mark.parametrize("make", [
    lambda r, t: PositionIK(r, t.position),
    lambda r, t: PoseIK(r, t, orientation="eosma-euler"),
    lambda r, t: BiObjectiveIK(r, t, displacement_weight=0.1, q_start=np.zeros(r.dof)),
], ids=["position", "pose", "bi-objective"])
def test_a_row_at_a_time_equals_evaluate(make):
    robot = get_robot("panda")
    problem = make(robot, random_reachable_targets(robot, 1, seed=3)[0])
    Q = np.random.default_rng(1).uniform(problem.xl, problem.xu, (5, problem.n_var))
    spec = problem.compiled_objectives()
    out = np.full((5, problem.n_obj), np.nan)
    for i in range(5):
        objectives_row(spec, Q, out, i)  # from Python: spec.write_row
    np.testing.assert_array_equal(out, problem.evaluate(Q).reshape(5, problem.n_obj))


def test_a_subclass_that_evaluates_otherwise_has_no_compiled_objectives():
    robot = get_robot("panda")

    class Shifted(PositionIK):
        def _evaluate(self, X, out, *args, **kwargs):
            super()._evaluate(X, out, *args, **kwargs)
            out["F"] = out["F"] + 1.0

    assert Shifted(robot, [0.3, 0.2, 0.5]).compiled_objectives() is None
