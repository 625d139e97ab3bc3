"""moik/warmup/beside.py: the ``"pareto-search"`` child of a cold first Pareto solve (when it
starts, what it is given, its stand-in criteria, and that a cold first Pareto solve after
it compiles none of the algorithm's kernels and gives the same result), and the
``"solve-leaves"`` child of a cold first plain solve (the same checks; the
``"collision-leaves"`` child's are in test_beside_collision.py, a file of its own so that
the two cold-cache runs share the default run's two workers)."""

import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import moik
from moik import _jit, warmup
from moik.algorithms.archive.fronts import nondominated_mask
from moik.kinematics.criteria import Criterion
from moik.robots import get_robot
from moik.warmup import background, beside
from moik.warmup.beside import StandInCriteria, beside_pareto, beside_solve, stand_in

TARGET = np.array([0.4, 0.2, 0.5])
SEARCH = {"objectives": ("manipulability", "limit_margin"), "n_solutions": 5, "starts": 8,
          "pop_size": 10, "generations": 2, "local_iterations": 1}


def _given(fake_popen):
    family, arguments = pickle.loads(fake_popen.started[0].written)
    assert family == "pareto-search"
    return arguments


def test_starts_the_pareto_search_child_with_the_solves_search(fake_popen):
    robot = get_robot("iiwa14")
    assert beside_pareto(robot, TARGET, **SEARCH) is not None
    given = _given(fake_popen)
    assert fake_popen.started[0].argv[1:] == ["-m", "moik.warmup"]
    assert given["robot"].name == "iiwa14" and given["m"] == 2
    assert given["criteria"] == ["manipulability", "limit_margin"]
    # the solve's defaults where not given
    assert (given["method"], given["pop_size"], given["generations"]) == ("moeosma", 10, 2)
    assert given["q_current"] is None and given["rotation"] is None


def test_the_child_is_never_given_a_users_criterion(fake_popen):
    mine = Criterion("reach", lambda Q: Q[:, 0], "max")
    beside_pareto(get_robot("iiwa14"), TARGET, objectives=("manipulability", mine))
    given = _given(fake_popen)
    assert given["criteria"] == ["manipulability"] and given["m"] == 2


@pytest.mark.parametrize("why", ["not redundant", "bad option", "cached"])
def test_starts_no_child_where_it_cannot_help(fake_popen, monkeypatch, why):
    robot, target, options = get_robot("iiwa14"), TARGET, dict(SEARCH)
    if why == "not redundant":  # a 6-joint arm at a pose: no search, no algorithm
        robot, target = get_robot("ur5"), np.eye(4)
    elif why == "bad option":
        options["no_such_option"] = 1  # the solve refuses it: nothing to compile for
    else:
        probed = []
        monkeypatch.setattr(_jit, "is_cached", lambda kernel: probed.append(kernel) or True)
    assert beside_pareto(robot, target, **options) is None
    assert not fake_popen.started
    if why == "cached":
        assert {k.__name__ for k in probed} == {"front_mask_2d", "generation_draws"}


def test_a_single_stand_in_criterion_is_a_joint_value():
    Q = get_robot("iiwa14").random_q(5, rng=np.random.default_rng(4))
    np.testing.assert_array_equal(stand_in(0, 1, Q), Q[:, 0])


@pytest.mark.parametrize("m", [2, 3])
def test_stand_in_criteria_conflict_like_a_front(m):
    """The stand-ins leave most points non-dominated and some dominated (the archive's
    kernels all run)."""
    Q = get_robot("iiwa14").random_q(200, rng=np.random.default_rng(3))
    F = np.column_stack([stand_in(k, m, Q) for k in range(m)])
    front = nondominated_mask(F)
    assert 0.2 * len(Q) < front.sum() < len(Q)


def test_the_stand_in_problem_gives_one_criterion_twice():
    robot = get_robot("iiwa14")
    problem = StandInCriteria(robot, 1)
    F = problem.evaluate(robot.random_q(3, rng=np.random.default_rng(0)))
    assert problem.n_obj == 2 and F.shape == (3, 2)
    np.testing.assert_array_equal(F[:, 0], F[:, 1])


COLD = """
import json, pickle, subprocess, sys, numpy as np, moik
from numba.core import event
from moik.warmup.beside import beside_pareto
from moik.warmup import background
captured = []
background.start = lambda family, arguments, probes: captured.append((family, arguments))
search = dict(objectives=("manipulability", "limit_margin"), n_solutions=5, starts=8,
              pop_size=10, generations=2, local_iterations=1)
robot, target = moik.get_robot("iiwa14"), np.array([0.4, 0.2, 0.5])
beside_pareto(robot, target, **search)
child = subprocess.run([sys.executable, "-m", "moik.warmup"], input=pickle.dumps(captured[0]))
assert child.returncode == 0
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        compiled.append(str(ev.data["dispatcher"].py_func.__module__))
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
res = moik.solve_ik_pareto(robot, target, **search)
print(json.dumps({"X": res.X.tolist(), "modules": sorted(set(compiled))}))
"""


def _run_cold(code: str, tmp_path) -> dict:
    """``code`` in a fresh interpreter of this moik on an empty kernel cache (no background
    child of its own); the JSON its last line prints."""
    root = Path(moik.__file__).parent
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("NUMBA_", "MOIK_")) and k != "PYTHONPATH"}
    env.update(NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(root.parent),
               **{background.ENV_SWITCH: "0"})
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, cwd=tmp_path, timeout=900)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.splitlines()[-1])


