"""The move around the best solution (moik.algorithms.moo.around_best) by hand."""

import numpy as np

from moik.algorithms.moo.around_best import around_best
from moik.testing import ScriptedRng


def test_around_best_keeps_the_printed_plus_lower_bound():
    best, xl, xu = np.array([1.0]), np.array([-1.0]), np.array([1.0])
    rng = ScriptedRng([[0.5], [0.25]], [[0.2], [0.7]])  # r, then the sign draw
    out = around_best(best, 0.5, xl, xu, (2, 1), rng=rng)
    # step = 0.5 ((1 - -1) r + -1): 0 for r = 0.5; -0.25 for r = 0.25, subtracted (0.7 >= 0.5)
    np.testing.assert_allclose(out, [[1.0], [1.25]])
