"""Crow search algorithm (CSA).

Askarzadeh, "A novel metaheuristic method for solving constrained engineering
optimization problems: Crow search algorithm", Computers & Structures 169,
1-12 (2016), DOI 10.1016/j.compstruc.2016.03.001:

- Eq. 3: crow i picks a random crow j; if ``r_j >= AP`` it flies toward j's
  hiding place, ``x_i + r_i fl (m_j - x_i)``, else to a random position;
- the new position is kept only if feasible (inside the bounds; otherwise
  the crow stays);
- Eq. 4: memory ``m_i`` takes the new position if it is better (greedy).

Defaults (the CSA paper; the MO-m-PSO paper gives none): AP = 0.1, fl = 2.
Evaluations: N per iteration (every crow's position is evaluated, as in the
author's code, also when it stayed). Constrained problems: the memory update
is feasibility-first (Deb's rules, see base.py); the paper's own engineering
runs used a penalty. ``X``/``F`` reports the memory.

Deviation: r_i is drawn per coordinate (the author's code draws one scalar per
crow; the paper does not say).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import greedy_memory, uniform_population


def crow_flight(X, M, xl, xu, *, AP: float, fl: float,
                rng: np.random.Generator) -> np.ndarray:
    """Eq. 3 and the feasibility rule: the crows' next positions."""
    n, d = X.shape
    j = rng.integers(n, size=n)
    follow = rng.random(n) >= AP
    r = rng.random((n, d))
    new = np.where(follow[:, None], X + r * fl * (M[j] - X),
                   uniform_population(n, xl, xu, rng=rng))
    inside = np.all((new >= xl) & (new <= xu), axis=1)
    return np.where(inside[:, None], new, X)


class CSA(ArrayAlgorithm):
    """Crow search algorithm with array state.

    Extra public arrays: ``positions`` (the crows' current positions).

    Args:
        pop_size: Flock size N.
        AP: Awareness probability in [0, 1] (paper: 0.1).
        fl: Flight length in (0, 10] (paper: 2).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, AP: float = 0.1, fl: float = 2.0,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.AP = interval("AP", AP, 0.0, 1.0)
        self.fl = interval("fl", fl, 0.0, 10.0, lo_open=True)

    def _initialize_state(self) -> None:
        self.positions = self.X

    def _generation(self) -> Step:
        X = crow_flight(self.positions, self.X, self.xl, self.xu, AP=self.AP, fl=self.fl,
                        rng=self.random_state)
        F, CV = yield X
        self.positions = X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
