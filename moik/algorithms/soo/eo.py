"""Equilibrium optimizer (EO).

Faramarzi, Heidarinejad, Stephens & Mirjalili, "Equilibrium optimizer: A novel
optimization algorithm", Knowledge-Based Systems 191, 105190 (2020),
DOI 10.1016/j.knosys.2019.105190. Equation numbers below are those of the EOSMA
paper (Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3),
which restates EO as Eqs. 6-9:

- Eq. 6: ``C = Ceq + F (C - Ceq) + (1 - F) G / (lambda V)``;
- Eq. 7: the equilibrium pool, the 4 best solutions found so far and their mean;
- Eq. 8: ``F = a1 sign(r - 0.5) (exp(-lambda t1) - 1)``,
  ``t1 = (1 - t/T)^(a2 t/T)``;
- Eq. 9: ``G = GCP (Ceq - lambda C) F`` with ``GCP = 0.5 r1`` if ``r2 >= GP``
  else 0;
- memory saving: an agent keeps its previous position if that was better.

Defaults (EOSMA paper, Table 3; the EO paper's own): a1=2, a2=1, GP=0.5, V=1.
Evaluations: N per iteration. Out-of-range coordinates are clipped to the bounds,
as in the authors' code.

Deviations:
- The authors' code keeps the pool as a cascade of ``if/elseif`` tests, which
  does not shift old members down when a new best arrives; here the pool is
  the true 4 best solutions evaluated so far (the paper's wording).
- The authors' code divides ``G ./ lambda * V``; the paper divides by
  ``lambda V``. Identical for the default V=1; the paper's form is used.
- Constrained problems: comparisons are feasibility-first (see base.py).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    ranking_fitness,
)


def update_pool(PX, PF, PCV, X, F, CV, k: int = 4):
    """Eq. 7 (first part): the ``k`` best of the old pool and a new evaluated batch.

    Returns:
        ``(PX, PF, PCV)`` with at most ``k`` rows, best first.
    """
    X_all = np.concatenate([PX, X])
    F_all = np.concatenate([PF, F])
    CV_all = None if CV is None else np.concatenate([PCV, CV])
    order = np.argsort(ranking_fitness(F_all, CV_all), kind="stable")[:k]
    return X_all[order], F_all[order], (None if CV is None else CV_all[order])


def with_mean(PX: np.ndarray) -> np.ndarray:
    """Eq. 7: append the mean of the pool members (Ceq_ave) as a last row."""
    return np.concatenate([PX, PX.sum(axis=0, keepdims=True) / len(PX)])


def eo_schedule(t: int, T: int, a2: float) -> float:
    """Eq. 8: ``t1 = (1 - t/T)^(a2 t/T)``, with t/T capped at 1."""
    s = min(t / T, 1.0)
    return (1.0 - s) ** (a2 * s)


def concentration_update(C, pool, t1: float, *, a1: float, GP: float, V: float,
                         rng: np.random.Generator) -> np.ndarray:
    """Eqs. 6, 8, 9: EO's concentration update of every row of ``C``.

    Args:
        C: Current concentrations (n, d).
        pool: Equilibrium pool (m, d), one member drawn per agent.
        t1: Time factor of Eq. 8.
        a1: Exploration factor. GP: generation probability. V: control volume.
        rng: Random generator.
    """
    n, d = C.shape
    lam = rng.random((n, d))
    r = rng.random((n, d))
    Ceq = pool[rng.integers(len(pool), size=n)]
    F = a1 * np.sign(r - 0.5) * (np.exp(-lam * t1) - 1.0)  # Eq. 8
    r1, r2 = rng.random(n), rng.random(n)
    GCP = np.where(r2 >= GP, 0.5 * r1, 0.0)[:, None]  # Eq. 9
    G = GCP * (Ceq - lam * C) * F
    return Ceq + (C - Ceq) * F + G / (lam * V) * (1.0 - F)  # Eq. 6


class EO(ArrayAlgorithm):
    """Equilibrium optimizer (Faramarzi et al. 2020) with array state.

    Extra public arrays: ``pool_X``/``pool_F`` (the 4 best so far). ``X``/``F`` is
    the memory (EO's memory saving makes the population its own memory).

    Args:
        pop_size: Number of particles N.
        a1: Exploration factor, > 0 (paper: 2).
        a2: Exploitation factor, > 0 (paper: 1).
        GP: Generation probability in [0, 1] (paper: 0.5).
        V: Control volume, > 0 (paper: 1).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, a1: float = 2.0, a2: float = 1.0,
                 GP: float = 0.5, V: float = 1.0, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.a1 = interval("a1", a1, 0.0, 10.0, lo_open=True)
        self.a2 = interval("a2", a2, 0.0, 10.0, lo_open=True)
        self.GP = interval("GP", GP, 0.0, 1.0)
        self.V = interval("V", V, 0.0, np.inf, lo_open=True, hi_open=True)

    def _initialize_state(self) -> None:
        empty = np.empty((0, self.problem.n_var))
        cv0 = None if self.CV is None else np.empty(0)
        self.pool_X, self.pool_F, self.pool_CV = update_pool(
            empty, np.empty(0), cv0, self.X, self.F, self.CV)

    def _generation(self) -> Step:
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        X = concentration_update(self.X, with_mean(self.pool_X), t1, a1=self.a1, GP=self.GP,
                                 V=self.V, rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.pool_X, self.pool_F, self.pool_CV = update_pool(
            self.pool_X, self.pool_F, self.pool_CV, X, F, CV)
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
