"""Harris hawks optimization (HHO).

Heidari, Mirjalili, Faris, Aljarah, Mafarja & Chen, "Harris hawks optimization:
Algorithm and applications", Future Generation Computer Systems 97, 849-872
(2019), DOI 10.1016/j.future.2019.02.028. Equation numbers are the paper's:

- Eq. 1 (exploration, ``|E| >= 1``): with ``q >= 0.5``
  ``X = X_rand - r1 |X_rand - 2 r2 X|``, else
  ``X = (X_rabbit - X_m) - r3 (LB + r4 (UB - LB))``; Eq. 2: ``X_m`` is the mean hawk;
- Eq. 3: escaping energy ``E = 2 E0 (1 - t/T)``, ``E0 ~ U(-1, 1)`` per hawk;
- Eqs. 4-5 (soft besiege, ``r >= 0.5``, ``|E| >= 0.5``):
  ``X = dX - E |J X_rabbit - X|``, ``dX = X_rabbit - X``, ``J = 2 (1 - r5)``;
- Eq. 6 (hard besiege, ``r >= 0.5``, ``|E| < 0.5``): ``X = X_rabbit - E |dX|``;
- Eqs. 7-10 (soft besiege with progressive rapid dives, ``r < 0.5``,
  ``|E| >= 0.5``): ``Y = X_rabbit - E |J X_rabbit - X|``, ``Z = Y + S * LF(D)``;
  the hawk moves to Y if ``F(Y) < F(X)``, else to Z if ``F(Z) < F(X)``, else stays;
- Eq. 9: Levy flight ``LF = 0.01 u sigma / |v|^(1/beta)``, u, v ~ N(0, 1);
- Eqs. 11-13 (hard besiege with progressive rapid dives, ``r < 0.5``,
  ``|E| < 0.5``): as Eqs. 7-10 with ``X_m`` in place of X in Y.

Defaults (EOSMA paper, Table 3): beta=1.5.

Evaluations per iteration: every hawk's new position is evaluated once (N),
plus one extra evaluation (Z) for every rapid-dive hawk whose Y did not
improve: between N and 2N. Over a run about 42% of the hawk moves are rapid
dives (``P(|E| < 1) = 0.5 + 0.5 ln 2`` averaged over t/T, times
``P(r < 0.5)``), so ``_evals_per_iteration`` assumes 1.3 N when T is inferred
from an ``n_eval`` budget (measured: 1.29 N on the 7-DOF position IK, 1.14 N
on the sphere, where Y improves more often); pass ``max_iter`` to fix T. The authors'
code evaluates Y, Z and the current hawk again in every comparison and the
whole population again at the start of each iteration (2 to 4 extra
evaluations per rapid dive); positions whose value is already known are not
re-evaluated here, which gives the same trajectory with fewer evaluations.

Deviations:
- All hawks move from the same population (vectorized); the authors' code
  updates hawk by hawk, so ``X_m`` and ``X_rand`` can mix old and new positions.
- Y and Z are clipped to the bounds before they are evaluated (the code
  evaluates them unclipped and clips only at the start of the next iteration).
- The Levy step uses the paper's factor 0.01 (Eq. 9).
- t/T is capped at 1 (E = 0 after T iterations).
- Constrained problems: comparisons are feasibility-first (see base.py).
"""

from __future__ import annotations

import math

import numpy as np

from moik._validate import interval
from moik.algorithms.base import ArrayAlgorithm, Step
from moik.algorithms.mechanics import clip_to_bounds, is_better, mantegna_levy

RAPID_DIVE_SHARE = 0.5 * (0.5 + 0.5 * math.log(2.0))


def levy_flight(shape, beta: float, *, rng: np.random.Generator) -> np.ndarray:
    """Eq. 9: Mantegna's Levy step times 0.01."""
    return 0.01 * mantegna_levy(shape, beta, rng=rng)


