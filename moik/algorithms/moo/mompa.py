"""MOMPA: multi-objective marine predators algorithm (reference-point selection).

Zhong, Zhou, Deng, Zhou & Luo, "MOMPA: Multi-objective marine predator
algorithm", Computer Methods in Applied Mechanics and Engineering 385, 114029
(2021), DOI 10.1016/j.cma.2021.114029 (the MOMPA of the EOSMA paper, Yin et al.
2022, DOI 10.1038/s41598-022-13516-3, its ref. 54 and Table 4), as the authors'
MATLAB code ``mompa.m`` does it (``EnvironmentalSelection.m``,
``mompa_Gaussian_search.m``, ``UniformPoint.m``; read in the copy of
github.com/mxd888/MOAOA_For_MOVRPD, ``MO_For_CEC2020/MOMPA``). MPA's operators
(Faramarzi et al. 2020, DOI 10.1016/j.eswa.2020.113377,
:mod:`moik.algorithms.soo.mpa`) on a population kept by NSGA-III's
reference-point environmental selection:

- reference points ``Z``: the Das-Dennis points with the most divisions giving at
  most ``pop_size`` of them (``UniformPoint``; 100 for two objectives, 91 for three
  at ``pop_size=100``), which sets the population size N; ``Zmin`` the ideal point
  of every evaluated row;
- the Elite of Eq. 10 is one random member of the previous population, repeated
  in every row;
- the phase move (Eqs. 12-15), then the FADs step (Eq. 16) on its result, then a
  Gaussian search on that: one random coordinate per row moves by
  ``(ub - lb) N(0, 1)``; each result clipped to the bounds;
- the previous population and the three new sets (4N rows, duplicates dropped) go
  through the environmental selection (:func:`reference_point_selection`):
  non-dominated sorting until N rows are ranked, then the last front is filled
  by niching on the normalised reference points (NSGA-III, as
  ``EnvironmentalSelection.m``/``LastSelection``).

Every evaluated row is also offered to the external crowding-radius archive
(capacity ``archive_size``, default ``pop_size``): ``res.X``/``res.F`` are its
members, as for every moik multi-objective method (the code reports the final
population).

Defaults (EOSMA Table 4): P=0.5, FADs=0.2. Evaluations: 3N per iteration (the
code re-evaluates the previous population too, 4N).

Deviations and readings:
- No archive guides the search (as in the authors' code): the Elite is drawn from the
  population, which the selection above keeps.
- The previous population is not re-evaluated (its objectives are known).
- Phase boundaries and the FADs branch are moik's MPA readings (``t = T/3`` is
  phase 2 here; the code sends it to phase 3).
- Normalisation: where the hyperplane through the extreme points is singular or
  gives a non-positive or non-finite intercept, the per-objective maximum is used
  (the code falls back only on NaN).
- The duplicate removal keeps MATLAB's ``unique(..., 'rows')`` order (rows sorted).
- Constraints (not in the code): the sorting puts the feasible rows first
  (non-dominated fronts), then the infeasible ones by increasing violation, each
  its own front (constraint-domination, as PlatEMO's NDSort with constraints).

While no feasible point was seen, the archive keeps its capacity of least infeasible
rows (a moik extension, :mod:`moik.algorithms.archive.base`; a strict
constraint-domination filter would keep only the least infeasible row, and every leader
would be it), and until a feasible point is found a companion DE population searches
for one (a moik extension, :mod:`moik.algorithms.moo.feasibility_search`). Infeasible
output on pymoo's MW and CTP problems with and without it, method or handling:
docs/results/constrained-moo.md (``studies/constrained_moo.py``).
"""

from __future__ import annotations

import numpy as np
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik._validate import interval
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.moo.reference_directions import default_ref_dirs
from moik.algorithms.soo.mpa import fads_effect, mpa_cf, mpa_phase, predator_move
from moik.exceptions import ParameterError


