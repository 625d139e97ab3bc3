"""A :class:`~moik.collision.CollisionChecker`'s arrays as one compiled value (numba StructRef).

The batch's start loop (:func:`moik.solver.starts.run_starts` in
:func:`moik.solver.starts.run_batch`) tests each converged end against the collision
check in the same compiled call, so a colliding exact answer is rejected and the next
start tried without a return to Python (one solve calls the test between compiled runs
of a plain loop instead: :mod:`moik.solver.tested_starts`). A
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
from moik.collision.distance import CAPSULE, HULL
from moik.collision.kernels import distance_below, distance_scratch, min_distances
from moik.collision.shapes import hull_capsule
from moik.robots.chain_model import ChainModel


@structref.register
class CollisionSetType(StructType):
    """numba type of :class:`CollisionSet` (literal field types widened)."""

    bounds_only = False  # read by moik.collision.kernels.primitive_pair's overload


@structref.register
class CompoundSetType(StructType):
    """numba type of :class:`CompoundSet`: the same fields, compiled with the pair kernels of
    compounds' bounds (:func:`moik.collision.kernels.primitive_pair`)."""

    bounds_only = True


class CollisionSet(structref.StructRefProxy):
    """A checker's arrays for compiled code (build it with :func:`collision_set`).

    Fields: ``chain`` (the arm's :class:`~moik.robots.chain_model.ChainModel`), ``body``,
    ``local``, ``kinds``, ``sizes``, ``pairs`` (the shapes and the pairs evaluated, as
    :mod:`moik.collision.kernels` describes them), ``hull_points``, ``hull_ranges`` (the
    vertices of the hull shapes, as :mod:`moik.collision.gjk` describes them), ``refine``
    (the compound parts that refine each pair).
    """


class CompoundSet(CollisionSet):
    """A :class:`CollisionSet` whose every pair of primitives (spheres, capsules, boxes,
    half-spaces) but capsule-capsule (spheres included) is the bound of a compound
    (refined on its hulls): such a pair's distance is only a lower bound there, which GJK
    and the support function give (:func:`moik.collision.kernels.primitive_pair`), so the
    box and half-space closed forms are not compiled for it (a mesh arm's self pairs, an
    all-mesh arm with a scene, a capsule model's self pairs: about a sixth less to compile
    on a first collision-aware solve). Capsule-capsule pairs are measured exactly as in a
    :class:`CollisionSet`. :func:`collision_set` picks it."""


FIELDS = ("chain", "body", "local", "kinds", "sizes", "pairs", "refine", "hull_points",
          "hull_ranges", "hull_caps")
define_struct(CollisionSet, CollisionSetType, FIELDS)
define_struct(CompoundSet, CompoundSetType, FIELDS)


@jit
def _new_set(chain, shapes, pairs, hulls):
    """The compiled constructor (cached)."""
    return CollisionSet(chain, shapes[0], shapes[1], shapes[2], shapes[3], pairs[0], pairs[1],
                        hulls[0], hulls[1], hulls[2])


@jit
def _new_compound_set(chain, shapes, pairs, hulls):
    """The compiled constructor of a :class:`CompoundSet` (cached)."""
    return CompoundSet(chain, shapes[0], shapes[1], shapes[2], shapes[3], pairs[0], pairs[1],
                       hulls[0], hulls[1], hulls[2])


def bounds_only(kinds: np.ndarray, pairs: np.ndarray, refine: np.ndarray) -> bool:
    """Whether every pair of two primitives but capsule-capsule (spheres included) is refined
    (a compound's bound, :func:`~moik.collision.shapes.refinements`): the set is then a
    :class:`CompoundSet`. Pairs with a hull are GJK's in either set; a compound's parts are
    hulls."""
    if len(pairs) == 0:
        return False
    ka, kb = kinds[pairs[:, 0]], kinds[pairs[:, 1]]
    exact = (ka != HULL) & (kb != HULL) & ((ka > CAPSULE) | (kb > CAPSULE))
    return bool(np.all(refine[exact, 1] > 0))


