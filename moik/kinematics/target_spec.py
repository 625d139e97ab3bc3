"""The target of a solve as one compiled record (:class:`TargetSpec`, a numba StructRef).

Every kernel outside :mod:`moik.algorithms` that compares a pose with a target takes
one :class:`TargetSpec` beside the arm's :class:`~moik.robots.chain_model.ChainModel`:
the target position, its rotation (the identity for a position target, with
``has_rotation`` false), and the orientation metric that compares a rotation with it
(``code`` of :func:`~moik.kinematics.rotation_metrics.metric_code` and the target's
angles of :func:`~moik.kinematics.rotation_metrics.metric_target`; :data:`NO_METRIC`
where no metric is used). It is built in one place, :func:`target_spec`.
"""

from __future__ import annotations

import numpy as np
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit, kernel_array
from moik.kinematics.rotation_metrics import metric_code, metric_target

NO_METRIC = -1  # ``code`` of a target compared by position only (or by the solver's residual)


@structref.register
class TargetSpecType(StructType):
    """numba type of :class:`TargetSpec` (literal field types widened)."""


class TargetSpec(structref.StructRefProxy):
    """A target for compiled code (build it with :func:`target_spec`).

    Fields (read in compiled code):
        position: ``(3,)`` target position (robot unit).
        rotation: ``(3, 3)`` target rotation (the identity for a position target).
        has_rotation: Whether the target has a rotation.
        code: Orientation metric (:func:`~moik.kinematics.rotation_metrics.metric_code`),
            or :data:`NO_METRIC`.
        angles: ``(3,)`` the metric's target angles (zeros for the matrix metrics).
    """


FIELDS = ("position", "rotation", "has_rotation", "code", "angles")
define_struct(TargetSpec, TargetSpecType, FIELDS)


@jit
def _new_spec(position, rotation, has_rotation, code, angles):
    """The compiled constructor (cached; the proxy's own would compile in every process)."""
    return TargetSpec(position, rotation, has_rotation, code, angles)


def target_spec(position, rotation=None, *, metric: str | None = None) -> TargetSpec:
    """The :class:`TargetSpec` of a position and an optional rotation.

    Args:
        position: ``(3,)`` target position.
        rotation: ``(3, 3)`` target rotation, or ``None`` (a position target).
        metric: Orientation metric name compared with ``rotation``, or ``None``
            (:data:`NO_METRIC`: position errors only, or the solver's own residual).

    Raises:
        UnknownNameError: An unknown metric name, listing the valid ones.
    """
    has_rotation = rotation is not None
    R = kernel_array(rotation if has_rotation else np.eye(3))
    if metric is None:
        code, angles = NO_METRIC, np.zeros(3)
    else:
        code, angles = metric_code(metric), metric_target(metric, R)
    return _new_spec(kernel_array(position), R, has_rotation, code, angles)


@jit
def retarget(spec, position, rotation):
    """Point ``spec`` at another target of the same kind (a batch: one record, many targets)."""
    spec.position = position
    spec.rotation = rotation
