"""JAYA (moik.algorithms.soo.jaya): Eq. 1 by hand, runs, benchmarks, the spring design."""

import numpy as np
import pytest

from moik.algorithms import get_algorithm
from moik.algorithms.soo.jaya import jaya_update
from moik.testing import ScriptedRng


def test_jaya_eq1():
    out = jaya_update(np.array([[1.0, -2.0]]), np.zeros(2), np.full(2, 3.0),
                      rng=ScriptedRng([[0.5, 0.5]], [[0.25, 0.25]]))
    np.testing.assert_allclose(out, [[0.0, -3.25]])


def test_jaya_move_is_eq_1_with_generator_draws():
    X = np.array([[-1.0, 2.0], [0.5, -0.5]])
    best, worst = np.array([1.0, 1.0]), np.array([-2.0, 3.0])
    r = np.random.default_rng(4)
    r1, r2 = r.random(X.shape), r.random(X.shape)
    expected = X + r1 * (best - np.abs(X)) - r2 * (worst - np.abs(X))
    np.testing.assert_allclose(jaya_update(X, best, worst, rng=np.random.default_rng(4)),
                               expected)


def test_deterministic_in_bounds_exact_budget(check, sphere):
    check.reproducible_exact_budget(lambda: get_algorithm("jaya", pop_size=12), sphere(n_var=3),
                                    n_eval=600, seed=4, bound=100.0)


def test_sphere_10d_within_30k(check):
    check.solves_sphere(lambda: get_algorithm("jaya", pop_size=30), level=1e-6)


@pytest.mark.parametrize(("bench", "level"), [("F1", 1e-6), ("F9", 60.0)])
def test_classical_benchmarks(check, bench, level):
    """F9 (Rastrigin, 10-D, 15,000 evaluations): JAYA stops in a local basin."""
    check.classical_benchmark(lambda: get_algorithm("jaya", pop_size=30), bench, level=level)


def test_spring_best_design_is_feasible(check):
    check.spring_feasible(lambda: get_algorithm("jaya", pop_size=30), n_eval=9_000)
