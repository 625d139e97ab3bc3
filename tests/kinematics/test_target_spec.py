"""moik/kinematics/target_spec.py: the target as one compiled record."""

import numpy as np
import pytest

from moik._jit import jit
from moik.exceptions import UnknownNameError
from moik.kinematics.rotation_metrics import metric_code, metric_target
from moik.kinematics.target_spec import NO_METRIC, retarget, target_spec
from moik.problems import Target


@jit
def _fields(spec):
    return (spec.position.copy(), spec.rotation.copy(), spec.has_rotation, spec.code,
            spec.angles.copy())


def test_a_position_target_has_the_identity_and_no_metric():
    p, R, has_rot, code, angles = _fields(target_spec([0.1, 0.2, 0.3]))
    np.testing.assert_array_equal(p, [0.1, 0.2, 0.3])
    np.testing.assert_array_equal(R, np.eye(3))
    assert not has_rot and code == NO_METRIC
    np.testing.assert_array_equal(angles, 0.0)


@pytest.mark.parametrize("metric", ["eosma-euler", "zyx-euler", "geodesic", "frobenius"])
def test_a_pose_target_carries_its_metric_and_angles(metric):
    R = Target.from_euler([0.0, 0.0, 0.0], [0.3, -0.2, 1.1]).rotation
    _, R_spec, has_rot, code, angles = _fields(target_spec([0, 0, 0], R, metric=metric))
    np.testing.assert_array_equal(R_spec, R)
    assert has_rot and code == metric_code(metric)
    np.testing.assert_array_equal(angles, metric_target(metric, R))


def test_unknown_metric_is_refused():
    with pytest.raises(UnknownNameError, match="geodesic"):
        target_spec([0, 0, 0], np.eye(3), metric="geodesick")


def test_retarget_moves_the_record():
    spec = target_spec([0.0, 0.0, 0.0], np.eye(3))
    R = Target.from_euler([0.0, 0.0, 0.0], [0.1, 0.2, 0.3]).rotation
    retarget(spec, np.array([1.0, 2.0, 3.0]), np.ascontiguousarray(R))
    p, R_spec, *_ = _fields(spec)
    np.testing.assert_array_equal(p, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(R_spec, R)
