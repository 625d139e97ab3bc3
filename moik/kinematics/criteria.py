"""Secondary criteria of an IK solution, batched over joint vectors and compiled.

An exact IK solution of a redundant arm is one point of a continuum (a 7-DOF arm
at a full pose: a one-dimensional self-motion manifold per branch); a 6-DOF arm
has up to 16 isolated branches. Which solution to use is decided by criteria
such as these, each a function ``Q (n, dof) -> (n,)`` in its natural sign:

- ``joint_motion`` (minimised): ``||q' - q_current||`` where ``q'`` is ``q`` with
  each revolute joint shifted by the multiple of 2 pi, within the joint limits,
  nearest to ``q_current`` (the same arm configuration; the motion the arm makes
  to reach it). Prismatic joints are taken as they are.
- ``manipulability`` (maximised): Yoshikawa's measure ``sqrt(det(J J^T))`` of the
  task Jacobian (Yoshikawa 1985, Int. J. Robot. Res. 4(2), 3-9,
  DOI 10.1177/027836498500400201): the 6 rows of the geometric Jacobian for a
  pose target, its 3 translational rows for a position target. With fewer
  joints than task rows it is ``sqrt(det(J^T J))`` (both are the product of the
  singular values of ``J``). Translational rows are in the robot's length unit,
  so the value depends on it (as in every library).
- ``limit_margin`` (maximised): the smallest normalised distance to a joint limit,
  ``min_j min(q_j - lower_j, upper_j - q_j) / (upper_j - lower_j)``, in ``[0, 0.5]``
  (joints whose range is empty are skipped; with none left it is 0.5).
- ``orientation`` (minimised): the geodesic angle (rad) between the end-effector
  rotation and a given rotation: for position-only targets, a preferred
  orientation traded against the other criteria.

:class:`Criterion` wraps one (built-in or a user's callable ``f(Q) -> (n,)``) with
its name and sense; calling it validates what the function returned.
:func:`build_criterion` makes the built-ins from their names (:data:`CRITERIA`).
The compiled kernels behind them are in :mod:`moik.kinematics.criteria_kernels`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from moik._jit import kernel_array
from moik._validate import choice
from moik.exceptions import NonFiniteError, ParameterError, ShapeError
from moik.kinematics.criteria_kernels import (
    distances_into,
    joint_motions,
    limit_margins,
    manipulabilities,
    nearest_copies_into,
)
from moik.kinematics.orientation import check_rotation
from moik.kinematics.rotation_metrics import GEODESIC, rotation_errors
from moik.robots.chain import Robot

MINIMIZE, MAXIMIZE = "min", "max"
SENSES = (MINIMIZE, MAXIMIZE)


@dataclass(frozen=True, eq=False)
class Criterion:
    """A criterion on a batch of joint vectors, with its name and sense.

    Args:
        name: What it is called in results and plots.
        function: ``f(Q) -> (n,)`` on a batch ``Q (n, dof)``, in its natural sign.
        sense: ``"min"`` (smaller is better) or ``"max"`` (larger is better).

    Raises:
        ParameterError: A name that is not a non-empty string, or a function that
            is not callable.
        UnknownNameError: A sense other than ``"min"`` / ``"max"``.
    """

    name: str
    function: Callable[[np.ndarray], np.ndarray]
    sense: str = MINIMIZE

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise ParameterError(f"a criterion name must be a non-empty string, got "
                                 f"{self.name!r}")
        if not callable(self.function):
            raise ParameterError(f"criterion {self.name!r}: function must be callable, got "
                                 f"{type(self.function).__name__}")
        object.__setattr__(self, "sense", choice("criterion sense", self.sense, SENSES))

    @property
    def sign(self) -> float:
        """``+1`` for a minimised criterion, ``-1`` for a maximised one (the minimisation form)."""
        return 1.0 if self.sense == MINIMIZE else -1.0

    def __call__(self, Q: np.ndarray) -> np.ndarray:
        """The values ``(n,)`` on ``Q (n, dof)``, in the natural sign (the function gets a
        read-only view of ``Q``).

        Raises:
            ShapeError: The function returned something else than ``n`` numbers.
            NonFiniteError: It returned NaN or infinite values.
        """
        view = np.asarray(Q).view()
        view.flags.writeable = False
        values = self.function(view)
        try:
            out = np.asarray(values, dtype=np.float64)
        except (TypeError, ValueError):
            raise ShapeError(f"criterion {self.name!r} must return {len(Q)} real numbers, "
                             f"got {type(values).__name__}") from None
        if out.shape != (len(Q),):
            raise ShapeError(f"criterion {self.name!r} must return shape ({len(Q)},) for "
                             f"{len(Q)} joint vectors, got {out.shape}")
        if not np.all(np.isfinite(out)):
            bad = int(np.flatnonzero(~np.isfinite(out))[0])
            raise NonFiniteError(f"criterion {self.name!r} returned a non-finite value "
                                 f"({out[bad]}) for joint vector {bad}")
        return out


def joint_distance(robot: Robot, q: np.ndarray, others: np.ndarray) -> np.ndarray:
    """Joint-space distances from ``q`` to each row of ``others``, revolute differences
    wrapped to ``[-pi, pi)`` (angles 2 pi apart are the same arm configuration, though not
    the same motion), prismatic ones as they are (:func:`wrapped_distance`)."""
    others = kernel_array(np.atleast_2d(others))
    if np.shape(q) != (robot.dof,) or others.shape[1] != robot.dof:
        raise ShapeError(f"joint_distance needs joint vectors of {robot.dof} values, got "
                         f"{np.shape(q)} and rows of {others.shape[1]}")
    out = np.empty(len(others))
    distances_into(others, kernel_array(q), robot.kinematic_chain.joint_types, out)
    return out


def nearest_copies(robot: Robot, Q: np.ndarray, q_ref: np.ndarray) -> np.ndarray:
    """Each row of ``Q`` with its revolute joints shifted by multiples of 2 pi towards ``q_ref``.

    ``q_j + 2 pi k`` is the same arm configuration; of the copies within the joint
    limits, the one nearest to ``q_ref_j`` is taken (``q_j`` itself if no other copy
    fits). Prismatic joints are left as they are. ``q_ref`` is one joint vector or
    one per row.
    """
    Q = kernel_array(np.atleast_2d(Q))
    out = np.empty_like(Q)
    nearest_copies_into(Q, kernel_array(np.broadcast_to(q_ref, Q.shape)), robot.lower,
                        robot.upper, robot.kinematic_chain.joint_types, out)
    return out


def joint_motion(robot: Robot, q_current: np.ndarray) -> Criterion:
    """``joint_motion`` from ``q_current`` (see the module docstring)."""
    q_ref = kernel_array(q_current)
    chain = robot.kinematic_chain

    def values(Q: np.ndarray) -> np.ndarray:
        Q = robot.kernel_batch(Q)
        out = np.empty(len(Q))
        joint_motions(Q, q_ref, robot.lower, robot.upper, chain.joint_types, out)
        return out

    return Criterion("joint_motion", values, MINIMIZE)


def manipulability(robot: Robot, *, translation_only: bool = False) -> Criterion:
    """Yoshikawa's manipulability of the 6 (pose) or 3 translational rows of the Jacobian."""
    chain = robot.kinematic_chain
    rows = 3 if translation_only else 6

    def values(Q: np.ndarray) -> np.ndarray:
        Q = robot.kernel_batch(Q)
        out = np.empty(len(Q))
        manipulabilities(chain.origins, chain.joint_types, Q, rows, out)
        return out

    return Criterion("manipulability", values, MAXIMIZE)


