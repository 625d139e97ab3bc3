"""EOSMA (moik.algorithms.soo.eosma): its kernels, scenarios, and its accuracy on the
EOSMA paper's 7-DOF arm with the paper's protocol.

Yin et al., Sci. Rep. 12, 9421 (2022). Targets are the paper's: FK of joint
vectors drawn uniformly within the Table 1 limits (``random_reachable_targets``),
20 per test. Each target is solved with the paper's re-solve
protocol (``solve_until_success``: re-run with a fresh seed, at most 10 runs).

Units decide scenario 2. Eq. 28 adds a length (Eq. 29) to an angle (Eq. 30,
radians), so the unit of length sets the balance of the two terms. Table 1
prints the lengths in metres (l1 = 0.5 m ...); the catalog's ``eosma7`` uses cm
because the paper's Simulation section and its MOEOSMA targets are in cm. Table
7's figures (mean 7.79e-18, worst 5.55e-17, best 0) can only come from
quantities of order 1: one rounding step of a 50 cm coordinate is already
7e-15. Measured here (seeds as below, 20 targets; single runs on 100 targets):

=====================  ===========  ===================================  =========
scenario 2, N=100,     single run   protocol (threshold 1e-6)            s/target
T=1000                 f < 1e-8     f < 1e-8; mean / worst f
=====================  ===========  ===================================  =========
arm in m (Table 1)     87 of 100    20 of 20; 4.4e-18 / 5.0e-17 (15 = 0)  0.33
arm in cm (catalog)    16 of 60     16 of 20; 9.4e-3 / 9.2e-2            1.65
=====================  ===========  ===================================  =========

So Table 7 is reproduced with the arm in metres (paper: 7.79e-18 / 5.55e-17,
0.36 s) and not in cm, where runs converge on the position and stall on the
orientation (position error ~1e-5 cm, Euler error 0.06-1.4 rad in failed runs). The
target "18 of 20 to < 1e-8" is asserted for the metre arm; the cm figure is asserted
as measured (slow test).

Scenario 1 (position only) does not depend on the unit: EOSMA's operators and
its comparisons are invariant to scaling f. Single runs reach < 1e-10 cm on 93
of 100 targets and < 1e-6 on 100 of 100; the others stall between 1e-10 and
3e-7 cm when the population collapses onto one point (q=0 has no mutation).
The paper reports a worst case of 7.85e-16 (Table 5), which these single runs
do not match; the target "< 1e-10 cm on 20 targets" is therefore reached with
the re-solve protocol at threshold 1e-10 instead of the paper's 1e-6.
"""


import numpy as np
import pytest
from pymoo.core.problem import Problem
from pymoo.optimize import minimize
from scipy.stats import binom

from moik.algorithms import EOSMA
from moik.algorithms.generator_handle import GeneratorHandles
from moik.algorithms.soo.eosma import (
    eosma_update,
    random_difference_mutation,
    update_distinct_pool,
)
from moik.algorithms.soo.eosma_kernels import GenerationDraws, fill_integers, generation_draws
from moik.exceptions import ParameterError
from moik.experiments.protocol import solve_until_success
from moik.problems import PoseIK, PositionIK, random_reachable_targets
from moik.robots import get_robot
from moik.testing import ScriptedRng

N_TARGETS = 20
TARGET_SEED = 2022


def eosma7_metres():
    """The catalog arm with Table 1's lengths as printed, in metres."""
    return get_robot("eosma7-m")


def pose_problem(robot, target):
    return PoseIK(robot, target, weights=(0.5, 0.5), orientation="eosma-euler")


def solve_all(robot, scenario: int, threshold: float, max_failures: int = 10):
    """Protocol runs over the seeded targets: (final f, first-run f) arrays."""
    n_gen = 500 if scenario == 1 else 1000
    final, first = [], []
    for i, target in enumerate(random_reachable_targets(robot, N_TARGETS, seed=TARGET_SEED)):
        problem = PositionIK(robot, target.position) if scenario == 1 else pose_problem(
            robot, target)
        out = solve_until_success(problem, lambda: EOSMA.scenario(scenario), ("n_gen", n_gen),
                                  seed=i, threshold=threshold, max_failures=max_failures)
        final.append(out.best_f)
        first.append(out.run_f[0])
        assert np.all(robot.within_limits(out.best.X))
    return np.array(final), np.array(first)


