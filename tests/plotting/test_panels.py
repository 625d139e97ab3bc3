"""Convergence panels, one per problem (moik.plotting.panels; MChOA Fig. 5)."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError  # noqa: E402
from moik.plotting import plot_convergence_panels  # noqa: E402


def test_one_panel_per_problem_and_one_legend(tmp_path):
    curves = {"a": np.array([[3.0, 2.0, 1.0], [2.0, 1.0, 0.0]]), "b": np.array([[1.0, 1.0, 1.0]])}
    fig = plot_convergence_panels({"F1": curves, "F2": curves, "F3": curves}, ncols=2,
                                  ylabel="mean best f (function value)", proposed="a",
                                  save=str(tmp_path / "c"))
    visible = [ax for ax in fig.axes if ax.get_visible()]
    assert [ax.get_title() for ax in visible] == ["F1", "F2", "F3"]
    assert all(ax.get_legend() is None for ax in visible) and len(fig.legends) == 1
    assert [t.get_text() for t in fig.legends[0].get_texts()] == ["a", "b"]
    assert fig.legends[0].get_texts()[0].get_fontweight() == "bold"
    assert visible[0].get_yscale() == "log" and "function value" in visible[0].get_ylabel()
    assert (tmp_path / "c.png").is_file() and (tmp_path / "c.pdf").is_file()
    plt.close("all")


def test_bad_panels_are_refused():
    with pytest.raises(ParameterError):
        plot_convergence_panels({})
    with pytest.raises(ParameterError, match="ncols must be an integer >= 1"):
        plot_convergence_panels({"F1": {"a": np.ones(3)}}, ncols=0)
    plt.close("all")
