"""Every kind of figure moik draws is laid out so that no two texts overlap: axis labels,
tick labels, titles, legends and notes, measured as the window extents matplotlib draws
them at. Joint numbers drawn on the arm (``gid="data-label"``) sit on the data and may
touch when joints are close; tick labels of ticks outside the view are not drawn."""

import itertools

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.text import Text  # noqa: E402

from moik import get_robot  # noqa: E402
from moik.plotting import (  # noqa: E402
    plot_convergence,
    plot_convergence_panels,
    plot_end_effector_paths,
    plot_error_boxes,
    plot_joint_history,
    plot_motion,
    plot_pareto_fronts,
    plot_path_tracking,
    plot_robot,
    plot_solve_times,
    plot_targets,
    plot_wilcoxon,
)
from moik.plotting.pareto import plot_pareto_ik  # noqa: E402
from moik.problems import circle_path, random_reachable_targets  # noqa: E402


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def drawn_texts(fig: Figure) -> list[tuple[Text, object]]:
    """The texts a draw of ``fig`` shows, with their window extents."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    hidden = set()
    for ax in fig.axes:
        for axis in ax._axis_map.values():
            lo, hi = sorted(axis.get_view_interval())
            eps = 1e-9 * max(abs(lo), abs(hi), 1.0)
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not lo - eps <= tick.get_loc() <= hi + eps:
                    hidden.update({id(tick.label1), id(tick.label2)})
    return [(t, t.get_window_extent(renderer)) for t in fig.findobj(Text)
            if t.get_visible() and t.get_text().strip() and id(t) not in hidden
            and t.get_gid() != "data-label"]


def overlapping(fig: Figure) -> list[tuple[str, str]]:
    """Pairs of drawn texts whose boxes share more than a pixel each way."""
    out = []
    for (a, A), (b, B) in itertools.combinations(drawn_texts(fig), 2):
        if min(A.x1, B.x1) - max(A.x0, B.x0) > 1 and min(A.y1, B.y1) - max(A.y0, B.y0) > 1:
            out.append((a.get_text(), b.get_text()))
    return out


def figure_of(drawn) -> Figure:
    return drawn if isinstance(drawn, Figure) else drawn.figure


ARMS = ["eosma7", "rokbani5", "planar2", "irb2600", "ur5", "puma560-urdf", "panda", "iiwa14"]


@pytest.mark.parametrize("name", ARMS)
def test_robot_figures_have_no_overlapping_text(name):
    """The ``moik solve --plot`` figure (3-D and side view) at three targets and at the
    zero posture (upright arms: a narrow side view)."""
    robot = get_robot(name)
    for seed, target in enumerate(random_reachable_targets(robot, 3, seed=0)):
        q = robot.random_q(2, rng=np.random.default_rng(seed))
        for Q in (q, np.zeros(robot.dof)):
            fig = figure_of(plot_robot(robot, Q, target=target))
            assert overlapping(fig) == [], (name, seed)
            plt.close(fig)


def _series(rng):
    return {"EOSMA": rng.random((5, 40)).cumsum(axis=1)[:, ::-1] + 1e-3,
            "SMA": rng.random((5, 40)).cumsum(axis=1)[:, ::-1] + 1e-2}


def test_every_other_plot_kind_has_no_overlapping_text():
    rng = np.random.default_rng(3)
    robot = get_robot("eosma7")
    q0, q1, q2 = robot.random_q(3, rng=rng)
    circle = circle_path([15.0, 0.0, 12.0], 8.0, 50)
    D = np.array([t.position for t in circle])
    iiwa = get_robot("iiwa14")
    X = iiwa.random_q(6, rng=rng)
    F2 = np.column_stack([np.linspace(0.1, 1.0, 6), np.linspace(0.02, 0.1, 6)])
    positions = np.array([t.position for t in random_reachable_targets(robot, 30, seed=1)])
    figures = {
        "convergence": lambda: plot_convergence(_series(rng), band=(25, 75)),
        "joint history": lambda: plot_joint_history(rng.random((50, 7))),
        "convergence panels": lambda: plot_convergence_panels(
            {f"F{k}": _series(rng) for k in range(1, 6)}, ncols=3,
            ylabel="mean best f (function value)", proposed="EOSMA"),
        "pareto fronts": lambda: plot_pareto_fronts(
            {"MOEOSMA": rng.random((20, 2)), "MOPSO": rng.random((20, 2))},
            compromise=[0.5, 0.2]),
        "pareto ik": lambda: plot_pareto_ik(iiwa, X, F2, objectives=("joint_motion",
                                                                    "manipulability"),
                                            senses=("min", "max"), compromise=2),
        "motion": lambda: plot_motion(robot, q0, q1, duration=3.0, n=31, label="EOSMA",
                                      others={"EO": q2}, target=robot.fk(q1)[:3, 3]),
        "end-effector paths": lambda: plot_end_effector_paths(robot, q0, {"A": q1, "B": q2},
                                                              n=11, show_arm=True),
        "path tracking": lambda: plot_path_tracking(
            D, D + 1e-3 * rng.standard_normal(D.shape),
            orientation_errors=rng.random(len(D)) * 1e-3),
        "targets": lambda: plot_targets(positions, unit="cm"),
        "solve times": lambda: plot_solve_times({"EOSMA": rng.random(20) + 0.1,
                                                 "SMA": rng.random(20) + 0.2}),
        "error boxes": lambda: plot_error_boxes({"EOSMA": rng.random(20) * 1e-8,
                                                 "SMA": rng.random(20) * 1e-3},
                                                ylabel="position error (cm)"),
        "wilcoxon": lambda: plot_wilcoxon({"SMA": 1e-30, "EO": 0.01, "SASS": 0.3, "PSO": 0.0},
                                          proposed="EOSMA"),
    }
    found = {}
    for kind, draw in figures.items():
        bad = overlapping(figure_of(draw()))
        if bad:
            found[kind] = bad
        plt.close("all")
    assert found == {}
