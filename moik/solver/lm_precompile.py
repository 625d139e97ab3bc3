"""The start loop's leaf kernels, compiled in a second process on a cold first solve.

With an empty kernel cache, a process's first solve compiles the start loop
(:func:`moik.solver.starts.run_starts`) as one tree, one kernel at a time, each kernel's
callees before it: first the FK and residual kernels (:func:`moik.solver.lm.residual`:
:mod:`moik.robots.fk_kernels`, :mod:`moik.kinematics.jacobian`), then the other leaves.
Where a second CPU is free, :func:`precompile` has a child process
(:mod:`moik._background`) compile those other leaves at the same time: the damped step
(:func:`~moik.solver.lm.damped_step`), the limits
(:func:`~moik.solver.lm.into_limits`), the re-check
(:func:`~moik.solver.starts.recheck`), the bookkeeping of found solutions and of the
best candidate, and the batch FK of the final re-check
(:meth:`~moik.robots.chain.Robot.fk_parts`), each called on a context and workspace of
the same numba types as the solve's. This process then loads each from the cache when
it gets to it (it compiles itself whatever the child has not written by then).
``benchmarks/startup.py`` times the cold first solve.

It starts once per process, for a solve without a collision check (a context with a
collision set is another numba type), when the start loop is not cached.
"""

from __future__ import annotations

import numpy as np

from moik import _background
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.solver.context import ik_context, lm_workspace
from moik.solver.lm import LAMBDA0, damped_step, into_limits
from moik.solver.starts import _improve, _keep, recheck, run_starts

_started = False  # a child was started (or found useless) in this process


def precompile(robot: Robot, reachable: bool = True) -> None:
    """Start the child for ``robot``'s first solve in this process, where it can help.
    ``reachable``: False for a target proven out of reach (its solve needs the batch FK of
    the re-check before the start loop's bookkeeping, so the child compiles it first)."""
    global _started
    if _started or getattr(run_starts, "overloads", True):  # compiled or loaded here (or
        return  # not compiled at all: NUMBA_DISABLE_JIT)
    _started = True
    _background.start(__name__, (robot, reachable), probes=[run_starts])


def _child() -> None:
    """The child: each leaf kernel called once, in the order the parent needs them."""
    robot, reachable = _background.child_arguments()
    dof = robot.dof
    ctx = ik_context(robot, Target(np.zeros(3), np.eye(3)), stop=(0.0, 0.0))
    ws = lm_workspace(dof)
    q = np.ascontiguousarray((robot.lower + robot.upper) / 2.0, dtype=np.float64)
    damped_step(ctx, ws, LAMBDA0, q)
    into_limits(0.0, robot.kinematic_chain.joint_types[0], robot.lower[0], robot.upper[0])
    if not reachable:
        robot.fk_parts(q[None])
    recheck(ctx, ws, q)
    _keep(ctx, ws, np.full((1, dof + 2), np.nan), 0, q)
    _improve(ctx, ws, np.full(dof + 1, np.inf), q)
    if reachable:
        robot.fk_parts(q[None])


if __name__ == "__main__":
    _child()
