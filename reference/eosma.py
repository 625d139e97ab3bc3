"""Ports on the EOSMA authors' archive files: MOEOSMA.m, and CSA.m per objective (MO-CSA);
see ``reference/__init__.py``."""

from __future__ import annotations

import math

import numpy as np

from .common import EPS, evaluate, roulette
from .mirjalili import mirjalili_handle_full


# ---- MOEOSMA.m ---------------------------------------------------------------------------
def eosma_ranks(AF, capacity):
    """RankingProcess.m of MOEOSMA: radius (max - min) / capacity."""
    unit = (AF.max(axis=0) - AF.min(axis=0)) / capacity
    return np.all(np.abs(AF[:, None, :] - AF[None, :, :]) < unit, axis=2).sum(axis=0).astype(float)


def eosma_update_archive(AX, AF, X, F):
    """UpdateArchive.m: strict all-objective dominance, then one of each equal row kept."""
    TX, TF = np.vstack([AX, X]), np.vstack([AF, F])
    strict = np.all(TF[None, :, :] < TF[:, None, :], axis=2)  # strict[i, j]: j < i everywhere
    keep = ~strict.any(axis=1)
    UX, UF = TX[keep], TF[keep]
    _, first = np.unique(UF, axis=0, return_index=True)
    first = np.sort(first)
    return UX[first], UF[first]


def moeosma_reference(problem, N, max_iter, rng, capacity=None, z=0.6, GP=0.5, mode="code"):
    cap = capacity or N
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim, M = problem.n_var, problem.n_obj
    AX, AF = np.zeros((0, dim)), np.zeros((0, M))
    X = lb + rng.random((N, dim)) * (ub - lb)
    fit = evaluate(problem, X)
    n_eval = N
    fit_old, X_old = fit.copy(), X.copy()
    weight = np.ones((N, dim))

    def bound(X, X_old):
        hi, lo = ub < X, lb > X
        return np.where(hi, (X_old + ub) / 2, np.where(lo, (X_old + lb) / 2, X))

    def memory(X, fit, X_old, fit_old):  # MATLAB ``if fit_old(k,:) < Fitness(k,:)``: all
        old = np.all(fit_old < fit, axis=1)[:, None]
        X, fit = np.where(old, X_old, X), np.where(old, fit_old, fit)
        return X, fit, X.copy(), fit.copy()

    def archive(AX, AF, X, fit):
        AX, AF = eosma_update_archive(AX, AF, X, fit)
        if len(AF) > cap:
            ranks = eosma_ranks(AF, cap)
            for _ in range(len(AF) - cap):
                i = max(roulette(ranks, rng), 0)
                AX, AF, ranks = np.delete(AX, i, 0), np.delete(AF, i, 0), np.delete(ranks, i)
        return AX, AF

    for it in range(1, max_iter + 1):
        X = bound(X, X_old)
        fit = evaluate(problem, X)
        n_eval += N
        AX, AF = archive(AX, AF, X, fit)
        ranks = eosma_ranks(AF, cap)
        pool = AX[ranks == ranks.min()]
        X, fit, X_old, fit_old = memory(X, fit, X_old, fit_old)
        order = np.argsort(fit[:, it % M], kind="stable")
        so = fit[order, it % M]
        best, worst = so[0], so[-1]
        S = best - worst - EPS  # the code adds eps, which divides by 0 once f spans < eps
        for k in range(N):
            lg = np.log10((best - so[k]) / S + 1)
            weight[order[k]] = 1 + (1 if k + 1 <= N / 2 else -1) * rng.random(dim) * lg
        s = it / max_iter
        a1 = (1 + (1 - s) ** (2 * s)) * rng.random()
        a2 = (2 - (1 - s) ** (2 * s)) * rng.random()
        if mode == "paper":
            a1, a2 = 2.0, 2.0
        t1 = (1 - s) ** (a2 * s)
        lam, r1, r2 = rng.random((N, dim)), rng.random(N), rng.random(N)
        rn = rng.integers(len(pool), size=N)
        a = math.atanh(1 - s) if s < 1 else 0.0
        vb, r = rng.uniform(-a, a, (N, dim)), rng.random((N, dim))
        R = rng.integers(N, size=(N, 2))
        for i in range(N):  # in place, as the code: later agents see the moved ones
            g = pool[rn[i]]
            if rng.random() < z:
                Fv = a1 * np.sign(r[i] - 0.5) * (np.exp(-lam[i] * t1) - 1)
                G = 0.5 * r1[i] * (r2[i] >= GP) * (g - lam[i] * X[i]) * Fv
                X[i] = g + (X[i] - g) * Fv + G / lam[i] * (1 - Fv)
            else:
                X[i] = g + vb[i] * (weight[i] * X[R[i, 0]] - X[R[i, 1]])
        X = bound(X, X_old)
        fit = evaluate(problem, X)
        n_eval += N
        AX, AF = archive(AX, AF, X, fit)
        X, fit, X_old, fit_old = memory(X, fit, X_old, fit_old)
        if mode == "paper":  # Eq. 16
            SF = rng.uniform(0.3, 0.6, (N, 1))
            R = rng.integers(N, size=(N, 3))
            X = X[R[:, 0]] + SF * (X[R[:, 1]] - X[R[:, 2]])
        else:  # MOEOSMA.m
            SF = 0.2 + rng.random() * 0.8
            R = rng.integers(N, size=(N, 2))
            X = X + SF * (X[R[:, 0]] - X[R[:, 1]])
    return AX, AF, n_eval


