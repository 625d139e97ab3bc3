"""A :class:`~moik.collision.CollisionChecker`'s arrays as one compiled value (numba StructRef).

The solver's start loop (:func:`moik.solver.starts.run_starts`) tests each converged
end against the collision check in the same compiled call, so a colliding exact
answer is rejected and the next start tried without a return to Python. A
:class:`CollisionSet` carries what :func:`moik.collision.kernels.min_distance_of`
needs (the chain, the base, the shapes and the pairs) and is typed by numba as one
value, as :class:`~moik.solver.context.IKContext` is (see there for why a StructRef);
a solve without a check carries ``None`` instead, for which :func:`end_distance`
compiles to ``inf`` (numba specialises the start loop on the field's type).
"""

from __future__ import annotations

import numpy as np
from numba import types as nb_types
from numba.experimental import structref
from numba.extending import overload

from moik._jit import StructType, define_struct, jit
from moik.collision.kernels import min_distance_of


@structref.register
class CollisionSetType(StructType):
    """numba type of :class:`CollisionSet` (literal field types widened)."""


class CollisionSet(structref.StructRefProxy):
    """A checker's arrays for compiled code (build it with :func:`collision_set`).

    Fields: ``origins``, ``link_frames``, ``base``, ``joint_types`` (the chain, as
    :func:`~moik.collision.kernels.world_frames` takes it), ``body``, ``local``,
    ``kinds``, ``sizes``, ``pairs`` (the shapes and the pairs evaluated).
    """


FIELDS = ("origins", "link_frames", "base", "joint_types", "body", "local", "kinds", "sizes",
          "pairs")
define_struct(CollisionSet, CollisionSetType, FIELDS)


@jit
def _new_set(chain, shapes):
    """The compiled constructor (cached)."""
    return CollisionSet(chain[0], chain[1], chain[2], chain[3], shapes[0], shapes[1],
                        shapes[2], shapes[3], shapes[4])


def collision_set(chain: tuple, shapes: tuple) -> CollisionSet:
    """A :class:`CollisionSet` from ``(origins, link_frames, base, joint_types)`` and
    ``(body, local, kinds, sizes, pairs)`` (the arrays of a checker)."""
    return _new_set(chain, shapes)


def end_distance(cs, q, scratch):
    """Smallest signed distance of ``q`` over the pairs of ``cs`` (``inf``: ``cs`` is
    ``None``, no check). In compiled code the overload below specialises it on ``cs``."""
    return np.inf if cs is None else set_min_distance(cs, q, scratch)


def end_scratch(cs):
    """Scratch of :func:`end_distance` for ``cs`` (``0`` for ``None``: none needed)."""
    return 0 if cs is None else set_scratch(cs)


def checks_pairs(cs):
    """Whether ``cs`` has pairs to evaluate (``False`` for ``None``)."""
    return cs is not None and n_pairs(cs) > 0


@jit
def n_pairs(cs):
    """Number of pairs of ``cs`` (read in compiled code: the proxy has no field getters)."""
    return cs.pairs.shape[0]


@overload(end_distance)
def _end_distance(cs, q, scratch):
    """``None`` (a solve without a check) compiles to ``inf``: the start loop of a
    collision-blind solve holds no distance code (smaller, quicker to load)."""
    if isinstance(cs, nb_types.NoneType):
        return lambda cs, q, scratch: np.inf
    return lambda cs, q, scratch: set_min_distance(cs, q, scratch)


@overload(end_scratch)
def _end_scratch(cs):
    if isinstance(cs, nb_types.NoneType):
        return lambda cs: 0
    return lambda cs: set_scratch(cs)


@overload(checks_pairs)
def _checks_pairs(cs):
    if isinstance(cs, nb_types.NoneType):
        return lambda cs: False
    return lambda cs: cs.pairs.shape[0] > 0


@jit
def set_scratch(cs):
    """Scratch of :func:`set_min_distance` (``frames``, ``axes``, ``W``) for ``cs``."""
    dof = cs.joint_types.size
    return (np.empty((dof + 1, 4, 4)), np.empty((dof, 6)), np.empty((cs.body.size, 4, 4)))


@jit
def set_min_distance(cs, q, scratch):
    """Smallest signed distance of ``q`` over the pairs of ``cs`` (``inf``: none)."""
    if cs.pairs.shape[0] == 0:
        return np.inf
    return min_distance_of(cs.origins, cs.link_frames, cs.base, cs.joint_types, q,
                           (cs.body, cs.local, cs.kinds, cs.sizes, cs.pairs), scratch)[0]


@jit(nogil=True)
def set_min_distances(cs, Q, dmin):
    """:func:`set_min_distance` of every row of ``Q`` ``(n, dof)`` into ``dmin`` ``(n,)``
    (three arguments: a call from Python costs a third of the twelve-array kernel's).
    Releases the GIL (the batch's threads re-check their chunks' distances with it)."""
    scratch = set_scratch(cs)
    for i in range(Q.shape[0]):
        dmin[i] = set_min_distance(cs, Q[i], scratch)
