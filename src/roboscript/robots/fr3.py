"""Franka Research 3 with the Franka hand: the model franky-sim (the libfranka simulator) runs, from its wheel."""

from __future__ import annotations

import mujoco

from roboscript.robots.assets import FR3, resolve_model
from roboscript.robots.description import (
    RobotDescription,
    enable_gravity_compensation,
    load_spec,
    strip_for_attachment,
)
from roboscript.robots.franka_hand import fit_franka_hand, franka_hand


def build_spec() -> mujoco.MjSpec:
    """The FR3 spec with a TCP site, gravity compensation and the hand's set-force grip, ready to attach."""
    xml_path = resolve_model(FR3.directory).xml_path
    spec = load_spec(xml_path)
    spec.meshdir = str(xml_path.parent.resolve() / FR3.meshdir)  # its XML names a folder the wheel lays out otherwise
    strip_for_attachment(spec)
    enable_gravity_compensation(spec)
    fit_franka_hand(spec, "hand")
    return spec


FR3_DESCRIPTION = RobotDescription(
    name="fr3",
    arm_joints=tuple(f"fr3_joint{i}" for i in range(1, 8)),
    arm_actuators=tuple(f"fr3_joint{i}" for i in range(1, 8)),
    tcp_site="tcp",
    home=(0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785),
    mount_yaw=0.0,
    # Franka's FR3 limits (its datasheet): 2.62 rad/s for joints 1-4, 5.26, 4.18 and 5.26 for 5-7; 10 rad/s^2 each.
    max_velocity=(2.62, 2.62, 2.62, 2.62, 5.26, 4.18, 5.26),
    max_acceleration=(10.0,) * 7,
    gripper=franka_hand("hand"),
    build_spec=build_spec,
    root_body="base",
)
