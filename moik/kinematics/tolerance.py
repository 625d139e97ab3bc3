"""The pose tolerance of a solve (:class:`Tolerance`): parsed in one place, with its rules.

Every entry point that certifies an IK answer (``solve_ik``, ``solve_ik_batch``,
``solve_path``, ``solve_ik_pareto`` and :class:`~moik.problems.ParetoIK`) reads its
``tol`` argument through :meth:`Tolerance.of`, so they refuse and accept the same values,
and asks the tolerance the questions that depend on it: when a local search may stop
(:attr:`Tolerance.stop`, :attr:`Tolerance.polish_stop`) and whether errors recomputed by
forward kinematics certify an answer (:meth:`Tolerance.certifies`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from moik._validate import positive
from moik.exceptions import ParameterError

MIN_TOL = 1e-14  # smallest tolerance (relative to reach; rad): ~45 eps, above FK's rounding
STOP_FRACTION = 0.1  # a start stops at this fraction of the tolerances (margin for the re-check)
POLISH_FRACTION = 1e-3  # a least-squares polish stops at this fraction of them


class Tolerance(NamedTuple):
    """Position (robot unit) and orientation (rad) tolerances of an answer.

    Build it with :meth:`of` (a number ``t`` means ``t * reach`` and ``t`` rad).
    """

    position: float
    orientation: float

    @classmethod
    def of(cls, tol, reach: float) -> Tolerance:
        """The tolerance of ``tol``: a number ``t`` (``t * reach``, ``t`` rad) or a pair.

        Each must be a finite number, at least :data:`MIN_TOL` (times ``reach`` for a
        position): float64 FK computes a pose to a few ``eps * reach`` (``eps`` = 2.2e-16,
        times the number of joints), so a smaller tolerance could not be certified by the
        re-check, and a reachable pose would be called unreachable.

        Raises:
            ParameterError: Anything else, naming what was given and the smallest
                accepted value.
        """
        if type(tol) is float and MIN_TOL <= tol < np.inf:  # the usual case, checked as below
            return cls(tol * reach, tol)
        if isinstance(tol, np.ndarray) and tol.ndim == 0:
            tol = tol.item()
        try:
            shape = np.shape(tol)
        except ValueError:  # ragged sequences
            shape = None
        if shape == ():
            t = _at_least("tol", tol, MIN_TOL, "")
            return cls(t * reach, t)
        if shape == (2,):
            return cls(_at_least("tol[0] (position tolerance)", tol[0], MIN_TOL * reach,
                                 f" ({MIN_TOL:g} x reach {reach:g})"),
                       _at_least("tol[1] (orientation tolerance)", tol[1], MIN_TOL, " rad"))
        raise ParameterError(f"tol must be a number or (position, orientation), got {tol!r}")

    @property
    def stop(self) -> tuple[float, float]:
        """Errors at which a Levenberg-Marquardt start has converged: a fraction
        (:data:`STOP_FRACTION`) of the tolerances, a margin for the re-check."""
        return STOP_FRACTION * self.position, STOP_FRACTION * self.orientation

    @property
    def polish_stop(self) -> tuple[float, float]:
        """Errors at which a least-squares polish stops (:data:`POLISH_FRACTION` of them)."""
        return POLISH_FRACTION * self.position, POLISH_FRACTION * self.orientation

    def certifies(self, position_error, orientation_error):
        """Whether recomputed errors are within the tolerance (a bool, or a bool array
        for arrays)."""
        if isinstance(position_error, float) and isinstance(orientation_error, float):
            return bool(position_error <= self.position
                        and orientation_error <= self.orientation)  # the hot path: scalars
        ok = (np.less_equal(position_error, self.position)
              & np.less_equal(orientation_error, self.orientation))
        return bool(ok) if np.ndim(ok) == 0 else ok

    def scaled(self, reach: float) -> float:
        """``position / reach + orientation``: the tolerance in the units of the solver's
        scaled error ``pos / reach + ori``."""
        return self.position / reach + self.orientation


def _at_least(name: str, value, smallest: float, unit: str) -> float:
    value = positive(name, value)
    if value < smallest:
        raise ParameterError(f"{name} must be at least {smallest:g}{unit}, the smallest "
                             f"tolerance float64 forward kinematics can certify, got {value!r}")
    return value
