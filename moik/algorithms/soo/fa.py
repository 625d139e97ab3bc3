"""Firefly algorithm (FA).

Yang, "Firefly algorithms for multimodal optimization", Stochastic Algorithms:
Foundations and Applications (SAGA 2009), LNCS 5792, 169-178,
DOI 10.1007/978-3-642-04944-6_14 (and Yang, Nature-Inspired Metaheuristic
Algorithms, 2nd ed., 2010, Ch. 10):

- Eq. 1 (attractiveness): ``beta(r) = beta0 exp(-gamma r^2)``;
- Eq. 2 (movement of firefly i toward every brighter j):
  ``x_i <- x_i + beta(r_ij) (x_j - x_i) + alpha eps``, ``eps`` uniform in
  [-0.5, 0.5] per coordinate, scaled by the box width (Yang's code);
- a firefly with no brighter one moves randomly (``alpha eps``).

Defaults (I-BES paper, Table 1): alpha = 0.2, beta0 = 2, gamma = 1; ``theta``
(alpha damping per iteration, ``alpha_t = alpha theta^t``) is 1 (no damping):
Table 1 gives a single alpha. Evaluations: N per iteration. Coordinates are
clipped to the bounds. There is no greedy memory (the original has none); the
best so far is kept by the base. Constrained problems: brightness is the
feasibility-first ranking value (Deb's rules, see base.py).

FA is weak on wide boxes with these settings: gamma = 1 makes the
attraction vanish beyond a few units (``exp(-r^2)``) and a constant alpha keeps
the random steps at 0.2 of the box, so on the 10-D sphere in [-100, 100] it
stays near 4e3 after 30,000 evaluations (``theta < 1`` does not help there, the
attraction is gone). On IK boxes ([-pi, pi]) attraction works; the I-BES paper
reports FA errors of 1e-3 to 1e-1 m (Table 8). On pymoo's 10-D sphere in [0, 1] these
settings stall near 1e-2 (beta0 = 2 jumps past the brighter firefly, to the mirror
point; the constant alpha keeps the random steps), while the settings of Yang's own code
(``beta0=1, theta=0.97``) reach 1e-28 (measured on seeds 0-2; tests/algorithms/soo/test_fa.py).

Deviations: fireflies move toward the brighter ones in the order of the
previous positions, all from the same previous swarm (Yang's code does the
same with its sorted copy); r uses firefly i's partly moved position, as in
the code.
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, ranking_fitness


def firefly_move(X, light, *, alpha: float, beta0: float, gamma: float, scale: np.ndarray,
                 rng: np.random.Generator) -> np.ndarray:
    """Eqs. 1-2: move every firefly toward each brighter one (lower ``light`` is brighter)."""
    n, d = X.shape
    new = X.copy()
    moved = np.zeros(n, dtype=bool)
    for j in range(n):
        brighter = light[j] < light
        if not brighter.any():
            continue
        r2 = ((new - X[j]) ** 2).sum(axis=1)
        beta = beta0 * np.exp(-gamma * r2)  # Eq. 1
        step = beta[:, None] * (X[j] - new) + alpha * (rng.random((n, d)) - 0.5) * scale
        new = np.where(brighter[:, None], new + step, new)  # Eq. 2
        moved |= brighter
    walk = alpha * (rng.random((n, d)) - 0.5) * scale
    return np.where(moved[:, None], new, new + walk)


class FA(ArrayAlgorithm):
    """Firefly algorithm with array state (``X``/``F`` is the current swarm).

    Args:
        pop_size: Number of fireflies N.
        alpha: Randomization in [0, 1] (paper: 0.2), times the box width.
        beta0: Attractiveness at r = 0 in [0, 10] (paper: 2).
        gamma: Light absorption in [0, 100] (paper: 1).
        theta: Alpha damping per iteration in (0, 1] (default 1: none).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 150, alpha: float = 0.2, beta0: float = 2.0,
                 gamma: float = 1.0, theta: float = 1.0, X0: np.ndarray | None = None,
                 **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.alpha = interval("alpha", alpha, 0.0, 1.0)
        self.beta0 = interval("beta0", beta0, 0.0, 10.0)
        self.gamma = interval("gamma", gamma, 0.0, 100.0)
        self.theta = interval("theta", theta, 0.0, 1.0, lo_open=True)

    def _generation(self) -> Step:
        alpha = self.alpha * self.theta**self.t
        X = firefly_move(self.X, ranking_fitness(self.F, self.CV), alpha=alpha,
                         beta0=self.beta0, gamma=self.gamma, scale=self.xu - self.xl,
                         rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
