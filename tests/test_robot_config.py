"""Robot configuration files: the packaged ones load, and a bad one says which field is wrong and what is valid."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

from roboscript.errors import UsageError
from roboscript.robot_config import (
    RobotConfigError,
    config_names,
    config_path,
    load_robot_config,
    parse_robot_config,
    ros_config_for,
)


def test_the_packaged_configurations_load(tmp_path):
    assert {"panda_franka_ros", "ur5e_ur_robot_driver"} <= set(config_names())
    ur5e = load_robot_config("ur5e_ur_robot_driver")
    assert ur5e.driver_joint("gripper/right_driver_joint") == "finger_joint" and ur5e.speed_scale == 0.25
    bad = Path(tmp_path / "bad.yaml")
    bad.write_text(Path(load_robot_config("panda_franka_ros").source).read_text().replace("kind: franka", "kind: x"))
    with pytest.raises(RobotConfigError, match="gripper: unknown gripper kind 'x'; kinds: gripper_command, franka"):
        load_robot_config(bad)
    with pytest.raises(RobotConfigError, match="no such packaged configuration; packaged: fr3_franky, panda_"):
        load_robot_config("kuka")


def test_ros_sim_without_a_master_says_how_to_start_one(monkeypatch, capsys):
    from roboscript.cli.main import main

    monkeypatch.delenv("ROS_MASTER_URI", raising=False)
    assert main(["ros-sim", "world_2_pick_and_place", "--robot", "panda"]) == 2
    assert "ROS_MASTER_URI is not set: start a master (rosmaster --core -p 11311)" in capsys.readouterr().err
    assert main(["ros-sim", "world_2_pick_and_place", "--robot", "ur5e", "--robot-config", "panda_franka_ros"]) == 2
    assert "robot configuration panda_franka_ros is for the panda, not the ur5e" in capsys.readouterr().err


def _data(name: str) -> dict:
    return yaml.safe_load(config_path(name).read_text())


@pytest.mark.parametrize(
    ("change", "problem"),
    [
        (lambda d: d.update(robot="ur5e"), "driver franky drives a Franka arm; robot must be one of fr3, panda"),
        (lambda d: d["gripper"].update(action="/franka_gripper"), "libfranka drives the Franka hand itself"),
        (lambda d: d.update(ros={"trajectory_action": "/x"}), "field 'ros' is for driver ros"),
        (lambda d: d["franky"].update(realtime="off"), "realtime must be 'enforce'"),
        (
            lambda d: d.update(cameras=[{"name": "c", "rgb": "/c/rgb", "depth": "/c/d", "info": "/c/i"}]),
            r"cameras\[0\]",
        ),
        (lambda d: d.update(driver="ur_rtde"), "unknown driver 'ur_rtde'; drivers: ros, franky"),
    ],
)
def test_a_franky_configuration_says_what_is_wrong_and_what_would_be_valid(change, problem):
    data = _data("fr3_franky")
    change(data)
    with pytest.raises(RobotConfigError, match=problem):
        parse_robot_config(data)


def test_the_packaged_franky_configuration_puts_the_base_where_the_worlds_put_the_arm():
    config = load_robot_config("fr3_franky")
    assert config.driver == "franky" and config.franky.realtime and config.franky.host == "172.16.0.2"
    assert np.allclose(config.franky.base_pose.position, [-0.45, 0.0, 0.82])
    assert config.gripper.kind == "franka" and config.gripper.width_joints == ("finger_joint1", "finger_joint2")


def test_two_cameras_of_one_name_or_one_serial_are_refused():
    data = _data("panda_franka_ros")
    data["cameras"].append(dict(data["cameras"][0]))
    with pytest.raises(RobotConfigError, match="the name 'camera_left' is given twice"):
        parse_robot_config(data)
    data = _data("fr3_franky")
    pose = {"position": [0, 0, 1], "quaternion": [1, 0, 0, 0]}
    data["cameras"] = [{"name": n, "realsense": {"serial": "A1", **pose}} for n in ("a", "b")]
    with pytest.raises(RobotConfigError, match="the RealSense serial 'A1' is given twice"):
        parse_robot_config(data)


def test_an_fr3_has_no_packaged_ros_configuration_and_the_error_says_what_to_pass():
    with pytest.raises(UsageError, match="no packaged ROS configuration for the fr3: name one with --robot-config"):
        ros_config_for("fr3")
