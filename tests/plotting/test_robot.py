"""Robot drawing: one line per configuration through every joint frame, in 3-D and from the side."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: E402

from moik.exceptions import ShapeError  # noqa: E402
from moik.kinematics.orientation import geodesic_error  # noqa: E402
from moik.plotting import plot_robot  # noqa: E402
from moik.plotting._scene import FRAME_COLORS  # noqa: E402
from moik.plotting.robot import joint_origins  # noqa: E402
from moik.problems import Target  # noqa: E402
from moik.robots import get_robot  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def test_plot_robot_content(tmp_path):
    robot = get_robot("puma560")
    Q = robot.random_q(2, rng=np.random.default_rng(0))
    target = np.array([0.4, 0.2, 0.5])
    ax = plot_robot(robot, Q, target=target, labels=["a", "b"], save=str(tmp_path / "r"))
    lines = ax.get_lines()
    assert len(lines) == 2
    x, y, z = lines[0].get_data_3d()
    np.testing.assert_allclose([x[-1], y[-1], z[-1]], robot.fk(Q[0])[:3, 3])
    assert len(x) == robot.dof + 1
    assert ax.get_xlabel() == "x (m)"
    errors = [np.linalg.norm(robot.fk(q)[:3, 3] - target) for q in Q]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        f"a (position error {errors[0]:.2e} m)", f"b (position error {errors[1]:.2e} m)",
        "target", "base"]
    assert (tmp_path / "r.png").stat().st_size > 0 and (tmp_path / "r.pdf").exists()


def test_side_view_shows_true_heights():
    robot = get_robot("eosma7")
    q = np.radians([45, 0, 45, 0, 45, 0, 0])
    target = robot.fk(q)[:3, 3]
    ax = plot_robot(robot, q, target=target)
    side = ax.figure.axes[1]
    h, z = side.get_lines()[0].get_data()
    np.testing.assert_allclose(z, robot.frames(q)[:, 2, 3])  # heights as they are
    np.testing.assert_allclose(h[-1], np.linalg.norm(target[:2]))  # reach toward the target
    assert side.get_ylabel() == "height z (cm)" and "toward azimuth" in side.get_xlabel()
    assert h[0] == 0.0 and z[0] == 0.0


def test_frames_joint_numbers_and_orientation_errors():
    robot = get_robot("eosma7")
    q = np.radians([45, 0, 45, 0, 45, 0, 0])
    target = Target(robot.fk(q)[:3, 3], np.eye(3))
    ax = plot_robot(robot, [q, q], target=target, labels=["A", "B"])
    err = float(geodesic_error(robot.fk(q)[:3, :3], np.eye(3)))
    assert ax.get_legend().get_texts()[0].get_text() == (
        f"A (position error {0.0:.2e} cm, orientation error {err:.2e} rad)")
    # red, green, blue axes of the two end-effector frames, then of the (dashed) target frame
    rgb = [to_hex(c) for c in FRAME_COLORS]
    axes = [c for c in ax.collections if isinstance(c, Line3DCollection)
            and to_hex(c.get_colors()[0]) in rgb]
    assert [to_hex(c.get_colors()[0]) for c in axes] == rgb + rgb
    assert [len(c._segments3d) for c in axes] == [2, 2, 2, 1, 1, 1]
    ee = np.asarray(axes[2]._segments3d)[0]  # z axis of solution A's end-effector frame
    np.testing.assert_allclose(ee[0], robot.fk(q)[:3, 3])
    np.testing.assert_allclose((ee[1] - ee[0]) / np.linalg.norm(ee[1] - ee[0]),
                               robot.fk(q)[:3, 2], atol=1e-12)
    # coincident joints of both solutions share one black label
    texts = {t.get_text(): t.get_color() for t in ax.texts}
    assert texts["1"] == "black" and set(texts) <= {str(j) for j in range(1, 8)} | {
        ",".join(map(str, c)) for c in ([4, 5], [6, 7], [2, 3], [3, 4], [5, 6])}
    lines = ax.get_lines()
    assert lines[0].get_linewidth() > lines[1].get_linewidth()  # the later one on top, thinner
    assert lines[0].get_linestyle() != lines[1].get_linestyle()
    assert lines[0].get_zorder() < lines[1].get_zorder()


def test_joint_origins_are_where_the_joints_act():
    robot = get_robot("eosma7")
    q = np.radians([45, 0, 45, 0, 45, 0, 0])
    J = joint_origins(robot, robot.frames(q[None]))[0]
    np.testing.assert_allclose(J[0], [0, 0, 0], atol=1e-12)  # joint 1 at the base
    np.testing.assert_allclose(J[1], [0, 0, 50], atol=1e-12)  # joint 2 at the shoulder, l1 up


def test_pose_target_and_bad_input():
    robot = get_robot("planar2")
    T = np.eye(4)
    T[:3, 3] = robot.fk(np.zeros(2))[:3, 3]
    ax = plot_robot(robot, np.zeros(2), target=T, side_view=False)
    assert len(ax.figure.axes) == 1
    assert "orientation error" in ax.get_legend().get_texts()[0].get_text()
    with pytest.raises(ShapeError, match="labels has 1 entries for 2"):
        plot_robot(robot, np.zeros((2, 2)), labels=["x"])
    with pytest.raises(ShapeError, match="target_rotation needs a target"):
        plot_robot(robot, np.zeros(2), target_rotation=np.eye(3))
    with pytest.raises(ShapeError, match="target must have shape"):
        plot_robot(robot, np.zeros(2), target=[1.0, 2.0])
