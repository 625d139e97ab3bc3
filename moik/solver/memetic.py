"""The memetic search of :func:`~moik.solver.pareto.solve_ik_pareto` on a redundant arm
(:func:`memetic_search`, the steps 1-3 of that module)."""

from __future__ import annotations

import numpy as np

from moik.solver.pareto_local import local_search, local_search_starts
from moik.solver.pareto_search import Projector, mo_search

ORIENTATION_STARTS = 16  # LM ends of the random starts moved towards the preferred rotation


def memetic_search(projector: Projector, first: np.ndarray, rng: np.random.Generator, *,
                   starts: int, method: str, pop_size: int, generations: int,
                   local_iterations: int, local_step: float, seed: int) -> None:
    """Steps 1-3 of a redundant arm's search: LM from ``first`` and ``starts`` random
    configurations (from ``rng``), the multi-objective ``method`` (seeded by ``seed``),
    the local search; every exact point enters ``projector``'s archive."""
    problem, robot = projector.problem, projector.robot
    P, ok, _ = projector.project(first, patient=True)
    Q, ok_q, _ = projector.project(robot.random_q(starts, rng=rng))
    exact = np.vstack([P[ok], Q[ok_q]])
    if problem.rotation is not None and "orientation" in problem.names:
        R, ok_r, _ = projector.project_via_pose(Q[:ORIENTATION_STARTS], problem.rotation)
        exact = np.vstack([exact, R[ok_r]])
    projector.objectives(exact)
    if generations:
        mo_search(projector, method, exact, pop_size=pop_size, generations=generations,
                  seed=seed)
    if local_iterations and len(projector.X):
        begin, weights = local_search_starts(projector)
        local_search(projector, begin, weights, iterations=local_iterations, step=local_step)
