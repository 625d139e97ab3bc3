"""Plots (matplotlib): robots, Pareto fronts, convergence, statistics."""

from moik.plotting.robot import plot_robot

__all__ = ["plot_robot"]
