"""Shared mechanics of moik's population algorithms, as pure functions.

Bound handling (uniform initialization, clipping, the EOSMA midpoint repair of
Eq. 17), the greedy personal-best memory (EOSMA Eq. 18) and feasibility-first
comparisons (Deb's rules: a feasible point beats an infeasible one, two
infeasible ones compare by total violation CV, two feasible ones by f). ``CV``
is ``None`` for unconstrained problems, which keeps their comparisons to a
single ``<``. Mantegna's Levy-stable step is shared by FPA, MPA, HHO, MODA and
I-BES. Randomness only through the ``rng`` keyword (no default). Hyperparameter
validation is :mod:`moik._validate`'s (``interval``, ``integer``, ``flag``).

The midpoint repair, the greedy memory and the ranking value are compiled
(:func:`moik._jit.jit`); their per-coordinate rules (:func:`midpoint_coordinate`,
:func:`is_better_scalar`, :func:`ranking_value`) are inlined into the compiled
update rules of EO and EOSMA, so each rule exists once. They select or halve values
only, so they give the same bits as numpy. numba raises on a float division by zero
where numpy returns inf or nan: compiled rules divide through :func:`ieee_divide`.
"""

from __future__ import annotations

import math

import numpy as np

from moik._jit import jit, kernel_array


def uniform_population(n: int, xl: np.ndarray, xu: np.ndarray, *, rng: np.random.Generator):
    """Return ``n`` points drawn uniformly in the box ``[xl, xu]``, shape (n, dim)."""
    return xl + rng.random((n, xl.size)) * (xu - xl)


def clip_to_bounds(X: np.ndarray, xl: np.ndarray, xu: np.ndarray) -> np.ndarray:
    """Return ``X`` with every coordinate clipped into ``[xl, xu]``."""
    return np.minimum(np.maximum(X, xl), xu)


@jit(inline=True)
def ieee_divide(a: float, b: float) -> float:
    """``a / b`` with IEEE 754's (numpy's) answer for ``b == 0``: +-inf, or nan for 0/0."""
    if b != 0.0:
        return a / b
    if a != a or a == 0.0:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


@jit(inline=True)
def midpoint_coordinate(x: float, old: float, lo: float, hi: float) -> float:
    """EOSMA Eq. 17 for one coordinate: halfway from ``old`` to the bound ``x`` violates."""
    if x < lo:
        return (old + lo) / 2.0
    if x > hi:
        return (old + hi) / 2.0
    return x


@jit
def _midpoint_repair(X_new, X_old, xl, xu):
    """Eq. 17 on every row; ``None`` when no coordinate is out of bounds."""
    n, d = X_new.shape
    inside = True
    for i in range(n):
        for j in range(d):
            if X_new[i, j] < xl[j] or X_new[i, j] > xu[j]:
                inside = False
    if inside:
        return None
    out = np.empty((n, d))
    for i in range(n):
        for j in range(d):
            out[i, j] = midpoint_coordinate(X_new[i, j], X_old[i, j], xl[j], xu[j])
    return out


def midpoint_repair(X_new: np.ndarray, X_old: np.ndarray, xl: np.ndarray, xu: np.ndarray):
    """EOSMA Eq. 17: a coordinate beyond a bound moves halfway from its old value to it.

    Returns ``X_new`` itself when every coordinate is within the bounds, else a new array.
    """
    out = _midpoint_repair(kernel_array(X_new), kernel_array(X_old), kernel_array(xl),
                           kernel_array(xu))
    return X_new if out is None else out


def constraint_violation(G: np.ndarray | None, H: np.ndarray | None, eq_tol: float = 1e-4):
    """Total violation per row (pymoo's default: sum of G+ and of |H| beyond ``eq_tol``)."""
    cv = 0.0
    if G is not None and G.size:
        cv = cv + np.maximum(G, 0.0).sum(axis=1)
    if H is not None and H.size:
        cv = cv + np.maximum(np.abs(H) - eq_tol, 0.0).sum(axis=1)
    return np.asarray(cv, dtype=float)


def is_better(f1, cv1, f2, cv2):
    """Feasibility-first strict comparison; ``cv1 is None`` means unconstrained."""
    if cv1 is None:
        return f1 < f2
    return (cv1 < cv2) | ((cv1 == cv2) & (f1 < f2))


@jit
def is_better_scalar(f1: float, cv1: float, f2: float, cv2: float) -> bool:
    """:func:`is_better` for one pair (unconstrained problems pass ``cv = 0``)."""
    return cv1 < cv2 or (cv1 == cv2 and f1 < f2)


