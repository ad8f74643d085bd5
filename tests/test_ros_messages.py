"""The ROS 1 action types Debian does not package, built from the definitions shipped here: their MD5 sums are the
upstream ones, which real drivers (franka_ros, ur_robot_driver, ros_control) check before they talk."""

from __future__ import annotations

import pytest

pytest.importorskip("genpy", reason="ROS 1 is not installed here (scripts/setup.sh installs it on Debian)")

from roboscript.ros.messages import MessageDefinitionError, action_types, full_text, message_class

UPSTREAM_MD5 = {  # the sums of the upstream message packages (control_msgs 1.5, franka_gripper 0.10)
    "control_msgs/FollowJointTrajectory": "bc4f9b743838566551c0390c65f1a248",
    "control_msgs/GripperCommand": "950b2a6ebe831f5d4f4ceaba3d8be01e",
    "franka_gripper/Grasp": "6f89449359949eaf1f0fef57b7e0db2a",
}


@pytest.mark.parametrize("action", sorted(UPSTREAM_MD5))
def test_action_types_carry_the_upstream_md5_sums(action):
    assert action_types(action).action._md5sum == UPSTREAM_MD5[action]


def test_a_goal_round_trips_through_its_wire_format():
    import io

    types = action_types("control_msgs/FollowJointTrajectory")
    goal = types.goal()
    goal.trajectory.joint_names = ["joint1", "joint2"]
    point = message_class("trajectory_msgs/JointTrajectoryPoint")(positions=[0.1, -0.2], velocities=[0.0, 0.0])
    goal.trajectory.points = [point]
    buffer = io.BytesIO()
    goal.serialize(buffer)
    back = types.goal().deserialize(buffer.getvalue())
    assert back.trajectory.joint_names == ["joint1", "joint2"]
    assert list(back.trajectory.points[0].positions) == [0.1, -0.2]
    assert types.result.PATH_TOLERANCE_VIOLATED == -4


def test_an_unknown_type_says_where_definitions_were_looked_for():
    with pytest.raises(MessageDefinitionError, match="no definition of nowhere_msgs/Thing: neither shipped in"):
        full_text("nowhere_msgs/Thing")
