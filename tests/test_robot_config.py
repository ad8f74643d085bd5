"""Robot configuration files: the packaged ones load, and a bad one says which field is wrong and what is valid."""

from __future__ import annotations

from pathlib import Path

import pytest

from roboscript.robot_config import RobotConfigError, config_names, load_robot_config


def test_the_packaged_configurations_load(tmp_path):
    assert {"panda_franka_ros", "ur5e_ur_robot_driver"} <= set(config_names())
    ur5e = load_robot_config("ur5e_ur_robot_driver")
    assert ur5e.driver_joint("gripper/right_driver_joint") == "finger_joint" and ur5e.speed_scale == 0.25
    bad = Path(tmp_path / "bad.yaml")
    bad.write_text(Path(load_robot_config("panda_franka_ros").source).read_text().replace("kind: franka", "kind: x"))
    with pytest.raises(RobotConfigError, match="gripper: unknown gripper kind 'x'; kinds: gripper_command, franka"):
        load_robot_config(bad)
    with pytest.raises(RobotConfigError, match="no such packaged configuration; packaged: panda_franka_ros"):
        load_robot_config("kuka")


def test_ros_sim_without_a_master_says_how_to_start_one(monkeypatch, capsys):
    from roboscript.cli import main

    monkeypatch.delenv("ROS_MASTER_URI", raising=False)
    assert main(["ros-sim", "world_2_pick_and_place", "--robot", "panda"]) == 2
    assert "ROS_MASTER_URI is not set: start a master (rosmaster --core -p 11311)" in capsys.readouterr().err
    assert main(["ros-sim", "world_2_pick_and_place", "--robot", "ur5e", "--robot-config", "panda_franka_ros"]) == 2
    assert "robot configuration panda_franka_ros is for the panda, not the ur5e" in capsys.readouterr().err
