"""Multi-objective dragonfly algorithm (MODA).

Mirjalili, "Dragonfly algorithm: a new meta-heuristic optimization technique
for solving single-objective, discrete, and multi-objective problems", Neural
Computing and Applications 27, 1053-1073 (2016), DOI 10.1007/s00521-015-1920-1,
Section 3 (Eqs. 3.1-3.10) and Section 3.3 (MODA), and Mirjalili's MODA.m
(version 1.0):

- neighbours of dragonfly i: every j with ``|X_jk - X_ik| <= r_k`` and
  ``X_jk != X_ik`` in every coordinate k, ``r = (ub - lb) (1/4 + 2 t / T)``;
- separation ``S = -sum_j (X_j - X)`` (Eq. 3.1), alignment ``A`` = mean of the
  neighbours' steps (Eq. 3.2), cohesion ``C`` = mean of their positions minus X
  (Eq. 3.3), food ``F = X+ - X`` (Eq. 3.4), enemy ``E = X- + X`` (Eq. 3.5, as
  printed), each used only with more than one neighbour (F, E only when the
  food / enemy lies within the radius in every coordinate);
- weights: ``w`` from ``w_start`` to ``w_end`` linearly, ``s = a = c = e =
  max(0.1 - 0.2 t / T, 0)`` (divided by t after 3T/4), ``f = 2 r`` (one draw
  per iteration);
- food within the radius: ``dX = s S + a A + c C + f F + e E + w dX`` (Eq. 3.6),
  ``X += dX`` (Eq. 3.7); food outside with neighbours:
  ``dX = w dX + r A + r C + r S`` (fresh ``r ~ U(0, 1)`` per term and coordinate);
  without neighbours: Levy flight ``X += Levy(d) X`` (Eq. 3.8, Mantegna,
  beta = 1.5, scale 0.01) and ``dX = 0``; steps clamped to ``+/- V_max``;
- food = archive member by roulette on 1 / crowding count, enemy by roulette on
  the count (most crowded), one of each per iteration
  (:meth:`CrowdingArchive.mirjalili`: radius (max - min) / 20);
- positions clipped to the bounds.

Defaults (EOSMA paper, Yin et al. 2022, Table 4): inertia weight w from 0.9 to
0.7 (the row printed "0.9-0.7"; MODA.m decreases it from 0.9 to 0.2); N =
archive = 100 (Table 8: T = 1000). Evaluations per iteration: N.

Deviations and readings:
- ``V_max = (ub - lb) / 10`` per coordinate (MODA.m uses the first
  coordinate's range for all).
- Steps start uniform in ``[lb, ub]`` (MODA.m's ``initialization``).
- MODA.m's wrap-around of out-of-bound coordinates before the move never
  fires (positions are clipped at the end of every iteration) and is omitted.
- Neighbour distances are computed from the positions at the start of the
  iteration for everyone at once (MODA.m moves dragonflies one by one, so later
  ones see some already moved neighbours).
- Random streams differ from MATLAB's; only the distributions match.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.archive.base import roulette
from moik.algorithms.mechanics import clip_to_bounds, mantegna_levy
from moik.algorithms.moo.base import MOArrayAlgorithm, Step


def levy(shape: tuple[int, ...], *, rng: np.random.Generator, beta: float = 1.5) -> np.ndarray:
    """Eqs. 3.8-3.9: Mantegna Levy steps times 0.01 (MODA.m's Levy.m)."""
    return 0.01 * mantegna_levy(shape, beta, rng=rng)


def swarm_weights(t: int, T: int, w_start: float, w_end: float) -> tuple[float, float]:
    """Inertia ``w`` and the common weight of s, a, c, e at iteration t (MODA.m)."""
    w = w_start - t * (w_start - w_end) / T
    my_c = max(0.1 - t * 0.1 / (T / 2), 0.0)
    return w, (my_c if t < 3 * T / 4 else my_c / t)


def dragonfly_step(X, dX, food, enemy, r, w: float, k: float, f: float, vmax, *,
                   rng: np.random.Generator):
    """Eqs. 3.1-3.8 for every dragonfly at once.

    Args:
        X: Positions (N, d).
        dX: Steps (N, d).
        food: Food source (d,).
        enemy: Enemy (d,).
        r: Neighbourhood radius per coordinate (d,).
        w: Inertia weight.
        k: Weight of separation, alignment, cohesion and enemy.
        f: Food weight.
        vmax: Step clamp per coordinate (d,).
        rng: Random generator.

    Returns:
        New positions (not clipped) and steps, each (N, d).
    """
    n, d = X.shape
    diff = X[None, :, :] - X[:, None, :]  # diff[i, j] = X_j - X_i
    nb = np.all((np.abs(diff) <= r) & (diff != 0), axis=2)
    count = nb.sum(axis=1)[:, None]
    many = count > 1
    safe = np.maximum(count, 1)
    S = np.where(many, -(nb[:, :, None] * diff).sum(axis=1), 0.0)  # Eq. 3.1
    A = np.where(many, (nb @ dX) / safe, dX)  # Eq. 3.2
    C = np.where(many, (nb @ X) / safe - X, 0.0)  # Eq. 3.3
    near_food = np.all(np.abs(food - X) <= r, axis=1)[:, None]
    F = np.where(near_food, food - X, 0.0)  # Eq. 3.4
    E = np.where(np.all(np.abs(enemy - X) <= r, axis=1)[:, None], enemy + X, 0.0)  # Eq. 3.5
    swarm = k * S + k * A + k * C + f * F + k * E + w * dX  # Eq. 3.6
    explore = w * dX + rng.random((n, d)) * A + rng.random((n, d)) * C + rng.random((n, d)) * S
    new_dX = np.clip(np.where(near_food, swarm, explore), -vmax, vmax)
    lone = ~near_food[:, 0] & ~many[:, 0]
    X_new = X + new_dX  # Eq. 3.7
    X_new[lone] = X[lone] + levy((int(lone.sum()), d), rng=rng) * X[lone]  # Eq. 3.8
    new_dX[lone] = 0.0
    return X_new, new_dX


class MODA(MOArrayAlgorithm):
    """MODA (Mirjalili 2016) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays: ``dX`` (step vectors), ``food`` and ``enemy`` of the
    last iteration.

    Args:
        pop_size: Number of dragonflies N (paper setting: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper setting: 100).
        w_start: Inertia weight at t = 0, in [0, 1] (Table 4: 0.9).
        w_end: Inertia weight at t = T, in [0, 1] (Table 4: 0.7; MODA.m: 0.2).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 w_start: float = 0.9, w_end: float = 0.7, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.w_start = interval("w_start", w_start, 0.0, 1.0)
        self.w_end = interval("w_end", w_end, 0.0, 1.0)

    pareto_archive: CrowdingArchive

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return CrowdingArchive.mirjalili(capacity)

    def _initialize_state(self) -> None:
        width = self.xu - self.xl
        self.dX = self.xl + self.random_state.random(self.X.shape) * width
        self.vmax = width / 10.0

    def _generation(self) -> Step:
        rng, A, T = self.random_state, self.pareto_archive, self.max_iter
        r = (self.xu - self.xl) * (0.25 + 2.0 * self.t / T)
        w, k = swarm_weights(self.t, T, self.w_start, self.w_end)
        f = 2.0 * rng.random()
        self.food = A.X[A.leaders(1, rng=rng)[0]]
        self.enemy = A.X[roulette(A.counts, 1, rng)[0]]  # the most crowded are likelier
        X, self.dX = dragonfly_step(self.X, self.dX, self.food, self.enemy, r, w, k, f,
                                    self.vmax, rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
