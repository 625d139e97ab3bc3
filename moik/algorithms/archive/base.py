"""Shared mechanics of the external archives: validation, Pareto filter, merge.

An external archive keeps the non-dominated solutions found so far as two
arrays, ``X`` (m, n_var) and ``F`` (m, n_obj). Every archive merges new
solutions the same way (EOSMA paper, Yin et al. 2022, Sci. Rep. 12, 9421,
https://doi.org/10.1038/s41598-022-13516-3, archive steps (1)-(2) before
Eq. 19):

1. stack the current members and the new solutions (members first);
2. keep the solutions no other solution dominates, with ordinary Pareto
   dominance (Eq. 11): ``a`` dominates ``b`` when ``a <= b`` in every objective
   and ``a < b`` in at least one;
3. drop exact duplicate objective rows, keeping the first occurrence (so a
   member already in the archive keeps its ``X``).

Constrained problems (``CV`` given, the total constraint violation of each row,
0 when feasible): step 2 uses constraint-domination (Deb's rules, as pymoo's
multi-objective algorithms): a feasible row dominates an infeasible one, of two
infeasible rows the smaller violation dominates, two feasible rows compare by
Pareto dominance. So the archive holds the feasible non-dominated rows as soon
as one feasible row was seen. Before that (a moik extension: the papers' archives
and their reference codes have no constraint handling), it holds the ``capacity``
rows of smallest violation, distinct in ``F``, as NSGA-II's constrained survival
fills its population with infeasible rows ranked by violation
(:func:`least_infeasible_mask`): a strict constraint-domination filter would
keep the single least infeasible row, and every leader drawn from a one-member
archive would be that row (the measured effect on pymoo's MW1-MW3 and CTP1-CTP3:
docs/results/constrained-moo.md, ``studies/constrained_moo.py``).
Truncation and leaders work on ``F`` as without constraints. Rows carried in
``extra`` (the constraint values G, H) follow their members. An unconstrained
archive (``CV`` None) is untouched by all of this.

What differs between archives is only how an overfull archive is truncated and
how leaders are drawn; subclasses implement ``_truncate`` and ``leaders``.

The Pareto filters themselves (plain and constraint-domination, the duplicate
filter) are in :mod:`moik.algorithms.archive.fronts`.
"""

from __future__ import annotations

import abc

import numpy as np
from numpy.typing import ArrayLike

from moik._validate import finite_array, is_integer, positive
from moik.algorithms.archive.fronts import (
    constrained_nondominated_mask,
    first_unique_mask,
    front_mask_2d,
)
from moik.exceptions import ParameterError, ShapeError


def as_finite_2d(name: str, value: object, n_cols: int | None = None) -> np.ndarray:
    """Return ``value`` as a finite float array of shape (rows, n_cols).

    Args:
        name: Name used in error messages (``"X"``, ``"F"``).
        value: Array-like input.
        n_cols: Required number of columns, or ``None`` for any positive number.

    Raises:
        ShapeError: If the array is not 2-D or has the wrong number of columns.
        NonFiniteError: If it holds NaN or infinite values.
    """
    arr = np.asarray(value, dtype=float)
    if arr.ndim != 2:
        raise ShapeError(f"{name} must be a 2-D array (rows, columns); got shape {arr.shape}")
    if n_cols is not None and arr.shape[1] != n_cols:
        raise ShapeError(f"{name} must have {n_cols} columns; got shape {arr.shape}")
    if arr.shape[1] == 0:
        raise ShapeError(f"{name} must have at least one column; got shape {arr.shape}")
    return finite_array(name, arr)


def check_count(name: str, value: object, minimum: int) -> int:
    """Return ``value`` as an int, checking it is an integer >= ``minimum``.

    The rule is moik's (:func:`moik._validate.is_integer`: bools and floats are
    refused); the message keeps the archives' wording.

    Raises:
        ParameterError: If ``value`` is not an integer or is below ``minimum``.
    """
    if not (is_integer(value) and value >= minimum):
        raise ParameterError(f"{name} must be an integer >= {minimum}; got {value!r}")
    return int(value)


def check_positive(name: str, value: object, *, allow_zero: bool = False) -> float:
    """Return ``value`` as a float, checking it is finite and > 0 (or >= 0).

    The rule is :func:`moik._validate.positive`; the message keeps the archives' wording.

    Raises:
        ParameterError: If ``value`` is not a finite real number in range.
    """
    try:
        return positive(name, value, allow_zero=allow_zero)
    except ParameterError:
        bound = ">= 0" if allow_zero else "> 0"
        raise ParameterError(f"{name} must be a finite number {bound}; got {value!r}") from None


def roulette(weights: np.ndarray, size: int, rng: np.random.Generator) -> np.ndarray:
    """Draw ``size`` indices with probability proportional to ``weights``.

    With replacement; ``weights`` must be non-negative with a positive sum.
    """
    cdf = np.cumsum(weights)
    return np.searchsorted(cdf, rng.random(size) * cdf[-1], side="right").clip(max=weights.size - 1)


def least_infeasible_mask(F: np.ndarray, CV: np.ndarray, capacity: int) -> np.ndarray:
    """Mask of the ``capacity`` rows of smallest violation (distinct objective rows, the
    first of equal violations first): the archive while no row is feasible (module doc)."""
    keep = np.zeros(len(CV), dtype=bool)
    unique = np.flatnonzero(first_unique_mask(F))
    keep[unique[np.argsort(CV[unique], kind="stable")[:capacity]]] = True
    return keep


