"""HHO, IGWO, PSOGSA, CODE, MTDE and SASS: kernels on hand-computed arrays and runs.

Every algorithm reaches < 1e-6 on the 10-D sphere ([-100, 100]^10) within
30,000 evaluations with its Table 3 defaults (measured: HHO ~1e-96, IGWO ~1e-48,
PSOGSA ~1e-23, CODE ~1e-38, MTDE ~1e-16, SASS ~1e-26).
"""

import math

import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize

from moik.algorithms import CODE, HHO, IGWO, MTDE, PSOGSA, SASS, get_algorithm
from moik.algorithms.soo.code import centroid_opposite, de_rand_1_bin, distinct_indices
from moik.algorithms.soo.hho import hho_moves, levy_flight
from moik.algorithms.soo.igwo import dimension_learning, gwo_move
from moik.algorithms.soo.mtde import (
    lehmer_mean,
    mtde_schedules,
    split_population,
    transformation_matrix,
)
from moik.algorithms.soo.psogsa import gsa_acceleration, gsa_masses, psogsa_velocity
from moik.algorithms.soo.sass import pair_rotation, planned_size, spherical_step
from moik.exceptions import ParameterError
from moik.problems import PositionIK
from moik.robots import get_robot
from moik.testing import ScriptedRng

CLASSES = [HHO, IGWO, PSOGSA, CODE, MTDE, SASS]


class Sphere(Problem):
    def __init__(self, n_var=10, bound=100.0):
        super().__init__(n_var=n_var, n_obj=1, xl=-bound, xu=bound)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = (X * X).sum(axis=1)


def test_levy_flight_eq9():
    beta = 1.5
    sigma = (math.gamma(2.5) * math.sin(0.75 * math.pi)
             / (math.gamma(1.25) * 1.5 * 2**0.25)) ** (1 / 1.5)
    out = levy_flight((1, 2), beta, rng=ScriptedRng([[1.0, -2.0]], [[1.0, 0.25]]))
    np.testing.assert_allclose(out, [[0.01 * sigma, -0.02 * sigma / 0.25 ** (2 / 3)]])


def test_hho_moves_hard_besiege_soft_dive_and_exploration():
    X = np.array([[1.0], [2.0], [3.0]])
    rabbit = np.array([0.0])
    E = np.array([0.25, 0.75, 1.5])  # hard besiege, soft dive, exploration
    r = np.array([0.9, 0.1, 0.9])
    rng = ScriptedRng([0.2, 0.2, 0.7], np.full((3, 1), 0.5), np.full((3, 1), 0.5),  # q, r1, r2
                      np.full((3, 1), 0.5), np.full((3, 1), 0.5),  # r3, r4
                      [0, 0, 0], np.full((3, 1), 0.5))  # X_rand = X[0]; J = 1
    Y, dive = hho_moves(X, rabbit, E, r, xl=np.array([-4.0]), xu=np.array([4.0]), rng=rng)
    # hard (Eq. 6): 0 - 0.25 |0 - 1|; soft dive (Eq. 7): 0 - 0.75 |0 - 2|;
    # exploration, q >= 0.5 (Eq. 1): X_rand - r1 |X_rand - 2 r2 X| = 1 - 0.5 |1 - 3|
    np.testing.assert_allclose(Y, [[-0.25], [-1.5], [0.0]])
    np.testing.assert_array_equal(dive, [False, True, False])


def test_gwo_move_mean_of_leaders():
    X, leaders = np.array([[0.0]]), [np.array([1.0]), np.array([2.0]), np.array([3.0])]
    half = np.full((1, 1), 0.5)  # A = 2 a 0.5 - a = 0, C = 1
    out = gwo_move(X, leaders, 1.0, rng=ScriptedRng(*[half] * 6))
    np.testing.assert_allclose(out, [[2.0]])


def test_dimension_learning_eqs_10_12():
    X = np.array([[0.0, 0.0], [1.0, 0.0], [5.0, 5.0]])
    X_gwo = np.array([[1.5, 0.0], [1.0, 0.1], [5.0, 5.0]])
    # wolf 0: radius 1.5 -> neighbours {0, 1}; wolf 1: radius 0.1 -> {1}; wolf 2: radius 0 -> {2}
    rng = ScriptedRng([[0.9, 0.1], [0.0, 0.0], [0.0, 0.0]], [2, 0, 1], np.full((3, 2), 0.5))
    out = dimension_learning(X, X_gwo, rng=rng)
    # wolf 0, d0: neighbour 1 (x=1), X_r = wolf 2 (5): 0 + 0.5 (1 - 5) = -2
    # wolf 0, d1: neighbour 0 (0), X_r = wolf 2 (5): 0 + 0.5 (0 - 5) = -2.5
    np.testing.assert_allclose(out[0], [-2.0, -2.5])
    np.testing.assert_allclose(out[1], [1.0 + 0.5 * (1.0 - 0.0), 0.0])
    np.testing.assert_allclose(out[2], [5.0 + 0.5 * (5.0 - 1.0), 5.0 + 0.5 * 5.0])


