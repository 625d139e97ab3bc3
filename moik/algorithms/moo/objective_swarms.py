"""One single-objective swarm per objective, sharing one archive (the MO-m-PSO construction).

Rokbani, Neji, Slim, Mirjalili & Ghandour, "A Multi-Objective Modified PSO for
Inverse Kinematics of a 5-DOF Robotic Arm", Applied Sciences 12, 7091 (2022),
DOI 10.3390/app12147091, Section 2.2 and Algorithm 2, build a multi-objective
method from a single-objective one as "a set of mono-objective ... instances,
where each instance is in charge of a single objective", "set to the same
number of particles, similar ... parameters, and the same maximum iterations
number"; the Pareto front of all evaluated points gives the compromise closest
to the utopia point (Eq. 8). The paper compares MO-m-PSO with MO-PSO, MO-JAYA
and MO-CSA built this way.

This module holds the mechanics those four methods share, once:

- M = ``n_obj`` swarms of ``pop_size`` rows each, advanced together as one
  (M * pop_size, n_var) array; rows ``k N .. (k + 1) N - 1`` form swarm k and
  ``swarm[i]`` is the objective row i works on;
- ``S``: each row's fitness on its own objective (:func:`own_objective`);
- a greedy personal-best memory on that fitness (``pbest_X``/``pbest_S``,
  strictly better replaces, :func:`moik.algorithms.mechanics.greedy_memory`);
- per-swarm best/worst rows (:func:`swarm_extreme`) and random partners inside
  the same swarm (:func:`swarm_partners`);
- every evaluated row of every swarm is offered to the shared archive (the
  base class), ``res.X``/``res.F`` is its front and ``moik.metrics.compromise(res)``
  picks the member closest to the utopia point.

Constraints (not in the paper): the memory and the swarm bests compare
feasibility first (:func:`~moik.algorithms.mechanics.is_better` on the swarm's
objective and the total violation), the shared archive uses constraint-domination,
and until a feasible point is found the feasibility search of the multi-objective base
runs beside the swarms (a moik extension, :mod:`moik.algorithms.moo.feasibility_search`).

Evaluations: M * pop_size for the initial population and, by default, per iteration.
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.initial_survival import best_rows
from moik.algorithms.mechanics import greedy_memory, is_better, ranking_fitness
from moik.algorithms.moo.base import MOArrayAlgorithm


def own_objective(F: np.ndarray, swarm: np.ndarray) -> np.ndarray:
    """Each row's fitness on the objective of its swarm: ``F[i, swarm[i]]``."""
    return F[np.arange(len(F)), swarm]


def swarm_extreme(P: np.ndarray, S: np.ndarray, n_swarms: int, *,
                  worst: bool = False) -> np.ndarray:
    """Best (or worst) row of every swarm, repeated per row, shape (M * N, d).

    Args:
        P: Positions, shape (M * N, d), swarm k in rows ``k N .. (k + 1) N - 1``.
        S: Their fitness on the swarm's objective, shape (M * N,).
        n_swarms: Number of swarms M.
        worst: Return the largest fitness instead of the smallest (first on ties).
    """
    N = len(S) // n_swarms
    S = S.reshape(n_swarms, N)
    pick = S.argmax(axis=1) if worst else S.argmin(axis=1)
    return np.repeat(P[pick + N * np.arange(n_swarms)], N, axis=0)


def swarm_best(P: np.ndarray, S: np.ndarray, n_swarms: int) -> np.ndarray:
    """Global best position of every swarm, repeated per particle, shape (M * N, d)."""
    return swarm_extreme(P, S, n_swarms)


def utopia_closest(F: np.ndarray) -> int:
    """Row of ``F`` closest (Euclidean) to the utopia point, objectives scaled to [0, 1].

    Eq. 8 of the MO-m-PSO paper: the utopia point is each objective's minimum over
    ``F``; each objective is scaled by its range over ``F`` (a constant one counts
    0) so that units (cm vs rad) do not decide. The same rule as
    :func:`moik.metrics.closest_to_utopia` (first row on ties), written here because
    the algorithms do not import the metrics.
    """
    lo, hi = F.min(axis=0), F.max(axis=0)
    Z = (F - lo) / np.where(hi > lo, hi - lo, 1.0)
    return int(np.argmin(np.linalg.norm(Z, axis=1)))


def swarm_partners(n_swarms: int, N: int, *, rng: np.random.Generator) -> np.ndarray:
    """A uniformly drawn row index of the same swarm for every row, shape (M * N,)."""
    return rng.integers(N, size=n_swarms * N) + N * np.repeat(np.arange(n_swarms), N)


class ObjectiveSwarms(MOArrayAlgorithm):
    """Base of the per-objective-swarm methods (MO-m-PSO, MO-PSO, MO-JAYA, MO-CSA).

    Public arrays (numpy; rows of swarm k are ``k N .. (k + 1) N - 1``): ``swarm``
    (objective index of each row), ``X``/``F``/``S`` (current rows, their
    objective vectors and their fitness on the swarm's objective; ``CV`` their
    violations or None), ``pbest_X``/``pbest_F``/``pbest_S``/``pbest_CV`` (greedy memory
    on ``S``, feasibility first).

    Args:
        pop_size: Rows per swarm N (one swarm per objective).
        archive_size: Archive capacity; None means ``pop_size``.
        X0: Optional initial points (more than M * pop_size rows: each swarm the best on
            its objective, :meth:`_initial_survivors`).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def _n_initial(self) -> int:
        return self.problem.n_obj * self.pop_size

    def _evals_per_iteration(self) -> float:
        return float(self.problem.n_obj * self.pop_size)

    def _initial_survivors(self, F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
        """Of a larger initial sample, swarm k takes the ``pop_size`` best rows on objective
        k, feasibility first (a row may start in several swarms)."""
        return np.concatenate([best_rows(F[:, k], CV, self.pop_size)
                               for k in range(self.problem.n_obj)])

    def _initialize_state(self) -> None:
        self.swarm = np.repeat(np.arange(self.problem.n_obj), self.pop_size)
        self.S = own_objective(self.F, self.swarm)
        self.pbest_X, self.pbest_F, self.pbest_S = self.X, self.F, self.S
        self.pbest_CV = self.CV

    def _pbest_rank(self) -> np.ndarray:
        """The memories' fitness in feasibility-first order (``pbest_S`` if unconstrained)."""
        return ranking_fitness(self.pbest_S, self.pbest_CV)

    def _remember(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None) -> None:
        """Take the evaluated rows as current and update the greedy memory on ``S``."""
        self.X, self.F, self.CV, self.S = X, F, CV, own_objective(F, self.swarm)
        better = is_better(self.S, CV, self.pbest_S, self.pbest_CV)[:, None]
        self.pbest_F = np.where(better, F, self.pbest_F)
        self.pbest_X, self.pbest_S, self.pbest_CV = greedy_memory(
            X, self.S, CV, self.pbest_X, self.pbest_S, self.pbest_CV)