class ArchiveBase(abc.ABC):
    """Array-based external archive of non-dominated solutions.

    Attributes:
        capacity: Maximum number of members after :meth:`add`.
        X: Decision vectors of the members, shape (m, n_var), read-only.
        F: Objective values of the members, shape (m, n_obj), read-only.
        CV: Constraint violation of the members (m,), or None (unconstrained).
        extra: Rows carried along with the members (m, k), or None.
    """

    def __init__(self, capacity: int):
        self.capacity = check_count("capacity", capacity, 1)
        self._X = np.empty((0, 0))
        self._F = np.empty((0, 0))
        self._CV: np.ndarray | None = None
        self._extra: np.ndarray | None = None
        self._freeze()

    @property
    def X(self) -> np.ndarray:
        """Decision vectors of the members, shape (m, n_var)."""
        return self._X

    @property
    def F(self) -> np.ndarray:
        """Objective values of the members, shape (m, n_obj)."""
        return self._F

    @property
    def CV(self) -> np.ndarray | None:
        """Constraint violation of the members (m,), 0 when feasible; None if unconstrained."""
        return self._CV

    @property
    def extra(self) -> np.ndarray | None:
        """The rows given as ``extra`` to :meth:`add`, one per member, or None."""
        return self._extra

    def __len__(self) -> int:
        return self._F.shape[0]

    def add(self, X: object, F: object, *, rng: np.random.Generator,
            CV: ArrayLike | None = None, extra: object = None) -> None:
        """Merge new solutions into the archive and truncate it to ``capacity``.

        Args:
            X: Decision vectors, shape (k, n_var).
            F: Their objective values (minimized), shape (k, n_obj).
            rng: Random generator used for truncation (roulette removal).
            CV: Their total constraint violations (k,), 0 when feasible, for constrained
                problems (constraint-domination, see the module doc); given on every
                call or on none.
            extra: Rows (k, j) to keep beside the members (e.g. the constraint values).

        Raises:
            ShapeError: If the shapes disagree with each other or with the
                members already stored, or ``CV`` is given on some calls only.
            NonFiniteError: If ``X``, ``F``, ``CV`` or ``extra`` hold NaN or infinite values.
        """
        empty = len(self) == 0 and self._X.shape[1] == 0
        X = as_finite_2d("X", X, None if empty else self._X.shape[1])
        F = as_finite_2d("F", F, None if empty else self._F.shape[1])
        if X.shape[0] != F.shape[0]:
            raise ShapeError(
                f"X and F must have the same number of rows; got X {X.shape} and F {F.shape}"
            )
        for name, new, old in (("CV", CV, self._CV), ("extra", extra, self._extra)):
            if not empty and (new is None) != (old is None):
                raise ShapeError(f"{name} must be given on every add() of an archive or on "
                                 f"none; got {'None' if new is None else 'values'} after "
                                 f"{'none' if old is None else 'values'}")
        if CV is not None:
            CV = as_finite_2d("CV", np.reshape(CV, (-1, 1)), 1)[:, 0]
        if extra is not None:
            extra = as_finite_2d("extra", extra, None if empty or self._extra is None
                                 else self._extra.shape[1])
        for name, arr in (("CV", CV), ("extra", extra)):
            if arr is not None and arr.shape[0] != X.shape[0]:
                raise ShapeError(f"{name} must have one entry per row of X ({X.shape[0]}); "
                                 f"got {arr.shape[0]}")
        X_all = np.concatenate([self._X, X]) if not empty else X.copy()
        F_all = np.concatenate([self._F, F]) if not empty else F.copy()
        CV_all = None if CV is None else (CV.copy() if empty else np.concatenate([self._CV, CV]))
        extra_all = None if extra is None else (
            extra.copy() if empty else np.concatenate([self._extra, extra]))
        if CV_all is None and F_all.shape[1] == 2:
            keep = front_mask_2d(F_all, True)  # both filters in one sweep
        elif CV_all is not None and not np.any(CV_all <= 0.0):
            keep = least_infeasible_mask(F_all, CV_all, self.capacity)
        else:
            keep = constrained_nondominated_mask(F_all, CV_all)
            keep[keep] = first_unique_mask(F_all[keep])
        self._X, self._F = X_all[keep], F_all[keep]
        self._CV = None if CV_all is None else CV_all[keep]
        self._extra = None if extra_all is None else extra_all[keep]
        self._update(rng)
        self._freeze()

    @abc.abstractmethod
    def _update(self, rng: np.random.Generator) -> None:
        """Truncate ``_X``/``_F`` to capacity and refresh derived state."""

    @abc.abstractmethod
    def leaders(self, k: int, *, rng: np.random.Generator) -> np.ndarray:
        """Indices (k,) of members drawn as leaders (with replacement)."""

    def _remove(self, drop: np.ndarray) -> None:
        keep = np.ones(len(self), dtype=bool)
        keep[drop] = False
        self._X, self._F = self._X[keep], self._F[keep]
        if self._CV is not None:
            self._CV = self._CV[keep]
        if self._extra is not None:
            self._extra = self._extra[keep]

    def _check_leaders(self, k: object) -> int:
        k = check_count("k", k, 0)
        if len(self) == 0:
            raise ShapeError("the archive is empty (0 members); add solutions before leaders()")
        return k

    def _freeze(self) -> None:
        for arr in (self._X, self._F, self._CV, self._extra):
            if arr is not None:
                arr.flags.writeable = False

    def __repr__(self) -> str:
        return f"{type(self).__name__}(capacity={self.capacity}, members={len(self)})"
