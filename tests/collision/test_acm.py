"""The allowed-collision matrix of a URDF model, sampled (moik/collision/acm.py)."""

from pathlib import Path

import numpy as np
import pytest

import moik
from moik import load_urdf, solve_ik
from moik.collision import CollisionChecker
from moik.collision.urdf import model_from_urdf

STUCK = (Path(__file__).resolve().parents[1] / "data" / "urdf" / "stuck.urdf").read_text()


def test_sampled_pairs_are_those_never_and_always_below_zero():
    """The allowed-collision sampling (a compiled pass that measures each pair only to its
    sign, and no more once it has been seen both in and out of collision) gives the body
    pairs whose full signed distance is never below 0 on the same random configurations,
    and those with a shape pair below 0 in all of them."""
    from moik.collision.acm import ACM_SEED, sample_pairs

    robot = moik.get_robot("ur5")
    desc = robot.description
    model = model_from_urdf(desc.source, robot, package_dirs=desc.package_dirs, samples=0)
    checker = CollisionChecker(model=model, self_collision=True)
    D = checker.distances(robot.random_q(400, rng=np.random.default_rng(ACM_SEED)))
    touched = {pair for k, pair in enumerate(checker.pair_bodies) if (D[:, k] < 0).any()}
    stuck = {pair for k, pair in enumerate(checker.pair_bodies) if (D[:, k] < 0).all()}
    name = model.links
    never, always = sample_pairs(model, 400)
    assert set(never) == {(name[i], name[j]) for i, j in checker.pair_bodies
                          if (i, j) not in touched}
    assert 0 < len(never) < len(set(checker.pair_bodies))
    assert set(always) == {(name[i], name[j]) for i, j in stuck}


def test_a_pair_in_collision_in_every_sample_is_named_not_allowed(tmp_path, monkeypatch):
    """Links a and c of tests/data/urdf/stuck.urdf overlap in every configuration (c's ball
    sits 10 mm below a's, the joints between them turn by at most 0.2 rad about the same
    axis): the pair stays checked (a pair never checked must never touch), and the model
    says why every answer will be rejected, on a fresh sampling and from the cache alike."""
    from moik.exceptions import GeometryWarning

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    robot = load_urdf(STUCK, tip_link="c")
    for _ in range(2):  # sampled, then read from the cache
        with pytest.warns(GeometryWarning, match="links a - c are in collision in every one"):
            model = model_from_urdf(STUCK, robot, samples=200)
        assert frozenset({"a", "c"}) not in model.allowed
        assert "every answer rejected): a - c" in model.source
    names = model.links
    assert ("a", "c") in [(names[i], names[j]) for i, j in model.checked_body_pairs()]
    res = solve_ik(robot, robot.fk(np.zeros(3))[:3, 3], self_collision=True, collision=model)
    assert res.status == "collides"
