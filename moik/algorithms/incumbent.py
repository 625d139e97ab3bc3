"""What an array-state algorithm reports: the best so far (one objective) or a Pareto archive.

The one array-state base (:class:`moik.algorithms.array_base.ArrayStateAlgorithm`)
composes one incumbent and hands it every evaluated batch (``receive``), closes each
iteration with it (``end_iteration``), records it after each generation (``record``) and
builds ``res.opt`` from it when read (``build_opt``):

- :class:`BestSoFar` (single-objective): the best point so far, updated at once with
  every batch (feasibility first: smaller violation, then smaller f), with its
  convergence history;
- :class:`ParetoIncumbent` (multi-objective): an external archive of non-dominated
  points (:mod:`moik.algorithms.archive`), fed once per iteration with that iteration's
  rows (the archive is read only between iterations, so this is the set a merge per batch
  would give; the truncation runs once on the union).

Rows a problem's NaN/inf made ``F = CV = inf`` (:mod:`moik.algorithms.nonfinite`) are
never reported: the archive never receives them, and a best so far with non-finite
values gives an empty ``opt`` (``res.X`` None).
"""

from __future__ import annotations

import numpy as np
from pymoo.core.population import Population

from moik.algorithms.archive import ArchiveBase
from moik.algorithms.mechanics import best_index, is_better
from moik.algorithms.nonfinite import finite_rows

__all__ = ["BestSoFar", "ParetoIncumbent"]


class BestSoFar:
    """The best point so far of a single-objective run, and its history.

    Attributes:
        x: The best point (n_var,), None before the first batch.
        f: Its objective value (inf before the first batch).
        cv: Its total violation, None for unconstrained problems.
        gh: Its constraint values G and H side by side, None for unconstrained problems.
        history_f: ``f`` after each generation.
        history_x: ``x`` after each generation.
    """

    def __init__(self) -> None:
        self.x: np.ndarray | None = None
        self.f = np.inf
        self.cv: float | None = None
        self.gh: np.ndarray | None = None
        self.history_f: list[float] = []
        self.history_x: list[np.ndarray] = []

    def receive(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None,
                GH: np.ndarray | None) -> bool:
        """Take an evaluated batch (F (k,), CV (k,) or None); True if the best changed."""
        if not len(F):
            return False
        if CV is None:  # unconstrained fast path
            i = int(F.argmin())
            if F[i] < self.f or self.x is None:
                self.x, self.f = X[i].copy(), float(F[i])
                return True
            return False
        i = best_index(F, CV)
        if self.x is None or is_better(F[i], CV[i], self.f, self.cv):
            self.x, self.f, self.cv = X[i].copy(), float(F[i]), float(CV[i])
            self.gh = None if GH is None else np.array(GH[i])
            return True
        return False

    def end_iteration(self, *, rng: np.random.Generator) -> bool:
        """Nothing to merge (the best is updated with every batch)."""
        return False

    def record(self) -> None:
        """Append the best so far to the history (after each generation)."""
        self.history_f.append(self.f)
        self.history_x.append(np.array(self.x, dtype=float))

    def build_opt(self, problem) -> Population:
        """The best so far as a one-row ``Population`` (empty when its values are not finite)."""
        cv = 0.0 if self.cv is None else self.cv
        if self.x is None or not (np.isfinite(self.f) and np.isfinite(cv)):
            return Population.empty()
        args = ["X", self.x[None], "F", np.array([[self.f]]), "CV", np.array([[cv]])]
        if self.gh is not None:
            n_ieq = problem.n_ieq_constr
            args += ["G", self.gh[None, :n_ieq], "H", self.gh[None, n_ieq:]]
        return Population.new(*args)


class ParetoIncumbent:
    """The external archive of a multi-objective run, fed once per iteration.

    Args:
        archive: The archive (capacity and truncation rule are its own).
    """

    def __init__(self, archive: ArchiveBase) -> None:
        self.archive = archive
        self._buffer: list[tuple[np.ndarray, np.ndarray, np.ndarray | None,
                                 np.ndarray | None]] = []

    def receive(self, X: np.ndarray, F: np.ndarray, CV: np.ndarray | None,
                GH: np.ndarray | None) -> bool:
        """Queue an evaluated batch's finite rows for the archive (merged by ``end_iteration``)."""
        ok = finite_rows(F, CV)
        if not ok.all():
            X, F = X[ok], F[ok]
            CV, GH = (None if CV is None else CV[ok]), (None if GH is None else GH[ok])
        if len(F):
            self._buffer.append((X, F, CV, GH))
        return False

    def end_iteration(self, *, rng: np.random.Generator) -> bool:
        """Merge the iteration's queued rows into the archive at once; True if any were."""
        if not self._buffer:
            return False
        parts = list(zip(*self._buffer, strict=True))
        self._buffer = []
        X, F = np.concatenate(parts[0]), np.concatenate(parts[1])
        if parts[2][0] is not None:
            self.archive.add(X, F, rng=rng, CV=np.concatenate(parts[2]),
                             extra=np.concatenate(parts[3]))
        else:
            self.archive.add(X, F, rng=rng)
        return True

    def record(self) -> None:
        """Nothing to record (the archive is the history that matters)."""

    def build_opt(self, problem) -> Population:
        """The archive members as a ``Population`` (with CV, G and H for constrained problems)."""
        A = self.archive
        args = ["X", A.X.copy(), "F", A.F.copy()]
        if A.CV is None:
            return Population.new(*args, "CV", np.zeros((len(A), 1)))
        n_ieq, GH = problem.n_ieq_constr, A.extra
        assert GH is not None  # constrained runs store G and H with every member
        args += ["CV", A.CV[:, None].copy(), "G", GH[:, :n_ieq].copy(),
                 "H", GH[:, n_ieq:].copy()]
        return Population.new(*args)
