"""Multi-objective multi-verse optimizer (MOMVO).

Mirjalili, Jangir, Mirjalili, Saremi & Trivedi, "Optimization of problems with
multiple objectives using the multi-verse optimization algorithm",
Knowledge-Based Systems 134, 50-71 (2017), DOI 10.1016/j.knosys.2017.07.018,
with the operators of MVO (Mirjalili, Mirjalili & Hatamlou, Neural Computing
and Applications 27, 495-513 (2016), DOI 10.1007/s00521-015-1870-7, Eqs.
3.1-3.4), and Mirjalili's MOMVO.m (version 1.0; read in
github.com/Natee-Panagant/Comparative-study-of-truss-sizing-optimisation-problems-in-MATLAB,
``Algorithms/MOMVO.m``, and github.com/Zionist1923/MOMVO_Based_MMGEMS, ``MOMVO.m``; its
line-by-line port is ``momvo_reference`` in ``reference/__init__.py``):

- inflation rates: the universes are sorted on the first objective and
  normalised, ``NI = I / ||I||_2`` over the population (Eq. 3.1, MATLAB's
  ``normr``);
- white/black hole tunnels (Eq. 3.1): coordinate j of universe i is replaced,
  with probability ``NI_i`` (a fresh ``r1`` per coordinate), by coordinate j
  of a white hole universe drawn by MVO's roulette wheel on ``-I`` (see
  :func:`mvo_roulette`);
- wormholes (Eq. 3.2): then, with probability WEP, the coordinate jumps to
  ``best_j +/- TDR ((ub_j - lb_j) r + lb_j)``; ``WEP = WEP_min + t (WEP_max -
  WEP_min) / T`` (Eq. 3.3), ``TDR = 1 - t^(1/p) / T^(1/p)``, p = 6 (Eq. 3.4);
- the best universe is one archive member per iteration, drawn by roulette on
  1 / crowding count (:meth:`CrowdingArchive.mirjalili`: radius (max - min) / 20);
- elitism: the universe best on the first objective is kept unchanged;
- positions clipped to the bounds.

Defaults (EOSMA paper, Yin et al. 2022, Table 4): WEP_min = 0.2, WEP_max = 1,
p = 6 (MVO); N = archive = 100 (Table 8: T = 1000). Evaluations per
iteration: N - 1 (the kept elite is not evaluated again; MOMVO.m re-evaluates it).

Deviations and readings:
- MOMVO.m sorts the (N, M) objective matrix column by column and reads the
  result through linear indexing: the universe order is that of the first
  objective, while ``normr`` mixes the independently sorted columns. Here the
  first objective is used throughout (order, NI and roulette), which is what
  the code does for one objective (MVO.m).
- MVO.m and MOMVO.m compare the NI of the i-th *sorted* universe with the i-th
  *unsorted* universe; here each universe uses its own NI (the paper's
  ``NI(U_i)``).
- NI assumes non-negative rates (as MVO); with negative values of the first
  objective the tunnel probability of those universes is 0.
- Constraints (not in the paper): the inflation rate of a universe is its first
  objective if feasible, else the worst feasible value plus its violation
  (:func:`~moik.algorithms.mechanics.ranking_fitness`), so feasible universes sort
  first; the archive uses constraint-domination.
- MOMVO.m's RouletteWheelSelection on the (N, M) matrix ``-sorted_Inflation_rates``
  scans the cumulative sums of the first column against ``rand`` times the total of
  the *last* column; here the first objective's own total. With non-negative rates
  both always return the first (best) universe (the cumulative sums only fall), so
  the white hole is the elite; they differ only where rates are negative.
- MOMVO.m writes the elite into row 1 of the *unsorted* universes before the archive
  update, so the archive receives the elite's position with the objectives of the
  universe it replaced; that universe is lost, and the elite is moved in its own row
  as well (rows 2..N move). Here the archive gets evaluated pairs only, and the N - 1
  universes other than the elite move.
- Random streams differ from MATLAB's; only the distributions match.

Beside the port on the same problems and budget (``studies/moo_quality.py``, section
``reference``), moik's MOMVO and MOMVO.m give the same picture, neither consistently ahead.

While no feasible point was seen, the archive keeps its capacity of least infeasible
rows (a moik extension, :mod:`moik.algorithms.archive.base`; a strict
constraint-domination filter would keep only the least infeasible row, and every leader
would be it), and until a feasible point is found a companion DE population searches
for one (a moik extension, :mod:`moik.algorithms.moo.feasibility_search`). Infeasible
output on pymoo's MW and CTP problems with and without it, method or handling:
docs/results/constrained-moo.md (``studies/constrained_moo.py``).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.mechanics import clip_to_bounds, ranking_fitness
from moik.algorithms.moo.around_best import around_best
from moik.algorithms.moo.base import MOArrayAlgorithm, Step


def mvo_schedule(t: int, T: int, wep_min: float, wep_max: float, p: float):
    """Eqs. 3.3-3.4: ``(WEP, TDR)`` at iteration t."""
    return wep_min + t * (wep_max - wep_min) / T, 1.0 - t ** (1.0 / p) / T ** (1.0 / p)


def mvo_roulette(weights: np.ndarray, u: np.ndarray) -> np.ndarray:
    """MVO.m's RouletteWheelSelection for each draw ``u`` (index 0 when it returns -1).

    The first index whose cumulative weight exceeds ``u * sum(weights)``. On
    MVO's weights ``-I`` with non-negative rates I the cumulative sums only fall,
    so it always returns 0 (the best universe), as the reference code does.
    """
    acc = np.cumsum(weights)
    hit = acc[None, :] > (u * acc[-1])[:, None]
    return np.where(hit.any(axis=1), hit.argmax(axis=1), 0)


def tunnels(X: np.ndarray, NI: np.ndarray, X_sorted: np.ndarray, I_sorted: np.ndarray, *,
            rng: np.random.Generator) -> np.ndarray:
    """Eq. 3.1: coordinates of ``X`` copied from roulette-chosen white holes.

    Args:
        X: Universes to update (n, d).
        NI: Their normalised inflation rates (n,): the probability of a tunnel
            for each coordinate.
        X_sorted: All universes sorted by inflation rate (N, d), the white holes.
        I_sorted: Their inflation rates, ascending (N,).
        rng: Random generator.

    Returns:
        Array (n, d).
    """
    n, d = X.shape
    swap = rng.random((n, d)) < NI[:, None]
    white = mvo_roulette(-I_sorted, rng.random(n * d)).reshape(n, d)
    return np.where(swap, X_sorted[white, np.arange(d)], X)


class MOMVO(MOArrayAlgorithm):
    """MOMVO (Mirjalili et al. 2017) with array state; ``res.X``/``res.F`` = the archive.

    Extra public array: ``best`` (the best universe of the last iteration).

    Args:
        pop_size: Number of universes N (paper setting: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper setting: 100).
        wep_min: Minimum wormhole existence probability in [0, 1] (Table 4: 0.2).
        wep_max: Maximum wormhole existence probability in [0, 1] (Table 4: 1).
        p: Exploitation accuracy of TDR, > 0 (MVO: 6).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 wep_min: float = 0.2, wep_max: float = 1.0, p: float = 6.0,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.wep_min = interval("wep_min", wep_min, 0.0, 1.0)
        self.wep_max = interval("wep_max", wep_max, self.wep_min, 1.0)
        self.p = interval("p", p, 0.0, 100.0, lo_open=True)

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return CrowdingArchive.mirjalili(capacity)

    def _evals_per_iteration(self) -> float:
        return self.pop_size - 1.0

    def _generation(self) -> Step:
        rng, A = self.random_state, self.pareto_archive
        wep, tdr = mvo_schedule(self.t, self.max_iter, self.wep_min, self.wep_max, self.p)
        self.best = A.X[A.leaders(1, rng=rng)[0]]
        I = ranking_fitness(self.F[:, 0], self.CV)  # noqa: E741
        order = np.argsort(I, kind="stable")
        X_s, F_s, I_s = self.X[order], self.F[order], I[order]
        CV_s = None if self.CV is None else self.CV[order]
        norm = np.sqrt(np.sum(I_s**2))
        NI = I_s / norm if norm > 0 else np.zeros_like(I_s)  # Eq. 3.1, normr
        moved = tunnels(X_s[1:], NI[1:], X_s, I_s, rng=rng)  # elite X_s[0] is kept
        n, d = moved.shape
        hole = rng.random((n, d)) < wep  # Eq. 3.2
        moved = np.where(hole, around_best(self.best, tdr, self.xl, self.xu, (n, d), rng=rng),
                         moved)
        X = clip_to_bounds(moved, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F = np.concatenate([X_s[:1], X]), np.concatenate([F_s[:1], F])
        self.CV = None if CV is None or CV_s is None else np.concatenate([CV_s[:1], CV])
