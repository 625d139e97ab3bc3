"""The bookkeeping of one solve (SolveSession) and its honest re-check (pose_errors), on
planar2 cases solved by hand (tests/solver/planar2_cases.py) and scipy's rotations."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from moik.kinematics.tolerance import Tolerance
from moik.problems.targets import Target
from moik.solver.session import SolveSession, geodesic_errors, pose_errors
from tests.solver.planar2_cases import (
    ARM,
    REACH,
    branches,
    elbow_distance,
    elbow_guard,
    rz,
    tool,
    wrapped,
)

TOL = Tolerance.of(1e-9, REACH)
XY = (0.3, 0.25)
TARGET = Target([*XY, 0.0])
SOLS = branches(*XY)


@pytest.mark.parametrize("reference", [False, True])
def test_pose_errors_by_hand(reference):
    """At q = (0, 0) the tool is at (0.65, 0, 0) with heading 0: 0.1 from (0.65, 0.1, 0)
    and 0.3 rad from Rz(0.3); at q = (0.2, 0.1) the heading is 0.3: 0 rad from it."""
    Q = np.array([[0.0, 0.0], [0.2, 0.1]])
    target = Target([0.65, 0.1, 0.0], rz(0.3))
    pos, ori = pose_errors(ARM, target, Q, reference=reference)
    p1 = tool(Q[1])[0]
    np.testing.assert_allclose(pos, [0.1, np.linalg.norm(p1 - [0.65, 0.1, 0.0])], atol=1e-15)
    np.testing.assert_allclose(ori, [0.3, 0.0], atol=1e-12)
    pos, ori = pose_errors(ARM, Target([0.65, 0.1, 0.0]), Q[0], reference=reference)
    assert pos.shape == ori.shape == (1,) and ori[0] == 0.0  # one vector; position only


def test_pose_errors_one_target_per_row():
    Q = np.array([[0.0, 0.0], [0.2, 0.1], [-1.0, 2.0]])
    P = np.array([tool(q)[0] for q in Q]) + [[0.0, 0.1, 0.0], [0.0, 0.0, 0.2], [0.0, 0.0, 0.0]]
    R = np.stack([rz(0.5), rz(0.3), rz(1.0 - 0.25)])
    pos, ori = pose_errors(ARM, (P, R), Q)
    np.testing.assert_allclose(pos, [0.1, 0.2, 0.0], atol=1e-15)
    np.testing.assert_allclose(ori, [0.5, 0.0, 0.25], atol=1e-12)
    pos, ori = pose_errors(ARM, (P, None), Q)
    assert not ori.any()
    empty = pose_errors(ARM, TARGET, np.empty((0, 2)))
    assert empty[0].shape == empty[1].shape == (0,)


def test_geodesic_errors_are_scipys_angles():
    """The angle of ``R_i^T R_t`` (scipy's rotation magnitude), per row or broadcast."""
    R = Rotation.random(20, random_state=1).as_matrix()
    Rt = Rotation.random(20, random_state=2).as_matrix()
    expected = (Rotation.from_matrix(R).inv() * Rotation.from_matrix(Rt)).magnitude()
    out = np.empty(20)
    geodesic_errors(R, Rt, out)
    np.testing.assert_allclose(out, expected, rtol=0, atol=1e-12)
    geodesic_errors(R, Rt[:1].copy(), out)
    one = (Rotation.from_matrix(R).inv() * Rotation.from_matrix(Rt[0])).magnitude()
    np.testing.assert_allclose(out, one, rtol=0, atol=1e-12)


def _session(wanted=2, guard=None, target=TARGET):
    return SolveSession(ARM, target, TOL, 0.1, wanted, guard=guard)


def test_consider_keeps_distinct_solutions_within_tolerance():
    session = _session(wanted=2)
    near_miss = SOLS[0] + [1e-6, 0.0]  # ~3.5e-7 m off: outside the tolerance
    again = SOLS[0] + [1e-12, -1e-12]  # within tolerance, not distinct from SOLS[0]
    session.consider(np.array([near_miss, SOLS[0], again, SOLS[1]]))
    assert len(session.found) == 2
    np.testing.assert_array_equal(session.found[0], SOLS[0])
    np.testing.assert_array_equal(session.found[1], SOLS[1])
    for q, (p, o) in zip(session.found, session.found_errors, strict=True):
        assert p == pose_errors(ARM, TARGET, q)[0][0] and p <= TOL.position and o == 0.0
    err, q_best = session.best
    assert err <= TOL.position / REACH and err == min(e[0] for e in session.found_errors) / REACH
    assert session.n_rejected == 0 and session.colliding is None


def test_consider_keeps_no_more_than_wanted():
    session = _session(wanted=1)
    session.consider(SOLS)
    assert len(session.found) == 1


def test_refine_clips_into_the_limits_or_polishes():
    session = _session()
    session.refine(np.array([4.0, -0.7]), do_polish=False)
    np.testing.assert_array_equal(session.best[1], [np.pi, -0.7])
    assert session.n_eval == 0 and not session.found
    session.refine(SOLS[1] + [2e-3, -1e-3], do_polish=True)
    assert len(session.found) == 1 and session.n_eval > 0
    assert wrapped(session.found[0], SOLS[1]).max() < 1e-6


def test_local_starts_finds_both_branches_then_nothing_new():
    session = _session(wanted=3)
    starts = ARM.random_q(30, rng=np.random.default_rng(0))
    assert session.local_starts(starts.copy())
    n_eval = session.n_eval
    assert len(session.found) == 2 and n_eval > 0  # planar2 has two, however many wanted
    for q in session.found:
        assert min(wrapped(q, s).max() for s in SOLS) < 1e-6
    assert all(p <= TOL.position for p, _ in session.found_errors)
    assert not session.local_starts(starts.copy())
    assert session.n_eval > n_eval and len(session.found) == 2


def test_a_session_counts_evaluations_within_its_budget():
    session = SolveSession(ARM, TARGET, TOL, 0.1, 3, max_evals=5)
    session.local_starts(ARM.random_q(30, rng=np.random.default_rng(0)))
    full = _session(wanted=3)
    full.local_starts(ARM.random_q(30, rng=np.random.default_rng(0)))
    assert session.n_eval < full.n_eval


def test_consider_rejects_answers_in_collision():
    """Branch 0's elbow is in the obstacle (-0.1), branch 1's clear of it."""
    session = _session(guard=elbow_guard(SOLS[0]))
    session.consider(SOLS.copy())
    assert len(session.found) == 1
    np.testing.assert_array_equal(session.found[0], SOLS[1])
    assert session.n_rejected == 1
    d, q = session.colliding
    assert d == pytest.approx(-0.1, abs=1e-12)
    np.testing.assert_array_equal(q, SOLS[0])


def test_the_farthest_from_contact_is_kept():
    """A clearance neither branch keeps: both rejected, branch 1 (farther) kept."""
    d1 = elbow_distance(SOLS[1], SOLS[0])
    assert d1 > 0
    session = _session(guard=elbow_guard(SOLS[0], clearance=d1 + 0.01))
    session.consider(SOLS.copy())
    assert not session.found and session.n_rejected == 2
    assert session.colliding[0] == pytest.approx(d1, abs=1e-12)
    np.testing.assert_array_equal(session.colliding[1], SOLS[1])


def test_local_starts_rejects_ends_in_collision_in_the_compiled_loop():
    session = _session(guard=elbow_guard(SOLS[0]))
    near_0 = SOLS[0] + np.array([[1e-3, -1e-3], [-1e-3, 2e-3]])
    assert not session.local_starts(near_0)
    assert session.n_rejected == 2 and not session.found
    d, q = session.colliding
    assert d == pytest.approx(-0.1, abs=1e-6) and wrapped(q, SOLS[0]).max() < 1e-6
    assert session.local_starts(SOLS[1] + np.array([[1e-3, -1e-3]]))
    assert len(session.found) == 1 and wrapped(session.found[0], SOLS[1]).max() < 1e-6