def collision_set(*, chain: ChainModel, body: np.ndarray, local: np.ndarray, kinds: np.ndarray,
                  sizes: np.ndarray, pairs: np.ndarray, hull_points: np.ndarray,
                  hull_ranges: np.ndarray, hull_caps: np.ndarray | None = None,
                  refine: np.ndarray | None = None) -> CollisionSet:
    """A :class:`CollisionSet` of an arm and its shapes: ``body (m,)`` int64, ``local
    (m, 4, 4)``, ``kinds (m,)`` int64, ``sizes (m, 3)``, ``pairs (p, 2)`` int64, the
    vertices of its hulls (:mod:`moik.collision.gjk`): ``hull_points (v, 3)`` and
    ``hull_ranges (h, 2)`` int64, a capsule holding each (``hull_caps (h, 8)``, from
    :func:`~moik.collision.shapes.hull_capsules`; computed when not given), and the
    refinement of each pair (a compound's parts, :func:`~moik.collision.shapes.refinements`:
    ``refine (p, 4)``; none by default). A :class:`CompoundSet` where :func:`bounds_only`."""
    if refine is None:
        refine = np.zeros((len(pairs), 4), dtype=np.int64)
    if hull_caps is None:
        hull_caps = np.ascontiguousarray(np.array(
            [hull_capsule(hull_points[s:e]) for s, e in hull_ranges]).reshape(-1, 8))
    new = _new_compound_set if bounds_only(kinds, pairs, refine) else _new_set
    return new(chain, (body, local, kinds, sizes), (pairs, refine),
               (hull_points, hull_ranges, hull_caps))


FEW_ROWS = 16  # rows whose smallest distances smallest_distances measures one by one


def smallest_distances(cs, Q2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Smallest distance of each row of ``Q2`` (C-contiguous float64) over the pairs of
    ``cs`` and the pair attaining it (-1: none): :func:`~moik.collision.kernels.min_distances`,
    or for at most :data:`FEW_ROWS` rows the same distance test row by row from Python (the
    kernel one solve's start loop calls: a first solve compiles no batch kernel for its
    answers' distances)."""
    n = Q2.shape[0]
    d, which = np.empty(n), np.empty(n, dtype=np.int64)
    if n > FEW_ROWS:
        min_distances(cs, Q2, d, which)
        return d, which
    scratch = distance_scratch(cs)
    for i in range(n):
        d[i], which[i] = distance_below(cs, Q2[i], scratch, np.inf)
    return d, which


def end_distance(cs, q, scratch, clearance):
    """Smallest signed distance of ``q`` over the pairs of ``cs`` when it is below
    ``clearance``, else a number at least ``clearance``
    (:func:`~moik.collision.kernels.distance_below`; ``inf``: ``cs`` is ``None``, no check).
    In compiled code the overload below specialises it on ``cs``."""
    return np.inf if cs is None else set_distance_below(cs, q, scratch, clearance)


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
def _end_distance(cs, q, scratch, clearance):
    """``None`` (a solve without a check) compiles to ``inf``: the start loop of a
    collision-blind solve holds no distance code (smaller, quicker to load)."""
    if isinstance(cs, nb_types.NoneType):
        return lambda cs, q, scratch, clearance: np.inf
    return lambda cs, q, scratch, clearance: set_distance_below(cs, q, scratch, clearance)


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


@jit(inline=True)
def set_scratch(cs):
    """Scratch of :func:`set_distance_below` for ``cs``."""
    return distance_scratch(cs)


@jit(inline=True)
def set_distance_below(cs, q, scratch, limit):
    """:func:`~moik.collision.kernels.distance_below` of ``q``: the distance (``inf``: no
    pair)."""
    if cs.pairs.shape[0] == 0:
        return np.inf
    return distance_below(cs, q, scratch, limit)[0]
