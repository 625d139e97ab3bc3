"""Collision shapes in a 3-D robot plot: capsules, spheres and boxes as translucent
surfaces, convex hulls as their triangles (a compound as its parts: the geometry the
check measures, not its bound), half-spaces as a translucent patch of their boundary
plane.

Called by :func:`moik.plotting.robot.plot_robot` with ``collision=`` (a
:class:`~moik.collision.model.CollisionChecker`): the robot's shapes at the first
configuration (blue) and the scene's obstacles (grey). :func:`scene_traces` gives a
scene's obstacles as plotly ``mesh3d`` traces, for the interactive explorer
(:func:`moik.plotting.explorer.pareto_explorer`, ``scene=``), and :func:`robot_meshes`
the robot's shapes as triangle meshes in their bodies' frames, which the explorer's page
places at each posture it draws (``collision=``). Both draw a compound as its convex
parts, as :func:`draw_shape` does.
"""

from __future__ import annotations

import numpy as np

from moik.collision.model import CollisionChecker, CollisionModel, Scene
from moik.collision.shapes import Box, Capsule, Compound, ConvexHull, HalfSpace, Shape, Sphere

ROBOT_COLOR, OBSTACLE_COLOR = "tab:blue", "0.45"


def _capsule_mesh(s: Capsule | Sphere, n: int = 16):
    """Points of a capsule (sphere: length 0) surface in its own frame, ``(3, m, n)``."""
    r = s.radius
    h = s.length / 2 if isinstance(s, Capsule) else 0.0
    u = np.linspace(0, 2 * np.pi, n)
    v = np.linspace(0, np.pi, n)
    x = r * np.outer(np.sin(v), np.cos(u))
    y = r * np.outer(np.sin(v), np.sin(u))
    z = r * np.outer(np.cos(v), np.ones_like(u))
    z = z + np.where(z >= 0, h, -h)  # the two hemispheres pushed apart by the segment
    return np.stack([x, y, z])


def _box_faces(s: Box):
    hx, hy, hz = (v / 2 for v in s.size)
    corners = np.array([[sx * hx, sy * hy, sz * hz] for sx in (-1, 1) for sy in (-1, 1)
                        for sz in (-1, 1)])
    faces = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4],
             [1, 3, 7, 5]]
    return corners, faces


def _hull_triangles(shape: ConvexHull) -> tuple[np.ndarray, np.ndarray]:
    """The hull's vertices (its frame) and its triangles (qhull; a flat hull: none)."""
    from scipy.spatial import ConvexHull as Qhull  # loaded at the first hull drawn
    from scipy.spatial import QhullError

    try:
        return shape.points, Qhull(shape.points).simplices
    except (QhullError, ValueError):
        return shape.points, np.zeros((0, 3), dtype=np.int64)


