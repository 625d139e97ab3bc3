"""Every registered multi-objective algorithm on pymoo's constrained and edge-case problems.

Issue 26: on main at 62ac347 nine moik MO algorithms died in the first generation on
CTP2-CTP5, truss2d and several MW problems (the problems return NaN or inf at points on
the bounds, and the archive refused the row), and MOPSO-CD on MW11. Here each algorithm
runs 5 seeds on each problem and must finish without an exception and never report an
infeasible or non-finite member: every reported ``res.X`` is re-evaluated, its objectives
must be finite and equal to ``res.F``, its constraints satisfied (``G <= 0``,
``|H| <= 1e-4``). A run that finds no feasible point reports none (``res.X`` None), as
pymoo's ``Result`` does.

Problems: CTP1-8, MW1-14, DAS-CMOP1-9 (difficulty 8: (0.5, 0.5, 0.5)), truss2d,
welded_beam, OSY, TNK, BNH, SRN, Carside, C1-DTLZ1, C2-DTLZ2, C3-DTLZ4, DC1-DTLZ1,
DC2-DTLZ3 (three objectives) and the unconstrained edge cases Kursawe, ZDT4 (bounds of
very different widths) and ZDT6. None of them downloads anything (``pareto_front()`` is
never called: some pymoo problems fetch their fronts from the internet).

Size: ``pop_size=20`` and 300 evaluations (the initial population and about 14
iterations: enough for the moves to reach the bounds, where these problems misbehave).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import available, get_algorithm

PROBLEMS = {
    **{f"ctp{i}": {} for i in range(1, 9)},
    **{f"mw{i}": {} for i in range(1, 15)},
    **{f"dascmop{i}": {"args": (8,)} for i in range(1, 10)},  # DAS-CMOP7-9 name it otherwise
    **{name: {} for name in ("truss2d", "welded_beam", "osy", "tnk", "bnh", "srn", "carside",
                             "c1dtlz1", "c2dtlz2", "c3dtlz4", "dc1dtlz1", "dc2dtlz3",
                             "kursawe", "zdt4", "zdt6")},
}
SEEDS = range(5)
PYMOO_SEEDS = {"moead-pymoo": range(1)}
"""pymoo's own MOEA/D (one evaluation at a time: 2 s a case, 40 % of this file with 5 seeds)
runs one seed; moik's algorithms and the other pymoo ones run five."""
BUDGET, POP_SIZE = 300, 20
H_TOLERANCE = 1e-4


def _check_reported(problem, res, where: str) -> None:
    if res.X is None:
        assert res.F is None, where
        return
    X, F = np.atleast_2d(res.X), np.atleast_2d(res.F)
    assert np.isfinite(F).all(), f"{where}: non-finite objectives reported"
    with np.errstate(all="ignore"):
        out = problem.evaluate(X, return_values_of=["F", "G", "H"], return_as_dictionary=True)
    np.testing.assert_allclose(F, out["F"], rtol=1e-12, atol=0.0, err_msg=where)
    G, H = out.get("G"), out.get("H")
    if G is not None and np.size(G):
        assert np.all(G <= 0.0), f"{where}: infeasible member reported (max G {np.max(G)})"
    if H is not None and np.size(H):
        assert np.all(np.abs(H) <= H_TOLERANCE), f"{where}: infeasible member reported"


@pytest.mark.parametrize("problem_name", sorted(PROBLEMS))
@pytest.mark.parametrize("name", available("multi-objective"))
def test_runs_and_reports_only_feasible_finite_members(name, problem_name):
    problem = get_problem(problem_name, *PROBLEMS[problem_name].get("args", ()))
    for seed in PYMOO_SEEDS.get(name, SEEDS):
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # the problems' own sqrt/log of < 0
            res = minimize(problem, get_algorithm(name, pop_size=POP_SIZE), ("n_eval", BUDGET),
                           seed=seed)
        _check_reported(problem, res, f"{name} on {problem_name}, seed {seed}")
