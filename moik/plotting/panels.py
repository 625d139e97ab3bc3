"""Convergence curves of many problems in one figure, one panel each (MChOA Fig. 5).

MChOA Fig. 5 draws the average convergence curves of its six variants on each
of the 23 benchmark functions and the IK function. :func:`plot_convergence_panels`
draws one :func:`moik.plotting.plot_convergence` panel per problem on a grid,
with one legend for the whole figure.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from moik._validate import integer
from moik.plotting._common import LOG_FLOOR, check_mapping, emphasise_legend, save_figure
from moik.plotting.convergence import plot_convergence


def plot_convergence_panels(
    panels: Mapping[str, Mapping[str, np.ndarray]],
    *,
    ncols: int = 6,
    log: bool = True,
    floor: float = LOG_FLOOR,
    xlabel: str = "iteration",
    ylabel: str = "mean best value",
    title: str = "Mean convergence curves",
    proposed: str | None = None,
    save: str | None = None,
):
    """One mean-convergence panel per problem, on a grid with a shared legend.

    Args:
        panels: Problem name -> (algorithm name -> ``(runs, generations)`` values),
            as :func:`~moik.plotting.plot_convergence` takes them.
        ncols: Panels per row (>= 1).
        log: Log y axes (values below ``floor`` drawn at ``floor``).
        floor: Smallest value shown on a log axis.
        xlabel: X label of every panel.
        ylabel: Y label of every panel, with the quantity and unit.
        title: Figure title.
        proposed: The paper's proposed algorithm, emphasised in every panel.
        save: Path stem; writes ``save.png`` and ``save.pdf``.

    Returns:
        The Figure (one Axes per problem, titled with its name).

    Raises:
        ParameterError: empty ``panels``, bad ``ncols``, or a panel that
            :func:`~moik.plotting.plot_convergence` refuses.
    """
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    panels = check_mapping(panels, "panels")
    ncols = min(integer("ncols", ncols, minimum=1), len(panels))
    nrows = -(-len(panels) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.2 * ncols, 2.7 * nrows + 0.8),
                             squeeze=False, layout="constrained")
    for ax, (name, curves) in zip(axes.flat, panels.items(), strict=False):
        plot_convergence(curves, log=log, floor=floor, ax=ax, xlabel=xlabel, ylabel=ylabel,
                         title=name, proposed=proposed)
        ax.get_legend().remove()
        ax.title.set_fontsize("medium")
        ax.yaxis.label.set_fontsize("x-small")
        ax.xaxis.set_major_locator(MaxNLocator(nbins=4, integer=True))  # labels apart
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    legend = fig.legend(handles, [lab.split(" (n=")[0] for lab in labels],
                        loc="outside lower center", ncol=len(labels), fontsize="medium")
    emphasise_legend(legend, proposed)
    fig.suptitle(title)
    save_figure(fig, save)
    return fig
