"""Classical inertia-weight PSO (moik.algorithms.soo.pso): Eq. 1, the clamp, the I-BES preset."""

import numpy as np

from moik.algorithms import PSO
from moik.algorithms.soo.pso import clamp_velocity, pso_velocity
from moik.testing import ScriptedRng


def test_pso_velocity_eq1_and_clamp():
    rng = ScriptedRng([[0.5]], [[0.25]])
    V = pso_velocity(np.array([[1.0]]), np.array([[0.0]]), np.array([[2.0]]), np.array([3.0]),
                     w=0.5, c1=1.0, c2=2.0, rng=rng)
    np.testing.assert_allclose(V, [[0.5 + 1.0 * 0.5 * 2.0 + 2.0 * 0.25 * 3.0]])
    np.testing.assert_array_equal(clamp_velocity(np.array([[3.0, -3.0]]), np.array([2.0, 2.0])),
                                  [[2.0, -2.0]])
    assert clamp_velocity(V, None) is V


def test_pso_ibes_preset():
    p = PSO.ibes(pop_size=20)
    assert (p.w, p.c1, p.c2, p.vmax_rate, p.pop_size) == (0.9, 1.4, 1.4, 0.5, 20)
