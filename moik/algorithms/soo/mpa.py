"""Marine predators algorithm (MPA).

Faramarzi, Heidarinejad, Mirjalili & Gandomi, "Marine Predators Algorithm: A
nature-inspired metaheuristic", Expert Systems with Applications 152, 113377
(2020), DOI 10.1016/j.eswa.2020.113377:

- Eq. 10: the Elite matrix, the top predator (best so far) in every row;
- Eq. 12 (phase 1, ``t < T/3``): ``stepsize = R_B (Elite - R_B Prey)``,
  ``Prey = Prey + P R stepsize``;
- Eqs. 13-14 (phase 2, ``T/3 <= t < 2T/3``): the first half of the population
  as Eq. 12 with Levy ``R_L`` in place of ``R_B``; the second half
  ``stepsize = R_B (R_B Elite - Prey)``, ``Prey = Elite + P CF stepsize``,
  ``CF = (1 - t/T)^(2 t/T)``;
- Eq. 15 (phase 3, ``t >= 2T/3``): ``stepsize = R_L (R_L Elite - Prey)``,
  ``Prey = Elite + P CF stepsize``;
- marine memory: a prey keeps its previous position if that was better;
- Eq. 16 (eddy formation / FADs effect): with probability FADs,
  ``Prey + CF (X_min + R (X_max - X_min)) U`` with ``U`` a binary mask of
  rate FADs, else ``Prey + (FADs (1 - r) + r) (Prey_r1 - Prey_r2)``.

``R_B`` is standard normal, ``R_L`` is ``0.05`` times a Mantegna Levy step with
exponent 1.5 (the authors' code; :func:`moik.algorithms.mechanics.mantegna_levy`),
``R`` uniform per coordinate.

Defaults (EOSMA paper, Table 3): P=0.5, FADs=0.2. Evaluations: **2N per
iteration** (after the phase update and after the FADs step, each followed by
marine memory, as in the authors' code); ``max_iter`` inferred from an
``n_eval`` termination accounts for it.

Deviations and readings:
- Phase boundaries: ``t < T/3`` phase 1, ``t < 2T/3`` phase 2, else phase 3
  (the authors' code sends ``t = T/3`` exactly to phase 3).
- As in the authors' code, the FADs branch and ``r`` are drawn once per
  iteration for the whole population and ``Prey_r1``, ``Prey_r2`` come from
  two random permutations.
- The iteration loop is rotated: the authors' code evaluates the FADs step at
  the top of its next iteration; here both batches belong to one generation
  (the same sequence of operations).
- Coordinates outside the box are clipped to the bounds (authors' code).
- Constrained problems: memory and Elite are feasibility-first (see base.py).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    mantegna_levy,
)


def mpa_phase(t: int, T: int) -> int:
    """The phase (1, 2 or 3) of iteration ``t`` in a schedule of length ``T``."""
    return 1 if t < T / 3.0 else (2 if t < 2.0 * T / 3.0 else 3)


def mpa_cf(t: int, T: int) -> float:
    """Adaptive step control ``CF = (1 - t/T)^(2 t/T)`` (t/T capped at 1)."""
    s = min(t / T, 1.0)
    return (1.0 - s) ** (2.0 * s)


def predator_move(prey, elite, phase: int, CF: float, *, P: float,
                  rng: np.random.Generator) -> np.ndarray:
    """Eqs. 12-15: the phase-dependent move of every prey (row), not yet bounded."""
    n, d = prey.shape
    RL = 0.05 * mantegna_levy((n, d), 1.5, rng=rng)
    RB = rng.standard_normal((n, d))
    R = rng.random((n, d))
    brownian_explore = prey + P * R * (RB * (elite - RB * prey))  # Eq. 12
    levy_explore = prey + P * R * (RL * (elite - RL * prey))  # Eq. 13
    brownian_exploit = elite + P * CF * (RB * (RB * elite - prey))  # Eq. 14
    levy_exploit = elite + P * CF * (RL * (RL * elite - prey))  # Eq. 15
    if phase == 1:
        return brownian_explore
    if phase == 3:
        return levy_exploit
    first = (np.arange(n) < n / 2.0)[:, None]  # code: i <= n/2 (1-based)
    return np.where(first, levy_explore, brownian_exploit)


def fads_effect(prey, CF: float, *, FADs: float, xl: np.ndarray, xu: np.ndarray,
                rng: np.random.Generator) -> np.ndarray:
    """Eq. 16: eddy formation and fish aggregating devices' effect, not yet bounded."""
    n, d = prey.shape
    if rng.random() < FADs:
        U = rng.random((n, d)) < FADs
        return prey + CF * (xl + rng.random((n, d)) * (xu - xl)) * U
    r = rng.random()
    return prey + (FADs * (1.0 - r) + r) * (prey[rng.permutation(n)] - prey[rng.permutation(n)])


class MPA(ArrayAlgorithm):
    """Marine predators algorithm (Faramarzi et al. 2020) with array state.

    ``X``/``F`` is the prey matrix after marine memory.

    Args:
        pop_size: Number of search agents N.
        P: Step constant in (0, 2] (Table 3: 0.5).
        FADs: Fish-aggregating-devices probability in [0, 1] (Table 3: 0.2).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, P: float = 0.5, FADs: float = 0.2,
                 max_iter: int | None = None, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.P = interval("P", P, 0.0, 2.0, lo_open=True)
        self.FADs = interval("FADs", FADs, 0.0, 1.0)

    def _evals_per_iteration(self) -> float:
        return 2.0 * self.pop_size

    def _generation(self) -> Step:
        rng = self.random_state
        CF = mpa_cf(self.t, self.max_iter)
        phase = mpa_phase(self.t, self.max_iter)
        X = predator_move(self.X, self.best_x, phase, CF, P=self.P, rng=rng)  # Elite: Eq. 10
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
        X = fads_effect(self.X, CF, FADs=self.FADs, xl=self.xl, xu=self.xu, rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
