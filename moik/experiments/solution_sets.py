"""Local dimension of the position-IK solution set at solved configurations (I-BES Table 8).

Where the position Jacobian ``J_p(q)`` (3 x dof) has rank r at a solution q,
the solutions near q form a manifold of dimension ``dof - r`` (the nullity).
Joints whose column of ``J_p`` is zero at every configuration (a wrist roll
about the axis through the end point) add trivial directions that do not
change the position at all; the remaining ``moving - r`` directions make
the solution set a continuum through the joints that matter (0: isolated
solutions). The ``solution-rank`` analysis prints this per target (arm) of an
experiment, from the configurations its runs solved (error below
``success_threshold``), beside the median error of every algorithm.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from moik.experiments.kinds.ik_robot import experiment_robot
from moik.experiments.tables import Results, Table, fmt
from moik.kinematics.jacobian import jacobian
from moik.robots import Robot

RANK_RTOL = 1e-9
"""Singular values below this fraction of the largest count as zero."""


@dataclass(frozen=True)
class SolutionRank:
    """Position-Jacobian rank at a set of configurations.

    Attributes:
        dof: Number of joints.
        ranks: Rank of ``J_p`` at each configuration.
        static: Joints whose ``J_p`` column is zero at every configuration.
        smallest: Smallest nonzero singular value over the configurations.
    """

    dof: int
    ranks: np.ndarray
    static: tuple[int, ...]
    smallest: float

    @property
    def nullity(self) -> np.ndarray:
        """``dof - rank`` at each configuration (local dimension of the solution set)."""
        return self.dof - self.ranks

    @property
    def continuum(self) -> np.ndarray:
        """Local dimension in the joints that move the end point (``moving - rank``)."""
        return self.dof - len(self.static) - self.ranks


def position_rank(robot: Robot, Q, *, rtol: float = RANK_RTOL) -> SolutionRank:
    """Rank of the position Jacobian of ``robot`` at every row of ``Q``."""
    J = jacobian(robot, np.atleast_2d(np.asarray(Q, dtype=float)))[:, :3, :]
    s = np.linalg.svd(J, compute_uv=False)
    tol = rtol * s[:, :1]
    ranks = np.sum(s > tol, axis=1)
    cols = np.linalg.norm(J, axis=1)
    static = tuple(int(j) for j in np.flatnonzero(np.all(cols <= rtol * cols.max(axis=1,
                                                                                 keepdims=True),
                                                         axis=0)))
    smallest = float(np.min(np.where(s > tol, s, np.inf)))
    return SolutionRank(dof=robot.dof, ranks=ranks, static=static, smallest=smallest)


def _span(v: np.ndarray) -> str:
    lo, hi = int(v.min()), int(v.max())
    return str(lo) if lo == hi else f"{lo}-{hi}"


def _median(res: Results, label: str, ti: int) -> str:
    f = [r["best_f"] for r in res.by_label[label] if r["target"] == ti
         and r.get("best_f") is not None]
    return fmt(float(np.median(f)), 2) if f else "-"


def solution_rank_table(res: Results) -> list[Table]:
    """Rank, nullity and continuum dimension at the solved configurations, per target."""
    thr = res.config.get("success_threshold", 1e-6)
    problem = res.config["problem"]
    rows = []
    for ti, target in enumerate(res.meta["targets"]):
        robot = experiment_robot(target.get("robot") or res.robot, problem)
        recs = [r for lab in res.labels for r in res.by_label[lab] if r["target"] == ti]
        solved = [r["best_x"] for r in recs if r.get("best_f") is not None and r["best_f"] < thr
                  and r.get("best_x") is not None]
        medians = [f"{lab} {_median(res, lab, ti)}" for lab in res.labels]
        if not solved:
            rows.append([target["name"], str(robot.dof), "0", "-", "-", "-", "-", "-",
                         "; ".join(medians)])
            continue
        sr = position_rank(robot, np.array(solved))
        dim = sr.continuum
        kind = "isolated" if dim.max() == 0 else f"{_span(dim)}-D continuum"
        rows.append([target["name"], str(robot.dof), str(len(solved)),
                     ", ".join(robot.joint_names[j] for j in sr.static) or "none",
                     _span(sr.ranks), _span(sr.nullity), kind, fmt(sr.smallest, 3),
                     "; ".join(medians)])
    notes = [f"configurations: every run of every algorithm with error < {thr:g}; rank by SVD "
             f"(singular values below {RANK_RTOL:g} x the largest count as zero)",
             "static joints: zero position-Jacobian column at every configuration (they do "
             "not move the end point); continuum = joints that move it - rank"]
    header = ["target", "dof", "solved configurations", "static joints", "rank of J_p",
              "nullity (dof - rank)", "solution set near the solutions",
              "smallest nonzero singular value", "median error per algorithm"]
    return [Table("Position-Jacobian rank at the solved configurations", header, rows, notes)]


FUNCTIONS = {"solution-rank": solution_rank_table}
"""Analysis name -> table function, merged into those of :mod:`moik.experiments.analysis`."""
