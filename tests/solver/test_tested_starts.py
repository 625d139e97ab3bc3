"""The collision-aware start loop of one solve (moik/solver/tested_starts.py) against the
compiled one it stands for (run_starts on a context with the collision set): the same
ends, evaluations, solutions, best candidate and distances, to the bit."""

import numpy as np
import pytest

from moik import get_robot
from moik.collision import Box, CollisionChecker, HalfSpace, Scene, Sphere
from moik.collision.io import rpy_pose
from moik.problems.targets import as_target
from moik.solver.collision import default_model
from moik.solver.context import ik_context
from moik.solver.starts import CHECK, PATIENT, found_table, run_starts
from moik.solver.tested_starts import run_tested_starts

TOL = (1e-9, 1e-9)
STOP = (1e-10, 1e-10)


@pytest.fixture(scope="module")
def arm():
    model = default_model(get_robot("panda"))
    scene = Scene({"table": HalfSpace.plane([0, 0, 1], 0.0),
                   "box": Box(size=(0.3, 0.3, 0.3), pose=rpy_pose([0.45, 0.0, 0.35])),
                   "ball": Sphere(radius=0.15, pose=rpy_pose([0.0, 0.45, 0.5]))},
                  allowed=frozenset({("table", model.links[0]), ("table", model.links[1])}))
    return model.robot, CollisionChecker(model=model, scene=scene, self_collision=True)


def _both(robot, checker, target, starts, policy, want, known, clearance):
    cs = checker.compiled
    out = []
    for tested in (False, True):
        ctx = ik_context(robot, target, stop=STOP, tol=TOL, distinct=0.1,
                         collision=None if tested else cs, clearance=clearance)
        S = starts.copy()
        found = found_table(want, robot.dof, known, [(0.0, 0.0)] * len(known))
        best = np.full(robot.dof + 1, np.inf)
        ends = np.full((len(S), 3), -7.0)
        args = (ctx, S, policy, found, best, ends)
        counts = (run_tested_starts(ctx, cs, clearance, *args[1:]) if tested
                  else run_starts(*args))
        out.append((tuple(int(c) for c in counts), S, found, best, ends))
    return out


@pytest.mark.parametrize("case", range(12))
def test_same_answers_as_the_compiled_test(arm, case):
    robot, checker = arm
    rng = np.random.default_rng(case)
    q = robot.random_q(1, rng=rng)[0]
    # half the targets are poses of configurations in collision: many exact ends rejected
    target = as_target(robot.fk(q) if case % 2 else robot.fk(q)[:3, 3])
    starts = robot.random_q(30, rng=rng)
    want = 1 + case % 4
    known = [robot.random_q(1, rng=rng)[0]] if case % 3 == 0 and want > 1 else []
    budget = [2**62, 400, 2000][case % 3]
    flags = CHECK | (PATIENT if case % 5 == 0 else 0)
    clearance = [0.0, 0.02, 0.1][case % 3]
    compiled, tested = _both(robot, checker, target, starts, (flags, budget), want, known,
                             clearance)
    assert compiled[0] == tested[0]
    for a, b in zip(compiled[1:], tested[1:], strict=True):  # ends, found, best, distances
        np.testing.assert_array_equal(a, b)


def test_rejections_happen_and_are_kept_apart(arm):
    """Over the cases above, some exact ends are rejected for collision and some kept (the
    comparison covers both branches)."""
    robot, checker = arm
    rejected = kept = 0
    for case in range(12):
        rng = np.random.default_rng(case)
        q = robot.random_q(1, rng=rng)[0]
        target = as_target(robot.fk(q))
        _, tested = _both(robot, checker, target, robot.random_q(30, rng=rng), (CHECK, 2**62),
                          4, [], 0.02)
        used = tested[0][2]
        d = tested[4][:used, 2]
        rejected += int(np.sum(~np.isnan(d) & (d < 0.02)))
        kept += tested[0][0]
    assert rejected > 0 and kept > 0


def test_the_compiled_loop_is_called_where_it_is_at_hand(arm, monkeypatch):
    """run_collision_starts: run_starts on the collision context once that loop is compiled
    (here, or in the kernel cache), run_tested_starts before; the same answers."""
    from moik.solver import tested_starts

    robot, checker = arm
    rng = np.random.default_rng(5)
    target = as_target(robot.fk(robot.random_q(1, rng=rng)[0]))
    starts = robot.random_q(10, rng=rng)
    ctx, cctx = (ik_context(robot, target, stop=STOP, tol=TOL, distinct=0.1,
                            collision=cs, clearance=0.02) for cs in (None, checker.compiled))
    calls = []

    def tested(*args):
        calls.append("tested")
        return run_tested_starts(*args)

    monkeypatch.setattr(tested_starts, "run_tested_starts", tested)
    answers = []
    for ready in (False, True):
        monkeypatch.setattr(tested_starts, "loop_at_hand", lambda kind, sig, r=ready: r)
        found, best = found_table(2, robot.dof), np.full(robot.dof + 1, np.inf)
        ends = np.full((len(starts), 3), -7.0)
        counts = tested_starts.run_collision_starts(ctx, lambda: cctx, checker.compiled, 0.02,
                                                    starts.copy(), (CHECK, 2**62), found,
                                                    best, ends)
        answers.append((counts, found, best, ends))
    assert calls == ["tested"]
    assert answers[0][0] == answers[1][0]
    for a, b in zip(answers[0][1:], answers[1][1:], strict=True):
        np.testing.assert_array_equal(a, b)


def test_is_cached_for_knows_a_signature_compiled_here(arm):
    from numba import types

    from moik import _jit
    from moik.solver.starts import solution_cost

    robot, _ = arm
    ctx = ik_context(robot, as_target(np.zeros(3)), stop=STOP, tol=TOL)
    solution_cost(ctx)
    assert _jit.is_cached_for(solution_cost, (solution_cost.typeof_pyval(ctx),))
    assert not _jit.is_cached_for(solution_cost, (types.float64,))  # never compiled
