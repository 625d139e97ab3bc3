"""Equilibrium optimizer slime mould algorithm (EOSMA), single-objective.

Yin, Luo, Zhou, Zhou & Zhu, "An equilibrium optimizer slime mould algorithm for
inverse kinematics of the 7-DOF robotic manipulator", Scientific Reports 12,
9421 (2022), DOI 10.1038/s41598-022-13516-3. Eqs. 15-18 and Algorithm 1:

- Eq. 15: with probability z the EO operator on the personal best,
  ``X = Xeq + (pBest - Xeq) F + G (1 - F)/(lambda V)`` (F, G as EO's Eqs. 8-9
  with ``C = pBest``), else the SMA operator
  ``X = gBest + vb (W pBest_A - pBest_B)`` (W from Eq. 4 on the personal-best
  fitness, ``vb ~ U(-a, a)``, ``a = atanh(1 - t/T)``);
- Eq. 16: random difference mutation ``X = pBest_R1 + SF (pBest_R2 - pBest_R3)``,
  ``SF ~ U[0.3, 0.6]``, applied with probability q (one draw per iteration,
  Algorithm 1 line 22);
- Eq. 17: a coordinate beyond a bound moves to the midpoint between the agent's
  previous position and that bound;
- Eq. 18: greedy personal-best memory.

Defaults (Table 3): z=0.5, V=1, GP=0.5, a2=2; scenario 1 (position only, N=50,
T=500): q=0, a1=1; scenario 2 (position and posture, N=100, T=1000): q=1, a1=2.
``EOSMA.scenario(1)`` / ``EOSMA.scenario(2)`` build those presets; the number of
iterations is the caller's termination (``("n_gen", 500)`` for scenario 1).

Evaluations per iteration: Algorithm 1 evaluates the Eq. 15 positions (line 24,
inside ``if rand < q``, or line 7 of the next iteration) and, when the mutation
fires, the Eq. 16 positions (line 7 of the next iteration). So N evaluations
per iteration with q=0 and 2N with q=1; N (1 + q) on average.

Deviations and readings:
- The equilibrium pool is the 4 best *distinct* solutions evaluated so far plus
  their mean (Eq. 7's wording), refreshed after every evaluation, not only at
  line 8. Exact duplicates (the SMA operator returns gBest itself once the
  weights are all 1) are kept once: the authors' code admits a pool member
  only with a strictly different fitness, and a pool of four copies of gBest
  makes ``Ceq_ave`` meaningless. (Their code fills the pool by a cascade of
  ``if/elseif`` tests that does not shift members down; the true 4 best are
  used here, as the text says.)
- Eq. 17 moves a coordinate halfway to the bound from the agent's location
  before the update, which is its personal best (the paper's IK section:
  "the location of the search agents ... i.e. pBest_i"; the authors' code
  repairs against the greedy memory ``Xold``). An earlier version of this
  module used the last evaluated position instead.
- ``pBest_A``/``pBest_B`` and ``R1..R3`` are drawn per agent (whole vectors, as
  the text says); SF is drawn per agent.
- W uses ``log10`` and ``eps`` as the SMA code (Eq. 4 prints ``log``).
- Constrained problems: comparisons are feasibility-first (see base.py).

Reproducing Tables 5 and 7 on the 7-DOF arm: tests/algorithms/soo/test_eosma.py
(Table 7 is reproduced with Table 1's lengths in metres, not in cm).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    greedy_memory,
    midpoint_repair,
    ranking_fitness,
)
from moik.algorithms.soo.eo import concentration_update, eo_schedule, with_mean
from moik.algorithms.soo.sma import sma_schedule, sma_weights
from moik.exceptions import ParameterError

SCENARIOS = {
    1: {"pop_size": 50, "q": 0.0, "a1": 1.0},
    2: {"pop_size": 100, "q": 1.0, "a1": 2.0},
}


def eosma_update(P, g_best, pool, W, t1: float, a: float, *, z: float, a1: float, GP: float,
                 V: float, rng: np.random.Generator) -> np.ndarray:
    """Eq. 15: the EO operator (probability z) or the SMA operator, per agent.

    Args:
        P: Personal bests (n, d). g_best: best so far (d,). pool: equilibrium pool.
        W: SMA weights (n, d). t1: EO time factor (Eq. 8). a: SMA range (Eq. 3).
        z, a1, GP, V: hyperparameters. rng: random generator.
    """
    n, d = P.shape
    X_eo = concentration_update(P, pool, t1, a1=a1, GP=GP, V=V, rng=rng)
    vb = rng.uniform(-a, a, (n, d))
    A, B = rng.integers(n, size=n), rng.integers(n, size=n)
    X_sma = g_best + vb * (W * P[A] - P[B])
    use_eo = rng.random(n) < z
    return np.where(use_eo[:, None], X_eo, X_sma)


def update_distinct_pool(PX, PF, PCV, X, F, CV, k: int = 4):
    """Eq. 7: the ``k`` best distinct rows of the old pool and a new evaluated batch.

    Rows are ranked by the feasibility-first fitness (stable); a row equal to
    a better-ranked one is dropped. Equal rows have equal fitness, so rows are
    compared only when the ``4 k`` best hold a tie (else nothing to drop), and
    all rows only when the ``4 k`` best hold fewer than ``k`` distinct points.

    Returns:
        ``(PX, PF, PCV)`` with at most ``k`` rows, best first.
    """
    X_all, F_all = np.concatenate([PX, X]), np.concatenate([PF, F])
    CV_all = None if CV is None else np.concatenate([PCV, CV])
    S = ranking_fitness(F_all, CV_all)
    order = np.argsort(S, kind="stable")
    for m in (4 * k, len(order)):
        top = order[:m]
        St = S[top]
        if not np.any(St[1:] == St[:-1]):
            break
        Xs = X_all[top]
        same = (Xs[:, None, :] == Xs[None, :, :]).all(axis=2) & (St[:, None] == St[None, :])
        top = top[~np.tril(same, -1).any(axis=1)]
        if len(top) >= k or m >= len(order):
            break
    top = top[:k]
    return X_all[top], F_all[top], (None if CV is None else CV_all[top])


def random_difference_mutation(P: np.ndarray, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 16: ``pBest_R1 + SF (pBest_R2 - pBest_R3)`` with ``SF ~ U[0.3, 0.6]``."""
    n = len(P)
    R = rng.integers(n, size=(3, n))
    SF = rng.uniform(0.3, 0.6, (n, 1))
    return P[R[0]] + SF * (P[R[1]] - P[R[2]])


