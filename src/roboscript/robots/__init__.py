"""Robot descriptions and the model-file resolver."""

from __future__ import annotations

from roboscript.robots.description import ROBOT_PREFIX, GripperDescription, RobotDescription
from roboscript.robots.fr3 import FR3_DESCRIPTION
from roboscript.robots.panda import PANDA_DESCRIPTION
from roboscript.robots.ur5e import UR5E_DESCRIPTION

ROBOTS: dict[str, RobotDescription] = {d.name: d for d in (PANDA_DESCRIPTION, UR5E_DESCRIPTION, FR3_DESCRIPTION)}


def get_robot(name: str) -> RobotDescription:
    """The description of robot ``name``; raises ``ValueError`` naming the valid robots."""
    try:
        return ROBOTS[name]
    except KeyError:
        raise ValueError(f"unknown robot {name!r}; valid robots: {', '.join(sorted(ROBOTS))}") from None


__all__ = ["ROBOTS", "ROBOT_PREFIX", "GripperDescription", "RobotDescription", "get_robot"]
