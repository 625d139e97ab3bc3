"""The reference Pareto front of (position error, orientation error, joint motion).

Objectives (:class:`moik.problems.PoseMotionIK`): ``f1`` the position error, ``f2`` an
orientation error (a smooth metric of :mod:`moik.kinematics.rotation_metrics`), ``f3 =
||q - q_start||`` (EOSMA Eq. 31's displacement term as an objective of its own). The
front is a surface; :func:`motion_front` samples it by epsilon-constraint subproblems
(Haimes, Lasdon & Wismer 1971; Miettinen 1999, Sec. 3.2; their solutions are weakly
Pareto optimal when solved globally), with ``s_j = f_j^2`` scaled as in
:mod:`moik.fronts.scalarised`:

1. Motion levels ``e3`` evenly spaced over ``[0, f3_max]``, ``f3_max`` the largest
   motion over the bi-objective reference front's joint vectors
   (:func:`moik.fronts.front.bi_objective_front`; above it the motion constraint no
   longer binds there). ``e3 = 0`` is the point ``q_start`` itself.
2. At each level, two anchors (many starts, warm-started from the level below too):
   ``A`` = the least ``f1`` subject to ``f3 <= e3``, ``B`` = the least ``f2`` subject
   to ``f3 <= e3``; then ``levels`` orientation levels ``e2`` evenly spaced over
   ``[f2(B), f2(A)]``: ``min s1 s.t. s2 <= e2^2, s3 <= e3^2``, swept from ``B`` and
   from ``A`` (each subproblem warm-started from its neighbour) and from the level
   below, the best kept.
3. The union filtered to its non-dominated points (errors within ``tol`` tie).

What it guarantees (stated on the returned object): every point is the errors of its
own joint vector (attainable), the end of SLSQP on its subproblem, with its projected KKT
residual recorded (:func:`kkt_residual`; the statement counts the points that are KKT
points to 1e-6: measured on ``eosma-p1-motion``, SLSQP stalls short of that on a few);
no point is dominated by another point found. Not global
optimality: a branch no start and no sweep reaches would be missed (the tests compare
the front with a long NSGA-II run for that reason).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik._validate import integer, positive
from moik.exceptions import ParameterError
from moik.fronts.front import ReferenceFront, bi_objective_front
from moik.fronts.scalarised import (
    BOUND_TOL,
    FTOL,
    ZERO_EPS,
    ErrorModel,
    SubproblemSolution,
    _minimize,
)
from moik.kinematics.rotation_metrics import ZYX_EULER, ZYX_EULER_FREE_GAMMA
from moik.robots.chain import Robot


class MotionModel:
    """:class:`~moik.fronts.scalarised.ErrorModel`'s two pose errors and the motion.

    Args:
        model: The pose errors.
        q_start: The configuration the motion is measured from ``(dof,)``.

    Attributes:
        scale: ``(S1, S2, S3)``: ``reach^2``, 1 rad^2 and ``dof`` rad^2 (a change of
            every joint by one radian scales to one).
    """

    def __init__(self, model: ErrorModel, q_start: np.ndarray):
        self.pose, self.q_start = model, np.asarray(q_start, dtype=float)
        self.lower, self.upper = model.lower, model.upper
        self.scale = np.array([*model.scale, float(self.q_start.size)])

    def squared(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Scaled ``(s1, s2, s3)`` and their gradients ``(3, dof)`` at ``q``."""
        value, grad = self.pose.squared(q)
        d = q - self.q_start
        return (np.append(value, d @ d / self.scale[2]),
                np.vstack([grad, 2.0 * d / self.scale[2]]))

    def errors(self, Q: np.ndarray) -> np.ndarray:
        """``(n, 3)``: position error, orientation error and motion of every row of ``Q``."""
        Q = np.atleast_2d(Q)
        return np.column_stack([self.pose.errors(Q),
                                np.linalg.norm(Q - self.q_start, axis=1)])


def _constraints(model: MotionModel, q0: np.ndarray, levels: dict[int, float]) -> list[dict]:
    """SLSQP constraints ``f_m <= eps`` for ``levels = {m: eps}`` (``inf``: none); an
    orientation level ``<= ZERO_EPS`` is the pose equations ``R = R_t`` (as in
    :func:`~moik.fronts.scalarised.solve_constrained`: ``s2 <= 0`` has no constraint
    qualification)."""
    out: list[dict] = []
    for m, eps in levels.items():
        if not np.isfinite(eps):
            continue
        if m == 1 and eps <= ZERO_EPS:
            r0, j0 = model.pose.residual(q0, 1)
            rows = (np.abs(r0) > 1e-14) | (np.abs(j0).max(axis=1) > 1e-12)
            out.append({"type": "eq", "fun": lambda x, r=rows: model.pose.residual(x, 1)[0][r],
                        "jac": lambda x, r=rows: model.pose.residual(x, 1)[1][r]})
            continue
        level = eps * eps / model.scale[m]
        out.append({"type": "ineq", "fun": lambda x, m=m, level=level:
                    level - model.squared(x)[0][m],
                    "jac": lambda x, m=m: -model.squared(x)[1][m]})
    return out


