"""Ports of Mirjalili's MSSA.m, MALO.m, MODA.m, MOMVO.m and their shared archive files
(see ``reference/__init__.py`` for the sources)."""

from __future__ import annotations

import math

import numpy as np

from .common import evaluate_cv, nondominated_fast, roulette


# ---- Mirjalili's archive (MSSA, MOALO, MODA) ------------------------------------------
def mirjalili_update_archive(AX, AF, X, F, ACV, CV):
    """UpdateArchive.m: the non-dominated rows; rows with an equal twin are dropped, both.

    Constrained problems (not in the code, which is unconstrained): constraint-domination
    first, the rule of moik's archives: only the feasible rows compete once one is
    feasible, before that only the rows of the smallest violation.
    """
    TX, TF, TCV = np.vstack([AX, X]), np.vstack([AF, F]), np.concatenate([ACV, CV])
    best = TCV <= 0.0
    if not best.any():
        best = TCV.min() == TCV
    TX, TF, TCV = TX[best], TF[best], TCV[best]
    keep = nondominated_fast(TF)
    _, inverse, counts = np.unique(TF, axis=0, return_inverse=True, return_counts=True)
    keep &= counts[inverse.reshape(-1)] == 1
    return TX[keep], TF[keep], TCV[keep]




def mirjalili_ranks(AF, divisor=20.0):
    """RankingProcess.m: members within (max - min) / divisor in every objective (strict)."""
    if len(AF) == 1:
        return np.zeros(1)  # min = max: a zero radius counts nobody
    r = (AF.max(axis=0) - AF.min(axis=0)) / divisor
    return np.all(np.abs(AF[None, :, :] - AF[:, None, :]) < r, axis=2).sum(axis=1).astype(float)


def mirjalili_handle_full(AX, AF, ACV, ranks, capacity, rng):
    """HandleFullArchive.m: remove by roulette on the ranks, without recounting."""
    for _ in range(len(AF) - capacity):
        i = max(roulette(ranks, rng), 0)
        AX, AF, ACV = np.delete(AX, i, 0), np.delete(AF, i, 0), np.delete(ACV, i)
        ranks = np.delete(ranks, i)
    return AX, AF, ACV


def mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng):
    AX, AF, ACV = mirjalili_update_archive(AX, AF, X, F, ACV, CV)
    if len(AF) > capacity:
        AX, AF, ACV = mirjalili_handle_full(AX, AF, ACV, mirjalili_ranks(AF), capacity, rng)
    return AX, AF, ACV, mirjalili_ranks(AF)


