"""Analytic Pareto fronts of pymoo's multi-objective benchmark problems, never downloaded.

pymoo's ``pareto_front()`` downloads some fronts at run time (DTLZ7's with
three objectives, the WFG ones, and the constrained OSY and TNK, through
``Remote``); nothing here touches the network. The fronts (:func:`analytic_front`):

- ZDT1-4, ZDT6: :data:`ZDT_FRONT_POINTS` points of pymoo's closed-form front;
- DTLZ1-4: pymoo's closed-form front at Das-Dennis reference directions
  (:data:`DTLZ_PARTITIONS` partitions per objective count: 496 points with three
  objectives);
- BNH (Binh & Korn 1997) and SRN (Srinivas & Deb 1994): pymoo's closed-form
  Pareto sets, :data:`CONSTRAINED_FRONT_POINTS` points;
- OSY (Osyczka & Kundu 1995): the five Pareto-optimal segments of Deb,
  "Multi-Objective Optimization Using Evolutionary Algorithms" (Wiley 2001),
  Section 14.1 (x4 = x6 = 0; x1 = 5, x2 = 1, x3 in [1, 5] with x5 = 5 and with
  x5 = 1; x1 in [4.056, 5], x2 = (x1 - 2) / 3, x3 = x5 = 1; x1 = 0, x2 = 2,
  x3 in [1, 3.732], x5 = 1; x1 in [0, 1], x2 = 2 - x1, x3 = x5 = 1), each
  sampled at :data:`CONSTRAINED_FRONT_POINTS` points, evaluated by pymoo's OSY
  and non-dominated filtered (f1 from -274 to -42, f2 from 76 to 4);
- MW1-MW3 (Ma & Wang 2019, DOI 10.1109/TEVC.2019.2896967): pymoo's closed-form fronts
  (the line ``f2 = 1 - 0.85 f1`` or ``1 - f1`` cut or pushed by the constraint), at
  :data:`CONSTRAINED_FRONT_POINTS` values of ``f1`` in [0, 1];
- TNK (Tanaka et al. 1995): ``f = x``, so the front is the non-dominated part
  of the first constraint's boundary ``x1^2 + x2^2 = 1 + 0.1 cos(16 atan(x1 /
  x2))`` inside the second constraint: the boundary in polar form,
  ``r(phi)^2 = 1 + 0.1 cos(16 phi)``, ``x = r (sin phi, cos phi)``, at
  :data:`TNK_ANGLES` angles in (0, pi/2], the feasible points non-dominated filtered.

The hypervolume reference point (:func:`hv_reference`) is the front's nadir
plus a tenth of its magnitude per objective: 1.1 x the nadir where it is
positive (every ZDT and DTLZ front), and still beyond the nadir where it is
negative (OSY's f1, SRN's f2).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from pymoo.core.problem import Problem
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting
from pymoo.util.ref_dirs import get_reference_directions

from moik.problems import available as ik_problems

ZDT_FRONT_POINTS = 1000
"""Points of a ZDT front (pymoo's ``pareto_front(n)``)."""

DTLZ_PARTITIONS = {2: 999, 3: 30}
"""Das-Dennis partitions of the DTLZ fronts per objective count (1000 and 496 points)."""

CONSTRAINED_FRONT_POINTS = 1000
"""Points of the BNH and SRN fronts, and per segment of the OSY front."""

TNK_ANGLES = 20_000
"""Angles sampled on TNK's constraint boundary (about 12,800 front points remain)."""

HV_MARGIN = 0.1
"""The HV reference point is the nadir plus this share of its magnitude, per objective."""

PYMOO_FRONTS = ("zdt1", "zdt2", "zdt3", "zdt4", "zdt6", "dtlz1", "dtlz2", "dtlz3", "dtlz4",
                "bnh", "srn")
"""Problems whose pymoo ``_calc_pareto_front`` is closed-form."""


def non_dominated(F: np.ndarray) -> np.ndarray:
    """The rows of ``F`` no other row dominates."""
    return F[NonDominatedSorting().do(F, only_non_dominated_front=True)]


def _feasible_front(problem: Problem, X: np.ndarray) -> np.ndarray:
    F, G = problem.evaluate(X, return_values_of=["F", "G"])
    return non_dominated(np.asarray(F, dtype=float)[np.all(np.asarray(G) <= 1e-12, axis=1)])


def mw_front(problem: Problem) -> np.ndarray:
    """MW1-MW3's front: pymoo's closed form at :data:`CONSTRAINED_FRONT_POINTS` values of f1."""
    F = np.zeros((CONSTRAINED_FRONT_POINTS, 2))
    F[:, 0] = np.linspace(0.0, 1.0, CONSTRAINED_FRONT_POINTS)
    return non_dominated(np.asarray(problem.pareto_front(F, use_cache=False), dtype=float))


def osy_front(problem: Problem) -> np.ndarray:
    """OSY's front from Deb's five segments (see the module docstring)."""
    s = np.linspace(0.0, 1.0, CONSTRAINED_FRONT_POINTS)
    one, x1_cd = np.ones_like(s), 4.056 + (5.0 - 4.056) * s
    segments = [(5 * one, one, 1 + 4 * s, 5 * one), (5 * one, one, 1 + 4 * s, one),
                (x1_cd, (x1_cd - 2) / 3, one, one), (0 * one, 2 * one, 1 + 2.732 * s, one),
                (s, 2 - s, one, one)]
    X = np.zeros((len(segments) * len(s), 6))
    for k, (x1, x2, x3, x5) in enumerate(segments):
        rows = slice(k * len(s), (k + 1) * len(s))
        X[rows, 0], X[rows, 1], X[rows, 2], X[rows, 4] = x1, x2, x3, x5
    return _feasible_front(problem, X)


def tnk_front(problem: Problem) -> np.ndarray:
    """TNK's front on its first constraint's boundary (see the module docstring)."""
    phi = np.linspace(np.pi / 2 / TNK_ANGLES, np.pi / 2, TNK_ANGLES)
    r = np.sqrt(1.0 + 0.1 * np.cos(16.0 * phi))
    return _feasible_front(problem, np.column_stack([r * np.sin(phi), r * np.cos(phi)]))


OWN_FRONTS: dict[str, Callable[[Problem], np.ndarray]] = {
    "osy": osy_front, "tnk": tnk_front, "mw1": mw_front, "mw2": mw_front, "mw3": mw_front}
"""Problems whose front is built here (pymoo downloads theirs, or gives 100 points)."""

IK_FRONTS = tuple(n for n in ik_problems() if not n.endswith("-motion"))
"""The bi-objective IK problems of :mod:`moik.problems.registry`: their fronts are the
reference fronts of :mod:`moik.fronts` (local solutions to 1e-9, shipped with moik), not
closed forms. A reachable pose's front is the one point (0, 0), whose HV reference point
(:func:`hv_reference`) is (0, 0) too: use the unreachable ones for HV."""

ANALYTIC_FRONTS = PYMOO_FRONTS + tuple(OWN_FRONTS) + IK_FRONTS
"""Every problem with a known front."""

CONSTRAINED = ("bnh", "osy", "srn", "tnk", "mw1", "mw2", "mw3")
"""The constrained problems among :data:`ANALYTIC_FRONTS`."""


def analytic_front(problem: Problem, name: str) -> np.ndarray:
    """The closed-form Pareto front of the problem ``name`` (see the module docstring)."""
    if name in OWN_FRONTS:
        return OWN_FRONTS[name](problem)
    if name in IK_FRONTS:
        return np.asarray(problem.pareto_front(), dtype=float)
    if name.startswith("dtlz"):
        dirs = get_reference_directions("das-dennis", problem.n_obj,
                                        n_partitions=DTLZ_PARTITIONS[problem.n_obj])
        return np.asarray(problem.pareto_front(dirs), dtype=float)
    if name in CONSTRAINED:
        return non_dominated(np.asarray(problem.pareto_front(n_points=CONSTRAINED_FRONT_POINTS),
                                        dtype=float))
    return np.asarray(problem.pareto_front(ZDT_FRONT_POINTS), dtype=float)


def hv_reference(front: np.ndarray) -> np.ndarray:
    """The HV reference point: the front's nadir + :data:`HV_MARGIN` x its magnitude."""
    nadir = np.max(front, axis=0)
    return nadir + HV_MARGIN * np.abs(nadir)
