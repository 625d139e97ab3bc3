"""The reference Pareto front of bi-objective IK by epsilon-constraint continuation.

Objectives (:class:`moik.problems.BiObjectiveIK`, MO-m-PSO Eq. 15): the position error
``f1`` and an orientation error ``f2`` (any metric of
:mod:`moik.kinematics.rotation_metrics`). The method (:func:`bi_objective_front`):

1. The weighted sum ``f1^2 / reach^2 + f2^2`` minimised from every start: if it reaches
   ``(0, 0)`` (to ``tol``) the pose is reachable and the front is that point. Else the
   anchors (many starts): ``A`` = the least position error ``f1*`` and, at it, the least
   orientation error; ``B`` = the least orientation error ``f2*`` and, at it, the least
   position error. If ``A`` and ``B`` coincide in objective space (to ``tol``) the front
   is that one point; it is ``(0, 0)`` exactly when the pose is reachable
   (``ReferenceFront.reachable``).
2. Two families of epsilon-constraint subproblems (:mod:`moik.fronts.scalarised`):
   ``min f1 s.t. f2 <= eps`` on ``levels`` values of ``eps`` evenly spaced over
   ``[f2*, f2(A)]`` and ``min f2 s.t. f1 <= eps`` over ``[f1*, f1(B)]``. Each family is
   swept from both anchors, each subproblem warm-started from its neighbour's solution,
   and the better of the two per level kept.
3. Checks: at both end levels and ``checks`` interior levels of each family the
   subproblem is solved from every one of the ``starts`` random starts; a start that
   beats the continuation by more than ``tol`` seeds a new sweep in both directions
   (repeated until none does).
4. The union is filtered to its non-dominated points (errors that differ by less than
   ``tol`` count as equal), sorted by ``f1``.

What it guarantees (stated on the returned object): every point is a local solution of
its subproblem found by SLSQP, with its projected KKT residual recorded
(:func:`moik.fronts.scalarised.kkt_residual`); no point is dominated by another point
found; at the check levels no random start found a better local solution. It does not
guarantee global optimality: a better branch that no start and no sweep reaches would be
missed (the paper-arm tests compare the front with long NSGA-II runs for that reason).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik._validate import integer, positive
from moik.exceptions import ParameterError
from moik.fronts.lifted import is_kinked, solve_lifted
from moik.fronts.scalarised import (
    ZERO_EPS,
    ErrorModel,
    SubproblemSolution,
    solve_constrained,
    solve_sum,
)
from moik.robots.chain import Robot

METHOD_VERSION = 1  # bump when a change of the method may move a front (invalidates caches)


@dataclass(frozen=True)
class ReferenceFront:
    """A computed reference front and what it guarantees.

    Attributes:
        F: ``(n, 2)`` non-dominated ``(position error, orientation error)``, by ``f1``.
        Q: ``(n, dof)`` the joint vectors of ``F``.
        kkt: ``(n,)`` each point's projected KKT residual in its subproblem (NaN for the
            ZYX Euler metrics' lifted subproblems, :mod:`moik.fronts.lifted`).
        reachable: Whether the target pose is reached (the front is ``[[0, 0]]``).
        metric: The orientation metric.
        starts, levels, checks: The method's settings.
        tol: Objective tolerance of the anchors and checks.
        guarantee: The statement of what was established, in words.
        version: :data:`METHOD_VERSION`.
    """

    F: np.ndarray
    Q: np.ndarray
    kkt: np.ndarray
    reachable: bool
    metric: str
    starts: int
    levels: int
    checks: int
    tol: float
    guarantee: str = ""
    version: int = METHOD_VERSION
    extra: dict = field(default_factory=dict)

    @property
    def max_kkt(self) -> float:
        """The largest KKT residual of the front's points."""
        return float(np.nanmax(self.kkt)) if np.any(np.isfinite(self.kkt)) else float("nan")


def _solver(model: ErrorModel):
    """The subproblem solver for ``model``'s metric (lifted for the ZYX Euler ones)."""
    return solve_lifted if is_kinked(model) else solve_constrained