def limit_margin(robot: Robot) -> Criterion:
    """The smallest normalised distance to a joint limit."""

    def values(Q: np.ndarray) -> np.ndarray:
        Q = robot.kernel_batch(Q)
        out = np.empty(len(Q))
        limit_margins(Q, robot.lower, robot.upper, out)
        return out

    return Criterion("limit_margin", values, MAXIMIZE)


def orientation(robot: Robot, rotation) -> Criterion:
    """Geodesic angle between the end-effector rotation and ``rotation`` (3, 3)."""
    R_ref = kernel_array(check_rotation(rotation, "preferred rotation"))
    no_angles = np.zeros(3)

    def values(Q: np.ndarray) -> np.ndarray:
        R, _ = robot.fk_parts(Q)
        out = np.empty(len(R))
        rotation_errors(GEODESIC, R, R_ref, no_angles, out)
        return out

    return Criterion("orientation", values, MINIMIZE)


CRITERIA: dict[str, str] = {"joint_motion": MINIMIZE, "manipulability": MAXIMIZE,
                            "limit_margin": MAXIMIZE, "orientation": MINIMIZE}
"""The built-in criteria: name -> sense (``"min"`` or ``"max"``)."""


def build_criterion(name: str, robot: Robot, *, q_current=None, rotation=None,
                    translation_only: bool = False) -> Criterion:
    """The built-in criterion ``name`` (:data:`CRITERIA`) for ``robot``.

    Args:
        name: ``"joint_motion"``, ``"manipulability"``, ``"limit_margin"`` or
            ``"orientation"`` (case-insensitive).
        robot: The arm.
        q_current: The configuration ``joint_motion`` measures from ``(dof,)``.
        rotation: The rotation ``orientation`` measures against ``(3, 3)``.
        translation_only: ``manipulability`` of the translational rows only (a
            position target).

    Raises:
        UnknownNameError: An unknown name (the message lists the built-ins).
        ParameterError: ``joint_motion`` without ``q_current`` or ``orientation``
            without ``rotation``.
    """
    key = choice("criterion", name, CRITERIA)
    if key == "joint_motion":
        if q_current is None:
            raise ParameterError("criterion 'joint_motion' needs q_current (the configuration "
                                 "the motion starts from), got None")
        return joint_motion(robot, q_current)
    if key == "manipulability":
        return manipulability(robot, translation_only=translation_only)
    if key == "limit_margin":
        return limit_margin(robot)
    if rotation is None:
        raise ParameterError("criterion 'orientation' needs a rotation (the preferred "
                             "end-effector orientation), got None")
    return orientation(robot, rotation)


