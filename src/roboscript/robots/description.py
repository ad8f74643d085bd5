"""What the rest of the project needs to know about a robot: joints, actuators, TCP, gripper, limits.

Names here are those inside the robot's own MJCF. Once attached to a world they carry the prefix
:data:`ROBOT_PREFIX`; :meth:`RobotDescription.qualified` adds it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

ROBOT_PREFIX = "robot/"


@dataclass(frozen=True)
class GripperDescription:
    """A parallel gripper driven by one position actuator.

    ``open_ctrl``/``closed_ctrl`` are the actuator commands for fully open and fully closed. The opening width
    is measured as the distance between ``finger_bodies`` along the TCP's y axis (the closing direction),
    less ``width_offset``. ``hand_box``: ``(lower, upper)`` corners, in the TCP frame, of a box around the hand
    behind the fingers (its body and, fully open, its linkages), for the grasp detector's collision check.
    """

    actuator: str
    open_ctrl: float
    closed_ctrl: float
    finger_bodies: tuple[str, str]
    width_offset: float
    max_width: float
    joints: tuple[str, ...]
    open_qpos: tuple[float, ...]  # positions of ``joints`` when open, to start worlds with the gripper open
    hand_box: tuple[tuple[float, float, float], tuple[float, float, float]]


@dataclass(frozen=True)
class RobotDescription:
    """An arm with its gripper: the contract between robot models and the controller, planner and API.

    The TCP site sits between the fingertips; its +z axis is the approach direction, its y axis the direction in
    which the fingers close.
    """

    name: str
    arm_joints: tuple[str, ...]
    arm_actuators: tuple[str, ...]
    tcp_site: str
    home: tuple[float, ...]
    mount_yaw: float
    max_velocity: tuple[float, ...]
    max_acceleration: tuple[float, ...]
    gripper: GripperDescription
    build_spec: Callable[[], mujoco.MjSpec]
    root_body: str  # the arm's base body in its MJCF: what a world mounts

    @property
    def dof(self) -> int:
        return len(self.arm_joints)

    @staticmethod
    def qualified(name: str) -> str:
        """The element's name once the robot is attached to a world."""
        return ROBOT_PREFIX + name

    def home_array(self) -> np.ndarray:
        return np.array(self.home, dtype=float)


def load_spec(xml_path) -> mujoco.MjSpec:
    """Parses an MJCF and makes its asset paths absolute, so the spec can be attached elsewhere."""
    spec = mujoco.MjSpec.from_file(str(xml_path))
    base = xml_path.parent.resolve()
    spec.meshdir = str(base / spec.meshdir) if spec.meshdir else str(base)
    spec.texturedir = str(base / spec.texturedir) if spec.texturedir else str(base)
    return spec


def strip_for_attachment(spec: mujoco.MjSpec) -> None:
    """Removes what a world must own: keyframes (their sizes change on attach) and lights (the world lights)."""
    for key in list(spec.keys):
        spec.delete(key)
    for light in list(spec.lights):
        spec.delete(light)


def enable_gravity_compensation(spec: mujoco.MjSpec) -> None:
    """Marks every body of the robot gravity-compensated, as a real arm's controller does for itself."""
    for body in spec.bodies:
        if body.name != "world":
            body.gravcomp = 1.0