# ---- CSA.m per objective (MO-CSA, the MO-m-PSO paper's construction) -------------------
def mo_csa_reference(problem, N, max_iter, rng, capacity=None, AP=0.1, fl=2.0):
    """Askarzadeh's CSA.m (crow search, Computers & Structures 2016, the code published with
    the paper), one flock per objective, every evaluated point inside the box offered to a
    shared archive: the construction of Rokbani et al. 2022 (Section 2.2, Algorithm 2),
    which publish no code. The archive is the EOSMA authors' (``UpdateArchive.m``,
    ``RankingProcess.m`` with radius (max - min) / capacity, ``HandleFullArchive.m``), the
    one moik's MO-CSA uses. Unconstrained problems only."""
    cap = capacity or N
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim, M = problem.n_var, problem.n_obj
    x = lb + rng.random((M, N, dim)) * (ub - lb)  # init.m, one flock per objective
    F = evaluate(problem, x.reshape(-1, dim)).reshape(M, N, M)
    n_eval = M * N
    mem, fit_mem = x.copy(), np.array([F[k, :, k] for k in range(M)])
    AX, AF = eosma_update_archive(np.zeros((0, dim)), np.zeros((0, M)), x.reshape(-1, dim),
                                   F.reshape(-1, M))
    for _ in range(max_iter):
        xnew = np.empty_like(x)
        for k in range(M):
            num = rng.integers(0, N, N)  # ceil(n*rand(1,n)): a crow may follow itself
            for i in range(N):
                if rng.random() > AP:  # state 1
                    xnew[k, i] = x[k, i] + fl * rng.random() * (mem[k, num[i]] - x[k, i])
                else:  # state 2: a random position
                    xnew[k, i] = lb - (lb - ub) * rng.random(dim)
        Fn = evaluate(problem, xnew.reshape(-1, dim)).reshape(M, N, M)  # all evaluated
        n_eval += M * N
        inside = np.all((xnew >= lb) & (xnew <= ub), axis=2)  # MATLAB ``if`` on a vector
        for k in range(M):
            for i in np.flatnonzero(inside[k]):
                x[k, i] = xnew[k, i]
                if Fn[k, i, k] < fit_mem[k, i]:
                    mem[k, i], fit_mem[k, i] = xnew[k, i], Fn[k, i, k]
        AX, AF = eosma_update_archive(AX, AF, xnew[inside], Fn[inside])
        if len(AF) > cap:
            AX, AF, _ = mirjalili_handle_full(AX, AF, np.zeros(len(AF)), eosma_ranks(AF, cap),
                                              cap, rng)
    return AX, AF, n_eval


