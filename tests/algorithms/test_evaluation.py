"""The array-state evaluation helpers (moik.algorithms.evaluation)."""

from __future__ import annotations

import numpy as np
from pymoo.constraints.as_penalty import ConstraintsAsPenalty
from pymoo.core.evaluator import Evaluator
from pymoo.problems import get_problem

from moik.algorithms.evaluation import (
    constraint_values,
    evaluator_attached,
    pad,
    problem_values,
    values_asked,
)


def test_pad_gives_unevaluated_rows_inf():
    F, CV = pad(4, np.ones((2, 3)), np.zeros(2))
    assert F.shape == (4, 3) and np.all(F[2:] == np.inf) and np.all(CV[2:] == np.inf)
    F1, CV1 = pad(3, np.ones(3), None)
    assert F1.shape == (3,) and CV1 is None


def test_constraint_values_are_pymoos_default_violation():
    G, H = np.array([[0.5, -1.0]]), np.array([[2e-4]])
    CV, GH = constraint_values(G, H, 1)
    assert CV[0] == 0.5 + (2e-4 - 1e-4) and GH.tolist() == [[0.5, -1.0, 2e-4]]
    CV, GH = constraint_values(G, None, 1)
    assert GH.shape == (1, 2)


def test_what_is_attached_and_what_is_asked():
    plain, wrapped = get_problem("g1"), ConstraintsAsPenalty(get_problem("g1"))
    assert not evaluator_attached(Evaluator(), None, plain)
    assert evaluator_attached(Evaluator(callback=print), None, plain)
    assert evaluator_attached(type("Mine", (Evaluator,), {})(), None, plain)
    assert evaluator_attached(Evaluator(), object(), plain)
    assert values_asked(plain, Evaluator()) is None  # pymoo's default for a plain problem
    assert values_asked(wrapped, Evaluator()) == ["F", "G", "H"]  # a meta-problem's do()
    X = np.full((2, plain.n_var), 0.5)
    out = problem_values(wrapped, X, constrained=False, asked=values_asked(wrapped, Evaluator()))
    assert out["F"].shape == (2, 1)
