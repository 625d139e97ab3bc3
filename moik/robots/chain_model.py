"""The chain of a robot as one compiled record (:class:`ChainModel`, a numba StructRef).

Pinocchio's ``Model``: what every kernel outside :mod:`moik.algorithms` needs of an arm
(the fixed transforms, the link frames, the base, the joint types, the limits and
``1 / reach``), built once per :class:`~moik.robots.chain.Robot` (its
:attr:`~moik.robots.chain.Robot.chain_model`) and passed to kernels as one argument
instead of four to seven arrays. The target is the other record,
:class:`~moik.kinematics.target_spec.TargetSpec`.

A StructRef (rather than a NamedTuple or a jitclass) because numba types it by one
attribute (a call from Python costs what a call with one array costs), it is cached
on disk with the kernels that take it, and compiled code reads its fields directly.
It does not pickle: a pickled :class:`~moik.robots.chain.Robot` drops its record and
builds it again where it is unpickled.
"""

from __future__ import annotations

import numpy as np
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit
from moik.robots.transforms import KinematicChain


@structref.register
class ChainModelType(StructType):
    """numba type of :class:`ChainModel` (literal field types widened)."""


class ChainModel(structref.StructRefProxy):
    """An arm's constants for compiled code (build it with :func:`chain_model`; a robot's
    own is :attr:`Robot.chain_model <moik.robots.chain.Robot.chain_model>`).

    Fields (read in compiled code; the arrays are read-only, one numba type for every arm):
        origins: ``(dof + 1, 4, 4)`` fixed transforms ``F_0 .. F_n`` (base and tool folded in).
        link_frames: ``(dof, 4, 4)`` transforms ``P_j`` of the link frames.
        base: ``(4, 4)`` base transform (frame 0 of :meth:`Robot.frames`).
        joint_types: ``(dof,)`` int64, revolute or prismatic
            (:mod:`moik.robots.transforms`).
        lower, upper: ``(dof,)`` joint limits.
        inv_reach: ``1 / reach`` (the position scale of residuals and scaled errors).
    """


FIELDS = ("origins", "link_frames", "base", "joint_types", "lower", "upper", "inv_reach")
define_struct(ChainModel, ChainModelType, FIELDS)


@jit
def _new_model(origins, link_frames, base, joint_types, limits, inv_reach):
    """The compiled constructor (cached; the proxy's own would compile in every process)."""
    return ChainModel(origins, link_frames, base, joint_types, limits[0], limits[1], inv_reach)


def chain_model(chain: KinematicChain, base: np.ndarray, lower: np.ndarray, upper: np.ndarray,
                reach: float) -> ChainModel:
    """The :class:`ChainModel` of a kinematic chain, its base, limits and reach.

    Every array is stored read-only and C-contiguous (copied if it is not), so every
    model has the same numba type and no kernel compiles twice for one. A chain of zero
    reach (its tool fixed at the base's origin; the solvers refuse it,
    :func:`moik.problems.targets.check_has_reach`) gets the scale 1, so that its frames and
    collision geometry are still computed.
    """
    arrays = [_read_only(a) for a in (base, lower, upper)]
    return _new_model(chain.origins, chain.link_frames, arrays[0], chain.joint_types,
                      (arrays[1], arrays[2]), 1.0 / float(reach) if reach > 0 else 1.0)


def _read_only(values: np.ndarray) -> np.ndarray:
    if (values.dtype == np.float64 and values.flags.c_contiguous
            and not values.flags.writeable):
        return values
    out = np.array(values, dtype=np.float64, order="C", copy=True)
    out.setflags(write=False)
    return out