def test_gsa_masses_acceleration_and_velocity():
    np.testing.assert_allclose(gsa_masses(np.array([1.0, 3.0])), [1.0, 0.0])
    np.testing.assert_allclose(gsa_masses(np.array([2.0, 2.0])), [0.5, 0.5])
    X, M = np.array([[0.0], [2.0]]), np.array([0.5, 0.5])
    acc = gsa_acceleration(X, M, 1.0, rng=ScriptedRng(np.full((2, 2), 0.5)))
    # F_01 = 0.5 G M0 M1 (2 - 0) / 2 = 0.125; a0 = F / M0 = 0.25, a1 = -0.25
    np.testing.assert_allclose(acc, [[0.25], [-0.25]], rtol=1e-12)
    V = psogsa_velocity(np.array([[1.0]]), np.array([[0.0]]), np.array([[2.0]]), np.array([4.0]),
                        w=0.5, c1=0.5, c2=1.5, rng=ScriptedRng([[0.5]], [[0.25]]))
    np.testing.assert_allclose(V, [[0.5 + 0.5 * 0.5 * 2.0 + 1.5 * 0.25 * 4.0]])


def test_centroid_opposite_and_resampling():
    X = np.array([[0.0], [2.0], [10.0]])  # M = 4: opposites 8, 6, -2
    out = centroid_opposite(X, np.array([0.0]), np.array([7.0]), rng=ScriptedRng(
        np.full((3, 1), 0.5)))
    # 8 > b = 7 -> 4 + 0.5 (7 - 4); -2 < a = 0 -> 0 + 0.5 (4 - 0)
    np.testing.assert_allclose(out, [[5.5], [6.0], [2.0]])


def test_distinct_indices_and_de_rand_1_bin():
    rng = np.random.default_rng(0)
    r = distinct_indices(6, 3, rng=rng)
    assert np.all(r != np.arange(6)) and np.all(r[0] != r[1]) and np.all(r[2] != r[1])
    X = np.arange(8.0).reshape(4, 2)
    U = de_rand_1_bin(X, F=0.5, Cr=1.0, xl=np.full(2, -100.0), xu=np.full(2, 100.0),
                      rng=np.random.default_rng(1))
    assert U.shape == X.shape and np.all(np.abs(U) <= 100.0)


def test_mtde_schedules_split_matrix_lehmer():
    assert mtde_schedules(0, 100, 0.001, 2.0, 1.0) == (2.0, 2.0)
    ca1, ca2 = mtde_schedules(50, 100, 0.001, 2.0, 2.0)  # Eqs. 9, 11
    assert ca1 == 1.0 and ca2 == pytest.approx(0.001 - (0.001 - 2.0) * 0.25)
    groups = split_population(10, 2, rng=np.random.default_rng(0))
    assert [len(g) for g in groups] == [2, 2, 6]
    assert sorted(np.concatenate(groups)) == list(range(10))
    M = transformation_matrix(7, 3, rng=np.random.default_rng(0))
    assert sorted(M.sum(axis=1)) == [1, 1, 1, 2, 2, 3, 3]
    assert lehmer_mean(np.array([0.5, 1.0]), np.array([1.0, 1.0])) == pytest.approx(1.25 / 1.5)


def test_sass_kernels():
    A = pair_rotation(5, 1e-12, rng=np.random.default_rng(0))
    np.testing.assert_allclose(A @ A.T, np.eye(5), atol=1e-12)
    Z = np.array([[1.0, 2.0], [3.0, 4.0]])
    rng = ScriptedRng(np.full((2, 2), 0.9), [1, 0])  # rd = 0: only the forced coordinate
    step = spherical_step(Z, np.eye(2), np.array([0.5, 1.0]), np.zeros(2), rng=rng)
    np.testing.assert_allclose(step, [[0.0, 1.0], [3.0, 0.0]])
    assert planned_size(0, 1000, 126) == 126 and planned_size(1000, 1000, 126) == 4
    assert planned_size(500, 1000, 126) == 65


