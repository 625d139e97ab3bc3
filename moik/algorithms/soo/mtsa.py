"""Modified tree-seed algorithm (MTSA), the I-BES paper's reference [43].

TSA: Kiran, "TSA: Tree-seed algorithm for continuous optimization", Expert
Systems with Applications 42, 6686-6698 (2015), DOI 10.1016/j.eswa.2015.04.055.
MTSA: Beskirli, Ozdemir & Temurtas, "A comparison of modified tree-seed
algorithm for high-dimensional numerical functions", Neural Computing and
Applications 32, 6877-6911 (2020), DOI 10.1007/s00521-019-04155-1.

TSA (Kiran's Eqs. 1-2): each tree T_i sows seeds; per coordinate j, with
probability ST ``S_j = T_ij + alpha (B_j - T_rj)`` (Eq. 1, B the best tree),
else ``S_j = T_ij + alpha (T_ij - T_rj)`` (Eq. 2), alpha uniform in [-1, 1],
T_r another tree; the best seed replaces its tree if it is better. MTSA's
change (its abstract): T_r is chosen by tournament selection instead of at
random, and the search tendency is tuned.

Defaults (I-BES paper, Table 1): Smax = 3, eps = 0.01. The MTSA paper itself
was not available here, so their roles are this module's reading, stated
plainly: ``s_max`` is the largest number of seeds per tree (each tree sows a
uniform random number of seeds in [1, s_max]), and ``eps`` is the tuned search
tendency ST (the probability of the best-guided Eq. 1). The tournament is
binary (the better of two random other trees). Evaluations: the number of
seeds, on average N (1 + s_max) / 2 = 2N per iteration. Coordinates are
clipped to the bounds (Kiran's code). Constrained problems: the tournament,
the best seed and its replacement of the tree are feasibility-first (Deb's
rules, as in Kiran's constrained TSA; see base.py).
"""

from __future__ import annotations

import numpy as np

from moik._validate import integer, interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    ranking_fitness,
)


def tournament_partners(owner: np.ndarray, rank: np.ndarray, *,
                        rng: np.random.Generator) -> np.ndarray:
    """Binary tournament: the better (lower ``rank``) of two random trees other than the owner."""
    n = len(rank)
    cand = rng.integers(n - 1, size=(2, len(owner)))
    cand += cand >= owner  # skip the owner itself
    return np.where(rank[cand[0]] <= rank[cand[1]], cand[0], cand[1])


def sow_seeds(T, owner, partner, best, *, ST: float, rng: np.random.Generator) -> np.ndarray:
    """Kiran's Eqs. 1-2: one seed per entry of ``owner`` (tree index) with its partner tree."""
    base, other = T[owner], T[partner]
    alpha = rng.uniform(-1.0, 1.0, base.shape)
    toward_best = rng.random(base.shape) < ST
    return np.where(toward_best, base + alpha * (best - other), base + alpha * (base - other))


def best_seed_per_tree(owner: np.ndarray, rank: np.ndarray, n: int) -> np.ndarray:
    """Index (into the seeds) of each tree's best seed; every tree has at least one."""
    order = np.lexsort((rank, owner))
    first = np.ones(len(order), dtype=bool)
    first[1:] = owner[order][1:] != owner[order][:-1]
    return order[first][:n]


class MTSA(ArrayAlgorithm):
    """Modified tree-seed algorithm with array state (``X``/``F``: the stand of trees).

    Args:
        pop_size: Number of trees N (>= 3).
        s_max: Largest number of seeds per tree, integer >= 1 (Table 1: 3).
        eps: Search tendency ST in [0, 1] (Table 1: 0.01).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    def __init__(self, *, pop_size: int = 150, s_max: int = 3, eps: float = 0.01,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.s_max = integer("s_max", s_max, minimum=1)
        self.eps = interval("eps", eps, 0.0, 1.0)

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1 + self.s_max) / 2.0

    def _generation(self) -> Step:
        rng, n = self.random_state, self.pop_size
        rank = ranking_fitness(self.F, self.CV)
        owner = np.repeat(np.arange(n), rng.integers(1, self.s_max + 1, size=n))
        partner = tournament_partners(owner, rank, rng=rng)
        S = sow_seeds(self.X, owner, partner, self.X[np.argmin(rank)], ST=self.eps, rng=rng)
        S = clip_to_bounds(S, self.xl, self.xu)
        F, CV = yield S
        pick = best_seed_per_tree(owner, ranking_fitness(F, CV), n)
        self.X, self.F, self.CV = greedy_memory(
            S[pick], F[pick], None if CV is None else CV[pick], self.X, self.F, self.CV)
