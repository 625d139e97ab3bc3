"""Feasibility search: a companion population that minimises the constraint violation while
a constrained run has found nothing feasible (a moik extension of every multi-objective
algorithm).

Why. On constrained problems whose feasible region is a narrow band along the front
(pymoo's MW1: the band is reached only when all 14 distance variables converge) most of the
papers' methods never reach it within 50,000 evaluations, with moik's constraint handling
and with the constraints ignored alike (docs/results/constrained-moo.md): their update
rules converge too slowly on the distance function, so a pymoo user who swaps one of them
in for NSGA-II got nothing back. Their papers and reference codes have no constraint
handling to follow.

What. While the run's archive holds no feasible member, every iteration of the method is
followed by generations of a companion population of ``pop_size`` rows (started from
the method's initial population) that minimises the total violation ``CV`` alone, as a
single-objective DE/rand/1/bin (Storn & Price 1997, J. Global Optim. 11, 341-359,
https://doi.org/10.1023/A:1008202821328):

- mutation, Eq. (1): ``v_i = x_r1 + F (x_r2 - x_r3)``, ``r1, r2, r3`` distinct and
  different from ``i``, ``F = 0.5``;
- binomial crossover, Eq. (2): component ``j`` from ``v_i`` when ``rand <= CR`` or
  ``j = j_rand``, ``CR = 0.1`` (Storn & Price's setting for separable functions: the
  violations of pymoo's MW and CTP problems are sums of per-variable terms);
- a component outside the bounds is set midway between the parent's value and the
  violated bound;
- selection, Eq. (3): the trial replaces its parent when its violation is not larger.

An iteration runs as many of these generations as give about the method's own evaluations
per iteration (at least one; MOPSO-CD, pymoo's loop, runs one), so the companion gets about
half the evaluations while it runs.

Every trial is offered to the archive like the method's own candidates, so the first
feasible trial makes the archive feasible; from then on the companion stops for good and
the method runs as published, its leaders drawn from the feasible archive. The
evaluations it used count in ``n_eval``; while it runs the schedule length T is planned
again every iteration, so the method's schedule ends with the budget.

Measured (pymoo's MW1 alone, 10 seeds, population 100): this DE reaches a feasible point in
every run within 7,900-14,500 evaluations; NSGA-II's constrained survival applied to the
violation alone (SBX and polynomial mutation, survival by violation) reaches one in 2,500-3,200
evaluations in 3 runs of 5 and stalls at violations 0.52-0.61 in the other 2 (its
population collapses onto a plateau of the distance function), and pymoo's NSGA-II itself
finds none in 3 of 10 runs of 20,000 evaluations. DE's one-to-one replacement keeps the
population spread. The per-algorithm effect: docs/results/constrained-moo.md.

A problem whose initial population holds a feasible point never starts the companion, and an
unconstrained problem never has one: those runs are bit for bit what they were.
"""

from __future__ import annotations

import numpy as np

SCALE = 0.5  # F of Eq. (1)
CROSSOVER_RATE = 0.1  # CR of Eq. (2)

__all__ = ["CROSSOVER_RATE", "SCALE", "FeasibilitySearch", "de_trials", "start_search"]


def de_trials(X: np.ndarray, xl: np.ndarray, xu: np.ndarray, rng: np.random.Generator, *,
              scale: float = SCALE, crossover_rate: float = CROSSOVER_RATE) -> np.ndarray:
    """DE/rand/1/bin trial vectors, one per row of ``X`` (Storn & Price 1997, Eqs. 1-2).

    Args:
        X: Population, shape (n, d) with n >= 4.
        xl, xu: Bounds, shape (d,).
        rng: The run's generator.
        scale: F of Eq. (1).
        crossover_rate: CR of Eq. (2).

    Returns:
        Trials, shape (n, d), within the bounds (a component past a bound is set midway
        between the parent's value and that bound).
    """
    n, d = X.shape
    # three distinct indices per row, none equal to the row: a random permutation of the
    # other n - 1 rows per target (argsort of uniform keys), then shifted past the row
    keys = rng.random((n, n - 1))
    r = np.argsort(keys, axis=1)[:, :3]
    r = r + (r >= np.arange(n)[:, None])
    V = X[r[:, 0]] + scale * (X[r[:, 1]] - X[r[:, 2]])
    V = np.where(xl > V, (xl + X) / 2, np.where(xu < V, (xu + X) / 2, V))
    take = rng.random((n, d)) <= crossover_rate
    take[np.arange(n), rng.integers(d, size=n)] = True
    return np.where(take, V, X)


class FeasibilitySearch:
    """The companion population (module doc): rows ``X`` and their violations ``CV``.

    Args:
        X: Starting rows (the method's initial population), shape (n, d), n >= 4.
        CV: Their total violations, shape (n,).
    """

    def __init__(self, X: np.ndarray, CV: np.ndarray) -> None:
        self.X = np.array(X, dtype=float)
        self.CV = np.array(CV, dtype=float)
        self.n_eval = 0

    def trials(self, xl: np.ndarray, xu: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """One generation's trial vectors (Eqs. 1-2)."""
        return de_trials(self.X, xl, xu, rng)

    def select(self, U: np.ndarray, CV: np.ndarray) -> None:
        """Eq. (3): each trial replaces its parent when its violation is not larger (rows
        the budget left unevaluated come back with an infinite violation and lose)."""
        self.n_eval += int(np.isfinite(CV).sum())
        better = CV <= self.CV
        self.X[better], self.CV[better] = U[better], CV[better]


def start_search(X: np.ndarray, CV: np.ndarray | None, size: int) -> FeasibilitySearch | None:
    """The companion for a run whose initial population is ``X`` with violations ``CV``:
    None for an unconstrained problem (``CV`` None), when a row is feasible, or with fewer
    than 4 rows (DE/rand/1 needs three others)."""
    if CV is None or bool(np.any(CV <= 0)) or min(size, len(CV)) < 4:
        return None
    return FeasibilitySearch(X[:size], CV[:size])
