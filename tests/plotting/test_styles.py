"""Series styles distinct up to 20 algorithms, the proposed method emphasised, legends off the
data, integer ticks for iterations and counts, few ticks on a squashed 3-D axis."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from moik.plotting import (  # noqa: E402
    plot_convergence,
    plot_error_boxes,
    plot_joint_history,
    plot_pareto_fronts,
    plot_path_tracking,
    plot_solve_times,
    plot_targets,
    plot_wilcoxon,
)
from moik.plotting._common import series_style  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def _key(style):
    return style["color"], style["marker"], style["linestyle"]


def test_series_styles_are_distinct():
    assert len({series_style(i)["color"] for i in range(20)}) == 20
    assert len({series_style(i)["marker"] for i in range(20)}) == 20
    assert len({_key(series_style(i)) for i in range(40)}) == 40
    plain, bold = series_style(0), series_style(0, emphasis=True)
    assert bold["linewidth"] > plain["linewidth"] and bold["zorder"] > plain["zorder"]
    assert bold["markersize"] > plain["markersize"] and bold["markeredgecolor"] == "black"


def _legend_is_outside(ax):
    ax.figure.canvas.draw()
    legend = ax.get_legend().get_window_extent()
    box = ax.get_window_extent()
    return legend.x0 >= box.x1 or legend.y1 <= box.y0


def test_fifteen_fronts_keep_their_own_colours_and_the_proposed_stands_out():
    rng = np.random.default_rng(0)
    names = ["moeosma"] + [f"alg{i}" for i in range(1, 14)] + ["mo-m-pso"]
    ax = plot_pareto_fronts({n: rng.uniform(0, 1, (5, 2)) for n in names}, proposed="moeosma")
    lines = ax.get_lines()
    colours = [to_hex(ln.get_color()) for ln in lines]
    assert len(set(colours)) == 15  # moeosma (1st) and mo-m-pso (15th) no longer share blue
    assert lines[0].get_markersize() > lines[1].get_markersize()
    assert lines[0].get_zorder() > lines[1].get_zorder()
    assert lines[14].get_markerfacecolor() == "none"  # the second ten: hollow markers
    texts = ax.get_legend().get_texts()
    assert texts[0].get_fontweight() == "bold" and texts[1].get_fontweight() == "normal"
    assert _legend_is_outside(ax)


def test_convergence_emphasis_legend_and_integer_iterations():
    curves = {f"a{i}": np.linspace(1.0, 0.1, 30) * (i + 1) for i in range(12)}
    ax = plot_convergence(curves, proposed="a3")
    lines = ax.get_lines()
    assert lines[3].get_linewidth() > lines[0].get_linewidth()
    assert [t.get_fontweight() for t in ax.get_legend().get_texts()].count("bold") == 1
    assert isinstance(ax.xaxis.get_major_locator(), MaxNLocator)
    assert all(float(t).is_integer() for t in ax.get_xticks())
    assert _legend_is_outside(ax)
    assert len({_key({"color": ln.get_color(), "marker": ln.get_marker(),
                      "linestyle": ln.get_linestyle()}) for ln in lines}) == 12


def test_integer_ticks_for_targets_iterations_and_path_points():
    ax = plot_solve_times({"A": [0.1, 0.2, 0.3], "B": [0.2, 0.1, 0.4]}, proposed="A")
    assert all(float(t).is_integer() for t in ax.get_xticks())
    assert ax.get_lines()[0].get_linewidth() > ax.get_lines()[1].get_linewidth()
    ax = plot_joint_history(np.ones((7, 3)))
    assert all(float(t).is_integer() for t in ax.get_xticks())
    D = np.c_[np.cos(np.arange(5)), np.sin(np.arange(5)), np.zeros(5)]
    fig = plot_path_tracking(D, D + 0.01, orientation_errors=np.full(5, 1e-3), log=True)
    assert all(float(t).is_integer() for t in fig.axes[-1].get_xticks())
    # the floor note on its own line: the long labels of stacked panels do not collide
    assert fig.axes[1].get_ylabel() == "position error (cm)\n[< 1e-18 shown at 1e-18]"


def test_error_boxes_and_wilcoxon_emphasis():
    ax = plot_error_boxes({"A": [1.0, 2.0, 3.0], "B": [2.0, 3.0, 4.0]}, proposed="B")
    assert [t.get_fontweight() for t in ax.get_xticklabels()] == ["normal", "bold"]
    ax = plot_wilcoxon({"A": 0.2, "B": 0.3}, proposed="C")
    assert ax.get_ylim() == pytest.approx((0.005, 1.0))  # bars measured from a fixed floor
    assert [t.get_text() for t in ax.get_legend().get_texts()][1:] == [
        "p < 0.05: significant difference", "p >= 0.05: no significant difference"]


def test_squashed_workspace_axis_keeps_few_readable_ticks():
    rng = np.random.default_rng(2)
    P = np.c_[rng.uniform(-1, 1, (30, 2)), rng.uniform(0.5, 0.52, 30)]  # one height, nearly
    ax = plot_targets(P)
    lo, hi = ax.get_zlim()
    assert hi - lo >= 0.3 * 2 * 0.99  # widened to 30 % of the longest axis, scales equal
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        lo, hi = axis.get_view_interval()
        assert 2 <= len([v for v in axis.get_majorticklocs() if lo <= v <= hi]) <= 6
