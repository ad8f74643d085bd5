"""``Pose`` behaves like ROS geometry_msgs/Pose and converts to and from numpy."""

import numpy as np
import pytest

from roboscript.api import Pose
from roboscript.geometry import quat_from_axis_angle


def test_default_pose_is_identity_and_fields_are_assignable():
    pose = Pose()
    assert tuple(pose.position) == (0.0, 0.0, 0.0)
    assert tuple(pose.orientation) == (0.0, 0.0, 0.0, 1.0)
    pose.position.x = 0.3
    pose.position.z += 0.1
    pose.orientation.w = 0.0
    pose.orientation.x = 1.0
    np.testing.assert_allclose(pose.position_array(), [0.3, 0.0, 0.1])
    np.testing.assert_allclose(pose.rotation_matrix(), np.diag([1.0, -1.0, -1.0]), atol=1e-12)


def test_matrix_round_trip():
    q = quat_from_axis_angle(np.array([0.2, -0.5, 1.0]), 0.7)
    pose = Pose.from_numpy([0.1, -0.2, 0.9], q)
    again = Pose.from_matrix(pose.to_matrix())
    np.testing.assert_allclose(again.position_array(), pose.position_array())
    np.testing.assert_allclose(again.to_matrix(), pose.to_matrix(), atol=1e-12)
    np.testing.assert_allclose(pose.to_transform().matrix(), pose.to_matrix(), atol=1e-12)


def test_bad_values_are_refused_with_the_field_named():
    pose = Pose()
    with pytest.raises(TypeError, match=r"position\.x must be a number"):
        pose.position.x = "0.3"
    with pytest.raises(ValueError, match=r"orientation\.y must be finite"):
        pose.orientation.y = float("nan")
    with pytest.raises(ValueError, match="position must be 3 numbers"):
        Pose(position=[1.0, 2.0])
    zero = Pose(orientation=[0, 0, 0, 0])
    with pytest.raises(ValueError, match="quaternion is zero"):
        zero.to_transform()
    with pytest.raises(ValueError, match="4x4"):
        Pose.from_matrix(np.eye(3))
