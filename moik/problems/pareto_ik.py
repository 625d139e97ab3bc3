"""Exact IK over secondary criteria as a constrained pymoo Problem.

:class:`ParetoIK` has the joint values as variables (bounds: the joint limits),
the criteria of :mod:`moik.kinematics.criteria` as objectives in minimisation form
(a maximised criterion such as ``manipulability`` is negated) and the pose error
as inequality constraints ``G <= 0``:

- ``G_0 = (position_error - tol_position) / reach``,
- ``G_1 = orientation_error - tol_orientation`` (geodesic angle, rad; pose targets only).

Any pymoo algorithm runs on it (``minimize(ParetoIK(...), NSGA2(), ...)``) and its
feasible front compares with :func:`moik.solve_ik_pareto`'s by hypervolume
(:meth:`ParetoIK.minimization_form` gives the solver's ``F`` in this form).
Evaluation is vectorised: one compiled FK pass for the errors, one call per criterion.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.problem import Problem

from moik.exceptions import ParameterError
from moik.kinematics.criteria import Criterion, build_criteria
from moik.kinematics.orientation import check_rotation
from moik.kinematics.tolerance import Tolerance
from moik.problems.ik import BiObjectiveIK, PositionIK
from moik.problems.targets import Target, as_target, check_unit_range
from moik.robots.chain import Robot


class ParetoIK(Problem):
    """Criteria of exact IK solutions as objectives, the pose error as constraints.

    Args:
        robot: The arm.
        target: Position, 4x4 pose, ``(position, rotation)`` or :class:`Target`.
        objectives: Criterion names, :class:`~moik.kinematics.criteria.Criterion`
            objects or callables ``f(Q) -> (n,)`` (see
            :func:`~moik.kinematics.criteria.build_criteria`).
        q_current: The configuration ``joint_motion`` measures from.
        rotation: The preferred rotation ``orientation`` measures against
            (position targets).
        tol: A number ``t`` (position <= ``t * reach``, orientation <= ``t`` rad)
            or a pair (position in the robot's unit, rad), as ``solve_ik`` takes it
            (:meth:`~moik.kinematics.tolerance.Tolerance.of`: the same values refused).

    Attributes:
        criteria: The :class:`Criterion` objects, in objective order.
        rotation: The preferred rotation (validated) or None.
        tol_position, tol_orientation: The tolerances.

    Raises:
        ParameterError, UnknownNameError: Bad criteria (see ``build_criteria``) or tolerance.
        ShapeError, NonFiniteError, TargetError: A malformed target or ``q_current``.
    """

    def __init__(self, robot: Robot, target, *, objectives=("joint_motion", "manipulability"),
                 q_current=None, rotation=None, tol=1e-9):
        if not isinstance(robot, Robot):
            raise ParameterError(f"robot must be a moik Robot, got {type(robot).__name__}")
        self.robot = robot
        self.target: Target = as_target(target)
        check_unit_range(self.target, robot)
        if q_current is not None:
            q_current = robot.check_q(q_current, "q_current")
            if q_current.ndim != 1:
                raise ParameterError(f"q_current must be one joint vector ({robot.dof},), got "
                                     f"{q_current.shape}")
        self.q_current = q_current
        position_only = self.target.rotation is None
        self.rotation = None if rotation is None else check_rotation(rotation, "rotation")
        self.criteria: tuple[Criterion, ...] = build_criteria(
            objectives, robot, q_current=q_current, rotation=self.rotation,
            position_only=position_only)
        self.tol = Tolerance.of(tol, robot.reach)
        self.tol_position, self.tol_orientation = self.tol
        self._signs = np.array([c.sign for c in self.criteria])
        self._errors = PositionIK(robot, self.target) if position_only else BiObjectiveIK(
            robot, self.target)
        super().__init__(n_var=robot.dof, n_obj=len(self.criteria),
                         n_ieq_constr=1 if position_only else 2, xl=robot.lower.copy(),
                         xu=robot.upper.copy(), vtype=float)

    @property
    def names(self) -> tuple[str, ...]:
        """The criteria's names, in objective order."""
        return tuple(c.name for c in self.criteria)

    @property
    def senses(self) -> tuple[str, ...]:
        """``"min"`` or ``"max"`` per criterion."""
        return tuple(c.sense for c in self.criteria)

    def natural(self, Q: np.ndarray) -> np.ndarray:
        """The criteria ``(n, m)`` of ``Q (n, dof)`` in their natural signs."""
        Q = self.robot.kernel_batch(Q)
        return np.column_stack([c(Q) for c in self.criteria]) if len(Q) else np.empty(
            (0, self.n_obj))

    def minimization_form(self, F_natural: np.ndarray) -> np.ndarray:
        """Natural-sign criteria as this problem's objectives (maximised ones negated)."""
        return np.asarray(F_natural, dtype=float) * self._signs

    def pose_errors(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position (robot unit) and geodesic orientation (rad) errors, each ``(n,)``."""
        if isinstance(self._errors, PositionIK):
            pos = self._errors.position_error(Q)
            return pos, np.zeros_like(pos)
        return self._errors.errors(Q)

    def _evaluate(self, X, out, *args, **kwargs):
        Q = self.robot.kernel_batch(np.atleast_2d(X))
        out["F"] = self.minimization_form(self.natural(Q))
        pos, ori = self.pose_errors(Q)
        G = [(pos - self.tol_position) / self.robot.reach]
        if self.n_ieq_constr == 2:
            G.append(ori - self.tol_orientation)
        out["G"] = np.column_stack(G)
