"""Local IK refinement: bounded least squares with the analytic Jacobian.

The residual of a pose target is ``[(p(q) - p_t) / L, log(R(q) R_t^T)]``:
the position error divided by a characteristic length ``L`` (so that one
robot-length of position error weighs like one radian) and the orientation
error as a rotation vector in the base frame. Its Jacobian is
``[J_v / L; J_l^{-1}(r) J_w]`` with the inverse left Jacobian of SO(3), exact
everywhere (so a non-zero minimum, an unreachable pose, is a true stationary
point of the model and the solver stops there); both come from
:mod:`moik.kinematics.so3`. Position-only targets use the first three rows.
``scipy.optimize.least_squares`` (``dogbox``: on these square-or-wide systems
it converges in ~5-10 evaluations where ``trf`` often runs out of budget) keeps
every iterate within the joint limits.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Any

import numpy as np

from moik.kinematics.jacobian import pose_and_jacobian
from moik.kinematics.so3 import pose_residual, pose_residual_jacobian
from moik.problems.targets import Target
from moik.robots.chain import Robot


def least_squares(*args: Any, **kwargs: Any) -> Any:
    """``scipy.optimize.least_squares``, imported at the first polish: scipy.optimize
    (with scipy.spatial and scipy.linalg) is slow to import, and the first stage solves
    nearly every pose without it (start-up time, not an import cycle)."""
    return importlib.import_module("scipy.optimize").least_squares(*args, **kwargs)


# least_squares statuses meaning "stationary point reached" (not budget).
CONVERGED_STATUS = (1, 2, 3, 4)


@dataclass(frozen=True)
class PolishResult:
    """Outcome of one local refinement.

    Attributes:
        q: Joint vector within the limits.
        cost: Final ``0.5 * ||residual||^2``.
        n_eval: FK evaluations used (residuals + Jacobians).
        stationary: Whether the solver stopped at a stationary point rather
            than on its evaluation budget.
    """

    q: np.ndarray
    cost: float
    n_eval: int
    stationary: bool


class ResidualModel:
    """Residual and Jacobian of a target, sharing one FK pass per point.

    ``least_squares`` asks for the residual and then the Jacobian at the same
    point; both come from one call of :func:`pose_and_jacobian`, cached.
    """

    def __init__(self, robot: Robot, target: Target, length: float):
        self.robot, self.target, self.length = robot, target, length
        self.n_fk = 0
        self._q: np.ndarray | None = None

    def _update(self, q: np.ndarray) -> None:
        if self._q is not None and np.array_equal(q, self._q):
            return
        T, J = pose_and_jacobian(self.robot, q)
        self.n_fk += 1
        self._q = np.array(q, dtype=float)
        r = pose_residual(T[None, :3, 3], T[None, :3, :3], self.target.position,
                          self.target.rotation, self.length)
        self._r, self._J = r[0], pose_residual_jacobian(J[None], r, self.length)[0]

    def residual(self, q: np.ndarray) -> np.ndarray:
        """``[(p - p_t) / L, log(R R_t^T)]`` (position rows only without rotation)."""
        self._update(q)
        return self._r

    def jacobian(self, q: np.ndarray) -> np.ndarray:
        """Exact Jacobian of :meth:`residual`: ``[J_v / L; J_l^{-1}(r) J_w]``."""
        self._update(q)
        return self._J


def _stopper(length: float, stop_position: float, stop_orientation: float):
    """least_squares callback: stop once the residual is well inside tolerance."""
    n_pos = 3

    def callback(intermediate_result) -> None:
        r = intermediate_result.fun
        if (np.linalg.norm(r[:n_pos]) * length <= stop_position
                and np.linalg.norm(r[n_pos:]) <= stop_orientation):
            raise StopIteration

    return callback


def polish(robot: Robot, target: Target, q0: np.ndarray, *, length: float,
           max_nfev: int = 60, stop_position: float = 0.0,
           stop_orientation: float = 0.0) -> PolishResult:
    """Refine ``q0`` towards ``target`` inside the joint limits.

    Args:
        robot: The arm.
        target: Position or pose target.
        q0: Start joint vector (moved just inside the limits if on or beyond them).
        length: Characteristic length ``L`` of the residual (robot unit).
        max_nfev: Residual evaluation budget of ``least_squares``.
        stop_position: Stop as soon as the position error is at most this
            (robot unit) and the orientation error at most ``stop_orientation``
            (rad); 0 runs to ``least_squares``' own convergence tests.
    """
    callback = _stopper(length, stop_position, stop_orientation)
    span = robot.upper - robot.lower
    margin = np.minimum(1e-10 * np.maximum(span, 1.0), 0.25 * span)
    x0 = np.clip(q0, robot.lower + margin, robot.upper - margin)
    free = span > 0  # least_squares needs lower < upper: freeze equal-limit joints
    model = ResidualModel(robot, target, length)

    def full(qf: np.ndarray) -> np.ndarray:
        if free.all():
            return qf
        q = x0.copy()
        q[free] = qf
        return q

    sol = least_squares(
        lambda qf: model.residual(full(qf)), x0[free],
        jac=lambda qf: model.jacobian(full(qf))[:, free],
        bounds=(robot.lower[free], robot.upper[free]), method="dogbox", xtol=1e-12,
        ftol=1e-10, gtol=1e-10, max_nfev=max_nfev, callback=callback)
    return _result(robot, sol, full(sol.x), model.n_fk)


def _result(robot: Robot, sol, q: np.ndarray, n_fk: int) -> PolishResult:
    q = np.clip(q, robot.lower, robot.upper)
    # status -2: stopped by the callback (within tolerance): a stationary success
    stationary = sol.status in CONVERGED_STATUS or sol.status == -2
    return PolishResult(q, float(sol.cost), n_fk, stationary)
