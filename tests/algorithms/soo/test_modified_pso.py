"""m-PSO (moik.algorithms.soo.modified_pso): the fitness-based switch of Eqs. 3-4 by hand."""

import numpy as np

from moik.algorithms.soo.modified_pso import mpso_velocity
from moik.testing import ScriptedRng


def test_mpso_velocity_eqs_3_4():
    zeros = np.zeros((2, 1))
    rng = ScriptedRng(np.full((2, 1), 0.5), np.full((2, 1), 0.5))
    V = mpso_velocity(zeros, zeros, np.ones((2, 1)), np.array([2.0]), np.array([True, False]),
                      w=0.8, c1=1.0, c2=1.0, rng=rng)
    np.testing.assert_allclose(V, [[0.5 * 1.0 + 0.5 * 2.0], [0.5 * 2.0]])
