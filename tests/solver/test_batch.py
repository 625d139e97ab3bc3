"""solve_ik_batch: one call, each target answered as solve_ik would, independent of the batch."""

import os
import signal
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from moik import solve_ik, solve_ik_batch
from moik.collision import CollisionChecker, HalfSpace, Scene
from moik.exceptions import NonFiniteError, ParameterError, ShapeError, TargetError
from moik.problems import random_reachable_targets
from moik.robots import get_robot
from moik.solver import batch, parallel
from moik.solver.batch import child_seeds
from moik.solver.collision import default_model


@pytest.mark.parametrize("name", ["eosma7", "ur5", "scara4"])
def test_batch_equals_one_by_one(name):
    robot = get_robot(name)
    poses = np.array([t.pose for t in random_reachable_targets(robot, 12, seed=4)])
    res = solve_ik_batch(robot, poses, seed=3)
    seeds = child_seeds(3, len(poses))
    for i, pose in enumerate(poses):
        one = solve_ik(robot, pose, seed=seeds[i])
        np.testing.assert_array_equal(res.q[i], one.q)
        assert res.status[i] == one.status and res.n_eval[i] == one.n_eval
        assert res.position_error[i] == one.position_error
        assert res.orientation_error[i] == one.orientation_error
    assert res.success.all() and res.q.shape == (12, robot.dof)


def test_a_targets_answer_does_not_depend_on_the_others():
    robot = get_robot("puma560")
    poses = np.array([t.pose for t in random_reachable_targets(robot, 10, seed=8)])
    full = solve_ik_batch(robot, poses, seed=1)
    other = poses.copy()
    other[1:] = np.array([t.pose for t in random_reachable_targets(robot, 9, seed=9)])
    mixed = solve_ik_batch(robot, other, seed=1)
    np.testing.assert_array_equal(full.q[0], mixed.q[0])  # same index, same seed, same target


def test_positions_q_current_and_the_hard_tail():
    robot = get_robot("eosma7")
    targets = random_reachable_targets(robot, 4, seed=2, with_orientation=False)
    positions = np.array([t.position for t in targets])
    far = np.array([[3.0 * robot.reach, 0.0, 0.0]])  # out of reach: solve_ik's verdict path
    q_current = robot.random_q(1, rng=np.random.default_rng(0))[0]
    res = solve_ik_batch(robot, np.vstack([positions, far]), seed=0, q_current=q_current)
    assert list(res.status) == ["solved"] * 4 + ["unreachable"]
    assert res.position_error[-1] >= 2.0 * robot.reach - 1e-9
    seeds = child_seeds(0, 5)
    for i in range(5):
        one = solve_ik(robot, np.vstack([positions, far])[i], seed=seeds[i], q_current=q_current)
        np.testing.assert_array_equal(res.q[i], one.q)
    assert np.all(robot.within_limits(res.q))


@pytest.mark.parametrize(("targets", "error", "match"), [
    (np.zeros((0, 4, 4)), ShapeError, "empty batch"),
    (np.zeros((3, 4)), ShapeError, r"\(n, 4, 4\) \(poses\) or \(n, 3\)"),
    (np.array([[0.0, np.nan, 1.0]]), NonFiniteError, "finite"),
    (np.ones((2, 4, 4)), TargetError, "last row"),
    ([["a", "b", "c"]], ShapeError, "array of real numbers"),
    (np.array([np.eye(4), np.diag([1.0, 1.0, -1.0, 1.0])]), TargetError,
     r"targets\[1\]: rotation must be a rotation matrix"),
    (np.array([[30.0, 0.0, 50.0], [30.0, 0.0, 50.0], [4000.0, 0.0, 0.0]]), TargetError,
     r"targets\[2\]: position .* more than 10x its reach"),
])
def test_bad_batches_raise_clear_errors(targets, error, match):
    with pytest.raises(error, match=match):
        solve_ik_batch(get_robot("eosma7"), targets)


def test_bad_options_and_q_current():
    robot = get_robot("eosma7")
    poses = np.array([t.pose for t in random_reachable_targets(robot, 2, seed=1)])
    with pytest.raises(ParameterError, match="n_solutions"):
        solve_ik_batch(robot, poses, n_solutions=2)
    with pytest.raises(ParameterError, match=r"unknown parameter\(s\) pop_sise"):
        solve_ik_batch(robot, poses, pop_sise=3)
    with pytest.raises(ShapeError, match="q_current must be"):
        solve_ik_batch(robot, poses, q_current=np.zeros((3, 7)))
    rot = poses.copy()
    rot[0, :3, :3] *= 2.0
    with pytest.raises(TargetError, match="rotation"):
        solve_ik_batch(robot, rot)
    assert solve_ik_batch("eosma7", poses[:1]).success[0]  # a catalog name is accepted


FIELDS = ("q", "status", "position_error", "orientation_error", "success", "n_eval",
          "min_distance")


def assert_same(a, b):
    """Two batch results equal bit for bit (NaN where NaN)."""
    for field in FIELDS:
        x, y = getattr(a, field), getattr(b, field)
        if x is None or y is None:
            assert x is None and y is None, field
        else:
            np.testing.assert_array_equal(x, y, err_msg=field)


def _mixed_batch(robot, n, seed):
    """Reachable poses and two out of reach (the hard tail: solve_ik, in a process pool)."""
    poses = robot.fk(robot.random_q(n, rng=np.random.default_rng(seed)))
    poses[[7, n - 3], :3, 3] += 3.0 * robot.reach
    return poses


