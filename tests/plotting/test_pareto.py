"""The Pareto set plot: front, postures on one scale, parallel coordinates for 3+ criteria."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from moik.exceptions import ParameterError, ShapeError  # noqa: E402
from moik.plotting.pareto import plot_pareto_ik, posture_picks  # noqa: E402
from moik.robots import get_robot  # noqa: E402

ROBOT = get_robot("iiwa14")
X = ROBOT.random_q(6, rng=np.random.default_rng(2))
F2 = np.column_stack([np.linspace(0.1, 1.0, 6), np.linspace(0.02, 0.1, 6)])  # (min, max)


def test_two_criteria_front_and_postures(tmp_path):
    fig = plot_pareto_ik(ROBOT, X, F2, objectives=("joint_motion", "manipulability"),
                         senses=("min", "max"), target=[0.3, 0.1, 0.5], compromise=2,
                         n_postures=3, save=str(tmp_path / "p"))
    front, *postures = fig.axes
    assert len(postures) == 3
    assert front.get_xlabel() == "joint_motion (smaller is better, rad)"
    assert front.get_ylabel() == "manipulability (larger is better)"
    limits = {tuple(np.round(ax.get_xlim3d(), 12)) for ax in postures}
    assert len(limits) == 1  # every posture on the same scale
    assert postures[0].get_title().startswith("A\njoint_motion = 0.1")
    assert (tmp_path / "p.png").stat().st_size > 0 and (tmp_path / "p.pdf").exists()
    matplotlib.pyplot.close(fig)


def test_three_criteria_add_parallel_coordinates():
    F3 = np.column_stack([F2, np.linspace(0.3, 0.0, 6)])
    fig = plot_pareto_ik(ROBOT, X, F3, objectives=("a", "b", "c"), senses=("min", "max", "max"))
    parallel = fig.axes[-1]
    assert parallel.get_ylabel() == "scaled (1 = best of the set)"
    assert len(parallel.get_xticks()) == 3
    matplotlib.pyplot.close(fig)


def test_posture_picks_keep_each_criterions_best_and_the_compromise():
    F_min = F2 * [1.0, -1.0]
    picks = posture_picks(F_min, 3, 4)
    assert {0, 5, 3} <= set(picks) and len(picks) == 4
    assert picks == sorted(picks, key=lambda i: F_min[i, 0])


def test_bad_input():
    with pytest.raises(ShapeError, match="objectives and senses"):
        plot_pareto_ik(ROBOT, X, F2, objectives=("a",), senses=("min", "max"))
    with pytest.raises(ParameterError, match="senses must be"):
        plot_pareto_ik(ROBOT, X, F2, objectives=("a", "b"), senses=("min", "up"))
    with pytest.raises(ParameterError, match="n_postures"):
        plot_pareto_ik(ROBOT, X, F2, objectives=("a", "b"), senses=("min", "max"), n_postures=9)
    with pytest.raises(ParameterError, match="compromise"):
        plot_pareto_ik(ROBOT, X, F2, objectives=("a", "b"), senses=("min", "max"),
                       compromise=6)
    with pytest.raises(ShapeError, match="criteria F"):
        plot_pareto_ik(ROBOT, X, F2[:3], objectives=("a", "b"), senses=("min", "max"))
