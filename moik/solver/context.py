"""The constants of one solve (:class:`IKContext`), the scratch of LM (:class:`LMWorkspace`).

Pinocchio's Model/Data split: the context is what a solve knows and never changes
(the chain, its joint types and limits, the target, ``1 / reach``, the stopping and
acceptance tolerances, the distinct-solution threshold), built in exactly one place,
:func:`ik_context`, from a :class:`~moik.robots.chain.Robot` and a
:class:`~moik.problems.targets.Target`; the workspace is the scratch the
Levenberg-Marquardt kernels (:mod:`moik.solver.lm`) write into. Every solver kernel
takes ``(ctx, ws, ...)`` instead of a dozen positional arrays, so a swapped
``stop_position`` / ``stop_orientation`` cannot compile silently.

Why these numba types (measured on this machine, one call from Python, median):
a ``NamedTuple`` passed from Python costs 7-16 us of numba's ``typeof`` per call (its
fields are typed one by one in Python), against 4-5 us for the 20 positional arrays it
replaces, and a jitclass cannot be cached on disk. A numba ``StructRef`` is typed by
one attribute (dispatch as cheap as the positional call), is cacheable, and is built by
a cached compiled constructor (about 2 us); so the context is a StructRef. The
workspace never crosses into Python: :func:`lm_workspace` builds it inside the compiled
start loop, once per call instead of once per start. It is a StructRef too, not a
NamedTuple of its 15 arrays: every kernel that takes a tuple unpacks, increfs and
decrefs all 15 at each call, code numba types, lowers and LLVM optimises again in each
of them (measured: a cold first solve compiles in about a tenth less CPU with the
StructRef; the solve times are the same).

Collision terms: the context carries the solve's
:class:`~moik.collision.compiled.CollisionSet` and clearance; the start loop tests an
accepted end against them (:func:`moik.solver.starts.run_starts`). Hinge residual rows on
distance would go in :func:`moik.solver.lm.residual` (after the 6 pose rows, with ``r``
and ``Jr`` sized for them in the workspace). A context is not picklable or copyable (numba
StructRef): objects that pymoo deep-copies build theirs per call, as
:class:`~moik.solver.pareto_search.Projector` does.
"""

from __future__ import annotations

import numpy as np
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit, kernel_array
from moik.collision.compiled import CollisionSet
from moik.problems.targets import Target
from moik.robots.chain import Robot

NO_STOP = -1.0  # a stopping tolerance that never converges (the front's scalarisations)


@structref.register
class IKContextType(StructType):
    """numba type of :class:`IKContext` (literal field types widened)."""


class IKContext(structref.StructRefProxy):
    """The constants of one solve (numba StructRef; build it with :func:`ik_context`).

    Fields (read in compiled code; reading one from Python compiles a getter, so
    Python code keeps its own copies):
        origins, joint_types: The chain (``KinematicChain.origins``, ``.joint_types``).
        lower, upper: Joint limits.
        rotation, position: The target (identity rotation for a position target).
        has_rotation: Whether the target has a rotation.
        inv_reach: ``1 / robot.reach`` (the residual's position scale ``1 / L``).
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


FIELDS = ("origins", "joint_types", "lower", "upper", "rotation", "position", "has_rotation",
          "inv_reach", "stop_position", "stop_orientation", "tol_position", "tol_orientation",
          "distinct", "max_iter", "collision", "clearance")
define_struct(IKContext, IKContextType, FIELDS)


@jit
def _new_context(chain, target, stops, accept, collision, sizes):
    """The compiled constructor (cached; the proxy's own would compile in every process).
    ``collision`` is an argument of its own: numba types a StructRef inside a tuple
    argument in Python (about 50 us a call, measured), one on its own in C (about 2 us)."""
    return IKContext(chain[0], chain[1], chain[2], chain[3], target[0], target[1], target[2],
                     stops[0], stops[1], stops[2], accept[0], accept[1], sizes[0], sizes[1],
                     collision, accept[2])


def target_arrays(target: Target) -> tuple[np.ndarray, np.ndarray, bool]:
    """``(rotation, position, has_rotation)`` of a target as kernel arrays (the one
    conversion; the identity rotation for a position target)."""
    has_rot = target.rotation is not None
    return (kernel_array(target.rotation if has_rot else np.eye(3)),
            kernel_array(target.position), has_rot)


def ik_context(robot: Robot, target: Target, *, stop: tuple[float, float],
               tol: tuple[float, float] = (0.0, 0.0), distinct: float = 0.1,
               max_iter: int = 30, collision: CollisionSet | None = None,
               clearance: float = 0.0) -> IKContext:
    """The :class:`IKContext` of ``robot`` and ``target`` (the one place it is built).

    Args:
        robot, target: The problem.
        stop: ``(position, orientation)`` at which a start has converged (robot unit,
            rad; :data:`NO_STOP` for never).
        tol: ``(position, orientation)`` within which a re-checked end is a solution.
        distinct: Joint-space distance above which two solutions are distinct.
        max_iter: Levenberg-Marquardt iterations per start.
        collision, clearance: An end is accepted only if its smallest distance over the
            pairs of ``collision`` (a checker's
            :attr:`~moik.collision.CollisionChecker.compiled`) is at least ``clearance``;
            ``None``: no check.
    """
    chain = robot.kinematic_chain
    return _new_context((chain.origins, chain.joint_types, robot.lower, robot.upper),
                        target_arrays(target),
                        (1.0 / robot.reach, float(stop[0]), float(stop[1])),
                        (float(tol[0]), float(tol[1]), float(clearance)),
                        collision,
                        (float(distinct), int(max_iter)))


@jit
def retarget(ctx, rotation, position):
    """Point ``ctx`` at another target of the same kind (a batch: one context, many targets)."""
    ctx.rotation = rotation
    ctx.position = position


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
