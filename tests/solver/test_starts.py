"""The start loop (run_starts), its batch (run_batch), the weighted-sum front (lm_front)
and their helpers, on cases solved by hand.

The arm is ``planar2`` (tests/solver/planar2_cases.py: two solutions of a position target
by the law of cosines). A position target at distance ``D > reach`` is missed by at least
``D - reach``, attained by the stretched arm pointing at it, so the lowest cost
``0.5 |r|^2`` (position rows scaled by ``1 / reach``) is ``0.5 ((D - reach) / reach)^2``.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from moik.problems.targets import Target
from moik.robots import get_robot
from moik.robots.chain import fk_reference
from moik.solver.context import ik_context
from moik.solver.session import pose_errors
from moik.solver.starts import (
    CHECK,
    UNLIMITED,
    found_table,
    front,
    is_distinct,
    is_new,
    multistart,
    run_batch,
    run_starts,
)
from tests.solver.planar2_cases import ARM, REACH, branches, wrapped

TOL = (1e-9 * REACH, 1e-9)


def _context(target, **kwargs):
    stop = (0.1 * TOL[0], 0.1 * TOL[1])
    return ik_context(ARM, target, stop=stop, tol=TOL, **kwargs)


STARTS = ARM.random_q(40, rng=np.random.default_rng(0))


def test_found_table_holds_the_known_rows_then_nan():
    table = found_table(3, 2, [np.array([1.0, 2.0])], [(1e-3, 2e-3)])
    np.testing.assert_array_equal(table[0], [1.0, 2.0, 1e-3, 2e-3])
    assert np.isnan(table[1:]).all()
    table = found_table(1, 2, [np.ones(2), np.zeros(2)])  # more known than wanted
    np.testing.assert_array_equal(table[0, :2], [1.0, 1.0])
    assert np.isnan(table[0, 2:]).all()  # no errors given: NaN


def test_finds_exactly_the_two_branches_of_a_planar_target():
    x, y = 0.3, 0.25
    ctx = _context(Target([x, y, 0.0]))
    found = found_table(4, 2)
    best, ends = np.empty(3), np.empty((len(STARTS), 3))
    best[0] = np.inf
    n_found, n_eval, used = run_starts(ctx, STARTS.copy(), (CHECK, UNLIMITED), found, best,
                                       ends)
    assert n_found == 2 and used == len(STARTS) and n_eval >= used  # no third solution
    assert np.isnan(found[2:]).all()
    expected = branches(x, y)
    for row in found[:2]:
        assert min(wrapped(row[:2], e).max() for e in expected) < 1e-6
        assert np.all(ARM.within_limits(row[:2]))
    assert wrapped(found[0, :2], found[1, :2]).max() > 0.1
    # the errors stored are the FK re-check's (the reference FK agrees), within tolerance
    pos, ori = pose_errors(ARM, Target([x, y, 0.0]), found[:2, :2], reference=True)
    np.testing.assert_allclose(found[:2, 2], pos, rtol=0, atol=1e-15)
    assert np.all(found[:2, 2] <= TOL[0]) and np.all(found[:2, 3] == 0.0)
    assert best[0] == pytest.approx(min(found[:2, 2]) / REACH, abs=1e-15)


def test_a_full_table_or_a_spent_budget_starts_nothing_more():
    ctx = _context(Target([0.3, 0.25, 0.0]))
    known = found_table(1, 2, branches(0.3, 0.25)[:1])
    best, ends = np.full(3, np.inf), np.full((len(STARTS), 3), -7.0)
    assert run_starts(ctx, STARTS.copy(), (CHECK, UNLIMITED), known, best, ends) == (1, 0, 0)
    assert np.all(ends == -7.0) and best[0] == np.inf
    found = found_table(4, 2)
    n_found, n_eval, used = run_starts(ctx, STARTS.copy(), (CHECK, 1), found, best, ends)
    assert used == 1 and n_eval >= 1 and n_found <= 1


def test_a_known_solution_is_not_found_again():
    sols = branches(0.3, 0.25)
    ctx = _context(Target([0.3, 0.25, 0.0]))
    found = found_table(4, 2, sols[:1])
    starts = np.vstack([sols[0] + 1e-4, sols[0] - 1e-4])  # both converge to it
    n_found, _, used = run_starts(ctx, starts, (CHECK, UNLIMITED), found, np.full(3, np.inf),
                                  np.empty((2, 3)))
    assert used == 2 and n_found == 1


def test_best_of_an_unreachable_target_is_the_lowest_end():
    """Position target 1.0 m along x: missed by at least 0.35 m (module doc). Without
    CHECK ``best`` holds the lowest end's cost ``0.5 (miss / L)^2``, with it ``miss / L``
    (its re-checked ``pos / L + ori``), each the value of the ``q`` stored beside it."""
    target = Target([1.0, 0.0, 0.0])
    ctx = _context(target)
    starts = ARM.random_q(8, rng=np.random.default_rng(1))
    for flags, value in ((0, lambda miss: 0.5 * (miss / REACH) ** 2),
                         (CHECK, lambda miss: miss / REACH)):
        best, ends = np.full(3, np.inf), np.empty((8, 3))
        P = starts.copy()
        n_found, _, _ = run_starts(ctx, P, (flags, UNLIMITED), found_table(1, 2), best, ends)
        assert n_found == 0
        miss = pose_errors(ARM, target, best[1:], reference=True)[0][0]
        assert best[0] == pytest.approx(value(miss), rel=1e-12)
        assert value(0.35) <= best[0] <= value(0.35) * 1.01  # near the stretched arm
        assert np.all(best[1:] == P, axis=1).any()  # an end of a start
        assert np.min(ends[:, 1]) == pytest.approx(0.5 * (miss / REACH) ** 2, rel=1e-12)


def test_a_projection_runs_every_row_whatever_the_budget():
    ctx = _context(Target([0.3, 0.25, 0.0]))
    P, ends = STARTS[:5].copy(), np.empty((5, 3))
    n_found, n_eval, used = run_starts(ctx, P, (0, 0), None, None, ends)
    assert (n_found, used) == (0, 5) and n_eval >= 5
    assert np.isnan(ends[:, 2]).all()
    conv = ends[:, 0] != 0
    assert conv.any()
    pos = np.linalg.norm(fk_reference(ARM, P[conv])[:, :3, 3] - [0.3, 0.25, 0.0], axis=1)
    assert np.all(pos <= 0.1 * TOL[0] * 1.0001)  # a converged end meets the stop


def test_batch_skips_solved_targets_and_counts_per_target():
    targets = [(0.3, 0.25), (0.1, -0.4), (-0.5, 0.2)]
    rotations = np.tile(np.eye(3), (3, 1, 1))
    positions = np.array([[x, y, 0.0] for x, y in targets])
    ctx = _context(Target(positions[0]))
    found = np.stack([found_table(1, 2) for _ in targets])
    found[1, 0] = [9.0, 9.0, 0.0, 0.0]  # already solved: left alone
    n_evals = np.zeros(3, dtype=np.int64)
    starts = np.stack([STARTS[:6], STARTS[6:12], STARTS[12:18]])
    run_batch(ctx, starts.copy(), (rotations, positions), (CHECK, UNLIMITED), found, n_evals)
    assert n_evals[1] == 0 and n_evals[0] > 0 and n_evals[2] > 0
    np.testing.assert_array_equal(found[1, 0], [9.0, 9.0, 0.0, 0.0])
    for i in (0, 2):
        p = fk_reference(ARM, found[i, :, :2])[0, :3, 3]
        assert np.linalg.norm(p - positions[i]) <= TOL[0]


def test_front_without_budget_repeats_the_first_weight():
    """No start begins once the budget is spent: weights after the first keep its answer."""
    target = Target([0.9, 0.2, 0.0], np.eye(3))
    Q, n_eval = front(ARM, target, STARTS[:3], np.linspace(1.0, 0.0, 5), budget=0)
    assert n_eval >= 1
    np.testing.assert_array_equal(Q, np.repeat(Q[:1], 5, axis=0))
    Q_full, _ = front(ARM, target, STARTS[:3], np.linspace(1.0, 0.0, 5))
    assert not np.array_equal(Q_full[0], Q_full[-1])


def test_multistart_stops_at_its_budget():
    target = Target([0.3, 0.25, 0.0])
    kwargs = dict(stop_position=1e-12, stop_orientation=0.0, want=2)
    out = multistart(ARM, target, STARTS, max_evals=1, **kwargs)
    assert out.starts_used == 1 and out.n_eval >= 1
    assert multistart(ARM, target, STARTS, **kwargs).starts_used > 1


SCARA = get_robot("scara4")  # joints revolute, revolute, prismatic, revolute
vectors = st.lists(st.floats(-7.0, 7.0), min_size=4, max_size=4).map(np.array)


@settings(max_examples=60, deadline=None)
@given(q=vectors, others=st.lists(vectors, min_size=1, max_size=3),
       threshold=st.floats(0.01, 3.0), shift=st.lists(st.integers(-1, 1), min_size=4,
                                                      max_size=4))
def test_is_new_and_is_distinct_agree(q, others, threshold, shift):
    """The compiled test of the start loop and the Python one of the session are one rule;
    adding whole turns to the revolute joints never makes a vector new."""
    ctx = ik_context(SCARA, Target([0.5, 0.2, 0.1]), stop=(0.0, 0.0), distinct=threshold)
    table = np.array(others)
    assert is_new(ctx, table, len(table), q) == is_distinct(SCARA, q, list(table), threshold)
    turned = q + 2 * np.pi * np.array(shift) * [1, 1, 0, 1]
    assert not is_new(ctx, q[None], 1, turned)
    assert not is_distinct(SCARA, turned, [q], threshold)
    moved = q + np.array([0.0, 0.0, 2 * threshold, 0.0])  # the prismatic joint: no wrap
    assert is_new(ctx, q[None], 1, moved) and is_distinct(SCARA, moved, [q], threshold)
