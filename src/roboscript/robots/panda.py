"""Franka Emika Panda with the Franka hand (Menagerie model)."""

from __future__ import annotations

import mujoco

from roboscript.robots.assets import PANDA, resolve_model
from roboscript.robots.description import (
    RobotDescription,
    enable_gravity_compensation,
    load_spec,
    strip_for_attachment,
)
from roboscript.robots.franka_hand import fit_franka_hand, franka_hand


def build_spec() -> mujoco.MjSpec:
    """The Panda spec with a TCP site, gravity compensation and a firmer grip, ready to attach."""
    spec = load_spec(resolve_model(PANDA.directory).xml_path)
    strip_for_attachment(spec)
    enable_gravity_compensation(spec)
    fit_franka_hand(spec, "actuator8")
    return spec


PANDA_DESCRIPTION = RobotDescription(
    name="panda",
    arm_joints=tuple(f"joint{i}" for i in range(1, 8)),
    arm_actuators=tuple(f"actuator{i}" for i in range(1, 8)),
    tcp_site="tcp",
    home=(0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785),
    mount_yaw=0.0,
    max_velocity=(2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61),
    max_acceleration=(15.0, 7.5, 10.0, 12.5, 15.0, 20.0, 20.0),
    gripper=franka_hand("actuator8"),
    build_spec=build_spec,
    root_body="link0",
)