def hho_moves(X, rabbit, E, r, *, xl, xu, rng: np.random.Generator):
    """Eqs. 1-7, 12: the first candidate of every hawk.

    Args:
        X: Hawks (n, d). rabbit: best so far (d,). E: escaping energies (n,).
        r: besiege draws (n,) (``r < 0.5``: rapid dives). xl, xu: bounds.
        rng: Random generator.

    Returns:
        ``(Y, dive)``: the candidates (n, d), not yet bounded, and the mask of
        hawks doing progressive rapid dives (Y is their Eq. 7 / Eq. 12 point).
    """
    n, d = X.shape
    Xm = X.mean(axis=0)  # Eq. 2
    q, r1, r2 = rng.random(n), rng.random((n, 1)), rng.random((n, 1))
    r3, r4 = rng.random((n, 1)), rng.random((n, 1))
    Xr = X[rng.integers(n, size=n)]
    J = 2.0 * (1.0 - rng.random((n, 1)))
    explore_rand = Xr - r1 * np.abs(Xr - 2.0 * r2 * X)  # Eq. 1, q >= 0.5
    explore_mean = (rabbit - Xm) - r3 * (xl + r4 * (xu - xl))  # Eq. 1, q < 0.5
    Ec, absE = E[:, None], np.abs(E)[:, None]
    soft = (rabbit - X) - Ec * np.abs(J * rabbit - X)  # Eqs. 4-5
    hard = rabbit - Ec * np.abs(rabbit - X)  # Eq. 6
    soft_dive = rabbit - Ec * np.abs(J * rabbit - X)  # Eq. 7
    hard_dive = rabbit - Ec * np.abs(J * rabbit - Xm)  # Eq. 12
    rr = r[:, None] >= 0.5
    besiege = np.where(rr, np.where(absE >= 0.5, soft, hard),
                       np.where(absE >= 0.5, soft_dive, hard_dive))
    explore = np.where(q[:, None] >= 0.5, explore_rand, explore_mean)
    Y = np.where(absE >= 1.0, explore, besiege)
    dive = (np.abs(E) < 1.0) & (r < 0.5)
    return Y, dive


class HHO(ArrayAlgorithm):
    """Harris hawks optimization (Heidari et al. 2019) with array state.

    ``X``/``F`` is the current flock (the rabbit is ``best_x``).

    Args:
        pop_size: Number of hawks N.
        beta: Levy exponent in (0, 2] (paper: 1.5).
        max_iter: Schedule length T (see ArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 50, beta: float = 1.5, max_iter: int | None = None,
                 X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, X0=X0, max_iter=max_iter, **kwargs)
        self.beta = interval("beta", beta, 0.0, 2.0, lo_open=True)

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + 0.7 * RAPID_DIVE_SHARE)

    def _generation(self) -> Step:
        rng = self.random_state
        n = len(self.X)
        E = 2.0 * (2.0 * rng.random(n) - 1.0) * (1.0 - min(self.t / self.max_iter, 1.0))  # Eq. 3
        r = rng.random(n)
        Y, dive = hho_moves(self.X, self.best_x, E, r, xl=self.xl, xu=self.xu, rng=rng)
        Y = clip_to_bounds(Y, self.xl, self.xu)
        FY, CVY = yield Y
        X, F = Y.copy(), FY.copy()
        CV = None if CVY is None else CVY.copy()
        # Eqs. 10-11: a diving hawk keeps Y only if it improves, else tries Z, else stays
        stay = np.flatnonzero(dive & ~is_better(FY, CVY, self.F, self.CV))
        X[stay], F[stay] = self.X[stay], self.F[stay]
        if CV is not None and self.CV is not None:
            CV[stay] = self.CV[stay]
        if stay.size:
            S = rng.random((stay.size, Y.shape[1]))
            Z = clip_to_bounds(Y[stay] + S * levy_flight(S.shape, self.beta, rng=rng),
                               self.xl, self.xu)  # Eqs. 8, 13
            FZ, CVZ = yield Z
            took = is_better(FZ, CVZ, F[stay], None if CV is None else CV[stay])
            X[stay[took]], F[stay[took]] = Z[took], FZ[took]
            if CV is not None:
                CV[stay[took]] = CVZ[took]
        self.X, self.F, self.CV = X, F, CV
