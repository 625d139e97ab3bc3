"""Self-adaptive spherical search (SASS).

Kumar, Das & Zelinka, "A self-adaptive spherical search algorithm for
real-world constrained optimization problems", GECCO 2020 Companion, 13-14,
DOI 10.1145/3377929.3398186; built on the spherical search (SS) of Kumar,
Misra, Singh, Mallipeddi & Das, Applied Soft Computing 85, 105734 (2019),
DOI 10.1016/j.asoc.2019.105734. One generation:

- trial ``y_i = x_i + c_i A B_i A^T z_i`` (SS): A an orthogonal matrix (one per
  generation, the authors' near-permutation built from random coordinate pairs
  with angle 1e-12), B_i a diagonal 0/1 matrix with one forced 1 and the other
  entries 1 with probability rd_i;
- search direction: the better half of the population (by fitness) goes
  towards-rand ``z = x_r3 - x + x_r1 - x_r2`` (x_r2 from population plus
  archive), the other half towards-pbest ``z = x_pbest - x + x_r1 - s_r1`` with
  x_pbest one of the best ``max(round(0.11 N), 2)`` and s the "shadow"
  population (each agent's position before its last improvement);
- self-adaptation as in L-SHADE: ``c_i ~ Cauchy(M_c, 0.1)`` (re-drawn while
  <= 0, capped at 1), ``rd_i ~ N(M_rd, 0.1)`` clipped to [0, 1] (0 once the
  memory slot is terminal); memories of Ms entries updated each generation
  with the improvement-weighted Lehmer mean of the successful values;
- greedy selection (strict); replaced parents enter an archive of
  ``round(Ar N)`` members (random members dropped when full);
- linear population size reduction from ``N_init = 18 D`` to 4:
  ``N = round(4 nfes/MAX + N_init (1 - nfes/MAX))``, worst agents removed.

Defaults (EOSMA paper, Table 3): N from 18 D to 4, rd=0.5 and c=0.7 (the
memories' initial values), Ar=1.4, Ms=100.

Evaluations: the current population size per iteration, N_init down to 4,
so the budget MAX decides the run. MAX is the ``n_eval`` termination's limit.
Without one (``n_gen`` = T, a time limit, or pymoo's default), MAX is
``(N_init - 4) T / ln(N_init / 4)``, the budget at which the continuous
reduction schedule reaches 4 agents at iteration T (T from ``max_iter``, else
the update iterations an ``n_gen`` limit allows, ``n_max_gen - 1``, else 1000). For
the EOSMA paper's equal-budget comparison (N, T for the others) run SASS with
``("n_eval", N + N * T)``. The
population size changes between
iterations; ``X``/``F`` always hold the current agents (ArrayAlgorithm
reports whatever size they have).

Deviations and readings (the GECCO paper is a two-page abstract; details follow
a public port of the authors' MATLAB code):
- rd is drawn per agent (the port draws one normal deviate per generation).
- Out-of-range coordinates move halfway between the parent and the bound.
- Memory slots advance every generation, as in the port.
- Constrained problems: feasibility-first comparisons and ranking.
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import integer, interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    is_better,
    midpoint_repair,
    ranking_fitness,
    uniform_population,
)
from moik.algorithms.soo.code import distinct_indices
from moik.algorithms.soo.mtde import cauchy_scale_factors, lehmer_mean

MIN_POP = 4


def pair_rotation(d: int, theta: float, *, rng: np.random.Generator) -> np.ndarray:
    """The authors' orthogonal A: random coordinate pairs rotated by ``theta``."""
    A = np.eye(d)
    pairs = rng.permutation(d)
    for i in range(0, d - 1, 2):
        p, q = pairs[i], pairs[i + 1]
        A[p, p] = A[q, q] = math.sin(theta)
        A[p, q], A[q, p] = math.cos(theta), -math.cos(theta)
    return A


def spherical_step(Z, A, c, rd, *, rng: np.random.Generator) -> np.ndarray:
    """SS trial step ``c A B A^T z`` per row of ``Z`` (n, d)."""
    n, d = Z.shape
    Zr = Z @ A  # rows of (A^T z)^T
    B = rng.random((n, d)) < rd[:, None]
    B[np.arange(n), rng.integers(d, size=n)] = True
    return (c[:, None] * np.where(B, Zr, 0.0)) @ A.T


def planned_size(nfes: float, max_nfes: float, n_init: int) -> int:
    """Linear population size reduction from ``n_init`` to 4 over the budget."""
    s = min(nfes / max_nfes, 1.0)
    return max(int(round(MIN_POP * s + n_init * (1.0 - s))), MIN_POP)


