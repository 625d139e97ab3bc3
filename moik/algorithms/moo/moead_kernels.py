"""MOEA/D's compiled generation: mating (SBX, polynomial mutation) and the Tchebycheff update.

Zhang & Li, "MOEA/D: A Multiobjective Evolutionary Algorithm Based on Decomposition",
IEEE TEC 11(6), 712-731 (2007), DOI 10.1109/TEVC.2007.892759, Section III-A (Steps
2.1-2.5, the Tchebycheff approach Eq. 3); the mating-pool probability ``delta`` and the
replacement limit ``nr`` of Li & Zhang, IEEE TEC 13(2), 284-302 (2009), DOI
10.1109/TEVC.2008.925798; the operators are pymoo 0.6's (``SBX(prob=1, eta=20)``, one
of its two children, then ``PM(eta=20)`` with ``prob_var = min(0.5, 1 / n_var)``),
which pymoo's MOEA/D uses. The readings are in :mod:`moik.algorithms.moo.moead`.

Random numbers are drawn by the caller in one numpy call per generation (``U``, one
row per offspring; columns in :data:`N_FIXED` and :func:`draw_columns`), so the
kernels are pure arithmetic.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit

N_FIXED = 4
"""Leading columns of a row of ``U``: the pool test, the two parent picks, the child."""


def draw_columns(n_var: int) -> int:
    """Columns of ``U`` per offspring: :data:`N_FIXED`, then per variable the crossover
    test, SBX's spread, the child swap, the mutation test and the mutation's spread."""
    return N_FIXED + 5 * n_var


@jit
def _sbx_betaq(beta: float, u: float, eta: float) -> float:
    """SBX's spread factor for a bound distance ``beta`` (pymoo's ``calc_betaq``)."""
    alpha = 2.0 - beta ** (-(eta + 1.0))
    if u <= 1.0 / alpha:
        return (u * alpha) ** (1.0 / (eta + 1.0))
    return (1.0 / (2.0 - u * alpha)) ** (1.0 / (eta + 1.0))


@jit
def _pm(x: float, lo: float, hi: float, u: float, eta: float) -> float:
    """Polynomial mutation of one coordinate (pymoo's ``mut_pm``), clamped."""
    d1, d2 = (x - lo) / (hi - lo), (hi - x) / (hi - lo)
    power = 1.0 / (eta + 1.0)
    if u <= 0.5:
        val = 2.0 * u + (1.0 - 2.0 * u) * (1.0 - d1) ** (eta + 1.0)
        dq = val ** power - 1.0
    else:
        val = 2.0 * (1.0 - u) + 2.0 * (u - 0.5) * (1.0 - d2) ** (eta + 1.0)
        dq = 1.0 - val ** power
    return min(max(x + dq * (hi - lo), lo), hi)


@jit
def offspring(X, neighbors, perm, U, xl, xu, delta: float, eta_c: float, eta_m: float,
              prob_mut: float):
    """Step 2.1-2.2: one offspring per subproblem, in the order ``perm``.

    Offspring ``i`` belongs to subproblem ``perm[i]``: its two parents are distinct
    members of the neighbourhood with probability ``delta`` (``U[i, 0] < delta``), else
    of the whole population; SBX (each variable crossed with probability 0.5 unless the
    parents coincide there, spread ``eta_c``; one of the two children, each variable from
    either SBX value with probability 0.5), then polynomial mutation (each variable with
    probability ``prob_mut``, spread ``eta_m``); clamped to the bounds.

    Args:
        X: Population (n, d). neighbors: Neighbourhood indices (n, T), int64.
        perm: Subproblem of each offspring (n,), int64. U: Uniform draws (n, 4 + 5 d).
        xl, xu: Bounds (d,).

    Returns:
        Offspring (n, d).
    """
    n, d = X.shape
    T = neighbors.shape[1]
    Y = np.empty((n, d))
    for i in range(n):
        k = perm[i]
        m = T if U[i, 0] < delta else n
        a = min(int(U[i, 1] * m), m - 1)
        b = min(int(U[i, 2] * (m - 1)), m - 2)
        if b >= a:
            b += 1
        if m == T:
            a, b = neighbors[k, a], neighbors[k, b]
        base = a if U[i, 3] < 0.5 else b
        for j in range(d):
            c = N_FIXED + 5 * j
            p1, p2, lo, hi = X[a, j], X[b, j], xl[j], xu[j]
            y = X[base, j]
            if U[i, c] < 0.5 and abs(p1 - p2) > 1.0e-14 and lo != hi:
                y1, y2 = min(p1, p2), max(p1, p2)
                spread, u = y2 - y1, U[i, c + 1]
                if U[i, c + 2] < 0.5:
                    y = 0.5 * ((y1 + y2) - _sbx_betaq(1.0 + 2.0 * (y1 - lo) / spread, u, eta_c)
                               * spread)
                else:
                    y = 0.5 * ((y1 + y2) + _sbx_betaq(1.0 + 2.0 * (hi - y2) / spread, u, eta_c)
                               * spread)
                y = min(max(y, lo), hi)
            if U[i, c + 3] < prob_mut and lo != hi:
                y = _pm(y, lo, hi, U[i, c + 4], eta_m)
            Y[i, j] = y
    return Y


@jit
def _tchebycheff(F, row: int, w, z) -> float:
    """Eq. 3: ``max_i w_i |f_i - z_i|`` of row ``row`` of ``F``."""
    g = 0.0
    for o in range(F.shape[1]):
        g = max(g, w[o] * abs(F[row, o] - z[o]))
    return g


@jit
def _finite_row(F, CV, row: int) -> bool:
    """Whether row ``row`` of ``F`` and ``CV[row]`` are all finite."""
    ok = np.isfinite(CV[row])
    for o in range(F.shape[1]):
        ok = ok and np.isfinite(F[row, o])
    return ok


@jit
def update(X, F, CV, W, neighbors, perm, Y, FY, CVY, z, nr: int, order_keys):
    """Steps 2.3-2.4 for each offspring in turn (in place): the reference point, then the
    neighbours it replaces.

    An offspring with a non-finite objective or violation is skipped; a member with one is
    replaced by any other offspring of its neighbourhood. A feasible offspring
    updates ``z`` (the best feasible value per objective) and replaces each neighbour
    that is infeasible or whose Tchebycheff value it lowers strictly; an infeasible one
    replaces only infeasible neighbours of a larger violation. At most ``nr`` neighbours
    are replaced per offspring, visited in the order of ``order_keys[i]`` when ``nr`` is
    smaller than the neighbourhood (in index order otherwise).

    Args:
        X, F, CV: Population (n, d), objectives (n, m), violations (n,); updated.
        W: Weight vectors (n, m). neighbors: (n, T) int64. perm: Subproblem of each
            offspring (n,). Y, FY, CVY: Offspring, their objectives and violations.
        z: Reference point (m,); updated.
        nr: Replacement limit. order_keys: Uniform draws (n, T) for the visiting order.

    Returns:
        Number of replacements made.
    """
    T = neighbors.shape[1]
    replaced = 0
    for i in range(Y.shape[0]):
        if not _finite_row(FY, CVY, i):
            continue
        feasible = CVY[i] <= 0.0
        if feasible:
            for o in range(FY.shape[1]):
                z[o] = min(z[o], FY[i, o])
        k = perm[i]
        order = np.argsort(order_keys[i]) if nr < T else np.arange(T)
        count = 0
        for t in range(T):
            j = neighbors[k, order[t]]
            if not _finite_row(F, CV, j):
                better = True  # a member the problem gave no finite value
            elif feasible:
                better = CV[j] > 0.0 or _tchebycheff(FY, i, W[j], z) < _tchebycheff(F, j, W[j], z)
            else:
                better = CV[j] > 0.0 and CVY[i] < CV[j]
            if better:
                X[j, :] = Y[i, :]
                F[j, :] = FY[i, :]
                CV[j] = CVY[i]
                count += 1
                if count >= nr:
                    break
        replaced += count
    return replaced
