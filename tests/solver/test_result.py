"""The verdict of a finished solve (the pure :func:`verdict`) and its assembly
(:func:`ik_result`), on hand-made sessions of planar2 (tests/solver/planar2_cases.py).

Tolerance ``1e-9`` (times the reach 0.65 for positions): the scaled tolerance is
``2e-9``, so a best candidate counts as far (``UNREACHABLE_FACTOR`` = 1e3 tolerances)
above a scaled error of ``2e-6``. The position target ``(1, 0, 0)`` is 0.35 out of
reach: the stretched arm ``q = (0, 0)`` misses it by 0.35 (scaled error 0.35 / 0.65).
"""

import copy

import numpy as np
import pytest

from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import Target
from moik.solver.result import UNREACHABLE_FACTOR, ik_result, verdict
from moik.solver.session import SolveSession, pose_errors
from tests.solver.planar2_cases import ARM, REACH, branches, elbow_distance, elbow_guard

TOL = Tolerance.of(1e-9, REACH)
XY = (0.3, 0.25)
TARGET = Target([*XY, 0.0])
SOLS = branches(*XY)
FAR = Target([1.0, 0.0, 0.0])


def _session(target=TARGET, *, found=(), errors=(), best=None, colliding=None, guard=None,
             wanted=2):
    session = SolveSession(ARM, target, TOL, 0.1, wanted, guard=guard)
    session.found, session.found_errors = [np.array(q) for q in found], list(errors)
    session.best, session.colliding = best, colliding
    return session


def _state(session):
    return copy.deepcopy((session.found, session.found_errors, session.best,
                          session.colliding, session.n_rejected))


def test_solved_keeps_the_sessions_solutions_and_errors():
    session = _session(found=SOLS[::-1], errors=[(3e-13, 0.0), (4e-13, 0.0)],
                       best=(0.0, SOLS[1]))
    before = _state(session)
    v = verdict(session, None, True, None, None)
    assert v.status == "solved" and v.errors == (3e-13, 0.0)  # the stored ones, not redone
    np.testing.assert_array_equal(v.q, SOLS[1])
    np.testing.assert_array_equal(v.solutions, SOLS[::-1])
    assert v.front is None and v.distances is None and v.min_distance is None
    np.testing.assert_equal(_state(session), before)  # the session is not changed


def test_solutions_nearest_the_current_configuration_first():
    session = _session(found=SOLS[::-1], errors=[(0.0, 0.0)] * 2, best=(0.0, SOLS[1]))
    v = verdict(session, SOLS[0] + 0.01, True, None, None)
    np.testing.assert_array_equal(v.solutions, SOLS)
    pos, ori = pose_errors(ARM, TARGET, SOLS[0])
    assert v.errors == (pos[0], ori[0])  # recomputed for the one now first


@pytest.mark.parametrize("searched_out, proven, status", [
    (True, False, "unreachable"), (False, False, "not-converged"),
    (False, True, "unreachable")])
def test_unreachable_only_for_a_proof_or_a_full_search_that_ended_far(searched_out, proven,
                                                                      status):
    session = _session(FAR, best=(0.35 / 0.65, np.zeros(2)))
    v = verdict(session, None, searched_out, None, None, proven)
    assert v.status == status and not len(v.solutions)
    assert v.errors[0] == pytest.approx(0.35, abs=1e-15) and v.errors[1] == 0.0
    np.testing.assert_array_equal(v.q, [0.0, 0.0])


def test_a_near_miss_after_a_full_search_is_not_converged():
    """Scaled error ~1.5e-7: not within tolerance, not 1e3 tolerances away."""
    q = SOLS[0] + [2e-7, 0.0]
    err = pose_errors(ARM, TARGET, q)[0][0] / REACH
    assert TOL.scaled(REACH) < err < UNREACHABLE_FACTOR * TOL.scaled(REACH)
    v = verdict(_session(best=(err, q)), None, True, None, None)
    assert v.status == "not-converged"
    np.testing.assert_array_equal(v.q, q)


