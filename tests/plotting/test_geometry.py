"""The robot plot draws the collision shapes and the obstacles."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from moik import get_robot  # noqa: E402
from moik.collision import Box, CollisionChecker, HalfSpace, Scene  # noqa: E402
from moik.collision.catalog import collision_model  # noqa: E402
from moik.collision.io import rpy_pose  # noqa: E402
from moik.plotting.robot import plot_robot  # noqa: E402


def test_shapes_and_obstacles_drawn():
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    robot = get_robot("ur5")
    scene = Scene({"table": HalfSpace(), "box": Box(size=(0.2, 0.2, 0.2),
                                                    pose=rpy_pose([0.4, 0, 0.3]))})
    checker = CollisionChecker(model=collision_model(robot), scene=scene, self_collision=True)
    plain = plot_robot(robot, np.zeros(6), side_view=False)
    n_plain = len(plain.collections)
    ax = plot_robot(robot, np.zeros(6), side_view=False, collision=checker)
    n_robot = sum(len(v) for v in checker.model.shapes.values())
    added = ax.collections[n_plain:] if len(ax.collections) > n_plain else []
    polys = [c for c in ax.collections if isinstance(c, Poly3DCollection)]
    assert len(ax.collections) >= n_plain + n_robot + 2 and added
    assert len(polys) >= n_robot + 2  # surfaces are Poly3DCollections too
    plt.close("all")


def test_scene_traces_are_the_obstacles_surfaces():
    """Each obstacle one mesh3d trace named after it: a box's 8 corners in the world, a
    capsule's vertices at its radius from its segment, a half-space's on its plane."""
    from moik.collision import Capsule
    from moik.plotting.geometry import scene_traces

    box_pose = rpy_pose([0.4, 0.1, 0.3], [0.0, 0.0, 0.5])
    scene = Scene({"table": HalfSpace.plane([0, 0, 1], 0.05),
                   "box": Box(size=(0.2, 0.4, 0.1), pose=box_pose),
                   "post": Capsule.between([0.3, -0.2, 0.0], [0.3, -0.2, 0.5], 0.04)})
    traces = {t["name"]: t for t in scene_traces(scene, span=1.0)}
    assert set(traces) == {"table", "box", "post"}
    for t in traces.values():
        V = np.column_stack([t["x"], t["y"], t["z"]])
        T = np.column_stack([t["i"], t["j"], t["k"]])
        assert t["type"] == "mesh3d" and T.min() >= 0 and T.max() < len(V)
        traces[t["name"]]["V"] = V
    local = (traces["box"]["V"] - box_pose[:3, 3]) @ box_pose[:3, :3]
    np.testing.assert_allclose(np.sort(np.abs(local), axis=0)[0], [0.1, 0.2, 0.05])
    assert len(traces["box"]["V"]) == 8 and len(traces["box"]["i"]) == 12
    np.testing.assert_allclose(traces["table"]["V"][:, 2], 0.05)
    V = traces["post"]["V"]
    along = np.clip(V[:, 2], 0.0, 0.5)  # the segment runs along z at (0.3, -0.2)
    dist = np.linalg.norm(V - np.column_stack([np.full(len(V), 0.3), np.full(len(V), -0.2),
                                               along]), axis=1)
    np.testing.assert_allclose(dist, 0.04, atol=1e-12)


def _vertices(mesh: dict) -> np.ndarray:
    return np.column_stack([mesh["x"], mesh["y"], mesh["z"]])


def test_robot_meshes_are_the_parts_of_each_compound_in_its_bodys_frame():
    """The explorer's robot shapes (panda: its URDF meshes as compounds) are the convex parts
    the check measures, not the bound: moved by the body's frame they are the parts' vertices
    at that configuration, and every triangle is a face of its part's hull."""
    from moik.collision.model import CollisionModel
    from moik.collision.shapes import Compound
    from moik.plotting.geometry import robot_meshes
    from moik.solver.collision import default_model

    robot = get_robot("panda")
    full = default_model(robot)  # its compounds; the fingers' boxes (on the hand) left out
    model = CollisionModel(robot=robot, links=full.links, shapes={
        link: [s for s in items if isinstance(s, Compound)] for link, items in full.shapes.items()})
    meshes = robot_meshes(model, digits=12)
    bodies = sorted({b for b, _ in model.items})  # one mesh per body (panda_link7: 2 shapes)
    assert [(m["name"], m["frame"]) for m in meshes] == [(model.links[b], b) for b in bodies]
    q = robot.random_q(1, rng=np.random.default_rng(4))[0]
    frames = robot.frames(q)
    for mesh in meshes:
        shapes = [s for b, s in model.items if b == mesh["frame"]]
        assert all(isinstance(s, Compound) for s in shapes)
        T = frames[mesh["frame"]]
        world = _vertices(mesh) @ T[:3, :3].T + T[:3, 3]
        parts = [p.moved(T) for s in shapes for p in s.parts]
        want = np.vstack([p.points @ p.pose[:3, :3].T + p.pose[:3, 3] for p in parts])
        np.testing.assert_allclose(world, want, atol=1e-9)  # the parts, not the bound
        tri = np.column_stack([mesh["i"], mesh["j"], mesh["k"]])
        ends = np.cumsum([len(p.points) for p in parts])
        for a, b, c in tri[:: max(1, len(tri) // 40)]:  # a face of one part's hull
            k = int(np.searchsorted(ends, a, side="right"))
            assert ends[k] > max(a, b, c) and (k == 0 or min(a, b, c) >= ends[k - 1])
            P = world[(0 if k == 0 else ends[k - 1]):ends[k]]
            n = np.cross(world[b] - world[a], world[c] - world[a])
            side = (P - world[a]) @ (n / np.linalg.norm(n))  # metres from its plane
            # qhull merges facets coplanar to its precision: a drawn triangle may lie a
            # few nanometres off the exact facet (clipped pieces have such facets)
            assert side.min() >= -1e-7 or side.max() <= 1e-7


def test_a_compound_obstacle_is_drawn_as_its_parts():
    from moik.plotting.geometry import scene_traces
    from moik.solver.collision import default_model

    [(_, compound), *_] = default_model(get_robot("ur5")).items
    [trace] = scene_traces(Scene({"base": compound}), span=1.0)
    V = np.column_stack([trace["x"], trace["y"], trace["z"]])
    want = np.vstack([p.points @ p.pose[:3, :3].T + p.pose[:3, 3] for p in compound.parts])
    np.testing.assert_allclose(V, want, atol=1e-12)
    assert max(trace["i"] + trace["j"] + trace["k"]) == len(V) - 1
