"""MOSMA: multi-objective slime mould algorithm with elitist non-dominated sorting.

Premkumar, Jangir, Sowmya, Alhelou, Heidari & Chen, "MOSMA: Multi-Objective
Slime Mould Algorithm Based on Elitist Non-Dominated Sorting", IEEE Access 9,
3229-3248 (2021), DOI 10.1109/ACCESS.2020.3047936 (the MOSMA of the EOSMA
paper, Yin et al. 2022, DOI 10.1038/s41598-022-13516-3, its ref. 35 and
Table 4). SMA's operators (Li et al. 2020; EOSMA paper Eqs. 1-5,
:mod:`moik.algorithms.soo.sma`) on a population kept by NSGA-II's elitist
non-dominated sorting and crowding distance:

- the population (N) is sorted by non-domination rank, then by decreasing
  crowding distance (:func:`elitist_order`);
- the scalar fitness of SMA is the place in that order: ``S_k = k`` (0-based),
  used by the weights (Eqs. 4-5) and by Eq. 2, ``p = tanh|S_k - DF|`` with
  ``DF = 0``: the first agent oscillates (``vc X``), the next ones mostly
  approach the food;
- Eq. 1: with probability z a random restart, else per coordinate
  ``X_b + vb (W X_A - X_B)`` if ``r < p``, ``vc X`` otherwise; the food ``X_b``
  is drawn uniformly per agent from the first front; Eq. 3 schedules a, b;
- parents and offspring (2N) are merged and the best N by rank and crowding
  distance survive (elitist non-dominated sorting).

Every evaluated point is also offered to the external crowding-radius archive
(capacity ``archive_size``, default ``pop_size``): ``res.X``/``res.F`` are its
members, as for every moik multi-objective method.

Defaults (EOSMA Table 4): z=0.03, N = archive = 100. Evaluations: N per iteration.

Deviations and readings:
- The authors' MATLAB code differs from the paper's text in ways read as
  slips: it sorts the decision matrix for the weights, uses
  ``X_b = new_Sol(j) - new_Sol(1)`` and replaces ``vc X`` by
  ``X_b + vc (W X_A - X_B)``. Here SMA's printed equations are used with the
  readings above; ``X_b`` drawn from the first front keeps the food diverse
  (the code's single elite ``new_Sol(1)`` is a boundary point with infinite
  crowding distance).
- The paper does not say which scalar plays SMA's fitness. The place in the
  elitist order is used for both Eq. 2 and Eqs. 4-5; the non-domination rank
  would give ``p = 0`` to the whole first front, so once the population is
  mutually non-dominated every agent would only oscillate (``vc X``), which
  collapses the front (ZDT1 HV 0.44 instead of 0.87 in a check).
- ``X``, ``X_A``, ``X_B`` are the surviving (sorted) population; the code draws
  ``X_A``, ``X_B`` from the previous offspring.
- The reported front is the external archive (the paper reports the first
  front of the final population, at most N points; the archive holds every
  non-dominated point found, truncated to capacity).
- Eq. 3 uses ``t / (T + 1)``, T the update iterations: SMA's code counts the
  initial evaluation as its first iteration (:mod:`moik.algorithms.soo.sma`);
  ``t / T = 1`` would send every ``vc X`` coordinate to exactly 0.
- Coordinates are clipped to the bounds (as in the code); rows left without
  evaluation by an ``n_eval`` budget (``F = inf``) never survive.
- Constraints (not in the paper): the elitist order puts the feasible rows first
  (by rank and crowding distance), then the infeasible ones by increasing
  violation, each its own front (constraint-domination, as pymoo's NSGA-II).

While no feasible point was seen, the archive keeps its capacity of least infeasible
rows (a moik extension, :mod:`moik.algorithms.archive.base`; a strict
constraint-domination filter would keep only the least infeasible row, and every leader
would be it), and until a feasible point is found a companion DE population searches
for one (a moik extension, :mod:`moik.algorithms.moo.feasibility_search`). Infeasible
output on pymoo's MW and CTP problems with and without it, method or handling:
docs/results/constrained-moo.md (``studies/constrained_moo.py``).
"""

from __future__ import annotations

