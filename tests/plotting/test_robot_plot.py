"""Robot drawing: one line per configuration through every joint frame."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from moik.plotting import plot_robot  # noqa: E402
from moik.robots import get_robot  # noqa: E402


def test_plot_robot_content(tmp_path):
    robot = get_robot("puma560")
    Q = robot.random_q(2, rng=np.random.default_rng(0))
    ax = plot_robot(robot, Q, target=[0.4, 0.2, 0.5], labels=["a", "b"], save=str(tmp_path / "r"))
    lines = ax.get_lines()
    assert len(lines) == 2
    x, y, z = lines[0].get_data_3d()
    np.testing.assert_allclose([x[-1], y[-1], z[-1]], robot.fk(Q[0])[:3, 3])
    assert len(x) == robot.dof + 1
    assert ax.get_xlabel() == "x (m)"
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["a", "b", "target"]
    assert (tmp_path / "r.png").stat().st_size > 0 and (tmp_path / "r.pdf").exists()
