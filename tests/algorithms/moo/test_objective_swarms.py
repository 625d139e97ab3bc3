"""One swarm per objective sharing an archive (moik.algorithms.moo.objective_swarms): kernels."""

import numpy as np

from moik.algorithms.moo.objective_swarms import (
    own_objective,
    swarm_best,
    swarm_extreme,
    swarm_partners,
    utopia_closest,
)
from moik.metrics import closest_to_utopia


def test_own_objective_and_swarm_best_on_tiny_arrays():
    F = np.array([[1.0, 9.0], [2.0, 8.0], [3.0, 7.0], [4.0, 6.0]])
    swarm = np.array([0, 0, 1, 1])
    np.testing.assert_array_equal(own_objective(F, swarm), [1.0, 2.0, 7.0, 6.0])
    P = np.arange(8.0).reshape(4, 2)
    g = swarm_best(P, np.array([5.0, 1.0, 3.0, 4.0]), 2)
    np.testing.assert_array_equal(g, [[2.0, 3.0], [2.0, 3.0], [4.0, 5.0], [4.0, 5.0]])


def test_swarm_extremes_and_partners():
    P = np.arange(8.0).reshape(4, 2)
    S = np.array([5.0, 1.0, 3.0, 4.0])
    np.testing.assert_array_equal(swarm_extreme(P, S, 2), [[2, 3], [2, 3], [4, 5], [4, 5]])
    np.testing.assert_array_equal(swarm_extreme(P, S, 2, worst=True),
                                  [[0, 1], [0, 1], [6, 7], [6, 7]])
    j = swarm_partners(3, 4, rng=np.random.default_rng(0))
    np.testing.assert_array_equal(j // 4, np.repeat([0, 1, 2], 4))


def test_utopia_closest_is_the_metrics_rule():
    F = np.array([[0.0, 10.0], [0.4, 2.0], [1.0, 0.0]])  # scaled: (0, 1), (0.4, 0.2), (1, 0)
    assert utopia_closest(F) == 1
    assert utopia_closest(np.array([[1.0, 5.0], [1.0, 3.0]])) == 1  # a constant objective counts 0
    rng = np.random.default_rng(4)
    for _ in range(20):
        F = rng.random((int(rng.integers(1, 30)), int(rng.integers(2, 4))))
        assert utopia_closest(F) == closest_to_utopia(F)
