"""Multi-objective equilibrium optimizer slime mould algorithm (MOEOSMA).

Yin, Luo, Zhou, Zhou & Zhu, "An equilibrium optimizer slime mould algorithm for
inverse kinematics of the 7-DOF robotic manipulator", Scientific Reports 12,
9421 (2022), DOI 10.1038/s41598-022-13516-3: Algorithm 2, Figs. 2-3, Eqs. 11,
15-21. EOSMA's operators (:mod:`moik.algorithms.soo.eosma`) with:

- the external archive (:class:`~moik.algorithms.archive.CrowdingArchive`,
  Eqs. 11, 19, 20): every evaluated batch is merged, the non-dominated rows
  kept, duplicates dropped, overflow removed by roulette on the crowding count;
- the equilibrium pool = the archive members with the smallest crowding count
  ("the food source"), redrawn each iteration; ``Xeq`` (EO operator) and
  ``gBest`` (SMA operator) of Eq. 15 are drawn uniformly from it per agent;
- Eq. 21 rotation sorting: iteration t sorts the personal-best fitness on
  objective ``O = rem(t, M) + 1`` (1-based; index ``t % M`` here, with t = 1
  in the first iteration as in the paper) to compute the SMA weights (Eq. 4);
- Eq. 17 midpoint repair toward the agent's personal best (the retained
  position ``Xold`` of MOEOSMA.m, as moik's EOSMA), Eq. 16 random difference
  mutation (probability q, one draw per iteration, Algorithm 2 line 26), Eq. 18
  greedy memory.

Greedy memory with several objectives (Eq. 18, "save better solutions"): the
paper does not define "better" for objective vectors. The authors' MOEOSMA.m
keeps the old position only when it is strictly better in every objective
(``if fit_old(k,:) < Fitness(k,:)``) and otherwise takes the new one. Here the
old personal best is kept exactly when it Pareto-dominates the new point
(Eq. 11, :func:`~moik.algorithms.moo.dominance.dominance_memory`); a new point that is
better in one objective, incomparable or equal replaces it.

Defaults (Table 4): z=0.5, q=1, V=1, GP=0.5, a1=2, a2=2, N = archive = 100
(Table 8: T = 1000). Evaluations: N (1 + q) per iteration on average (the
Eq. 15 positions, then the Eq. 16 mutants when the mutation fires).

Deviations and readings:
- ``Xeq`` and ``gBest`` are independent uniform draws from the pool (the code
  uses one draw for both; the text draws "a solution" for gBest).
- Mutation as printed (Eq. 16, ``SF ~ U[0.3, 0.6]``, probability q). The
  authors' MOEOSMA.m instead applies ``X + SF (X_R1 - X_R2)`` with
  ``SF ~ U[0.2, 1]`` every iteration.
- The archive follows Eq. 11 (ordinary dominance; the code: strict) and Eq. 20
  probabilities over the merged set (see the archive module).
- The two evaluated batches of an iteration enter the archive in one merge
  at the end of the iteration (Algorithm 2 merges after each, lines 7 and 29).
  The archive is not read in between, so the non-dominated set is the same;
  the roulette truncation (Eq. 20) runs once on the union. This saves one
  archive update per iteration (about 17% of a Table 8 P2 run).
- Constraints (not in the paper): constraint-domination in the archive and the
  memory; the Eq. 21 sort ranks feasible rows by the objective, infeasible ones
  after them by violation (:func:`~moik.algorithms.mechanics.ranking_fitness`).

The paper's method loses its front on some benchmark fronts (measured with
``studies/moo_quality.py``, 25,000 evaluations, population 100, 10 seeds): on ZDT2
every archive member ends at f1 ~ 0 (HV 20 % of NSGA-II's, every seed), on ZDT6 the
front is reached only in part (HV 64 %), on ZDT3 92 %. The line-by-line port of the authors'
MOEOSMA.m collapses on ZDT2 alike (4 of 5 seeds), so it is the method, not this
implementation. Cause, measured: on ZDT2 the early non-dominated points all have a
small f1 (the front is concave and g is large, so f1 decides dominance); the EO
operator contracts every agent towards them (its z = 1 variant collapses, z = 0
does not), the Pareto memory accepts every such move, and no operator adds
variation at the scale of the box, so x1 shrinks geometrically before g converges.
Leader choice is not the cause (leaders drawn from the whole archive collapse alike).

``diversity="nsga2-gaussian"`` (not in the paper) fixes it with two changes, both
needed (each alone leaves ZDT2 or ZDT6 collapsed): the personal-best memory of
Eq. 18 is replaced by NSGA-II's elitist survival of the memory and the new batch
(non-domination rank, then crowding distance; the memory keeps dominated points
spread over the front), and every Eq. 16 mutant then gets MOMPA's Gaussian search
(one random coordinate moves by ``(ub - lb) N(0, 1)``,
:func:`moik.algorithms.moo.mompa.gaussian_search`), the variation at the scale of
the box the paper's operators lack. Measured: the ``moeosma-nsga2-gaussian`` rows of
the ``moo-suite`` experiment (docs/results/moo-suite.md: 95 % of NSGA-II's HV or more
on ZDT1/2/3/6) and Table 8 in docs/results/moo-quality.md (P1: about the paper's
method's HV, with a front reaching further towards both ends; P2: the full box).

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

from moik._jit import kernel_array
from moik._validate import choice, interval
from moik.algorithms.archive import CrowdingArchive
from moik.algorithms.generator_handle import GeneratorHandles
from moik.algorithms.mechanics import ranking_fitness
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.moo.dominance import dominance_memory
from moik.algorithms.moo.moeosma_kernels import generation_draws
from moik.algorithms.moo.mompa import gaussian_search
from moik.algorithms.moo.mosma import elitist_order
from moik.algorithms.soo.eo import eo_schedule
from moik.algorithms.soo.eosma_kernels import (
    GenerationDraws,
    generation_candidates,
    mutation_candidates,
)
from moik.algorithms.soo.sma import sma_schedule

DIVERSITY = ("paper", "nsga2-gaussian")


def rotation_objective(t: int, n_obj: int) -> int:
    """Eq. 21: zero-based index of the objective sorted at iteration t (``rem(t, M)``)."""
    return t % n_obj


def equilibrium_pool(X: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The archive members with the smallest crowding count (MOEOSMA's equilibrium pool)."""
    return X[counts == counts.min()]


