"""Scenes and capsule models from JSON; malformed files raise clear errors."""

import json

import numpy as np
import pytest

from moik import get_robot
from moik.collision import Box, Capsule, HalfSpace
from moik.collision.catalog import collision_model, shipped_models
from moik.collision.io import load_model, load_scene, model_to_dict, shape_from_dict
from moik.exceptions import GeometryError, NonFiniteError, UnknownNameError


def test_scene_file(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"obstacles": [
        {"name": "table", "type": "halfspace", "normal": [0, 0, 1], "offset": 0.1},
        {"name": "shelf", "type": "box", "size": [0.4, 0.8, 0.02], "xyz": [0.6, 0, 0.5],
         "rpy": [0, 0, 0.3]},
        {"name": "pole", "type": "capsule", "a": [0, 0.5, 0], "b": [0, 0.5, 1], "radius": 0.05}]}))
    scene = load_scene(path)
    assert isinstance(scene.obstacles["table"], HalfSpace)
    assert np.allclose(scene.obstacles["table"].pose[:3, 3], [0, 0, 0.1])
    assert isinstance(scene.obstacles["shelf"], Box)
    assert isinstance(scene.obstacles["pole"], Capsule) and scene.obstacles["pole"].length == 1


def test_bad_shapes():
    with pytest.raises(UnknownNameError, match="box, capsule, cylinder, halfspace, sphere"):
        shape_from_dict({"type": "cone", "radius": 1})
    with pytest.raises(NonFiniteError):
        shape_from_dict({"type": "sphere", "radius": float("nan")})
    with pytest.raises(GeometryError, match="needs the key 'radius'"):
        shape_from_dict({"type": "sphere"})
    with pytest.raises(GeometryError, match="not valid JSON"):
        load_scene(__file__)


def test_model_round_trip_and_wrong_robot():
    model = collision_model("ur5")
    again = load_model(model_to_dict(model), model.robot)
    assert again.links == model.links and again.allowed == model.allowed
    assert again.checked_body_pairs() == model.checked_body_pairs()
    with pytest.raises(GeometryError, match="for robot 'ur5'"):
        load_model(model_to_dict(model), get_robot("puma560"))


def test_every_catalog_arm_has_a_model():
    for name in ("panda", "ur5", "iiwa14", "puma560", "eosma7", "rokbani5", "irb2600"):
        assert name in shipped_models()
        model = collision_model(name)
        assert sum(len(v) for v in model.shapes.values()) >= model.robot.dof
    with pytest.raises(UnknownNameError):
        collision_model(get_robot("panda").with_locked_joints({0: 0.0}))
