"""The Franka hand, as the Panda and the FR3 carry it (Menagerie's model): its TCP, a grip that squeezes with a set
force as the real hand does, flat fingertip pads, and its description for the gripper's users."""

from __future__ import annotations

import mujoco
import numpy as np

from roboscript.robots.description import GripperDescription

# Fingertip pad centres sit 0.1034 m from the hand frame along its z axis.
TCP_OFFSET = 0.1034
# The finger servo: stiff, with its force capped. The tendon's force is shared by the two fingers. A soft servo
# squeezes in proportion to the object's width (Menagerie's 100 N/m: 2.5 N on a 5 cm box; even 1000 N/m gives
# 1.5 N per finger on a mug's 6 mm rim, and the mug turns about the pads). The real hand grasps with a set force:
# at 10000 N/m the cap is reached from 8 mm of width on, 20 N per finger, within the hand's 70 N. The target stays
# at fully closed, because the fingers' joint limits are soft and a target past them would push them through.
FINGER_KP = 10000.0
FINGER_KV = 300.0
FINGER_FORCE_LIMIT = 40.0
FINGER_STROKE = 0.04
FRANKA_FINGERS = ("left_finger", "right_finger")


def fit_franka_hand(spec: mujoco.MjSpec, actuator: str) -> None:
    """Adds the TCP site to the hand, makes the finger servo ``actuator`` grip with a set force, and flattens the
    fingertips' pads."""
    spec.body("hand").add_site(name="tcp", pos=[0, 0, TCP_OFFSET], size=[0.005, 0, 0], group=5)
    finger = spec.actuator(actuator)
    finger.gainprm[0] = FINGER_STROKE * FINGER_KP / 255.0
    finger.biasprm[1] = -FINGER_KP
    finger.biasprm[2] = -FINGER_KV
    finger.forcerange = [-FINGER_FORCE_LIMIT, FINGER_FORCE_LIMIT]
    for name in FRANKA_FINGERS:
        _flat_pad(spec.body(name))


def _flat_pad(finger: mujoco.MjsBody) -> None:
    """One flat pad over the fingertip's four bumps, the bumps left out of contact. A round thing (a 4 cm bottle)
    sank between the bumps, 5 mm apart, and the bumps' edges pinched it across the finger with 7 to 10 N each:
    as the hand opened, that pinch dragged the bottle 2.5 cm along with the finger, and it fell over."""
    boxes = [g for g in finger.geoms if g.type == mujoco.mjtGeom.mjGEOM_BOX and g.contype]
    pad = max(boxes, key=lambda g: float(np.prod(g.size)))
    lower = np.min([np.asarray(g.pos) - np.asarray(g.size) for g in boxes], axis=0)
    upper = np.max([np.asarray(g.pos) + np.asarray(g.size) for g in boxes], axis=0)
    pad.pos, pad.size = (lower + upper) / 2, (upper - lower) / 2
    for bump in boxes:
        if bump is not pad:
            bump.contype, bump.conaffinity = 0, 0


def franka_hand(actuator: str) -> GripperDescription:
    """The hand's description, its finger servo named ``actuator`` (the models name it differently)."""
    return GripperDescription(
        actuator=actuator,
        open_ctrl=255.0,
        closed_ctrl=0.0,
        finger_bodies=FRANKA_FINGERS,
        width_offset=0.0,
        max_width=0.08,
        joints=("finger_joint1", "finger_joint2"),
        open_qpos=(FINGER_STROKE, FINGER_STROKE),
        hand_box=((-0.033, -0.105, -0.13), (0.033, 0.101, -0.036)),  # the hand mesh's vertices, 1 mm out
    )
