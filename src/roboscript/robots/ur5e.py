"""Universal Robots UR5e with a Robotiq 2F-85 on its flange (Menagerie models joined with MjSpec)."""

from __future__ import annotations

import math

import mujoco

from roboscript.robots.assets import ROBOTIQ_2F85, UR5E, resolve_model
from roboscript.robots.description import (
    GripperDescription,
    RobotDescription,
    enable_gravity_compensation,
    load_spec,
    strip_for_attachment,
)

GRIPPER_PREFIX = "gripper/"


def build_spec() -> mujoco.MjSpec:
    """The UR5e spec with the 2F-85 attached at its flange site, ready to attach to a world."""
    arm = load_spec(resolve_model(UR5E.directory).xml_path)
    hand = load_spec(resolve_model(ROBOTIQ_2F85.directory).xml_path)
    for spec in (arm, hand):
        strip_for_attachment(spec)
    # attach() keeps the parent's options; the gripper needs these to hold things (Menagerie's own settings).
    arm.option.impratio = hand.option.impratio
    arm.option.cone = hand.option.cone
    arm.attach(hand, prefix=GRIPPER_PREFIX, site=arm.site("attachment_site"))
    enable_gravity_compensation(arm)
    return arm


UR5E_DESCRIPTION = RobotDescription(
    name="ur5e",
    arm_joints=(
        "shoulder_pan_joint",
        "shoulder_lift_joint",
        "elbow_joint",
        "wrist_1_joint",
        "wrist_2_joint",
        "wrist_3_joint",
    ),
    arm_actuators=("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3"),
    tcp_site=GRIPPER_PREFIX + "pinch",
    home=(0.0, -1.9, 2.1, -1.7708, -1.5708, 0.0),
    # Menagerie yaws the UR5e base by 180 degrees; mounting it yawed back makes pan = 0 face +x.
    mount_yaw=math.pi,
    max_velocity=(3.14, 3.14, 3.14, 3.14, 3.14, 3.14),
    max_acceleration=(8.0, 8.0, 8.0, 10.0, 10.0, 10.0),
    gripper=GripperDescription(
        actuator=GRIPPER_PREFIX + "fingers_actuator",
        open_ctrl=0.0,
        closed_ctrl=255.0,
        finger_bodies=(GRIPPER_PREFIX + "left_pad", GRIPPER_PREFIX + "right_pad"),
        # The pad bodies' origins sit 13.5 mm outside the pad surfaces in total (measured: 98.5 mm fully open).
        width_offset=0.0135,
        max_width=0.085,
        joints=(GRIPPER_PREFIX + "left_driver_joint", GRIPPER_PREFIX + "right_driver_joint"),
        open_qpos=(0.0, 0.0),
        # The vertices of the base's, drivers', couplers' and spring links' meshes, fully open, 1 mm out.
        hand_box=((-0.039, -0.075, -0.15), (0.039, 0.075, -0.034)),
    ),
    build_spec=build_spec,
    root_body="base",
)