def kkt_residual(model: MotionModel, q: np.ndarray, k: int, levels: dict[int, float]
                 ) -> float:
    """Projected KKT residual of ``min s_k s.t. f_m <= levels[m]`` at ``q``.

    ``|| P(grad s_k + sum_m lam_m grad c_m) ||_inf`` with the multipliers of the active
    constraints (``s_m >= level (1 - 1e-6)``; ``lam_m >= 0``, free for the rows of the
    pose equations at a zero orientation level) fitted by bounded least squares over
    the joints off their limits, and ``P`` zeroing a component at a joint limit whose
    sign a bound multiplier absorbs. Zero at a KKT point.
    """
    from scipy.optimize import lsq_linear

    value, grad = model.squared(q)
    g = grad[k].copy()
    free = ~((q - model.lower <= BOUND_TOL) | (model.upper - q <= BOUND_TOL))
    columns, lower = [], []
    for m, eps in levels.items():
        if not np.isfinite(eps):
            continue
        if m == 1 and eps <= ZERO_EPS:
            rows = model.pose.residual(q, 1)[1]
            columns += list(rows)
            lower += [-np.inf] * len(rows)
        elif value[m] >= eps * eps / model.scale[m] * (1 - 1e-6):
            columns.append(grad[m])
            lower.append(0.0)
    if columns and free.any():
        A = np.array(columns).T[free]
        lam = lsq_linear(A, -g[free], bounds=(np.array(lower), np.inf)).x
        g = g + np.array(columns).T @ lam
    g[((q - model.lower <= BOUND_TOL) & (g > 0)) | ((model.upper - q <= BOUND_TOL) & (g < 0))] = 0
    return float(np.max(np.abs(g)))


def solve_motion(model: MotionModel, q0: np.ndarray, k: int, levels: dict[int, float], *,
                 maxiter: int = 1000) -> SubproblemSolution:
    """Minimise ``s_k`` subject to ``f_m <= levels[m]`` and the joint limits, from ``q0``
    (SLSQP; ``errors`` of the result: ``(f1, f2, f3)``)."""
    x0 = np.clip(np.asarray(q0, dtype=float), model.lower, model.upper)
    res = _minimize(lambda x: model.squared(x)[0][k], x0,
                    jac=lambda x: model.squared(x)[1][k], method="SLSQP",
                    bounds=list(zip(model.lower, model.upper, strict=True)),
                    constraints=_constraints(model, x0, levels),
                    options={"ftol": FTOL, "maxiter": maxiter})
    q = np.clip(res.x, model.lower, model.upper)
    return SubproblemSolution(q=q, errors=model.errors(q)[0],
                              kkt=kkt_residual(model, q, k, levels), success=bool(res.success))


def _better(a: SubproblemSolution, b: SubproblemSolution | None, k: int,
            levels: dict[int, float]) -> bool:
    """Whether ``a`` improves on ``b`` in ``min f_k s.t. f_m <= levels[m]``: feasibility
    (to ``ZERO_EPS``) first, then ``f_k``."""
    if b is None:
        return True
    fa = all(a.errors[m] <= e + ZERO_EPS for m, e in levels.items())
    fb = all(b.errors[m] <= e + ZERO_EPS for m, e in levels.items())
    return bool(fa) if fa != fb else bool(a.errors[k] < b.errors[k])


def _best(model: MotionModel, starts, k: int, levels: dict[int, float]) -> SubproblemSolution:
    out: SubproblemSolution | None = None
    for q in starts:
        s = solve_motion(model, q, k, levels)
        if _better(s, out, k, levels):
            out = s
    assert out is not None
    return out


