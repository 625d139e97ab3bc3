"""JAYA.

Rao, "Jaya: A simple and new optimization algorithm for solving constrained
and unconstrained optimization problems", International Journal of Industrial
Engineering Computations 7, 19-34 (2016), DOI 10.5267/j.ijiec.2015.8.004:

- Eq. 1: ``x' = x + r1 (x_best - |x|) - r2 (x_worst - |x|)``, r1 and r2
  uniform in [0, 1] per coordinate, best and worst of the current population;
- a new solution replaces the old one only if it is better (greedy).

JAYA has no algorithm-specific parameters. Evaluations: N per iteration.
Coordinates are clipped to the bounds (Rao's code). Constrained problems: best,
worst and the greedy replacement are feasibility-first (Deb's rules, see
base.py); the paper used a penalty instead.
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, greedy_memory, ranking_fitness


def jaya_update(X, x_best, x_worst, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 1: move toward the best and away from the worst solution."""
    r1 = rng.random(X.shape)
    r2 = rng.random(X.shape)
    A = np.abs(X)
    return X + r1 * (x_best - A) - r2 * (x_worst - A)


class JAYA(ArrayAlgorithm):
    """JAYA with array state (``X``/``F`` is the greedy population).

    Args:
        pop_size: Population size N.
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)

    def _generation(self) -> Step:
        rank = ranking_fitness(self.F, self.CV)
        X = jaya_update(self.X, self.X[np.argmin(rank)], self.X[np.argmax(rank)],
                        rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
