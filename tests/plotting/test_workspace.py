"""Targets in the workspace: points coloured by height and orientation arrows."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError, ShapeError  # noqa: E402
from moik.plotting import plot_targets  # noqa: E402
from moik.problems.targets import random_reachable_targets  # noqa: E402
from moik.robots import get_robot  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def test_targets_with_arrows(tmp_path):
    robot = get_robot("eosma7")
    targets = random_reachable_targets(robot, 12, seed=3)
    P = np.array([t.position for t in targets])
    R = np.array([t.rotation for t in targets])
    ax = plot_targets(P, R, unit=robot.unit, save=str(tmp_path / "ws"))
    scatter, quiver = ax.collections
    x, y, z = scatter._offsets3d
    np.testing.assert_allclose(np.c_[x, y, z], P)
    np.testing.assert_allclose(scatter.get_array(), P[:, 2])  # colour = height
    segs = np.asarray(quiver._segments3d)
    assert segs.shape == (3 * 12, 2, 3)  # per arrow: shaft + two head strokes
    shafts = segs[:12]  # each shaft runs from the tip back to the target position
    np.testing.assert_allclose(shafts[:, 1], P)
    direction = shafts[:, 0] - shafts[:, 1]
    np.testing.assert_allclose(direction / np.linalg.norm(direction, axis=1)[:, None],
                               R[:, :, 2], atol=1e-9)
    assert ax.get_xlabel() == f"x ({robot.unit})" and ax.get_zlabel() == f"z ({robot.unit})"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "targets (12)", "target z axis"]
    assert (tmp_path / "ws.png").exists() and (tmp_path / "ws.pdf").exists()


def test_positions_only():
    P = np.random.default_rng(0).uniform(-1, 1, (30, 3))
    ax = plot_targets(P)
    assert len(ax.collections) == 1
    assert ax.get_title() == "Targets in the workspace"


@pytest.mark.parametrize(
    ("P", "R", "kwargs", "error", "match"),
    [
        (np.zeros((4, 2)), None, {}, ShapeError, r"positions must have shape \(n, 3\)"),
        (np.zeros((4, 3)), np.zeros((3, 3, 3)), {}, ShapeError, "3 matrices for 4"),
        (np.zeros((4, 3)), None, {"axis": 3}, ParameterError, "axis"),
        (np.zeros((4, 3)), None, {"arrow_length": -1}, ParameterError, "arrow_length"),
    ],
)
def test_targets_bad_input(P, R, kwargs, error, match):
    with pytest.raises(error, match=match):
        plot_targets(P, R, **kwargs)
