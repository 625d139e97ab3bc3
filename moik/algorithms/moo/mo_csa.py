"""MO-CSA: one crow search flock per objective and a shared archive.

The MO-CSA baseline of Rokbani, Neji, Slim, Mirjalili & Ghandour, "A
Multi-Objective Modified PSO for Inverse Kinematics of a 5-DOF Robotic Arm",
Applied Sciences 12, 7091 (2022), DOI 10.3390/app12147091, Section 5.2
(Table 6), built the way the paper builds MO-m-PSO (Section 2.2, Algorithm 2,
:mod:`moik.algorithms.moo.objective_swarms`): flock k runs the crow search algorithm on
objective k alone.

Crow search: Askarzadeh, "A novel metaheuristic method for solving constrained
engineering optimization problems: Crow search algorithm", Computers &
Structures 169, 1-12 (2016), DOI 10.1016/j.compstruc.2016.03.001:

- Eq. 2: crow i picks a random crow j (of its flock); if ``r_j >= AP``,
  ``x_i' = x_i + r_i fl (m_j - x_i)`` with ``m_j`` crow j's memory and
  ``r_i ~ U(0, 1)`` one number per crow; otherwise ``x_i'`` is a random position
  in the box;
- the new position is taken only if it is feasible (inside the box), else the
  crow stays where it is;
- Eq. 3: the memory ``m_i`` takes ``x_i'`` if it is better.

Every evaluated position of every flock is offered to the shared
crowding-radius archive; ``res.X``/``res.F`` are its front and
``moik.metrics.compromise(res)`` picks the member closest to the utopia point (Eq. 8).

Defaults: awareness probability AP=0.1, flight length fl=2 (Askarzadeh's
defaults; the MO-m-PSO paper gives none). Evaluations: at most
``M pop_size`` per iteration (the positions inside the box), ``M pop_size``
for the initial population.

Readings and deviations:
- The paper names MO-CSA after Rizk-Allah et al. (its ref. 37) but describes
  it no further; this is the paper's own multi-swarm construction with CSA.
- Askarzadeh's code evaluates the infeasible new positions too and then
  discards them; here they are not evaluated (they could never be taken and
  must not enter the archive), so an iteration may use fewer evaluations.
- The CSA kernel lives here (moik has no single-objective CSA module yet).
- Archive: the EOSMA paper's crowding-radius archive, capacity ``archive_size``
  (default ``pop_size``), as for MO-m-PSO.

Close to uniform random sampling on ZDT1/3 with 30 variables: a port of Askarzadeh's
CSA.m run in the same construction gives the same picture (``studies/moo_quality.py``,
reference table): the method's (a crow follows a random crow's memory, a tenth of the
moves are random positions), not this implementation's.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik._validate import interval
from moik.algorithms.mechanics import clip_to_bounds, uniform_population
from moik.algorithms.moo.base import Step
from moik.algorithms.moo.objective_swarms import ObjectiveSwarms, swarm_partners


def crow_move(X: np.ndarray, M_followed: np.ndarray, *, AP: float, fl: float,
              xl: np.ndarray, xu: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """CSA Eq. 2: follow the memory of a chosen crow, or fly to a random position.

    Args:
        X: Crow positions, shape (n, d).
        M_followed: Memory of the crow each one follows, shape (n, d).
        AP: Awareness probability (the followed crow notices: random position).
        fl: Flight length.
        xl: Lower bounds, shape (d,).
        xu: Upper bounds, shape (d,).
        rng: Random generator.

    Returns:
        New positions, shape (n, d); may lie outside the box (see
        :func:`inside_box`).
    """
    n = len(X)
    aware = rng.random(n) < AP
    X_new = X + (rng.random(n) * fl)[:, None] * (M_followed - X)
    k = int(aware.sum())
    if k:
        X_new[aware] = uniform_population(k, xl, xu, rng=rng)
    return X_new


def inside_box(X: np.ndarray, xl: np.ndarray, xu: np.ndarray) -> np.ndarray:
    """Rows of ``X`` with every coordinate in ``[xl, xu]`` (CSA's feasibility test)."""
    return np.all(clip_to_bounds(X, xl, xu) == X, axis=1)


class MOCSA(ObjectiveSwarms):
    """MO-CSA (crow search per objective, Rokbani et al. 2022); ``res.F`` = the archive.

    ``X``/``F`` are the crows' positions, ``pbest_X``/``pbest_S`` their
    memories (see :class:`ObjectiveSwarms`).

    Args:
        pop_size: Crows per flock N (one flock per objective).
        archive_size: Archive capacity; None means ``pop_size``.
        AP: Awareness probability in [0, 1] (Askarzadeh: 0.1).
        fl: Flight length in (0, 10] (Askarzadeh: 2).
        X0: Optional initial points (at most M * pop_size rows).
        **kwargs: pymoo ``Algorithm`` options.
    """

    def __init__(self, *, pop_size: int = 100, archive_size: int | None = None,
                 AP: float = 0.1, fl: float = 2.0, X0: np.ndarray | None = None, **kwargs):
        super().__init__(pop_size=pop_size, archive_size=archive_size, X0=X0, **kwargs)
        self.AP = interval("AP", AP, 0.0, 1.0)
        self.fl = interval("fl", fl, 0.0, 10.0, lo_open=True)

    def _generation(self) -> Step:
        rng = self.random_state
        j = swarm_partners(self.problem.n_obj, self.pop_size, rng=rng)
        X_new = crow_move(self.X, self.pbest_X[j], AP=self.AP, fl=self.fl, xl=self.xl,
                          xu=self.xu, rng=rng)  # Eq. 2
        ok = inside_box(X_new, self.xl, self.xu)
        X, F = self.X.copy(), self.F.copy()
        X[ok] = X_new[ok]
        F[ok], CV_ok = yield X_new[ok]  # possibly no rows: an iteration always yields once
        CV = None if self.CV is None else self.CV.copy()
        if CV is not None:
            CV[ok] = CV_ok
        self._remember(X, F, CV)  # Eq. 3; crows that stayed cannot improve their memory
