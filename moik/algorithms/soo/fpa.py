"""Flower pollination algorithm (FPA).

Yang, "Flower pollination algorithm for global optimization", Unconventional
Computation and Natural Computation (UCNC 2012), LNCS 7445, 240-249,
DOI 10.1007/978-3-642-32894-7_27:

- Eq. 1 (global pollination): ``x_i <- x_i + L (x_i - g*)``, ``g*`` the best
  solution so far, ``L`` a Levy-distributed step (Eq. 2, exponent
  ``lambda = 1.5``);
- Eq. 3 (local pollination): ``x_i <- x_i + eps (x_j - x_k)``,
  ``eps ~ U(0, 1)``, ``j, k`` two different random flowers;
- the switch: each flower pollinates globally with probability ``p``, else
  locally; a new solution replaces the flower's only if it is better.

Levy steps are drawn with Mantegna's algorithm (as in Yang's published code):
``step = u / |v|^(1/beta)``, ``u ~ N(0, sigma_u^2)``, ``v ~ N(0, 1)``,
``sigma_u = (Gamma(1+beta) sin(pi beta/2) / (Gamma((1+beta)/2) beta 2^((beta-1)/2)))^(1/beta)``,
scaled by 0.01 (``L = 0.01 step`` in Yang's code; the paper gives no scale).
:func:`~moik.algorithms.mechanics.mantegna_levy` is shared with MPA, HHO, MODA, I-BES.

Defaults (EOSMA paper, Table 3): p=0.2; beta=1.5. Evaluations: N per iteration.
Out-of-range coordinates are clipped to the bounds (Yang's ``simplebounds``).

Deviations and readings:
- ``p`` is the probability of *global* pollination, the paper's pseudo-code
  convention (``rand < p``: global). Table 3's p=0.2 thus gives the behaviour
  of Yang's published code, which tests ``rand > 0.8`` for global pollination
  (the paper recommends p=0.8 in its own convention: global 80% of the time).
- Table 3 also lists "scale factor a = 2" and "constant b = 0.5" for FPA; they
  have no counterpart in Yang's paper or code and are not used.
- Eq. 1 and the code use ``L (x_i - g*)`` (the pseudo-code prints
  ``L (g* - x_i)``); the Levy step is symmetric, so both are the same law.
- Local pollination starts from ``x_i`` (Eq. 3); Yang's code adds to the
  flower's previous trial vector instead.
- Flowers are updated all at once from the same population (Yang's code
  updates them in turn, with ``g*`` refreshed after each); a trial replaces
  its flower only if strictly better (the code accepts ties).
- Constrained problems: comparisons are feasibility-first (see base.py).
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


def pollinate(X, g, *, p: float, beta: float, levy_scale: float,
              rng: np.random.Generator) -> np.ndarray:
    """Eqs. 1-3: one pollination step of every flower (row of ``X``), not yet bounded.

    Args:
        X: Current flowers (n, d), n >= 2.
        g: Best solution so far (d,).
        p: Probability of global pollination per flower.
        beta: Levy exponent.
        levy_scale: Factor on the Mantegna step (Yang's code: 0.01).
        rng: Random generator.
    """
    n, d = X.shape
    glob = rng.random(n) < p
    L = levy_scale * mantegna_levy((n, d), beta, rng=rng)
    eps = rng.random(n)[:, None]
    j = rng.integers(n, size=n)
    k = (j + rng.integers(1, n, size=n)) % n  # k != j
    X_global = X + L * (X - g)  # Eq. 1
    X_local = X + eps * (X[j] - X[k])  # Eq. 3
    return np.where(glob[:, None], X_global, X_local)


class FPA(ArrayAlgorithm):
    """Flower pollination algorithm (Yang 2012) with array state.

    ``X``/``F`` is the population, which keeps each flower's best (greedy).

    Args:
        pop_size: Number of flowers N.
        p: Probability of global (Levy) pollination in [0, 1] (Table 3: 0.2).
        beta: Levy exponent in (0, 2] (paper: 1.5).
        levy_scale: Factor on the Levy step, > 0 (Yang's code: 0.01).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, p: float = 0.2, beta: float = 1.5,
                 levy_scale: float = 0.01, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.p = interval("p", p, 0.0, 1.0)
        self.beta = interval("beta", beta, 0.0, 2.0, lo_open=True)
        self.levy_scale = interval("levy_scale", levy_scale, 0.0, np.inf, lo_open=True,
                                      hi_open=True)

    def _generation(self) -> Step:
        X = pollinate(self.X, self.best_x, p=self.p, beta=self.beta,
                      levy_scale=self.levy_scale, rng=self.random_state)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = greedy_memory(X, F, CV, self.X, self.F, self.CV)