@pytest.mark.parametrize("cls", CLASSES)
def test_deterministic_in_bounds_and_budget(cls):
    problem = Sphere(n_var=5, bound=10.0)
    runs = [minimize(problem, cls(pop_size=20), ("n_eval", 1037), seed=4) for _ in range(2)]
    np.testing.assert_array_equal(runs[0].X, runs[1].X)
    np.testing.assert_array_equal(runs[0].F, runs[1].F)
    assert runs[0].algorithm.evaluator.n_eval == 1037
    X = runs[0].pop.get("X")
    assert np.all(np.abs(X) <= 10.0) and np.all(np.abs(runs[0].X) <= 10.0)
    other = minimize(problem, cls(pop_size=20), ("n_eval", 1037), seed=5)
    assert not np.array_equal(other.X, runs[0].X)


@pytest.mark.parametrize("cls", CLASSES)
def test_sphere_10d_below_1e_6_within_30k_evaluations(cls):
    res = minimize(Sphere(), cls(), ("n_eval", 30_000), seed=1)
    assert res.algorithm.evaluator.n_eval == 30_000 and res.F[0] < 1e-6


@pytest.mark.parametrize("name", ["hho", "igwo", "psogsa", "code", "mtde", "sass"])
def test_runs_on_position_ik(name):
    """200 iterations, N=50 (SASS: 18 D). Most runs end below 1 cm; PSOGSA and HHO
    occasionally stagnate at 5-13 cm (seen for 2 of 6 seeds), hence the loose bound."""
    robot = get_robot("eosma7")
    q = np.deg2rad([45.0, 0.0, 45.0, 0.0, 45.0, 0.0, 0.0])
    problem = PositionIK(robot, robot.fk(q[None])[0][:3, 3])
    res = minimize(problem, get_algorithm(name), ("n_gen", 200), seed=2)
    conv = res.algorithm.convergence
    assert np.isfinite(res.F[0]) and res.F[0] < conv[0] and res.F[0] < 20.0  # cm
    xl, xu = problem.bounds()
    x = res.X
    assert np.all((xl <= x) & (x <= xu))


def test_evaluations_per_iteration():
    def n_eval(algo, n_gen=4):
        return minimize(Sphere(), algo, ("n_gen", n_gen), seed=0).algorithm.evaluator.n_eval

    assert n_eval(IGWO(pop_size=10)) == 10 + 3 * 20
    assert n_eval(PSOGSA(pop_size=10)) == n_eval(MTDE(pop_size=10)) == 40
    assert 40 <= n_eval(HHO(pop_size=10)) <= 70
    assert n_eval(CODE(pop_size=10, Jr=0.0)) == 40  # 10 initial + 10 opposite + 2 x 10
    assert n_eval(CODE(pop_size=10, Jr=1.0)) == 10 + 10 + 2 * 20


def test_sass_population_shrinks_to_four():
    algo = SASS()
    res = minimize(Sphere(n_var=3), algo, ("n_eval", 3000), seed=0)
    assert res.algorithm.pop_size == 54 and len(res.algorithm.X) == 4
    assert res.algorithm.evaluator.n_eval == 3000
    algo = minimize(Sphere(n_var=3), SASS(), ("n_gen", 200), seed=0).algorithm
    assert len(algo.convergence) == 200 and len(algo.X) <= 6  # the schedule ends near 4 at T
    assert len(algo.archive_X) <= round(1.4 * len(algo.X))


@pytest.mark.parametrize(("name", "params", "message"), [
    ("hho", {"beta": 0}, r"beta must be a number in \(0.0, 2.0\]"),
    ("psogsa", {"alpha": -1}, r"alpha must be a number in \[0.0, 100.0\]"),
    ("psogsa", {"G0": 0}, r"G0 must be a number in \(0.0, inf\)"),
    ("code", {"Jr": 1.5}, r"Jr must be a number in \[0.0, 1.0\]"),
    ("code", {"pop_size": 3}, r"pop_size must be an integer >= 4"),
    ("mtde", {"WinIter": 0}, r"WinIter must be an integer >= 1"),
    ("mtde", {"pr": 0}, r"pr must be a number in \(0.0, 1.0\]"),
    ("sass", {"Ms": 0}, r"Ms must be an integer >= 1"),
    ("sass", {"c": 0}, r"c must be a number in \(0.0, 1.0\]"),
    ("igwo", {"pop_size": 2}, r"pop_size must be an integer >= 3"),
])
def test_bad_values_raise(name, params, message):
    with pytest.raises(ParameterError, match=message):
        get_algorithm(name, **params)
