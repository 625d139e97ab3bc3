"""A link's collision mesh cut into pieces whose convex hulls hold it and follow its concavities.

The exact stage of a mesh link measures the convex hulls of pieces of its triangles
(:mod:`moik.collision.gjk`). Any partition of the triangles is sound (each triangle lies in
its piece's hull, so the hulls hold the mesh); how tight it is depends on the pieces.
:func:`convex_pieces` starts from :data:`SLABS` slabs along the principal axis of a long
mesh (a long link with its joint housings is followed far closer by several hulls than by
one; a compact one, less than :data:`ELONGATED` times longer than wide, starts whole) and
then cuts where a hull still holds deep empty space, in the spirit of approximate convex
decomposition (V-HACD, CoACD: a concavity measure, plane cuts, the most concave piece cut
first), measured on a voxel grid for speed:

* **Concavity.** The link's solid is voxelised (cells of side 1/:data:`RESOLUTION` of the
  mesh's largest extent, finer for a large link: :func:`resolution_of`; the cells the
  surface passes through, one cell thicker, and those they enclose, scipy's
  ``binary_fill_holes``) and every empty cell gets its distance to the solid (scipy's
  Euclidean distance transform). A piece's concavity is the largest distance of an empty
  cell inside its hull: how deep another link could reach into the hull without touching
  the mesh; its empty space is the sum of those distances. Only the cells inside the
  whole mesh's hull count (no piece's hull reaches beyond it), :data:`MAX_EMPTY` of them
  evenly spread when there are more (keeping the deepest of the whole grid kept only a
  compact link's corners, outside every hull, and every piece's concavity read 0:
  measured on the ABB IRB 140's flange, whose hulls then overlapped the forearm's fork in
  every configuration). A mesh that is not closed has no inside: its cells count as empty
  and it is cut further (still sound, at most :func:`pieces_of` pieces).
* **Cuts.** The most concave piece is cut by the plane, across one of its principal axes
  at one of :data:`QUANTILES` of its polygons' centroids or of its extent, that leaves the
  least empty space in the two hulls (the extent's: a flange's many small triangles put
  every centroid quantile on the flange, none where its rod meets it). A cut clips the
  triangles (:func:`moik.collision.clip.split`): each piece is the part of the mesh in a
  convex cell of the planes, so the pieces tile the surface exactly and a hull reaches
  across no cut. The slabs are cuts too: planes across the principal axis that split the
  triangles' area evenly (equal counts of triangles put one slab over a whole tube of long
  triangles: measured on example-robot-data's UR5 with its gripper, the forearm's tube
  slab then overlapped the wrist in 66 of the 1,448 mesh-free configurations of 2,000).
* **Stop** when every piece's concavity is at most :data:`TOLERANCE_CELLS` cells, or there
  are :func:`pieces_of` pieces; a piece no cut improves stays whole.

How tight the hulls are, against coal on the meshes: ``python -m
studies.mesh_collision_check`` (docs/results/mesh-collision.md).

A decomposition is its list of cuts, ``(piece, normal, offset)``: the piece is replaced by
its part below the plane and its part above is appended (:func:`apply_cuts`). Any such list
tiles the mesh, so it is what the disk cache keeps (:mod:`moik.collision.mesh_pieces`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from moik.collision.clip import Polygons, split
from moik.collision.shapes import MAX_PARTS

RESOLUTION = 64  # cells along the mesh's largest extent, at least
MAX_RESOLUTION = 128  # ... and at most
FINE_PITCH = 0.001  # m (a URDF's unit): no finer cells (a small link gets fewer of them)
TOLERANCE_CELLS = 1.5  # a piece whose hull holds no empty cell deeper than this is not cut
SLABS = 12  # slabs along the principal axis, before the cuts
ELONGATED = 1.5  # a link is cut into slabs only if this many times longer than wide
MAX_PIECES = 32  # pieces of a link at RESOLUTION at most, more at a finer one (to MAX_PARTS)
QUANTILES = (0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8)  # where a piece may be cut along an axis
MAX_EMPTY = 40_000  # empty cells used for the measures at most (evenly spread)
_HULL_MARGIN = 1e-9  # relative: a cell centre on a hull's facet counts as inside
_FACETS = 32  # facets a cell is tested against at a time

Cut = tuple[int, tuple[float, float, float], float]  # (piece, normal, offset)


def _grid_weights(n: int) -> np.ndarray:
    """Barycentric weights ``(p, 3)`` of points spaced ``1 / n`` over a triangle."""
    i, j = np.divmod(np.arange((n + 1) ** 2), n + 1)
    keep = i + j <= n
    i, j = i[keep], j[keep]
    return np.c_[n - i - j, i, j] / n


def _surface_cells(T: np.ndarray, origin: np.ndarray, pitch: float,
                   shape: tuple[int, ...]) -> np.ndarray:
    """The cells the triangles ``T`` ``(k, 3, 3)`` pass through, from points spaced at most a
    third of a cell over each (a triangle's longest edge sets how many)."""
    grid = np.zeros(shape, dtype=bool)
    L = np.linalg.norm(T - np.roll(T, 1, axis=1), axis=2).max(axis=1)
    n = np.maximum(1, np.ceil(3.0 * L / pitch)).astype(np.int64)
    for v in np.unique(n):
        W = _grid_weights(int(v))
        for chunk in np.array_split(np.flatnonzero(n == v), max(1, len(W) * (n == v).sum()
                                                                // 2_000_000)):
            P = np.einsum("pw,twd->tpd", W, T[chunk]).reshape(-1, 3)
            idx = np.floor((P - origin) / pitch).astype(np.int64)
            grid[idx[:, 0], idx[:, 1], idx[:, 2]] = True
    return grid


def empty_cells(T: np.ndarray, pitch: float) -> tuple[np.ndarray, np.ndarray]:
    """The centres of the cells outside the solid ``(k, 3)`` and their distances to it,
    at most :data:`MAX_EMPTY` inside the mesh's hull, evenly spread (cells within a cell of
    the surface are left out)."""
    from scipy.ndimage import binary_dilation, binary_fill_holes, distance_transform_edt

    P = T.reshape(-1, 3)
    origin = P.min(axis=0) - 2 * pitch
    shape = tuple(int(n) for n in np.floor((P.max(axis=0) - origin) / pitch) + 3)
    surface = _surface_cells(T, origin, pitch, shape)
    solid = binary_fill_holes(binary_dilation(surface))  # one cell thicker: no leaks
    depth = distance_transform_edt(~solid) * pitch
    keep = depth >= pitch
    idx = np.argwhere(keep)
    d = depth[keep]
    centres = origin + (idx + 0.5) * pitch
    inside = _hull_inside(P, centres, np.arange(len(centres)))  # no piece's hull reaches out
    centres, d = centres[inside], d[inside]
    if len(d) > MAX_EMPTY:  # evenly spread: a narrow gap's shallow cells stay in
        keep_every = np.linspace(0, len(d) - 1, MAX_EMPTY).astype(np.int64)
        centres, d = centres[keep_every], d[keep_every]
    return centres, d


def _hull_inside(points: np.ndarray, cells: np.ndarray, among: np.ndarray) -> np.ndarray:
    """The indices, among ``among``, of the ``cells`` in the convex hull of ``points``
    (none when it is flat)."""
    from scipy.spatial import ConvexHull, QhullError

    if len(points) < 4 or len(among) == 0:
        return among[:0]
    try:
        eq = ConvexHull(points).equations
    except (QhullError, ValueError):
        return among[:0]
    lo, hi = points.min(axis=0), points.max(axis=0)
    C = cells[among]
    near = among[np.all((lo <= C) & (hi >= C), axis=1)]
    margin = _HULL_MARGIN * float(np.ptp(points, axis=0).max())
    for start in range(0, len(eq), _FACETS):  # a few facets at a time: most cells leave early
        E = eq[start:start + _FACETS]
        near = near[np.all(cells[near] @ E[:, :3].T + E[:, 3] <= margin, axis=1)]
    return near


class _Piece:
    """A piece's polygons, the empty cells inside their hull (indices), its concavity and
    its empty space (module docstring)."""

    def __init__(self, polygons: Polygons, cells: np.ndarray, depth: np.ndarray,
                 among: np.ndarray) -> None:
        self.polygons = polygons
        self.inside = _hull_inside(polygons.points(), cells, among)
        d = depth[self.inside]
        self.concavity = float(d.max()) if len(d) else 0.0
        self.waste = float(d.sum())


def _planes(polygons: Polygons) -> list[tuple[np.ndarray, float]]:
    """Candidate cuts of a piece: planes across its principal axes at :data:`QUANTILES` of
    its polygons' centroids and of its extent."""
    C = polygons.centroids()
    centred = C - C.mean(axis=0)
    _, axes = np.linalg.eigh(centred.T @ centred)
    P = polygons.points()
    out = []
    for axis in axes.T[::-1]:
        t, s = C @ axis, P @ axis
        lo, hi = float(s.min()), float(s.max())
        for q in QUANTILES:
            out.append((axis, float(np.quantile(t, q))))
            out.append((axis, lo + q * (hi - lo)))
    return out


def _area_quantiles(T: np.ndarray, area: np.ndarray, axis: np.ndarray, n: int) -> np.ndarray:
    """``n - 1`` offsets along ``axis`` that cut the triangles' area into ``n`` equal parts
    (each triangle's area spread evenly between its lowest and highest corner)."""
    t = T @ axis
    lo, hi = t.min(axis=1), t.max(axis=1)
    grid = np.linspace(lo.min(), hi.max(), 64 * n + 1)
    span = np.maximum(hi - lo, 1e-300)
    cover = np.clip((grid[None, :] - lo[:, None]) / span[:, None], 0.0, 1.0)
    cover[hi - lo <= 0] = (grid[None, :] >= lo[hi - lo <= 0, None]).astype(float)
    cum = (cover * area[:, None]).sum(axis=0)
    return np.interp(cum[-1] * np.arange(1, n) / n, cum, grid)


def resolution_of(vertices: np.ndarray) -> int:
    """Cells along the largest extent of a mesh with these vertices: :data:`MAX_RESOLUTION`,
    fewer for a link so small that its cells would be finer than :data:`FINE_PITCH` (at
    least :data:`RESOLUTION`). Measured on the ABB IRB 140 of rtb-data (400 configurations),
    whose flange turns 6-9 mm from its 0.86 m forearm's fork: 64 cells (32 pieces) rejected
    7.2 % of the mesh-free configurations, 96 (48) 5.3 %, 128 (62) 3.1 %; the shipped arms
    keep their collision-aware batch speed goal (``benchmarks/urdf_collision.py``)."""
    extent = float(np.ptp(vertices, axis=0).max())
    return int(np.clip(np.ceil(extent / FINE_PITCH), RESOLUTION, MAX_RESOLUTION))


def pitch_of(vertices: np.ndarray) -> float:
    """The side of the grid's cells for a mesh with these vertices."""
    return float(np.ptp(vertices, axis=0).max()) / resolution_of(vertices)


def pieces_of(vertices: np.ndarray) -> int:
    """Pieces of a mesh with these vertices at most: :data:`MAX_PIECES` at
    :data:`RESOLUTION`, as many more as its grid is finer, at most a compound's parts."""
    return min(MAX_PARTS, round(MAX_PIECES * resolution_of(vertices) / RESOLUTION))


def _cut(cuts: list[Cut], k: int, normal: np.ndarray, offset: float) -> None:
    cuts.append((k, (float(normal[0]), float(normal[1]), float(normal[2])), float(offset)))


def decompose(vertices: np.ndarray, faces: np.ndarray, *, max_pieces: int | None = None
              ) -> list[Cut]:
    """The cuts of the mesh ``vertices`` ``(v, 3)``, ``faces`` ``(f, 3)`` (module docstring;
    at most ``max_pieces`` pieces, :func:`pieces_of` by default)."""
    max_pieces = pieces_of(vertices) if max_pieces is None else max_pieces
    T = vertices[faces]
    pitch = pitch_of(vertices)
    cells, depth = empty_cells(T, pitch)
    every = np.arange(len(cells))
    C = T.mean(axis=1)
    area = np.linalg.norm(np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0]), axis=1)
    centred = C - C.mean(axis=0)
    _, vectors = np.linalg.eigh(centred.T @ centred)
    axis = vectors[:, 2]
    cuts: list[Cut] = []
    rest = Polygons.of_triangles(T)
    pieces: list[_Piece] = []
    spans = np.ptp(T.reshape(-1, 3) @ vectors, axis=0)
    slabs = SLABS if spans[2] >= ELONGATED * spans[1] else 1  # a compact link: no slabs
    for offset in _area_quantiles(T, area, axis, slabs):
        below, above = split(rest, axis, offset)
        if len(below.counts) == 0 or len(above.counts) == 0:
            continue
        _cut(cuts, len(pieces), axis, offset)
        pieces.append(_Piece(below, cells, depth, every))
        rest = above
    pieces.append(_Piece(rest, cells, depth, every))
    tolerance = TOLERANCE_CELLS * pitch
    while len(pieces) < max_pieces:
        k = max(range(len(pieces)), key=lambda i: pieces[i].concavity)
        worst = pieces[k]
        if worst.concavity <= tolerance:
            break
        best: tuple[float, np.ndarray, float, _Piece, _Piece] | None = None
        for normal, offset in _planes(worst.polygons):
            below, above = split(worst.polygons, normal, offset)
            if len(below.counts) == 0 or len(above.counts) == 0:
                continue
            a = _Piece(below, cells, depth, worst.inside)
            b = _Piece(above, cells, depth, worst.inside)
            if best is None or a.waste + b.waste < best[0]:
                best = (a.waste + b.waste, normal, offset, a, b)
        if best is None or best[0] >= worst.waste:
            worst.concavity = 0.0  # no cut helps: leave it whole
            continue
        _cut(cuts, k, best[1], best[2])
        pieces[k] = best[3]
        pieces.append(best[4])
    return cuts


def apply_cuts(vertices: np.ndarray, faces: np.ndarray, cuts: Sequence[Cut]) -> list[Polygons]:
    """The pieces of the mesh after ``cuts`` (module docstring), the empty ones left out.

    Raises:
        ValueError: A cut names a piece that does not exist (yet).
    """
    pieces = [Polygons.of_triangles(vertices[faces])]
    for k, normal, offset in cuts:
        if not 0 <= k < len(pieces):
            raise ValueError(f"cut of piece {k} of {len(pieces)}")
        pieces[k], above = split(pieces[k], np.asarray(normal, dtype=float), offset)
        pieces.append(above)
    return [p for p in pieces if len(p.counts)]


def convex_pieces(vertices: np.ndarray, faces: np.ndarray, *, max_pieces: int | None = None
                  ) -> list[np.ndarray]:
    """The corners of each piece's polygons: point sets whose convex hulls hold the mesh."""
    cuts = decompose(vertices, faces, max_pieces=max_pieces)
    return [p.points() for p in apply_cuts(vertices, faces, cuts)]
