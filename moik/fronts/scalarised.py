"""The scalarised subproblems of a bi-objective IK front, solved by SLSQP.

With ``s1 = f1^2`` (position error squared) and ``s2 = f2^2`` (orientation error
squared) of :mod:`moik.fronts.kernels`, the epsilon-constraint subproblem
(Haimes, Lasdon & Wismer 1971; Miettinen, *Nonlinear Multiobjective Optimization*,
1999, Sec. 3.2) of objective ``k`` at level ``eps`` is::

    minimise s_k(q)  subject to  s_m(q) <= eps^2,  lower <= q <= upper     (m != k)

and its solutions are weakly Pareto optimal (globally solved: Miettinen Thm 3.2.1);
:func:`solve_constrained` finds a local solution from one start with scipy's SLSQP
(Kraft 1988) and reports its KKT residual (:func:`kkt_residual`). ``eps = inf``
drops the constraint (the anchors: the least position error, the least orientation
error).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from moik.fronts.kernels import (
    batch_pose_errors,
    pose_equations_and_jacobian,
    squared_errors_and_gradients,
)
from moik.kinematics.rotation_metrics import ZYX_EULER_FREE_GAMMA, metric_code
from moik.kinematics.target_spec import target_spec
from moik.robots.chain import Robot


def _minimize(*args: Any, **kwargs: Any) -> Any:
    """scipy's ``optimize.minimize``, imported at the first front computed: importing
    :mod:`moik.problems` (and a first-stage solve) need not load scipy.optimize;
    typed ``Any``: scipy-stubs' overloads do not cover SLSQP's dict constraints."""
    from scipy import optimize

    return optimize.minimize(*args, **kwargs)
FD_STEP = 1e-6  # central-difference step of the gradients (rad, or robot unit)
FTOL = 1e-16  # SLSQP stopping tolerance on the scaled squared objective
ZERO_EPS = 1e-8  # a level this small is the constraint f_m = 0 (pose equations)
BOUND_TOL = 1e-10  # a joint this close to a limit counts as on it (KKT residual)


def kernel_array(x) -> np.ndarray:
    """``x`` as a C-contiguous writeable float64 array, what the kernels take (as
    :func:`moik._jit.kernel_array`; not imported, so editing this module does not change
    the kernels' cache key)."""
    return np.array(x, dtype=np.float64, order="C")


class ErrorModel:
    """The compiled errors of one (robot, target position, target rotation, metric).

    Args:
        robot: The arm.
        position: Target position ``(3,)``.
        rotation: Target rotation ``(3, 3)``.
        metric: Orientation metric name (:func:`moik.kinematics.rotation_metrics.metric_code`).

    Attributes:
        scale: ``(S1, S2)``: ``s1`` is divided by ``reach^2``, ``s2`` by 1 rad^2, so the
            subproblems see numbers of order one.
    """

    def __init__(self, robot: Robot, position: np.ndarray, rotation: np.ndarray, metric: str):
        self.robot = robot
        self.code = metric_code(metric)
        self.chain = robot.chain_model
        self.target = target_spec(np.asarray(position, dtype=float),
                                  np.asarray(rotation, dtype=float), metric=metric)
        self.lower, self.upper = robot.lower.astype(float), robot.upper.astype(float)
        self.scale = np.array([robot.reach ** 2, 1.0])
        self._last: tuple[bytes, np.ndarray, np.ndarray] | None = None

    def residual(self, q: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
        """The pose equations of ``f_m = 0`` at ``q`` and their Jacobian ``(3, dof)``.

        ``m = 0``: ``(p(q) - p_t) / reach``; ``m = 1``: for the Euler metrics the angle
        differences (EOSMA Eq. 26 or ZYX; zero on every rotation with the target's angles,
        several rotations for Eq. 26), else the skew part of ``R_t^T R(q)``
        (``sin(angle) * axis``, zero at ``R = R_t``; its other zeros, rotations by pi, have
        ``f_m = pi`` and are told apart by ``f_m``). Central differences, one batched FK call.
        """
        value, jac = np.empty(3), np.empty((3, q.size))
        pose_equations_and_jacobian(self.chain, self.target, kernel_array(q),
                                    (m, np.sqrt(self.scale[0]), FD_STEP), value, jac)
        n = 2 if m == 1 and self.code == ZYX_EULER_FREE_GAMMA else 3
        return value[:n], jac[:n]

    def errors(self, Q: np.ndarray) -> np.ndarray:
        """``(n, 2)``: position and orientation errors of every row of ``Q``."""
        Q = kernel_array(np.atleast_2d(Q))
        out = np.empty((Q.shape[0], 2))
        batch_pose_errors(self.chain, self.target, Q, out)
        return out

    def squared(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Scaled ``(s1, s2)`` and their gradients ``(2, dof)`` at ``q`` (last one cached)."""
        key = q.tobytes()
        if self._last is None or self._last[0] != key:
            value, grad = np.empty(2), np.empty((2, q.size))
            squared_errors_and_gradients(self.chain, self.target, kernel_array(q), FD_STEP,
                                         value, grad)
            self._last = (key, value / self.scale, grad / self.scale[:, None])
        return self._last[1], self._last[2]


@dataclass(frozen=True)
class SubproblemSolution:
    """One local solution of an epsilon-constraint subproblem.

    Attributes:
        q: The joint vector.
        errors: ``(f1, f2)`` at ``q``.
        kkt: The KKT residual (:func:`kkt_residual`, scaled squared objectives).
        success: SLSQP's own convergence flag.
    """

    q: np.ndarray
    errors: np.ndarray
    kkt: float
    success: bool


def kkt_residual(model: ErrorModel, q: np.ndarray, k: int, eps: float) -> float:
    """Projected KKT residual of subproblem ``(k, eps)`` at ``q``.

    ``|| P(grad s_k + lam grad s_m) ||_inf`` with the least-squares multiplier
    ``lam = max(0, -<grad s_k, grad s_m> / |grad s_m|^2)`` (over the joints off their
    limits) when the constraint is active
    (``s_m >= eps^2 (1 - 1e-6)``, else ``lam = 0``), and ``P`` zeroing a component at a
    joint limit whose sign a bound multiplier can absorb. Zero at a KKT point; in units
    of the scaled squared objectives per radian. At a level ``eps <= ZERO_EPS`` the
    constraint ``f_m = 0`` is degenerate (``grad s_m = 0``): the residual is then that of
    the pose manifold ``f_m = 0``: ``grad s_k`` less its projection on the rows of the
    Jacobian of the pose equations (:meth:`ErrorModel.residual`; joints at a limit left
    out).
    """
    value, grad = model.squared(q)
    m = 1 - k
    g = grad[k].copy()
    level = eps * eps / model.scale[m] if np.isfinite(eps) and eps > ZERO_EPS else np.inf
    level = 0.0 if eps <= ZERO_EPS else level
    bound = (q - model.lower <= BOUND_TOL) | (model.upper - q <= BOUND_TOL)
    free = ~bound
    if level == 0.0:
        # f_m = 0: the constraint is the pose manifold (p = p_t or R = R_t), whose normal
        # space is spanned by the Jacobian rows of that error; remove g's part in it
        rows = model.residual(q, m)[1][:, free]
        g[free] = g[free] - rows.T @ np.linalg.lstsq(rows.T, g[free], rcond=None)[0]
    elif np.isfinite(level) and value[m] >= level * (1 - 1e-6):
        gm = grad[m]
        norm = gm[free] @ gm[free]
        if norm > 0:
            g = g + max(0.0, -(g[free] @ gm[free]) / norm) * gm
    at_lower = (q - model.lower <= BOUND_TOL) & (g > 0)
    at_upper = (model.upper - q <= BOUND_TOL) & (g < 0)
    g[at_lower | at_upper] = 0.0
    return float(np.max(np.abs(g)))


def solve_constrained(model: ErrorModel, q0: np.ndarray, k: int, eps: float, *,
                      maxiter: int = 200) -> SubproblemSolution:
    """Minimise ``s_k`` subject to ``s_m <= eps^2`` and the joint limits, from ``q0``.

    At ``eps <= ZERO_EPS`` the constraint is ``f_m = 0`` written as three smooth
    equations (:meth:`ErrorModel.residual`): ``p = p_t`` or ``R = R_t``.

    Args:
        model: The errors.
        q0: The start (clipped into the limits).
        k: 0 minimises the position error, 1 the orientation error.
        eps: The level of the other error (``inf``: unconstrained).
        maxiter: SLSQP's iteration limit.
    """
    m = 1 - k
    x0 = np.clip(np.asarray(q0, dtype=float), model.lower, model.upper)
    constraints: list[dict] = []
    if eps <= ZERO_EPS:  # f_m = 0 as three smooth equations (LICQ holds, unlike s_m <= 0)
        r0, j0 = model.residual(x0, m)  # an equation that is identically 0 (a planar arm's
        rows = (np.abs(r0) > 1e-14) | (np.abs(j0).max(axis=1) > 1e-12)  # x, y) is left out
        constraints = [{"type": "eq", "fun": lambda x: model.residual(x, m)[0][rows],
                        "jac": lambda x: model.residual(x, m)[1][rows]}]
        eps = 0.0
    elif np.isfinite(eps):
        level = eps * eps / model.scale[m]
        constraints = [{"type": "ineq", "fun": lambda x: level - model.squared(x)[0][m],
                        "jac": lambda x: -model.squared(x)[1][m]}]
    res = _minimize(lambda x: model.squared(x)[0][k], x0, jac=lambda x: model.squared(x)[1][k],
                   method="SLSQP", bounds=list(zip(model.lower, model.upper, strict=True)),
                   constraints=constraints, options={"ftol": FTOL, "maxiter": maxiter})
    q = np.clip(res.x, model.lower, model.upper)
    return SubproblemSolution(q=q, errors=model.errors(q)[0], kkt=kkt_residual(model, q, k, eps),
                              success=bool(res.success))


def solve_sum(model: ErrorModel, q0: np.ndarray, *, maxiter: int = 200) -> SubproblemSolution:
    """Minimise ``s1 + s2`` (scaled) within the joint limits from ``q0`` (a weighted-sum
    scalarisation: its solution is Pareto optimal when global, and ``(0, 0)`` when the
    pose is reached). Its ``kkt`` is the projected gradient of ``s1 + s2``."""
    x0 = np.clip(np.asarray(q0, dtype=float), model.lower, model.upper)
    res = _minimize(lambda x: model.squared(x)[0].sum(), x0,
                   jac=lambda x: model.squared(x)[1].sum(axis=0), method="SLSQP",
                   bounds=list(zip(model.lower, model.upper, strict=True)),
                   options={"ftol": 1e-30, "maxiter": maxiter})
    q = np.clip(res.x, model.lower, model.upper)
    g = model.squared(q)[1].sum(axis=0)
    g[((q - model.lower <= BOUND_TOL) & (g > 0)) | ((model.upper - q <= BOUND_TOL) & (g < 0))] = 0
    return SubproblemSolution(q=q, errors=model.errors(q)[0], kkt=float(np.max(np.abs(g))),
                              success=bool(res.success))
