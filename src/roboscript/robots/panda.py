"""Franka Emika Panda with the Franka hand (Menagerie model)."""

from __future__ import annotations

import mujoco

from roboscript.robots.assets import PANDA, resolve_model
from roboscript.robots.description import (
    GripperDescription,
    RobotDescription,
    enable_gravity_compensation,
    load_spec,
    strip_for_attachment,
)

# Fingertip pad centres sit 0.1034 m from the hand frame along its z axis.
TCP_OFFSET = 0.1034
# Grip stiffness of the finger tendon, N/m. Menagerie's 100 N/m squeezes a 5 cm object with about 2.5 N;
# 1000 N/m gives about 25 N, within the real hand's 70 N continuous force.
FINGER_KP = 1000.0
FINGER_KV = 15.0
FINGER_STROKE = 0.04


def build_spec() -> mujoco.MjSpec:
    """The Panda spec with a TCP site, gravity compensation and a firmer grip, ready to attach."""
    spec = load_spec(resolve_model(PANDA.directory).xml_path)
    strip_for_attachment(spec)
    enable_gravity_compensation(spec)
    spec.body("hand").add_site(name="tcp", pos=[0, 0, TCP_OFFSET], size=[0.005, 0, 0], group=5)
    finger = spec.actuator("actuator8")
    finger.gainprm[0] = FINGER_STROKE * FINGER_KP / 255.0
    finger.biasprm[1] = -FINGER_KP
    finger.biasprm[2] = -FINGER_KV
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
    gripper=GripperDescription(
        actuator="actuator8",
        open_ctrl=255.0,
        closed_ctrl=0.0,
        finger_bodies=("left_finger", "right_finger"),
        width_offset=0.0,
        max_width=0.08,
        joints=("finger_joint1", "finger_joint2"),
        open_qpos=(FINGER_STROKE, FINGER_STROKE),
    ),
    build_spec=build_spec,
)
