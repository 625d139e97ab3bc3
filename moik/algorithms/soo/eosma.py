"""Equilibrium optimizer slime mould algorithm (EOSMA), single-objective.

Yin, Luo, Zhou, Zhou & Zhu, "An equilibrium optimizer slime mould algorithm for
inverse kinematics of the 7-DOF robotic manipulator", Scientific Reports 12,
9421 (2022), DOI 10.1038/s41598-022-13516-3. Eqs. 15-18 and Algorithm 1:

- Eq. 15: with probability z the EO operator on the personal best,
  ``X = Xeq + (pBest - Xeq) F + G (1 - F)/(lambda V)`` (F, G as EO's Eqs. 8-9
  with ``C = pBest``), else the SMA operator
  ``X = gBest + vb (W pBest_A - pBest_B)`` (W from Eq. 4 on the personal-best
  fitness, ``vb ~ U(-a, a)``, ``a = atanh(1 - t/T)``);
- Eq. 16: random difference mutation ``X = pBest_R1 + SF (pBest_R2 - pBest_R3)``,
  ``SF ~ U[0.3, 0.6]``, applied with probability q (one draw per iteration,
  Algorithm 1 line 22);
- Eq. 17: a coordinate beyond a bound moves to the midpoint between the agent's
  previous position and that bound;
- Eq. 18: greedy personal-best memory.

Defaults (Table 3): z=0.5, V=1, GP=0.5, a2=2; scenario 1 (position only, N=50,
T=500): q=0, a1=1; scenario 2 (position and posture, N=100, T=1000): q=1, a1=2.
``EOSMA.scenario(1)`` / ``EOSMA.scenario(2)`` build those presets; the number of
iterations is the caller's termination (``("n_gen", 500)`` for scenario 1).

Evaluations per iteration: Algorithm 1 evaluates the Eq. 15 positions (line 24,
inside ``if rand < q``, or line 7 of the next iteration) and, when the mutation
fires, the Eq. 16 positions (line 7 of the next iteration). So N evaluations
per iteration with q=0 and 2N with q=1; N (1 + q) on average.

Deviations and readings:
- The equilibrium pool is the 4 best *distinct* solutions evaluated so far plus
  their mean (Eq. 7's wording), refreshed after every evaluation, not only at
  line 8. Exact duplicates (the SMA operator returns gBest itself once the
  weights are all 1) are kept once: the authors' code admits a pool member
  only with a strictly different fitness, and a pool of four copies of gBest
  makes ``Ceq_ave`` meaningless. (Their code fills the pool by a cascade of
  ``if/elseif`` tests that does not shift members down; the true 4 best are
  used here, as the text says.)
- Eq. 17 moves a coordinate halfway to the bound from the agent's location
  before the update, which is its personal best (the paper's IK section:
  "the location of the search agents ... i.e. pBest_i"; the authors' code
  repairs against the greedy memory ``Xold``), not the last evaluated position.
- ``pBest_A``/``pBest_B`` and ``R1..R3`` are drawn per agent (whole vectors, as
  the text says); SF is drawn per agent.
- W uses ``log10`` and ``eps`` as the SMA code (Eq. 4 prints ``log``).
- Constrained problems: comparisons are feasibility-first (see base.py).

Compiled (:mod:`moik.algorithms.soo.eosma_kernels`): a generation of the class is three
compiled calls (the draws, the candidates, the memory update, which also builds the
Eq. 16 batch when the mutation fires) and one more memory update after that batch. All
of a generation's random numbers are drawn at its start on ``self.random_state`` in the
order Algorithm 1 uses them, including the line-22 test and the Eq. 16 numbers; nothing
else draws from the generator in between, so the stream and the results are bit for
bit those of drawing each number where it is used.
The functions below (:func:`eosma_update`, :func:`random_difference_mutation`, also
used by MOEOSMA) draw with the Generator's methods and call the same compiled operators.

Reproducing Tables 5 and 7 on the 7-DOF arm: tests/algorithms/soo/test_eosma.py
(Table 7 is reproduced with Table 1's lengths in metres, not in cm).
"""

from __future__ import annotations

import numpy as np

