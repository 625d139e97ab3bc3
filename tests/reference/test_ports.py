"""Smoke test of the reference-code ports (``reference/``): each runs two iterations on
ZDT1 and returns a finite, non-empty archive inside the bounds with an honest count."""

from __future__ import annotations

import numpy as np
import pytest
from pymoo.problems import get_problem

from reference import REFERENCES, SINGLE_REFERENCES


@pytest.mark.parametrize("name", sorted(REFERENCES))
def test_port_runs_two_iterations(name):
    problem = get_problem("zdt1", n_var=6)
    # CSA.m evaluates every new position, those outside the box too (mo_csa_reference),
    # where ZDT1's square root is NaN; only the returned points are checked below
    with np.errstate(invalid="ignore"):
        X, F, n_eval = REFERENCES[name](problem, 10, 2, np.random.default_rng(0))
    X, F = np.atleast_2d(X), np.atleast_2d(F)
    assert len(X) >= 1 and X.shape[1] == 6 and F.shape == (len(X), 2)
    assert np.isfinite(F).all()
    assert (problem.xl - 1e-12 <= X).all() and (problem.xu + 1e-12 >= X).all()
    np.testing.assert_allclose(F, problem.evaluate(X), rtol=1e-12, atol=1e-12)
    assert n_eval >= 10


@pytest.mark.parametrize("name", sorted(SINGLE_REFERENCES))
def test_single_objective_port_runs_two_iterations(name):
    problem = get_problem("sphere", n_var=4)
    X, F, n_eval = SINGLE_REFERENCES[name](problem, 10, 2, np.random.default_rng(0))
    assert X.shape == (1, 4) and F.shape == (1, 1) and n_eval == 20
    assert (problem.xl <= X).all() and (problem.xu >= X).all()
    np.testing.assert_allclose(F, problem.evaluate(X), rtol=1e-12)