def build_criteria(objectives, robot: Robot, *, q_current=None, rotation=None,
                   position_only: bool = False) -> tuple[Criterion, ...]:
    """The criteria named or given in ``objectives``, in order.

    Args:
        objectives: A sequence (or one) of built-in names (:data:`CRITERIA`),
            :class:`Criterion` objects and callables ``f(Q) -> (n,)`` (minimised).
        robot: The arm.
        q_current: For ``joint_motion``.
        rotation: For ``orientation``.
        position_only: The target is a position: ``manipulability`` uses the
            translational rows, and ``orientation`` is allowed (a pose fixes the
            orientation of every exact solution, so it is refused there).

    Raises:
        ParameterError: No criterion, one given twice, an entry that is neither a
            name nor a callable, ``orientation`` with a pose target, or a built-in
            missing what it measures from.
        UnknownNameError: An unknown built-in name.
    """
    items = (objectives,) if isinstance(objectives, str) or callable(objectives) else objectives
    try:
        items = tuple(items)
    except TypeError:
        raise ParameterError(f"objectives must be criterion names or callables, got "
                             f"{objectives!r}") from None
    if not items:
        raise ParameterError("objectives must name at least one criterion, got none")
    out: list[Criterion] = []
    for k, item in enumerate(items):
        if isinstance(item, Criterion):
            out.append(item)
        elif isinstance(item, str):
            if item.lower() == "clearance":  # a solve's (moik.solver.collision.with_clearance)
                raise ParameterError("criterion 'clearance' needs geometry to measure: a solve "
                                     "with scene= and/or self_collision=True")
            if choice("criterion", item, [*CRITERIA, "clearance"]) == "orientation" \
                    and not position_only:
                raise ParameterError("criterion 'orientation' is for position-only targets; "
                                     "a pose target fixes the orientation of every solution")
            out.append(build_criterion(item, robot, q_current=q_current, rotation=rotation,
                                       translation_only=position_only))
        elif callable(item):
            name = getattr(item, "__name__", "")
            out.append(Criterion(name if name.isidentifier() else f"criterion_{k + 1}", item))
        else:
            raise ParameterError(f"objectives[{k}] must be a criterion name, a Criterion or a "
                                 f"callable f(Q) -> (n,), got {item!r}")
    names = [c.name for c in out]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ParameterError(f"each criterion may appear once; given more than once: "
                             f"{', '.join(twice)}")
    return tuple(out)
