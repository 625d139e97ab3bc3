"""A :class:`~moik.collision.CollisionChecker`'s arrays as one compiled value (numba StructRef).

The solver's start loop (:func:`moik.solver.starts.run_starts`) tests each converged
end against the collision check in the same compiled call, so a colliding exact
answer is rejected and the next start tried without a return to Python. A
:class:`CollisionSet` carries what :func:`moik.collision.kernels.min_distance_of`
needs (the arm's :class:`~moik.robots.chain_model.ChainModel`, the shapes and the pairs)
and is typed by numba as one value (see :mod:`moik.robots.chain_model` for why a StructRef);
a solve without a check carries ``None`` instead, for which :func:`end_distance`
compiles to ``inf`` (numba specialises the start loop on the field's type).
"""

from __future__ import annotations

import numpy as np
from numba import types as nb_types
from numba.experimental import structref
from numba.extending import overload

from moik._jit import StructType, define_struct, jit
from moik.collision.kernels import distance_scratch, min_distance_of
from moik.robots.chain_model import ChainModel


@structref.register
class CollisionSetType(StructType):
    """numba type of :class:`CollisionSet` (literal field types widened)."""


class CollisionSet(structref.StructRefProxy):
    """A checker's arrays for compiled code (build it with :func:`collision_set`).

    Fields: ``chain`` (the arm's :class:`~moik.robots.chain_model.ChainModel`), ``body``,
    ``local``, ``kinds``, ``sizes``, ``pairs`` (the shapes and the pairs evaluated, as
    :mod:`moik.collision.kernels` describes them), ``hull_points``, ``hull_ranges`` (the
    vertices of the hull shapes, as :mod:`moik.collision.gjk` describes them).
    """


FIELDS = ("chain", "body", "local", "kinds", "sizes", "pairs", "hull_points", "hull_ranges")
define_struct(CollisionSet, CollisionSetType, FIELDS)


@jit
def _new_set(chain, shapes, pairs, hulls):
    """The compiled constructor (cached)."""
    return CollisionSet(chain, shapes[0], shapes[1], shapes[2], shapes[3], pairs, hulls[0],
                        hulls[1])


def collision_set(*, chain: ChainModel, body: np.ndarray, local: np.ndarray, kinds: np.ndarray,
                  sizes: np.ndarray, pairs: np.ndarray, hull_points: np.ndarray,
                  hull_ranges: np.ndarray) -> CollisionSet:
    """A :class:`CollisionSet` of an arm and its shapes: ``body (m,)`` int64, ``local
    (m, 4, 4)``, ``kinds (m,)`` int64, ``sizes (m, 3)``, ``pairs (p, 2)`` int64, and the
    vertices of its hulls (:mod:`moik.collision.gjk`): ``hull_points (v, 3)`` and
    ``hull_ranges (h, 2)`` int64."""
    return _new_set(chain, (body, local, kinds, sizes), pairs, (hull_points, hull_ranges))


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
    """Scratch of :func:`set_min_distance` for ``cs``."""
    return distance_scratch(cs)


@jit
def set_min_distance(cs, q, scratch):
    """Smallest signed distance of ``q`` over the pairs of ``cs`` (``inf``: none)."""
    if cs.pairs.shape[0] == 0:
        return np.inf
    return min_distance_of(cs, q, scratch)[0]
