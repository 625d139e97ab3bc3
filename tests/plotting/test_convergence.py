"""Convergence plot: mean over runs on a log axis, zeros drawn at the floor."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError, ShapeError  # noqa: E402
from moik.plotting import plot_convergence, plot_joint_history  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def test_convergence_content(tmp_path):
    a = np.array([[1.0, 1e-3, 0.0], [3.0, 1e-1, 0.0]])
    b = np.array([2.0, 1.0, 0.5, 0.25])  # one run, longer
    ax = plot_convergence({"EOSMA": a, "SMA": b}, band=(25, 75), save=str(tmp_path / "c"))
    lines = ax.get_lines()
    assert len(lines) == 2
    np.testing.assert_array_equal(lines[0].get_xdata(), [1, 2, 3])
    np.testing.assert_allclose(lines[0].get_ydata(), [2.0, 0.0505, 1e-18])  # zero -> floor
    assert len(lines[1].get_xdata()) == 4
    assert ax.get_yscale() == "log"
    assert "shown at 1e-18" in ax.get_ylabel()
    assert ax.get_xlabel() == "iteration"
    assert "25-75 percentile" in ax.get_title()
    assert len(ax.collections) == 2  # one band per algorithm
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["EOSMA (n=2)", "SMA (n=1)"]
    assert (tmp_path / "c.png").exists() and (tmp_path / "c.pdf").exists()


def test_convergence_linear_with_x():
    ax = plot_convergence({"A": np.ones((3, 2))}, x=[100, 200], log=False,
                          xlabel="function evaluations")
    assert ax.get_yscale() == "linear" and ax.get_ylabel() == "mean best fitness"
    np.testing.assert_array_equal(ax.get_lines()[0].get_xdata(), [100, 200])
    assert not ax.collections


@pytest.mark.parametrize(
    ("curves", "kwargs", "error", "match"),
    [
        ({}, {}, ParameterError, "empty"),
        ({"A": np.ones((2, 3))}, {"x": [1, 2]}, ShapeError, "3 generations"),
        ({"A": np.ones((2, 3, 1))}, {}, ShapeError, "runs, generations"),
        ({"A": np.ones((2, 3))}, {"band": (80, 20)}, ParameterError, "band"),
        ({"A": -np.ones((2, 3))}, {}, ParameterError, "negative"),
        ({"A": np.ones(3)}, {"floor": 0.0}, ParameterError, "floor"),
    ],
)
def test_convergence_bad_input(curves, kwargs, error, match):
    with pytest.raises(error, match=match):
        plot_convergence(curves, **kwargs)


def test_joint_history():
    H = np.cumsum(np.ones((50, 7)) * 0.01, axis=0)
    ax = plot_joint_history(H)
    assert len(ax.get_lines()) == 7
    assert ax.get_ylabel() == "joint angle (deg)"  # given in rad, drawn in degrees
    np.testing.assert_allclose(ax.get_lines()[3].get_ydata(), np.degrees(H[:, 3]))
    mixed = plot_joint_history(H[:, :3], prismatic=[False, False, True], unit="m")
    assert mixed.get_ylabel() == "joint value (deg | m for prismatic joints)"
    np.testing.assert_allclose(mixed.get_lines()[2].get_ydata(), H[:, 2])  # prismatic as is
    assert [t.get_text() for t in ax.get_legend().get_texts()][-1] == "q7"
    with pytest.raises(ShapeError, match="joint_labels"):
        plot_joint_history(H, joint_labels=["a"])
    with pytest.raises(ShapeError, match="prismatic has 2 entries, history has 7 joints"):
        plot_joint_history(H, prismatic=[True, False])
    with pytest.raises(ShapeError, match="2-D"):
        plot_joint_history(np.ones(5))
