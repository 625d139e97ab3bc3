"""Multi-objective dragonfly algorithm (MODA).

Mirjalili, "Dragonfly algorithm: a new meta-heuristic optimization technique
for solving single-objective, discrete, and multi-objective problems", Neural
Computing and Applications 27, 1053-1073 (2016), DOI 10.1007/s00521-015-1920-1,
Section 3 (Eqs. 3.1-3.10) and Section 3.3 (MODA), and Mirjalili's MODA.m
(version 1.0):

- the dragonflies move one after another, in place, as in MODA.m's loop: dragonfly i
  finds its neighbours among the current positions (those of dragonflies 0..i-1
  already moved and clipped in this iteration, the others not yet), averages the
  neighbours' steps as they are at that moment (the moved ones' new steps), then
  moves and is clipped to the bounds before dragonfly i + 1 looks
  (:func:`dragonflies_in_turn`, compiled);
- neighbours of dragonfly i: every j with ``|X_jk - X_ik| <= r_k`` and
  ``X_jk != X_ik`` in every coordinate k, ``r = (ub - lb) (1/4 + 2 t / T)``;
- separation ``S = -sum_j (X_j - X)`` (Eq. 3.1), alignment ``A`` = mean of the
  neighbours' steps (Eq. 3.2), cohesion ``C`` = mean of their positions minus X
  (Eq. 3.3), food ``F = X+ - X`` (Eq. 3.4), enemy ``E = X- + X`` (Eq. 3.5, as
  printed), each used only with more than one neighbour (F, E only when the
  food / enemy lies within the radius in every coordinate, measured from dragonfly
  i's position before its move);
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
- each moved position clipped to the bounds (the last operation of a dragonfly's turn).

Defaults (EOSMA paper, Yin et al. 2022, Table 4): inertia weight w from 0.9 to
0.7 (the row printed "0.9-0.7"; MODA.m decreases it from 0.9 to 0.2); N =
archive = 100 (Table 8: T = 1000). Evaluations per iteration: N.

Deviations and readings:
- ``V_max = (ub - lb) / 10`` per coordinate (MODA.m uses the first
  coordinate's range for all).
- Steps start uniform in ``[lb, ub]`` (MODA.m's ``initialization``).
- MODA.m's wrap-around of out-of-bound coordinates before the move never
  fires (every position is clipped at the end of its move, and initial points lie
  within the bounds) and is omitted.
- Random numbers are drawn per iteration before the moves, on the algorithm's
  Generator: the three uniforms of the exploring step (3, N, d), then a Levy step
  (N, d) for every dragonfly, whichever branch each takes (MODA.m draws only those
  it uses; drawing them all keeps the compiled loop free of random draws and the
  Levy step in one implementation, :func:`~moik.algorithms.mechanics.mantegna_levy`).
  Random streams differ from MATLAB's; only the distributions match.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit, kernel_array
from moik._validate import interval
from moik.algorithms.archive import ArchiveBase, CrowdingArchive
from moik.algorithms.archive.base import roulette
from moik.algorithms.mechanics import mantegna_levy
from moik.algorithms.moo.base import MOArrayAlgorithm, Step


def levy(shape: tuple[int, ...], *, rng: np.random.Generator, beta: float = 1.5) -> np.ndarray:
    """Eqs. 3.8-3.9: Mantegna Levy steps times 0.01 (MODA.m's Levy.m)."""
    return 0.01 * mantegna_levy(shape, beta, rng=rng)


def swarm_weights(t: int, T: int, w_start: float, w_end: float) -> tuple[float, float]:
    """Inertia ``w`` and the common weight of s, a, c, e at iteration t (MODA.m)."""
    w = w_start - t * (w_start - w_end) / T
    my_c = max(0.1 - t * 0.1 / (T / 2), 0.0)
    return w, (my_c if t < 3 * T / 4 else my_c / t)


@jit
def dragonflies_in_turn(X, dX, food, enemy, r, w: float, k: float, f: float, vmax, xl, xu,
                        U, L):
    """Eqs. 3.1-3.8 for dragonfly 0, 1, ..., N - 1 in turn, in place (MODA.m's loop).

    Dragonfly i sees the positions and steps of the dragonflies before it as already
    moved (and clipped) in this iteration, those after it as they were.

    Args:
        X: Positions (N, d), overwritten with the new (clipped) positions.
        dX: Steps (N, d), overwritten with the new steps.
        food: Food source (d,). enemy: Enemy (d,).
        r: Neighbourhood radius per coordinate (d,).
        w: Inertia weight. k: Weight of separation, alignment, cohesion and enemy.
        f: Food weight. vmax: Step clamp per coordinate (d,). xl, xu: Bounds (d,).
        U: Uniform numbers (3, N, d): those of A, C and S of dragonfly i's exploring step.
        L: Levy steps (N, d) (already scaled by 0.01) of dragonfly i's lone flight.
    """
    n, d = X.shape
    S, A, C = np.empty(d), np.empty(d), np.empty(d)
    for i in range(n):
        count = 0
        S[:] = 0.0
        A[:] = 0.0
        C[:] = 0.0
        for j in range(n):  # neighbours: within r and distinct in every coordinate
            near = True
            for m in range(d):
                dist = abs(X[i, m] - X[j, m])
                if dist > r[m] or dist == 0.0:
                    near = False
                    break
            if near:
                count += 1
                for m in range(d):
                    S[m] += X[j, m] - X[i, m]
                    A[m] += dX[j, m]
                    C[m] += X[j, m]
        many = count > 1
        near_food, near_enemy = True, True
        for m in range(d):
            near_food = near_food and abs(X[i, m] - food[m]) <= r[m]
            near_enemy = near_enemy and abs(X[i, m] - enemy[m]) <= r[m]
        for m in range(d):
            if many:
                S[m] = -S[m]  # Eq. 3.1
                A[m] = A[m] / count  # Eq. 3.2
                C[m] = C[m] / count - X[i, m]  # Eq. 3.3
            else:
                S[m], A[m], C[m] = 0.0, dX[i, m], 0.0
        for m in range(d):
            if near_food:  # Eq. 3.6 with F (Eq. 3.4) and E (Eq. 3.5)
                E = enemy[m] + X[i, m] if near_enemy else 0.0
                step = (k * S[m] + k * A[m] + k * C[m] + f * (food[m] - X[i, m]) + k * E
                        + w * dX[i, m])
            elif many:
                step = w * dX[i, m] + U[0, i, m] * A[m] + U[1, i, m] * C[m] + U[2, i, m] * S[m]
            else:  # Eq. 3.8: Levy flight, the step is reset
                X[i, m] = min(max(X[i, m] + L[i, m] * X[i, m], xl[m]), xu[m])
                dX[i, m] = 0.0
                continue
            step = min(max(step, -vmax[m]), vmax[m])
            dX[i, m] = step
            X[i, m] = min(max(X[i, m] + step, xl[m]), xu[m])  # Eq. 3.7, clipped


def dragonfly_step(X, dX, food, enemy, r, w: float, k: float, f: float, vmax, xl, xu, *,
                   rng: np.random.Generator):
    """One MODA iteration: draws its random numbers, then :func:`dragonflies_in_turn`.

    Draws the uniforms of the exploring steps (3, N, d) and then the Levy steps (N, d)
    for every dragonfly, whichever branch it takes.

    Returns:
        New positions (clipped to ``[xl, xu]``) and steps, each (N, d); the inputs are
        not modified.
    """
    U = rng.random((3, *np.shape(X)))
    L = levy(np.shape(X), rng=rng)
    X_new, dX_new = np.array(X, dtype=float), np.array(dX, dtype=float)
    dragonflies_in_turn(X_new, dX_new, kernel_array(food), kernel_array(enemy), kernel_array(r),
                        float(w), float(k), float(f), kernel_array(vmax), kernel_array(xl),
                        kernel_array(xu), U, L)
    return X_new, dX_new


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
                                    self.vmax, self.xl, self.xu, rng=rng)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
