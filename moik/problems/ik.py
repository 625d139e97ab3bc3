"""Inverse kinematics as vectorized pymoo Problems.

Decision variables are the joint values (bounds = the robot's joint limits).
``_evaluate`` makes one compiled call per population,
:func:`~moik.problems.ik_kernels.ik_objectives`: FK of every row, its error metric and
the displacement term, fused, so no intermediate pose array is built.

* :class:`PositionIK`: one objective, the position error (EOSMA Eq. 29; also
  the I-BES and MChOA Eq. 3 objective).
* :class:`PoseIK`: one objective, ``w1 * position + w2 * orientation`` (EOSMA
  Eq. 28 with ``orientation="eosma-euler"``, the Eq. 26/30 Euler error; MChOA
  Eq. 6 with ``orientation="frobenius"``; the geodesic angle by default).
* :class:`BiObjectiveIK`: two objectives (position error, orientation error),
  the MOEOSMA / MO-m-PSO formulation (MO-m-PSO Eq. 15).

Each takes ``displacement_weight`` and ``q_start`` for EOSMA Eq. 31: the term
``w * ||q - q_start||`` is added to every objective, preferring solutions that
move the arm least.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from pymoo.core.problem import Problem

from moik._lazy import lazy_module
from moik._validate import positive, real_array
from moik.exceptions import NonFiniteError, ParameterError, ShapeError, TargetError
from moik.kinematics.rotation_metrics import metric_code
from moik.kinematics.target_spec import TargetSpec, target_spec
from moik.problems.ik_kernels import (
    BI_OBJECTIVE,
    POSITION,
    WEIGHTED_POSE,
    IKObjectives,
    ik_objectives,
    new_objectives,
)
from moik.problems.targets import Target, as_target, check_unit_range
from moik.robots.chain import Robot
from moik.robots.fk_kernels import all_finite

if TYPE_CHECKING:
    from moik.fronts import cache as front_cache
    from moik.fronts.front import ReferenceFront
else:  # loaded at the first reference front (moik._lazy): a solve needs none of it
    front_cache = lazy_module("moik.fronts.cache")


class _IKProblem(Problem):
    """Shared set-up: robot, target, bounds, displacement term."""

    def evaluate(self, X, *args, **kwargs):
        """pymoo's ``evaluate``, after checking that ``X`` has one column per joint."""
        shape = np.shape(X)
        if len(shape) not in (1, 2) or shape[-1] != self.n_var:
            raise ShapeError(f"X must have shape (n, {self.n_var}) or ({self.n_var},) (one "
                             f"column per joint), got {shape}")
        return super().evaluate(X, *args, **kwargs)

    n_obj_ik = 1
    _mode = POSITION  # what ik_objectives computes for this problem

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = self._objectives(X, self._mode, self._weights)

    def batch_objectives(self, X: np.ndarray) -> np.ndarray | None:
        """``evaluate(X)["F"]`` of a 2-D batch ``(n, n_var)``, bit for bit, in one compiled
        call without pymoo's per-call bookkeeping (the array-state algorithms' hot path:
        at N = 50 that bookkeeping is a third of a generation). ``None`` when a subclass
        evaluates differently (overrides ``evaluate`` or ``_evaluate``): callers then use
        ``evaluate``."""
        if not self._evaluates_as_defined():
            return None
        if X.ndim != 2 or X.shape[1] != self.n_var:
            raise ShapeError(f"X must have shape (n, {self.n_var}), got {X.shape}")
        return self._objectives(X, self._mode, self._weights)

    def compiled_objectives(self) -> IKObjectives | None:
        """This problem's objectives as compiled code evaluates them (:class:`IKObjectives`,
        through :func:`moik._jit.objectives_row`: ``evaluate(Q)["F"]`` of a row bit for bit,
        no check, so the rows must be finite joint values within the bounds): the hot path
        of an algorithm that evaluates one row at a time, such as MOEA/D. ``None`` when a
        subclass evaluates differently (as :meth:`batch_objectives`). Made per use, not
        stored: a numba StructRef does not pickle."""
        if not self._evaluates_as_defined():
            return None
        return new_objectives(chain=self.robot.chain_model, target=self.target_spec,
                              mode=self._mode, weights=self._weights, q_start=self._q_start)

    @property
    def target_spec(self) -> TargetSpec:
        """The target and its orientation metric as kernels take them
        (:class:`~moik.kinematics.target_spec.TargetSpec`; built once, not pickled)."""
        spec = self.__dict__.get("_target_spec")
        if spec is None:
            spec = self.__dict__["_target_spec"] = target_spec(
                self.target.position, self.target.rotation if self._metric else None,
                metric=self._metric)
        return spec

    def __getstate__(self) -> dict:
        """pymoo's state without the compiled target (a numba StructRef does not pickle)."""
        state = dict(super().__getstate__())
        state.pop("_target_spec", None)
        return state

    def _evaluates_as_defined(self) -> bool:
        """Whether ``evaluate`` is this class's own (no subclass overrides it or ``_evaluate``)."""
        cls = type(self)
        return cls._evaluate is _IKProblem._evaluate and cls.evaluate is _IKProblem.evaluate

    def __init__(self, robot: Robot, target, *, displacement_weight: float = 0.0,
                 q_start=None, needs_orientation: bool = False):
        if not isinstance(robot, Robot):
            raise ParameterError(f"robot must be a moik Robot, got {type(robot).__name__}")
        self.robot = robot
        self.target: Target = as_target(target)
        check_unit_range(self.target, robot)
        if needs_orientation and not self.target.has_orientation:
            raise TargetError(
                f"{type(self).__name__} needs a target with an orientation (a 4x4 pose or "
                "(position, rotation)); got a position only"
            )
        self.displacement_weight = positive("displacement_weight", displacement_weight,
                                            allow_zero=True)
        self.q_start = None
        if q_start is not None:
            self.q_start = robot.check_q(q_start, "q_start")
            if self.q_start.ndim != 1:
                raise ParameterError(f"q_start must be one joint vector, got {self.q_start.shape}")
        elif self.displacement_weight > 0:
            raise ParameterError("displacement_weight > 0 needs q_start (Eq. 31)")
        super().__init__(n_var=robot.dof, n_obj=self.n_obj_ik, xl=robot.lower.copy(),
                         xu=robot.upper.copy(), vtype=float)
        self._q_start = np.zeros(robot.dof) if self.q_start is None else self.q_start.copy()
        self._metric: str | None = None  # the orientation metric (None: position only)
        self._weights = np.array([1.0, 0.0, self.displacement_weight])

    def _objectives(self, X, mode: int, weights: np.ndarray) -> np.ndarray:
        """One compiled call: the objectives ``(n, 1)`` or ``(n, 2)`` of a batch."""
        Q = self.robot.kernel_batch(np.atleast_2d(X))
        if not all_finite(Q.reshape(-1)):
            raise NonFiniteError(f"{type(self).__name__}: joint values contain NaN or inf")
        out = np.empty((Q.shape[0], 2 if mode == BI_OBJECTIVE else 1))
        ik_objectives(self.robot.chain_model, self.target_spec, Q,
                      (mode, weights, self._q_start), out)
        return out

    def position_error(self, X: np.ndarray) -> np.ndarray:
        """Euclidean position error (Eq. 29), shape ``(n,)``."""
        return self._objectives(X, POSITION, _NO_DISPLACEMENT)[:, 0]


