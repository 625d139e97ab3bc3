"""Bit-level fingerprints of results: every registered algorithm on a small
problem at a fixed seed, the IK problems' objectives, and ``solve_ik`` on a few
poses. A refactoring that keeps behaviour keeps these hashes.

Run ``python tests/fingerprint/test_fingerprint.py`` to print the current values
(the stored ones live in ``fingerprints.json`` beside this file).

Bit-level results hold on one kind of machine, not across them: numpy dispatches its
sorts (the order of ties) and reductions (the summation order) on the CPU's SIMD
features, so pymoo's NSGA-II gives other bits on an AVX2 machine than on an AVX-512
one from the same seed. ``fingerprints.json`` therefore records the SIMD features
it was recorded with (``machine``); on another kind of machine the tests fail with a
message that says so, instead of a bare hash mismatch.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

import moik
from moik.algorithms import available, get_algorithm
from moik.algorithms.registry import is_multi_objective
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, random_reachable_targets
from moik.robots import get_robot

FILE = Path(__file__).with_name("fingerprints.json")


class _ShiftedSphere(Problem):
    def __init__(self):
        super().__init__(n_var=5, n_obj=1, xl=-5.0, xu=3.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = ((X - 1.3) ** 2).sum(axis=1)


def digest(*arrays) -> str:
    h = hashlib.sha256()
    for a in arrays:
        a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
        h.update(str(a.shape).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:20]


def algorithm_fingerprint(name: str) -> str:
    if is_multi_objective(name):
        problem, budget = get_problem("zdt1", n_var=6), 600
    else:
        problem, budget = _ShiftedSphere(), 600
    res = minimize(problem, get_algorithm(name), ("n_eval", budget), seed=3)
    return digest(res.X, res.F)


def problem_fingerprints() -> dict[str, str]:
    robot = get_robot("eosma7")
    target = random_reachable_targets(robot, 1, seed=5)[0]
    X = np.random.default_rng(0).uniform(robot.lower, robot.upper, (20, robot.dof))
    out = {}
    for key, problem in [("PositionIK", PositionIK(robot, target.position)),
                         ("PoseIK-eosma-euler", PoseIK(robot, target, orientation="eosma-euler")),
                         ("PoseIK-geodesic", PoseIK(robot, target, orientation="geodesic")),
                         ("BiObjectiveIK", BiObjectiveIK(robot, target))]:
        out[key] = digest(problem.evaluate(X, return_values_of=["F"]))
    return out


def solver_fingerprints() -> dict[str, str]:
    out = {}
    for name in ("eosma7", "puma560", "rokbani5"):
        robot = get_robot(name)
        for i, target in enumerate(random_reachable_targets(robot, 2, seed=11)):
            pose = target.position if name == "rokbani5" else target.pose
            res = moik.solve_ik(robot, pose, seed=i, n_solutions=2)
            out[f"{name}-{i}"] = digest(res.q, res.solutions, [res.n_eval]) + ":" + res.status
    return out


def machine_signature() -> str:
    """The SIMD features numpy dispatches on here (they decide its sorts' and sums' bits)."""
    from numpy._core._multiarray_umath import __cpu_features__

    return " ".join(sorted(k for k, on in __cpu_features__.items() if on))


def current() -> dict[str, dict[str, str] | str]:
    return {"algorithms": {n: algorithm_fingerprint(n) for n in available()},
            "problems": problem_fingerprints(),
            "solver": solver_fingerprints(),
            "machine": machine_signature()}

STORED = json.loads(FILE.read_text()) if FILE.exists() else {"algorithms": {}}


@pytest.fixture(autouse=True)
def _same_kind_of_machine():
    recorded = STORED.get("machine")
    if recorded != machine_signature():
        pytest.fail("fingerprints.json was recorded on a machine whose numpy SIMD features are "
                    f"{recorded!r}; this one has {machine_signature()!r}. numpy's sorts and sums "
                    "give other bits there: check on the recording kind of machine that a "
                    "change keeps the fingerprints, then re-record them here with "
                    "`python tests/fingerprint/test_fingerprint.py`.")


@pytest.mark.parametrize("name", sorted(STORED["algorithms"]))
def test_algorithm_result_unchanged(name):
    assert algorithm_fingerprint(name) == STORED["algorithms"][name]


def test_registry_has_no_unfingerprinted_algorithm():
    assert sorted(available()) == sorted(STORED["algorithms"])


def test_ik_objectives_unchanged():
    assert problem_fingerprints() == STORED["problems"]


def test_solver_unchanged():
    assert solver_fingerprints() == STORED["solver"]


if __name__ == "__main__":
    FILE.write_text(json.dumps(current(), indent=1, sort_keys=True) + "\n")
    print(FILE.read_text())
