"""Collision-aware solve_ik / solve_ik_batch / solve_path (moik/solver/collision.py):
answers checked by coal, forced collisions give "collides", defaults unchanged, bad input."""

import importlib

import numpy as np
import pytest

from moik import get_robot, solve_ik
from moik.collision import Box, CollisionChecker, HalfSpace, Scene, Sphere
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.exceptions import GeometryError, MoikError, ParameterError
from moik.problems.targets import as_target
from moik.solver import solve_ik_batch, solve_ik_pareto, solve_path
from moik.solver.batch import child_seeds
from moik.solver.collision import collision_guard, default_model
from moik.solver.session import pose_errors

coal = pytest.importorskip("coal")
from tests.coal_oracle import coal_distances  # noqa: E402  (after the skip)

TOL = 1e-9


def coal_min(checker, q):
    """The smallest signed distance over the checker's pairs, by coal (independent)."""
    return float(coal_distances(checker, q).min())


@pytest.fixture(scope="module")
def world():
    model = default_model(get_robot("panda"))  # the solve's own: the URDF's meshes
    scene = Scene({"table": HalfSpace.plane([0, 0, 1], 0.0),
                   "box": Box(size=(0.2, 0.2, 0.2), pose=rpy_pose([0.5, 0.0, 0.4])),
                   "ball": Sphere(radius=0.1, pose=rpy_pose([0.0, 0.5, 0.5]))},
                  allowed=frozenset({("table", model.links[0]), ("table", model.links[1])}))
    checker = CollisionChecker(model=model, scene=scene, self_collision=True)
    Q = model.robot.random_q(400, rng=np.random.default_rng(7))
    free = Q[checker.min_distance(Q) >= 0.0][:12]
    return model, scene, checker, model.robot.fk(free)


def _check_answer(robot, checker, target, q, clearance):
    assert np.all(q >= robot.lower) and np.all(q <= robot.upper)
    pos, ori = pose_errors(robot, as_target(target), q, reference=True)
    assert pos[0] <= TOL * robot.reach and ori[0] <= TOL
    assert coal_min(checker, q) >= clearance - 1e-9


def test_answers_are_collision_free_by_coal(world):
    model, scene, checker, T = world
    robot, blind_hits = model.robot, 0
    for k, pose in enumerate(T):
        res = solve_ik(robot, pose, seed=k, scene=scene, self_collision=True)
        assert res.status == "solved"
        _check_answer(robot, checker, pose, res.q, 0.0)
        assert res.min_distance == pytest.approx(coal_min(checker, res.q), abs=1e-9)
        blind = solve_ik(robot, pose, seed=k)
        blind_hits += blind.success and coal_min(checker, blind.q) < 0.0
    assert blind_hits > 0  # the check made a difference on these targets


def test_clearance_and_several_solutions(world):
    model, scene, checker, T = world
    res = solve_ik(model.robot, T[0], seed=0, scene=scene, self_collision=True,
                   clearance=0.01, n_solutions=3)
    assert res.success and len(res.solutions) >= 1
    assert res.distances is not None and np.all(res.distances >= 0.01)
    for q in res.solutions:
        _check_answer(model.robot, checker, T[0], q, 0.01)


def test_target_inside_obstacle_collides(world):
    model, scene, checker, _ = world
    res = solve_ik(model.robot, [0.5, 0.0, 0.4], seed=0, scene=scene, starts=40,
                   patience=1, max_evals=5000)
    assert res.status == "collides" and not res.success and len(res.solutions) == 0
    assert res.min_distance < 0.0
    # in contact: a mesh link's depth is its hulls' overlap along their centres, never less
    # deep than coal's exact depth (a primitive pair's is exact)
    assert res.min_distance <= coal_min(checker, res.q) + 1e-9
    pos, _ = pose_errors(model.robot, as_target([0.5, 0.0, 0.4]), res.q)
    assert pos[0] <= TOL * model.robot.reach  # the best answer is exact, only colliding
    assert "rejected for collision" in res.detail


def test_clearance_beyond_reach_collides(world):
    model, scene, _, T = world
    res = solve_ik(model.robot, T[1], seed=0, scene=scene, clearance=5.0, starts=20,
                   patience=1, max_evals=3000)
    assert res.status == "collides" and not res.success
    assert 0.0 <= res.min_distance < 5.0


