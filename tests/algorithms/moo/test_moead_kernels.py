"""MOEA/D's kernels (moik.algorithms.moo.moead_kernels): offspring inside the bounds, the
Tchebycheff replacement rule, the limit nr, non-finite rows, the fused sequential step."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.algorithms.moo.moead_kernels import draw_columns, generation, offspring, update
from tests.algorithms.conftest import IKProblems


@settings(max_examples=30, deadline=None)
@given(st.integers(3, 12), st.integers(1, 6), st.integers(0, 2**32 - 1),
       st.floats(0.0, 1.0))
def test_offspring_stay_in_bounds_and_mix_their_parents(n, d, seed, delta):
    rng = np.random.default_rng(seed)
    xl, xu = -rng.random(d) - 0.5, rng.random(d) + 0.5
    X = xl + rng.random((n, d)) * (xu - xl)
    neighbors = np.argsort(rng.random((n, n)), axis=1)[:, :3].astype(np.int64)
    perm = rng.permutation(n).astype(np.int64)
    U = rng.random((n, draw_columns(d)))
    Y = offspring(X, neighbors, perm, U, xl, xu, np.array([delta, 20.0, 20.0, 0.0]))
    assert Y.shape == (n, d) and np.all(xl <= Y) and np.all(xu >= Y)
    # with no crossover and no mutation each offspring is one of its parents
    U[:, 4::5] = 1.0
    Y = offspring(X, neighbors, perm, U, xl, xu, np.array([1.0, 20.0, 20.0, 0.0]))
    for i, k in enumerate(perm):
        assert any(np.array_equal(Y[i], X[j]) for j in neighbors[k])


def _population():
    W = np.array([[1.0, 0.0], [0.5, 0.5], [0.0, 1.0]])
    F = np.array([[1.0, 5.0], [2.0, 2.0], [5.0, 1.0]])
    return W, F, np.arange(9.0).reshape(3, 3), np.zeros(3)


def test_tchebycheff_replacement_and_reference_point():
    W, F, X, CV = _population()
    neighbors = np.array([[0, 1, 2]] * 3, dtype=np.int64)
    z = np.array([1.0, 1.0])
    Y, FY = np.full((1, 3), 7.0), np.array([[1.5, 1.5]])
    # g = max_k w_k |f_k - z_k|: member 0: 0, member 1: 0.5, member 2: 0 -> offspring 0.25
    # against member 1 only (0.5 |1.5 - 1|); against member 0 it is 0.5 > 0
    n = update(X, F, CV, W, neighbors, np.array([1], dtype=np.int64), Y, FY, np.zeros(1), z,
               3, np.empty((1, 0)))
    assert n == 1 and np.array_equal(F[1], [1.5, 1.5]) and np.array_equal(X[1], [7.0] * 3)
    assert np.array_equal(F[0], [1.0, 5.0]) and np.array_equal(F[2], [5.0, 1.0])
    FY = np.array([[0.5, 0.5]])  # a new best in both objectives moves z first
    n = update(X, F, CV, W, neighbors, np.array([0], dtype=np.int64), Y, FY, np.zeros(1), z,
               1, np.array([[0.9, 0.1, 0.5]]))
    assert np.array_equal(z, [0.5, 0.5]) and n == 1  # nr = 1: only the first visited (1)
    assert np.array_equal(F[1], [0.5, 0.5]) and np.array_equal(F[0], [1.0, 5.0])


def test_infeasible_offspring_replace_only_worse_infeasible_members():
    W, F, X, _ = _population()
    CV = np.array([0.0, 2.0, 1.0])
    neighbors = np.array([[0, 1, 2]] * 3, dtype=np.int64)
    n = update(X, F, CV, W, neighbors, np.array([0], dtype=np.int64), np.zeros((1, 3)),
               np.array([[9.0, 9.0]]), np.array([1.5]), np.array([1.0, 1.0]), 3,
               np.empty((1, 0)))
    assert n == 1 and np.array_equal(CV, [0.0, 1.5, 1.0])


def test_non_finite_offspring_are_skipped_and_non_finite_members_replaced():
    W, F, X, CV = _population()
    F[2] = np.nan
    neighbors = np.array([[0, 1, 2]] * 3, dtype=np.int64)
    z = np.array([1.0, 1.0])
    n = update(X, F, CV, W, neighbors, np.array([0], dtype=np.int64), np.zeros((1, 3)),
               np.array([[np.nan, 0.0]]), np.zeros(1), z, 3, np.empty((1, 0)))
    assert n == 0 and np.array_equal(z, [1.0, 1.0])
    n = update(X, F, CV, W, neighbors, np.array([0], dtype=np.int64), np.zeros((1, 3)),
               np.array([[9.0, 9.0]]), np.zeros(1), z, 3, np.empty((1, 0)))
    assert n == 1 and np.array_equal(F[2], [9.0, 9.0])


@settings(max_examples=10, deadline=None)
@given(st.integers(4, 10), st.integers(0, 2**32 - 1), st.sampled_from([1, 2, 20]),
       st.integers(0, 10))
def test_the_compiled_generation_is_offspring_then_update_one_row_at_a_time(n, seed, nr, short):
    """generation() (the fast path, an IK problem's compiled objectives) does what offspring,
    evaluate and update do for each row in turn, each offspring seeing the population as
    the earlier ones left it (Zhang & Li's loop); ``short`` rows fewer: the budget."""
    problem = IKProblems.biobjective()
    d, k = problem.n_var, max(n - short, 0)
    rng = np.random.default_rng(seed)
    xl, xu = problem.xl.astype(float), problem.xu.astype(float)
    W = rng.random((n, 2))
    neighbors = np.argsort(rng.random((n, n)), axis=1)[:, :3].astype(np.int64)
    perm = rng.permutation(n).astype(np.int64)
    U, keys = rng.random((n, draw_columns(d))), rng.random((n, 3))
    rates = np.array([0.9, 20.0, 20.0, 1.0 / d])
    X0 = xl + rng.random((n, d)) * (xu - xl)
    F0 = problem.evaluate(X0)

    X, F, z = X0.copy(), F0.copy(), F0.min(axis=0)
    replaced = 0
    for i in range(k):
        Y = offspring(X, neighbors, perm[i:i + 1], U[i:i + 1], xl, xu, rates)
        replaced += update(X, F, np.zeros(n), W, neighbors, perm[i:i + 1], Y,
                           problem.evaluate(Y), np.zeros(1), z, nr, keys[i:i + 1])
    X2, F2, z2 = X0.copy(), F0.copy(), F0.min(axis=0)
    Y2, FY2 = np.empty((k, d)), np.empty((k, 2))
    replaced2 = generation(X2, F2, np.zeros(n), W, neighbors, (perm, U, keys), xl, xu, rates,
                           z2, nr, Y2, FY2, problem.compiled_objectives())
    assert replaced == replaced2
    np.testing.assert_array_equal(X, X2)
    np.testing.assert_array_equal(F, F2)
    np.testing.assert_array_equal(z, z2)
    np.testing.assert_array_equal(FY2, problem.evaluate(Y2).reshape(k, 2))
