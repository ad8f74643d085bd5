"""The LLM-facing tool API: ``Pose`` and the perception and motion tools.

``ToolAPI`` is imported on first use: a program's process needs the pose types alone, without the planner,
perception and simulator modules the tools stand on.
"""

from roboscript.api.pose import Point, Pose, Quaternion

__all__ = ["Point", "Pose", "Quaternion", "ToolAPI"]


def __getattr__(name: str):
    if name == "ToolAPI":
        from roboscript.api.tools import ToolAPI

        return ToolAPI
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