_NO_DISPLACEMENT = np.array([1.0, 0.0, 0.0])


class PositionIK(_IKProblem):
    """Position-only IK: ``f = ||p(q) - p_target||`` (EOSMA Eq. 29).

    Args:
        robot: The arm (bounds are its joint limits).
        target: 3-vector position (or any target; its orientation is ignored).
        displacement_weight: Weight ``w`` of EOSMA Eq. 31 (0 = off).
        q_start: Current joint vector for Eq. 31.
    """

    def __init__(self, robot: Robot, target, *, displacement_weight: float = 0.0, q_start=None):
        super().__init__(robot, target, displacement_weight=displacement_weight,
                         q_start=q_start)

    _mode = POSITION


class _OrientedIK(_IKProblem):
    def __init__(self, robot, target, *, orientation: str, displacement_weight, q_start):
        metric_code(orientation)  # an unknown name raises before anything else
        self.orientation = orientation
        super().__init__(robot, target, displacement_weight=displacement_weight,
                         q_start=q_start, needs_orientation=True)
        self._metric = orientation

    def errors(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Position and orientation errors of a batch, each ``(n,)``."""
        F = self._objectives(X, BI_OBJECTIVE, _NO_DISPLACEMENT)
        return F[:, 0], F[:, 1]


class PoseIK(_OrientedIK):
    """Weighted pose IK: ``f = w1 * f1 + w2 * f2`` (EOSMA Eq. 28).

    Args:
        robot: The arm.
        target: Pose (4x4), ``(position, rotation)`` or :class:`Target` with rotation.
        weights: ``(w1, w2)``, non-negative, not both zero (paper: 0.5, 0.5).
        orientation: Orientation metric name (default ``"geodesic"``;
            ``"eosma-euler"`` reproduces EOSMA, ``"frobenius"`` MChOA).
        displacement_weight: Weight of EOSMA Eq. 31 (0 = off).
        q_start: Current joint vector for Eq. 31.
    """

    def __init__(self, robot: Robot, target, *, weights=(0.5, 0.5),
                 orientation: str = "geodesic", displacement_weight: float = 0.0,
                 q_start=None):
        w = real_array("weights", weights, error=ParameterError)
        if w.shape != (2,) or not np.all(np.isfinite(w)) or np.any(w < 0) or w.sum() == 0:
            raise ParameterError(
                f"weights must be two finite non-negative numbers, not both zero; got {weights}"
            )
        self.weights = w
        super().__init__(robot, target, orientation=orientation,
                         displacement_weight=displacement_weight, q_start=q_start)
        self._weights = np.array([w[0], w[1], self.displacement_weight])

    _mode = WEIGHTED_POSE


class BiObjectiveIK(_OrientedIK):
    """Two objectives: position error and orientation error (MO-m-PSO Eq. 15).

    Args:
        robot: The arm.
        target: Pose with an orientation.
        orientation: Orientation metric (``"eosma-euler"`` for MOEOSMA,
            ``"zyx-euler"`` for MO-m-PSO, ``"geodesic"`` for users).
        displacement_weight: Weight of EOSMA Eq. 31, added to both objectives.
        q_start: Current joint vector for Eq. 31.
    """

    n_obj_ik = 2

    def __init__(self, robot: Robot, target, *, orientation: str = "geodesic",
                 displacement_weight: float = 0.0, q_start=None):
        super().__init__(robot, target, orientation=orientation,
                         displacement_weight=displacement_weight, q_start=q_start)

    _mode = BI_OBJECTIVE

    def reference_front(self, *, use_cache: bool = True) -> ReferenceFront:
        """The reference Pareto front (:func:`moik.fronts.cache.cached_front`): computed on
        first use (seconds), then read from the disk cache (milliseconds).

        Raises:
            ParameterError: With the displacement term (Eq. 31) on: the reference front
                covers the two pose errors only.
        """
        if self.displacement_weight > 0:
            raise ParameterError("the reference front covers displacement_weight = 0 only "
                                 f"(got {self.displacement_weight})")
        return front_cache.cached_front(self.robot, self.target.position, self.target.rotation,
                                        metric=self.orientation, use_cache=use_cache)

    def _calc_pareto_front(self, *args, **kwargs) -> np.ndarray:
        """pymoo's ``pareto_front()``: the reference front's ``F`` (see
        :meth:`reference_front`), so pymoo's IGD, IGD+, GD and HV work as on ZDT."""
        return self.reference_front().F.copy()