from moik._jit import kernel_array
from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.generator_handle import GeneratorHandles
from moik.algorithms.soo.eo import eo_schedule, select_pool
from moik.algorithms.soo.eosma_kernels import (
    POOL_SIZE,
    GenerationDraws,
    difference_rows,
    eosma_rows,
    first_pool,
    generation_candidates,
    generation_draws,
    remember,
)
from moik.algorithms.soo.sma import sma_schedule
from moik.exceptions import ParameterError

SCENARIOS = {
    1: {"pop_size": 50, "q": 0.0, "a1": 1.0},
    2: {"pop_size": 100, "q": 1.0, "a1": 2.0},
}


def eosma_update(P, g_best, pool, W, t1: float, a: float, *, z: float, a1: float, GP: float,
                 V: float, rng: np.random.Generator) -> np.ndarray:
    """Eq. 15: the EO operator (probability z) or the SMA operator, per agent.

    Args:
        P: Personal bests (n, d). g_best: best so far (d,), or a leader per agent (n, d).
            pool: equilibrium pool.
        W: SMA weights (n, d). t1: EO time factor (Eq. 8). a: SMA range (Eq. 3).
        z, a1, GP, V: hyperparameters.
        rng: Random generator: EO's ``lam``, ``r`` (n, d), pool index, ``r1``, ``r2``
            (n,), then ``vb`` (n, d), ``A``, ``B`` and the operator test (n,), in that order.
    """
    P = kernel_array(P)
    n, d = P.shape
    lam, r = kernel_array(rng.random((n, d))), kernel_array(rng.random((n, d)))
    idx = np.asarray(rng.integers(len(pool), size=n), dtype=np.int64)
    r1, r2 = kernel_array(rng.random(n)), kernel_array(rng.random(n))
    vb = kernel_array(rng.uniform(-a, a, (n, d)))
    A = np.asarray(rng.integers(n, size=n), dtype=np.int64)
    B = np.asarray(rng.integers(n, size=n), dtype=np.int64)
    u = kernel_array(rng.random(n))
    g_best = kernel_array(g_best).reshape(-1, d)
    return eosma_rows(P, g_best, kernel_array(pool), kernel_array(W), lam,
                      np.exp(-lam * t1), r, idx, r1, r2, vb, A, B, u, float(z), float(a1),
                      float(GP), float(V), np.empty((n, d)))


def update_distinct_pool(PX, PF, PCV, X, F, CV, k: int = POOL_SIZE):
    """Eq. 7: the ``k`` best distinct rows of the old pool and a new evaluated batch.

    Rows are ranked by the feasibility-first fitness (stable); a row equal to a
    better-ranked one (same point, same fitness) is dropped
    (:func:`moik.algorithms.soo.eo.best_rows`).

    Returns:
        ``(PX, PF, PCV)`` with at most ``k`` rows, best first.
    """
    return select_pool(PX, PF, PCV, X, F, CV, k, True)


