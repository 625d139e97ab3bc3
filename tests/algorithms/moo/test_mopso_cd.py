"""MOPSO-CD (moik.algorithms.moo.mopso_cd): pymoo's, seeded by the run, constraint-domination."""

import numpy as np
from pymoo.algorithms.moo.mopso_cd import MOPSO_CD
from pymoo.optimize import minimize
from pymoo.problems import get_problem

from moik.algorithms import MOPSOCD


def test_unconstrained_runs_are_pymoos_bit_for_bit_and_seeded_by_the_run():
    problem = get_problem("zdt1", n_var=6)
    ours = minimize(problem, MOPSOCD(pop_size=20), ("n_eval", 600), seed=3)
    theirs = minimize(problem, MOPSO_CD(pop_size=20), ("n_eval", 600), seed=3)
    np.testing.assert_array_equal(ours.F, theirs.F)
    again = minimize(problem, MOPSOCD(pop_size=20, seed=3), ("n_eval", 600))
    np.testing.assert_array_equal(again.F, ours.F)
    other = minimize(problem, MOPSOCD(pop_size=20), ("n_eval", 600), seed=4)
    assert not np.array_equal(other.F, ours.F)


def test_a_termination_given_to_the_constructor_is_kept():
    alg = MOPSOCD(pop_size=10, termination=("n_gen", 4))
    res = minimize(get_problem("zdt1", n_var=4), alg, seed=0)
    assert res.algorithm.n_gen == 5  # 4 generations (pymoo counts one past the last)


def test_constrained_archive_and_personal_bests_are_feasible_first():
    problem = get_problem("osy")
    res = minimize(problem, MOPSOCD(pop_size=30), ("n_eval", 3000), seed=1)
    G = problem.evaluate(res.X, return_values_of=["G"])
    assert np.all(G <= 0.0) and np.all(res.CV == 0.0)
    assert np.any(res.algorithm.pbest.get("CV")[:, 0] == 0.0)
    theirs = minimize(problem, MOPSO_CD(pop_size=30), ("n_eval", 3000), seed=1)
    # pymoo's own compares F only: its archive keeps infeasible points (here none of its
    # members is feasible, so its result is empty, or it mixes in infeasible ones)
    assert theirs.F is None or np.any(theirs.CV > 0.0)
