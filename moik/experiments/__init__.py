"""Experiments that regenerate the papers' tables and figures.

Configs (one file per table/figure in the repository's ``experiments/``,
shipped as ``moik.paper_configs``; see :mod:`moik.experiments.registry`) are
validated into :class:`ExperimentConfig` by their kind
(:mod:`moik.experiments.kinds`: IK problems on robot arms, benchmark
functions, multi-objective benchmark functions with analytic fronts);
:func:`run_experiment` runs their trials (serially, in a process
pool or on Dask) and stores each as it finishes in a :class:`ResultStore`;
:func:`write_report` writes the Markdown report, :func:`report_explorer` the
interactive page (fronts linked to postures, convergence, the report's tables);
:func:`load_results` returns the stored trials as records (or a pandas DataFrame).
:func:`solve_until_success` is the EOSMA paper's re-solve protocol.
"""

from moik.experiments.config import ExperimentConfig, load_config
from moik.experiments.explorer import report_explorer
from moik.experiments.protocol import ProtocolResult, solve_until_success
from moik.experiments.registry import available_experiments, get_experiment
from moik.experiments.report import write_report
from moik.experiments.results import load_results
from moik.experiments.runner import RunSummary, run_experiment
from moik.experiments.store import ResultStore

__all__ = [
    "ExperimentConfig",
    "ProtocolResult",
    "ResultStore",
    "RunSummary",
    "available_experiments",
    "get_experiment",
    "load_results",
    "load_config",
    "report_explorer",
    "run_experiment",
    "solve_until_success",
    "write_report",
]
