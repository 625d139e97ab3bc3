"""CollisionModel, Scene and the compiled checker: against coal on random configurations,
the gradient against finite differences, and the model's validation."""

import numpy as np
import pytest

from moik import get_robot
from moik.collision import Box, Capsule, CollisionChecker, CollisionModel, HalfSpace, Scene, Sphere
from moik.collision.catalog import collision_model
from moik.collision.io import rpy_pose
from moik.exceptions import GeometryError, ParameterError, UnknownNameError

coal = pytest.importorskip("coal")


from tests.coal_oracle import coal_distances as _coal_min  # noqa: E402  (after the skip)


def _scene():
    return Scene({"table": HalfSpace.plane([0, 0, 1], -0.1),
                  "shelf": Box(size=(0.3, 0.8, 0.03), pose=rpy_pose([0.55, 0, 0.45])),
                  "ball": Sphere(radius=0.08, pose=rpy_pose([0.3, 0.4, 0.3])),
                  "post": Capsule(radius=0.04, length=0.6, pose=rpy_pose([-0.4, 0.3, 0.3]))})


@pytest.mark.parametrize("name", ["panda", "ur5", "iiwa14"])
def test_distances_match_coal_on_random_configurations(name):
    checker = CollisionChecker(model=collision_model(name), scene=_scene(), self_collision=True)
    Q = checker.robot.random_q(30, rng=np.random.default_rng(3))
    D = checker.distances(Q)
    for q, d in zip(Q, D, strict=True):
        np.testing.assert_allclose(d, _coal_min(checker, q), rtol=0, atol=1e-9)
    np.testing.assert_array_equal(checker.min_distance(Q), D.min(axis=1))


@pytest.mark.parametrize("name", ["panda", "ur5", "iiwa14"])
def test_pruned_minimum_is_the_minimum_over_every_pair(name):
    """The broad phase skips pairs, never the minimum: min_distance and closest_pair
    equal the minimum (and first pair attaining it) of every pair's distance."""
    checker = CollisionChecker(model=collision_model(name), scene=_scene(), self_collision=True)
    Q = checker.robot.random_q(500, rng=np.random.default_rng(11))
    D = checker.distances(Q)
    np.testing.assert_array_equal(checker.min_distance(Q), D.min(axis=1))
    for q, d in zip(Q[:50], D[:50], strict=True):
        assert checker.closest_pair(q)[1] == checker.pair_names[int(np.argmin(d))]


def test_gradient_matches_finite_differences():
    checker = CollisionChecker(model=collision_model("panda"), scene=_scene(),
                               self_collision=True)
    rng = np.random.default_rng(5)
    checked = 0
    for q in checker.robot.random_q(20, rng=rng):
        d, g = checker.min_distance_and_gradient(q)
        if d < 0.005:  # penetrating box pairs use the contact-normal approximation
            continue
        eps = 1e-6
        fd = np.array([(checker.min_distance(q + eps * e) - checker.min_distance(q - eps * e))
                       / (2 * eps) for e in np.eye(q.size)])
        np.testing.assert_allclose(g, fd, atol=1e-5)
        checked += 1
    assert checked >= 5


def test_model_validation():
    robot = get_robot("planar2")
    with pytest.raises(UnknownNameError, match="link0, link1, link2"):
        CollisionModel(robot=robot, shapes={"forearm": Sphere(radius=0.1)})
    with pytest.raises(GeometryError, match="half-space"):
        CollisionModel(robot=robot, shapes={"link1": HalfSpace()})
    with pytest.raises(GeometryError, match="must be moik.collision shapes"):
        CollisionModel(robot=robot, shapes={"link1": [0.1]})
    with pytest.raises(UnknownNameError):
        CollisionModel(robot=robot, shapes={}, allowed=frozenset({frozenset(("link0", "x"))}))
    with pytest.raises(GeometryError, match="3 distinct names"):
        CollisionModel(robot=robot, shapes={}, links=("a", "b"))


def test_self_collision_switch_and_adjacency():
    robot = get_robot("planar2")
    model = CollisionModel(robot=robot, shapes={"link0": Sphere(radius=0.05),
                                                "link1": Sphere(radius=0.05),
                                                "link2": Sphere(radius=0.05)})
    assert model.checked_body_pairs() == [(0, 2)]
    assert CollisionChecker(model=model, self_collision=True).n_pairs == 1
    with pytest.raises(ParameterError, match="nothing to check"):  # never a silent inf
        CollisionChecker(model=model, self_collision=False)
    # folded back, the tool sphere meets the base sphere: a2 = 0.30 < a1 = 0.35
    checker = CollisionChecker(model=model, self_collision=True)
    d, pair = checker.closest_pair(np.array([0.0, np.pi]))
    assert pair == ("link0", "link2") and d == pytest.approx(0.05 - 0.1)