class EOSMA(ArrayAlgorithm):
    """EOSMA (Yin et al. 2022) with array state.

    Extra public arrays: ``pbest_X``/``pbest_F``/``pbest_CV`` (personal bests),
    ``pool_X``/``pool_F`` (4 best distinct so far). ``X``/``F`` are the last evaluated
    positions.

    Args:
        pop_size: Number of agents N (paper: 50 or 100).
        z: Probability of the EO operator in [0, 1] (paper: 0.5).
        q: Mutation probability in [0, 1] (paper: 0 or 1).
        V: Control volume, > 0 (paper: 1).
        GP: Generation probability in [0, 1] (paper: 0.5).
        a1: Exploration factor, > 0 (paper: 1 or 2).
        a2: Exploitation factor, > 0 (paper: 2).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    def __init__(self, *, pop_size: int = 100, z: float = 0.5, q: float = 1.0, V: float = 1.0,
                 GP: float = 0.5, a1: float = 2.0, a2: float = 2.0,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.z = interval("z", z, 0.0, 1.0)
        self.q = interval("q", q, 0.0, 1.0)
        self.V = interval("V", V, 0.0, np.inf, lo_open=True, hi_open=True)
        self.GP = interval("GP", GP, 0.0, 1.0)
        self.a1 = interval("a1", a1, 0.0, 10.0, lo_open=True)
        self.a2 = interval("a2", a2, 0.0, 10.0, lo_open=True)

    @classmethod
    def scenario(cls, number: int, **overrides) -> EOSMA:
        """The paper's preset: 1 (position, q=0, a1=1, N=50) or 2 (pose, q=1, a1=2, N=100)."""
        if number not in SCENARIOS:
            raise ParameterError(f"scenario must be 1 or 2, got {number!r}")
        return cls(**{**SCENARIOS[number], **overrides})

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + self.q)

    def _initialize_state(self) -> None:
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV
        empty, cv0 = np.empty((0, self.problem.n_var)), (None if self.CV is None else np.empty(0))
        self.pool_X, self.pool_F, self.pool_CV = update_distinct_pool(
            empty, np.empty(0), cv0, self.X, self.F, self.CV)

    def _remember(self, X, F, CV) -> None:
        """Eq. 18 and the pool after an evaluation."""
        self.X, self.F, self.CV = X, F, CV
        self.pbest_X, self.pbest_F, self.pbest_CV = greedy_memory(
            X, F, CV, self.pbest_X, self.pbest_F, self.pbest_CV)
        self.pool_X, self.pool_F, self.pool_CV = update_distinct_pool(
            self.pool_X, self.pool_F, self.pool_CV, X, F, CV)

    def _population_arrays(self):
        return self.pbest_X, self.pbest_F, self.pbest_CV

    def _generation(self) -> Step:
        rng = self.random_state
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        a, _ = sma_schedule(self.t, self.max_iter)
        W = sma_weights(ranking_fitness(self.pbest_F, self.pbest_CV), self.problem.n_var, rng=rng)
        X = eosma_update(self.pbest_X, self.best_x, with_mean(self.pool_X), W, t1, a, z=self.z,
                         a1=self.a1, GP=self.GP, V=self.V, rng=rng)
        X = midpoint_repair(X, self.pbest_X, self.xl, self.xu)  # Eq. 17
        F, CV = yield X
        self._remember(X, F, CV)
        if rng.random() < self.q:  # Algorithm 1, line 22
            X = midpoint_repair(random_difference_mutation(self.pbest_X, rng=rng),
                                self.pbest_X, self.xl, self.xu)
            F, CV = yield X
            self._remember(X, F, CV)