def _better(a: SubproblemSolution, b: SubproblemSolution | None, k: int,
            level: float = np.inf) -> bool:
    """Whether ``a`` improves on ``b`` in subproblem ``(k, level)``: feasibility first
    (``f_m <= level``, to ``ZERO_EPS``), then objective ``k``, then the other one."""
    if b is None:
        return True
    fa, fb = a.errors[1 - k] <= level + ZERO_EPS, b.errors[1 - k] <= level + ZERO_EPS
    if fa != fb:
        return bool(fa)
    return bool(a.errors[k] < b.errors[k] or (a.errors[k] == b.errors[k]
                                             and a.errors[1 - k] < b.errors[1 - k]))


def _anchor(model: ErrorModel, starts: np.ndarray, k: int, tol: float) -> SubproblemSolution:
    """The least ``f_k`` from every start, then the least ``f_m`` at ``f_k <= best + tol``."""
    sols = [_solver(model)(model, q, k, np.inf) for q in starts]
    best = min(s.errors[k] for s in sols)
    near = [s for s in sols if s.errors[k] <= best + tol]
    level = best + tol if best > tol else 0.0
    out: SubproblemSolution | None = None
    for s in near:
        r = _solver(model)(model, s.q, 1 - k, level)
        if _better(r, out, 1 - k, level):
            out = r
        if _better(s, out, 1 - k, level):
            out = s
    assert out is not None
    return out


def _sweep(model: ErrorModel, k: int, eps: np.ndarray, q0: np.ndarray, order) -> list:
    """Continuation over ``eps[order]`` from ``q0``: one solution per level."""
    sols: list[SubproblemSolution | None] = [None] * len(eps)
    q = q0
    for i in order:
        s = _solver(model)(model, q, k, eps[i])
        sols[i] = s
        q = s.q
    return sols


def _family(model, k, eps, end_lo, end_hi, starts, checks, tol, stats) -> list:
    """Epsilon-constraint family ``min f_k s.t. f_m <= eps``, swept and checked."""
    n = len(eps)
    best = _sweep(model, k, eps, end_hi.q, range(n - 1, -1, -1))
    for i, s in enumerate(_sweep(model, k, eps, end_lo.q, range(n))):
        if _better(s, best[i], k, eps[i]):
            best[i] = s
    check_levels = np.unique(np.linspace(0, n - 1, checks + 2).round().astype(int))
    for _ in range(5):
        improved = False
        for i in check_levels:
            for q in starts:
                s = _solver(model)(model, q, k, eps[i])
                stats["check_solves"] += 1
                if (s.errors[1 - k] <= eps[i] + ZERO_EPS
                        and (best[i].errors[1 - k] > eps[i] + ZERO_EPS
                             or s.errors[k] < best[i].errors[k] - tol)):
                    improved = True
                    stats["improvements"] += 1
                    best[i] = s
                    for sweep in (_sweep(model, k, eps, s.q, range(i, -1, -1)),
                                  _sweep(model, k, eps, s.q, range(i, n))):
                        for j, t in enumerate(sweep):
                            if t is not None and _better(t, best[j], k, eps[j]):
                                best[j] = t
        if not improved:
            break
    return best


