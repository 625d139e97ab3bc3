"""The constants of one solve (:class:`IKContext`), the scratch of LM (:class:`LMWorkspace`).

Pinocchio's Model/Data split: the context is what a solve knows and never changes
(the arm's :class:`~moik.robots.chain_model.ChainModel`, the target's
:class:`~moik.kinematics.target_spec.TargetSpec`, the stopping and acceptance
tolerances, the distinct-solution threshold, the collision check), built in exactly
one place, :func:`ik_context`; the workspace is the scratch the Levenberg-Marquardt
kernels (:mod:`moik.solver.lm`) write into. Every solver kernel takes ``(ctx, ws, ...)``
instead of a dozen positional arrays. Both are numba StructRefs (typed by one attribute,
cached on disk; see :mod:`moik.robots.chain_model`); the workspace never crosses into
Python: :func:`lm_workspace` builds it inside the compiled start loop.

Collision terms: the context carries the solve's
:class:`~moik.collision.compiled.CollisionSet` and clearance; the start loop tests an
accepted end against them (:func:`moik.solver.starts.run_starts`). A context is not
picklable or copyable (numba StructRef): objects that pymoo deep-copies build theirs per
call, as :class:`~moik.solver.pareto_search.Projector` does.
"""

from __future__ import annotations

import numpy as np
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit, kernel_array
from moik.collision.compiled import CollisionSet
from moik.kinematics.target_spec import NO_METRIC, TargetSpec
from moik.problems.targets import Target
from moik.robots.chain import Robot
from moik.robots.chain_model import ChainModel

NO_STOP = -1.0  # a stopping tolerance that never converges (the front's scalarisations)
LM_ITERATIONS = 30  # Levenberg-Marquardt iterations per start (first stage, projections)


@structref.register
class IKContextType(StructType):
    """numba type of :class:`IKContext` (literal field types widened)."""


class IKContext(structref.StructRefProxy):
    """The constants of one solve (numba StructRef; build it with :func:`ik_context`).

    Fields (read in compiled code; reading one from Python compiles a getter, so
    Python code keeps its own copies):
        chain: The arm (:class:`~moik.robots.chain_model.ChainModel`).
        target: The target (:class:`~moik.kinematics.target_spec.TargetSpec`; the solver
            compares rotations by its own residual and the geodesic angle).
        stop_position, stop_orientation: A start has converged when its errors (robot
            unit, rad) are at most these (:data:`NO_STOP`: never).
        tol_position, tol_orientation: A re-checked end is a solution when its errors
            are at most these.
        distinct: Joint-space distance (revolute joints modulo 2 pi) above which two
            solutions are distinct.
        max_iter: Levenberg-Marquardt iterations per start.
        collision: The collision check of an accepted end
            (:class:`~moik.collision.compiled.CollisionSet`, or ``None``: none; a
            context of each kind is its own numba type).
        clearance: Smallest signed distance an accepted end keeps (robot unit).
    """


FIELDS = ("chain", "target", "stop_position", "stop_orientation", "tol_position",
          "tol_orientation", "distinct", "max_iter", "collision", "clearance")
define_struct(IKContext, IKContextType, FIELDS)


@jit
def _new_context(chain, target, stops, accept, collision, sizes):
    """The compiled constructor (cached; the proxy's own would compile in every process).
    ``target = (position, rotation, has_rotation, angles)`` becomes the context's
    :class:`~moik.kinematics.target_spec.TargetSpec` here, in the same call (the solver
    compares rotations by its own residual: no metric; ``angles`` comes allocated: an
    ``np.zeros`` here would compile numba's own before every cold first solve).
    ``collision`` is an argument of its own: numba types a StructRef inside a tuple
    argument in Python, one on its own in C."""
    spec = TargetSpec(target[0], target[1], target[2], NO_METRIC, target[3])
    return IKContext(chain, spec, stops[0], stops[1], accept[0], accept[1], sizes[0],
                     sizes[1], collision, accept[2])


