"""Centroid opposition-based differential evolution (CODE).

Rahnamayan, Jesuthasan, Bourennani, Salehinejad & Naterer, "Computing
opposition by involving entire population", 2014 IEEE Congress on Evolutionary
Computation (CEC), 1800-1807, DOI 10.1109/CEC.2014.6900329. CODE is
opposition-based DE (ODE; Rahnamayan, Tizhoosh & Salama, IEEE TEVC 12, 64-79
(2008), DOI 10.1109/TEVC.2007.894200) with the centroid opposite in place of
the type-I opposite:

- centroid ``M = (X_1 + ... + X_N) / N``; centroid opposite ``X~_i = 2 M - X_i``;
- a coordinate of ``X~`` outside the interval ``[a_j, b_j]`` is re-sampled
  between the centroid and that bound: ``a_j + rand (M_j - a_j)`` below,
  ``M_j + rand (b_j - M_j)`` above;
- opposition-based initialization: the N fittest of the random population and
  its centroid opposite (``[a, b]`` = the problem bounds);
- every generation DE/rand/1/bin ``v = x_r1 + F (x_r2 - x_r3)``, binomial
  crossover with rate Cr and one forced coordinate, greedy selection; then with
  probability Jr generation jumping: the N fittest of the population and its
  centroid opposite, ``[a_j, b_j]`` = the population's current range in
  dimension j (ODE's dynamic interval).

Defaults (EOSMA paper, Table 3): F=0.5, Cr=0.9, Jr=0.3.

Evaluations per iteration: N (trial vectors) plus N with probability Jr
(generation jumping): N (1 + Jr) = 1.3 N on average. The opposition-based
initialization (N more evaluations) runs as the first iteration, so it counts
against the same budget.

Deviations and readings:
- The papers do not say how a trial vector outside the box is repaired; here
  its out-of-range coordinates are re-drawn uniformly in the box (ODE's usual
  choice).
- Selection keeps a trial only if it is strictly better (the shared greedy
  memory); Storn & Price's DE also accepts ties.
- Constrained problems: comparisons and the "N fittest" are feasibility-first.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    greedy_memory,
    ranking_fitness,
    uniform_population,
)


def distinct_indices(n: int, k: int, *, rng: np.random.Generator, pool: int | None = None,
                     exclude: tuple[np.ndarray, ...] | None = None) -> np.ndarray:
    """Return ``k`` index rows (k, n): row r differs from rows < r and from ``exclude``.

    Indices are drawn from ``range(pool)`` (``pool`` defaults to n) by rejection,
    as Zhang's ``gnR1R2`` does; ``exclude`` (arrays of n indices) defaults to
    ``(arange(n),)``, each agent itself.
    """
    pool = n if pool is None else pool
    taken = [np.arange(n)] if exclude is None else list(exclude)
    rows = []
    for _ in range(k):
        r = rng.integers(pool, size=n)
        for _ in range(1000):
            clash = np.zeros(n, dtype=bool)
            for t in taken:
                clash |= r == t
            if not clash.any():
                break
            r[clash] = rng.integers(pool, size=int(clash.sum()))
        rows.append(r)
        taken.append(r)
    return np.array(rows)


def de_rand_1_bin(X, *, F: float, Cr: float, xl, xu, rng: np.random.Generator) -> np.ndarray:
    """DE/rand/1/bin trial vectors; out-of-box coordinates re-drawn uniformly."""
    n, d = X.shape
    r1, r2, r3 = distinct_indices(n, 3, rng=rng)
    V = X[r1] + F * (X[r2] - X[r3])
    cross = rng.random((n, d)) < Cr
    cross[np.arange(n), rng.integers(d, size=n)] = True
    trial = np.where(cross, V, X)
    out = (trial < xl) | (trial > xu)
    return np.where(out, uniform_population(n, xl, xu, rng=rng), trial)


def centroid_opposite(X, a, b, *, rng: np.random.Generator) -> np.ndarray:
    """Centroid opposite ``2 M - X``, out-of-interval coordinates re-sampled toward M."""
    M = X.mean(axis=0)
    opp = 2.0 * M - X
    r = rng.random(X.shape)
    opp = np.where(opp < a, a + r * (M - a), opp)
    return np.where(opp > b, M + r * (b - M), opp)


def fittest(X, F, CV, k: int):
    """The ``k`` feasibility-first best rows of a batch, best first."""
    order = np.argsort(ranking_fitness(F, CV), kind="stable")[:k]
    return X[order], F[order], (None if CV is None else CV[order])


class CODE(ArrayAlgorithm):
    """Centroid opposition-based DE (Rahnamayan et al. 2014) with array state.

    ``X``/``F`` is the population.

    Args:
        pop_size: Population size N (at least 4 for DE/rand/1).
        F: Scale factor in (0, 2] (Table 3: 0.5).
        Cr: Crossover rate in [0, 1] (Table 3: 0.9).
        Jr: Generation-jumping rate in [0, 1] (Table 3: 0.3).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 4

    def __init__(self, *, pop_size: int = 50, F: float = 0.5, Cr: float = 0.9, Jr: float = 0.3,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.F_scale = interval("F", F, 0.0, 2.0, lo_open=True)
        self.Cr = interval("Cr", Cr, 0.0, 1.0)
        self.Jr = interval("Jr", Jr, 0.0, 1.0)

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + self.Jr)

    def _initialize_state(self) -> None:
        self._opposition_initialized = False

    def _jump(self, a, b) -> Step:
        opp = centroid_opposite(self.X, a, b, rng=self.random_state)
        FO, CVO = yield opp
        CV = None if CVO is None else np.concatenate([self.CV, CVO])
        self.X, self.F, self.CV = fittest(np.concatenate([self.X, opp]),
                                          np.concatenate([self.F, FO]), CV, len(self.X))

    def _generation(self) -> Step:
        rng = self.random_state
        if not self._opposition_initialized:  # opposition-based initialization
            self._opposition_initialized = True
            yield from self._jump(self.xl, self.xu)
            return
        U = de_rand_1_bin(self.X, F=self.F_scale, Cr=self.Cr, xl=self.xl, xu=self.xu, rng=rng)
        FU, CVU = yield U
        self.X, self.F, self.CV = greedy_memory(U, FU, CVU, self.X, self.F, self.CV)
        if rng.random() < self.Jr:  # generation jumping on the dynamic interval
            yield from self._jump(self.X.min(axis=0), self.X.max(axis=0))
