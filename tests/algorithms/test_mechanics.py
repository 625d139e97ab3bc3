"""Hand-computed checks of the shared mechanics (moik.algorithms.mechanics)."""

import numpy as np
import pytest

from moik.algorithms.mechanics import (
    best_index,
    clip_to_bounds,
    constraint_violation,
    greedy_memory,
    is_better,
    mantegna_levy,
    mantegna_sigma,
    midpoint_repair,
    ranking_fitness,
    stable_order,
    uniform_population,
)
from moik.testing import ScriptedRng

XL, XU = np.array([0.0, -1.0]), np.array([1.0, 1.0])


def test_midpoint_repair_eq17():
    X_old = np.array([[0.5, 0.0], [0.2, 0.4]])
    X_new = np.array([[1.5, -3.0], [0.3, 0.9]])
    out = midpoint_repair(X_new, X_old, XL, XU)
    # (0.5 + 1)/2 = 0.75 above; (0 + -1)/2 = -0.5 below; the second row is inside
    np.testing.assert_array_equal(out, [[0.75, -0.5], [0.3, 0.9]])
    assert midpoint_repair(X_old, X_new, XL, XU) is X_old  # nothing out: unchanged


def test_clip_and_uniform_population_stay_in_bounds():
    np.testing.assert_array_equal(clip_to_bounds(np.array([[2.0, -2.0]]), XL, XU), [[1.0, -1.0]])
    X = uniform_population(50, XL, XU, rng=np.random.default_rng(0))
    assert X.shape == (50, 2) and np.all((X >= XL) & (X <= XU))


def test_greedy_memory_eq18_keeps_strictly_better():
    PX, PF = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]), np.array([1.0, 1.0, 1.0])
    X, F = np.array([[9.0, 9.0], [8.0, 8.0], [7.0, 7.0]]), np.array([0.5, 1.0, 2.0])
    MX, MF, MCV = greedy_memory(X, F, None, PX, PF, None)
    np.testing.assert_array_equal(MX, [[9.0, 9.0], [1.0, 1.0], [2.0, 2.0]])  # tie keeps old
    np.testing.assert_array_equal(MF, [0.5, 1.0, 1.0])
    assert MCV is None
    assert PF[0] == 1.0  # pure: the inputs are untouched


def test_feasibility_first_comparisons():
    F, CV = np.array([0.0, 5.0, 3.0, 1.0]), np.array([2.0, 0.0, 0.0, 0.5])
    assert best_index(F, CV) == 2  # best feasible, although row 0 has lower f
    assert best_index(F, None) == 0
    assert best_index(F, np.array([2.0, 1.0, 3.0, 0.5])) == 3  # none feasible: least CV
    np.testing.assert_array_equal(is_better(F, CV, 4.0, 0.0), [False, False, True, False])
    # ranking: feasible keep f, infeasible get worst feasible f (5) + CV
    np.testing.assert_array_equal(ranking_fitness(F, CV), [7.0, 5.0, 3.0, 5.5])


def test_constraint_violation_matches_pymoo_default():
    G = np.array([[-1.0, 0.5], [0.0, 0.0]])
    H = np.array([[1e-5], [0.1]])
    np.testing.assert_allclose(constraint_violation(G, H), [0.5, 0.1 - 1e-4])
    np.testing.assert_array_equal(constraint_violation(G, None), [0.5, 0.0])


def test_mantegna_sigma_and_levy_step():
    assert mantegna_sigma(1.5) == pytest.approx(0.696574502, rel=1e-8)
    step = mantegna_levy((1, 1), 1.5, rng=ScriptedRng([[1.0]], [[-4.0]]))
    assert step[0, 0] == pytest.approx(mantegna_sigma(1.5) / 4.0 ** (2 / 3))


@pytest.mark.parametrize("seed", range(6))
def test_compiled_mechanics_equal_the_numpy_formulas(seed):
    """Eq. 17, Eq. 18 and the ranking value against their numpy formulas (nan included)."""
    rng = np.random.default_rng(seed)
    n = 15
    X_new, X_old = rng.uniform(-2, 2, (n, 2)), rng.uniform(0, 1, (n, 2))
    X_new[0, 0] = np.nan
    expected = np.where(X_new > XU, (X_old + XU) / 2.0, X_new)
    expected = np.where(X_new < XL, (X_old + XL) / 2.0, expected)
    np.testing.assert_array_equal(midpoint_repair(X_new, X_old, XL, XU), expected)
    F, PF = rng.integers(0, 3, n).astype(float), rng.integers(0, 3, n).astype(float)
    CV, PCV = rng.integers(0, 2, n).astype(float), rng.integers(0, 2, n).astype(float)
    for cv, pcv in ((None, None), (CV, PCV)):
        better = is_better(F, cv, PF, pcv)
        MX, MF, MCV = greedy_memory(X_new, F, cv, X_old, PF, pcv)
        np.testing.assert_array_equal(MX, np.where(better[:, None], X_new, X_old))
        np.testing.assert_array_equal(MF, np.where(better, F, PF))
        assert MCV is None if cv is None else np.array_equal(MCV, np.where(better, cv, pcv))
    F[2] = np.nan
    feas = CV <= 0.0
    expected = np.where(feas, F, (F[feas].max() if feas.any() else 0.0) + CV)
    np.testing.assert_array_equal(ranking_fitness(F, CV), expected)


@pytest.mark.parametrize("seed", range(20))
def test_stable_order_is_numpys_stable_argsort(seed):
    """Ties keep their order, nan sorts last, -0.0 ties with 0.0, any length."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 130))
    S = rng.integers(0, 6, n).astype(float)
    S[rng.random(n) < 0.1] = np.nan
    S[rng.random(n) < 0.05] = -np.inf
    S[rng.random(n) < 0.05] = -0.0
    order = stable_order(S, np.empty(n, dtype=np.int64))
    np.testing.assert_array_equal(order, np.argsort(S, kind="stable"))