def test_a_cold_first_pareto_solve_loads_the_algorithm_kernels_the_child_compiled(tmp_path):
    """In a fresh interpreter on an empty cache the child runs to its end first; the solve
    then compiles its LM kernels and none of the algorithm's or archive's (the child's
    numba types are the solve's), and its result is the warm one."""
    cold = _run_cold(COLD, tmp_path)
    assert "moik.solver.lm" in cold["modules"]  # the cache was cold: LM compiled here
    assert not [m for m in cold["modules"] if m.startswith("moik.algorithms")], cold["modules"]
    assert not {"moik.kinematics.criteria_kernels", "moik.kinematics.jacobian"} & set(
        cold["modules"]), cold["modules"]
    warm = moik.solve_ik_pareto("iiwa14", TARGET, **SEARCH)
    np.testing.assert_array_equal(np.array(cold["X"]), warm.X)


def test_every_background_family_has_a_child_workload():
    assert set(warmup.BESIDE) == {"collision-leaves", "collision-stand-in", "front-leaves",
                                  "pareto-search", "solve-leaves"}
    for path in warmup.BESIDE.values():
        assert callable(beside.kernel(path))


def test_starts_the_solve_leaves_child_for_the_arm(fake_popen):
    assert beside_solve(get_robot("puma560")) is not None
    family, arguments = pickle.loads(fake_popen.started[0].written)
    assert family == "solve-leaves" and arguments["robot"].name == "puma560"


@pytest.mark.parametrize("target, family", [
    ((0.4, 0.2, 0.3), "solve-leaves"), ((2.0, 0.0, 0.0), "front-leaves"),
    (np.eye(4), "solve-leaves"), (None, "solve-leaves")])
def test_the_child_compiles_the_leaves_of_the_targets_path(fake_popen, target, family):
    """A target beyond puma560's reach (0.9 m) runs the front, not the start loop."""
    assert beside_solve(get_robot("puma560"), target) is not None
    assert pickle.loads(fake_popen.started[0].written)[0] == family


def test_a_target_the_solve_refuses_starts_no_child(fake_popen):
    assert beside_solve(get_robot("puma560"), np.array([np.nan, 0.0, 0.0])) is None
    assert beside_solve(get_robot("puma560"), "no target") is None
    assert not fake_popen.started


def test_starts_no_solve_leaves_child_when_they_are_cached(fake_popen, monkeypatch):
    probed = []
    monkeypatch.setattr(_jit, "is_cached", lambda kernel: probed.append(kernel) or True)
    assert beside_solve(get_robot("puma560")) is None
    assert not fake_popen.started
    assert {k.__name__ for k in probed} == {"run_starts", "damped_step"}
    assert beside_solve("puma560") is None  # a name, not a Robot: the solve says what it is


COLD_SOLVE = """
import json, pickle, subprocess, sys, numpy as np, moik
from numba.core import event
from moik.warmup.beside import beside_solve
from moik.warmup import background
captured = []
background.start = lambda family, arguments, probes: captured.append((family, arguments))
robot = moik.get_robot("puma560")
beside_solve(robot)
child = subprocess.run([sys.executable, "-m", "moik.warmup"], input=pickle.dumps(captured[0]))
assert child.returncode == 0
compiled = []
class Recorder(event.Listener):
    def on_start(self, ev):
        f = ev.data["dispatcher"].py_func
        compiled.append(f"{f.__module__}.{f.__qualname__}")
    def on_end(self, ev):
        pass
event.register("numba:compile", Recorder())
res = moik.solve_ik(robot, np.array([0.4, 0.2, 0.3]))
print(json.dumps({"q": res.q.tolist(), "kernels": sorted(set(compiled))}))
"""


def test_a_cold_first_solve_loads_the_leaves_the_child_compiled(tmp_path):
    """In a fresh interpreter on an empty cache the child runs to its end first; the solve
    then compiles its start loop but none of the leaves the child wrote (its numba types
    are the solve's), and its answer is the warm one."""
    cold = _run_cold(COLD_SOLVE, tmp_path)
    assert "moik.solver.starts.run_starts" in cold["kernels"]  # the cache was cold
    leaves = {"moik.solver.lm.damped_step", "moik.solver.starts.recheck",
              "moik.solver.starts.keep_found", "moik.solver.starts.improve_best",
              "moik.solver.start_streams._seed_state"}
    assert not leaves & set(cold["kernels"]), cold["kernels"]
    warm = moik.solve_ik("puma560", np.array([0.4, 0.2, 0.3]))
    np.testing.assert_array_equal(np.array(cold["q"]), warm.q)


COLD_FRONT = COLD_SOLVE.replace("beside_solve(robot)", "beside_solve(robot, [2.0, 0.0, 0.0])"
                                ).replace("[0.4, 0.2, 0.3]", "[2.0, 0.0, 0.0]")


def test_a_cold_first_unreachable_solve_loads_the_leaves_the_child_compiled(tmp_path):
    """The ``"front-leaves"`` child's kernels are those of the front's path (its numba
    types are the solve's): the solve compiles its front loop but not them."""
    cold = _run_cold(COLD_FRONT, tmp_path)
    assert "moik.solver.starts.lm_front" in cold["kernels"]  # the cache was cold
    leaves = {"moik.solver.lm.damped_step", "moik.robots.fk_kernels.fk_rotations_positions",
              "moik.robots.fk_kernels.joint_screen"}
    assert not leaves & set(cold["kernels"]), cold["kernels"]
    assert "moik.solver.starts.run_starts" not in cold["kernels"]  # no start loop: none needed
    warm = moik.solve_ik("puma560", np.array([2.0, 0.0, 0.0]))
    np.testing.assert_array_equal(np.array(cold["q"]), warm.q)