def leader(AX, ranks, rng, inverse=True):
    """``RouletteWheelSelection(1 ./ ranks)`` (or on the ranks), -1 read as the first member:
    a zero rank gives an infinite weight, an infinite sum and so the first member, as in
    MATLAB."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return AX[max(roulette(1.0 / ranks if inverse else ranks, rng), 0)]


# ---- MSSA.m ------------------------------------------------------------------------------
def mssa_reference(problem, N, max_iter, rng, capacity=100):
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim = problem.n_var
    AX, AF, ACV = np.zeros((0, dim)), np.zeros((0, problem.n_obj)), np.zeros(0)
    X = lb + rng.random((N, dim)) * (ub - lb)
    n_eval = 0
    for it in range(1, max_iter + 1):
        c1 = 2 * math.exp(-((4 * it / max_iter) ** 2))  # Eq. 3.2
        F, CV = evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        food = leader(AX, ranks, rng)
        for i in range(N):
            if i + 1 <= N / 2:
                c2, c3 = rng.random(dim), rng.random(dim)
                step = c1 * ((ub - lb) * c2 + lb)
                X[i] = np.where(c3 < 0.5, food + step, food - step)  # Eq. 3.1
            else:
                X[i] = (X[i - 1] + X[i]) / 2  # Eq. 3.4, with the moved predecessor
            X[i] = np.clip(X[i], lb, ub)
    return AX, AF, n_eval


# ---- MALO.m ------------------------------------------------------------------------------
def _walk_around(antlion, it, max_iter, lb, ub, rng):
    """Random_walk_around_antlion.m, the row ``it`` (1-based) of the walks."""
    ratio = 1.0
    for frac, w in ((0.1, 2), (0.5, 3), (0.75, 4), (0.9, 5), (0.95, 6)):
        if it > max_iter * frac:
            ratio = 1 + 10**w * (it / max_iter)
    lo, hi = lb / ratio, ub / ratio  # Eqs. 2.10-2.11
    lo = lo + antlion if rng.random() < 0.5 else -lo + antlion  # Eq. 2.8
    hi = hi + antlion if rng.random() >= 0.5 else -hi + antlion  # Eq. 2.9
    steps = 2 * (rng.random((len(lb), max_iter)) > 0.5) - 1
    walk = np.concatenate([np.zeros((len(lb), 1)), np.cumsum(steps, axis=1)], axis=1)
    a, b = walk.min(axis=1), walk.max(axis=1)
    return (walk[:, it - 1] - a) * (hi - lo) / (b - a) + lo  # Eq. 2.7


def malo_reference(problem, N, max_iter, rng, capacity=100):
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim = problem.n_var
    AX, AF, ACV = np.zeros((0, dim)), np.zeros((0, problem.n_obj)), np.zeros(0)
    X = lb + rng.random((N, dim)) * (ub - lb)
    n_eval = 0
    for it in range(1, max_iter + 1):
        F, CV = evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        elite = leader(AX, ranks, rng)
        antlion = AX[0]  # MALO.m: the first archive member, for every ant
        for i in range(N):
            RA = _walk_around(antlion, it, max_iter, lb, ub, rng)
            RE = _walk_around(elite, it, max_iter, lb, ub, rng)
            X[i] = np.clip((RE + RA) / 2, lb, ub)  # Eq. 2.13
    return AX, AF, n_eval


# ---- MODA.m ------------------------------------------------------------------------------
def _levy(d, rng, beta=1.5):
    sigma = (math.gamma(1 + beta) * math.sin(math.pi * beta / 2)
             / (math.gamma((1 + beta) / 2) * beta * 2 ** ((beta - 1) / 2))) ** (1 / beta)
    return 0.01 * rng.standard_normal(d) * sigma / np.abs(rng.standard_normal(d)) ** (1 / beta)


def moda_reference(problem, N, max_iter, rng, capacity=100):
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim = problem.n_var
    AX, AF, ACV = np.zeros((0, dim)), np.zeros((0, problem.n_obj)), np.zeros(0)
    v_max = (ub[0] - lb[0]) / 10
    X = lb + rng.random((N, dim)) * (ub - lb)
    dX = lb + rng.random((N, dim)) * (ub - lb)
    n_eval = 0
    for it in range(1, max_iter + 1):
        r = (ub - lb) / 4 + (ub - lb) * (it / max_iter) * 2
        w = 0.9 - it * ((0.9 - 0.2) / max_iter)
        my_c = max(0.1 - it * ((0.1 - 0) / (max_iter / 2)), 0.0)
        k = my_c if it < 3 * max_iter / 4 else my_c / it
        f = 2 * rng.random()
        F, CV = evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        food = leader(AX, ranks, rng)
        enemy = leader(AX, ranks, rng, inverse=False)
        for i in range(N):  # in place: later dragonflies see the moved ones
            dist = np.abs(X - X[i])
            nb = np.flatnonzero(np.all(dist <= r, axis=1) & np.all(dist != 0, axis=1))
            many = nb.size > 1
            S = -(X[nb] - X[i]).sum(axis=0) if many else np.zeros(dim)
            A = dX[nb].mean(axis=0) if many else dX[i].copy()
            C = (X[nb].mean(axis=0) if many else X[i]) - X[i]
            to_food = np.abs(X[i] - food)
            Fo = food - X[i] if np.all(to_food <= r) else np.zeros(dim)
            E = enemy + X[i] if np.all(np.abs(X[i] - enemy) <= r) else np.zeros(dim)
            out_hi, out_lo = X[i] > ub, X[i] < lb
            X[i] = np.where(out_hi, lb, np.where(out_lo, ub, X[i]))
            redraw = out_hi | out_lo
            dX[i, redraw] = rng.random(int(redraw.sum()))
            if np.any(to_food > r):
                if many:
                    for j in range(dim):
                        dX[i, j] = np.clip(w * dX[i, j] + rng.random() * A[j] + rng.random() * C[j]
                                           + rng.random() * S[j], -v_max, v_max)
                        X[i, j] += dX[i, j]
                else:
                    X[i] = X[i] + _levy(dim, rng) * X[i]
                    dX[i] = 0.0
            else:
                dX[i] = np.clip(k * S + k * A + k * C + f * Fo + k * E + w * dX[i], -v_max, v_max)
                X[i] = X[i] + dX[i]
            X[i] = np.clip(X[i], lb, ub)
    return AX, AF, n_eval


# ---- MOMVO.m -----------------------------------------------------------------------------
def momvo_reference(problem, N, max_iter, rng, capacity=100):
    """MOMVO.m (Mirjalili's MOMVO 1.0), read in Natee-Panagant/Comparative-study-of-truss-
    sizing-optimisation-problems-in-MATLAB ``Algorithms/MOMVO.m`` (aeb246c7) and
    Zionist1923/MOMVO_Based_MMGEMS ``MOMVO.m`` (bda128e7).

    The code keeps the MVO.m statements that were written for a row of N scalar
    inflation rates and runs them on the (N, M) objective matrix; MATLAB's matrix
    semantics then decide what they do (kept here, noted inline). Unconstrained in the
    code: on constrained problems the universes are sorted on the raw objectives and the
    archive update uses constraint-domination (``mirjalili_update_archive``). Assumes
    N >= M (``length`` of the (N, M) matrix in RouletteWheelSelection is then N).
    """
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim, M = problem.n_var, problem.n_obj
    AX, AF, ACV = np.zeros((0, dim)), np.zeros((0, M)), np.zeros(0)
    wep_max, wep_min = 1.0, 0.2
    U = lb + rng.random((N, dim)) * (ub - lb)  # initialization.m
    n_eval = 0
    for t in range(1, max_iter + 1):
        wep = wep_min + t * ((wep_max - wep_min) / max_iter)  # Eq. 3.3
        tdr = 1 - t ** (1 / 6) / max_iter ** (1 / 6)  # Eq. 3.4
        U = np.clip(U, lb, ub)  # Flag4ub / Flag4lb, before the evaluation
        I, CV = evaluate_cv(problem, U)  # noqa: E741
        n_eval += N
        # (the code's dominance "elitism" here sets Best_universe, which is overwritten by
        # the archive draw below before any use: left out)
        S = np.sort(I, axis=0, kind="stable")  # sort(Inflation_rates): each column on its own
        order = np.argsort(I[:, 0], kind="stable")  # sorted_indexes(newindex), newindex <= N:
        sorted_U = U[order]  # linear indexing reads the first column -> the order of f1
        with np.errstate(invalid="ignore", divide="ignore"):
            # normr: each row of the column-sorted matrix to unit length (a zero row is NaN
            # or 0: no tunnel either way); NI(i) reads column 1 by linear indexing
            NI = S[:, 0] / np.sqrt(np.sum(S**2, axis=1))
        U[0] = sorted_U[0]  # the elite, before the archive update: the archive gets the
        # elite's X with the F (and CV) of the universe it replaced (row 1's, as in the code)
        TX, TF, TCV = mirjalili_update_archive(AX, AF, U, I, ACV, CV)
        if len(TF):  # empty when every best row has an equal twin (copies of the elite):
            AX, AF, ACV = TX, TF, TCV  # MATLAB then stops with an error; the archive is kept
            if len(AF) > capacity:
                AX, AF, ACV = mirjalili_handle_full(AX, AF, ACV, mirjalili_ranks(AF), capacity,
                                                    rng)
        best = leader(AX, mirjalili_ranks(AF), rng)
        # RouletteWheelSelection(-sorted_Inflation_rates) on the matrix: cumsum runs down
        # each column, accumulation(end) is the total of the LAST objective's column, and
        # the scan over 1:length() reads the first column (f1) by linear indexing
        acc = np.cumsum(-S, axis=0)
        scan, total = acc.ravel(order="F")[:max(N, M)], acc[-1, -1]
        for i in range(1, N):  # row i of the unsorted universes, with the i-th sorted NI
            for j in range(dim):
                if rng.random() < NI[i]:  # Eq. 3.1 (the white hole: -1 read as the first)
                    hit = np.flatnonzero(scan > rng.random() * total)
                    U[i, j] = sorted_U[int(hit[0]) if hit.size else 0, j]
                if rng.random() < wep:  # Eq. 3.2, per-variable bounds (dim > 1)
                    r3 = rng.random()
                    if r3 < 0.5:
                        U[i, j] = best[j] + tdr * ((ub[j] - lb[j]) * rng.random() + lb[j])
                    if r3 > 0.5:
                        U[i, j] = best[j] - tdr * ((ub[j] - lb[j]) * rng.random() + lb[j])
    return AX, AF, n_eval


