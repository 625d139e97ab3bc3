"""A checker's arrays as one compiled value (CollisionSet) and the start loop's collision
test (end_distance, end_scratch, checks_pairs), in compiled code and from Python.

Hand case: planar2 (tool at ``0.35 u(q1) + 0.30 u(q1 + q2)``, ``u(a) = (cos a, sin a, 0)``,
frame 2 = the tool) with a sphere of radius 0.05 on the tool and world spheres of radius
0.1 at ``c``: the signed distance is ``|tool(q) - c| - 0.15``.
"""

import numpy as np
import pytest

from moik._jit import jit
from moik.collision import CollisionChecker, CollisionModel, Scene, Sphere
from moik.collision.compiled import (
    checks_pairs,
    collision_set,
    end_distance,
    end_scratch,
    n_pairs,
    set_distance_below,
    set_scratch,
)
from moik.collision.distance import SPHERE
from moik.robots import get_robot

ARM = get_robot("planar2")
CENTRES = np.array([[0.0, 0.7, 0.0], [0.7, 0.0, 0.0]])


def _tool(q):
    return np.array([0.35 * np.cos(q[0]) + 0.30 * np.cos(q[0] + q[1]),
                     0.35 * np.sin(q[0]) + 0.30 * np.sin(q[0] + q[1]), 0.0])


def _set(pairs):
    local = np.tile(np.eye(4), (3, 1, 1))
    local[1:, :3, 3] = CENTRES
    return collision_set(chain=ARM.chain_model, body=np.array([2, -1, -1]), local=local,
                         kinds=np.full(3, SPHERE), sizes=np.array([[0.05, 0, 0], [0.1, 0, 0],
                                                                   [0.1, 0, 0]]),
                         pairs=np.array(pairs, dtype=np.int64).reshape(-1, 2),
                         hull_points=np.zeros((0, 3)), hull_ranges=np.zeros((0, 2), dtype=np.int64))


@jit
def _in_compiled_code(cs, q):
    """The start loop's calls, compiled for the type of ``cs`` (a set or None)."""
    return checks_pairs(cs), end_distance(cs, q, end_scratch(cs), np.inf)


Q = ARM.random_q(6, rng=np.random.default_rng(0))


def test_the_smallest_distance_over_the_pairs_by_hand():
    cs = _set([[0, 1], [0, 2]])
    assert n_pairs(cs) == 2
    scratch = set_scratch(cs)
    for q in Q:
        expected = min(np.linalg.norm(_tool(q) - c) for c in CENTRES) - 0.15
        assert set_distance_below(cs, q, scratch, np.inf) == pytest.approx(expected, abs=1e-14)
    one = _set([[0, 2]])  # only the second obstacle
    for q in Q:
        expected = np.linalg.norm(_tool(q) - CENTRES[1]) - 0.15
        d = set_distance_below(one, q, set_scratch(one), np.inf)
        assert d == pytest.approx(expected, abs=1e-14)


def test_a_set_without_pairs_checks_nothing():
    cs = _set([])
    assert n_pairs(cs) == 0 and not checks_pairs(cs)
    assert set_distance_below(cs, Q[0], set_scratch(cs), np.inf) == np.inf
    assert _in_compiled_code(cs, Q[0]) == (False, np.inf)


def test_the_start_loops_test_compiled_for_a_set_and_for_none():
    cs = _set([[0, 1], [0, 2]])
    for q in Q[:3]:
        checks, d = _in_compiled_code(cs, q)
        assert checks and d == set_distance_below(cs, q, set_scratch(cs), np.inf)
        assert end_distance(cs, q, end_scratch(cs), np.inf) == d  # the Python path agrees
    assert _in_compiled_code(None, Q[0]) == (False, np.inf)
    assert end_scratch(None) == 0


def test_a_checkers_compiled_value_is_the_same_set():
    """The checker builds its set from the same shapes: the same distances."""
    model = CollisionModel(robot=ARM, shapes={"link2": Sphere(radius=0.05)})
    poses = [np.eye(4), np.eye(4)]
    poses[0][:3, 3], poses[1][:3, 3] = CENTRES
    scene = Scene({"a": Sphere(radius=0.1, pose=poses[0]),
                   "b": Sphere(radius=0.1, pose=poses[1])})
    compiled = CollisionChecker(model=model, scene=scene).compiled
    cs = _set([[0, 1], [0, 2]])
    assert n_pairs(compiled) == 2
    for q in Q:
        assert set_distance_below(compiled, q, set_scratch(compiled), np.inf) == pytest.approx(
            set_distance_below(cs, q, set_scratch(cs), np.inf), abs=1e-15)


