"""Line-by-line numpy ports of the authors' MATLAB codes, to run beside moik's implementations.

Used by ``benchmarks/moo_quality.py`` (section "reference codes side by side") to tell a
bug from a method's weakness: where moik's algorithm and the port of its reference
code give the same picture on the same problem and budget, the weakness is the
method's. Each port keeps the code's control flow, its order of operations and its
quirks (noted inline); only the random streams differ (numpy instead of MATLAB), and
evaluations are vectorized where the code evaluates one agent at a time without the
others seeing the result. Ports (files as published):

- ``moeosma_reference``: Shihong-Yin/MOEOSMA, ``MOEOSMA_for_CEC2020/MOEOSMA.m``,
  ``UpdateArchive.m``, ``RankingProcess.m``, ``HandleFullArchive.m``,
  ``RouletteWheelSelection.m`` (``mode="paper"`` swaps in the paper's Eq. 16 mutation
  and a1 = a2 = 2 for the code's random a1, a2 and ``X + SF (X_R1 - X_R2)``);
- ``mogwo_reference``: Mirjalili's MOGWO 1.0 (``MOGWO.m``, ``SelectLeader.m``,
  ``DeleteFromRep.m``, ``CreateHypercubes.m``, ``GetGridIndex.m``);
- ``malo_reference``: Mirjalili's MOALO 1.0 (``MALO.m``, ``Random_walk_around_antlion.m``);
- ``mssa_reference``: Mirjalili's MSSA 1.0 (``MSSA.m``);
- ``moda_reference``: Mirjalili's MODA 1.0 (``MODA.m``, ``Levy.m``);
- ``momvo_reference``: Mirjalili's MOMVO 1.0 (``MOMVO.m``);
- ``mo_csa_reference``: Askarzadeh's ``CSA.m``, one flock per objective (the MO-m-PSO
  paper's construction; it publishes no code), on the EOSMA authors' archive files;
  the last four with Mirjalili's shared archive files (``UpdateArchive.m``,
  ``RankingProcess.m``, ``HandleFullArchive.m``, ``RouletteWheelSelection.m``).

The MSSA/MOALO/MODA codes were read in the copies of github.com/mxd888/MOAOA_For_MOVRPD
(``MO_For_CEC2020/``), which carry Mirjalili's version-1.0 headers. MOMVO.m is not
there; it was read in github.com/Natee-Panagant/Comparative-study-of-truss-sizing-
optimisation-problems-in-MATLAB, ``Algorithms/MOMVO.m`` (commit aeb246c7), which carries
Mirjalili's MOMVO version-1.0 header (its adapter added a penalty and constraint values
G around the loop), and in github.com/Zionist1923/MOMVO_Based_MMGEMS, ``MOMVO.m``
(commit bda128e7, a re-headed copy without constraints); their main loops agree line
for line.

Constrained problems: the codes handle none. The MOGWO port and the ports on Mirjalili's
shared archive (MSSA, MOALO, MODA, MOMVO) then use constraint-domination in their archive
updates, the rule of moik's archives (only the feasible rows compete once one is
feasible; before that only those of the smallest total violation); the search itself
is the code's. The MOEOSMA port is for unconstrained problems only.

Every function takes a pymoo problem, the population size, the number of iterations
and a numpy Generator and returns ``(archive_X, archive_F, n_eval)``.
"""

from __future__ import annotations

import math

import numpy as np

EPS = np.finfo(float).eps


def _evaluate(problem, X):
    return problem.evaluate(X, return_values_of=["F"])


def _evaluate_cv(problem, X):
    """``(F, CV)``: CV the total violation (positive G plus abs(H)), 0 when feasible."""
    F, G, H = problem.evaluate(X, return_values_of=["F", "G", "H"])
    cv = np.zeros(len(F))
    for part in (np.maximum(G, 0.0) if G is not None else None,
                 np.abs(H) if H is not None else None):
        if part is not None and part.size:
            cv += part.reshape(len(F), -1).sum(axis=1)
    return F, cv


def _dominates(a, b):
    return bool(np.all(a <= b) and np.any(a < b))


def _nondominated(F):
    m = len(F)
    return np.array([not any(_dominates(F[j], F[i]) for j in range(m) if j != i)
                     for i in range(m)], dtype=bool)


def _roulette(weights, rng) -> int:
    """RouletteWheelSelection.m (Mirjalili): first index with cumsum > r sum, else -1."""
    acc = np.cumsum(weights)
    hit = np.flatnonzero(acc > rng.random() * acc[-1])
    return int(hit[0]) if hit.size else -1


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
    keep = _nondominated_fast(TF)
    _, inverse, counts = np.unique(TF, axis=0, return_inverse=True, return_counts=True)
    keep &= counts[inverse.reshape(-1)] == 1
    return TX[keep], TF[keep], TCV[keep]


def _nondominated_fast(F):
    leq = np.all(F[:, None, :] <= F[None, :, :], axis=2)  # leq[j, i]: F_j <= F_i
    lt = np.any(F[:, None, :] < F[None, :, :], axis=2)
    return ~np.any(leq & lt, axis=0)


