"""The exact stage's compiled kernels: hull-piece bounds of shape pairs, for compiled loops.

The arrays (built by :meth:`moik.collision.exact.ExactStage.arrays`, one tuple ``ex``):

* per shape ``s`` (the checker's shapes: the robot's, then the obstacles): ``body[s]``
  (``-1``: the world frame), ``radius[s]`` (the sweeping radius), ``plane[s]`` (1: a
  half-space ``normal[s] . x <= offset[s]``, world frame), and its hull pieces
  ``piece_start[s] .. piece_start[s + 1]``;
* per piece ``p``: its points ``points[point_start[p] .. point_start[p + 1]]`` in its
  shape's body frame, and its bounding sphere ``centre[p]``, ``reach[p]``.

:func:`pair_bound` is a lower bound on the distance of two shapes' hulls at body frames
``frames`` (``(dof + 1, 4, 4)``, :meth:`Robot.frames`), ``-inf`` when not separated,
decided against a threshold ``below`` (the clearance): a bound below it is returned as
soon as one is found, and the search stops once every piece pair is proven beyond it;
:func:`refine_distances` raises, in a batch of per-pair distances, the entries below the
threshold to that bound where it is larger. The solver's start loop can call
:func:`pair_bound` for the pairs whose bounding-shape distance is below the clearance.
"""

from __future__ import annotations

import numpy as np

from moik._jit import jit
from moik.collision.gjk import halfspace_distance, hull_distance_bound


@jit
def _placed(points: np.ndarray, lo: int, hi: int, F: np.ndarray) -> np.ndarray:
    out = np.empty((hi - lo, 3))
    for i in range(hi - lo):
        for r in range(3):
            out[i, r] = (F[r, 0] * points[lo + i, 0] + F[r, 1] * points[lo + i, 1]
                         + F[r, 2] * points[lo + i, 2] + F[r, 3])
    return out


@jit
def _frame(frames: np.ndarray, body: int) -> np.ndarray:
    return np.eye(4) if body < 0 else frames[body]


@jit
def pair_bound(ex, frames: np.ndarray, a: int, b: int, below: float) -> float:
    """A lower bound on the distance of shapes ``a`` (a robot shape) and ``b``, sharp
    about ``below``: once a piece pair is found below it, the search stops (the pieces
    not measured count with their bounding spheres' distance, so the value stays a lower
    bound); a piece pair's GJK stops once its bound reaches ``below`` (what a
    keeps-the-clearance test needs, at a fraction of the cost of converged distances)."""
    body, radius, plane, normal, offset, piece_start, point_start, points, centre, reach = ex
    if plane[a] == 1:
        a, b = b, a
    Fa, Fb = _frame(frames, body[a]), _frame(frames, body[b])
    best = np.inf
    if plane[b] == 1:
        for p in range(piece_start[a], piece_start[a + 1]):
            P = _placed(points, point_start[p], point_start[p + 1], Fa)
            best = min(best, halfspace_distance(P, radius[a], normal[b], offset[b]))
        return best
    na = piece_start[a + 1] - piece_start[a]
    nb = piece_start[b + 1] - piece_start[b]
    spheres = np.empty(na * nb)
    ca, cb = np.empty((na, 3)), np.empty((nb, 3))
    for i in range(na):
        ca[i] = _placed(centre, piece_start[a] + i, piece_start[a] + i + 1, Fa)[0]
    for j in range(nb):
        cb[j] = _placed(centre, piece_start[b] + j, piece_start[b] + j + 1, Fb)[0]
    for i in range(na):
        for j in range(nb):
            d = ca[i] - cb[j]
            spheres[i * nb + j] = (np.sqrt(d @ d) - reach[piece_start[a] + i]
                                   - reach[piece_start[b] + j] - radius[a] - radius[b])
    order = np.argsort(spheres)
    for t in range(order.size):
        flat = order[t]
        if spheres[flat] >= best:
            break  # the sphere bound of the rest is no smaller than the bound found
        pa, pb = piece_start[a] + flat // nb, piece_start[b] + flat % nb
        A = _placed(points, point_start[pa], point_start[pa + 1], Fa)
        B = _placed(points, point_start[pb], point_start[pb + 1], Fb)
        best = min(best, hull_distance_bound(A, radius[a], B, radius[b], below))
        if best < below and t + 1 < order.size:
            # decided; the pieces not measured are bounded by their spheres (sorted)
            return min(best, spheres[order[t + 1]])
    return best


@jit
def refine_distances(ex, frames: np.ndarray, D: np.ndarray, pairs: np.ndarray,
                     below: float) -> None:
    """``D[i, k] = max(D[i, k], pair_bound(...))`` where ``D[i, k] < below``, for the
    frames ``frames[i]`` (``(n, dof + 1, 4, 4)``) and the shape pairs ``pairs`` (``(k, 2)``)."""
    for i in range(D.shape[0]):
        for k in range(D.shape[1]):
            if D[i, k] < below:
                bound = pair_bound(ex, frames[i], pairs[k, 0], pairs[k, 1], below)
                if bound > D[i, k]:
                    D[i, k] = bound
