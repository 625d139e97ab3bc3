"""Plots (matplotlib): robots, Pareto fronts, convergence, statistics, motions.

Every function takes plain arrays (or dicts name -> array), returns the Axes or
Figure it drew, and with ``save="path/stem"`` writes ``stem.png`` and
``stem.pdf``. matplotlib is imported only when a plot is drawn.

:func:`pareto_explorer` and :func:`write_explorer` write the interactive explorer
(one self-contained HTML page, plotly: the ``explorer`` extra, imported only then).
"""

from moik.plotting.convergence import plot_convergence, plot_joint_history
from moik.plotting.explorer import pareto_explorer, write_explorer
from moik.plotting.fronts import plot_pareto_fronts
from moik.plotting.motion import plot_end_effector_paths, plot_motion
from moik.plotting.panels import plot_convergence_panels
from moik.plotting.path import plot_path_tracking
from moik.plotting.robot import plot_robot
from moik.plotting.statistics import plot_error_boxes, plot_solve_times, plot_wilcoxon
from moik.plotting.workspace import plot_targets

__all__ = [
    "pareto_explorer",
    "plot_convergence",
    "plot_convergence_panels",
    "plot_end_effector_paths",
    "plot_error_boxes",
    "plot_joint_history",
    "plot_motion",
    "plot_pareto_fronts",
    "plot_path_tracking",
    "plot_robot",
    "plot_solve_times",
    "plot_targets",
    "plot_wilcoxon",
    "write_explorer",
]