def _constrained_nondominated(F, CV):
    """Constraint-domination first (not in the codes; the rule of moik's archives): the
    non-dominated rows among the feasible ones, or among those of the smallest violation."""
    best = CV <= 0.0
    if not best.any():
        best = CV.min() == CV
    keep = np.zeros(len(F), dtype=bool)
    keep[np.flatnonzero(best)[_nondominated_fast(F[best])]] = True
    return keep


def mirjalili_ranks(AF, divisor=20.0):
    """RankingProcess.m: members within (max - min) / divisor in every objective (strict)."""
    if len(AF) == 1:
        return np.zeros(1)  # min = max: a zero radius counts nobody
    r = (AF.max(axis=0) - AF.min(axis=0)) / divisor
    return np.all(np.abs(AF[None, :, :] - AF[:, None, :]) < r, axis=2).sum(axis=1).astype(float)


def mirjalili_handle_full(AX, AF, ACV, ranks, capacity, rng):
    """HandleFullArchive.m: remove by roulette on the ranks, without recounting."""
    for _ in range(len(AF) - capacity):
        i = max(_roulette(ranks, rng), 0)
        AX, AF, ACV = np.delete(AX, i, 0), np.delete(AF, i, 0), np.delete(ACV, i)
        ranks = np.delete(ranks, i)
    return AX, AF, ACV


def _mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng):
    AX, AF, ACV = mirjalili_update_archive(AX, AF, X, F, ACV, CV)
    if len(AF) > capacity:
        AX, AF, ACV = mirjalili_handle_full(AX, AF, ACV, mirjalili_ranks(AF), capacity, rng)
    return AX, AF, ACV, mirjalili_ranks(AF)


