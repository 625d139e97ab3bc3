"""Multi-trial vector-based differential evolution (MTDE).

Nadimi-Shahraki, Taghian, Mirjalili & Faris, "MTDE: An effective multi-trial
vector-based differential evolution algorithm and its applications for
engineering design problems", Applied Soft Computing 97, 106761 (2020),
DOI 10.1016/j.asoc.2020.106761. Equation numbers are the paper's as cited in
the authors' code:

- Definition 1 / Eq. 2: every WinIter iterations the trial-vector producer
  (TVP) with the best improvement rate (improvements / trials) becomes the winner;
- Definition 2 / Eqs. 3-4: each iteration the population is shuffled and split:
  the two losers get ``floor(0.2 N)`` agents each, the winner the rest;
- Eq. 9: ``ca1 = 2 - 2 t/T``; Eq. 11:
  ``ca2 = initial - (initial - final) ((T - t)/T)^Mu`` (from ``final`` to ``initial``);
- R-TVP (representative-based): ``v = x + F (x_pbest - x) + F (x_pworst - x)
  + ca1 (x_r - x)``, x_pbest / x_pworst drawn from the best / worst ``pr``
  share of its subpopulation, x_r from population plus life-time archive;
  binomial-like crossover with the transformation matrix M;
- L-TVP (local random-based): ``v = x + ca2 (x_r - x) + F (x_m1 - x_m2)`` with
  two distinct random members of its subpopulation, no crossover;
- G-TVP (global best history-based): ``v = x_gbh + ca2 (x_r1 - x_r2)``, x_gbh a
  member of the gbest history (H entries), crossover with M;
- M: row i keeps ``k_i`` of the agent's own coordinates (``k_i`` cycling through
  1..D over the rows, positions shuffled), the rest come from v;
- F ~ Cauchy(mu_F, sigma) truncated to (0, 1], mu_F drawn from a memory of D
  entries (initially mu_f) updated with the weighted Lehmer mean of the
  successful F;
- greedy selection; replaced parents enter the life-time archive (size N);
  the new best enters the gbest history if it beats the history's mean.

Defaults (EOSMA paper, Table 3): WinIter=20, H=5, initial=0.001, final=2,
Mu=log(D), mu_f=0.5, sigma=0.2, pr=0.11. Evaluations: N per iteration. Out-of-range
coordinates move to the middle of the old value and the bound (``boundConstraint``).

Deviations:
- Winner shares follow the paper for all three winners; the authors' code gives
  a winning G-TVP only 20% (R and L 40% each).
- x_pbest / x_pworst come from the best / worst ``pr`` share (Table 3's pr);
  the authors' code draws them from the whole subpopulation.
- The life-time archive drops random members when full (JADE's rule); the
  authors' ``updateArchive`` with life-time counters was not available.
- Constrained problems: comparisons are feasibility-first (see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import integer, interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import is_better, midpoint_repair, ranking_fitness
from moik.algorithms.soo.code import distinct_indices


def mtde_schedules(t: int, T: int, initial: float, final: float, Mu: float):
    """Eqs. 9 and 11: ``ca1`` (2 -> 0) and ``ca2`` (final -> initial)."""
    s = min(t / T, 1.0)
    return 2.0 - 2.0 * s, initial - (initial - final) * (1.0 - s) ** Mu


def cauchy_scale_factors(mu, sigma: float, *, rng: np.random.Generator) -> np.ndarray:
    """F ~ Cauchy(mu, sigma), re-drawn while <= 0, capped at 1 (SHADE's rule)."""
    F = mu + sigma * np.tan(np.pi * (rng.random(len(mu)) - 0.5))
    bad = F <= 0
    while bad.any():
        F[bad] = mu[bad] + sigma * np.tan(np.pi * (rng.random(int(bad.sum())) - 0.5))
        bad = F <= 0
    return np.minimum(F, 1.0)


def transformation_matrix(n: int, d: int, *, rng: np.random.Generator) -> np.ndarray:
    """M (n, d) boolean: row i keeps ``1 + (i mod d)`` coordinates, shuffled, rows permuted."""
    keep = 1 + np.arange(n) % d
    M = np.arange(d)[None, :] < keep[:, None]
    M = np.take_along_axis(M, np.argsort(rng.random((n, d)), axis=1), axis=1)
    return M[rng.permutation(n)]


def split_population(n: int, winner: int, *, rng: np.random.Generator) -> list[np.ndarray]:
    """Eqs. 3-4: shuffled index groups for R-, L- and G-TVP; the winner gets the rest."""
    perm = rng.permutation(n)
    small = int(0.2 * n)
    sizes = [small, small, small]
    sizes[winner] = n - 2 * small
    return np.split(perm, np.cumsum(sizes)[:2])


def lehmer_mean(values: np.ndarray, weights: np.ndarray) -> float:
    """Weighted Lehmer mean ``sum w v^2 / sum w v`` (weights normalized)."""
    w = weights / weights.sum()
    return float((w * values**2).sum() / (w * values).sum())


class MTDE(ArrayAlgorithm):
    """Multi-trial vector DE (Nadimi-Shahraki et al. 2020) with array state.

    ``X``/``F`` is the population; extra arrays ``archive_X``, ``gbest_history``.

    Args:
        pop_size: Population size N (at least 5, so each TVP gets an agent).
        WinIter: Iterations between winner updates, >= 1 (Table 3: 20).
        H: Size of the gbest history, >= 1 (Table 3: 5).
        initial: Final value of ca2, > 0 (Table 3: 0.001).
        final: Initial value of ca2, > 0 (Table 3: 2).
        Mu: Exponent of Eq. 11, >= 0; None means log(D) (Table 3).
        mu_f: Initial memory of the scale factor in (0, 1] (Table 3: 0.5).
        sigma: Cauchy scale of F, > 0 (Table 3: 0.2).
        pr: Share of best / worst agents for R-TVP in (0, 1] (Table 3: 0.11).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 5

    def __init__(self, *, pop_size: int = 50, WinIter: int = 20, H: int = 5,
                 initial: float = 0.001, final: float = 2.0, Mu: float | None = None,
                 mu_f: float = 0.5, sigma: float = 0.2, pr: float = 0.11,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.WinIter = integer("WinIter", WinIter, minimum=1)
        self.H = integer("H", H, minimum=1)
        self.initial = interval("initial", initial, 0.0, 10.0, lo_open=True)
        self.final = interval("final", final, 0.0, 10.0, lo_open=True)
        self.Mu = None if Mu is None else interval("Mu", Mu, 0.0, 100.0)
        self.mu_f = interval("mu_f", mu_f, 0.0, 1.0, lo_open=True)
        self.sigma = interval("sigma", sigma, 0.0, 10.0, lo_open=True)
        self.pr = interval("pr", pr, 0.0, 1.0, lo_open=True)

    def _initialize_state(self) -> None:
        n, d = self.X.shape
        self._mu = math.log(d) if self.Mu is None else self.Mu
        self.memory_f, self._mem_pos = np.full(d, self.mu_f), 0
        self.archive_X = np.empty((0, d))
        i = int(np.argmin(ranking_fitness(self.F, self.CV)))
        self.gbest_history, self.gbest_history_F = self.X[i:i + 1].copy(), self.F[i:i + 1].copy()
        self._winner, self._improved, self._trials = 0, np.ones(3), np.zeros(3)

    def _trials_for(self, groups, F, ca1: float, ca2: float) -> np.ndarray:
        """R-, L- and G-TVP mutants, crossed over with M where the TVP uses it."""
        rng, X = self.random_state, self.X
        n, d = X.shape
        M = transformation_matrix(n, d, rng=rng)
        union = np.concatenate([X, self.archive_X])
        S = ranking_fitness(self.F, self.CV)
        U = np.empty_like(X)
        R, L, G = groups
        if R.size:  # R-TVP
            k = max(1, round(self.pr * R.size))
            order = R[np.argsort(S[R], kind="stable")]
            pbest = X[order[rng.integers(k, size=R.size)]]
            pworst = X[order[::-1][rng.integers(k, size=R.size)]]
            xr = union[distinct_indices(R.size, 1, rng=rng, pool=len(union), exclude=(R,))[0]]
            f = F[R, None]
            V = X[R] + f * (pbest - X[R]) + f * (pworst - X[R]) + ca1 * (xr - X[R])
            U[R] = np.where(M[R], X[R], V)
        if L.size:  # L-TVP
            m1, m2 = distinct_indices(L.size, 2, rng=rng) if L.size > 2 else (
                rng.integers(L.size, size=(2, L.size)))
            xr = union[distinct_indices(L.size, 1, rng=rng, pool=len(union), exclude=(L,))[0]]
            U[L] = X[L] + ca2 * (xr - X[L]) + F[L, None] * (X[L][m1] - X[L][m2])
        if G.size:  # G-TVP
            r1, r2 = (distinct_indices(G.size, 2, rng=rng) if G.size > 2
                      else rng.integers(G.size, size=(2, G.size)))
            gbh = self.gbest_history[G % len(self.gbest_history)]
            V = gbh + ca2 * (X[G][r1] - X[G][r2])
            U[G] = np.where(M[G], X[G], V)
        return midpoint_repair(U, X, self.xl, self.xu)

    def _generation(self) -> Step:
        rng = self.random_state
        n = len(self.X)
        ca1, ca2 = mtde_schedules(self.t, self.max_iter, self.initial, self.final, self._mu)
        F = cauchy_scale_factors(self.memory_f[rng.integers(len(self.memory_f), size=n)],
                                 self.sigma, rng=rng)
        if self.t % self.WinIter == 0 and self.t > 0:  # Definition 1 / Eq. 2
            self._winner = int(np.argmax(self._improved / np.maximum(self._trials, 1)))
            self._improved, self._trials = np.ones(3), np.zeros(3)
        groups = split_population(n, self._winner, rng=rng)
        U = self._trials_for(groups, F, ca1, ca2)
        FU, CVU = yield U
        better = is_better(FU, CVU, self.F, self.CV)
        for k, g in enumerate(groups):
            self._trials[k] += g.size
            self._improved[k] += better[g].sum()
        if better.any():
            self._remember(better, U, FU, CVU, F)
        self._update_history()

    def _remember(self, better, U, FU, CVU, F) -> None:
        """Selection, life-time archive, scale-factor memory (Lehmer mean)."""
        rng = self.random_state
        gain = np.abs(self.F[better] - FU[better])
        if np.isfinite(gain).all() and gain.sum() > 0:
            self.memory_f[self._mem_pos] = lehmer_mean(F[better], gain)
            self._mem_pos = (self._mem_pos + 1) % len(self.memory_f)
        archive = np.unique(np.concatenate([self.archive_X, self.X[better]]), axis=0)
        if len(archive) > len(self.X):
            archive = archive[rng.permutation(len(archive))[:len(self.X)]]
        self.archive_X = archive
        self.X = np.where(better[:, None], U, self.X)
        self.F = np.where(better, FU, self.F)
        if self.CV is not None:
            self.CV = np.where(better, CVU, self.CV)

    def _update_history(self) -> None:
        """gbest history: the best enters if it beats the history mean and is new."""
        i = int(np.argmin(ranking_fitness(self.F, self.CV)))
        f, hist = self.F[i], self.gbest_history_F
        if f < hist.mean() and not np.isclose(hist, f, rtol=1e-12, atol=1e-12).any():
            if len(hist) >= self.H:
                j = int(np.argmax(hist))
                self.gbest_history[j], self.gbest_history_F[j] = self.X[i], f
            else:
                self.gbest_history = np.concatenate([self.gbest_history, self.X[i:i + 1]])
                self.gbest_history_F = np.append(hist, f)
