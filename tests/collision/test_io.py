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


@pytest.mark.parametrize("item, near", [
    ({"type": "box", "size": [1, 1, 1], "xzy": [1, 0, 0]}, "xyz"),
    ({"type": "halfspace", "normal": [0, 0, 1], "ofset": 0.5}, "offset"),
    ({"type": "sphere", "radius": 0.1, "radus": 0.2}, "radius"),
])
def test_a_misspelt_scene_key_is_refused_with_the_nearest_key(item, near):
    """Before: the key was ignored (a box at the origin, a floor at 0)."""
    with pytest.raises(GeometryError, match=f"did you mean '{near}'"):
        load_scene({"obstacles": [item]})


def test_unknown_top_level_keys_are_refused_in_scenes_and_models():
    with pytest.raises(GeometryError, match="did you mean 'allowed'"):
        load_scene({"obstacles": [], "alowed": []})
    data = model_to_dict(collision_model(get_robot("planar2")))
    data["shape"] = data.pop("shapes")
    with pytest.raises(GeometryError, match="did you mean 'shapes'"):
        load_model(data, get_robot("planar2"))
    data = model_to_dict(collision_model(get_robot("planar2")))
    data["shapes"][0]["lnk"] = "x"
    with pytest.raises(GeometryError, match="did you mean 'link'"):
        load_model(data, get_robot("planar2"))


@pytest.mark.parametrize("scene, match", [
    ({"obstacles": [{"name": ["a"], "type": "sphere", "radius": 1}]}, "'name' must be a string"),
    ({"obstacles": [{"type": "sphere", "radius": 1}], "allowed": [[["a"], "b"]]}, "pairs"),
    ({"obstacles": [{"type": "capsule", "radius": 0.1, "length": int("9" * 400)}]}, "digits"),
    ({"obstacles": [{"type": "sphere", "radius": "big"}]}, "number"),
    ({"obstacles": [{"type": ["sphere"], "radius": 1}]}, "shape type"),
])
def test_malformed_names_and_numbers_end_in_a_geometry_error(scene, match):
    """Before: TypeError for list-valued names, OverflowError for a 400-digit length."""
    with pytest.raises((GeometryError, UnknownNameError), match=match):
        load_scene(scene)


def test_deep_and_endless_scene_files_are_refused(tmp_path):
    """Before: RecursionError for deep nesting; /dev/zero was read without limit."""
    deep = tmp_path / "deep.json"
    deep.write_text('{"obstacles": ' + "[" * 100_000 + "]" * 100_000 + "}")
    with pytest.raises(GeometryError, match="nested deeper"):
        load_scene(deep)
    with pytest.raises(GeometryError, match="not a regular file"):
        load_scene("/dev/zero")
    with pytest.raises(GeometryError, match="JSON file path"):
        load_scene("")


def test_a_scene_cylinder_is_a_prism_in_its_capsule():
    """A cylinder of a scene file is the compound of moik.collision.prism (measured on the
    prism that holds it, tests/collision/test_prism.py), not its enclosing capsule."""
    from moik.collision import cylinder
    from moik.collision.io import rpy_pose
    from moik.collision.shapes import Compound

    scene = load_scene({"obstacles": [{"name": "can", "type": "cylinder", "radius": 0.04,
                                       "length": 0.12, "xyz": [0.5, 0.0, 0.06]}]})
    can = scene.obstacles["can"]
    built = cylinder(radius=0.04, length=0.12, pose=rpy_pose([0.5, 0.0, 0.06]))
    assert isinstance(can, Compound) and isinstance(can.bound, Capsule)
    assert (can.bound.radius, can.bound.length) == (0.04, 0.12)
    np.testing.assert_array_equal(can.pose, built.pose)
    np.testing.assert_array_equal(can.parts[0].points, built.parts[0].points)
    np.testing.assert_array_equal(can.parts[0].pose, built.parts[0].pose)