def _leader(AX, ranks, rng, inverse=True):
    """``RouletteWheelSelection(1 ./ ranks)`` (or on the ranks), -1 read as the first member:
    a zero rank gives an infinite weight, an infinite sum and so the first member, as in
    MATLAB."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return AX[max(_roulette(1.0 / ranks if inverse else ranks, rng), 0)]


# ---- MSSA.m ------------------------------------------------------------------------------
def mssa_reference(problem, N, max_iter, rng, capacity=100):
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim = problem.n_var
    AX, AF, ACV = np.zeros((0, dim)), np.zeros((0, problem.n_obj)), np.zeros(0)
    X = lb + rng.random((N, dim)) * (ub - lb)
    n_eval = 0
    for it in range(1, max_iter + 1):
        c1 = 2 * math.exp(-((4 * it / max_iter) ** 2))  # Eq. 3.2
        F, CV = _evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = _mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        food = _leader(AX, ranks, rng)
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
        F, CV = _evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = _mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        elite = _leader(AX, ranks, rng)
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
        F, CV = _evaluate_cv(problem, X)
        n_eval += N
        AX, AF, ACV, ranks = _mirjalili_archive_step(AX, AF, ACV, X, F, CV, capacity, rng)
        food = _leader(AX, ranks, rng)
        enemy = _leader(AX, ranks, rng, inverse=False)
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
        I, CV = _evaluate_cv(problem, U)  # noqa: E741
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
        best = _leader(AX, mirjalili_ranks(AF), rng)
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


# ---- MOGWO.m -----------------------------------------------------------------------------
def _hypercubes(AF, n_grid, alpha):
    """CreateHypercubes.m: per objective n_grid - 1 edges over the inflated range, +-inf ends."""
    lo, hi = AF.min(axis=0), AF.max(axis=0)
    d = alpha * (hi - lo)
    return [np.linspace(lo[k] - d[k], hi[k] + d[k], n_grid - 1) for k in range(AF.shape[1])]


def _grid_index(AF, grid):
    """GetGridIndex.m: the first upper edge above each value; one scalar cell id per row."""
    subs = [np.searchsorted(edges, AF[:, k], side="right") for k, edges in enumerate(grid)]
    return np.ravel_multi_index(subs, [len(e) + 1 for e in grid])


def _select_by_cell(cells, rng, power):
    """SelectLeader.m / DeleteFromRep.m: a cell by roulette on count^power, a uniform member."""
    ids, counts = np.unique(cells, return_counts=True)
    p = counts.astype(float) ** power
    c = np.cumsum(p / p.sum())
    cell = ids[min(int(np.searchsorted(c, rng.random(), side="left")), len(ids) - 1)]
    members = np.flatnonzero(cells == cell)
    return members[rng.integers(members.size)]


def mogwo_reference(problem, N, max_iter, rng, capacity=100, n_grid=10, alpha=0.1, beta=4.0,
                    gamma=2.0):
    lb, ub = problem.xl.astype(float), problem.xu.astype(float)
    dim = problem.n_var
    X = lb + rng.random((N, dim)) * (ub - lb)
    F, CV = _evaluate_cv(problem, X)
    n_eval = N
    keep = _constrained_nondominated(F, CV)
    AX, AF, ACV = X[keep], F[keep], CV[keep]
    grid = _hypercubes(AF, n_grid, alpha)
    cells = _grid_index(AF, grid)
    for it in range(1, max_iter + 1):
        a = 2 - it * (2 / max_iter)
        for i in range(N):
            d = _select_by_cell(cells, rng, -beta)
            leaders = [d, _select_by_cell(cells, rng, -beta), _select_by_cell(cells, rng, -beta)]
            # rep2 / rep3: the members at another position than delta / beta (MATLAB
            # stops with an error when none is left: the earlier draw is kept here)
            rep2 = np.flatnonzero(np.any(AX[d] != AX, axis=1))
            if len(AX) > 1 and rep2.size:
                leaders[1] = rep2[_select_by_cell(cells[rep2], rng, -beta)]
                rep3 = rep2[np.any(AX[rep2] != AX[leaders[1]], axis=1)]
                if len(AX) > 2 and rep3.size:
                    leaders[2] = rep3[_select_by_cell(cells[rep3], rng, -beta)]
            moves = []
            for k, j in enumerate(leaders):  # Eqs. 3.1-3.10; A is a vector only for delta
                c = 2 * rng.random(dim)
                D = np.abs(c * AX[j] - X[i])
                A = 2 * a * (rng.random(dim) if k == 0 else rng.random()) - a
                moves.append(AX[j] - A * np.abs(D))
            X[i] = np.clip(sum(moves) / 3, lb, ub)  # Eq. 3.11
        F, CV = _evaluate_cv(problem, X)
        n_eval += N
        nd = _constrained_nondominated(F, CV)
        TX, TF = np.vstack([AX, X[nd]]), np.vstack([AF, F[nd]])
        TCV = np.concatenate([ACV, CV[nd]])
        keep = _constrained_nondominated(TF, TCV)  # duplicates stay (no mutual dominance)
        AX, AF, ACV = TX[keep], TF[keep], TCV[keep]
        cells = _grid_index(AF, grid)  # the grid of the last truncation
        if len(AX) > capacity:
            for _ in range(len(AX) - capacity):
                j = _select_by_cell(cells, rng, gamma)
                AX, AF, cells = np.delete(AX, j, 0), np.delete(AF, j, 0), np.delete(cells, j)
                ACV = np.delete(ACV, j)
            grid = _hypercubes(AF, n_grid, alpha)  # the indices stay those of the old grid
    return AX, AF, n_eval


# ---- MOEOSMA.m ---------------------------------------------------------------------------
def _eosma_ranks(AF, capacity):
    """RankingProcess.m of MOEOSMA: radius (max - min) / capacity."""
    unit = (AF.max(axis=0) - AF.min(axis=0)) / capacity
    return np.all(np.abs(AF[:, None, :] - AF[None, :, :]) < unit, axis=2).sum(axis=0).astype(float)


def _eosma_update_archive(AX, AF, X, F):
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
    fit = _evaluate(problem, X)
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
        AX, AF = _eosma_update_archive(AX, AF, X, fit)
        if len(AF) > cap:
            ranks = _eosma_ranks(AF, cap)
            for _ in range(len(AF) - cap):
                i = max(_roulette(ranks, rng), 0)
                AX, AF, ranks = np.delete(AX, i, 0), np.delete(AF, i, 0), np.delete(ranks, i)
        return AX, AF

    for it in range(1, max_iter + 1):
        X = bound(X, X_old)
        fit = _evaluate(problem, X)
        n_eval += N
        AX, AF = archive(AX, AF, X, fit)
        ranks = _eosma_ranks(AF, cap)
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
        fit = _evaluate(problem, X)
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
    F = _evaluate(problem, x.reshape(-1, dim)).reshape(M, N, M)
    n_eval = M * N
    mem, fit_mem = x.copy(), np.array([F[k, :, k] for k in range(M)])
    AX, AF = _eosma_update_archive(np.zeros((0, dim)), np.zeros((0, M)), x.reshape(-1, dim),
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
        Fn = _evaluate(problem, xnew.reshape(-1, dim)).reshape(M, N, M)  # all evaluated
        n_eval += M * N
        inside = np.all((xnew >= lb) & (xnew <= ub), axis=2)  # MATLAB ``if`` on a vector
        for k in range(M):
            for i in np.flatnonzero(inside[k]):
                x[k, i] = xnew[k, i]
                if Fn[k, i, k] < fit_mem[k, i]:
                    mem[k, i], fit_mem[k, i] = xnew[k, i], Fn[k, i, k]
        AX, AF = _eosma_update_archive(AX, AF, xnew[inside], Fn[inside])
        if len(AF) > cap:
            AX, AF, _ = mirjalili_handle_full(AX, AF, np.zeros(len(AF)), _eosma_ranks(AF, cap),
                                              cap, rng)
    return AX, AF, n_eval


REFERENCES = {
    "moeosma": moeosma_reference,
    "mogwo": mogwo_reference,
    "moalo": malo_reference,
    "mssa": mssa_reference,
    "moda": moda_reference,
    "momvo": momvo_reference,
    "mo-csa": mo_csa_reference,
}
"""moik registry name -> port of its reference code."""
