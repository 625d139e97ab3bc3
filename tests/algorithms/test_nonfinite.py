"""A problem's NaN/inf: infeasible and worst, warned once, never reported (nonfinite.py)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import available, get_algorithm
from moik.algorithms.array_base import ArrayStateAlgorithm
from moik.algorithms.nonfinite import finite_rows, sanitise
from moik.algorithms.registry import entry, is_multi_objective
from moik.exceptions import NonFiniteError, NonFiniteValuesWarning

MOIK = [n for n in available() if issubclass(entry(n).cls, ArrayStateAlgorithm)]
MOIK_MO = [n for n in MOIK if is_multi_objective(n)]
MOIK_SO = [n for n in MOIK if not is_multi_objective(n)]


class HoleSphere(Problem):
    """Sphere that is NaN (objective, or constraint with ``constrained``) where ``x0 > 0.5``."""

    def __init__(self, n_obj: int = 1, constrained: bool = False):
        super().__init__(n_var=3, n_obj=n_obj, n_ieq_constr=int(constrained), xl=-1.0, xu=1.0)

    def _evaluate(self, X, out, *args, **kwargs):
        hole = X[:, 0] > 0.5
        F = np.stack([((X - k) ** 2).sum(axis=1) for k in range(self.n_obj)], axis=1)
        if self.n_ieq_constr:
            out["G"] = np.where(hole, np.nan, -1.0)[:, None]
        else:
            F[hole] = np.nan
        out["F"] = F


@given(arrays(float, (6, 2), elements=st.sampled_from([0.0, 1.5, np.nan, np.inf, -np.inf])),
       arrays(float, 6, elements=st.sampled_from([0.0, 2.0, np.nan, np.inf])))
def test_sanitise_makes_exactly_the_non_finite_rows_worst(F, CV):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NonFiniteValuesWarning)
        F2, CV2, _ = sanitise(np.zeros((6, 1)), F, CV, problem=None, warned=False)
    bad = ~(np.isfinite(F).all(axis=1) & np.isfinite(CV))
    assert np.array_equal(finite_rows(F, CV), ~bad)
    assert np.all(F2[bad] == np.inf) and np.all(CV2[bad] == np.inf)
    assert np.array_equal(F2[~bad], F[~bad]) and np.array_equal(CV2[~bad], CV[~bad])


def test_sanitise_returns_finite_input_itself_without_warning():
    F, CV = np.ones((3, 2)), np.zeros(3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        F2, CV2, warned = sanitise(np.zeros((3, 1)), F, CV, problem=None, warned=False)
    assert F2 is F and CV2 is CV and warned is False


def _run(problem, name, n_eval=600, seed=1):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = minimize(problem, get_algorithm(name), ("n_eval", n_eval), seed=seed)
    ours = [w for w in caught if issubclass(w.category, NonFiniteValuesWarning)]
    return res, ours


@pytest.mark.parametrize("name", MOIK_MO)
@pytest.mark.parametrize("problem", ["ctp2", "truss2d", "mw11"])
def test_mo_algorithm_survives_pymoo_problems_that_return_nan(name, problem):
    res, _ = _run(get_problem(problem), name)
    if res.F is not None:
        assert np.isfinite(res.F).all() and np.isfinite(res.X).all()
        assert np.all(res.CV <= 0)


@pytest.mark.parametrize("name", MOIK_MO)
@pytest.mark.parametrize("constrained", [False, True])
def test_mo_nan_rows_warn_once_and_are_never_archived(name, constrained):
    res, ours = _run(HoleSphere(n_obj=2, constrained=constrained), name)
    assert len(ours) == 1 and "HoleSphere" in str(ours[0].message)
    assert res.F is not None and np.isfinite(res.F).all()
    assert np.all(res.X[:, 0] <= 0.5)


@pytest.mark.parametrize("name", MOIK_SO)
@pytest.mark.parametrize("constrained", [False, True])
def test_so_nan_rows_warn_once_and_are_never_reported(name, constrained):
    res, ours = _run(HoleSphere(constrained=constrained), name)
    assert len(ours) == 1
    assert res.X is not None and res.X[0] <= 0.5 and np.isfinite(res.F).all()


class AllNaN(Problem):
    def __init__(self, n_obj):
        super().__init__(n_var=2, n_obj=n_obj, xl=0.0, xu=1.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = np.full((len(X), self.n_obj), np.nan)


def test_so_all_nan_reports_no_solution():
    res, ours = _run(AllNaN(1), "pso", n_eval=300)
    assert res.X is None and res.F is None and len(ours) == 1


def test_mo_all_nan_initial_population_is_a_clear_error():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NonFiniteValuesWarning)
        with pytest.raises(NonFiniteError, match="AllNaN returned NaN or infinite values at every"):
            minimize(AllNaN(2), get_algorithm("mosma"), ("n_eval", 300), seed=1)
