"""Motion plot: quintic joint curves and the end-effector path by FK."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError, ShapeError  # noqa: E402
from moik.kinematics.trajectory import quintic_trajectory  # noqa: E402
from moik.plotting import plot_end_effector_paths, plot_motion  # noqa: E402
from moik.robots import get_robot  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


@pytest.fixture
def setup():
    robot = get_robot("eosma7")
    rng = np.random.default_rng(1)
    q0, q1, q2 = robot.random_q(3, rng=rng)
    return robot, q0, q1, q2


def test_motion_figure(tmp_path, setup):
    robot, q0, q1, q2 = setup
    target = robot.fk(q1)[:3, 3]
    fig = plot_motion(robot, q0, q1, duration=3.0, n=31, label="EOSMA", others={"EO": q2},
                      target=target, save=str(tmp_path / "m"))
    ax3, axq, axv, axa = fig.axes
    t, Q, Qd, Qdd = quintic_trajectory(q0, q1, 3.0, 31)
    for ax, Y in ((axq, Q), (axv, Qd), (axa, Qdd)):
        assert len(ax.get_lines()) == robot.dof
        np.testing.assert_allclose(ax.get_lines()[2].get_ydata(), np.degrees(Y[:, 2]))
        np.testing.assert_allclose(ax.get_lines()[0].get_xdata(), t)
        assert ax.get_xlabel() == "time (s)"
    assert axq.get_ylabel() == "joint angle (deg)"  # the same unit as every joint figure
    assert axv.get_ylabel() == "joint velocity (deg/s)"
    assert axa.get_ylabel() == "joint acceleration (deg/s²)"
    # 3-D panel: path of EOSMA ends at the FK of q1, i.e. the target
    path = ax3.get_lines()[0]
    x, y, z = path.get_data_3d()
    assert len(x) == 31
    np.testing.assert_allclose([x[-1], y[-1], z[-1]], target, atol=1e-9)
    np.testing.assert_allclose([x[0], y[0], z[0]], robot.fk(q0)[:3, 3], atol=1e-9)
    legend = [t.get_text() for t in ax3.get_legend().get_texts()]
    assert legend == ["EOSMA", "EO", "start", "target"]
    assert ax3.get_xlabel() == f"x ({robot.unit})"
    assert (tmp_path / "m.png").exists() and (tmp_path / "m.pdf").exists()


def test_end_effector_paths_lines(setup):
    robot, q0, q1, q2 = setup
    ax = plot_end_effector_paths(robot, q0, {"A": q1, "B": q2}, n=11, show_arm=True)
    # 2 paths + 3 grey arms (start and both goals) + start marker
    assert len(ax.get_lines()) == 6
    arm = ax.get_lines()[2].get_data_3d()
    assert len(arm[0]) == robot.dof + 1
    ax2 = plot_end_effector_paths(robot, q0, {"A": q1}, show_arm=False)
    assert len(ax2.get_lines()) == 2


def test_motion_bad_input(setup):
    robot, q0, q1, _ = setup
    with pytest.raises(ShapeError, match="must have shape"):
        plot_motion(robot, q0, q1[:3])
    with pytest.raises(ParameterError, match="reuse the label"):
        plot_motion(robot, q0, q1, label="A", others={"A": q1})
    with pytest.raises(ParameterError, match="duration"):
        plot_motion(robot, q0, q1, duration=0)
    with pytest.raises(ParameterError, match="empty"):
        plot_end_effector_paths(robot, q0, {})
    with pytest.raises(ShapeError, match=r"q_start .*must have shape \(7,\)"):
        plot_end_effector_paths(robot, np.vstack([q0, q0]), {"A": q1})
