"""Hybrid particle swarm optimization and gravitational search (PSOGSA).

Mirjalili & Hashim, "A new hybrid PSOGSA algorithm for function optimization",
2010 International Conference on Computer and Information Application (ICCIA),
374-377, DOI 10.1109/ICCIA.2010.6141614. The paper combines GSA's acceleration
(Rashedi, Nezamabadi-pour & Saryazdi, Information Sciences 179, 2232-2248
(2009), DOI 10.1016/j.ins.2009.03.004) with PSO's social term:

- GSA masses: ``m_i = (f_i - worst) / (best - worst)``, ``M_i = m_i / sum_j m_j``
  (all masses 1/N when every f is equal);
- gravitational constant ``G(t) = G0 exp(-alpha t/T)``;
- force ``F_ij = G M_i M_j (x_j - x_i) / (R_ij + eps)`` with the Euclidean
  distance ``R_ij``, total ``F_i = sum_{j != i} rand_j F_ij``;
- acceleration ``ac_i = F_i / M_i``;
- PSOGSA velocity ``V = w V + c1' rand ac + c2' rand (gbest - X)`` and position
  ``X = X + V``.

Defaults (EOSMA paper, Table 3): w from 1 to 0 (linearly, ``w = 1 - t/T``),
c1'=0.5, c2'=1.5, G0=1, alpha=23. Evaluations: N per iteration. gbest is the
best position found so far; velocities start at zero.

Deviations (choices the paper leaves open):
- ``rand`` in the velocity update is drawn per coordinate; ``rand_j`` in the
  total force per pair (i, j).
- ``eps`` is the machine epsilon.
- Positions leaving the box are clipped to the bounds (the paper has no bound
  handling); velocities are not clamped.
- Constrained problems: masses use the feasibility-first ranking value
  (mechanics.ranking_fitness) and gbest the feasibility-first best.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, ranking_fitness

EPS = np.finfo(float).eps


def gsa_masses(S: np.ndarray) -> np.ndarray:
    """GSA normalized masses from fitness values ``S`` (minimization)."""
    best, worst = S.min(), S.max()
    if best == worst:
        return np.full(len(S), 1.0 / len(S))
    m = (S - worst) / (best - worst)
    return m / m.sum()


def gsa_acceleration(X, M, G: float, *, rng: np.random.Generator) -> np.ndarray:
    """GSA acceleration ``F_i / M_i`` with randomly weighted pair forces."""
    n = len(X)
    diff = X[None, :, :] - X[:, None, :]  # x_j - x_i at [i, j]
    R = np.sqrt((diff * diff).sum(axis=2))
    w = rng.random((n, n)) * (G * M[:, None] * M[None, :] / (R + EPS))
    np.fill_diagonal(w, 0.0)
    force = np.einsum("ij,ijd->id", w, diff)
    with np.errstate(divide="ignore", invalid="ignore"):
        acc = force / M[:, None]
    return np.where(M[:, None] > 0, acc, 0.0)


def psogsa_velocity(V, X, acc, g, *, w: float, c1: float, c2: float,
                    rng: np.random.Generator) -> np.ndarray:
    """PSOGSA velocity: inertia, GSA acceleration and the pull toward gbest."""
    return w * V + c1 * rng.random(X.shape) * acc + c2 * rng.random(X.shape) * (g - X)


class PSOGSA(ArrayAlgorithm):
    """Hybrid PSO-GSA (Mirjalili & Hashim 2010) with array state.

    Extra public array: ``V`` (velocities). ``X``/``F`` is the current swarm.

    Args:
        pop_size: Number of agents N.
        w_start: Inertia weight at t = 0, in [0, 1.5] (Table 3: 1).
        w_end: Inertia weight at t = T, in [0, 1.5] (Table 3: 0).
        c1: Weight of the GSA acceleration, in [0, 4] (Table 3: 0.5).
        c2: Weight of the gbest pull, in [0, 4] (Table 3: 1.5).
        G0: Initial gravitational constant, > 0 (Table 3: 1).
        alpha: Decay rate of G, >= 0 (Table 3: 23).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 50, w_start: float = 1.0, w_end: float = 0.0,
                 c1: float = 0.5, c2: float = 1.5, G0: float = 1.0, alpha: float = 23.0,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.w_start = interval("w_start", w_start, 0.0, 1.5)
        self.w_end = interval("w_end", w_end, 0.0, 1.5)
        self.c1 = interval("c1", c1, 0.0, 4.0)
        self.c2 = interval("c2", c2, 0.0, 4.0)
        self.G0 = interval("G0", G0, 0.0, np.inf, lo_open=True, hi_open=True)
        self.alpha = interval("alpha", alpha, 0.0, 100.0)

    def _initialize_state(self) -> None:
        self.V = np.zeros_like(self.X)

    def _generation(self) -> Step:
        rng = self.random_state
        s = min(self.t / self.max_iter, 1.0)
        G = self.G0 * np.exp(-self.alpha * s)
        w = self.w_start + (self.w_end - self.w_start) * s
        acc = gsa_acceleration(self.X, gsa_masses(ranking_fitness(self.F, self.CV)), G, rng=rng)
        self.V = psogsa_velocity(self.V, self.X, acc, self.best_x, w=w, c1=self.c1, c2=self.c2,
                                 rng=rng)
        X = clip_to_bounds(self.X + self.V, self.xl, self.xu)
        self.X = X
        self.F, self.CV = yield X
