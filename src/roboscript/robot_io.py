"""The data a robot backend takes and gives, whichever robot it drives: camera frames and the reports of motions.

Neutral ground between the layers: backends (simulated or real) produce these, perception and planning consume them,
and nothing here knows of MuJoCo or ROS. Joint trajectories are in :mod:`roboscript.trajectory`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Transform


@dataclass
class CameraFrame:
    """One RGB-D(-S) capture: images plus the calibration that perception needs."""

    name: str
    rgb: np.ndarray | None  # (H, W, 3) uint8; None when captured without colour (Backend.capture's color)
    depth: np.ndarray  # (H, W) float32, metres; 0 where nothing was hit
    segmentation: np.ndarray | None  # (H, W) int32 label index, -1 for background and unnamed things
    intrinsics: np.ndarray  # (3, 3)
    extrinsics: Transform  # camera-to-world, OpenCV convention


@dataclass(frozen=True)
class ExecutionReport:
    """How well a trajectory was tracked. Errors are maxima over the run; TCP errors in metres."""

    duration: float
    max_joint_error: float
    max_tcp_error: float
    final_joint_error: float
    final_tcp_error: float


@dataclass(frozen=True)
class GripperReport:
    """Gripper state after a command: opening width in metres, and whether the fingers stopped on something."""

    width: float
    command: float  # 0 = open, 1 = closed
    blocked: bool
    duration: float
