"""Solve times, error box plots and Wilcoxon p-value bars."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import NonFiniteError, ParameterError, ShapeError  # noqa: E402
from moik.plotting import plot_error_boxes, plot_solve_times, plot_wilcoxon  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def test_solve_times_content(tmp_path):
    times = {"EOSMA": [0.3, 0.4, 0.5], "EO": [0.6, 0.7, 0.8]}
    ax = plot_solve_times(times, save=str(tmp_path / "t"))
    lines = ax.get_lines()
    assert len(lines) == 2
    np.testing.assert_array_equal(lines[0].get_xdata(), [1, 2, 3])
    np.testing.assert_array_equal(lines[1].get_ydata(), [0.6, 0.7, 0.8])
    assert ax.get_ylabel() == "solve time (s)"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "EOSMA (mean 0.4 s)", "EO (mean 0.7 s)"]
    assert (tmp_path / "t.png").exists() and (tmp_path / "t.pdf").exists()
    assert plot_solve_times(times, log=True).get_yscale() == "log"


def test_solve_times_bad_input():
    with pytest.raises(ShapeError, match="one time per target"):
        plot_solve_times({"A": [1.0, 2.0], "B": [1.0]})
    with pytest.raises(ParameterError, match="> 0 on a log axis"):
        plot_solve_times({"A": [0.0, 2.0]}, log=True)
    with pytest.raises(ParameterError, match="empty"):
        plot_solve_times({})


def test_error_boxes_content(tmp_path):
    errs = {"EOSMA": [0.0, 1e-20, 1e-10, 1e-12], "SMA": [1e-3, 1e-2, 1e-4]}
    ax = plot_error_boxes(errs, ylabel="position error (cm)", save=str(tmp_path / "b"))
    assert [t.get_text() for t in ax.get_xticklabels()] == ["EOSMA", "SMA"]
    assert ax.get_yscale() == "log"
    assert ax.get_ylabel() == "position error (cm) [< 1e-18 shown at 1e-18]"
    # Whisker lines carry the floored data: the lowest plotted value is the floor.
    ys = np.concatenate([ln.get_ydata() for ln in ax.get_lines()])
    assert ys.min() == 1e-18
    assert len(ax.get_lines()) == 2 * 7  # per box: 2 whiskers, 2 caps, box, median, fliers
    flat = [ln.get_ydata() for ln in ax.get_lines() if len(set(ln.get_ydata())) == 1]
    levels = {float(y[0]) for y in flat}
    assert np.median([1e-18, 1e-18, 1e-10, 1e-12]) in levels  # EOSMA median of floored data
    assert 1e-3 in levels  # SMA median
    assert (tmp_path / "b.pdf").exists()


def test_error_boxes_bad_input():
    with pytest.raises(ShapeError, match="1-D"):
        plot_error_boxes({"A": np.ones((2, 2))})
    with pytest.raises(NonFiniteError, match="NaN"):
        plot_error_boxes({"A": [1.0, np.nan]})
    with pytest.raises(ParameterError, match="negative"):
        plot_error_boxes({"A": [-1.0]})


def test_wilcoxon_content(tmp_path):
    p = {"SMA": 1e-30, "EO": 0.01, "SASS": 0.3, "PSO": 0.0}
    ax = plot_wilcoxon(p, proposed="EOSMA", save=str(tmp_path / "w"))
    bars = ax.patches
    assert len(bars) == 4
    heights = [b.get_height() for b in bars]
    np.testing.assert_allclose(heights, [1e-30, 0.01, 0.3, 1e-300])
    assert [t.get_text() for t in ax.get_xticklabels()] == list(p)
    # significant bars share one colour, the non-significant one differs
    assert bars[0].get_facecolor() == bars[1].get_facecolor() != bars[2].get_facecolor()
    hlines = [ln for ln in ax.get_lines() if ln.get_label() == "p = 0.05"]
    assert len(hlines) == 1 and hlines[0].get_ydata()[0] == 0.05
    assert ax.get_yscale() == "log"
    assert ax.get_ylabel() == "p-value [< 1e-300 shown at 1e-300]"  # PSO's 0 was floored
    assert plot_wilcoxon({"A": 0.2}).get_ylabel() == "p-value"
    assert "EOSMA" in ax.get_title()
    assert (tmp_path / "w.png").exists()


def test_wilcoxon_bad_input():
    with pytest.raises(ParameterError, match=r"\[0, 1\]; bad for \['A'\]"):
        plot_wilcoxon({"A": 1.5})
    with pytest.raises(ParameterError, match="alpha"):
        plot_wilcoxon({"A": 0.5}, alpha=1.0)
    with pytest.raises(ShapeError, match="scalar"):
        plot_wilcoxon({"A": [0.1, 0.2]})
    with pytest.raises(ParameterError, match="empty"):
        plot_wilcoxon({})