def test_defaults_unchanged(world):
    model, _, _, T = world
    a = solve_ik(model.robot, T[2], seed=4)
    b = solve_ik(model.robot, T[2], seed=4, scene=None, self_collision=False, clearance=0.0)
    assert np.array_equal(a.q, b.q) and a.n_eval == b.n_eval and a.status == b.status
    assert a.min_distance is None and a.distances is None


def test_checker_as_geometry(world):
    model, scene, checker, T = world
    res = solve_ik(model.robot, T[3], seed=1, collision=checker)
    assert res.success and coal_min(checker, res.q) >= 0.0


def test_batch_verdicts_equal_solve_ik(world):
    model, scene, checker, T = world
    b = solve_ik_batch(model.robot, T[:6], seed=5, scene=scene, self_collision=True)
    assert b.min_distance is not None and np.all(b.success)
    for i, s in enumerate(child_seeds(5, 6)):
        r = solve_ik(model.robot, T[i], seed=s, scene=scene, self_collision=True)
        assert np.array_equal(r.q, b.q[i]) and r.status == b.status[i]
        _check_answer(model.robot, checker, T[i], b.q[i], 0.0)
    forced = solve_ik_batch(model.robot, np.array([[0.5, 0.0, 0.4]]), scene=scene, starts=40,
                            patience=1, max_evals=5000)
    assert forced.status[0] == "collides" and not forced.success[0]


def test_batch_distances_are_exact_when_read(world):
    """The batch tests each answer's clearance at the end and measures its exact distance
    at the first read of min_distance: the values solve_ik reports, coal's within the
    hulls' margin, and the full measure runs once."""
    model, scene, checker, T = world
    b = solve_ik_batch(model.robot, T[:6], seed=5, scene=scene, self_collision=True)
    assert b.distances is not None and not b.distances._known.all()  # not measured yet
    d = b.min_distance
    assert d is b.min_distance and b.distances._known.all()  # measured once, kept
    guard = collision_guard(model.robot, scene=scene, self_collision=True)
    np.testing.assert_array_equal(d, guard.distances(b.q))
    for i, s in enumerate(child_seeds(5, 6)):
        r = solve_ik(model.robot, T[i], seed=s, scene=scene, self_collision=True)
        assert r.min_distance == d[i]
        assert 0.0 <= d[i] <= coal_min(checker, b.q[i]) + 1e-9  # the hulls hold the meshes
    below = guard.below(b.q)  # the clearance test: at least the clearance, not measured
    assert np.all(below >= 0.0)


def test_path_waypoints_collision_free(world):
    model, scene, checker, T = world
    res = solve_path(model.robot, list(T[:3]), scene=scene, self_collision=True,
                     first_branches=1)
    assert res.min_distances is not None and np.all(res.success)
    for pose, q in zip(T[:3], res.Q, strict=True):
        _check_answer(model.robot, checker, pose, q, 0.0)


@pytest.mark.parametrize("kwargs, error", [
    ({"scene": 42}, GeometryError),
    ({"scene": "scene", "clearance": float("nan")}, ParameterError),
    ({"scene": "scene", "clearance": -0.1}, ParameterError),
    ({"scene": "scene", "collision": "ur5-model"}, GeometryError),
    ({"scene": "scene", "collision": "not a model"}, GeometryError),
    ({"clearance": 0.1}, ParameterError),
    ({"collision": "checker", "scene": "scene"}, ParameterError),
    ({"scene": "scene", "self_collision": 1}, ParameterError),
])
def test_bad_input(world, kwargs, error):
    model, scene, checker, T = world
    subst = {"scene": scene, "ur5-model": collision_model("ur5"), "checker": checker}
    kw = {k: subst.get(v, v) if isinstance(v, str) else v for k, v in kwargs.items()}
    for call in (lambda: solve_ik(model.robot, T[0], **kw),
                 lambda: solve_ik_batch(model.robot, T[:1], **kw)):
        with pytest.raises(error) as info:
            call()
        assert isinstance(info.value, MoikError)