def test_end_distance_from_python_equals_the_checker():
    """The start loop's collision test (moik.collision.compiled) called from Python: the
    checker's minimum distance, and inf / no pairs without a collision set."""
    from moik.collision.compiled import checks_pairs, end_distance, end_scratch

    checker = CollisionChecker(model=collision_model("panda"), scene=_scene(),
                               self_collision=True)
    q = checker.robot.random_q(1, rng=np.random.default_rng(2))[0]
    cs = checker.compiled
    assert checks_pairs(cs) and not checks_pairs(None)
    d = checker.min_distance(q)
    assert end_distance(cs, q, end_scratch(cs), np.inf) == d
    assert end_distance(cs, q, end_scratch(cs), d + 1e-3) == d  # below the clearance: exact
    assert end_distance(cs, q, end_scratch(cs), d - 1e-3) >= d - 1e-3  # above: a bound
    assert end_distance(None, q, end_scratch(None), 0.0) == np.inf
    Q = checker.robot.random_q(50, rng=np.random.default_rng(3))
    np.testing.assert_array_equal(checker.min_distance_batch(Q), checker.min_distance(Q))
    with pytest.raises(ParameterError, match="nothing to check"):
        CollisionChecker(model=collision_model("panda"), self_collision=False)


def test_shapes_listed_out_of_body_order_keep_their_pairs():
    """A model whose shapes are given last body first checks the same body pairs."""
    robot = get_robot("panda")
    shapes = {"link7": Sphere(radius=0.05), "link0": Sphere(radius=0.05),
              "link3": Sphere(radius=0.05)}
    checker = CollisionChecker(model=CollisionModel(robot=robot, shapes=shapes),
                               self_collision=True)
    assert sorted(tuple(sorted(p)) for p in checker.pair_bodies) == [(0, 3), (0, 7), (3, 7)]


def test_self_pairs_are_every_item_pair_of_a_checked_body_pair_in_order():
    """The checker's self pairs: each pair of shapes a < b (in the model's item order) whose
    bodies are a checked pair, every one once and in that order, on a model with several
    shapes per body and bodies listed out of order."""
    robot = get_robot("panda")
    rng = np.random.default_rng(2)
    names = ["link7", "link0", "link3", "link5", "link1"]
    shapes = {n: [Sphere(radius=0.02, pose=np.block([[np.eye(3), rng.uniform(-0.05, 0.05, (3, 1))],
                                                      [np.zeros((1, 3)), np.ones((1, 1))]]))
                  for _ in range(int(rng.integers(1, 4)))] for n in names}
    model = CollisionModel(robot=robot, shapes=shapes).with_allowed([("link0", "link5")])
    checker = CollisionChecker(model=model, self_collision=True)
    bodies = [b for b, _ in model.items]
    checked = set(model.checked_body_pairs())
    want = [(a, b) for a in range(len(bodies)) for b in range(a + 1, len(bodies))
            if tuple(sorted((bodies[a], bodies[b]))) in checked]
    got = [tuple(p) for p in checker._shapes["pairs"].tolist()]
    assert got == want and len(want) > 5


@pytest.mark.parametrize("obstacle, says", [
    (Sphere(radius=0.1, pose=rpy_pose([400.0, 0.0, 500.0])), "lies .* more than 100x its reach"),
    (Box(size=[300.0, 300.0, 10.0], pose=rpy_pose([0.0, 0.0, -5.0])), "extends .* from its "
     "centre, more than 100x the reach"),
    (Sphere(radius=1e300), "extends 1e\\+300 m"),
    (Sphere(radius=0.1, pose=rpy_pose([1e308, 1e308, 0.0])), "lies inf m"),
])
def test_a_scene_in_other_units_or_absurd_sizes_is_refused(obstacle, says):
    """Before: a scene written in millimetres for a metre arm solved "collision-free,
    smallest distance 534.7 m"; a sphere at 1e308 gave "inf (no pair)"."""
    robot = get_robot("panda")
    scene = Scene({"thing": obstacle, "table": HalfSpace.plane([0, 0, 1], 0.0)})
    with pytest.raises(GeometryError, match=f"obstacle 'thing' {says}"):
        CollisionChecker(model=collision_model(robot), scene=scene)
    near = Scene({"thing": Sphere(radius=0.1, pose=rpy_pose([0.5 * robot.reach, 0, 0.3])),
                  "far wall": Box(size=[0.1, 4.0, 2.0], pose=rpy_pose([20 * robot.reach, 0, 1]))})
    assert CollisionChecker(model=collision_model(robot), scene=near).n_pairs > 0


def test_an_obstacle_named_like_a_link_is_refused():
    """Before: an obstacle 'panda_link3' was accepted and its pairs printed as
    'panda_link7 - panda_link3', which reads as a self pair."""
    model = collision_model(get_robot("panda"))
    for name in (model.links[3], model.links[0]):
        with pytest.raises(GeometryError, match=f"obstacle '{name}' has the name of a link"):
            CollisionChecker(model=model, scene=Scene({name: Sphere(radius=0.1)}))