def draw_shape(ax, shape: Shape, *, color: str, span: float, alpha: float = 0.25) -> None:
    """Draw one shape (in world coordinates) into the 3-D Axes ``ax``."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    if isinstance(shape, Compound):
        for part in shape.parts:
            draw_shape(ax, part, color=color, span=span, alpha=alpha)
        return
    R, p = shape.pose[:3, :3], shape.pose[:3, 3]
    if isinstance(shape, ConvexHull):
        P, tri = _hull_triangles(shape)
        W = P @ R.T + p
        ax.add_collection3d(Poly3DCollection([W[t] for t in tri], facecolor=color,
                                             edgecolor="none", alpha=alpha))
    elif isinstance(shape, (Capsule, Sphere)):
        P = np.einsum("ij,jmn->imn", R, _capsule_mesh(shape)) + p[:, None, None]
        ax.plot_surface(P[0], P[1], P[2], color=color, alpha=alpha, linewidth=0,
                        shade=True)
    elif isinstance(shape, Box):
        corners, faces = _box_faces(shape)
        W = corners @ R.T + p
        ax.add_collection3d(Poly3DCollection([W[f] for f in faces], facecolor=color,
                                             edgecolor="0.2", linewidths=0.4, alpha=alpha))
    elif isinstance(shape, HalfSpace):
        a, b = R[:, 0], R[:, 1]
        quad = [p + span * (sa * a + sb * b) for sa, sb in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        ax.add_collection3d(Poly3DCollection([quad], facecolor=color, edgecolor="none",
                                             alpha=0.12))


def draw_collision(ax, checker: CollisionChecker, q: np.ndarray, *, span: float) -> None:
    """The robot's shapes at ``q`` and the scene's obstacles."""
    n_robot = len(checker.model.items)  # the robot's shapes come first, then the obstacles
    for k, (_, shape) in enumerate(checker.world_shapes(q)):
        draw_shape(ax, shape, span=span, color=ROBOT_COLOR if k < n_robot else OBSTACLE_COLOR)


def _mesh(shape: Shape, span: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices ``(v, 3)`` and triangles ``(t, 3)`` of one shape's surface, in the frame its
    pose is given in (the world for an obstacle, its body's frame for a robot shape)."""
    R, p = shape.pose[:3, :3], shape.pose[:3, 3]
    if isinstance(shape, (Capsule, Sphere)):
        n = 12
        P = _capsule_mesh(shape, n).reshape(3, -1).T
        cells = [(a * n + b, a * n + b + 1, (a + 1) * n + b, (a + 1) * n + b + 1)
                 for a in range(n - 1) for b in range(n - 1)]
        tri = [t for c in cells for t in ((c[0], c[1], c[2]), (c[1], c[3], c[2]))]
    elif isinstance(shape, Box):
        P, faces = _box_faces(shape)
        tri = [t for f in faces for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))]
    elif isinstance(shape, HalfSpace):
        P = np.array([[sa * span, sb * span, 0.0] for sa, sb in ((-1, -1), (1, -1), (1, 1),
                                                                 (-1, 1))])
        tri = [(0, 1, 2), (0, 2, 3)]
    elif isinstance(shape, ConvexHull):
        P, hull_tri = _hull_triangles(shape)
        tri = [tuple(t) for t in hull_tri]
    elif isinstance(shape, Compound):  # its parts, each placed by its own pose
        meshes = [_mesh(part, span) for part in shape.parts]
        return _joined(meshes)
    else:
        raise TypeError(f"no surface for {type(shape).__name__}")
    return P @ R.T + p, np.array(tri, dtype=np.int64).reshape(-1, 3)


def _joined(meshes: list[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """Several meshes as one: the vertices stacked, the triangles renumbered."""
    offsets = np.cumsum([0] + [len(V) for V, _ in meshes[:-1]])
    return (np.vstack([V for V, _ in meshes]),
            np.vstack([T.reshape(-1, 3) + k for (_, T), k in zip(meshes, offsets, strict=True)]))


def _mesh_dict(V: np.ndarray, T: np.ndarray, digits: int) -> dict:
    V = np.round(V, digits)
    return {"x": V[:, 0].tolist(), "y": V[:, 1].tolist(), "z": V[:, 2].tolist(),
            "i": T[:, 0].tolist(), "j": T[:, 1].tolist(), "k": T[:, 2].tolist()}


def robot_meshes(model: CollisionModel, *, digits: int = 6) -> list[dict]:
    """The robot's shapes of ``model`` as one triangle mesh per body, in that body's frame.

    Each entry is ``{"name": body, "frame": body index (the frame of
    :meth:`moik.robots.Robot.frames` it moves with), "x", "y", "z": vertices (rounded to
    ``digits`` decimals), "i", "j", "k": triangles}``; a compound is its convex parts (the
    geometry the check measures, not its bound), a capsule or sphere a 12 x 12 grid.
    """
    out = []
    for body, name in enumerate(model.links):
        shapes = [s for b, s in model.items if b == body]
        if shapes:
            V, T = _joined([_mesh(s, 0.0) for s in shapes])
            out.append({"name": name, "frame": body, **_mesh_dict(V, T, digits)})
    return out


def scene_traces(scene: Scene, span: float) -> list[dict]:
    """The obstacles of ``scene`` as plotly ``mesh3d`` trace dicts (grey, translucent,
    named by obstacle; a half-space as a square of half-side ``span`` of its boundary
    plane around its pose's origin)."""
    traces = []
    for name, shape in scene.obstacles.items():
        V, T = _mesh(shape, span)
        traces.append({"type": "mesh3d", "name": name, "x": V[:, 0].tolist(),
                       "y": V[:, 1].tolist(), "z": V[:, 2].tolist(), "i": T[:, 0].tolist(),
                       "j": T[:, 1].tolist(), "k": T[:, 2].tolist(), "color": "grey",
                       "opacity": 0.12 if isinstance(shape, HalfSpace) else 0.35,
                       "hoverinfo": "name", "showlegend": False})
    return traces
