"""The numpy formulas that EO's, SMA's, EOSMA's and the shared mechanics' compiled kernels
replaced, kept here as the oracle of the tests (whole-array numpy operations, drawing each
random array where it is used): fixture ``numpy_rules``. A compiled kernel must give the
same bits on the same inputs and the same random stream.
"""

from __future__ import annotations

import sys
from collections.abc import Generator

import numpy as np
import pytest

from moik.algorithms.soo.eo import eo_schedule
from moik.algorithms.soo.eosma import EOSMA
from moik.algorithms.soo.sma import sma_schedule

EPS = np.finfo(float).eps


def is_better(f1, cv1, f2, cv2):
    if cv1 is None:
        return f1 < f2
    return (cv1 < cv2) | ((cv1 == cv2) & (f1 < f2))


def midpoint_repair(X_new, X_old, xl, xu):
    hi, lo = X_new > xu, X_new < xl
    if not (hi.any() or lo.any()):
        return X_new
    X = np.where(hi, (X_old + xu) / 2.0, X_new)
    return np.where(lo, (X_old + xl) / 2.0, X)


def greedy_memory(X, F, CV, PX, PF, PCV):
    better = is_better(F, CV, PF, PCV)
    PX = np.where(better[:, None], X, PX)
    PCV = None if CV is None else np.where(better, CV, PCV)
    return PX, np.where(better, F, PF), PCV


def ranking_fitness(F, CV):
    if CV is None:
        return F
    feas = CV <= 0.0
    worst = F[feas].max() if feas.any() else 0.0
    return np.where(feas, F, worst + CV)


def update_pool(PX, PF, PCV, X, F, CV, k=4):
    X_all, F_all = np.concatenate([PX, X]), np.concatenate([PF, F])
    CV_all = None if CV is None else np.concatenate([PCV, CV])
    order = np.argsort(ranking_fitness(F_all, CV_all), kind="stable")[:k]
    return X_all[order], F_all[order], (None if CV is None else CV_all[order])


def update_distinct_pool(PX, PF, PCV, X, F, CV, k=4):
    X_all, F_all = np.concatenate([PX, X]), np.concatenate([PF, F])
    CV_all = None if CV is None else np.concatenate([PCV, CV])
    S = ranking_fitness(F_all, CV_all)
    order = np.argsort(S, kind="stable")
    for m in (4 * k, len(order)):
        top = order[:m]
        St = S[top]
        if not np.any(St[1:] == St[:-1]):
            break
        Xs = X_all[top]
        same = (Xs[:, None, :] == Xs[None, :, :]).all(axis=2) & (St[:, None] == St[None, :])
        top = top[~np.tril(same, -1).any(axis=1)]
        if len(top) >= k or m >= len(order):
            break
    top = top[:k]
    return X_all[top], F_all[top], (None if CV is None else CV_all[top])


def with_mean(PX):
    return np.concatenate([PX, PX.sum(axis=0, keepdims=True) / len(PX)])


def concentration_update(C, pool, t1, *, a1, GP, V, rng):
    n, d = C.shape
    lam = rng.random((n, d))
    r = rng.random((n, d))
    Ceq = pool[rng.integers(len(pool), size=n)]
    F = a1 * np.sign(r - 0.5) * (np.exp(-lam * t1) - 1.0)
    r1, r2 = rng.random(n), rng.random(n)
    GCP = np.where(r2 >= GP, 0.5 * r1, 0.0)[:, None]
    G = GCP * (Ceq - lam * C) * F
    return Ceq + (C - Ceq) * F + G / (lam * V) * (1.0 - F)


def sma_weights(S, d, *, rng):
    n = len(S)
    order = np.argsort(S, kind="stable")
    S_sorted = S[order]
    bF, wF = S_sorted[0], S_sorted[-1]
    log = np.log10((bF - S_sorted) / (bF - wF - EPS) + 1.0)
    sign = np.where(np.arange(1, n + 1) <= n / 2, 1.0, -1.0)
    W = np.empty((n, d))
    W[order] = 1.0 + (sign * log)[:, None] * rng.random((n, d))
    return W


def sma_update(X, W, x_best, S, f_best, a, b, *, z, xl, xu, rng):
    n, d = X.shape
    p = np.tanh(np.abs(S - f_best))
    vb = rng.uniform(-a, a, (n, d))
    vc = rng.uniform(-b, b, (n, d))
    r = rng.random((n, d))
    cols = np.arange(d)
    XA = X[rng.integers(n, size=(n, d)), cols]
    XB = X[rng.integers(n, size=(n, d)), cols]
    X_new = np.where(r < p[:, None], x_best + vb * (W * XA - XB), vc * X)
    restart = rng.random(n) < z
    k = int(restart.sum())
    if k:
        X_new[restart] = xl + rng.random((k, xl.size)) * (xu - xl)
    return X_new


def eosma_update(P, g_best, pool, W, t1, a, *, z, a1, GP, V, rng):
    n, d = P.shape
    X_eo = concentration_update(P, pool, t1, a1=a1, GP=GP, V=V, rng=rng)
    vb = rng.uniform(-a, a, (n, d))
    A, B = rng.integers(n, size=n), rng.integers(n, size=n)
    X_sma = g_best + vb * (W * P[A] - P[B])
    use_eo = rng.random(n) < z
    return np.where(use_eo[:, None], X_eo, X_sma)


def random_difference_mutation(P, *, rng):
    n = len(P)
    R = rng.integers(n, size=(3, n))
    SF = rng.uniform(0.3, 0.6, (n, 1))
    return P[R[0]] + SF * (P[R[1]] - P[R[2]])


class NumpyEOSMA(EOSMA):
    """EOSMA's Algorithm 1 with the numpy formulas above, drawing each number where it is
    used: the oracle of the compiled generation."""

    def _initialize_state(self) -> None:
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV
        empty, cv0 = np.empty((0, self.problem.n_var)), (None if self.CV is None else np.empty(0))
        self.pool_X, self.pool_F, self.pool_CV = update_distinct_pool(
            empty, np.empty(0), cv0, self.X, self.F, self.CV)

    def _numpy_remember(self, X, F, CV) -> None:
        self.X, self.F, self.CV = X, F, CV
        self.pbest_X, self.pbest_F, self.pbest_CV = greedy_memory(
            X, F, CV, self.pbest_X, self.pbest_F, self.pbest_CV)
        self.pool_X, self.pool_F, self.pool_CV = update_distinct_pool(
            self.pool_X, self.pool_F, self.pool_CV, X, F, CV)

    def _generation(self) -> Generator:
        rng = self.random_state
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        a, _ = sma_schedule(self.t, self.max_iter)
        W = sma_weights(ranking_fitness(self.pbest_F, self.pbest_CV), self.problem.n_var, rng=rng)
        X = eosma_update(self.pbest_X, self.best_x, with_mean(self.pool_X), W, t1, a, z=self.z,
                         a1=self.a1, GP=self.GP, V=self.V, rng=rng)
        X = midpoint_repair(X, self.pbest_X, self.xl, self.xu)
        F, CV = yield X
        self._numpy_remember(X, F, CV)
        if rng.random() < self.q:
            X = midpoint_repair(random_difference_mutation(self.pbest_X, rng=rng),
                                self.pbest_X, self.xl, self.xu)
            F, CV = yield X
            self._numpy_remember(X, F, CV)


@pytest.fixture(scope="session")
def numpy_rules():
    """This module: the numpy formulas and :class:`NumpyEOSMA`."""
    return sys.modules[__name__]