class SASS(ArrayAlgorithm):
    """Self-adaptive spherical search (Kumar et al. 2020) with array state.

    Extra public arrays: ``shadow_X``, ``archive_X``, ``memory_c``, ``memory_rd``.

    Args:
        pop_size: Initial population size N_init (>= 4); None means 18 D.
        rd: Initial memory value of the rank ratio, in [0, 1] (Table 3: 0.5).
        c: Initial memory value of the step factor, in (0, 1] (Table 3: 0.7).
        Ar: Archive size as a multiple of N, in [0, 10] (Table 3: 1.4).
        Ms: Memory size, integer >= 1 (Table 3: 100).
        p_best: Share of the pbest pool in (0, 1] (authors' code: 0.11).
        max_iter: Iterations T used only when no n_eval budget is set (see above).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = MIN_POP

    def __init__(self, *, pop_size: int | None = None, rd: float = 0.5, c: float = 0.7,
                 Ar: float = 1.4, Ms: int = 100, p_best: float = 0.11,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=MIN_POP if pop_size is None else pop_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self._auto_size = pop_size is None
        self.rd = interval("rd", rd, 0.0, 1.0)
        self.c = interval("c", c, 0.0, 1.0, lo_open=True)
        self.Ar = interval("Ar", Ar, 0.0, 10.0)
        self.Ms = integer("Ms", Ms, minimum=1)
        self.p_best = interval("p_best", p_best, 0.0, 1.0, lo_open=True)

    def _setup(self, problem, **kwargs) -> None:
        if self._auto_size:
            self.pop_size = max(18 * problem.n_var, MIN_POP)
        super()._setup(problem, **kwargs)
        n0 = self.pop_size
        self.max_nfes = (self._max_evals if np.isfinite(self._max_evals) else
                         max((n0 - MIN_POP) * self.max_iter / math.log(n0 / MIN_POP), n0 + 1.0))

    def _initialize_state(self) -> None:
        n, d = self.X.shape
        self.shadow_X = uniform_population(n, self.xl, self.xu, rng=self.random_state)
        self.archive_X = np.empty((0, d))
        self.memory_c, self.memory_rd = np.full(self.Ms, self.c), np.full(self.Ms, self.rd)
        self._mem_pos = 0

    def _parameters(self, n: int):
        """L-SHADE sampling of c (Cauchy) and rd (normal) from random memory slots."""
        rng = self.random_state
        k = rng.integers(self.Ms, size=n)
        mu_rd = self.memory_rd[k]
        rd = np.clip(mu_rd + 0.1 * rng.standard_normal(n), 0.0, 1.0)
        rd[mu_rd == -1] = 0.0
        c = cauchy_scale_factors(self.memory_c[k], 0.1, rng=rng)
        return c, rd

    def _directions(self) -> np.ndarray:
        """Towards-rand for the better half, towards-pbest (with shadows) for the rest."""
        rng, X = self.random_state, self.X
        n = len(X)
        union = np.concatenate([X, self.archive_X])
        r3 = rng.permutation(n)
        while np.any(r3 == np.arange(n)):
            r3 = rng.permutation(n)
        me = np.arange(n)
        r1 = distinct_indices(n, 1, rng=rng, exclude=(me, r3))[0]
        r2 = distinct_indices(n, 1, rng=rng, pool=len(union), exclude=(me, r1, r3))[0]
        order = np.argsort(ranking_fitness(self.F, self.CV), kind="stable")
        p = max(int(round(self.p_best * n)), 2)
        pbest = X[order[rng.integers(p, size=n)]]
        rand_half = np.zeros(n, dtype=bool)
        rand_half[order[: n // 2]] = True
        Z_rand = X[r3] - X + X[r1] - union[r2]
        Z_best = pbest - X + X[r1] - self.shadow_X[r1]
        return np.where(rand_half[:, None], Z_rand, Z_best)

    def _generation(self) -> Step:
        rng = self.random_state
        n, d = self.X.shape
        self.shadow_X = self.shadow_X[rng.permutation(n)]
        c, rd = self._parameters(n)
        Z = self._directions()
        step = spherical_step(Z, pair_rotation(d, 1e-12, rng=rng), c, rd, rng=rng)
        Y = midpoint_repair(self.X + step, self.X, self.xl, self.xu)
        FY, CVY = yield Y
        win = is_better(FY, CVY, self.F, self.CV)
        if win.any():
            gain = self.F[win] - FY[win]
            if np.isfinite(gain).all() and gain.sum() > 0:
                j = self._mem_pos
                self.memory_c[j] = lehmer_mean(c[win], gain)
                terminal = rd[win].max() == 0 or self.memory_rd[j] == -1
                self.memory_rd[j] = -1 if terminal else lehmer_mean(rd[win], gain)
            self._archive(self.X[win])
            self.shadow_X[win] = self.X[win]
            self.X = np.where(win[:, None], Y, self.X)
            self.F = np.where(win, FY, self.F)
            if self.CV is not None:
                self.CV = np.where(win, CVY, self.CV)
        self._mem_pos = (self._mem_pos + 1) % self.Ms
        self._reduce(planned_size(self.n_received, self.max_nfes, self.pop_size))

    def _archive(self, X_old: np.ndarray) -> None:
        cap = int(round(self.Ar * len(self.X)))
        archive = np.unique(np.concatenate([self.archive_X, X_old]), axis=0)
        if len(archive) > cap:
            archive = archive[self.random_state.permutation(len(archive))[:cap]]
        self.archive_X = archive

    def _reduce(self, size: int) -> None:
        """Drop the worst agents down to ``size`` (survivors keep their order)."""
        if len(self.X) <= size:
            return
        keep = np.sort(np.argsort(ranking_fitness(self.F, self.CV), kind="stable")[:size])
        self.X, self.F, self.shadow_X = self.X[keep], self.F[keep], self.shadow_X[keep]
        if self.CV is not None:
            self.CV = self.CV[keep]
        cap, m = int(round(self.Ar * size)), len(self.archive_X)
        if m > cap:
            self.archive_X = self.archive_X[self.random_state.permutation(m)[:cap]]
