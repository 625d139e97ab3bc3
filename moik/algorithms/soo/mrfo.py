"""Manta ray foraging optimization (MRFO).

Zhao, Zhang & Wang, "Manta ray foraging optimization: An effective
bio-inspired optimizer for engineering applications", Engineering
Applications of Artificial Intelligence 87, 103300 (2020),
DOI 10.1016/j.engappai.2019.103300:

- Eqs. 1-2 (chain foraging): ``x_i + r (x_{i-1} - x_i) + alpha (x_best - x_i)``
  (``x_best`` in place of ``x_{i-1}`` for i = 1),
  ``alpha = 2 r sqrt(|log r|)``;
- Eqs. 4-5 (cyclone foraging, exploitation):
  ``x_best + r (x_{i-1} - x_i) + beta (x_best - x_i)``,
  ``beta = 2 exp(r1 (T - t + 1)/T) sin(2 pi r1)``;
- Eqs. 6-7 (cyclone foraging, exploration, when ``t/T < rand``): the same
  with a random point ``x_rand = Lb + r (Ub - Lb)`` in place of ``x_best``;
- each manta ray takes cyclone foraging with probability 0.5, else chain;
- Eq. 8 (somersault foraging): ``x_i + S (r2 x_best - r3 x_i)``.

Defaults (EOSMA paper, Table 3): somersault factor S=2. Evaluations: **2N per
iteration** (chain/cyclone batch, then somersault batch, as in the paper's
pseudo-code); ``max_iter`` inferred from an ``n_eval`` termination accounts
for it. ``t`` and ``T`` are the base class's iteration and schedule length.

Deviations and readings:
- ``x_{i-1}`` is the previous manta ray's position at iteration t (the
  paper's Eqs. 1, 4, 7), so all rays move at once; the authors' code uses the
  previous ray's already-updated position (a sequential chain).
- ``r`` is a fresh uniform vector per coordinate wherever it appears (``alpha``
  draws its own), ``r1``, ``r2``, ``r3`` are scalars per ray, as in the
  authors' code.
- A ray keeps its new position only if it is better, and ``x_best`` is
  refreshed after each batch, as in the authors' code (the paper's
  pseudo-code only updates ``x_best``).
- Coordinates outside the box are clipped to the bounds (the authors' code
  redraws them uniformly; the paper does not say).
- Constrained problems: comparisons are feasibility-first (see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    uniform_population,
)


def chain_and_cyclone(X, best, t: int, T: int, *, xl: np.ndarray, xu: np.ndarray,
                      rng: np.random.Generator) -> np.ndarray:
    """Eqs. 1-7: chain or cyclone foraging of every ray (row of ``X``), not yet bounded."""
    n, d = X.shape
    prev = np.concatenate([best[None], X[:-1]])  # x_{i-1}; x_best for the first ray
    cyclone = rng.random(n) < 0.5
    r = rng.random((n, d))
    alpha = 2.0 * rng.random((n, d)) * np.sqrt(np.abs(np.log(rng.random((n, d)))))  # Eq. 2
    chain = X + r * (prev - X) + alpha * (best - X)  # Eq. 1
    r1 = rng.random(n)[:, None]
    beta = 2.0 * np.exp(r1 * (T - t + 1) / T) * np.sin(2.0 * math.pi * r1)  # Eq. 5
    explore = rng.random(n) > t / T  # t/T < rand: Eq. 7
    ref = np.where(explore[:, None], uniform_population(n, xl, xu, rng=rng), best)  # Eq. 6
    prev_cyc = np.concatenate([ref[:1], X[:-1]])
    cyc = ref + r * (prev_cyc - X) + beta * (ref - X)  # Eqs. 4, 7
    return np.where(cyclone[:, None], cyc, chain)


def somersault(X, best, S: float, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 8: ``x_i + S (r2 x_best - r3 x_i)`` with scalars ``r2``, ``r3`` per ray."""
    n = len(X)
    r2 = rng.random(n)[:, None]
    r3 = rng.random(n)[:, None]
    return X + S * (r2 * best - r3 * X)


class MRFO(ArrayAlgorithm):
    """Manta ray foraging optimization (Zhao et al. 2020) with array state.

    ``X``/``F`` is the population (each ray keeps its best, greedy).

    Args:
        pop_size: Number of manta rays N.
        S: Somersault factor, > 0 (Table 3: 2).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, S: float = 2.0, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.S = interval("S", S, 0.0, 10.0, lo_open=True)

    def _evals_per_iteration(self) -> float:
        return 2.0 * self.pop_size

    def _generation(self) -> Step:
        rng = self.random_state
        X = chain_and_cyclone(self.X, self.best_x, self.t, self.max_iter, xl=self.xl,
                              xu=self.xu, rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
        X = clip_to_bounds(somersault(self.X, self.best_x, self.S, rng=rng), self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