def random_difference_mutation(P: np.ndarray, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 16: ``pBest_R1 + SF (pBest_R2 - pBest_R3)`` with ``SF ~ U[0.3, 0.6]``.

    Draws the indices ``R`` (3, n), then ``SF`` (n, 1).
    """
    P = kernel_array(P)
    n = len(P)
    R = np.asarray(rng.integers(n, size=(3, n)), dtype=np.int64)
    SF = kernel_array(rng.uniform(0.3, 0.6, (n, 1))).reshape(n)
    return difference_rows(P, R, SF, np.empty(P.shape))


class EOSMA(ArrayAlgorithm):
    """EOSMA (Yin et al. 2022) with array state.

    Extra public arrays: ``pbest_X``/``pbest_F``/``pbest_CV`` (personal bests),
    ``pool_X``/``pool_F`` (4 best distinct so far). ``X``/``F`` are the last evaluated
    positions.

    Args:
        pop_size: Number of agents N (paper: 50 or 100).
        z: Probability of the EO operator in [0, 1] (paper: 0.5).
        q: Mutation probability in [0, 1] (paper: 0 or 1).
        V: Control volume, > 0 (paper: 1).
        GP: Generation probability in [0, 1] (paper: 0.5).
        a1: Exploration factor, > 0 (paper: 1 or 2).
        a2: Exploitation factor, > 0 (paper: 2).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    def __init__(self, *, pop_size: int = 100, z: float = 0.5, q: float = 1.0, V: float = 1.0,
                 GP: float = 0.5, a1: float = 2.0, a2: float = 2.0,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.z = interval("z", z, 0.0, 1.0)
        self.q = interval("q", q, 0.0, 1.0)
        self.V = interval("V", V, 0.0, np.inf, lo_open=True, hi_open=True)
        self.GP = interval("GP", GP, 0.0, 1.0)
        self.a1 = interval("a1", a1, 0.0, 10.0, lo_open=True)
        self.a2 = interval("a2", a2, 0.0, 10.0, lo_open=True)

    @classmethod
    def scenario(cls, number: int, **overrides) -> EOSMA:
        """The paper's preset: 1 (position, q=0, a1=1, N=50) or 2 (pose, q=1, a1=2, N=100)."""
        if number not in SCENARIOS:
            raise ParameterError(f"scenario must be 1 or 2, got {number!r}")
        return cls(**{**SCENARIOS[number], **overrides})

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + self.q)

    def _initialize_state(self) -> None:
        n, d = self.pop_size, self.problem.n_var
        self._draws = GenerationDraws(n, d)  # one generation's random numbers (named slots)
        self._zeros = np.zeros(n)  # the violation of unconstrained rows
        self._handles = GeneratorHandles()
        self._bounds = np.stack([self.xl, self.xu]).astype(float)
        X, F, CV = kernel_array(self.X), kernel_array(self.F), self._violation(self.CV)
        self._set_memory(X, np.stack([F, CV]), *first_pool(X, F, CV))

    def _violation(self, CV):
        return self._zeros if CV is None else kernel_array(CV)

    def _set_memory(self, PX, pbest_fcv, pool, pool_fcv) -> None:
        """The memory: kernels use the packed arrays (pbest F and CV in ``_pbest_fcv``
        (2, n), the pool with its mean as a last row in ``_pool``, its F and CV in
        ``_pool_fcv``); the public attributes are views of them."""
        self.pbest_X, self._pbest_fcv, self._pool, self._pool_fcv = PX, pbest_fcv, pool, pool_fcv
        self.pbest_F, self.pool_X, self.pool_F = pbest_fcv[0], pool[:-1], pool_fcv[0]
        self.pbest_CV: np.ndarray | None
        self.pool_CV: np.ndarray | None
        self.pbest_CV, self.pool_CV = ((pbest_fcv[1], pool_fcv[1]) if self._constrained
                                       else (None, None))

    def _remember(self, X, F, CV, mutate: bool) -> np.ndarray:
        """Eqs. 18 and 7 after an evaluation; returns the Eq. 16 candidates if ``mutate``."""
        self.X, self.F, self.CV = X, F, CV
        *memory, X_mut = remember(X, kernel_array(F), self._violation(CV), self.pbest_X,
                                  self._pbest_fcv, self._pool, self._pool_fcv, mutate,
                                  self._draws.rows, self._draws.picks, self._bounds)
        self._set_memory(*memory)
        return X_mut

    def _population_arrays(self):
        return self.pbest_X, self.pbest_F, self.pbest_CV

    def _generation(self) -> Step:
        """Algorithm 1, one iteration. All its random numbers are drawn first, in the
        order the numpy operators draw them (:func:`generation_draws`): nothing else draws
        from the generator before the mutation, so the stream and the results are those
        of drawing each number where it is used."""
        t1 = eo_schedule(self.t, self.max_iter, self.a2)
        a, _ = sma_schedule(self.t, self.max_iter)
        draws = self._draws
        mutate = generation_draws(self._handles.of(self.random_state), self._pbest_fcv,
                                  len(self._pool), t1, a, self.q, draws.cells, draws.rows,
                                  draws.picks)
        draws.apply_numpy_maths()  # Eqs. 4 and 8
        X = generation_candidates(self.pbest_X, kernel_array(self.best_x)[None], self._pool,
                                  draws.cells, draws.rows, draws.picks, self.z, self.a1,
                                  self.GP, self.V, self._bounds)
        F, CV = yield X
        X = self._remember(X, F, CV, mutate)
        if mutate:  # Algorithm 1, line 22 (Eq. 16)
            F, CV = yield X
            self._remember(X, F, CV, False)