def test_an_unreachable_verdict_answers_with_the_fronts_compromise():
    """Normalised, (0.5, 0.5) is nearest the utopia point (0, 0); its joint vector is
    clipped into the limits. A not-converged verdict keeps the best candidate."""
    front = np.array([[0.0, 1.0], [0.5, 0.5], [1.0, 0.0]])
    front_q = np.array([[0.0, 0.0], [4.0, 0.1], [1.0, 1.0]])
    session = _session(FAR, best=(0.35 / 0.65, np.zeros(2)))
    v = verdict(session, None, True, front, front_q)
    assert v.status == "unreachable" and v.front is front and v.front_q is front_q
    np.testing.assert_array_equal(v.q, [np.pi, 0.1])
    assert v.errors[0] == pytest.approx(pose_errors(ARM, FAR, v.q, reference=True)[0][0],
                                        abs=0)
    assert verdict(session, None, False, front, front_q).q is session.best[1]


def test_an_answer_within_tolerance_is_promoted_to_solved():
    session = _session(best=(1.0, SOLS[0]))  # no stage counted it as found
    v = verdict(session, None, False, None, None)
    assert v.status == "solved"
    np.testing.assert_array_equal(v.solutions, SOLS[:1])
    assert v.errors[0] <= TOL.position
    assert not session.found  # the session is not changed


def test_an_exact_answer_in_collision_is_never_solved():
    session = _session(best=(1.0, SOLS[0]), guard=elbow_guard(SOLS[0]))
    v = verdict(session, None, False, None, None)
    assert v.status == "collides" and not len(v.solutions)
    assert v.min_distance == pytest.approx(-0.1, abs=1e-12)


def test_solutions_below_the_clearance_are_dropped():
    """Branch 0 is in contact; branch 1, kept, brings its own errors and distance."""
    session = _session(found=SOLS, errors=[(1e-13, 0.0), (2e-13, 0.0)], best=(0.0, SOLS[0]),
                       guard=elbow_guard(SOLS[0]))
    v = verdict(session, None, True, None, None)
    d1 = elbow_distance(SOLS[1], SOLS[0])
    assert v.status == "solved" and v.errors == (2e-13, 0.0)
    np.testing.assert_array_equal(v.solutions, SOLS[1:])
    np.testing.assert_allclose(v.distances, [d1], atol=1e-12)
    assert v.min_distance == pytest.approx(d1, abs=1e-12)
    assert len(session.found) == 2  # dropped from the verdict, not from the session


def test_collides_when_every_exact_answer_is_in_contact():
    d1 = elbow_distance(SOLS[1], SOLS[0])
    guard = elbow_guard(SOLS[0], clearance=d1 + 0.01)
    session = _session(found=SOLS[1:], errors=[(0.0, 0.0)], colliding=(-0.1, SOLS[0]),
                       best=(0.0, SOLS[1]), guard=guard)
    v = verdict(session, None, True, None, None)
    assert v.status == "collides" and v.solutions.shape == (0, 2)
    np.testing.assert_array_equal(v.q, SOLS[0])
    assert v.min_distance == pytest.approx(-0.1, abs=1e-12)  # recomputed at the end


def test_ik_result_says_why_it_delivered_less():
    fewer = _session(found=SOLS[:1], errors=[(0.0, 0.0)], best=(0.0, SOLS[0]), wanted=3)
    res = ik_result(fewer, None, 0.0, True, None, None)
    assert res.success and res.fewer_solutions and res.n_requested == 3
    assert res.detail == ("found 1 of the 3 distinct solutions requested (the search "
                          "stopped finding new ones)")
    fewer.n_eval = fewer.max_evals
    assert "the evaluation budget was spent" in ik_result(fewer, None, 0.0, True, None,
                                                          None).detail
    guard = elbow_guard(SOLS[0])
    hit = _session(colliding=(-0.1, SOLS[0]), best=(0.0, SOLS[0]), guard=guard)
    hit.n_rejected = 2
    res = ik_result(hit, None, 0.0, True, None, None)
    assert res.status == "collides" and not res.success and res.distances.shape == (0,)
    assert res.detail == ("2 exact answer(s) rejected for collision; the farthest from "
                          "contact is at -0.1 m, below the clearance 0")
