"""The LLM-facing tool API: ``Pose`` and the perception and motion tools (DESIGN.md §3)."""

from roboscript.api.pose import Point, Pose, Quaternion
from roboscript.api.tools import ToolAPI

__all__ = ["Point", "Pose", "Quaternion", "ToolAPI"]
