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
