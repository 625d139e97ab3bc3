"""Least-squares fit of DH lengths to a paper's printed joint solutions (I-BES Table 9).

The paper prints, per target, joint solutions that are meant to reach it; when
they miss, the arm they were computed on is not the catalog's. :func:`fit_dh_lengths`
finds the DH lengths (``a`` and ``d`` entries named in the config) that make
the printed solutions reach the printed targets, from the catalog arm's twists
and a start guess; the ``dh-fit`` analysis prints the fit beside the catalog
arm and, per target, where the printed solutions land on the catalog arm.

Config (``paper["dh_fit"]``)::

    {"solutions": "paper",            # which q of paper["branches"] to fit
     "lengths": [["a", 1], ["a", 2], ["d", 2], ["d", 3]],
     "start": [0.431, 0.02, 0.15, 0.432],
     "targets": {"T1": [0.6, 0.15, 0.2], ...},   # the targets as printed
     "fit_targets": ["T2", "T3", "T4", "T5"]}    # the targets the fit uses

Locked joints (``problem["locked_joints_deg"]``) take their locked values.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import least_squares

from moik._validate import choice, integer
from moik.exceptions import ConfigError
from moik.experiments.kinds.ik_robot import arm
from moik.experiments.tables import Results, Table, fmt
from moik.robots import Robot


@dataclass(frozen=True)
class LengthFit:
    """Result of :func:`fit_dh_lengths`.

    Attributes:
        values: The fitted lengths, in the order asked for (robot unit).
        max_residual: Largest coordinate residual over the fitted targets (robot unit).
        robot: The arm with the fitted lengths.
    """

    values: np.ndarray
    max_residual: float
    robot: Robot


def full_q(robot: Robot, q, locked_deg) -> np.ndarray:
    """Joint vectors ``q`` (``(n, free)``) completed with the locked joints' values."""
    q = np.atleast_2d(np.asarray(q, dtype=float))
    if not locked_deg:
        return q
    out = np.zeros((q.shape[0], robot.dof))
    free = [j for j, v in enumerate(locked_deg) if v is None]
    out[:, free] = q
    for j, v in enumerate(locked_deg):
        if v is not None:
            out[:, j] = np.radians(v)
    return out


def with_lengths(robot: Robot, lengths, values) -> Robot:
    """``robot`` with the DH entries ``lengths`` (``[("a" | "d", row), ...]``) set to ``values``."""
    assert robot.a is not None and robot.d is not None  # the fitted arms are DH chains
    cols = {"a": robot.a.copy(), "d": robot.d.copy()}
    for (key, row), v in zip(lengths, values, strict=True):
        cols[key][row] = v
    return replace(robot, a=cols["a"], d=cols["d"])


def fit_dh_lengths(robot: Robot, lengths, start, solutions, targets) -> LengthFit:
    """DH lengths that make every joint vector of ``solutions[k]`` reach ``targets[k]``.

    Args:
        robot: The DH arm whose twists (and other entries) stay fixed.
        lengths: ``[("a" or "d", 0-based row), ...]``, the entries to fit.
        start: Start values of those entries.
        solutions: Per target, ``(n_k, dof)`` full joint vectors.
        targets: Per target, the ``(3,)`` position.

    Returns:
        A :class:`LengthFit`.

    Raises:
        ConfigError: ``robot`` has no DH rows, or a row is out of range.
        UnknownNameError: An entry is neither ``"a"`` nor ``"d"``.
    """
    if not robot.is_dh:
        raise ConfigError(f"robot {robot.name!r} has no DH rows to fit")
    lengths = [(choice("DH length", k, ("a", "d")),
                integer("DH row", r, minimum=0, maximum=robot.dof - 1, error=ConfigError))
               for k, r in lengths]
    Q = [np.asarray(s, dtype=float) for s in solutions]
    P = [np.asarray(t, dtype=float) for t in targets]

    def residuals(x):
        arm = with_lengths(robot, lengths, x)
        return np.concatenate([(arm.fk_position(q) - p).ravel() for q, p in zip(Q, P, strict=True)])

    sol = least_squares(residuals, np.asarray(start, dtype=float), xtol=1e-15, ftol=1e-15,
                        gtol=1e-15)
    return LengthFit(values=sol.x, max_residual=float(np.max(np.abs(sol.fun))),
                     robot=with_lengths(robot, lengths, sol.x))


def _solutions(res: Results, spec: dict, robot: Robot) -> dict[str, np.ndarray]:
    locked = res.config["problem"].get("locked_joints_deg")
    key = spec.get("solutions", "paper")
    return {name: full_q(robot, [b[key] for b in rows], locked)
            for name, rows in res.paper.get("branches", {}).items()}


def dh_fit_table(res: Results) -> list[Table]:
    """The fitted lengths beside the catalog arm's, and where the printed solutions land."""
    spec = res.paper.get("dh_fit")
    if not spec:
        return []
    robot = arm(res.robot)
    sols, printed = _solutions(res, spec, robot), spec["targets"]
    fit_names = spec["fit_targets"]
    fit = fit_dh_lengths(robot, spec["lengths"], spec["start"], [sols[n] for n in fit_names],
                         [printed[n] for n in fit_names])
    names = [f"{k}{r + 1}" for k, r in spec["lengths"]]
    catalog = [getattr(robot, k)[r] for k, r in spec["lengths"]]
    rows = [[n, f"{v:.6g}", f"{c:.6g}", fmt(abs(v - c), 2)]
            for n, v, c in zip(names, fit.values, catalog, strict=True)]
    paper_q = spec.get("solutions", "paper") == "paper"
    which = (res.labels[0] if res.labels else "algorithm") if paper_q else "geometric"
    fitted = Table(f"DH lengths fitted to the paper's {which} solutions at {', '.join(fit_names)} "
                   f"({robot.unit})",
                   ["length", "least-squares fit", f"catalog {robot.name}", "|difference|"], rows,
                   [f"largest coordinate residual of the fit: {fit.max_residual:.2g} {robot.unit} "
                    f"({sum(len(sols[n]) for n in fit_names)} solutions; the paper prints them "
                    "to 8 decimals)", f"twists and other rows as in the catalog arm; start "
                    f"{spec['start']}"])
    reach = []
    targets = {t["name"]: t["position"] for t in res.meta["targets"]}
    for name, q in sols.items():
        p = robot.fk_position(q)
        miss = np.linalg.norm(p - np.asarray(printed[name]), axis=1)
        reach.append([name, _point(printed[name]), _point(targets.get(name, [])),
                      _point(p.mean(axis=0)), fmt(float(np.ptp(p, axis=0).max()), 2),
                      fmt(float(miss.max()), 2)])
    landing = Table(f"Where the paper's solutions land on {robot.name} ({robot.unit})",
                    ["target", "printed", "used here", "reached (mean of the solutions)",
                     "spread of the solutions", "largest miss of the printed target"], reach)
    return [fitted, landing]


def _point(p) -> str:
    return "(" + ", ".join(f"{v:.6g}" for v in p) + ")"


FUNCTIONS = {"dh-fit": dh_fit_table}
"""Analysis name -> table function, merged into those of :mod:`moik.experiments.analysis`."""