def solver_target(target: Target) -> tuple[np.ndarray, np.ndarray, bool]:
    """``(position, rotation, has_rotation)`` of a target as the context's
    :class:`~moik.kinematics.target_spec.TargetSpec` takes them (the identity rotation for
    a position target)."""
    has_rot = target.rotation is not None
    return (kernel_array(target.position),
            kernel_array(target.rotation if has_rot else np.eye(3)), has_rot)


def ik_context(robot: Robot, target: Target, *, stop: tuple[float, float],
               tol: tuple[float, float] = (0.0, 0.0), distinct: float = 0.1,
               max_iter: int = LM_ITERATIONS, collision: CollisionSet | None = None,
               clearance: float = 0.0, chain: ChainModel | None = None) -> IKContext:
    """The :class:`IKContext` of ``robot`` and ``target`` (the one place it is built).

    Args:
        robot, target: The problem.
        stop: ``(position, orientation)`` at which a start has converged (robot unit,
            rad; :data:`NO_STOP` for never); a :class:`~moik.kinematics.tolerance.Tolerance`'s
            :attr:`~moik.kinematics.tolerance.Tolerance.stop`.
        tol: ``(position, orientation)`` within which a re-checked end is a solution (a
            :class:`~moik.kinematics.tolerance.Tolerance`).
        distinct: Joint-space distance above which two solutions are distinct.
        max_iter: Levenberg-Marquardt iterations per start.
        collision, clearance: An end is accepted only if its smallest distance over the
            pairs of ``collision`` (a checker's
            :attr:`~moik.collision.CollisionChecker.compiled`) is at least ``clearance``;
            ``None``: no check.
        chain: The arm's compiled record (default ``robot.chain_model``; a thread passes
            one of its own, :meth:`~moik.robots.chain.Robot.new_chain_model`).
    """
    return _new_context(robot.chain_model if chain is None else chain,
                        (*solver_target(target), np.zeros(3)),
                        (float(stop[0]), float(stop[1])),
                        (float(tol[0]), float(tol[1]), float(clearance)),
                        collision,
                        (float(distinct), int(max_iter)))


@jit
def retarget(ctx, rotation, position):
    """Point ``ctx`` at another target of the same kind (a batch: one context, many targets)."""
    ctx.target.rotation = rotation
    ctx.target.position = position


@structref.register
class LMWorkspaceType(StructType):
    """numba type of :class:`LMWorkspace`."""


class LMWorkspace(structref.StructRefProxy):
    """Scratch of the Levenberg-Marquardt kernels for one chain (numba StructRef; built by
    :func:`lm_workspace`).

    ``T``: the pose; ``M``: ``R R_t^T``; ``J``: the geometric Jacobian; ``r``, ``Jr``: the
    residual and its Jacobian at the iterate, ``rt``, ``Jrt`` at the trial point;
    ``JtJ``, ``A``, ``g``, ``gb``, ``step``, ``blocked``: the damped normal equations;
    ``trial``: the trial point; ``err``: a re-check's (position, orientation) errors.
    """


WORKSPACE_FIELDS = ("T", "M", "J", "r", "Jr", "rt", "Jrt", "JtJ", "A", "g", "gb", "step",
                    "blocked", "trial", "err")
define_struct(LMWorkspace, LMWorkspaceType, WORKSPACE_FIELDS)


@jit
def lm_workspace(dof):
    """A fresh :class:`LMWorkspace` for a chain of ``dof`` joints."""
    return LMWorkspace(np.empty((4, 4)), np.empty((3, 3)), np.empty((6, dof)), np.empty(6),
                       np.empty((6, dof)), np.empty(6), np.empty((6, dof)),
                       np.empty((dof, dof)), np.empty((dof, dof)), np.empty(dof),
                       np.empty(dof), np.empty(dof), np.zeros(dof, dtype=np.bool_),
                       np.empty(dof), np.empty(2))
