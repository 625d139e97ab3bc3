"""MOEA/D: moik's array-state, compiled multi-objective evolutionary algorithm by decomposition.

Zhang & Li, "MOEA/D: A Multiobjective Evolutionary Algorithm Based on
Decomposition", IEEE Transactions on Evolutionary Computation 11(6), 712-731
(2007), DOI 10.1109/TEVC.2007.892759, Section III-A with the Tchebycheff approach
(Eq. 3), as pymoo 0.6 runs it (``pymoo.algorithms.moo.moead.MOEAD``, registered in
moik as ``moead-pymoo``, :mod:`moik.algorithms.moo.moead_pymoo`):

- weights: Das-Dennis directions, the most that give at most ``pop_size`` (two
  objectives: exactly ``pop_size``; :mod:`~moik.algorithms.moo.reference_directions`),
  or ``ref_dirs``; one subproblem per direction;
- neighbourhood B(i): the ``n_neighbors`` (T = 20) directions closest to direction i,
  itself included (pymoo's);
- mating (Step 2.1): two distinct parents from B(i) with probability ``delta`` (0.9),
  else from the whole population (the mating-pool rule of Li & Zhang, IEEE TEC 13(2)
  284-302, 2009, DOI 10.1109/TEVC.2008.925798, pymoo's ``prob_neighbor_mating``);
  pymoo's operators: SBX (``eta_c`` 20, one of its two children) and polynomial
  mutation (``eta_m`` 20, probability ``min(0.5, 1 / n_var)`` per variable);
- reference point z (Step 2.3): the best value per objective found;
- update of neighbours (Step 2.4): the offspring replaces each x_j, j in B(i), whose
  Tchebycheff value ``max_k lambda_jk |f_k - z_k|`` it lowers (strictly, as pymoo),
  at most ``nr`` of them (Li & Zhang 2009; None: no limit, as Zhang & Li 2007 and
  pymoo), visited in random order when ``nr`` limits them;
- external population (Step 2.5): moik's external archive of every evaluated point
  (capacity ``archive_size``, default ``pop_size``, crowding truncation; see
  :mod:`moik.algorithms.moo.base`), which is the result ``res.X``/``res.F``.

The loop is Zhang & Li's (and pymoo's ``MOEAD``): in each generation the subproblems
are visited in a random order, and each offspring is evaluated and applied (Steps
2.3-2.4) before the next subproblem mates, so it may mate with an earlier offspring
of the same generation; one row per evaluation (an ``ask()`` gives a one-row
``Population``). For moik's IK problems (``compiled_objectives``, nothing attached to
the Evaluator, no constraints) a whole generation is one compiled call
(:func:`~moik.algorithms.moo.moead_kernels.generation`, the problem's objectives
evaluated inside it through :func:`moik._jit.objectives_row`); otherwise each row goes
through the base's evaluation; both paths give the same run bit for bit. Quality
against pymoo's MOEA/D and cost: ``python -m studies.moead_vs_pymoo``
(docs/results/moead-vs-pymoo.md) and ``benchmarks/moead.py``.
Deviation on request, ``batch=True``: every offspring of a generation is made from the
population at its start, evaluated as one batch, then applied in the visiting order
(for a vectorized problem that is costly per call). Measured on ZDT3 (10 seeds, 10,000
evaluations, HV of ``res.F``): 1.2600 against pymoo's ``MOEAD`` 1.2755 (rank-sum p
0.028); pymoo's own batch variant ``ParallelMOEAD`` (which also updates z from the whole
batch first) 0.664.

Constraints: constraint-domination as in ``moead-pymoo``: z is the best *feasible*
value per objective; a feasible offspring replaces every infeasible neighbour and
the feasible ones it improves; an infeasible one replaces only infeasible neighbours
of a larger total violation. An offspring with a non-finite objective or violation
replaces nothing; a member with one is replaced by any finite offspring.

The EOSMA paper's experiments (``eosma-table8``, ``moo-*``) run this MOEA/D
(registry name ``moead``); the paper's Table 4 lists N = 100, archive 100 and a
"crossover parameter gamma = 0.5" of its MATLAB baseline, whose crossover is not
given otherwise: the operators here are pymoo's. The mating and the update loop are
numba kernels (:mod:`moik.algorithms.moo.moead_kernels`).

The archive that reports the result: while no feasible point was seen, it keeps its
capacity of least infeasible rows (a moik extension,
:mod:`moik.algorithms.archive.base`; a strict constraint-domination filter would keep
only the least infeasible row, and every leader would be it). Infeasible output on
pymoo's MW and CTP problems, and the feasibility search that reaches the feasible
region until one feasible point is found (a moik extension,
:mod:`moik.algorithms.moo.feasibility_search`): docs/results/constrained-moo.md
(``studies/constrained_moo.py``).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.distance import cdist

from moik._jit import kernel_array
from moik._validate import flag, integer, interval, optional_integer, positive
from moik.algorithms.array_state import budget_left
from moik.algorithms.evaluation import compiled_objectives
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.moo.moead_kernels import draw_columns, generation, offspring, update
from moik.algorithms.moo.reference_directions import default_ref_dirs
from moik.exceptions import ParameterError, ShapeError


class MOEAD(MOArrayAlgorithm):
    """MOEA/D with Tchebycheff decomposition (Zhang & Li 2007; see the module doc).

    Public attributes for callbacks (besides the base's): ``ref_dirs`` (n, n_obj),
    ``neighbors`` (n, T), ``z`` (the reference point) and ``n_replaced`` (replacements
    in the last generation).

    Args:
        pop_size: Number of Das-Dennis directions when ``ref_dirs`` is None (at most
            this many), an integer >= 2.
        ref_dirs: Weight vectors (n, n_obj), rows non-negative; None: Das-Dennis.
        n_neighbors: Neighbourhood size T (capped at the number of directions).
        delta: Probability of mating within the neighbourhood, in [0, 1].
        nr: Most neighbours one offspring replaces; None: no limit.
        batch: False (default): Zhang & Li's loop, one offspring evaluated at a time.
            True: every offspring of a generation made from the population at its start and
            evaluated as one batch (for a vectorized problem whose evaluation is costly
            per call; a deviation from the paper, see the module doc).
        eta_c: SBX distribution index (> 0). eta_m: Mutation distribution index (> 0).
        archive_size: External archive capacity; None: ``pop_size``.
        X0: Optional initial points (see :class:`~moik.algorithms.moo.base.MOArrayAlgorithm`).
        max_iter: Accepted for the base; MOEA/D has no schedule.
        **kwargs: pymoo ``Algorithm`` options.

    Raises:
        ParameterError: For an unknown keyword or a value out of range; at setup, for a
            problem with one objective.
        ShapeError: At setup, for ``ref_dirs`` that do not have one column per objective.
    """

    ref_dirs: np.ndarray
    neighbors: np.ndarray
    z: np.ndarray

    def __init__(self, *, pop_size: int = 100, ref_dirs: np.ndarray | None = None,
                 n_neighbors: int = 20, delta: float = 0.9, nr: int | None = None,
                 batch: bool = False,
                 eta_c: float = 20.0, eta_m: float = 20.0, archive_size: int | None = None,
                 X0: np.ndarray | None = None, max_iter: int | None = None, **kwargs):
        if ref_dirs is not None:
            ref_dirs = np.array(ref_dirs, dtype=float)
            if ref_dirs.ndim != 2 or len(ref_dirs) < 2 or not np.all(np.isfinite(ref_dirs)) \
                    or np.any(ref_dirs < 0.0):
                raise ParameterError("ref_dirs must be a (n >= 2, n_obj) array of finite, "
                                     f"non-negative weights, got shape {ref_dirs.shape}")
            pop_size = len(ref_dirs)
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self._given_dirs = ref_dirs
        self.n_neighbors = integer("n_neighbors", n_neighbors, minimum=2)
        self.delta = interval("delta", delta, 0.0, 1.0)
        self.nr = optional_integer("nr", nr, minimum=1)
        self.batch = flag("batch", batch)
        self.eta_c = positive("eta_c", eta_c)
        self.eta_m = positive("eta_m", eta_m)
        self.n_replaced = 0

    def _setup(self, problem, **kwargs) -> None:
        if problem.n_obj < 2:  # the base refuses it too, after the directions are needed
            raise ParameterError(f"MOEAD is multi-objective; the problem has n_obj={problem.n_obj}")
        W = default_ref_dirs(problem.n_obj, self.pop_size) if self._given_dirs is None \
            else self._given_dirs
        if W.shape[1] != problem.n_obj:
            raise ShapeError(f"ref_dirs must have {problem.n_obj} columns (the problem's "
                             f"n_obj), got shape {W.shape}")
        self.ref_dirs = kernel_array(W)
        T = min(self.n_neighbors, len(W))
        self.neighbors = np.ascontiguousarray(  # pymoo's: each direction is its own neighbour
            np.argsort(cdist(W, W), axis=1, kind="quicksort")[:, :T], dtype=np.int64)
        super()._setup(problem, **kwargs)

    def _n_initial(self) -> int:
        return len(self.ref_dirs)

    def _evals_per_iteration(self) -> float:
        return float(len(self.ref_dirs))

    def _initialize_state(self) -> None:
        self.X, self.F = kernel_array(self.X).copy(), kernel_array(self.F).copy()
        self._cv = np.zeros(len(self.X)) if self.CV is None else kernel_array(self.CV).copy()
        self.CV = None if self.CV is None else self._cv
        self._xl, self._xu = kernel_array(self.xl), kernel_array(self.xu)
        feasible = self.F[(self._cv <= 0.0) & np.isfinite(self.F).all(axis=1)]
        self.z = feasible.min(axis=0) if len(feasible) else np.full(self.F.shape[1], np.inf)

    def _draws(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """A generation's random numbers, drawn at its start: the visiting order, the
        mating draws (one row per offspring) and the replacement order keys."""
        n, d = self.X.shape
        T = self.neighbors.shape[1]
        rng = self.random_state
        perm = rng.permutation(n).astype(np.int64)
        U = rng.random((n, draw_columns(d)))
        keys = rng.random((n, T)) if self._nr < T else np.empty((n, 0))
        return perm, U, keys

    @property
    def _nr(self) -> int:
        T = self.neighbors.shape[1]
        return T if self.nr is None else min(self.nr, T)

    def _rates(self) -> np.ndarray:
        d = self.X.shape[1]
        return np.array([self.delta, self.eta_c, self.eta_m, min(0.5, 1.0 / d)])

    def _generation(self) -> Step:
        perm, U, keys = self._draws()
        rates, nr, self.n_replaced = self._rates(), self._nr, 0
        n = len(perm)  # batch: one batch of every offspring; else one row at a time
        for row in [slice(0, n)] if self.batch else [slice(i, i + 1) for i in range(n)]:
            Y = offspring(self.X, self.neighbors, perm[row], U[row], self._xl, self._xu, rates)
            FY, CVY = yield Y
            self.n_replaced += update(self.X, self.F, self._cv, self.ref_dirs, self.neighbors,
                                      perm[row], Y, kernel_array(FY),
                                      np.zeros(len(Y)) if CVY is None else kernel_array(CVY),
                                      self.z, nr, keys[row])

    def _run_generation(self) -> None:
        """One compiled call for a problem with compiled objectives (module doc), else the
        base's path."""
        spec = None if self.batch else compiled_objectives(
            self.problem, self.evaluator, self.__dict__.get("archive"),
            constrained=self._constrained)
        if spec is None:
            return super()._run_generation()
        draws = self._draws()
        k = budget_left(self._max_evals, self.evaluator.n_eval, len(draws[0]))
        Y, FY = np.empty((k, self.X.shape[1])), np.empty((k, self.F.shape[1]))
        self.n_replaced = generation(self.X, self.F, self._cv, self.ref_dirs, self.neighbors,
                                     draws, self._xl, self._xu, self._rates(), self.z,
                                     self._nr, Y, FY, spec)
        self.evaluator.n_eval += k
        FY, CV = self._sanitise(Y, FY, None)
        self._receive(Y, FY, CV, None)
