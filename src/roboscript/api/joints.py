"""What ``get_object_joint_info`` reports of a drawer's or door's joint: where its axis lies, which way it opens,
how far it is open and how far it opens at most (metres for a drawer, degrees for a door, as the arc tool takes)."""

from __future__ import annotations

import math

import numpy as np

from roboscript.api.arguments import ArgumentError
from roboscript.perception.base import Perception

JOINT_TYPES = ("any", "revolute", "prismatic")


def joint_report(perception: Perception, name: str, point: np.ndarray, joint_type: str) -> dict:
    """The joint of ``name`` of ``joint_type`` nearest ``point``, as the tool returns it."""
    joints = [j for j in perception.joints(name) if joint_type in ("any", j.type)]
    if not joints:
        articulated = [n for n in perception.names() if perception.joints(n)]
        kind = "" if joint_type == "any" else f"{joint_type} "
        raise ArgumentError(f"{name!r} has no {kind}joint; articulated objects: {', '.join(articulated) or 'none'}")
    joint = min(joints, key=lambda j: float(np.linalg.norm(j.position - point)))
    unit = 1.0 if joint.type == "prismatic" else 180.0 / math.pi
    return {
        "joint_position": joint.position.copy(),
        "joint_axis": joint.axis.copy(),
        "type": joint.type,
        "joint_value": float(joint.value) * unit,
        "joint_upper": float(joint.upper) * unit,
    }