import numpy as np
from pymoo.operators.survival.rank_and_crowding.metrics import calc_crowding_distance
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik._validate import interval
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.soo.sma import sma_schedule, sma_update, sma_weights


def elitist_order(F: np.ndarray, n: int, CV: np.ndarray | None = None
                  ) -> tuple[np.ndarray, np.ndarray]:
    """NSGA-II elitist selection: the best ``n`` rows by rank, then crowding distance.

    Args:
        F: Objective values (finite), shape (m, M) with m >= n.
        n: Number of rows to keep.
        CV: Total constraint violations (m,), or None (unconstrained): feasible rows
            are ordered first, the infeasible ones after them by increasing
            violation (stable), each with its own rank.

    Returns:
        ``(index, rank)``: the kept row indices sorted by (rank ascending,
        crowding distance descending within each front; stable on ties) and
        their 0-based non-domination ranks.
    """
    if CV is not None:
        feas = np.flatnonzero(CV <= 0.0)
        index, rank = (elitist_order(F[feas], min(n, feas.size)) if feas.size
                       else (np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)))
        index = feas[index]
        bad = np.flatnonzero(CV > 0.0)
        bad = bad[np.argsort(CV[bad], kind="stable")][: n - index.size]
        start = rank.max() + 1 if rank.size else 0
        return (np.concatenate([index, bad]),
                np.concatenate([rank, start + np.arange(bad.size)]))
    fronts = NonDominatedSorting().do(F, n_stop_if_ranked=n)
    kept: list[np.ndarray] = []
    ranks: list[np.ndarray] = []
    for r, front in enumerate(fronts):
        cd = calc_crowding_distance(F[front])
        front = front[np.argsort(-cd, kind="stable")]
        kept.append(front[: n - sum(map(len, kept))])
        ranks.append(np.full(len(kept[-1]), r))
        if sum(map(len, kept)) == n:
            break
    return np.concatenate(kept), np.concatenate(ranks)


class MOSMA(MOArrayAlgorithm):
    """MOSMA (Premkumar et al. 2021) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays: ``pop_X``/``pop_F``/``pop_CV``/``pop_rank`` (the elitist
    population in sorted order). ``X``/``F`` are the last offspring.

    Args:
        pop_size: Number of agents N (Table 4: 100).
        archive_size: Archive capacity; None means ``pop_size`` (Table 4: 100).
        z: Random-restart probability in [0, 1] (Table 4: 0.03).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 z: float = 0.03, max_iter: int | None = None, X0: np.ndarray | None = None,
                 **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.z = interval("z", z, 0.0, 1.0)

    def _initialize_state(self) -> None:
        self._survive(self.X, self.F, self.CV)

    def _survive(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None) -> None:
        """Elitist non-dominated sorting of the finite rows of ``X``/``F`` (at least N)."""
        finite = np.all(np.isfinite(F), axis=1)
        X, F = X[finite], F[finite]
        CV = None if CV is None else CV[finite]
        keep, self.pop_rank = elitist_order(F, self.pop_size, CV)
        self.pop_X, self.pop_F = X[keep], F[keep]
        self.pop_CV = None if CV is None else CV[keep]

    def _population_arrays(self):
        return self.pop_X, self.pop_F, self.pop_CV

    def _generation(self) -> Step:
        rng, n, d = self.random_state, self.pop_size, self.problem.n_var
        S = np.arange(n, dtype=float)  # fitness = place in the elitist order
        W = sma_weights(S, d, rng=rng)  # Eqs. 4-5
        n_first = int(np.sum(self.pop_rank == 0))
        food = self.pop_X[rng.integers(n_first, size=n)]
        a, b = sma_schedule(self.t, self.max_iter + 1)  # Eq. 3; Max_iter = T + 1 (module doc)
        X = sma_update(self.pop_X, W, food, S, 0.0, a, b, z=self.z, xl=self.xl, xu=self.xu,
                       rng=rng)  # Eqs. 1-2
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
        self._survive(np.concatenate([self.pop_X, X]), np.concatenate([self.pop_F, F]),
                      None if CV is None else np.concatenate([self.pop_CV, CV]))