class MOEOSMA(MOArrayAlgorithm):
    """MOEOSMA (Yin et al. 2022) with array state; ``res.X``/``res.F`` = the archive.

    Extra public arrays: ``pbest_X``/``pbest_F``/``pbest_CV`` (personal bests, Eq. 18) and
    ``pool_X`` (equilibrium pool of the last iteration). ``X``/``F`` are the
    last evaluated positions. ``moik.metrics.compromise(res)`` picks the member
    closest to the utopia point.

    Args:
        pop_size: Number of agents N (paper: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper: 100).
        z: Probability of the EO operator in [0, 1] (paper: 0.5).
        q: Mutation probability in [0, 1] (paper: 1).
        V: Control volume, > 0 (paper: 1).
        GP: Generation probability in [0, 1] (paper: 0.5).
        a1: Exploration factor in (0, 10] (paper: 2).
        a2: Exploitation factor in (0, 10] (paper: 2).
        diversity: ``"paper"`` (Eq. 18 memory, the paper's method) or
            ``"nsga2-gaussian"`` (NSGA-II elitist memory and a Gaussian search on the
            mutants, which keeps the front on ZDT2/ZDT6; see the module doc).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    pareto_archive: CrowdingArchive  # the base's default (MOEOSMA's crowding count)

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None, z: float = 0.5,
                 q: float = 1.0, V: float = 1.0, GP: float = 0.5, a1: float = 2.0,
                 a2: float = 2.0, diversity: str = "paper", max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.z = interval("z", z, 0.0, 1.0)
        self.q = interval("q", q, 0.0, 1.0)
        self.V = interval("V", V, 0.0, np.inf, lo_open=True, hi_open=True)
        self.GP = interval("GP", GP, 0.0, 1.0)
        self.a1 = interval("a1", a1, 0.0, 10.0, lo_open=True)
        self.a2 = interval("a2", a2, 0.0, 10.0, lo_open=True)
        self.diversity = choice("diversity", diversity, DIVERSITY)

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + self.q)

    def _initialize_state(self) -> None:
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV
        self._bounds = np.stack([self.xl, self.xu]).astype(float)
        self._draws = GenerationDraws(self.pop_size, self.problem.n_var)
        self._leaders = np.empty(self.pop_size, dtype=np.int64)
        self._handles = GeneratorHandles()
        self.pool_X = equilibrium_pool(self.pareto_archive.X, self.pareto_archive.counts)

    def _remember(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None) -> None:
        """Eq. 18 (Pareto form) after an evaluation; the archive was updated on evaluation."""
        self.X, self.F, self.CV = X, F, CV
        if self.diversity == "paper":
            self.pbest_X, self.pbest_F, self.pbest_CV = dominance_memory(
                X, F, CV, self.pbest_X, self.pbest_F, self.pbest_CV)
            return
        PX, PF = np.concatenate([self.pbest_X, X]), np.concatenate([self.pbest_F, F])
        PCV = None if CV is None else np.concatenate([self.pbest_CV, CV])
        finite = np.all(np.isfinite(PF), axis=1)  # rows left unevaluated by the budget
        PX, PF, PCV = PX[finite], PF[finite], None if PCV is None else PCV[finite]
        keep, _ = elitist_order(PF, self.pop_size, PCV)  # NSGA-II survival
        self.pbest_X, self.pbest_F = PX[keep], PF[keep]
        self.pbest_CV = None if PCV is None else PCV[keep]

    def _population_arrays(self):
        return self.pbest_X, self.pbest_F, self.pbest_CV

    def _generation(self) -> Step:
        """Algorithm 2, one iteration: its own draw order (:mod:`.moeosma_kernels`), EOSMA's
        maths (:mod:`moik.algorithms.soo.eosma_kernels`) with one leader per agent."""
        A = self.pareto_archive
        self.pool_X = pool = kernel_array(equilibrium_pool(A.X, A.counts))  # line 12
        obj = rotation_objective(self.t, self.problem.n_obj)  # Eq. 21
        S = kernel_array(ranking_fitness(self.pbest_F[:, obj], self.pbest_CV))
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        a, _ = sma_schedule(self.t, self.max_iter)
        draws, leaders = self._draws, self._leaders
        mutate = generation_draws(self._handles.of(self.random_state), S, len(pool), t1, a,
                                  self.q, leaders, draws.cells, draws.rows, draws.picks)
        draws.apply_numpy_maths()  # Eqs. 4 and 8
        P = kernel_array(self.pbest_X)
        X = generation_candidates(P, pool[leaders], pool, draws.cells, draws.rows, draws.picks,
                                  self.z, self.a1, self.GP, self.V, self._bounds)  # Eqs. 4, 15, 17
        F, CV = yield X
        self._remember(X, F, CV)
        if mutate:  # Algorithm 2, line 26
            X = mutation_candidates(kernel_array(self.pbest_X), draws.rows, draws.picks,
                                    self._bounds)  # Eqs. 16-17
            if self.diversity == "nsga2-gaussian":
                X = gaussian_search(X, self.xl, self.xu, rng=self.random_state)
            F, CV = yield X
            self._remember(X, F, CV)
