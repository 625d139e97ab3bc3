"""The local search of :func:`moik.solver.pareto.solve_ik_pareto`: steps along the
solution set of a redundant arm.

At an exact solution ``q`` the directions that keep the pose (to first order) are
the null space of the task Jacobian (6 rows for a pose, 3 for a position; position
rows scaled by ``1 / reach``), from its SVD. A weighted sum ``w . F / span`` of the
criteria (minimisation form, scaled by their ranges over the archive) is
differentiated along an orthonormal basis of it by central differences, so any
criterion works, a user's callable too. Its steepest descent (joints at a limit it
would push out held fixed) is tried at several step lengths at once; each trial is
projected back onto the exact solutions (:class:`~moik.solver.pareto_search.Projector`,
every exact trial enters the archive) and the best one is taken if it improves
the weighted sum.
"""

from __future__ import annotations

import numpy as np

from moik.kinematics.criteria import joint_distance
from moik.kinematics.jacobian import parts_and_jacobian
from moik.solver.pareto_search import Projector

STEP_FACTORS = np.array([2.0, 1.0, 0.5, 0.25])  # trial step lengths, times the current one
FD_STEP = 1e-6  # central-difference step (rad) of the directional derivatives
MIN_STEP = 1e-5  # a local search stops below this step length (rad)
LIMIT_GAP = 1e-9  # a joint this near a limit (rad or robot unit) counts as at it
START_DISTINCT = 0.3  # joint-space distance between the starts of one local search weight


def nullspace(projector: Projector, P: np.ndarray) -> np.ndarray:
    """Orthonormal null-space bases ``(n, dof - rows, dof)`` of the task Jacobians at ``P``
    (position rows scaled by ``1 / reach``)."""
    robot, rows = projector.robot, projector.task_rows
    _, _, J = parts_and_jacobian(robot, P)
    Jt = J[:, :rows].copy()
    Jt[:, :3] /= robot.reach
    return np.linalg.svd(Jt)[2][:, rows:, :]


def descent_directions(robot, P: np.ndarray, N: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Steepest descent ``(n, dof)`` within the null spaces ``N (n, r, dof)`` given the
    directional derivatives ``g (n, r)`` along their basis, with the joints at a limit
    that it would push out held fixed (the descent within the remaining subspace)."""
    d = -np.einsum("ar,ard->ad", g, N)
    at_lo, at_hi = P - robot.lower <= LIMIT_GAP, robot.upper - P <= LIMIT_GAP
    for i in np.flatnonzero(np.any((at_lo & (d < 0)) | (at_hi & (d > 0)), axis=1)):
        held = (at_lo[i] & (d[i] < 0)) | (at_hi[i] & (d[i] > 0))
        _, sv, Vt = np.linalg.svd(N[i][:, held].T)  # coefficients a with (N^T a)_held = 0
        B = Vt[int(np.sum(sv > 1e-12)):].T
        d[i] = -N[i].T @ (B @ (B.T @ g[i]))
    return d


def scaled_scores(F: np.ndarray, W: np.ndarray, span: np.ndarray) -> np.ndarray:
    """Weighted sums ``sum_k W_ik F_ik / span_k`` per row."""
    return np.einsum("...m,...m->...", F / span, W)


def local_search(projector: Projector, starts: np.ndarray, weights: np.ndarray, *,
                 iterations: int, step: float) -> None:
    """Descend each weighted sum from its start along the solution set, all at once.

    Each iteration takes the gradient of ``w . F / span`` within the null space
    (central differences along its basis), tries steps of several lengths along
    it, projects them back (every exact trial enters the archive) and moves to the
    best trial if it improves the weighted sum; the step length grows after a
    long accepted step and shrinks by 4 after a failure.
    """
    problem, dof = projector.problem, projector.robot.dof
    span = np.ptp(projector.F, axis=0)
    span = np.where(span > 0, span, 1.0)
    P, W = starts.copy(), weights
    S = scaled_scores(problem.minimization_form(problem.natural(P)), W, span)
    h = np.full(len(P), float(step))
    for _ in range(iterations):
        act = np.flatnonzero(h > MIN_STEP)
        if not len(act):
            return
        N = nullspace(projector, P[act])
        D = P[act, None, None, :] + FD_STEP * np.array([1.0, -1.0])[:, None] * N[:, :, None, :]
        Fd = problem.minimization_form(problem.natural(D.reshape(-1, dof)))
        Sd = scaled_scores(Fd.reshape(*D.shape[:3], -1), W[act, None, None], span)
        d = descent_directions(projector.robot, P[act], N,
                               (Sd[..., 0] - Sd[..., 1]) / (2.0 * FD_STEP))
        norm = np.linalg.norm(d, axis=1)
        norm = np.where(norm > 0, norm, 1.0)
        lengths = h[act, None] * STEP_FACTORS
        trials = P[act, None, :] + lengths[..., None] * (d / norm[:, None])[:, None, :]
        Pt, ok, _ = projector.project(trials.reshape(-1, dof))
        scores = np.full(len(Pt), np.inf)
        scores[ok] = scaled_scores(projector.objectives(Pt[ok]), np.repeat(W[act], len(
            STEP_FACTORS), axis=0)[ok], span)
        St = scores.reshape(len(act), -1)
        b = np.argmin(St, axis=1)
        better = St[np.arange(len(act)), b] < S[act]
        Pt = Pt.reshape(len(act), len(STEP_FACTORS), dof)
        won = act[better]
        P[won], S[won] = Pt[better, b[better]], St[better, b[better]]
        h[won] = lengths[better, b[better]] * 1.5
        h[act[~better]] *= 0.25


def local_search_starts(projector: Projector, per_extreme: int = 4
                        ) -> tuple[np.ndarray, np.ndarray]:
    """``(starts, weights)``: for each criterion, the ``per_extreme`` best exact points
    seen that are ``START_DISTINCT`` apart in joint space (local optima on other
    branches or regions), with that criterion's unit weight; and the archive member
    best in a few even weighted sums (three for two criteria, one for more)."""
    m = projector.F.shape[1]
    mixes = [np.array([t, 1.0 - t]) for t in (0.25, 0.5, 0.75)] if m == 2 else (
        [np.full(m, 1.0 / m)] if m > 2 else [])
    X, F = projector.seen()
    span = np.ptp(projector.F, axis=0)
    span = np.where(span > 0, span, 1.0)
    starts, weights = [], []
    for k in range(m):
        picked = _distinct_best(projector.robot, X, F[:, k], per_extreme)
        starts += picked
        weights += [np.eye(m)[k]] * len(picked)
    for w in mixes:
        starts += _distinct_best(projector.robot, projector.X, projector.F / span @ w, 1)
        weights.append(w)
    return np.array(starts), np.array(weights)


def _distinct_best(robot, X: np.ndarray, score: np.ndarray, count: int) -> list[np.ndarray]:
    """The ``count`` rows of ``X`` lowest in ``score``, each ``START_DISTINCT`` from the others."""
    order = np.argsort(score, kind="stable")
    free = np.ones(len(order), dtype=bool)  # far enough from every row picked so far
    picked: list[np.ndarray] = []
    while len(picked) < count and free.any():
        q = X[order[int(np.argmax(free))]]
        picked.append(q)
        free &= joint_distance(robot, q, X[order]) > START_DISTINCT
    return picked