def front_numbers(F: np.ndarray, CV: np.ndarray | None, n: int) -> np.ndarray:
    """Front number of every row (0 = best) until ``n`` rows are ranked; later rows get -1.

    Feasible rows are sorted by Pareto dominance; infeasible ones follow by increasing
    violation, one row per front (``NDSort.m`` with constraints).
    """
    m = len(F)
    front = np.full(m, -1, dtype=np.int64)
    feas = np.arange(m) if CV is None else np.flatnonzero(CV <= 0.0)
    ranked = 0
    if feas.size:
        for k, members in enumerate(NonDominatedSorting().do(F[feas], n_stop_if_ranked=n)):
            front[feas[members]] = k
            ranked += len(members)
    if CV is not None and ranked < n:
        bad = np.flatnonzero(CV > 0.0)
        bad = bad[np.argsort(CV[bad], kind="stable")][: n - ranked]
        front[bad] = (front.max() + 1) + np.arange(bad.size)
    return front


def _normalised(F: np.ndarray, z_min: np.ndarray) -> np.ndarray:
    """LastSelection's normalisation: translate by ``z_min``, divide by the intercepts."""
    P = F - z_min
    M = P.shape[1]
    w = np.full((M, M), 1e-6) + np.eye(M)
    extreme = [int(np.argmin(np.max(P / w[i], axis=1))) for i in range(M)]
    try:
        a = 1.0 / np.linalg.solve(P[extreme], np.ones(M))
    except np.linalg.LinAlgError:
        a = np.full(M, np.nan)
    if not np.all(np.isfinite(a) & (a > 0)):
        a = P.max(axis=0)
    return P / np.where(a > 0, a, 1.0)


def reference_point_selection(F: np.ndarray, CV: np.ndarray | None, n: int, Z: np.ndarray,
                              z_min: np.ndarray, *, rng: np.random.Generator) -> np.ndarray:
    """NSGA-III environmental selection (``EnvironmentalSelection.m``): ``n`` row indices.

    Args:
        F: Objective values (m, M), m >= n. CV: Violations (m,) or None.
        n: Number of rows to keep. Z: Reference points (k, M). z_min: Ideal point (M,).
        rng: Random generator (ties between reference points and members).

    Returns:
        Sorted indices of the kept rows.
    """
    front = front_numbers(F, CV, n)
    last = front.max()
    chosen = np.flatnonzero((front >= 0) & (front < last))
    candidates = np.flatnonzero(front == last)
    k = n - chosen.size
    if k >= candidates.size:
        return np.sort(np.concatenate([chosen, candidates]))
    P = _normalised(F[np.concatenate([chosen, candidates])], z_min)
    norm = np.sqrt(np.sum(P * P, axis=1))
    cosine = (P @ Z.T) / np.maximum(norm[:, None] * np.sqrt(np.sum(Z * Z, axis=1))[None, :],
                                    np.finfo(float).tiny)
    distance = norm[:, None] * np.sqrt(np.maximum(1.0 - cosine**2, 0.0))
    niche, d = distance.argmin(axis=1), distance.min(axis=1)
    rho = np.bincount(niche[: chosen.size], minlength=len(Z))
    n1 = chosen.size
    take = np.zeros(candidates.size, dtype=bool)
    open_ = np.ones(len(Z), dtype=bool)
    while take.sum() < k:
        idx = np.flatnonzero(open_)
        least = idx[np.flatnonzero(rho[idx] == rho[idx].min())]
        j = least[rng.integers(least.size)]
        I = np.flatnonzero(~take & (niche[n1:] == j))  # noqa: E741
        if I.size:
            s = int(np.argmin(d[n1 + I])) if rho[j] == 0 else int(rng.integers(I.size))
            take[I[s]] = True
            rho[j] += 1
        else:
            open_[j] = False
    return np.sort(np.concatenate([chosen, candidates[take]]))