@jit
def greedy_step(X, F, CV, PX, PF, PCV):
    """Eq. 18 into new arrays ``(PX, PF, PCV)``; ``CV``/``PCV`` are zeros when unconstrained."""
    PX, PF, PCV = PX.copy(), PF.copy(), PCV.copy()
    for i in range(F.size):
        if is_better_scalar(F[i], CV[i], PF[i], PCV[i]):
            for j in range(X.shape[1]):
                PX[i, j] = X[i, j]
            PF[i], PCV[i] = F[i], CV[i]
    return PX, PF, PCV


def greedy_memory(X, F, CV, PX, PF, PCV):
    """EOSMA Eq. 18: keep a new point in the memory only if strictly better.

    Returns:
        The updated memory ``(PX, PF, PCV)`` as new arrays (``PCV`` None when ``CV`` is).
    """
    F, PF = kernel_array(F), kernel_array(PF)
    cv, pcv = (np.zeros(F.size), np.zeros(F.size)) if CV is None else (
        kernel_array(CV), kernel_array(PCV))
    PX, PF, pcv = greedy_step(kernel_array(X), F, cv, kernel_array(PX), PF, pcv)
    return PX, PF, (None if CV is None else pcv)


@jit
def ranking_value(f: float, cv: float, worst_feasible: float) -> float:
    """:func:`ranking_fitness` of one row, given the worst feasible f (0 if none)."""
    return f if cv <= 0.0 else worst_feasible + cv


@jit
def ranking_into(F, CV, out):
    """:func:`ranking_fitness` of every row into ``out``."""
    worst, found = 0.0, False  # numpy's max of the feasible F: nan propagates
    for i in range(F.size):
        if CV[i] <= 0.0:
            if not found:
                worst, found = F[i], True
            elif worst == worst and (F[i] > worst or F[i] != F[i]):
                worst = F[i]
    for i in range(F.size):
        out[i] = ranking_value(F[i], CV[i], worst)
    return out


@jit(inline=True)
def ranks_before(a: float, b: float) -> bool:
    """Whether ``a`` sorts strictly before ``b`` in numpy's order (nan last)."""
    return a < b or (b != b and a == a)


@jit
def stable_order(S, order):
    """``np.argsort(S, kind="stable")`` (nan last) into ``order``: a bottom-up merge sort
    (numba's own ``argsort`` gives the same order but takes seconds to compile)."""
    n = S.size
    for i in range(n):
        order[i] = i
    buf = np.empty(n, np.int64)
    width = 1
    while width < n:
        for lo in range(0, n, 2 * width):
            mid, hi = min(lo + width, n), min(lo + 2 * width, n)
            i, j, k = lo, mid, lo
            while i < mid and j < hi:
                if ranks_before(S[order[j]], S[order[i]]):  # strictly: ties keep the left
                    buf[k] = order[j]
                    j += 1
                else:
                    buf[k] = order[i]
                    i += 1
                k += 1
            while i < mid:
                buf[k], i, k = order[i], i + 1, k + 1
            while j < hi:
                buf[k], j, k = order[j], j + 1, k + 1
        for i in range(n):
            order[i] = buf[i]
        width *= 2
    return order


def ranking_fitness(F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
    """A scalar with the feasibility-first order: F if feasible, else worst feasible F + CV."""
    if CV is None:
        return F
    F = kernel_array(F)
    return ranking_into(F, kernel_array(CV), np.empty(F.size))


def best_index(F: np.ndarray, CV: np.ndarray | None) -> int:
    """Index of the feasibility-first best row."""
    if CV is None:
        return int(np.argmin(F))
    feas = CV <= 0.0
    if feas.any():
        idx = np.flatnonzero(feas)
        return int(idx[np.argmin(F[idx])])
    return int(np.argmin(CV))


def mantegna_sigma(beta: float) -> float:
    """Scale ``sigma_u`` of the numerator in Mantegna's Levy-stable step
    (Mantegna 1994): ``(G(1+b) sin(pi b/2) / (G((1+b)/2) b 2^((b-1)/2)))^(1/b)``."""
    num = math.gamma(1.0 + beta) * math.sin(math.pi * beta / 2.0)
    den = math.gamma((1.0 + beta) / 2.0) * beta * 2.0 ** ((beta - 1.0) / 2.0)
    return (num / den) ** (1.0 / beta)


def mantegna_levy(shape: tuple[int, ...], beta: float, *,
                  rng: np.random.Generator) -> np.ndarray:
    """Symmetric Levy-stable steps ``sigma u / |v|^(1/beta)`` (u, v standard normal,
    drawn in that order), unscaled: FPA, MPA, HHO, MODA and I-BES multiply by
    their own factor (0.01 or 0.05)."""
    u = rng.standard_normal(shape) * mantegna_sigma(beta)
    v = rng.standard_normal(shape)
    return u / np.abs(v) ** (1.0 / beta)
