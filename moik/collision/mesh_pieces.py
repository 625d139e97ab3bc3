"""The convex parts of a mesh link, its decomposition cached on disk with the fits.

:func:`cached_parts` gives the vertices of the convex parts of a link's compound: the
pieces of its triangles (:mod:`moik.collision.decompose`), each piece's hull, or the
enclosing polytope that replaces a hull of more than
:data:`~moik.collision.outer_hull.MAX_EXACT_VERTICES` vertices
(:func:`moik.collision.outer_hull.enclosing_polytope`). The decomposition takes a second or
more on a detailed link, so its cuts are cached (:func:`moik.collision.mesh_fit.load_cached`:
the shipped arms' in moik's data, others in the user's cache), keyed by the meshes (their
digests, scales and poses) and every setting. Any list of cuts tiles the mesh, so a read
entry is sound whatever file it came from; one that is not a list of cuts (damaged,
foreign) is recomputed and rewritten.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from moik.collision import decompose
from moik.collision.mesh_fit import digest, load_cached, store_cached
from moik.collision.outer_hull import enclosing_polytope

PIECES_VERSION = 4  # bump when the decomposition changes: old cache entries are not read


def _read(payload: Any) -> list[decompose.Cut] | None:
    """The cuts stored as ``[[piece, nx, ny, nz, offset], ...]``, or None when it is not
    that (finite numbers, a non-zero normal, a piece that exists when it is cut)."""
    if not isinstance(payload, list):
        return None
    cuts: list[decompose.Cut] = []
    for k, row in enumerate(payload):
        if (not isinstance(row, list) or len(row) != 5 or type(row[0]) is not int
                or not 0 <= row[0] <= k
                or not all(isinstance(x, (int, float)) and np.isfinite(x) for x in row[1:])):
            return None
        normal = (float(row[1]), float(row[2]), float(row[3]))
        if not any(normal):
            return None
        cuts.append((row[0], normal, float(row[4])))
    return cuts


def cached_parts(vertices: np.ndarray, faces: np.ndarray, *, identity: Sequence[Any],
                 use_cache: bool = True) -> list[np.ndarray]:
    """The vertices of the convex parts of the mesh ``vertices``, ``faces`` (module
    docstring); its cuts read from / written to the disk cache under the digest of
    ``identity`` (the meshes' digests, scales and poses) and the settings."""
    settings = {"version": PIECES_VERSION, "resolution": decompose.RESOLUTION,
                "max_resolution": decompose.MAX_RESOLUTION, "fine_pitch": decompose.FINE_PITCH,
                "slabs": decompose.SLABS, "elongated": decompose.ELONGATED,
                "tolerance_cells": decompose.TOLERANCE_CELLS,
                "max_pieces": decompose.MAX_PIECES, "quantiles": list(decompose.QUANTILES),
                "max_empty": decompose.MAX_EMPTY}
    key = digest([settings, *identity])
    cuts = _read(load_cached("pieces", key)) if use_cache else None
    if cuts is None:
        cuts = decompose.decompose(vertices, faces)
        if use_cache:
            store_cached("pieces", key, [[k, *normal, offset] for k, normal, offset in cuts])
    pieces = decompose.apply_cuts(vertices, faces, cuts)
    return [np.ascontiguousarray(enclosing_polytope(p.points())) for p in pieces]
