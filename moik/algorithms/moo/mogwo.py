"""Multi-objective grey wolf optimizer (MOGWO).

Mirjalili, Saremi, Mirjalili & Coelho, "Multi-objective grey wolf optimizer: a
novel algorithm for multi-criterion optimization", Expert Systems with
Applications 47, 106-119 (2016), DOI 10.1016/j.eswa.2015.10.039, Section 3
(GWO Eqs. 3.1-3.11, archive and leader selection in Section 3.1), and
Mirjalili's MOGWO.m / SelectLeader.m / DeleteFromRep.m (version 1.0):

- hunting (Eqs. 3.1-3.11): ``D = |C X_p - X|``, ``X_k = X_p - A D`` for the
  leaders alpha, beta, delta; ``A = 2 a r1 - a``, ``C = 2 r2`` (per
  coordinate), ``a = 2 - 2 t / T`` with ``t = 1 .. T``; ``X = (X1 + X2 + X3) / 3``;
  clipped to the bounds;
- leaders: per wolf, three distinct archive members drawn from the adaptive
  grid: a cell by roulette with weight ``n_c^(-beta)``, then a uniform member;
  the second draw leaves the first out, the third leaves both out (cell counts
  recomputed without them), as MOGWO.m does with ``rep2``/``rep3``;
- archive (:meth:`GridArchive.mogwo`): non-dominated merge, overflow removed
  cell by cell with weight ``n_c^gamma``.

Defaults (EOSMA paper, Yin et al. 2022, Table 4): 10 grids, inflation alpha
0.1, leader pressure beta 4, deletion pressure gamma 2; N = archive = 100
(Table 8: T = 1000). Evaluations per iteration: N.

Deviations and readings:
- ``A`` is drawn per coordinate for all three leaders (Eq. 3.3); MOGWO.m
  draws one scalar ``A`` for the beta and alpha moves.
- The grid is rebuilt over the archive after every update (see
  :mod:`moik.algorithms.archive.grid`); MOGWO.m rebuilds it only after a
  truncation, so new members can fall outside it.
- Leader pressure ``n^(-beta)`` and deletion ``n^gamma`` are the code's; the
  paper's ``P_i = c / N_i`` is the case beta = 1.
- Random streams differ from MATLAB's; only the distributions match.

Constraints: a moik extension (the paper and the authors' code have none), the shared one
of docs/algorithms.md "Constraints" (constraint-domination in the archive and the leaders;
the least infeasible rows kept while none is feasible, and the feasibility search of
:mod:`moik.algorithms.moo.feasibility_search` until one is; docs/results/constrained-moo.md).
"""

from __future__ import annotations

import numpy as np

from moik.algorithms.archive import ArchiveBase, GridArchive
from moik.algorithms.mechanics import clip_to_bounds
from moik.algorithms.moo.base import MOArrayAlgorithm, Step
from moik.algorithms.soo.igwo import gwo_move


def distinct_grid_leaders(archive: GridArchive, n: int, *, rng: np.random.Generator
                          ) -> np.ndarray:
    """Delta, beta and alpha of ``n`` wolves: member indices (n, 3), distinct where possible.

    Each draw picks a cell by roulette on ``archive.leader_weights`` of the cell
    counts without the members already drawn for that wolf, then a uniform member
    of that cell among the remaining ones (MOGWO.m's SelectLeader on rep2/rep3).
    """
    m, cells, counts = len(archive), archive.cells, archive.cell_counts
    order = np.argsort(cells, kind="stable")
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    rank = np.empty(m, dtype=np.int64)
    rank[order] = np.arange(m) - starts[cells[order]]
    rows = np.arange(n)
    out = np.empty((n, 3), dtype=np.int64)
    for k in range(3):
        excl = out[:, :k] if k < m else out[:, :0]  # MOGWO.m: rep2 if m > 1, rep3 if m > 2
        left = np.broadcast_to(counts, (n, counts.size)).copy()
        for e in excl.T:
            left[rows, cells[e]] -= 1
        w = np.where(left > 0, archive.leader_weights(np.maximum(left, 1)), 0.0)
        cdf = np.cumsum(w, axis=1)
        cell = (cdf > rng.random(n)[:, None] * cdf[:, -1:]).argmax(axis=1)
        r = np.minimum((rng.random(n) * left[rows, cell]).astype(np.int64), left[rows, cell] - 1)
        skip = np.sort(np.where(cells[excl] == cell[:, None], rank[excl], m), axis=1)
        for q in skip.T:  # step over the left-out members of the chosen cell
            r = r + (q <= r)
        out[:, k] = order[starts[cell] + r]
    return out


class MOGWO(MOArrayAlgorithm):
    """MOGWO (Mirjalili et al. 2016) with array state; ``res.X``/``res.F`` = the archive.

    Extra public array: ``leader_index`` ((N, 3) archive rows of delta, beta,
    alpha in the last iteration).

    Args:
        pop_size: Number of wolves N (paper setting: 100).
        archive_size: Archive capacity; None means ``pop_size`` (paper setting: 100).
        max_iter: Schedule length T (see MOArrayAlgorithm).
        X0: Optional initial points.
        **kwargs: pymoo ``Algorithm`` options.
    """

    pareto_archive: GridArchive

    def _make_archive(self, capacity: int) -> ArchiveBase:
        return GridArchive.mogwo(capacity)

    def _generation(self) -> Step:
        rng, A = self.random_state, self.pareto_archive
        a = 2.0 - 2.0 * self.t / self.max_iter
        self.leader_index = idx = distinct_grid_leaders(A, self.pop_size, rng=rng)
        X = gwo_move(self.X, (A.X[idx[:, 0]], A.X[idx[:, 1]], A.X[idx[:, 2]]), a, rng=rng)
        X = clip_to_bounds(X, self.xl, self.xu)
        F, CV = yield X
        self.X, self.F, self.CV = X, F, CV
