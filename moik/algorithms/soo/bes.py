"""Bald eagle search (BES) and the improved, Levy-flight BES (I-BES).

BES: Alsattar, Zaidan & Zaidan, "Novel meta-heuristic bald eagle search
optimisation algorithm", Artificial Intelligence Review 53, 2237-2264 (2020),
DOI 10.1007/s10462-019-09732-5. I-BES: Zhao, Tao, Jiang, Yun & Fan, "Improved
Bald Eagle Search Optimization Algorithm for the Inverse Kinematics of Robotic
Manipulators", Biomimetics 9, 627 (2024), DOI 10.3390/biomimetics9100627.
Equation numbers are those of the I-BES paper:

- Eq. 5 (select): ``x_new = x_best + alpha r (x_mean - x_i)``;
- Eq. 6 (spiral search): ``x_new = x_i + n1 (x_i - x_{i+1}) + m1 (x_i - x_mean)``
  with ``lambda1 = a rand``, ``r1 = lambda1 + R rand``, ``m1 = r1 sin(lambda1)``
  and ``n1 = r1 cos(lambda1)``, each divided by its largest magnitude; i runs
  over 1..N-1 (the last eagle has no successor);
- Eq. 7 (swoop): ``x_new = k x_best + m2 (x_i - c1 x_mean) + n2 (x_i - c2 x_best)``
  with ``lambda2 = r2 = a k``, ``m2 = r2 sinh(lambda2)``, ``n2 = r2 cosh(lambda2)``
  (normalized likewise), k uniform in [0.5, 2];
- I-BES Eqs. 9-10: the spiral search is replaced by a Levy flight
  ``x_new = x_i + L (x_i - x_best)``, ``L = 0.01 sigma u / |v|^(1/beta)``,
  u, v standard normal per coordinate, beta = 1.5;
- I-BES Eq. 13: a coordinate outside ``[q_l, q_u]`` is re-placed uniformly at
  random, ``q_l + k (q_u - q_l)`` with k in [0, 1];
- Algorithm 1: after each phase a new position replaces the eagle's only if it
  is strictly better (greedy); ``x_best`` is the best position so far and
  ``x_mean`` is recomputed at the start of each phase.

Defaults (I-BES Table 1, for both): c1 = c2 = 1.5, R = 1.4, alpha = 1.8, a = 8;
beta = 1.5. Evaluations per iteration: BES 3N - 1, I-BES 3N. BES clips
coordinates to the bounds (the BES authors' code); I-BES uses Eq. 13.
Constrained problems: the greedy replacement and ``x_best`` are feasibility
first (Deb's rules, see base.py); no penalty.

Readings and deviations:
- Algorithm 1 (line 5) omits alpha from Eq. 5; Eq. 5 with alpha = 1.8 is used.
- Eq. 6 prints ``n1 = nr1 / max(mr1)``; as in the BES paper and its code each
  of m1, n1, m2, n2 is divided by its own largest magnitude.
- The I-BES paper prints ``lambda1 = a rand`` and ``lambda2 = a k``; the BES
  paper uses ``a pi rand`` (its code ``a pi exp(rand)`` in the swoop) and a
  uniform [0, 1) factor per coordinate in place of k. The I-BES forms are
  used, with one k per eagle shared by the first term and lambda2.
- The BES code re-shuffles the whole population before every single eagle of
  the search and swoop phases and updates eagles one after another; here the
  spiral pairs (i, i+1) follow one random permutation per phase and every
  phase updates all eagles at once (vectorized).
"""

from __future__ import annotations

import numpy as np

from moik._validate import flag, interval, positive
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import (
    clip_to_bounds,
    greedy_memory,
    mantegna_levy,
    mantegna_sigma,
)
from moik.exceptions import ParameterError

BOUND_HANDLING = ("clip", "random")


def _normalized(v: np.ndarray) -> np.ndarray:
    """Divide by the largest magnitude (left as is when all are zero)."""
    top = np.abs(v).max()
    return v / top if top > 0 else v


def select_space(X, x_best, x_mean, *, alpha: float, rng: np.random.Generator) -> np.ndarray:
    """Eq. 5: ``x_best + alpha r (x_mean - x_i)`` with r uniform per coordinate."""
    return x_best + alpha * rng.random(X.shape) * (x_mean - X)


def spiral_search(X, x_mean, *, a: float, R: float, rng: np.random.Generator) -> np.ndarray:
    """Eq. 6 for rows 0..n-2 of ``X`` (row i moves relative to row i+1); (n-1, d)."""
    n = len(X)
    lam = a * rng.random(n - 1)
    r = lam + R * rng.random(n - 1)
    m1, n1 = _normalized(r * np.sin(lam)), _normalized(r * np.cos(lam))
    return X[:-1] + n1[:, None] * (X[:-1] - X[1:]) + m1[:, None] * (X[:-1] - x_mean)


levy_sigma = mantegna_sigma  # Eq. 10


def levy_step(shape: tuple[int, ...], beta: float, *, rng: np.random.Generator,
              scale: float = 0.01) -> np.ndarray:
    """Eq. 9: ``L = 0.01 sigma u / |v|^(1/beta)``, u and v standard normal (``scale`` = 0.01)."""
    return scale * mantegna_levy(shape, beta, rng=rng)


def levy_search(X, x_best, *, beta: float, rng: np.random.Generator,
                scale: float = 0.01) -> np.ndarray:
    """I-BES search phase (Algorithm 1, line 15): ``x_i + L (x_i - x_best)``."""
    return X + levy_step(X.shape, beta, rng=rng, scale=scale) * (X - x_best)