def test_eosma_update_eq15_picks_operator_per_agent():
    P, W, pool = np.array([[1.0], [2.0]]), np.array([[1.0], [2.0]]), np.array([[3.0], [4.0]])
    rng = ScriptedRng(np.full((2, 1), 0.5), np.full((2, 1), 0.75), [1, 0], [0.4, 0.4],
                      [0.6, 0.6],  # EO draws (t1 = 0 makes F = 0: X = Ceq)
                      [[0.9], [0.5]], [0, 1], [0, 0],  # vb, A, B
                      [0.1, 0.9])  # rand < z: EO for agent 0, SMA for agent 1
    out = eosma_update(P, np.array([0.5]), pool, W, 0.0, 1.0, z=0.5, a1=2.0, GP=0.5, V=1.0,
                       rng=rng)
    np.testing.assert_allclose(out, [[4.0], [0.5 + 0.5 * (2.0 * 2.0 - 1.0)]])


def test_random_difference_mutation_eq16():
    P = np.array([[0.0], [1.0], [2.0]])
    rng = ScriptedRng([[2, 1, 1], [1, 2, 0], [0, 0, 0]], [[0.5], [0.4], [0.3]])
    out = random_difference_mutation(P, rng=rng)
    np.testing.assert_allclose(out, [[2.5], [1.8], [1.0]])


def random_case(seed: int, n: int = 9, d: int = 4):
    """Personal bests with repeated rows and fitness ties, a pool with its mean, weights."""
    rng = np.random.default_rng(seed)
    P = rng.uniform(-2.0, 2.0, (n, d))
    P[1] = P[0]  # duplicates
    pool = np.concatenate([P[:4], P[:4].mean(axis=0, keepdims=True)])
    W = rng.uniform(0.0, 2.0, (n, d))
    return P, pool, W


@pytest.mark.parametrize("seed", range(8))
def test_compiled_operators_equal_the_numpy_formulas(seed, numpy_rules):
    """Eqs. 15 and 16: the same bits as the numpy formulas on the same random stream,
    with one best for all agents and with one leader per agent (MOEOSMA)."""
    P, pool, W = random_case(seed)
    for g_best in (P[2], P[np.random.default_rng(seed).integers(len(P), size=len(P))]):
        for z in (0.0, 0.5, 1.0):
            args = (P, g_best, pool, W, 0.3 + 0.05 * seed, 0.7)
            kw = {"z": z, "a1": 2.0, "GP": 0.5, "V": 1.0}
            out = eosma_update(*args, **kw, rng=np.random.default_rng(seed))
            ref = numpy_rules.eosma_update(*args, **kw, rng=np.random.default_rng(seed))
            np.testing.assert_array_equal(out, ref)
    out = random_difference_mutation(P, rng=np.random.default_rng(seed))
    ref = numpy_rules.random_difference_mutation(P, rng=np.random.default_rng(seed))
    np.testing.assert_array_equal(out, ref)


@pytest.mark.parametrize("seed", range(30))
def test_distinct_pool_equals_the_numpy_selection(seed, numpy_rules):
    """Eq. 7 with ties, exact duplicates, nan and infinite fitness, with and without
    constraints, pools of 1 to 6 rows: the same rows in the same order."""
    rng = np.random.default_rng(seed)
    n, d = int(rng.integers(1, 40)), 3
    X = rng.integers(0, 3, (n, d)).astype(float)  # many equal rows
    F = rng.integers(0, 4, n).astype(float)
    F[rng.random(n) < 0.1] = np.nan
    F[rng.random(n) < 0.1] = np.inf
    CV = None if seed % 2 else np.where(rng.random(n) < 0.5, 0.0, rng.integers(1, 3, n))
    PX, PF = X[:2] + 1.0, F[:2].copy()
    PCV = None if CV is None else CV[:2].copy()
    for k in (1, 4, 6):
        out = update_distinct_pool(PX, PF, PCV, X, F, CV, k)
        ref = numpy_rules.update_distinct_pool(PX, PF, PCV, X, F, CV, k)
        for a, b in zip(out, ref, strict=True):
            if b is None:
                assert a is None
            else:
                np.testing.assert_array_equal(a, b)


