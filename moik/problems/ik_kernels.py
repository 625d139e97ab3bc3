"""The compiled IK objectives: FK of every row, its error metric and the displacement
term, fused (:func:`ik_objectives`), and the same for compiled callers that evaluate one
row at a time (:class:`IKObjectives`, through :func:`moik._jit.objectives_row`).

The problems built on them are in :mod:`moik.problems.ik` (EOSMA Eqs. 26-31, MO-m-PSO
Eq. 15, MChOA Eqs. 3 and 6).
"""

from __future__ import annotations

import math

from numba.core.extending import overload
from numba.experimental import structref

from moik._jit import StructType, define_struct, jit, objectives_row
from moik.kinematics.rotation_metrics import rotation_error
from moik.robots.fk_kernels import (
    BLOCK,
    block_position,
    block_rotation,
    block_workspace,
    chain_block,
)

POSITION, WEIGHTED_POSE, BI_OBJECTIVE = 0, 1, 2  # what ik_objectives computes


@jit
def ik_objectives(chain, target, Q, terms, out):
    """The IK objectives of every row of ``Q``, into ``out``.

    Args:
        chain: The arm (:class:`~moik.robots.chain_model.ChainModel`).
        target: The target and its orientation metric
            (:class:`~moik.kinematics.target_spec.TargetSpec`).
        Q: Joint vectors ``(n, dof)``.
        terms: ``(mode, weights, q_start)``: ``mode`` :data:`POSITION` (``out (n, 1)``:
            position error), :data:`WEIGHTED_POSE` (``out (n, 1)``:
            ``w_pos * position + w_ori * orientation``) or :data:`BI_OBJECTIVE`
            (``out (n, 2)``: position, orientation); ``weights`` ``(w_pos, w_ori, w_disp)``,
            the displacement term ``w_disp * ||q - q_start||`` (EOSMA Eq. 31) added to every
            objective; ``q_start`` ``(dof,)``, read only when ``w_disp != 0``.
        out: ``(n, 1)`` or ``(n, 2)``.
    """
    F, types = chain.origins, chain.joint_types
    p_t, code, R_t, angles_t = target.position, target.code, target.rotation, target.angles
    mode, weights, q_start = terms
    W = block_workspace(types.size)
    for start in range(0, Q.shape[0], BLOCK):
        m = min(BLOCK, Q.shape[0] - start)
        chain_block(F, types, Q, start, m, W)
        for b in range(m):
            i = start + b
            x, y, z = block_position(W, b)
            dx, dy, dz = x - p_t[0], y - p_t[1], z - p_t[2]
            pos = math.sqrt(dx * dx + dy * dy + dz * dz)
            disp = 0.0
            if weights[2] != 0.0:
                acc = 0.0
                for j in range(types.size):
                    diff = Q[i, j] - q_start[j]
                    acc += diff * diff
                disp = weights[2] * math.sqrt(acc)
            if mode == POSITION:
                out[i, 0] = pos + disp
                continue
            ori = rotation_error(code, block_rotation(W, b), R_t, angles_t)
            if mode == WEIGHTED_POSE:
                out[i, 0] = weights[0] * pos + weights[1] * ori + disp
            else:
                out[i, 0] = pos + disp
                out[i, 1] = ori + disp


@structref.register
class IKObjectivesType(StructType):
    """numba type of :class:`IKObjectives` (literal field types widened)."""


class IKObjectives(structref.StructRefProxy):
    """An IK problem's objectives for compiled code (numba StructRef; made by
    :func:`new_objectives`, e.g. through ``compiled_objectives()`` of the problems in
    :mod:`moik.problems.ik`): the arm, the target and the terms of :func:`ik_objectives`,
    whose rows :func:`moik._jit.objectives_row` takes."""

    def write_row(self, Q, out, i: int) -> None:
        """The objectives of row ``i`` of ``Q`` into ``out[i]`` (from Python: what
        :func:`moik._jit.objectives_row` does in compiled code)."""
        _write_row(self, Q, out, i)


define_struct(IKObjectives, IKObjectivesType, ["chain", "target", "mode", "weights", "q_start"])


@jit
def _new_objectives(chain, target, mode, weights, q_start):
    """The compiled constructor (cached; the proxy's own would compile in every process)."""
    return IKObjectives(chain, target, mode, weights, q_start)


def new_objectives(*, chain, target, mode: int, weights, q_start) -> IKObjectives:
    """The :class:`IKObjectives` of an arm (``ChainModel``), a target (``TargetSpec``) and
    the terms of :func:`ik_objectives`."""
    return _new_objectives(chain, target, mode, weights, q_start)


@overload(objectives_row)
def _objectives_row(spec, Q, out, i):
    """:func:`moik._jit.objectives_row` for :class:`IKObjectives`: :func:`ik_objectives` of
    row ``i``."""
    if isinstance(spec, IKObjectivesType):
        def impl(spec, Q, out, i):
            ik_objectives(spec.chain, spec.target, Q[i:i + 1],
                          (spec.mode, spec.weights, spec.q_start), out[i:i + 1])
        return impl
    return None


@jit
def _write_row(spec, Q, out, i):
    """:meth:`IKObjectives.write_row`, compiled."""
    objectives_row(spec, Q, out, i)