def test_collision_set_takes_keywords_only():
    with pytest.raises(TypeError):
        collision_set(ARM.chain_model, np.zeros(1, dtype=np.int64), np.eye(4)[None],
                      np.zeros(1, dtype=np.int64), np.zeros((1, 3)),
                      np.zeros((0, 2), dtype=np.int64))


def test_a_mesh_arms_set_compiles_bounds_only_and_measures_the_same():
    """A mesh arm's set (iiwa14: every primitive pair but capsule-capsule a compound's bound) is a
    CompoundSet, whose bounds of boxes and half-spaces come from GJK and the support
    function instead of the closed forms: its distances (exact ones from the hulls) are the
    general set's bit for bit where free (the same verdicts elsewhere), and each bound is at
    most the exact distance of the bounds."""
    from moik.collision import Box, HalfSpace
    from moik.collision.compiled import CollisionSet, CompoundSet, _new_set, bounds_only
    from moik.collision.io import rpy_pose
    from moik.collision.kernels import distance_scratch, min_distances, place_all, shape_pair
    from moik.collision.pairs import pair_distance
    from moik.collision.urdf import robot_model

    panda = get_robot("iiwa14")
    scene = Scene({"table": HalfSpace.plane([0, 0, 1], -0.02),
                   "box": Box(size=[0.3, 0.2, 0.4],
                              pose=rpy_pose([0.45, 0.1, 0.35], [0.3, 0, 1])),
                   "ball": Sphere(radius=0.1, pose=rpy_pose([0.1, -0.5, 0.5]))},
                  allowed={("table", "base_link")})
    checker = CollisionChecker(model=robot_model(panda), scene=scene, self_collision=True)
    cs = checker.compiled
    assert type(cs) is CompoundSet
    boxed = CollisionChecker(model=robot_model(get_robot("panda")), scene=scene.__class__(
        scene.obstacles), self_collision=True)  # panda_link7 has box primitives: exact kernels
    assert type(boxed.compiled) is CollisionSet
    arrays = checker.compiled_arrays
    assert bounds_only(arrays["kinds"], arrays["pairs"], arrays["refine"])
    general = _new_set(panda.chain_model, tuple(arrays[k] for k in ("body", "local", "kinds",
                                                                     "sizes")),
                       (arrays["pairs"], arrays["refine"]),
                       tuple(arrays[k] for k in ("hull_points", "hull_ranges", "hull_caps")))
    assert type(general) is CollisionSet
    Q = np.ascontiguousarray(panda.random_q(300, rng=np.random.default_rng(5)))
    out = []
    for s in (cs, general):
        d, which = np.empty(len(Q)), np.empty(len(Q), dtype=np.int64)
        min_distances(s, Q, d, which)
        out.append((d, which))
    (d, which), (d_general, which_general) = out
    free = d_general >= 0.0
    assert free.any() and (~free).any()  # both kinds of verdict
    np.testing.assert_array_equal(d[free], d_general[free])  # a distance: the hulls' own
    np.testing.assert_array_equal(which[free], which_general[free])
    # in collision the same verdict; the depth reported is a hull's GJK overlap (an upper
    # bound of the depth), which the general set's exact bounds may prune to another pair's
    assert (d[~free] < 0.0).all() and (d[~free] <= d_general[~free]).all()
    # the bounds: GJK / support against the closed forms, on the tops' pairs with a box or
    # a half-space
    kinds, sizes, pairs = arrays["kinds"], arrays["sizes"], arrays["pairs"]
    tops = [k for k in range(len(pairs)) if 1 < max(kinds[pairs[k]]) < 4]
    assert tops
    scratch = distance_scratch(cs)
    W = scratch[2]
    compared = 0
    for q in Q[:60]:
        place_all(cs, q, scratch)
        for k in tops:
            a, b = pairs[k]
            bound = shape_pair(cs, W, a, b, np.inf)[0]
            exact = pair_distance(kinds[a], W[a], sizes[a], kinds[b], W[b], sizes[b])[0]
            assert bound <= exact + 1e-9 * max(1.0, abs(exact))
            if exact > 0:
                assert bound >= exact - 1e-8  # separated: GJK's bound is the distance
            compared += 1
    assert compared > 100
