"""Enclosing capsules fitted to point clouds (mesh vertices), for building capsule models.

Used at build time (``studies/fit_capsules.py`` makes the shipped models with it) and
when a URDF's meshes are loaded (:mod:`moik.collision.mesh_fit`).
:func:`enclosing_capsule` returns a capsule that contains every point given.
:func:`mesh_vertices` reads a mesh file with trimesh, imported only when called;
:func:`urdf_mesh_points` and :func:`fit_urdf` put a URDF's mesh vertices on a robot's
bodies (:func:`moik.robots.urdf_geometry.mesh_geometry`) and fit one capsule per link.

The fit, for one candidate axis direction ``u``: the points' coordinates across ``u``,
their smallest enclosing circle (Welzl's algorithm, :mod:`moik.collision.circle`) gives
the axis line (its centre) and the radius ``r`` (the largest distance of a point from
that line, recomputed exactly); along ``u``, with axial coordinate ``t`` and distance
``rho <= r`` from the line, the shortest segment ``[t0, t1]`` that keeps every point
within ``r`` of it is
``t1 = max(t - sqrt(r^2 - rho^2))``, ``t0 = min(t + sqrt(r^2 - rho^2))`` (the farthest
point has ``rho = r``, so ``t0 <= t1``). The candidates: the three principal axes of the
points (PCA) and any directions the caller adds (e.g. the body's joint axes); the
smallest capsule volume wins, and (``refine=True``) its direction is then polished by
Nelder-Mead on the volume (scipy). Every candidate direction gives an enclosing
capsule, so the search only makes it tighter. The circles are found on the points'
convex-hull vertices (the same circles, faster); radius and segment always come from
all the points.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from moik._validate import finite_array
from moik.collision.circle import smallest_circle_centre
from moik.exceptions import GeometryError, MoikError
from moik.robots.chain import Robot
from moik.robots.fk_kernels import world_frames
from moik.robots.urdf_geometry import mesh_geometry


def capsule_volume(radius: float, length: float) -> float:
    """The volume of a capsule: a cylinder of ``length`` and two half-spheres."""
    return float(np.pi * radius**2 * length + 4.0 / 3.0 * np.pi * radius**3)


def capsule_excess(points: Any, a: Any, b: Any, radius: float) -> float:
    """The largest distance of a point outside the capsule (0 when all are inside)."""
    P = np.atleast_2d(np.asarray(points, dtype=float))
    pa, pb = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = pb - pa
    L2 = float(d @ d)
    s = np.zeros(len(P)) if L2 == 0.0 else np.clip((P - pa) @ d / L2, 0.0, 1.0)
    dist = np.linalg.norm(P - (pa + s[:, None] * d), axis=1)
    return float(max(0.0, (dist - radius).max()))


def _perpendicular(u: np.ndarray) -> np.ndarray:
    """Two unit vectors completing ``u`` to an orthonormal basis (as rows)."""
    x, y, z = u
    k = int(np.argmin(np.abs(u)))  # u x (the axis u is most across)
    e1 = np.array([0.0, z, -y] if k == 0 else [-z, 0.0, x] if k == 1 else [y, -x, 0.0])
    e1 /= np.linalg.norm(e1)
    a, b, c = e1
    return np.array([e1, [y * c - z * b, z * a - x * c, x * b - y * a]])


def _along(P: np.ndarray, u: np.ndarray, H: np.ndarray | None = None
           ) -> tuple[np.ndarray, np.ndarray, float]:
    """The capsule around ``P`` along ``u``; the axis line from the smallest circle
    around ``H`` (``P``'s convex-hull vertices: the same circle, found faster)."""
    E = _perpendicular(u)
    X = P @ E.T
    centre = np.array(smallest_circle_centre(X if H is None else H @ E.T))
    rho = np.linalg.norm(X - centre, axis=1)
    r = float(rho.max())
    h = np.sqrt(np.maximum(r * r - rho * rho, 0.0))
    t = P @ u
    t0, t1 = float((t + h).min()), float((t - h).max())
    foot = centre @ E
    return foot + t0 * u, foot + t1 * u, r


def hull_vertices(P: np.ndarray) -> np.ndarray:
    """The convex-hull vertices of ``P`` (all of ``P`` when it is flat or too small)."""
    from scipy.spatial import ConvexHull, QhullError

    if len(P) < 5:
        return P
    try:
        return P[ConvexHull(P).vertices]
    except (QhullError, ValueError):
        return P


def _refined(H: np.ndarray, u: np.ndarray) -> np.ndarray:
    """``u`` tilted to a local minimum of the volume of the capsule around the points
    ``H`` (Nelder-Mead)."""
    from scipy.optimize import minimize

    E = _perpendicular(u)

    def direction(w: np.ndarray) -> np.ndarray:
        v = u + w[0] * E[0] + w[1] * E[1]
        return v / np.linalg.norm(v)

    def volume(w: np.ndarray) -> float:
        a, b, r = _along(H, direction(w))
        return capsule_volume(r, float(np.linalg.norm(b - a)))

    res = minimize(volume, np.zeros(2), method="Nelder-Mead",
                   options={"xatol": 1e-4, "fatol": 0.0, "maxfev": 200})
    return direction(res.x) if res.fun < volume(np.zeros(2)) else u


def enclosing_capsule(points: Any, axes: Sequence[Any] = (), refine: bool = True
                      ) -> tuple[np.ndarray, np.ndarray, float]:
    """A capsule containing every point: its segment's ends ``a``, ``b`` and its radius.

    Args:
        points: ``(n, 3)`` points, ``n >= 1``.
        axes: Extra candidate axis directions (any length > 0) beside the principal
            axes of the points; the candidate giving the smallest volume is kept.
        refine: Polish the best candidate direction (Nelder-Mead on the volume).
    """
    P = finite_array("points", points)
    if P.ndim != 2 or P.shape[1] != 3 or len(P) == 0:
        raise GeometryError(f"points must be an (n, 3) array with n >= 1, got shape {P.shape}")
    P = np.unique(P, axis=0)
    centred = P - P.mean(axis=0)
    _, vectors = np.linalg.eigh(centred.T @ centred)
    candidates = [vectors[:, k] for k in (2, 1, 0)]
    for axis in axes:
        v = finite_array("axis", axis, shape=(3,))
        n = float(np.linalg.norm(v))
        if n > 0.0:
            candidates.append(v / n)
    H = hull_vertices(P)
    best: tuple[np.ndarray, np.ndarray, float] | None = None
    best_volume = np.inf
    for u in candidates:
        a, b, r = _along(P, u, H)
        volume = capsule_volume(r, float(np.linalg.norm(b - a)))
        if volume < best_volume:
            best, best_volume = (a, b, r), volume
    assert best is not None
    if refine and len(P) > 1:
        a, b, _ = best
        length = float(np.linalg.norm(b - a))
        u = (b - a) / length if length > 0.0 else candidates[0]
        tilted = _along(P, _refined(H, u), H)
        if capsule_volume(tilted[2], float(np.linalg.norm(tilted[1] - tilted[0]))) < best_volume:
            best = tilted
    return best


def mesh_vertices(path: Any) -> np.ndarray:
    """The vertices of a mesh file (STL, OBJ, COLLADA ...), read with trimesh.

    Raises:
        MoikError: trimesh is not installed (``pip install -e '.[fit]'`` in the
            moik repository).
        GeometryError: the file holds no triangle mesh.
    """
    try:
        import trimesh
    except ImportError:
        raise MoikError("reading meshes needs trimesh: pip install -e '.[fit]' in the moik "
                        "repository") from None
    mesh = trimesh.load(str(path), force="mesh")
    if not isinstance(mesh, trimesh.Trimesh):
        raise GeometryError(f"{str(path)!r} holds no triangle mesh")
    return np.asarray(mesh.vertices, dtype=float)


def urdf_mesh_points(source: Any, robot: Robot, mesh_dir: Any, element: str = "collision"
                     ) -> tuple[list[str], dict[str, tuple[int, np.ndarray]]]:
    """Each URDF link's mesh vertices in the frame of the body it is on.

    A mesh ``package://.../name.stl`` is read from ``mesh_dir / name.stl``; its
    ``scale`` and the element's ``<origin>`` are applied. Links with several meshes get
    the union of their vertices; links without a mesh are left out.

    Returns:
        The body names (:func:`~moik.robots.urdf_geometry.link_placements`) and
        ``{link: (body, (n, 3) points)}``.
    """
    names, items = mesh_geometry(source, robot, element)
    folder = Path(mesh_dir)
    out: dict[str, tuple[int, np.ndarray]] = {}
    for item in items:
        path = folder / Path(str(item["filename"]).split("://")[-1]).name
        V = mesh_vertices(path) * item["scale"]
        P = V @ item["pose"][:3, :3].T + item["pose"][:3, 3]
        body, prev = out.get(item["link"], (item["body"], np.empty((0, 3))))
        out[item["link"]] = (body, np.vstack([prev, P]))
    return names, out


def body_axes(robot: Robot) -> list[list[np.ndarray]]:
    """Candidate capsule axes per body, in its frame: the axes of the joints at its two
    ends and the direction between their axis points (the tool point after the last)."""
    q = (robot.lower + robot.upper) / 2
    frames, axes = np.empty((robot.dof + 1, 4, 4)), np.empty((robot.dof, 6))
    world_frames(robot.chain_model, q, frames, axes)
    points = [axes[j, :3] for j in range(robot.dof)] + [frames[-1][:3, 3]]
    out = []
    for body in range(robot.dof + 1):
        R = frames[body][:3, :3]
        joints = [j for j in (body - 1, body) if 0 <= j < robot.dof]
        dirs = [R.T @ axes[j, 3:] for j in joints]
        if body >= 1:
            dirs.append(R.T @ (points[body] - points[body - 1]))
        out.append(dirs)
    return out


def fit_urdf(source: Any, robot: Robot, mesh_dir: Any, element: str = "collision"
             ) -> tuple[list[str], list[dict[str, Any]]]:
    """One enclosing capsule per URDF link with a mesh, on ``robot``'s bodies.

    Returns:
        The body names, and per link (in the URDF's order of links on the chain):
        ``link``, ``body``, ``a``, ``b``, ``radius`` (the capsule in the body's frame,
        in the URDF's unit, metres) and ``points`` (the link's vertices there).
    """
    names, links = urdf_mesh_points(source, robot, mesh_dir, element)
    candidates = body_axes(robot)
    fits = []
    for link, (body, P) in links.items():
        a, b, r = enclosing_capsule(P, candidates[body])
        fits.append({"link": link, "body": body, "a": a, "b": b, "radius": r, "points": P})
    return names, fits
