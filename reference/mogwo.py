"""Port of Mirjalili's MOGWO 1.0 (``MOGWO.m`` and its grid files; see ``reference/__init__.py``)."""

from __future__ import annotations

import numpy as np

from .common import constrained_nondominated, evaluate_cv


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
    F, CV = evaluate_cv(problem, X)
    n_eval = N
    keep = constrained_nondominated(F, CV)
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
        F, CV = evaluate_cv(problem, X)
        n_eval += N
        nd = constrained_nondominated(F, CV)
        TX, TF = np.vstack([AX, X[nd]]), np.vstack([AF, F[nd]])
        TCV = np.concatenate([ACV, CV[nd]])
        keep = constrained_nondominated(TF, TCV)  # duplicates stay (no mutual dominance)
        AX, AF, ACV = TX[keep], TF[keep], TCV[keep]
        cells = _grid_index(AF, grid)  # the grid of the last truncation
        if len(AX) > capacity:
            for _ in range(len(AX) - capacity):
                j = _select_by_cell(cells, rng, gamma)
                AX, AF, cells = np.delete(AX, j, 0), np.delete(AF, j, 0), np.delete(cells, j)
                ACV = np.delete(ACV, j)
            grid = _hypercubes(AF, n_grid, alpha)  # the indices stay those of the old grid
    return AX, AF, n_eval


