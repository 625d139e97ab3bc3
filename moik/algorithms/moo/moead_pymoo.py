"""MOEA/D: pymoo's, with default reference directions (registered as ``moead-pymoo``).

Zhang & Li, "MOEA/D: A Multiobjective Evolutionary Algorithm Based on
Decomposition", IEEE Transactions on Evolutionary Computation 11(6), 712-731
(2007), DOI 10.1109/TEVC.2007.892759, as implemented by pymoo. pymoo's ``MOEAD``
needs reference directions at construction; :class:`MOEAD` here is pymoo's with
a default: when ``ref_dirs`` is None, the Das-Dennis directions for the
problem's number of objectives are built at setup with the most partitions that
give at most ``pop_size`` directions (for two objectives:
``n_partitions = pop_size - 1``, exactly ``pop_size`` directions).

Constraints: pymoo's MOEA/D refuses constrained problems. Here an offspring
replaces a neighbour by constraint-domination of the decomposed values (feasible
first, then smaller total violation, then the smaller decomposed value), the rule
pymoo's source leaves commented out; ``res.F`` is pymoo's feasible non-dominated
set of the population. The decomposed values of feasible points are taken from
the best feasible value per objective seen so far (``feasible_ideal``), not from
pymoo's ideal point of every evaluated point: infeasible points may lie far
beyond the feasible front (OSY: f1 of infeasible points goes far below the
feasible minimum), and an ideal point there draws all subproblems to the same
few feasible points (measured on OSY, 25,000 evaluations, 3 seeds: 26 feasible
members reported in all, HV 61 % of NSGA-II's; with the feasible ideal point
100 per run, 72 %). Unconstrained runs are pymoo's, bit for bit.

A ``sampling=`` of more points than directions (pymoo's biased initialization): all are
evaluated and NSGA-II's rank and crowding keeps one per direction
(:func:`~moik.algorithms.initial_survival.surviving_population`; pymoo's own MOEA/D keeps
them all and then fails on its neighbourhood indices).
pymoo's NSGA2 and SMS-EMOA are registered unchanged, MOPSO-CD with constraint
handling (:mod:`moik.algorithms.moo.mopso_cd`).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pymoo.algorithms.moo import moead
from scipy.spatial.distance import cdist

from moik._validate import integer, interval
from moik.algorithms.array_state import refuse_unknown_keywords
from moik.algorithms.initial_survival import surviving_population
from moik.algorithms.meta import setup_through_wrapper
from moik.algorithms.moo.reference_directions import default_ref_dirs
from moik.exceptions import ParameterError


class PymooMOEAD(moead.MOEAD):
    """pymoo's MOEA/D with default reference directions (see the module doc).

    Args:
        ref_dirs: Reference directions (n, n_obj), or None for Das-Dennis ones.
        pop_size: Number of directions when ``ref_dirs`` is None, an integer >= 2.
        **kwargs: pymoo ``MOEAD`` options (``n_neighbors``, ``decomposition`` ...) and
            pymoo ``Algorithm`` options.

    Raises:
        ParameterError: For a keyword pymoo's ``MOEAD`` does not take (listing the
            accepted ones), a bad ``pop_size``, ``n_neighbors`` (an integer >= 1) or
            ``prob_neighbor_mating`` (in [0, 1]); at setup, for a problem with one
            objective.
    """

    ref_dirs: np.ndarray
    decomposition: Any  # pymoo's decomposition (Tchebicheff, PBI ...), chosen in setup()

    def __init__(self, *, ref_dirs: np.ndarray | None = None, pop_size: int = 100, **kwargs):
        refuse_unknown_keywords(type(self), kwargs)
        self._n_dirs = integer("pop_size", pop_size, minimum=2)
        if "n_neighbors" in kwargs:
            integer("n_neighbors", kwargs["n_neighbors"], minimum=1)
        if "prob_neighbor_mating" in kwargs:
            interval("prob_neighbor_mating", kwargs["prob_neighbor_mating"], 0.0, 1.0)
        self._default_dirs = ref_dirs is None
        dirs = default_ref_dirs(2, self._n_dirs) if ref_dirs is None else ref_dirs
        super().__init__(ref_dirs=dirs, **kwargs)

    def setup(self, problem, **kwargs):
        """pymoo's, also inside a wrapper that skips ``_setup`` (:mod:`moik.algorithms.meta`)."""
        setup_through_wrapper(self, super().setup, problem, **kwargs)
        return self

    def _setup(self, problem, **kwargs) -> None:
        self._problem_read = True
        if problem.n_obj < 2:  # pymoo's fails with numpy's "larger sample than population"
            raise ParameterError(f"MOEA/D is multi-objective; the problem has "
                                 f"n_obj={problem.n_obj}")
        if self._default_dirs and self.ref_dirs.shape[1] != problem.n_obj:
            self.ref_dirs = default_ref_dirs(problem.n_obj, self._n_dirs)
        if not problem.has_constraints():
            super()._setup(problem, **kwargs)
            return
        # pymoo's _setup without its refusal of constraints
        self.pop_size = len(self.ref_dirs)
        self.neighbors = np.argsort(cdist(self.ref_dirs, self.ref_dirs), axis=1,
                                    kind="quicksort")[:, : self.n_neighbors]
        if self.decomposition is None:
            self.decomposition = moead.default_decomp(problem)

    def _initialize_advance(self, infills=None, **kwargs) -> None:
        if infills is not None and len(infills) > len(self.ref_dirs):  # a larger sample=
            infills = self.pop = surviving_population(infills, len(self.ref_dirs))
        super()._initialize_advance(infills, **kwargs)
        if self.problem.has_constraints():
            F, CV = self.pop.get("F"), self.pop.get("CV")[:, 0]
            self.feasible_ideal = np.min(np.vstack([np.full(F.shape[1], np.inf), F[CV <= 0.0]]),
                                         axis=0)

    def _replace(self, k, off) -> None:
        """pymoo's replacement; with constraints by constraint-domination (module doc)."""
        if not self.problem.has_constraints():
            super()._replace(k, off)
            return
        pop, N = self.pop, self.neighbors[k]
        CV, off_CV = pop[N].get("CV")[:, 0], float(off.CV[0])
        if off_CV > 0.0:  # replaces only infeasible neighbours of a larger violation
            better = (CV > 0.0) & (off_CV < CV)
        else:
            self.feasible_ideal = np.minimum(self.feasible_ideal, off.F)
            FV = self.decomposition.do(pop[N].get("F"), weights=self.ref_dirs[N, :],
                                       ideal_point=self.feasible_ideal)
            off_FV = self.decomposition.do(off.F[None, :], weights=self.ref_dirs[N, :],
                                           ideal_point=self.feasible_ideal)
            better = np.where(CV <= 0.0, off_FV < FV, True)
        pop[N[np.flatnonzero(better)]] = off
