"""Manta ray foraging (moik.algorithms.soo.mrfo): Eqs. 1-8 on hand-computed arrays, runs."""

import math

import numpy as np
import pytest

from moik.algorithms import MRFO, get_algorithm
from moik.algorithms.soo.mrfo import chain_and_cyclone, somersault
from moik.exceptions import ParameterError
from moik.testing import ScriptedRng


def test_mrfo_chain_cyclone_and_somersault_eqs_1_to_8():
    X, best = np.array([[1.0], [2.0]]), np.array([0.0])
    r = [[0.5], [0.5]]
    e = math.exp(-1.0)  # alpha = 2 * 0.5 * sqrt(|log e^-1|) = 1
    rng = ScriptedRng([0.9, 0.1], r, [[0.5], [0.5]], [[e], [e]], [0.25, 0.25], [0.1, 0.9],
                      [[0.8], [0.8]])  # cyclone?, r, alpha draws, r1, explore?, x_rand = 3
    out = chain_and_cyclone(X, best, 1, 2, xl=np.array([-5.0]), xu=np.array([5.0]), rng=rng)
    chain = 1.0 + 0.5 * (0 - 1) + 1.0 * (0 - 1)  # Eq. 1, ray 1 follows x_best
    beta = 2.0 * math.exp(0.25 * (2 - 1 + 1) / 2) * math.sin(2 * math.pi * 0.25)  # Eq. 5
    cyclone = 3.0 + 0.5 * (1.0 - 2.0) + beta * (3.0 - 2.0)  # Eq. 7 (explores: 0.9 > t/T)
    np.testing.assert_allclose(out, [[chain], [cyclone]])
    rng = ScriptedRng([0.5, 1.0], [0.25, 0.0])
    out = somersault(X, np.array([4.0]), 2.0, rng=rng)
    np.testing.assert_allclose(out, [[1.0 + 2 * (0.5 * 4 - 0.25 * 1)], [2.0 + 2 * 4.0]])


def test_deterministic_in_bounds_and_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("mrfo", pop_size=20),
                                    sphere(n_var=7, bound=10.0), n_eval=1037, seed=11,
                                    bound=10.0, other_seed=12)


def test_evaluations_per_iteration_as_documented(check, sphere):
    n_eval = check.n_eval_after(lambda: MRFO(pop_size=10), sphere(n_var=5), ("n_gen", 4))
    assert n_eval == 10 + 3 * 10 * 2


def test_sphere_10d_below_1e_6_within_30000_evaluations(check):
    check.solves_sphere(lambda: get_algorithm("mrfo", pop_size=30), level=1e-6)


def test_constrained_feasibility_first(check):
    check.feasibility_first(lambda: get_algorithm("mrfo", pop_size=20))


def test_runs_on_position_ik(check, ik):
    check.improves_on_position_ik(lambda: get_algorithm("mrfo", pop_size=30), ik.Q_GENERAL,
                                  ("n_eval", 3000), level=5.0)


def test_bad_parameters_raise():
    with pytest.raises(ParameterError, match=r"S must be a number in \(0.0, 10.0\]"):
        MRFO(S=-1)
