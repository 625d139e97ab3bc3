"""Multi-objective ant lion optimizer (MOALO).

Mirjalili, Jangir & Saremi, "Multi-objective ant lion optimizer: a
multi-objective optimization algorithm for solving engineering problems",
Applied Intelligence 46, 79-95 (2017), DOI 10.1007/s10489-016-0825-8, with the
operators of ALO (Mirjalili, Advances in Engineering Software 83, 80-98 (2015),
DOI 10.1016/j.advengsoft.2015.01.010, Eqs. 2.1-2.13), and Mirjalili's MALO.m /
Random_walk_around_antlion.m (version 1.0):

- random walk (Eq. 2.1): ``X = [0, cumsum(2 r(t) - 1)]`` over T steps, one
  walk per coordinate, ``r(t) = 1`` with probability 1/2;
- trapping (Eqs. 2.10-2.11): the bounds shrink to ``lb / I``, ``ub / I`` with
  ``I = 1 + 10^w t / T`` (w = 2, 3, 4, 5, 6 once t exceeds 0.1, 0.5, 0.75,
  0.9, 0.95 T; I = 1 before 0.1 T), then move around the antlion (Eqs.
  2.8-2.9): ``c = antlion + lb / I`` or ``antlion - lb / I`` (one coin),
  ``d = antlion + ub / I`` or ``antlion - ub / I`` (another coin);
- min-max normalisation of the walk into ``[c, d]`` (Eq. 2.7), read at the
  current iteration (step ``t - 1`` of the walk);
- Eq. 2.13: ``ant = (R_A + R_E) / 2``, walks around the antlion and the elite;
- the elite is one archive member per iteration, the antlion one per ant,
  both by roulette on 1 / crowding count
  (:meth:`CrowdingArchive.mirjalili`: radius (max - min) / 20);
- positions clipped to the bounds.

Defaults (EOSMA paper, Yin et al. 2022, Table 4): "parameter less"; N =
archive = 100 (Table 8: T = 1000). Evaluations per iteration: N.

Deviations and readings:
- Antlion: the paper selects it from the archive by roulette wheel on the
  crowding (``antlion="roulette"``, the default); MALO.m uses the first archive
  member for every ant (``antlion="first"``). Both rules are measured side by side in
  the ``moo-suite`` experiment (rows ``moalo`` and ``moalo-first``; the line-by-line port
  of MALO.m in ``studies/moo_quality.py``'s reference table): MALO.m's rule is the
  better one on DTLZ2, the paper's on ZDT1 with 30 variables, and both stay behind
  uniform random sampling on DTLZ2, as the port does: a weakness of the method.
- ``I = 1 + 10^w t / T`` as in MALO.m (ALO's paper prints ``I = 10^w t / T``).
- Walks are generated in full (T steps per coordinate, two per ant) as in the
  code, since the min and max of the whole walk set the scale: O(N d T) work
  per iteration, vectorized.
- Random streams differ from MATLAB's; only the distributions match.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik._validate import choice
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step

_STAGES = ((0.95, 6), (0.9, 5), (0.75, 4), (0.5, 3), (0.1, 2))
ANTLION_RULES = ("roulette", "first")


def shrink_ratio(t: int, T: int) -> float:
    """The ratio I of Eqs. 2.10-2.11 (MALO.m): ``1 + 10^w t / T``, or 1 early on."""
    for frac, w in _STAGES:
        if t > frac * T:
            return 1.0 + 10.0**w * t / T
    return 1.0


def walk_at(n: int, T: int, t: int, *, rng: np.random.Generator) -> np.ndarray:
    """Eqs. 2.1 and 2.7 on [0, 1]: each of ``n`` walks of T steps, min-max scaled, at step t-1.

    Returns:
        Array (n,) in [0, 1]: ``(X[t-1] - min X) / (max X - min X)``.
    """
    bits = np.unpackbits(rng.integers(0, 256, size=(n, (T + 7) // 8), dtype=np.uint8),
                         axis=1, count=T)
    X = np.zeros((n, T + 1), dtype=np.int32)
    np.cumsum(2 * bits.astype(np.int32) - 1, axis=1, out=X[:, 1:])  # Eq. 2.1
    lo, hi = X.min(axis=1), X.max(axis=1)
    k = min(max(t - 1, 0), T)
    return (X[:, k] - lo) / (hi - lo)


def walk_around(centres: np.ndarray, t: int, T: int, xl: np.ndarray, xu: np.ndarray,
                *, rng: np.random.Generator) -> np.ndarray:
    """Random walks around each row of ``centres`` (Eqs. 2.7-2.11), read at iteration t.

    Args:
        centres: Antlions (n, d).
        t: Current iteration (1-based).
        T: Number of iterations (walk length).
        xl: Lower bounds (d,).
        xu: Upper bounds (d,).
        rng: Random generator.

    Returns:
        Array (n, d).
    """
    n, d = centres.shape
    I = shrink_ratio(t, T)  # noqa: E741
    coins = rng.random((n, 2))
    c = np.where(coins[:, :1] < 0.5, centres + xl / I, centres - xl / I)  # Eq. 2.8
    e = np.where(coins[:, 1:] >= 0.5, centres + xu / I, centres - xu / I)  # Eq. 2.9
    u = walk_at(n * d, T, t, rng=rng).reshape(n, d)
    return u * (e - c) + c  # Eq. 2.7


class MOALO(MOArrayAlgorithm):
    """MOALO (Mirjalili et al. 2017) with array state; ``res.X``/``res.F`` = the archive.

    Extra public array: ``elite`` (the elite of the last iteration).

    Args:
        pop_size: Number of ants N (paper setting: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper setting: 100).
        antlion: ``"roulette"`` (one archive member per ant by roulette on 1 / count,
            the paper) or ``"first"`` (the first archive member for every ant, MALO.m).
        max_iter: Schedule length T, also the walk length (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 antlion: str = "roulette", max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.antlion = choice("antlion", antlion, ANTLION_RULES)

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return CrowdingArchive.mirjalili(capacity)

    def _generation(self) -> Step:
        rng, A, n, T = self.random_state, self.pareto_archive, self.pop_size, self.max_iter
        self.elite = A.X[A.leaders(1, rng=rng)[0]]
        antlions = (A.X[A.leaders(n, rng=rng)] if self.antlion == "roulette"
                    else np.repeat(A.X[:1], n, axis=0))
        R_A = walk_around(antlions, self.t, T, self.xl, self.xu, rng=rng)
        R_E = walk_around(np.broadcast_to(self.elite, antlions.shape), self.t, T,
                          self.xl, self.xu, rng=rng)
        X = clip_to_bounds((R_A + R_E) / 2.0, self.xl, self.xu)  # Eq. 2.13
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
