"""Which rows of an oversized initial sample an array-state algorithm keeps.

pymoo's ``sampling=`` may hand an algorithm more points than its population (pymoo's
biased-initialization workflow, docs/source/customization/initialization: 300 rows for
``pop_size=100``, as an array, a ``Population`` or an evaluated ``Population``). As in
pymoo, every row is evaluated once (an individual already evaluated is not evaluated
again, and only the evaluations done count in ``n_eval``), every row is offered to what
the algorithm reports (the best so far, the external archive), and the algorithm's own
ranking keeps its initial population size:

- single-objective algorithms (:func:`best_rows`): the best fitness in feasibility-first
  order (feasible rows by f, then infeasible ones by total violation), as pymoo's
  ``FitnessSurvival``;
- multi-objective algorithms (:func:`rank_and_crowding_rows`): NSGA-II's survival, as
  pymoo's ``RankAndCrowding``: feasible rows by non-dominated rank, the last front cut by
  crowding distance (largest first), then infeasible rows by smallest total violation;
- pymoo's MOEA/D and MOPSO-CD as registered by moik (:func:`surviving_population`): the
  same rank and crowding, on the evaluated ``Population``;
- an algorithm with a survival of its own uses it instead (MOMPA: its reference-point
  selection over all rows; the one-swarm-per-objective methods: each swarm the best rows
  on its own objective).

Rows a problem's NaN/inf made ``F = CV = inf`` (:mod:`moik.algorithms.nonfinite`) come
last. Ties keep the order given (stable sorts; no random draw, so a sample of at most
the population size changes nothing). The rows kept keep their order in the sample.
"""

from __future__ import annotations

import numpy as np
from pymoo.core.population import Population
from pymoo.operators.survival.rank_and_crowding.metrics import calc_crowding_distance
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik.algorithms.mechanics import ranking_fitness

__all__ = ["best_rows", "rank_and_crowding_rows", "surviving_population"]


def best_rows(F: np.ndarray, CV: np.ndarray | None, n: int) -> np.ndarray:
    """Indices (ascending) of the ``n`` best rows of a single-objective sample.

    Args:
        F: Objective values (k,).
        CV: Total violations (k,), None for an unconstrained problem.
        n: How many to keep (all when ``n >= k``).
    """
    order = np.argsort(ranking_fitness(np.asarray(F, float), CV), kind="stable")
    return np.sort(order[:n])


def rank_and_crowding_rows(F: np.ndarray, CV: np.ndarray | None, n: int) -> np.ndarray:
    """Indices (ascending) of the ``n`` rows NSGA-II's survival keeps (module doc).

    Args:
        F: Objective values (k, n_obj).
        CV: Total violations (k,), None for an unconstrained problem.
        n: How many to keep (all when ``n >= k``).
    """
    k = len(F)
    if n >= k:
        return np.arange(k)
    cv = np.zeros(k) if CV is None else np.asarray(CV, float)
    finite = np.isfinite(F).all(axis=1) & np.isfinite(cv)
    feasible = np.flatnonzero(finite & (cv <= 0.0))
    chosen: list[np.ndarray] = []
    left = n
    if len(feasible):
        fronts = NonDominatedSorting().do(F[feasible], n_stop_if_ranked=left)
        for front in fronts:
            if left == 0:
                break
            rows = feasible[np.sort(front)]
            if len(rows) > left:
                crowding = calc_crowding_distance(F[rows])
                rows = rows[np.argsort(-crowding, kind="stable")[:left]]
            chosen.append(rows)
            left -= len(rows)
    if left:
        infeasible = np.flatnonzero(finite & (cv > 0.0))
        chosen.append(infeasible[np.argsort(cv[infeasible], kind="stable")[:left]])
        left -= len(chosen[-1])
    if left:
        chosen.append(np.flatnonzero(~finite)[:left])
    return np.sort(np.concatenate(chosen))


def surviving_population(pop: Population, n: int) -> Population:
    """The ``n`` individuals of an evaluated ``Population`` NSGA-II's survival keeps
    (:func:`rank_and_crowding_rows` on its F and CV); ``pop`` itself when it has at most
    ``n``."""
    if len(pop) <= n:
        return pop
    return pop[rank_and_crowding_rows(pop.get("F"), pop.get("CV")[:, 0], n)]
