"""Differential evolution, DE/rand/1/bin, with array state.

Storn & Price, "Differential evolution - a simple and efficient heuristic for
global optimization over continuous spaces", Journal of Global Optimization
11, 341-359 (1997), DOI 10.1023/A:1008202821328 (scheme DE1, Section 2):

- Eq. 1 (mutation): ``v_i = x_r1 + F (x_r2 - x_r3)``, with ``r1, r2, r3``
  mutually different random indices, all different from ``i``;
- Eqs. 2-3 (binomial crossover): ``u_ji = v_ji`` if ``randb(j) <= CR`` or
  ``j = rnbr(i)`` (one coordinate always taken from ``v``), else ``x_ji``;
- selection: ``u_i`` replaces ``x_i`` only if it has a smaller cost.

Defaults (EOSMA paper, Table 3): F=0.5, Cr=0.9. Evaluations: N per iteration.
The population needs N >= 4 (three partners other than ``i``).

Deviations:
- The 1997 paper does not bound the search; trial coordinates outside the box
  are clipped to the bounds.
- Constrained problems: selection is feasibility-first (see base.py).

pymoo's own DE is registered as ``pymoo-de`` for reference.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, greedy_memory


def distinct_partners(n: int, k: int, *, rng: np.random.Generator) -> np.ndarray:
    """For each of ``n`` rows, ``k`` mutually different indices, all different from the row.

    Returns:
        Integer array (n, k). Needs ``n >= k + 1``.
    """
    keys = rng.random((n, n))
    keys[np.arange(n), np.arange(n)] = np.inf  # never pick i itself
    return np.argsort(keys, axis=1)[:, :k]


def rand_1_mutation(X: np.ndarray, R: np.ndarray, F: float) -> np.ndarray:
    """Eq. 1: ``v_i = x_r1 + F (x_r2 - x_r3)`` for partner indices ``R`` (n, 3)."""
    return X[R[:, 0]] + F * (X[R[:, 1]] - X[R[:, 2]])


def binomial_crossover(X: np.ndarray, V: np.ndarray, CR: float, *,
                       rng: np.random.Generator) -> np.ndarray:
    """Eqs. 2-3: take ``v_ji`` where ``randb(j) <= CR`` or ``j = rnbr(i)``, else ``x_ji``."""
    n, d = X.shape
    take = rng.random((n, d)) <= CR
    take[np.arange(n), rng.integers(d, size=n)] = True
    return np.where(take, V, X)


class DE(ArrayAlgorithm):
    """Differential evolution DE/rand/1/bin (Storn & Price 1997) with array state.

    ``X``/``F`` is the population (each row survives until a better trial replaces it).

    Args:
        pop_size: Population size N >= 4.
        F: Differential weight in (0, 2] (Table 3: 0.5).
        CR: Crossover rate in [0, 1] (Table 3: 0.9).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 4

    def __init__(self, *, pop_size: int = 100, F: float = 0.5, CR: float = 0.9,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.F_weight = interval("F", F, 0.0, 2.0, lo_open=True)
        self.CR = interval("CR", CR, 0.0, 1.0)

    def _generation(self) -> Step:
        rng = self.random_state
        R = distinct_partners(len(self.X), 3, rng=rng)
        V = rand_1_mutation(self.X, R, self.F_weight)
        U = clip_to_bounds(binomial_crossover(self.X, V, self.CR, rng=rng), self.xl, self.xu)
        F, CV = yield U
        self.X, self.F, self.CV = greedy_memory(U, F, CV, self.X, self.F, self.CV)
