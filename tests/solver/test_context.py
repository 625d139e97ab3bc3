"""The constants of one solve (IKContext, built only by ik_context), retarget, solver_target
and the Levenberg-Marquardt workspace: each field holds what was passed, read in compiled
code as the kernels read it. The arm is ``planar2``, its poses written by hand
(tests/solver/planar2_cases.py).
"""

import numpy as np
import pytest

from moik._jit import jit
from moik.collision import CollisionChecker, CollisionModel, Sphere
from moik.collision.compiled import checks_pairs
from moik.kinematics.target_spec import NO_METRIC
from moik.problems.targets import Target
from moik.solver.context import (
    LM_ITERATIONS,
    NO_STOP,
    ik_context,
    lm_workspace,
    retarget,
    solver_target,
)
from moik.solver.starts import recheck, run_starts
from tests.solver.planar2_cases import ARM, rz, tool


@jit
def _fields(ctx):
    t = ctx.target
    return (t.position.copy(), t.rotation.copy(), t.has_rotation, t.code,
            (ctx.stop_position, ctx.stop_orientation, ctx.tol_position, ctx.tol_orientation,
             ctx.distinct, ctx.clearance, ctx.chain.inv_reach),
            ctx.max_iter, checks_pairs(ctx.collision))


@jit
def _workspace_shapes(dof):
    ws = lm_workspace(dof)
    return (ws.T.shape, ws.M.shape, ws.J.shape, ws.r.shape, ws.Jr.shape, ws.rt.shape,
            ws.Jrt.shape, ws.JtJ.shape, ws.A.shape, ws.g.shape, ws.gb.shape,
            ws.step.shape, ws.trial.shape, ws.err.shape, ws.blocked.shape, ws.blocked.any())


def test_every_field_holds_what_was_passed():
    target = Target([0.4, 0.2, 0.0])
    ctx = ik_context(ARM, target, stop=(1e-3, 2e-3), tol=(1e-2, 2e-2), distinct=0.25,
                     max_iter=17, clearance=0.0)
    p, R, has_rot, code, numbers, max_iter, collides = _fields(ctx)
    np.testing.assert_array_equal(p, [0.4, 0.2, 0.0])
    np.testing.assert_array_equal(R, np.eye(3))  # a position target: the identity
    assert not has_rot and code == NO_METRIC  # the solver compares rotations itself
    assert numbers[:6] == (1e-3, 2e-3, 1e-2, 2e-2, 0.25, 0.0)
    assert numbers[6] == pytest.approx(1.0 / 0.65, rel=1e-15)  # reach 0.35 + 0.30
    assert max_iter == 17 and not collides


def test_defaults_and_a_pose_target():
    position, rotation = tool((0.3, -0.7))
    ctx = ik_context(ARM, Target(position, rotation), stop=(NO_STOP, NO_STOP))
    p, R, has_rot, _, numbers, max_iter, collides = _fields(ctx)
    np.testing.assert_array_equal(p, position)
    np.testing.assert_array_equal(R, rotation)
    assert has_rot
    assert numbers[:6] == (NO_STOP, NO_STOP, 0.0, 0.0, 0.1, 0.0)
    assert max_iter == LM_ITERATIONS and not collides


def test_solver_target_is_what_the_target_spec_takes():
    R = rz(0.4)
    p, rot, has_rot = solver_target(Target([1, 2, 3], R))
    assert has_rot and p.dtype == rot.dtype == np.float64
    assert p.flags.c_contiguous and rot.flags.c_contiguous and rot.flags.writeable
    np.testing.assert_array_equal(p, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(rot, R)
    p, rot, has_rot = solver_target(Target([1, 2, 3]))
    assert not has_rot
    np.testing.assert_array_equal(rot, np.eye(3))


def test_retarget_points_the_solve_at_another_pose():
    """After retarget the FK re-check accepts the new pose's solution and refuses the
    old one's; the other constants are untouched."""
    q_a, q_b = np.array([0.3, -0.7]), np.array([-1.1, 0.9])
    ctx = ik_context(ARM, Target(*tool(q_a)), stop=(1e-12, 1e-12), tol=(1e-9, 1e-9),
                     distinct=0.2, max_iter=11)
    ws = lm_workspace(2)
    assert recheck(ctx, ws, q_a.copy()) and not recheck(ctx, ws, q_b.copy())
    before = _fields(ctx)
    p_b, R_b = tool(q_b)
    retarget(ctx, R_b, p_b)
    after = _fields(ctx)
    np.testing.assert_array_equal(after[0], p_b)
    np.testing.assert_array_equal(after[1], R_b)
    assert after[2:] == before[2:]
    assert recheck(ctx, ws, q_b.copy()) and not recheck(ctx, ws, q_a.copy())


def test_no_stop_never_converges():
    """From an exact solution a start with a stop converges at once (one evaluation); with
    NO_STOP (the front's scalarisations) it runs on and never reports convergence."""
    q = np.array([0.3, -0.7])
    target = Target(*tool(q))
    for stop, converged in (((1e-9, 1e-9), True), ((NO_STOP, NO_STOP), False)):
        ctx = ik_context(ARM, target, stop=stop)
        ends = np.empty((1, 3))
        _, n_eval, used = run_starts(ctx, q[None].copy(), (0, 10**9), None, None, ends)
        assert bool(ends[0, 0]) is converged and used == 1
        assert (n_eval == 1) is converged


def test_the_collision_check_and_clearance_are_carried():
    model = CollisionModel(robot=ARM, shapes={"link0": Sphere(radius=0.05),
                                              "link2": Sphere(radius=0.05)})
    checker = CollisionChecker(model=model, self_collision=True)
    ctx = ik_context(ARM, Target([0.4, 0.2, 0.0]), stop=(1e-3, 1e-3),
                     collision=checker.compiled, clearance=0.02)
    numbers, collides = _fields(ctx)[4], _fields(ctx)[6]
    assert numbers[5] == 0.02 and collides


@pytest.mark.parametrize("dof", [2, 7])
def test_workspace_shapes(dof):
    shapes = _workspace_shapes(dof)
    assert shapes[:-1] == ((4, 4), (3, 3), (6, dof), (6,), (6, dof), (6,), (6, dof),
                           (dof, dof), (dof, dof), (dof,), (dof,), (dof,), (dof,), (2,),
                           (dof,))
    assert not shapes[-1]  # no joint blocked at the start