def bi_objective_front(robot: Robot, position, rotation, *, metric: str = "geodesic",
                       levels: int = 40, starts: int = 16, checks: int = 1,
                       tol: float = 1e-9, rng: np.random.Generator) -> ReferenceFront:
    """The Pareto front of ``(position error, orientation error)`` at one target pose.

    Args:
        robot: The arm (its joint limits bound the search).
        position: Target position ``(3,)`` in the robot's unit.
        rotation: Target rotation ``(3, 3)``.
        metric: Orientation metric name.
        levels: Epsilon levels per family (two families).
        starts: Random starts of the anchors and of each check.
        checks: Interior levels per family solved from every start.
        tol: Objective tolerance (anchors, reachability, checks).
        rng: The random starts' generator.

    Returns:
        The :class:`ReferenceFront` (see the module docstring for its guarantee).

    Raises:
        ParameterError: A setting out of range.
    """
    levels = integer("levels", levels, minimum=2)
    starts = integer("starts", starts, minimum=1)
    checks = integer("checks", checks, minimum=0)
    tol = positive("tol", tol)
    if not isinstance(rng, np.random.Generator):
        raise ParameterError(f"rng must be a numpy Generator, got {type(rng).__name__}")
    model = ErrorModel(robot, position, rotation, metric)
    Q0 = robot.random_q(starts, rng=rng)
    settings: dict[str, Any] = dict(metric=metric, starts=starts, levels=levels, checks=checks,
                                    tol=tol)
    ideal = min((solve_sum(model, q) for q in Q0), key=lambda s: float(s.errors.max()))
    a = b = ideal
    if ideal.errors.max() > tol:
        a = _anchor(model, Q0, 0, tol)
        b = _anchor(model, Q0, 1, tol)
    if a.errors[1] <= b.errors[1] + tol and b.errors[0] <= a.errors[0] + tol:
        one = a if a.errors.sum() <= b.errors.sum() else b
        reachable = bool(np.all(one.errors <= tol))
        F = np.zeros((1, 2)) if reachable else one.errors[None].copy()
        text = (f"the anchors coincide: the least position error and the least orientation "
                f"error are reached together from {starts} starts (to {tol:g})"
                + (", the pose is reachable and the front is the point (0, 0)" if reachable
                   else ""))
        return ReferenceFront(F=F, Q=one.q[None].copy(), kkt=np.array([one.kkt]),
                              reachable=reachable, guarantee=text,
                              extra={"anchor_errors": one.errors.tolist()}, **settings)
    stats = {"check_solves": 0, "improvements": 0}
    sols = [a, b, ideal]
    eps2 = np.linspace(b.errors[1], a.errors[1], levels)
    sols += _family(model, 0, eps2, b, a, Q0, checks, tol, stats)
    eps1 = np.linspace(a.errors[0], b.errors[0], levels)
    sols += _family(model, 1, eps1, a, b, Q0, checks, tol, stats)
    F = np.array([s.errors for s in sols])
    hit = int(np.argmin(F.max(axis=1)))
    if F[hit].max() <= tol:  # a sweep reached the pose: the front is the ideal point
        text = (f"the pose is reachable: a subproblem solution has both errors <= {tol:g} "
                f"({F[hit, 0]:.2e}, {F[hit, 1]:.2e}); the front is the point (0, 0)")
        return ReferenceFront(F=np.zeros((1, 2)), Q=sols[hit].q[None].copy(),
                              kkt=np.array([sols[hit].kkt]), reachable=True, guarantee=text,
                              extra={"anchor_errors": F[hit].tolist(), **stats}, **settings)
    Fq = np.round(F / tol) * tol  # errors that differ by less than tol are ties
    keep = NonDominatedSorting().do(Fq, only_non_dominated_front=True)
    keep = keep[np.lexsort((F[keep, 1], F[keep, 0]))]
    _, first = np.unique(Fq[keep], axis=0, return_index=True)
    keep = keep[np.sort(first)]
    kkt = np.array([sols[i].kkt for i in keep])
    text = (f"{len(keep)} non-dominated local solutions of 2 x {levels} epsilon-constraint "
            f"subproblems (SLSQP, continuation from both anchors), max projected KKT residual "
            f"{np.nanmax(kkt) if np.isfinite(kkt).any() else np.nan:.2e}; anchors, end "
            f"levels and {checks} interior levels per family from {starts} random starts "
            f"each ({stats['improvements']} improvements found); local, not "
            "global, optimality")
    return ReferenceFront(F=F[keep], Q=np.array([sols[i].q for i in keep]), kkt=kkt,
                          reachable=False, guarantee=text, extra=stats, **settings)


def dominating_points(reference: np.ndarray, F: np.ndarray, tol: float) -> np.ndarray:
    """The rows of ``F`` that dominate a point of ``reference`` beyond ``tol``.

    Objectives are scaled by the reference front's range (1 where it has none, e.g. the
    single point of a reachable pose); ``a`` dominates ``r`` beyond ``tol`` when it is
    better in every scaled objective by more than ``tol``: ``(r - a) / span > tol``.
    Empty when nothing found beats the reference front.
    """
    R, A = np.asarray(reference, dtype=float), np.atleast_2d(np.asarray(F, dtype=float))
    span = np.ptp(R, axis=0)
    span = np.where(span > 0, span, 1.0)
    better = (R[None, :, :] - A[:, None, :]) / span > tol
    return A[np.all(better, axis=2).any(axis=1)]
