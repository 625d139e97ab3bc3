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
    checker = CollisionChecker(model=collision_model(robot), scene=scene)
    plain = plot_robot(robot, np.zeros(6), side_view=False)
    n_plain = len(plain.collections)
    ax = plot_robot(robot, np.zeros(6), side_view=False, collision=checker)
    n_robot = sum(len(v) for v in checker.model.shapes.values())
    added = ax.collections[n_plain:] if len(ax.collections) > n_plain else []
    polys = [c for c in ax.collections if isinstance(c, Poly3DCollection)]
    assert len(ax.collections) >= n_plain + n_robot + 2 and added
    assert len(polys) >= n_robot + 2  # surfaces are Poly3DCollections too
    plt.close("all")