class ConstrainedSphere(Problem):
    """``|x - 0.3|^2`` subject to ``x_0 + x_1 >= 0.5`` (infeasible corners in the box)."""

    def __init__(self):
        super().__init__(n_var=4, n_obj=1, n_ieq_constr=1, xl=-1.0, xu=1.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = ((X - 0.3) ** 2).sum(axis=1)
        out["G"] = 0.5 - X[:, 0] - X[:, 1]


class Sphere(Problem):
    def __init__(self):
        super().__init__(n_var=5, n_obj=1, xl=-5.0, xu=3.0)

    def _evaluate(self, X, out, *args, **kwargs):
        out["F"] = ((X - 1.3) ** 2).sum(axis=1)


@pytest.mark.parametrize("q", [0.0, 0.5, 1.0])
@pytest.mark.parametrize("problem", [Sphere(), ConstrainedSphere()], ids=["sphere", "constrained"])
def test_compiled_generation_equals_the_numpy_generation(q, problem, numpy_rules):
    """The class's compiled generation (all of a generation's numbers drawn at its start)
    and Algorithm 1 in numpy drawing each number where it is used give the same run, bit
    for bit, also when an evaluation budget cuts a batch."""
    for termination in (("n_gen", 40), ("n_eval", 1234)):
        for seed in (0, 1):
            kw = {"pop_size": 12, "q": q}
            res = minimize(problem, EOSMA(**kw), termination, seed=seed)
            ref = minimize(problem, numpy_rules.NumpyEOSMA(**kw), termination, seed=seed)
            np.testing.assert_array_equal(res.algorithm.pbest_X, ref.algorithm.pbest_X)
            np.testing.assert_array_equal(res.algorithm.pool_X, ref.algorithm.pool_X)
            np.testing.assert_array_equal(res.algorithm.convergence, ref.algorithm.convergence)
            assert res.algorithm.evaluator.n_eval == ref.algorithm.evaluator.n_eval


def test_same_seed_same_run_through_minimize_and_ask_tell():
    problem = ConstrainedSphere()
    runs = [minimize(problem, EOSMA(pop_size=10), ("n_gen", 30), seed=7) for _ in range(2)]
    algorithm = EOSMA(pop_size=10)
    algorithm.setup(problem, termination=("n_gen", 30), seed=7)
    while algorithm.has_next():
        pop = algorithm.ask()
        algorithm.evaluator.eval(problem, pop)
        algorithm.tell(infills=pop)
    for other in (runs[1].algorithm, algorithm):
        np.testing.assert_array_equal(other.pbest_X, runs[0].algorithm.pbest_X)
        np.testing.assert_array_equal(other.pbest_CV, runs[0].algorithm.pbest_CV)


def test_generation_draws_follow_the_numpy_stream():
    """The in-kernel draws are the numbers numpy's Generator methods give, in order, each
    in its named slot of GenerationDraws."""
    n, d, n_pool = 6, 3, 5
    draws = GenerationDraws(n, d)
    rng = np.random.default_rng(4)
    F = np.arange(n, 0, -1.0)
    assert generation_draws(GeneratorHandles().of(rng), np.stack([F, np.zeros(n)]), n_pool,
                            0.25, 0.5, 1.0, draws.cells, draws.rows, draws.picks)
    after = rng.random()
    ref = np.random.default_rng(4)
    np.testing.assert_array_equal(draws.weight_r, ref.random((n, d)))
    lam = ref.random((n, d))
    np.testing.assert_array_equal(draws.lam, lam)
    np.testing.assert_array_equal(draws.decay, -lam * 0.25)  # before apply_numpy_maths
    np.testing.assert_array_equal(draws.eo_r, ref.random((n, d)))
    np.testing.assert_array_equal(draws.pool_index, ref.integers(n_pool, size=n))
    np.testing.assert_array_equal(draws.gcp_r1, ref.random(n))
    np.testing.assert_array_equal(draws.gcp_r2, ref.random(n))
    np.testing.assert_array_equal(draws.vb, ref.uniform(-0.5, 0.5, (n, d)))
    np.testing.assert_array_equal(draws.a_index, ref.integers(n, size=n))
    np.testing.assert_array_equal(draws.b_index, ref.integers(n, size=n))
    np.testing.assert_array_equal(draws.operator_u, ref.random(n))
    assert ref.random() < 1.0  # the line-22 test
    np.testing.assert_array_equal(draws.mutant_r, ref.integers(n, size=(3, n)))
    np.testing.assert_array_equal(draws.sf, ref.uniform(0.3, 0.6, (n, 1))[:, 0])
    np.testing.assert_array_equal(draws.order, np.arange(n)[::-1])  # the ranking (Eq. 5)
    assert after == ref.random()  # the Generator continues from where the kernel stopped
    draws.apply_numpy_maths()
    np.testing.assert_array_equal(draws.decay, np.exp(-lam * 0.25))


def test_scenarios():
    s1, s2 = EOSMA.scenario(1), EOSMA.scenario(2)
    assert (s1.pop_size, s1.q, s1.a1, s1.a2, s1.z) == (50, 0.0, 1.0, 2.0, 0.5)
    assert (s2.pop_size, s2.q, s2.a1) == (100, 1.0, 2.0)
    assert EOSMA.scenario(1, pop_size=20).pop_size == 20
    with pytest.raises(ParameterError, match="scenario must be 1 or 2"):
        EOSMA.scenario(3)


def test_distinct_pool_keeps_each_point_once():
    X = np.array([[0.0, 1.0], [0.0, 1.0], [2.0, 0.0], [0.0, 1.0], [3.0, 3.0], [1.0, 1.0]])
    F = np.array([1.0, 1.0, 2.0, 1.0, 4.0, 3.0])
    PX, PF, PCV = update_distinct_pool(np.empty((0, 2)), np.empty(0), None, X, F, None)
    np.testing.assert_array_equal(PF, [1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(PX, X[[0, 2, 5, 4]])
    assert PCV is None


@pytest.mark.parametrize("robot", [get_robot("eosma7"), eosma7_metres()], ids=["cm", "m"])
def test_target_joint_vector_has_zero_error(robot):
    """f(q_source) = 0 exactly: the Eq. 26 (atan) angles of the target are its own."""
    for target in random_reachable_targets(robot, N_TARGETS, seed=TARGET_SEED):
        q = target.q_source[None]
        assert pose_problem(robot, target).evaluate(q)[0, 0] == 0.0
        assert PositionIK(robot, target.position).evaluate(q)[0, 0] == 0.0


def paper_first_run_bound(n_targets: int = N_TARGETS) -> int:
    """The fewest first-run successes of ``n_targets`` consistent with the paper.

    Tables 5 and 7 (Yin et al. 2022) report the mean and the worst error of one run on
    each of 100 random targets (worst 7.85e-16 and 5.55e-17): 100 successes of 100.
    The 95 % Clopper-Pearson lower bound of the success rate is then
    ``p = 0.05 ** (1 / 100)`` (0.9705), and a count below the 1 % quantile of
    Binomial(n_targets, p) would contradict the paper at that level (17 of 20).
    """
    return int(binom.ppf(0.01, n_targets, 0.05 ** (1 / 100)))


def test_paper_first_run_bound():
    assert paper_first_run_bound() == 17
    assert binom.cdf(16, N_TARGETS, 0.05 ** (1 / 100)) < 0.01


def test_scenario1_position_to_1e10_cm():
    """Scenario 1 (N=50, T=500, q=0, a1=1): all 20 targets below 1e-10 cm.

    Measured: 19 of 20 first runs below 1e-10 cm, all 20 below 1e-6 (the
    paper's protocol would accept every first run); 1.4 s in all. The first-run count
    is held to the paper's claim (:func:`paper_first_run_bound`), not to the measure.
    """
    final, first = solve_all(get_robot("eosma7"), 1, threshold=1e-10)
    assert np.all(final < 1e-10)
    assert np.all(first < 1e-6)
    assert np.sum(first < 1e-10) >= paper_first_run_bound()


def test_scenario2_pose_table1_metres():
    """Scenario 2 (N=100, T=1000, q=1, a1=2), arm in metres: Table 7 reproduced.

    Measured: 18 of 20 first runs below 1e-8, all 20 after re-runs (22 runs),
    mean 4.4e-18, worst 5.0e-17; about 7 s. Bounds from the paper's Table 7 (every
    target solved, worst 5.55e-17): all protocol results, and the first runs by
    :func:`paper_first_run_bound`.
    """
    final, first = solve_all(eosma7_metres(), 2, threshold=1e-6)
    assert np.all(final < 1e-8)
    assert np.sum(first < 1e-8) >= paper_first_run_bound()


def test_scenario2_pose_in_cm_falls_short_of_the_paper():
    """Scenario 2 with the catalog arm in cm: the first runs contradict the paper's Table 7.

    The same algorithm and targets as :func:`test_scenario2_pose_table1_metres`; only the
    unit of length differs. Measured: 2 of 20 first runs below 1e-8 (16 of 20 after the
    protocol's re-runs, 103 runs; the best of 10 runs of each of the other 4 still has
    f = 0.002-0.09), below :func:`paper_first_run_bound` (17), which the metres arm meets:
    the unit the paper's arm is given in matters.
    """
    _, first = solve_all(get_robot("eosma7"), 2, threshold=1e-6, max_failures=1)
    assert np.sum(first < 1e-8) < paper_first_run_bound()


def test_table9_pose_is_reached_in_metres():
    """EOSMA Table 9 (Eq. 31, w = 1e-15, start (45, 0, 45, 0, 45, 0, 0) deg): the
    paper's EOSMA reaches (50, -75, 75, 0, 0, 0) exactly. With the arm in metres
    3 runs (N=100, T=1000, q=1, a1=2; seeds 0-2) are enough for one exact
    solution (7 of 10 runs in ``eosma-table9``); in cm none of 10 runs reached it
    (orientation stuck at 0.03-1.1 rad), see experiments/eosma_table9.toml.
    The solution lies on the boundary family q2 = q3 = -90 deg as the paper's,
    or on the EO row's family (q1 near +-175 deg)."""
    from pymoo.optimize import minimize

    from moik.problems import Target

    robot = eosma7_metres()
    target = Target.from_euler([0.50, -0.75, 0.75], [0, 0, 0], convention="eosma-euler",
                               degrees=True)
    problem = PoseIK(robot, target, weights=(0.5, 0.5), orientation="eosma-euler",
                     displacement_weight=1e-15, q_start=np.radians([45, 0, 45, 0, 45, 0, 0]))
    runs = [minimize(problem, EOSMA.scenario(2), ("n_gen", 1000), seed=s) for s in range(3)]
    best = min(runs, key=lambda r: r.F[0])
    pos, ori = problem.errors(best.X[None])
    assert pos[0] < 1e-12 and ori[0] < 1e-12
    q_deg = np.degrees(best.X)
    assert (np.allclose(q_deg[1:3], -90.0, atol=1e-6) or abs(abs(q_deg[0]) - 175) < 10)


@pytest.mark.parametrize("high", [1, 2, 7, 1000, 2**32 - 1, 2**32, 2**32 + 1, 2**40 + 3])
def test_fill_integers_is_the_numpy_stream(high):
    """fill_integers calls numba's bounded-integer fill below Generator.integers: the
    same numbers as numpy's ``integers(high, size=shape)``, the stream left where numpy
    leaves it (32-bit draws buffered across calls included)."""
    rng, ref = np.random.default_rng(high), np.random.default_rng(high)
    for shape in [(1, 5), (3, 4), (1, 1), (2, 9)]:
        A = np.empty(shape, dtype=np.int64)
        fill_integers(rng, high, A)
        np.testing.assert_array_equal(A, ref.integers(high, size=shape))
        assert rng.random() == ref.random()
