"""The ranking that keeps the population of a larger initial sample
(moik.algorithms.initial_survival)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from pymoo.core.population import Population
from pymoo.operators.survival.rank_and_crowding import RankAndCrowding
from pymoo.operators.survival.rank_and_crowding.metrics import calc_crowding_distance
from pymoo.problems import get_problem
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik.algorithms.initial_survival import (
    best_rows,
    rank_and_crowding_rows,
    surviving_population,
)


def test_best_rows_feasibility_first_and_stable():
    F = np.array([3.0, 1.0, 2.0, 0.5, 1.0, np.inf])
    np.testing.assert_array_equal(best_rows(F, None, 3), [1, 3, 4])  # tie at 1.0: both kept
    np.testing.assert_array_equal(best_rows(F, None, 2), [1, 3])
    CV = np.array([0.0, 0.0, 0.0, 2.0, 0.0, np.inf])  # 0.5 infeasible: after every feasible
    np.testing.assert_array_equal(best_rows(F, CV, 4), [0, 1, 2, 4])
    np.testing.assert_array_equal(best_rows(F, CV, 5), [0, 1, 2, 3, 4])  # the inf row last
    np.testing.assert_array_equal(best_rows(F, None, 10), np.arange(6))


def test_rank_and_crowding_order():
    F = np.array([[0.0, 1.0], [1.0, 0.0], [0.5, 0.5], [0.6, 0.6], [2.0, 2.0], [0.4, 0.55]])
    # front 1: rows 0, 1, 2, 5; of them the extremes (infinite crowding) come first
    np.testing.assert_array_equal(rank_and_crowding_rows(F, None, 4), [0, 1, 2, 5])
    np.testing.assert_array_equal(rank_and_crowding_rows(F, None, 2), [0, 1])
    np.testing.assert_array_equal(rank_and_crowding_rows(F, None, 5), [0, 1, 2, 3, 5])
    CV = np.array([0.0, 0.3, 0.0, 0.1, 0.0, 0.0])
    # feasible rows 0, 2, 4, 5 first (fronts {0, 2, 5} then {4}), then CV 0.1 before 0.3
    np.testing.assert_array_equal(rank_and_crowding_rows(F, CV, 5), [0, 2, 3, 4, 5])
    F[2] = np.inf
    np.testing.assert_array_equal(rank_and_crowding_rows(F, None, 5), [0, 1, 3, 4, 5])


def _rank_and_crowding(F: np.ndarray) -> dict[int, tuple[int, float]]:
    """Each row's front rank and its crowding distance within that front."""
    out = {}
    for rank, front in enumerate(NonDominatedSorting().do(F)):
        for i, c in zip(front, calc_crowding_distance(F[front]), strict=True):
            out[int(i)] = (rank, float(c))
    return out


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.integers(0, 10_000), st.integers(5, 40), st.integers(1, 30))
def test_rank_and_crowding_keeps_what_pymoos_survival_keeps(seed, k, n):
    """pymoo's RankAndCrowding with its constraint filter keeps rows of the same front
    ranks and crowding distances (pymoo breaks crowding ties at random: the rows may
    differ only among equal keys) and the same violations."""
    rng = np.random.default_rng(seed)
    F = rng.integers(0, 6, size=(k, 2)).astype(float)  # many ties
    CV = np.where(rng.random(k) < 0.3, rng.random(k), 0.0)
    ours = rank_and_crowding_rows(F, CV, n)
    assert len(ours) == min(n, k) and len(np.unique(ours)) == len(ours)
    pop = Population.new("X", np.arange(k, dtype=float)[:, None], "F", F, "CV", CV[:, None],
                         "G", CV[:, None])
    theirs = RankAndCrowding().do(get_problem("bnh"), pop, n_survive=min(n, k),
                                  random_state=np.random.default_rng(0)).get("X")[:, 0]
    theirs = theirs.astype(int)
    np.testing.assert_array_equal(np.sort(CV[ours]), np.sort(CV[theirs]))
    feasible = np.flatnonzero(CV <= 0.0)
    keys = _rank_and_crowding(F[feasible])
    position = {int(i): j for j, i in enumerate(feasible)}

    def kept(rows):
        return sorted(keys[position[int(i)]] for i in rows if CV[i] <= 0.0)

    assert kept(ours) == kept(theirs)


def test_surviving_population():
    F = np.array([[0.0, 1.0], [1.0, 0.0], [2.0, 2.0]])
    pop = Population.new("X", np.arange(3.0)[:, None], "F", F, "CV", np.zeros((3, 1)))
    assert surviving_population(pop, 3) is pop
    np.testing.assert_array_equal(surviving_population(pop, 2).get("X")[:, 0], [0.0, 1.0])
