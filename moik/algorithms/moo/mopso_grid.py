"""MOPSO: multi-objective particle swarm optimization with an adaptive grid.

Coello Coello, Toscano Pulido & Salazar Lechuga, "Handling multiple objectives
with particle swarm optimization", IEEE Transactions on Evolutionary
Computation 8(3), 256-279 (2004), DOI 10.1109/TEVC.2004.826067, Section III,
with the parameters of the EOSMA paper's Table 4 (Yin et al. 2022,
DOI 10.1038/s41598-022-13516-3), which are those of the widely used MATLAB
port by M. K. Heris (Yarpiz), whose mutation this module follows:

- repository: non-dominated particles in an adaptive hypercube grid
  (:meth:`~moik.algorithms.archive.GridArchive.mopso`: 7 grids, inflation 0.1,
  leader pressure beta=2, deletion pressure gamma=2), capacity ``archive_size``;
- Eq. (a) of Section III: ``v = w v + c1 r1 (pbest - x) + c2 r2 (REP[h] - x)``,
  one leader ``REP[h]`` per particle drawn from the grid (emptier cells likelier),
  r1 and r2 per coordinate; ``x = x + v``;
- a particle leaving the box takes the boundary value and the velocity
  component is reversed (``v = -v``, Section III);
- mutation: with probability ``pm = (1 - (t - 1)/(T - 1))^(1/mu)`` a particle
  gets one coordinate redrawn uniformly in ``x_j +/- pm (xu_j - xl_j)`` (clipped
  to the box); the mutant replaces the particle if it dominates it, is kept
  out if dominated, else replaces it with probability 1/2;
- personal best: replaced if the new position dominates it, kept if it
  dominates the new position, else replaced with probability 1/2 (Section III);
- inertia damped every iteration: ``w_t = w wdamp^(t - 1)``.

Defaults (Table 4): w=0.5, damping 0.99, c1=1, c2=2, mutation rate mu=0.1,
7 grids, inflation 0.1, beta=2, gamma=2, N = archive = 100. Evaluations per
iteration: ``N`` plus one per mutated particle, ``N (1 + pm(t))`` on average,
``N (1 + mu / (1 + mu))`` over a run (~1.09 N).

Deviations and readings:
- The 2004 paper uses w=0.4, c1=c2=1, 30 grid divisions and its own mutation
  schedule; Table 4's values and the Yarpiz mutation are used instead.
- Every evaluated point (mutants included) is offered to the repository (the
  Yarpiz code offers only each particle's final position of the iteration).
- Constraints (not in the paper's Section III): every "dominates" above is
  constraint-domination (feasible first, then smaller violation), as in the
  repository.

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

from moik._validate import interval
from moik.algorithms.archive import ArchiveBase, GridArchive
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.moo.dominance import constrained_dominates
from moik.algorithms.soo.pso import pso_velocity


def mutation_rate(t: int, T: int, mu: float) -> float:
    """``pm = (1 - (t - 1)/(T - 1))^(1/mu)`` for iteration ``t = 1 .. T`` (0 after T)."""
    s = min((t - 1) / max(T - 1, 1), 1.0)
    return (1.0 - s) ** (1.0 / mu)


def mopso_mutation(X: np.ndarray, pm: float, xl: np.ndarray, xu: np.ndarray, *,
                   rng: np.random.Generator) -> np.ndarray:
    """Redraw one random coordinate per row uniformly in ``x_j +/- pm (xu_j - xl_j)``."""
    n, d = X.shape
    rows, j = np.arange(n), rng.integers(d, size=n)
    dx = pm * (xu[j] - xl[j])
    lo = np.maximum(X[rows, j] - dx, xl[j])
    hi = np.minimum(X[rows, j] + dx, xu[j])
    X = X.copy()
    X[rows, j] = lo + rng.random(n) * (hi - lo)
    return X


def pareto_accept(F_new: np.ndarray, F_old: np.ndarray, *, rng: np.random.Generator,
                  CV_new: np.ndarray | None = None, CV_old: np.ndarray | None = None
                  ) -> np.ndarray:
    """Rows where the new point replaces the old: it dominates, or neither does and a coin.

    With ``CV_new``/``CV_old`` (constrained problems) "dominates" is constraint-domination.
    """
    coin = rng.random(len(F_new)) < 0.5
    return constrained_dominates(F_new, CV_new, F_old, CV_old) | (
        ~constrained_dominates(F_old, CV_old, F_new, CV_new) & coin)


def reflect_velocity(X: np.ndarray, V: np.ndarray, xl: np.ndarray, xu: np.ndarray):
    """Move ``X`` by ``V``; a coordinate leaving the box stops at the bound, its velocity flips.

    Returns:
        The new positions and velocities ``(X, V)``.
    """
    X_moved = X + V
    X_new = clip_to_bounds(X_moved, xl, xu)
    return X_new, np.where(X_new != X_moved, -V, V)


class MOPSO(MOArrayAlgorithm):
    """MOPSO (Coello Coello et al. 2004) with array state; ``res.X``/``res.F`` = the grid archive.

    Extra public arrays: ``V`` (velocities), ``pbest_X``/``pbest_F``/``pbest_CV``
    (personal bests), ``w_t`` (inertia of the last iteration). ``X``/``F``/``CV`` is
    the swarm.

    Args:
        pop_size: Number of particles N (Table 4: 100).
        archive_size: Repository capacity; None means ``pop_size`` (Table 4: 100).
        w: Initial inertia weight in [0, 1.5] (Table 4: 0.5).
        wdamp: Inertia damping rate per iteration in (0, 1] (Table 4: 0.99).
        c1: Personal coefficient in [0, 4] (Table 4: 1).
        c2: Social coefficient in [0, 4] (Table 4: 2).
        mu: Mutation rate in (0, 1] (Table 4: 0.1).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 w: float = 0.5, wdamp: float = 0.99, c1: float = 1.0, c2: float = 2.0,
                 mu: float = 0.1, max_iter: int | None = None, X0: np.ndarray | None = None,
                 **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0,
                         max_iter=max_iter, **kwargs)
        self.w = interval("w", w, 0.0, 1.5)
        self.wdamp = interval("wdamp", wdamp, 0.0, 1.0, lo_open=True)
        self.c1 = interval("c1", c1, 0.0, 4.0)
        self.c2 = interval("c2", c2, 0.0, 4.0)
        self.mu = interval("mu", mu, 0.0, 1.0, lo_open=True)

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return GridArchive.mopso(capacity)

    def _evals_per_iteration(self) -> float:
        return self.pop_size * (1.0 + self.mu / (1.0 + self.mu))

    def _initialize_state(self) -> None:
        self.V = np.zeros_like(self.X)
        self.pbest_X, self.pbest_F, self.pbest_CV = self.X, self.F, self.CV
        self.w_t = self.w

    def _generation(self) -> Step:
        rng, A = self.random_state, self.pareto_archive
        self.w_t = self.w * self.wdamp ** max(self.t - 1, 0)
        leader = A.X[A.leaders(self.pop_size, rng=rng)]
        V = pso_velocity(self.V, self.X, self.pbest_X, leader, w=self.w_t, c1=self.c1,
                         c2=self.c2, rng=rng)
        X, self.V = reflect_velocity(self.X, V, self.xl, self.xu)
        F, CV = yield X
        pm = mutation_rate(self.t, self.max_iter, self.mu)
        mutated = np.flatnonzero(rng.random(self.pop_size) < pm)
        if mutated.size:
            Xm = mopso_mutation(X[mutated], pm, self.xl, self.xu, rng=rng)
            Fm, CVm = yield Xm
            take = pareto_accept(Fm, F[mutated], rng=rng, CV_new=CVm,
                                 CV_old=None if CV is None else CV[mutated])
            X, F = X.copy(), F.copy()
            X[mutated[take]], F[mutated[take]] = Xm[take], Fm[take]
            if CV is not None:
                CV = CV.copy()
                CV[mutated[take]] = CVm[take]
        self.X, self.F, self.CV = X, F, CV
        take = pareto_accept(F, self.pbest_F, rng=rng, CV_new=CV, CV_old=self.pbest_CV)
        self.pbest_X = np.where(take[:, None], X, self.pbest_X)
        self.pbest_F = np.where(take[:, None], F, self.pbest_F)
        if CV is not None and self.pbest_CV is not None:
            self.pbest_CV = np.where(take, CV, self.pbest_CV)
