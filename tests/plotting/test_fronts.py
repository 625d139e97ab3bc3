"""Pareto-front plot: one sorted marker series per algorithm plus the compromise."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError, ShapeError  # noqa: E402
from moik.plotting import plot_pareto_fronts  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def test_fronts_content(tmp_path):
    a = np.array([[3.0, 0.1], [1.0, 0.3], [2.0, 0.2]])
    b = np.array([[0.5, 0.9], [4.0, 0.05]])
    ax = plot_pareto_fronts({"MOEOSMA": a, "MOPSO": b}, compromise=[2.0, 0.2],
                            xlabel="position error (cm)", title="PF at pose P1",
                            save=str(tmp_path / "pf"))
    lines = ax.get_lines()
    assert len(lines) == 3
    np.testing.assert_array_equal(lines[0].get_xdata(), [1.0, 2.0, 3.0])  # sorted by f1
    np.testing.assert_array_equal(lines[0].get_ydata(), [0.3, 0.2, 0.1])
    assert len(lines[1].get_xdata()) == 2
    assert lines[2].get_marker() == "*"
    assert ax.get_xlabel() == "position error (cm)"
    assert ax.get_ylabel() == "orientation error (rad)"
    assert ax.get_title() == "PF at pose P1"
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["MOEOSMA (3)", "MOPSO (2)", "compromise"]
    assert ax.get_xscale() == "linear"
    assert (tmp_path / "pf.png").stat().st_size > 0 and (tmp_path / "pf.pdf").exists()


def test_fronts_log_floor():
    ax = plot_pareto_fronts({"A": [[0.0, 1e-3], [1e-2, 0.0]]}, log=True, floor=1e-12)
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert ax.get_lines()[0].get_xdata().min() == 1e-12
    assert "shown at 1e-12" in ax.get_xlabel()


@pytest.mark.parametrize(
    ("fronts", "kwargs", "error", "match"),
    [
        ({}, {}, ParameterError, "empty"),
        ({"A": np.zeros((3, 3))}, {}, ShapeError, r"front of 'A' must have shape \(n, 2\)"),
        ({"A": np.zeros((0, 2))}, {}, ShapeError, "at least 1"),
        ({"A": np.zeros((2, 2))}, {"compromise": [1, 2, 3]}, ShapeError, "compromise"),
        ({"A": -np.ones((2, 2))}, {"log": True}, ParameterError, "negative"),
    ],
)
def test_fronts_bad_input(fronts, kwargs, error, match):
    with pytest.raises(error, match=match):
        plot_pareto_fronts(fronts, **kwargs)
