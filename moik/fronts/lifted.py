"""The epsilon-constraint subproblems for the ZYX Euler metrics, made smooth by lifting.

MO-m-PSO's Eq. 14 error ``f2 = (|d_1| + |d_2| + |d_3|) / 3`` (``d``: the ZYX angle
differences; Section 4.4's free-gamma variant drops ``d_3``) has kinks wherever an angle
matches, exactly where the front's points lie, and SLSQP stalls on them. The standard
lifting (e.g. Boyd & Vandenberghe, *Convex Optimization*, 2004, Sec. 4.1.3) adds one
variable ``t_i`` per angle with ``t_i >= d_i`` and ``t_i >= -d_i``: then
``f2 = sum(t) / 3`` at a solution and every function is smooth. ``min f1^2 s.t. f2 <= eps``
becomes ``min s1(q) s.t. sum(t) / 3 <= eps``; ``min f2 s.t. f1 <= eps`` becomes
``min sum(t) / 3 s.t. s1(q) <= eps^2``. The KKT residual of
:func:`moik.fronts.scalarised.kkt_residual` does not apply to the kinked form; it is
reported as NaN for these solutions.
"""

from __future__ import annotations

import numpy as np

from moik.fronts.scalarised import (
    FTOL,
    ZERO_EPS,
    ErrorModel,
    SubproblemSolution,
    _minimize,
    solve_constrained,
)
from moik.kinematics.rotation_metrics import ZYX_EULER, ZYX_EULER_FREE_GAMMA


def is_kinked(model: ErrorModel) -> bool:
    """Whether ``model``'s orientation error is a ZYX Euler (absolute-value) metric."""
    return model.code in (ZYX_EULER, ZYX_EULER_FREE_GAMMA)


def solve_lifted(model: ErrorModel, q0: np.ndarray, k: int, eps: float, *,
                 maxiter: int = 200) -> SubproblemSolution:
    """:func:`~moik.fronts.scalarised.solve_constrained` for a ZYX metric, lifted.

    Falls back to ``solve_constrained`` where no absolute value is involved (``k = 0``
    without an orientation level, or the level ``f2 = 0``, three smooth equations).
    """
    if k == 0 and (not np.isfinite(eps) or eps <= ZERO_EPS):
        return solve_constrained(model, q0, k, eps, maxiter=maxiter)
    dof = model.lower.size
    q0 = np.clip(np.asarray(q0, dtype=float), model.lower, model.upper)
    d0 = model.residual(q0, 1)[0]
    n = d0.size
    x0 = np.concatenate([q0, np.abs(d0)])
    eye = np.eye(n)

    def abs_rows(x):  # t - d >= 0 and t + d >= 0
        d, J = model.residual(x[:dof], 1)
        return (np.concatenate([x[dof:] - d, x[dof:] + d]),
                np.block([[-J, eye], [J, eye]]))

    constraints = [{"type": "ineq", "fun": lambda x: abs_rows(x)[0],
                    "jac": lambda x: abs_rows(x)[1]}]
    pad = np.zeros(n)
    if k == 0:  # min s1 s.t. sum(t) / 3 <= eps
        def fun(x):
            return model.squared(x[:dof])[0][0]

        def jac(x):
            return np.concatenate([model.squared(x[:dof])[1][0], pad])
        constraints.append({"type": "ineq", "fun": lambda x: eps - x[dof:].sum() / 3,
                            "jac": lambda x: np.concatenate([np.zeros(dof), -np.ones(n) / 3])})
    else:  # min sum(t) / 3 s.t. f1 <= eps
        grad_t = np.concatenate([np.zeros(dof), np.ones(n) / 3])

        def fun(x):
            return x[dof:].sum() / 3

        def jac(x):
            return grad_t
        if eps <= ZERO_EPS:  # the position equations, less those that vanish identically
            r0, j0 = model.residual(q0, 0)  # (a planar arm's z), as solve_constrained does
            rows = (np.abs(r0) > 1e-14) | (np.abs(j0).max(axis=1) > 1e-12)
            zero = np.zeros((int(rows.sum()), n))
            constraints.append({"type": "eq",
                                "fun": lambda x: model.residual(x[:dof], 0)[0][rows],
                                "jac": lambda x: np.hstack([model.residual(x[:dof], 0)[1][rows],
                                                            zero])})
        elif np.isfinite(eps):
            level = eps * eps / model.scale[0]
            constraints.append({"type": "ineq",
                                "fun": lambda x: level - model.squared(x[:dof])[0][0],
                                "jac": lambda x: np.concatenate(
                                    [-model.squared(x[:dof])[1][0], pad])})
    bounds = list(zip(model.lower, model.upper, strict=True)) + [(0.0, None)] * n
    res = _minimize(fun, x0, jac=jac, method="SLSQP", bounds=bounds, constraints=constraints,
                    options={"ftol": FTOL, "maxiter": maxiter})
    q = np.clip(res.x[:dof], model.lower, model.upper)
    return SubproblemSolution(q=q, errors=model.errors(q)[0], kkt=float("nan"),
                              success=bool(res.success))
