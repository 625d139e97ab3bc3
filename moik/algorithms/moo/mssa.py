"""Multi-objective salp swarm algorithm (MSSA).

Mirjalili, Gandomi, Mirjalili, Saremi, Faris & Mirjalili, "Salp Swarm
Algorithm: A bio-inspired optimizer for engineering design problems", Advances
in Engineering Software 114, 163-191 (2017), DOI
10.1016/j.advengsoft.2017.07.002, Section 3 (SSA, Eqs. 3.1-3.4) and Section 4
(MSSA), and Mirjalili's MSSA.m (version 1.0):

- the food source F is one archive member per iteration, drawn by roulette on
  1 / crowding count (the least crowded regions are favoured);
- leaders (Eq. 3.1): ``x_j = F_j +/- c1 ((ub_j - lb_j) c2 + lb_j)``, sign ``+``
  when ``c3 < 0.5``; ``c2, c3 ~ U(0, 1)`` per coordinate;
- Eq. 3.2: ``c1 = 2 exp(-(4 t / T)^2)`` with ``t = 1 .. T``;
- followers (Eq. 3.4): ``x_i = (x_i + x_{i-1}) / 2``, in salp order, with the
  already moved predecessor (the chain);
- positions clipped to the bounds; every evaluated salp is offered to the
  archive (:meth:`CrowdingArchive.mirjalili`: radius (max - min) / 20, removal
  by roulette on the count).

Defaults (EOSMA paper, Yin et al. 2022, Table 4): "parameter less"; N =
archive = 100 (Table 8: T = 1000). Evaluations per iteration: N.

Deviations and readings:
- Leaders are the first half of the chain (``i <= N/2``, as MSSA.m); the paper's
  text has a single leader (the first salp).
- Eq. 3.1 is printed with ``c3 >= 0`` / ``c3 < 0`` for ``c3 ~ U(0, 1)``, which
  would always take ``+``; the code's threshold 0.5 is used.
- Random streams differ from MATLAB's; only the distributions match.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.around_best import around_best
from moik.algorithms.moo.base import MOArrayAlgorithm, Step


def ssa_c1(t: int, T: int) -> float:
    """Eq. 3.2: ``c1 = 2 exp(-(4 t / T)^2)``."""
    return 2.0 * float(np.exp(-((4.0 * t / T) ** 2)))


def salp_chain(X: np.ndarray, food: np.ndarray, c1: float, xl: np.ndarray, xu: np.ndarray,
               *, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 3.1 and 3.4: move the leaders (first half) around the food, then the followers.

    Args:
        X: Salp positions (N, d), in chain order.
        food: Food source (d,).
        c1: Eq. 3.2 coefficient.
        xl: Lower bounds (d,).
        xu: Upper bounds (d,).
        rng: Random generator.

    Returns:
        New positions (N, d) within the bounds (leaders clipped, followers are
        midpoints of points within them).
    """
    n, d = X.shape
    n_lead = max(n // 2, 1)
    out = np.empty_like(X)
    lead = around_best(food, c1, xl, xu, (n_lead, d), rng=rng)  # Eq. 3.1
    out[:n_lead] = clip_to_bounds(lead, xl, xu)  # MSSA.m clips each salp as it moves
    prev = out[n_lead - 1]
    for i in range(n_lead, n):  # Eq. 3.4, each follower after its moved predecessor
        prev = out[i] = (X[i] + prev) / 2.0
    return out


class MSSA(MOArrayAlgorithm):
    """MSSA (Mirjalili et al. 2017) with array state; ``res.X``/``res.F`` = the archive.

    Extra public array: ``food`` (the food source of the last iteration).

    Args:
        pop_size: Number of salps N (paper setting: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper setting: 100).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return CrowdingArchive.mirjalili(capacity)

    def _generation(self) -> Step:
        rng, A = self.random_state, self.pareto_archive
        self.food = A.X[A.leaders(1, rng=rng)[0]]
        c1 = ssa_c1(self.t, self.max_iter)
        X = salp_chain(self.X, self.food, c1, self.xl, self.xu, rng=rng)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