def test_answers_are_the_same_for_every_worker_count(monkeypatch):
    monkeypatch.setattr(parallel, "POOL_AFTER_S", 0.0)  # the tail on a pool at once
    robot = get_robot("panda")
    poses = _mixed_batch(robot, 300, 5)
    one = solve_ik_batch(robot, poses, seed=2, workers=1)
    assert list(np.flatnonzero(~one.success)) == [7, 297] and one.success.sum() == 298
    for workers in (2, 3):
        assert_same(one, solve_ik_batch(robot, poses, seed=2, workers=workers))
    seeds = child_seeds(2, len(poses))
    for i in (0, 7, 200, 297):  # and each as solve_ik answers it alone
        np.testing.assert_array_equal(one.q[i], solve_ik(robot, poses[i], seed=seeds[i]).q)


def test_a_tail_solved_beside_the_chunks_gives_the_same_answers(monkeypatch):
    """Tail targets solved in this thread while chunks still run (``busy`` forced: all of
    them) are answered as the tail after the chunks answers them."""
    robot = get_robot("panda")
    poses = _mixed_batch(robot, 300, 5)
    one = solve_ik_batch(robot, poses, seed=2, workers=1)
    run, early = parallel.map_chunks, []

    def always_busy(fn, n, workers, then=None):
        def then_busy(lo, hi, busy):
            early.append((lo, hi))
            then(lo, hi, lambda: True)
        run(fn, n, workers, then=then_busy)

    monkeypatch.setattr(parallel, "map_chunks", always_busy)
    monkeypatch.setattr(batch, "_tail_target", _counted(batch._tail_target, tails := []))
    assert_same(one, solve_ik_batch(robot, poses, seed=2, workers=2))
    assert len(early) > 1 and sorted(tails) == [7, 297]  # each tail target solved once


def _counted(fn, calls):
    def counted(job, i):
        calls.append(i)
        return fn(job, i)
    return counted


def test_collision_aware_answers_are_the_same_for_every_worker_count(monkeypatch):
    monkeypatch.setattr(parallel, "POOL_AFTER_S", 0.0)
    robot = get_robot("panda")
    model = default_model(robot)  # the geometry the solves check
    table = Scene({"table": HalfSpace.plane([0, 0, 1], 0.0)},
                  allowed=frozenset([("table", model.links[0]), ("table", model.links[1])]))
    checker = CollisionChecker(model=model, scene=table, self_collision=True)
    Q = robot.random_q(400, rng=np.random.default_rng(6))
    d = checker.min_distance(Q)
    Q = np.vstack([Q[d >= 0][:294], Q[d < 0][:6]])  # six poses reached only in collision
    poses = robot.fk(Q)
    kw = {"seed": 1, "scene": table, "self_collision": True}
    one = solve_ik_batch(robot, poses, workers=1, **kw)
    assert one.min_distance is not None and (one.status == "collides").any()
    assert_same(one, solve_ik_batch(robot, poses, workers=2, **kw))
    if parallel.can_fork():  # more workers: the tail in processes started before the chunks
        submitted: list = []

        class Recorded(parallel.TaskPool):
            def submit(self, items):
                items = list(items)
                submitted.extend(items)
                super().submit(items)

        monkeypatch.setattr(parallel, "TaskPool", Recorded)
        four = solve_ik_batch(robot, poses, workers=4, **kw)
        assert_same(one, four)
        tail = np.flatnonzero(one.status != "solved")
        assert len(submitted) == len(set(submitted)) and set(tail) <= set(submitted) != set()


def test_a_dask_cluster_gives_the_same_answers():
    distributed = pytest.importorskip("distributed")
    robot = get_robot("panda")
    poses = _mixed_batch(robot, 300, 7)
    serial = solve_ik_batch(robot, poses, seed=4, workers=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        chunks = []
        on_dask = solve_ik_batch(robot, poses, seed=4, client=client, progress=chunks.append)
    assert_same(serial, on_dask)
    assert sum(chunks) == len(poses) and len(chunks) > 1  # several chunks, each counted once


def test_a_lost_dask_worker_reruns_its_chunk():
    """A worker process killed while it solves a chunk: the scheduler runs the chunk again
    elsewhere; no target is lost or answered twice, the answers are the serial ones."""
    distributed = pytest.importorskip("distributed")
    robot = get_robot("panda")
    poses = _mixed_batch(robot, 300, 8)
    serial = solve_ik_batch(robot, poses, seed=5, workers=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        pool = ThreadPoolExecutor(1)
        batch = pool.submit(solve_ik_batch, robot, poses, seed=5, client=client)
        busy: list = []
        while not busy and not batch.done():  # a worker busy with a chunk (loading moik)
            busy = [w for w, tasks in client.processing().items() if tasks]
            time.sleep(0.02)
        assert busy, "the batch ended before a worker could be killed"
        pids = client.run(os.getpid, workers=busy[:1])
        os.kill(pids[busy[0]], signal.SIGKILL)
        on_dask = batch.result(timeout=120)
        pool.shutdown()
    assert_same(serial, on_dask)


def test_progress_must_be_a_function():
    """Before: progress=5 ran the first chunk, then raised TypeError: 'int' object is not
    callable."""
    with pytest.raises(ParameterError, match="progress must be a function"):
        solve_ik_batch("panda", np.array([[0.4, 0.1, 0.5]]), progress=5)


def test_status_codes_read_as_numpy_reads_the_names():
    """The batch keeps a status code per target (no Python string per row); its names are
    the strings numpy's astype(str) gives, as wide as the longest present."""
    from moik.solver.solve_ik import STATUSES
    rng = np.random.default_rng(2)
    for codes in ([0, 0, 0], [2, 0], [3, 1, 0, 2], list(rng.integers(0, 4, 50)), [1]):
        codes = np.array(codes, dtype=np.int8)
        names = batch.status_names(codes)
        expected = np.array([STATUSES[c] for c in codes], dtype=object).astype(str)
        assert names.dtype == expected.dtype and np.array_equal(names, expected)
