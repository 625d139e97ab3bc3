"""Pathfinder algorithm (PFA).

Yapici & Cetinkaya, "A new meta-heuristic optimizer: Pathfinder algorithm",
Applied Soft Computing 78, 545-568 (2019), DOI 10.1016/j.asoc.2019.03.012.
The update rules are cited by the paper's symbols (labels P1-P2, F1-F2 are
ours: the paper's text was not at hand to check its equation numbers):

- P1 (pathfinder): ``x_p(K+1) = x_p(K) + 2 r3 (x_p(K) - x_p(K-1)) + A``;
- P2: ``A = u2 exp(-2K/K_max)``;
- F1 (followers, i >= 2):
  ``x_i(K+1) = x_i(K) + R1 (x_j(K) - x_i(K)) + R2 (x_p(K) - x_i(K)) + eps``,
  ``R1 = alpha r1``, ``R2 = beta r2``;
- F2: ``eps = (1 - K/K_max) u1 D_ij``, ``D_ij = ||x_i - x_j||``;
- ``r1, r2, r3 ~ U(0, 1)`` and ``u1, u2 ~ U(-1, 1)`` per coordinate,
  ``alpha, beta ~ U(1, 2)`` once per iteration;
- the pathfinder moves first and is replaced if its move is better; then the
  followers move, each keeps its new position only if better, and the best
  member becomes the next pathfinder.

The population is kept sorted by fitness, so row 0 is the pathfinder.
Defaults: PFA has no tuning parameter (Table 3 lists none). Evaluations: N per
iteration (1 for the pathfinder, N-1 for the followers, in two batches).
``K``/``K_max`` are the base class's ``t``/``max_iter``.

Deviations and readings:
- ``x_j`` ("the j-th member") is a uniformly random other follower or the
  pathfinder (the paper does not fix j).
- ``x_p(K-1)`` is the pathfinder at the previous iteration; in the first
  iteration it equals ``x_p(K)``.
- Followers move all at once and toward the pathfinder after its move.
- Coordinates outside the box are clipped to the bounds.
- Constrained problems: feasibility-first comparisons (see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, greedy_memory, ranking_fitness


def pathfinder_move(xp, xp_prev, t: int, T: int, *, rng: np.random.Generator) -> np.ndarray:
    """P1-P2: the pathfinder's trial ``x_p + 2 r3 (x_p - x_p_prev) + u2 exp(-2t/T)``."""
    d = xp.size
    r3 = rng.random(d)
    A = rng.uniform(-1.0, 1.0, d) * math.exp(-2.0 * min(t / T, 1.0))
    return xp + 2.0 * r3 * (xp - xp_prev) + A


def follower_move(X, xp, t: int, T: int, alpha: float, beta: float, *,
                  rng: np.random.Generator) -> np.ndarray:
    """F1-F2: trials of the followers ``X[1:]`` of a herd ``X`` whose row 0 is the pathfinder.

    Returns:
        The n - 1 follower trials (not yet bounded).
    """
    n, d = X.shape
    i = np.arange(1, n)
    j = (i + rng.integers(1, n, size=n - 1)) % n  # any member but i
    Xi, Xj = X[i], X[j]
    R1 = alpha * rng.random((n - 1, d))
    R2 = beta * rng.random((n - 1, d))
    D = np.linalg.norm(Xi - Xj, axis=1)[:, None]
    eps = (1.0 - min(t / T, 1.0)) * rng.uniform(-1.0, 1.0, (n - 1, d)) * D  # F2
    return Xi + R1 * (Xj - Xi) + R2 * (xp - Xi) + eps  # F1


def sort_herd(X, F, CV):
    """Order the herd best first (feasibility-first); row 0 is the pathfinder."""
    order = np.argsort(ranking_fitness(F, CV), kind="stable")
    return X[order], F[order], (None if CV is None else CV[order])


class PFA(ArrayAlgorithm):
    """Pathfinder algorithm (Yapici & Cetinkaya 2019) with array state.

    ``X``/``F`` is the herd sorted best first (row 0: the pathfinder); extra
    public array ``xp_prev`` (the pathfinder at the previous iteration).

    Args:
        pop_size: Herd size N >= 2.
        max_iter: Schedule length K_max (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)

    def _initialize_state(self) -> None:
        self.X, self.F, self.CV = sort_herd(self.X, self.F, self.CV)
        self.xp_prev = self.X[0].copy()

    def _generation(self) -> Step:
        rng = self.random_state
        t, T = self.t, self.max_iter
        alpha, beta = rng.uniform(1.0, 2.0, 2)
        xp_old = self.X[0].copy()
        xp = clip_to_bounds(pathfinder_move(xp_old, self.xp_prev, t, T, rng=rng), self.xl,
                            self.xu)
        F, CV = yield xp[None]
        X, Fm, CVm = greedy_memory(xp[None], F, CV, self.X[:1], self.F[:1],
                                   None if self.CV is None else self.CV[:1])
        self.X = np.concatenate([X, self.X[1:]])
        self.F = np.concatenate([Fm, self.F[1:]])
        self.CV = None if CVm is None or self.CV is None else np.concatenate([CVm, self.CV[1:]])
        Y = follower_move(self.X, self.X[0], t, T, alpha, beta, rng=rng)
        Y = clip_to_bounds(Y, self.xl, self.xu)
        F, CV = yield Y
        CVf = None if self.CV is None else self.CV[1:]
        X, Fm, CVm = greedy_memory(Y, F, CV, self.X[1:], self.F[1:], CVf)
        self.X = np.concatenate([self.X[:1], X])
        self.F = np.concatenate([self.F[:1], Fm])
        self.CV = None if CVm is None or self.CV is None else np.concatenate([self.CV[:1], CVm])
        self.X, self.F, self.CV = sort_herd(self.X, self.F, self.CV)
        self.xp_prev = xp_old
