"""Path tracking plot: desired vs reached points and the per-point errors."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ShapeError  # noqa: E402
from moik.plotting import plot_path_tracking  # noqa: E402
from moik.problems.targets import circle_path  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


@pytest.fixture
def circle():
    D = np.array([t.position for t in circle_path([15.0, 0.0, 12.0], 8.0, 50)])
    offset = np.random.default_rng(0).normal(scale=0.03, size=D.shape)
    return D, D + offset


def test_path_full_figure(tmp_path, circle):
    D, R = circle
    ori = np.full(50, 5.7e-5)
    Q = np.random.default_rng(1).uniform(-1, 1, (50, 5))
    fig = plot_path_tracking(D, R, orientation_errors=ori, Q=Q, save=str(tmp_path / "p"))
    ax3, axp, axo, axq = fig.axes
    desired, reached = ax3.get_lines()
    np.testing.assert_allclose(np.column_stack(desired.get_data_3d()), D)
    np.testing.assert_allclose(np.column_stack(reached.get_data_3d()), R)
    assert [t.get_text() for t in ax3.get_legend().get_texts()] == ["desired", "reached"]
    err = axp.get_lines()[0]
    np.testing.assert_array_equal(err.get_xdata(), np.arange(1, 51))
    np.testing.assert_allclose(err.get_ydata(), np.linalg.norm(R - D, axis=1))
    assert axp.get_ylabel() == "position error (cm)"
    assert axo.get_ylabel() == "orientation error (rad)"
    np.testing.assert_allclose(axo.get_lines()[0].get_ydata(), ori)
    assert len(axq.get_lines()) == 5
    assert axq.get_ylabel() == "joint angle (deg)"  # Q in rad, drawn in degrees
    np.testing.assert_allclose(axq.get_lines()[1].get_ydata(), np.degrees(Q[:, 1]))
    assert axq.get_xlabel() == "path point index"
    assert fig._suptitle.get_text() == "Path tracking (50 points)"
    assert (tmp_path / "p.png").exists() and (tmp_path / "p.pdf").exists()


def test_path_minimal_log(circle):
    D, _ = circle
    fig = plot_path_tracking(D, D.copy(), log=True, floor=1e-9)
    assert len(fig.axes) == 2
    ax = fig.axes[1]
    assert ax.get_yscale() == "log"
    assert np.all(ax.get_lines()[0].get_ydata() == 1e-9)  # exact hits drawn at the floor
    assert "shown at 1e-09" in ax.get_ylabel()


def test_path_bad_input(circle):
    D, R = circle
    with pytest.raises(ShapeError, match="must match desired"):
        plot_path_tracking(D, R[:-1])
    with pytest.raises(ShapeError, match="49 values for 50 points"):
        plot_path_tracking(D, R, orientation_errors=np.zeros(49))
    with pytest.raises(ShapeError, match="Q has 3 rows"):
        plot_path_tracking(D, R, Q=np.zeros((3, 5)))
    with pytest.raises(ShapeError, match=r"desired points must have shape \(n, 3\)"):
        plot_path_tracking(D[:, :2], R)