def gaussian_search(X: np.ndarray, xl: np.ndarray, xu: np.ndarray, *,
                    rng: np.random.Generator) -> np.ndarray:
    """``mompa_Gaussian_search.m``: one random coordinate per row ``+= (ub - lb) N(0, 1)``."""
    n, d = X.shape
    X = X.copy()
    for i in range(n):  # the code draws the coordinate, then the normal number, row by row
        j = int(rng.integers(d))
        X[i, j] += (xu[j] - xl[j]) * rng.standard_normal()
    return clip_to_bounds(X, xl, xu)


class MOMPA(MOArrayAlgorithm):
    """MOMPA (Zhong et al. 2021) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays: ``Z`` (reference points; their number is the population size),
    ``z_min`` (ideal point), ``elite`` (Elite of the last iteration). ``X``/``F``/``CV``
    is the selected population.

    Args:
        pop_size: Requested number of search agents (Table 4: 100); the population is
            the number of Das-Dennis points that fit in it.
        archive_size: Archive capacity; None means ``pop_size`` (Table 4: 100).
        P: Step constant in (0, 2] (Table 4: 0.5).
        FADs: Fish-aggregating-devices probability in [0, 1] (Table 4: 0.2).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 P: float = 0.5, FADs: float = 0.2, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.P = interval("P", P, 0.0, 2.0, lo_open=True)
        self.FADs = interval("FADs", FADs, 0.0, 1.0)

    def _setup(self, problem, **kwargs) -> None:
        if problem.n_obj < 2:  # the base refuses it too, after Z is needed
            raise ParameterError(f"MOMPA is multi-objective; the problem has n_obj={problem.n_obj}")
        self.Z = np.maximum(default_ref_dirs(problem.n_obj, self.pop_size), 1e-6)
        super()._setup(problem, **kwargs)

    def _n_initial(self) -> int:
        return len(self.Z)

    def _evals_per_iteration(self) -> float:
        return 3.0 * len(self.Z)

    def _initial_survivors(self, F: np.ndarray, CV: np.ndarray | None) -> np.ndarray:
        """Every row of a larger initial sample: the reference-point selection of
        :meth:`_initialize_state` keeps the population."""
        return np.arange(len(F))

    def _initialize_state(self) -> None:
        self.z_min = self.F.min(axis=0)
        self._select(self.X, self.F, self.CV)

    def _select(self, X, F, CV) -> None:
        keep = reference_point_selection(F, CV, len(self.Z), self.Z, self.z_min,
                                         rng=self.random_state)
        self.X, self.F = X[keep], F[keep]
        self.CV = None if CV is None else CV[keep]

    def _generation(self) -> Step:
        rng, n = self.random_state, len(self.Z)
        self.elite = self.X[rng.integers(n)]  # Eq. 10: a random member of the population
        CF = mpa_cf(self.t, self.max_iter)
        X_evo = clip_to_bounds(predator_move(self.X, self.elite, mpa_phase(self.t, self.max_iter),
                                             CF, P=self.P, rng=rng), self.xl, self.xu)
        X_fads = clip_to_bounds(fads_effect(X_evo, CF, FADs=self.FADs, xl=self.xl, xu=self.xu,
                                            rng=rng), self.xl, self.xu)  # Eq. 16
        X_new = np.concatenate([X_evo, X_fads, gaussian_search(X_fads, self.xl, self.xu, rng=rng)])
        F_new, CV_new = yield X_new
        finite = np.all(np.isfinite(F_new), axis=1)  # rows left unevaluated by the budget
        if finite.any():
            self.z_min = np.minimum(self.z_min, F_new[finite].min(axis=0))
        X = np.concatenate([self.X, X_new[finite]])
        F = np.concatenate([self.F, F_new[finite]])
        CV = None if self.CV is None else np.concatenate([self.CV, CV_new[finite]])
        _, first = np.unique(X, axis=0, return_index=True)  # unique(two_Prey, 'rows')
        self._select(X[first], F[first], None if CV is None else CV[first])