def test_pareto_clearance_criterion(world):
    model, scene, checker, T = world
    res = solve_ik_pareto(model.robot, T[0], objectives=("clearance", "manipulability"),
                          scene=scene, self_collision=True, clearance=0.005, seed=0, starts=32,
                          generations=3, local_iterations=2, n_solutions=8)
    assert res.objectives[0] == "clearance" and res.senses[0] == "max" and len(res.X)
    for q, f in zip(res.X, res.F[:, 0], strict=True):
        assert f == pytest.approx(coal_min(checker, q), abs=1e-9) and f >= 0.005
        _check_answer(model.robot, checker, T[0], q, 0.005)
    with pytest.raises(ParameterError, match="clearance"):
        solve_ik_pareto(model.robot, T[0], objectives=("clearance", "manipulability"))


def test_pareto_constraint_form_keeps_feasible_members(world):
    """Collision is a constraint of the search, not a filter at the end: a colliding exact
    point never enters the archive, so it cannot push out the feasible ones it dominates
    (filtered at the end, targets 1-4 here returned no member though solve_ik solves them)."""
    model, scene, checker, T = world
    for k in range(1, 5):
        kwargs = {"scene": scene, "self_collision": True, "clearance": 0.01, "seed": k}
        assert solve_ik(model.robot, T[k], **kwargs).status == "solved"
        res = solve_ik_pareto(model.robot, T[k], objectives=("manipulability", "limit_margin"),
                              n_solutions=10, **kwargs)
        assert len(res.X) >= 1
        for q in res.X:
            _check_answer(model.robot, checker, T[k], q, 0.01)


def test_collision_proof_ends_a_target_whose_hand_is_in_an_obstacle(world, monkeypatch):
    """A pose putting the hand in the box: every exact answer collides, which the target
    alone proves (the last body vs the box); the search is skipped, and a full search
    without the proof finds nothing collision-free either (the proof's soundness here)."""
    model, scene, checker, _ = world
    robot = model.robot
    pose = np.eye(4)
    pose[:3, :3] = np.diag([1.0, -1.0, -1.0])  # pointing down, into the box's top
    pose[:3, 3] = [0.5, 0.0, 0.45]
    res = solve_ik(robot, pose, seed=0, scene=scene)
    assert res.status == "collides" and "proven" in res.detail and "box" in res.detail
    pos, ori = pose_errors(robot, as_target(pose), res.q, reference=True)
    assert pos[0] <= TOL * robot.reach and ori[0] <= TOL  # exact, only colliding
    last = [k for k, (a, b) in enumerate(checker.pair_bodies)
            if a == robot.dof and checker.pair_names[k][1] == "box"]
    assert last and coal_distances(checker, res.q)[last].min() < 0.0  # coal: the hand is in it
    solve_ik_module = importlib.import_module("moik.solver.solve_ik")  # not the function
    monkeypatch.setattr(solve_ik_module, "collision_proven", lambda session: False)
    full = solve_ik(robot, pose, seed=0, scene=scene, max_evals=20_000)
    assert full.status == "collides" and full.n_eval > 5 * res.n_eval


def test_collision_proof_never_for_what_the_target_does_not_place(world):
    """A position target leaves the hand free to turn: only base and obstacle pairs (none
    checked here but the table's allowed ones) can prove a collision, so the search runs."""
    model, scene, _, _ = world
    guard = collision_guard(model.robot, scene=scene, self_collision=True)
    bodies = guard.checker.pair_bodies
    q = model.robot.random_q(1, rng=np.random.default_rng(0))[0]
    d_pose, pair_pose, least = guard.target_bound(q, True)
    d_pos, pair_pos, _ = guard.target_bound(q, False)
    fixed = {-1, 0, model.robot.dof}
    expected = min((d for d, (a, b) in zip(guard.checker.distances(q), bodies, strict=True)
                    if a in fixed and b in fixed), default=np.inf)
    assert d_pose == pytest.approx(expected, abs=1e-12) and least <= d_pose
    assert pair_pos is None or model.robot.dof not in {
        bodies[guard.checker.pair_names.index(pair_pos)][0]}
    assert d_pos >= d_pose
