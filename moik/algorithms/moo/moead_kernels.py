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

from moik._jit import jit, objectives_row

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
def _child(X, neighbors, k: int, u, xl, xu, rates, y) -> None:
    """Step 2.1-2.2 for subproblem ``k`` from the draws ``u`` (one row of ``U``), into ``y``.

    Its two parents are distinct members of the neighbourhood with probability ``delta``
    (``u[0] < delta``), else of the whole population; SBX (each variable crossed with
    probability 0.5 unless the parents coincide there, spread ``eta_c``; one of the two
    children, each variable from either SBX value with probability 0.5), then polynomial
    mutation (each variable with probability ``prob_mut``, spread ``eta_m``); clamped to
    the bounds. ``rates``: ``(delta, eta_c, eta_m, prob_mut)``.
    """
    n, d = X.shape
    delta, eta_c, eta_m, prob_mut = rates[0], rates[1], rates[2], rates[3]
    T = neighbors.shape[1]
    m = T if u[0] < delta else n
    a = min(int(u[1] * m), m - 1)
    b = min(int(u[2] * (m - 1)), m - 2)
    if b >= a:
        b += 1
    if m == T:
        a, b = neighbors[k, a], neighbors[k, b]
    base = a if u[3] < 0.5 else b
    for j in range(d):
        c = N_FIXED + 5 * j
        p1, p2, lo, hi = X[a, j], X[b, j], xl[j], xu[j]
        v = X[base, j]
        if u[c] < 0.5 and abs(p1 - p2) > 1.0e-14 and lo != hi:
            y1, y2 = min(p1, p2), max(p1, p2)
            spread, w = y2 - y1, u[c + 1]
            if u[c + 2] < 0.5:
                v = 0.5 * ((y1 + y2) - _sbx_betaq(1.0 + 2.0 * (y1 - lo) / spread, w, eta_c)
                           * spread)
            else:
                v = 0.5 * ((y1 + y2) + _sbx_betaq(1.0 + 2.0 * (hi - y2) / spread, w, eta_c)
                           * spread)
            v = min(max(v, lo), hi)
        if u[c + 3] < prob_mut and lo != hi:
            v = _pm(v, lo, hi, u[c + 4], eta_m)
        y[j] = v


@jit
def offspring(X, neighbors, perm, U, xl, xu, rates):
    """Step 2.1-2.2 (:func:`_child`) for each subproblem of ``perm``, from the population as
    it stands.

    Args:
        X: Population (n, d). neighbors: Neighbourhood indices (n, T), int64.
        perm: Subproblem of each offspring (k,), int64. U: Uniform draws (k, 4 + 5 d).
        xl, xu: Bounds (d,). rates: ``(delta, eta_c, eta_m, prob_mut)``.

    Returns:
        Offspring (k, d), one per entry of ``perm``.
    """
    Y = np.empty((perm.shape[0], X.shape[1]))
    for i in range(perm.shape[0]):
        _child(X, neighbors, perm[i], U[i], xl, xu, rates, Y[i])
    return Y


@jit
def _tchebycheff(f, w, z) -> float:
    """Eq. 3: ``max_i w_i |f_i - z_i|``."""
    g = 0.0
    for o in range(f.shape[0]):
        g = max(g, w[o] * abs(f[o] - z[o]))
    return g


@jit
def _finite(f, cv: float) -> bool:
    """Whether the objectives ``f`` and the violation ``cv`` are all finite."""
    ok = np.isfinite(cv)
    for o in range(f.shape[0]):
        ok = ok and np.isfinite(f[o])
    return ok


@jit
def _replace(X, F, CV, W, neighbors, k: int, y, fy, cvy: float, z, nr: int, keys) -> int:
    """Steps 2.3-2.4 for one offspring ``(y, fy, cvy)`` of subproblem ``k`` (in place):
    the reference point, then the neighbours it replaces (see :func:`update`)."""
    if not _finite(fy, cvy):
        return 0
    feasible = cvy <= 0.0
    if feasible:
        for o in range(fy.shape[0]):
            z[o] = min(z[o], fy[o])
    T = neighbors.shape[1]
    order = np.argsort(keys) if nr < T else np.arange(T)
    count = 0
    for t in range(T):
        j = neighbors[k, order[t]]
        if not _finite(F[j], CV[j]):
            better = True  # a member the problem gave no finite value
        elif feasible:
            better = CV[j] > 0.0 or _tchebycheff(fy, W[j], z) < _tchebycheff(F[j], W[j], z)
        else:
            better = CV[j] > 0.0 and cvy < CV[j]
        if better:
            X[j, :] = y
            F[j, :] = fy
            CV[j] = cvy
            count += 1
            if count >= nr:
                break
    return count


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
            offspring (k,). Y, FY, CVY: Offspring, their objectives and violations.
        z: Reference point (m,); updated.
        nr: Replacement limit. order_keys: Uniform draws (k, T) for the visiting order
            ((k, 0) when ``nr`` does not limit).

    Returns:
        Number of replacements made.
    """
    replaced = 0
    for i in range(Y.shape[0]):
        replaced += _replace(X, F, CV, W, neighbors, perm[i], Y[i], FY[i], CVY[i], z, nr,
                             order_keys[i])
    return replaced


@jit
def generation(X, F, CV, W, neighbors, draws, xl, xu, rates, z, nr: int, Y, FY, spec) -> int:
    """One whole generation of the sequential loop for an unconstrained problem with
    compiled objectives (``spec``, evaluated by :func:`moik._jit.objectives_row`): for each
    offspring ``i`` in turn, Steps 2.1-2.2 (:func:`_child`) from the population as the
    earlier ones left it, its objectives into ``FY[i]``, then Steps 2.3-2.4
    (:func:`_replace`). The same arithmetic as :func:`offspring` and :func:`update` one
    row at a time, in one call.

    Args:
        X, F, CV, W, neighbors: As :func:`update` (``X``, ``F`` updated; ``CV`` all zero).
        draws: ``(perm, U, order_keys)`` of the generation (as :func:`offspring` and
            :func:`update`).
        xl, xu, rates: As :func:`offspring`. z, nr: As :func:`update`.
        Y, FY: The offspring (k, d) and their objectives (k, m), written; ``k`` (at most
            ``len(perm)``: the budget) offspring are made.
        spec: The problem's compiled objectives.

    Returns:
        Number of replacements made.
    """
    perm, U, keys = draws
    replaced = 0
    for i in range(Y.shape[0]):
        _child(X, neighbors, perm[i], U[i], xl, xu, rates, Y[i])
        objectives_row(spec, Y, FY, i)
        replaced += _replace(X, F, CV, W, neighbors, perm[i], Y[i], FY[i], 0.0, z, nr, keys[i])
    return replaced