def motion_front(robot: Robot, position, rotation, q_start, *, metric: str = "geodesic",
                 levels: int = 12, motion_levels: int = 12, starts: int = 8,
                 tol: float = 1e-9, rng: np.random.Generator) -> ReferenceFront:
    """The Pareto front of ``(position error, orientation error, ||q - q_start||)``.

    Args:
        robot: The arm (its joint limits bound the search).
        position: Target position ``(3,)``.
        rotation: Target rotation ``(3, 3)``.
        q_start: The configuration the motion is measured from (within the limits).
        metric: Orientation metric name (not a ZYX Euler one: their kinks need the
            lifted subproblems of :mod:`moik.fronts.lifted`, for two objectives only).
        levels: Orientation levels per motion level.
        motion_levels: Motion levels (``e3 = 0`` included).
        starts: Random starts of each anchor (and of the bi-objective front).
        tol: Objective tolerance of the non-dominated filter.
        rng: The random starts' generator.

    Returns:
        The :class:`~moik.fronts.front.ReferenceFront` (``F`` ``(n, 3)``; see the module
        docstring for its guarantee); ``extra["q_start"]`` records ``q_start``.

    Raises:
        ParameterError: A setting out of range, a ZYX Euler metric, or ``q_start``
            outside the limits.
    """
    levels = integer("levels", levels, minimum=2)
    motion_levels = integer("motion_levels", motion_levels, minimum=2)
    starts = integer("starts", starts, minimum=1)
    tol = positive("tol", tol)
    q_start = robot.check_q(q_start, "q_start")
    if q_start.ndim != 1 or not robot.within_limits(q_start)[0]:
        raise ParameterError(f"q_start must be one joint vector within the limits of "
                             f"{robot.name!r}")
    pose = ErrorModel(robot, position, rotation, metric)
    if pose.code in (ZYX_EULER, ZYX_EULER_FREE_GAMMA):
        raise ParameterError(f"motion_front needs a smooth orientation metric, got {metric!r}")
    model = MotionModel(pose, q_start)
    bi = bi_objective_front(robot, position, rotation, metric=metric, starts=starts,
                            rng=rng)
    picks = np.unique(np.linspace(0, len(bi.Q) - 1, min(len(bi.Q), starts)).round().astype(int))
    Q0 = np.vstack([robot.random_q(starts, rng=rng), bi.Q[picks]])
    f3_max = float(model.errors(bi.Q)[:, 2].max())
    sols: list[SubproblemSolution] = []
    below: list[SubproblemSolution] = []  # the previous motion level's solutions
    for e3 in np.linspace(0.0, f3_max, motion_levels):
        if e3 == 0.0:  # only q_start itself moves by 0
            q = q_start.copy()
            sols.append(SubproblemSolution(q=q, errors=model.errors(q)[0], kkt=0.0,
                                           success=True))
            below = [sols[-1]]
            continue
        warm = np.vstack([Q0, [s.q for s in below]])
        a = _best(model, warm, 0, {2: e3})
        b = _best(model, warm, 1, {2: e3})
        eps2 = np.linspace(b.errors[1], a.errors[1], levels)
        level_sols: list[SubproblemSolution | None] = [None] * levels
        for order, origin in ((range(levels), b), (range(levels - 1, -1, -1), a)):
            q = origin.q
            for i in order:
                lv = {1: float(eps2[i]), 2: float(e3)}
                candidates = [solve_motion(model, q, 0, lv)]
                if len(below) == levels:
                    candidates.append(solve_motion(model, below[i].q, 0, lv))
                for s in candidates:
                    if _better(s, level_sols[i], 0, lv):
                        level_sols[i] = s
                q = candidates[0].q
        below = [s for s in level_sols if s is not None]
        sols += [a, b, *below]
    F = np.array([s.errors for s in sols])
    Fq = np.round(F / tol) * tol
    keep = NonDominatedSorting().do(Fq, only_non_dominated_front=True)
    keep = keep[np.lexsort((F[keep, 2], F[keep, 1], F[keep, 0]))]
    _, first = np.unique(Fq[keep], axis=0, return_index=True)
    keep = keep[np.sort(first)]
    kkt = np.array([sols[i].kkt for i in keep])
    settings: dict[str, Any] = dict(metric=metric, starts=starts, levels=levels, checks=0,
                                    tol=tol)
    text = (f"{len(keep)} non-dominated local solutions of epsilon-constraint subproblems "
            f"min f1 s.t. f2 <= e2, f3 <= e3 on {motion_levels} motion x {levels} orientation "
            f"levels (SLSQP, continuation along both and from {starts} random starts per "
            f"anchor); {int(np.sum(kkt <= 1e-6))} of them with a projected KKT residual <= "
            f"1e-6 (SLSQP stalled short of it on the others: max {np.nanmax(kkt):.2e}; each "
            "point is the errors of its own joint vector, so attainable); local, not global, "
            "optimality")
    return ReferenceFront(F=F[keep], Q=np.array([sols[i].q for i in keep]), kkt=kkt,
                          reachable=bool(np.any(F[keep, :2].max(axis=1) <= tol)),
                          guarantee=text,
                          extra={"q_start": q_start.tolist(), "motion_levels": motion_levels,
                                 "bi_objective_points": len(bi.F)}, **settings)
