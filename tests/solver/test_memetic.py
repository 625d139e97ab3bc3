"""moik/solver/memetic.py: the search algorithm's kernels compiled in a child process
while the first LM stage compiles (when it starts, what the child is given, its stand-in
criteria, when the parent goes on, and that a cold first Pareto solve then compiles none
of them itself and gives the same result)."""

import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import moik
from moik import _background, _jit
from moik.algorithms.archive.fronts import nondominated_mask
from moik.kinematics.criteria import Criterion
from moik.problems.pareto_ik import ParetoIK
from moik.robots import get_robot
from moik.solver import memetic
from moik.solver.memetic import IdentityProjector, stand_in

TARGET = np.array([0.4, 0.2, 0.5])
SEARCH = {"starts": 8, "method": "moeosma", "pop_size": 10, "generations": 2,
          "local_iterations": 1, "local_step": 0.2, "seed": 1}


def _problem(objectives=("manipulability", "limit_margin")):
    return ParetoIK(get_robot("iiwa14"), TARGET, objectives=objectives)


def test_starts_a_child_with_the_problem_and_search(fake_popen):
    problem = _problem()
    handle = memetic.precompile(problem, ("manipulability", "limit_margin"),
                                np.empty((0, 7)), SEARCH)
    assert handle is not None and len(fake_popen.started) == 1
    child = fake_popen.started[0]
    assert child.argv[1:] == ["-m", "moik.solver.memetic"]
    assert child.kwargs["env"][_background.ENV_SWITCH] == "0"  # no grandchild
    searched, first, search, kinematic = pickle.loads(child.written)
    # the search runs on stand-ins of the criteria (no kinematic kernel), no local search
    assert [(c.name, c.sense, c.function.func) for c in searched["objectives"]] == [
        ("manipulability", "max", stand_in), ("limit_margin", "max", stand_in)]
    assert search == {**SEARCH, "local_iterations": 0} and first.shape == (0, 7)
    # then the built-in criteria by name (their kernels)
    assert kinematic["objectives"] == ["manipulability", "limit_margin"]
    assert searched["robot"].name == kinematic["robot"].name == "iiwa14"
    handle.wait()


def test_the_child_never_calls_a_users_criterion(fake_popen):
    calls = []

    def mine(Q):
        calls.append(len(Q))
        return Q[:, 0]

    objectives = ("manipulability", Criterion("reach", mine, "max"))
    memetic.precompile(_problem(objectives), objectives, np.empty((0, 7)), SEARCH)
    searched, _, _, kinematic = pickle.loads(fake_popen.started[0].written)
    for arguments in (searched, kinematic):
        replaced = arguments["objectives"][1]
        assert (replaced.name, replaced.sense) == ("reach", "max")
        assert replaced.function.func is stand_in
    assert kinematic["objectives"][0] == "manipulability" and calls == []


def test_does_not_start_when_the_algorithm_kernels_are_cached(fake_popen, monkeypatch):
    probed = []
    monkeypatch.setattr(_jit, "is_cached", lambda kernel: probed.append(kernel) or True)
    assert memetic.precompile(_problem(), ("manipulability", "limit_margin"),
                              np.empty((0, 7)), SEARCH) is None
    assert not fake_popen.started
    assert memetic.generation_draws in probed and memetic.front_mask_2d in probed


def test_a_single_stand_in_criterion_is_a_joint_value():
    Q = get_robot("iiwa14").random_q(5, rng=np.random.default_rng(4))
    np.testing.assert_array_equal(stand_in(0, 1, "max", Q), -Q[:, 0])


@pytest.mark.parametrize("m", [2, 3])
def test_stand_in_criteria_conflict_like_a_front(m):
    """In minimisation form the stand-ins leave most points non-dominated and some
    dominated (the archive's kernels all run), with the sign of each sense."""
    Q = get_robot("iiwa14").random_q(200, rng=np.random.default_rng(3))
    F = np.column_stack([stand_in(k, m, "min", Q) for k in range(m)])
    front = nondominated_mask(F)
    assert 0.2 * len(Q) < front.sum() < len(Q)
    np.testing.assert_array_equal(stand_in(m - 1, m, "max", Q), -F[:, m - 1])


def test_identity_projection_keeps_every_point_within_the_limits():
    projector = IdentityProjector(_problem())
    robot = projector.robot
    X = np.vstack([robot.lower - 1.0, (robot.lower + robot.upper) / 2])
    P, ok, cost = projector.project(X)
    np.testing.assert_array_equal(P, [robot.lower, (robot.lower + robot.upper) / 2])
    assert ok.all() and not cost.any()


COLD = """
import json, numpy as np, moik
from numba.core import event
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        compiled.append(str(ev.data["dispatcher"].py_func.__module__))
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
res = moik.solve_ik_pareto("iiwa14", np.array([0.4, 0.2, 0.5]), objectives=("manipulability",
    "limit_margin"), n_solutions=5, starts=8, pop_size=10, generations=2, local_iterations=1)
print(json.dumps({"X": res.X.tolist(), "modules": sorted(set(compiled))}))
"""


@pytest.mark.skipif(_background.cpus() < 2, reason="the child needs a second CPU")
def test_cold_first_pareto_solve_loads_the_memetic_kernels_the_child_compiled(tmp_path):
    root = Path(moik.__file__).parent
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("NUMBA_", "MOIK_")) and k != "PYTHONPATH"}
    env.update(NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(root.parent))
    out = subprocess.run([sys.executable, "-c", COLD], capture_output=True, text=True,
                         env=env, cwd=tmp_path, timeout=900)
    assert out.returncode == 0, out.stderr
    cold = json.loads(out.stdout.splitlines()[-1])
    assert "moik.solver.lm" in cold["modules"]  # the cache was cold: LM compiled here
    assert not [m for m in cold["modules"] if m.startswith("moik.algorithms")], cold["modules"]
    warm = moik.solve_ik_pareto("iiwa14", TARGET, objectives=("manipulability", "limit_margin"),
                                n_solutions=5, starts=8, pop_size=10, generations=2,
                                local_iterations=1)
    np.testing.assert_array_equal(np.array(cold["X"]), warm.X)
