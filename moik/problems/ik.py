"""Inverse kinematics as vectorized pymoo Problems.

Decision variables are the joint values (bounds = the robot's joint limits);
``_evaluate`` runs batched FK on the whole population at once.

* :class:`PositionIK`: one objective, the position error (EOSMA Eq. 29; also
  the I-BES and MChOA Eq. 3 objective).
* :class:`PoseIK`: one objective, ``w1 * position + w2 * orientation`` (EOSMA
  Eq. 28 with the Eq. 26/30 Euler error by default; MChOA Eq. 6 with
  ``orientation="frobenius"``).
* :class:`BiObjectiveIK`: two objectives (position error, orientation error),
  the MOEOSMA / MO-m-PSO formulation (MO-m-PSO Eq. 15).

Each takes ``displacement_weight`` and ``q_start`` for EOSMA Eq. 31: the term
``w * ||q - q_start||`` is added to every objective, preferring solutions that
move the arm least.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.problem import Problem

from moik.exceptions import NonFiniteError, ParameterError, TargetError
from moik.kinematics.orientation import orientation_metric
from moik.problems.targets import Target, as_target, check_unit_range
from moik.robots.chain import Robot


class _IKProblem(Problem):
    """Shared set-up: robot, target, bounds, displacement term."""

    n_obj_ik = 1

    def __init__(self, robot: Robot, target, *, displacement_weight: float = 0.0,
                 q_start=None, needs_orientation: bool = False):
        if not isinstance(robot, Robot):
            raise ParameterError(f"robot must be a moik Robot, got {type(robot).__name__}")
        self.robot = robot
        self.target: Target = as_target(target)
        check_unit_range(self.target, robot)
        if needs_orientation and not self.target.has_orientation:
            raise TargetError(
                f"{type(self).__name__} needs a target with an orientation (a 4x4 pose or "
                "(position, rotation)); got a position only"
            )
        if not (np.isfinite(displacement_weight) and displacement_weight >= 0):
            raise ParameterError(
                f"displacement_weight must be finite and >= 0, got {displacement_weight}"
            )
        self.displacement_weight = float(displacement_weight)
        self.q_start = None
        if q_start is not None:
            self.q_start = robot.check_q(q_start, "q_start")
            if self.q_start.ndim != 1:
                raise ParameterError(f"q_start must be one joint vector, got {self.q_start.shape}")
        elif self.displacement_weight > 0:
            raise ParameterError("displacement_weight > 0 needs q_start (Eq. 31)")
        super().__init__(n_var=robot.dof, n_obj=self.n_obj_ik, xl=robot.lower.copy(),
                         xu=robot.upper.copy(), vtype=float)

    def _check_X(self, X: np.ndarray) -> None:
        if not np.isfinite(X).all():
            raise NonFiniteError(f"{type(self).__name__}: joint values contain NaN or inf")

    def _displacement(self, X: np.ndarray) -> np.ndarray | float:
        """EOSMA Eq. 31 penalty ``w * ||q - q_start||`` (0 when disabled)."""
        if self.displacement_weight == 0.0:
            return 0.0
        return self.displacement_weight * np.linalg.norm(X - self.q_start, axis=1)

    def position_error(self, X: np.ndarray) -> np.ndarray:
        """Euclidean position error (Eq. 29), shape ``(n,)``."""
        diff = self.robot.fk_position(np.atleast_2d(X)) - self.target.position
        return np.sqrt(np.einsum("ij,ij->i", diff, diff))


class PositionIK(_IKProblem):
    """Position-only IK: ``f = ||p(q) - p_target||`` (EOSMA Eq. 29).

    Args:
        robot: The arm (bounds are its joint limits).
        target: 3-vector position (or any target; its orientation is ignored).
        displacement_weight: Weight ``w`` of EOSMA Eq. 31 (0 = off).
        q_start: Current joint vector for Eq. 31.
    """

    def __init__(self, robot: Robot, target, *, displacement_weight: float = 0.0, q_start=None):
        super().__init__(robot, target, displacement_weight=displacement_weight,
                         q_start=q_start)

    def _evaluate(self, X, out, *args, **kwargs):
        self._check_X(X)
        out["F"] = (self.position_error(X) + self._displacement(X))[:, None]


class _OrientedIK(_IKProblem):
    def __init__(self, robot, target, *, orientation: str, displacement_weight, q_start):
        self.orientation = orientation
        target_repr, self._orientation_error = orientation_metric(orientation)
        super().__init__(robot, target, displacement_weight=displacement_weight,
                         q_start=q_start, needs_orientation=True)
        self._target_repr = target_repr(self.target.rotation)

    def errors(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position and orientation errors of a batch, each ``(n,)``."""
        R, p = self.robot.fk_parts(np.atleast_2d(X))
        diff = p - self.target.position
        pos = np.sqrt(np.einsum("ij,ij->i", diff, diff))
        return pos, self._orientation_error(R, self._target_repr)


class PoseIK(_OrientedIK):
    """Weighted pose IK: ``f = w1 * f1 + w2 * f2`` (EOSMA Eq. 28).

    Args:
        robot: The arm.
        target: Pose (4x4), ``(position, rotation)`` or :class:`Target` with rotation.
        weights: ``(w1, w2)``, non-negative, not both zero (paper: 0.5, 0.5).
        orientation: Orientation metric name (``"eosma-euler"`` reproduces the paper).
        displacement_weight: Weight of EOSMA Eq. 31 (0 = off).
        q_start: Current joint vector for Eq. 31.
    """

    def __init__(self, robot: Robot, target, *, weights=(0.5, 0.5),
                 orientation: str = "eosma-euler", displacement_weight: float = 0.0,
                 q_start=None):
        w = np.asarray(weights, dtype=float)
        if w.shape != (2,) or not np.all(np.isfinite(w)) or np.any(w < 0) or w.sum() == 0:
            raise ParameterError(
                f"weights must be two finite non-negative numbers, not both zero; got {weights}"
            )
        self.weights = w
        super().__init__(robot, target, orientation=orientation,
                         displacement_weight=displacement_weight, q_start=q_start)

    def _evaluate(self, X, out, *args, **kwargs):
        self._check_X(X)
        pos, ori = self.errors(X)
        out["F"] = (self.weights[0] * pos + self.weights[1] * ori
                    + self._displacement(X))[:, None]


class BiObjectiveIK(_OrientedIK):
    """Two objectives: position error and orientation error (MO-m-PSO Eq. 15).

    Args:
        robot: The arm.
        target: Pose with an orientation.
        orientation: Orientation metric (``"eosma-euler"`` for MOEOSMA,
            ``"zyx-euler"`` for MO-m-PSO, ``"geodesic"`` for users).
        displacement_weight: Weight of EOSMA Eq. 31, added to both objectives.
        q_start: Current joint vector for Eq. 31.
    """

    n_obj_ik = 2

    def __init__(self, robot: Robot, target, *, orientation: str = "geodesic",
                 displacement_weight: float = 0.0, q_start=None):
        super().__init__(robot, target, orientation=orientation,
                         displacement_weight=displacement_weight, q_start=q_start)

    def _evaluate(self, X, out, *args, **kwargs):
        self._check_X(X)
        pos, ori = self.errors(X)
        disp = self._displacement(X)
        out["F"] = np.column_stack([pos + disp, ori + disp])