def swoop(X, x_best, x_mean, *, a: float, c1: float, c2: float,
          rng: np.random.Generator) -> np.ndarray:
    """Eq. 7: the swoop toward the best position, k uniform in [0.5, 2] per eagle."""
    k = rng.uniform(0.5, 2.0, len(X))
    lam = a * k
    m2, n2 = _normalized(lam * np.sinh(lam)), _normalized(lam * np.cosh(lam))
    return (k[:, None] * x_best + m2[:, None] * (X - c1 * x_mean)
            + n2[:, None] * (X - c2 * x_best))


def random_replacement(X_new, xl, xu, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 13: every out-of-limit coordinate becomes ``xl + k (xu - xl)``, k ~ U[0, 1]."""
    out = (X_new < xl) | (X_new > xu)
    k = rng.random(X_new.shape)
    return np.where(out, xl + k * (xu - xl), X_new)


class BES(ArrayAlgorithm):
    """Bald eagle search with array state; ``BES.ibes()`` builds the I-BES preset.

    ``X``/``F``/``CV`` is the population after the greedy replacements.

    Args:
        pop_size: Number of eagles N (>= 3).
        alpha: Position change factor of Eq. 5, in [1.5, 2] (paper: 1.8).
        a: Spiral angle factor of Eqs. 6-7, in [5, 10] (paper: 8).
        R: Search cycles of Eq. 6, in [0.5, 2] (paper: 1.4).
        c1: Mean learning factor of Eq. 7, in [1, 2] (paper: 1.5).
        c2: Best learning factor of Eq. 7, in [1, 2] (paper: 1.5).
        levy: Use the I-BES Levy-flight search phase (Eqs. 9-10) in place of the
            spiral (False for BES).
        beta: Levy exponent in (0, 2] (paper: 1.5).
        levy_scale: Factor of the Levy step, > 0 (Eq. 9 prints 0.01; 1.0 is the
            reading measured by the ``ibes-table8-levy`` experiment).
        bounds: ``"clip"`` (BES code) or ``"random"`` (I-BES Eq. 13).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    min_pop_size = 3

    def __init__(self, *, pop_size: int = 150, alpha: float = 1.8, a: float = 8.0,
                 R: float = 1.4, c1: float = 1.5, c2: float = 1.5, levy: bool = False,
                 beta: float = 1.5, levy_scale: float = 0.01, bounds: str = "clip",
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, **kwargs)
        self.alpha = interval("alpha", alpha, 1.5, 2.0)
        self.a = interval("a", a, 5.0, 10.0)
        self.R = interval("R", R, 0.5, 2.0)
        self.c1 = interval("c1", c1, 1.0, 2.0)
        self.c2 = interval("c2", c2, 1.0, 2.0)
        self.beta = interval("beta", beta, 0.0, 2.0, lo_open=True)
        self.levy_scale = positive("levy_scale", levy_scale)
        levy = flag("levy", levy)
        if bounds not in BOUND_HANDLING:
            raise ParameterError(f"bounds must be one of {', '.join(BOUND_HANDLING)}, "
                                 f"got {bounds!r}")
        self.levy, self.bounds = bool(levy), bounds

    @classmethod
    def ibes(cls, **kwargs) -> BES:
        """I-BES (Zhao et al. 2024): the Levy search phase (Eqs. 9-10) and the Eq. 13 bounds.

        Args:
            **kwargs: Any :class:`BES` keyword; ``levy`` and ``bounds`` override the preset.
        """
        return cls(**{"levy": True, "bounds": "random", **kwargs})

    def _evals_per_iteration(self) -> float:
        return 3.0 * self.pop_size - (0 if self.levy else 1)

    def _bound(self, X: np.ndarray) -> np.ndarray:
        if self.bounds == "random":
            return random_replacement(X, self.xl, self.xu, rng=self.random_state)
        return clip_to_bounds(X, self.xl, self.xu)

    def _accept(self, rows: np.ndarray | slice, X, F, CV) -> None:
        """Greedy replacement (Algorithm 1, lines 7-12) of the eagles ``rows``."""
        cv_old = None if self.CV is None else self.CV[rows]
        PX, PF, PCV = greedy_memory(X, F, CV, self.X[rows], self.F[rows], cv_old)
        self.X, self.F = self.X.copy(), self.F.copy()
        self.X[rows], self.F[rows] = PX, PF
        if CV is not None and self.CV is not None:
            self.CV = self.CV.copy()
            self.CV[rows] = PCV

    def _generation(self) -> Step:
        rng, rows = self.random_state, slice(None)
        X = self._bound(select_space(self.X, self.best_x, self.X.mean(axis=0),
                                     alpha=self.alpha, rng=rng))
        F, CV = yield X
        self._accept(rows, X, F, CV)
        if self.levy:
            X = levy_search(self.X, self.best_x, beta=self.beta, rng=rng, scale=self.levy_scale)
        else:
            order = rng.permutation(self.pop_size)
            X = spiral_search(self.X[order], self.X.mean(axis=0), a=self.a, R=self.R, rng=rng)
            rows = order[:-1]
        X = self._bound(X)
        F, CV = yield X
        self._accept(rows, X, F, CV)
        X = self._bound(swoop(self.X, self.best_x, self.X.mean(axis=0), a=self.a,
                              c1=self.c1, c2=self.c2, rng=rng))
        F, CV = yield X
        self._accept(slice(None), X, F, CV)
