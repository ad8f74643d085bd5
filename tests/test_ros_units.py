"""Pieces of the ROS side that need no master: finding a complete camera frame among lagging topics, and the
tool calls a run's log records."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from roboscript.ros.driver import _newest_complete
from roboscript.ros.run_log import logged_namespace


def _message(stamp: float) -> SimpleNamespace:
    return SimpleNamespace(header=SimpleNamespace(stamp=SimpleNamespace(to_sec=lambda: stamp)), stamp=stamp)


def test_a_frame_is_the_newest_instant_every_part_has_even_when_one_topic_lags():
    kept = {
        "rgb": [_message(t) for t in (1.0, 1.5, 2.0, 2.5)],
        "depth": [_message(t) for t in (0.5, 1.0, 1.5)],  # a frame and more behind
        "info": [_message(t) for t in (1.5, 2.0, 2.5)],
    }
    frame = _newest_complete(kept, not_before=0.0)
    assert {part: m.stamp for part, m in frame.items()} == {"rgb": 1.5, "depth": 1.5, "info": 1.5}
    assert _newest_complete(kept, not_before=1.6) is None  # none complete after the last motion ended
    assert _newest_complete({**kept, "depth": []}, not_before=0.0) is None


class RecordingLog:
    """Test double of RosRunLog: keeps the tool calls it is given."""

    def __init__(self):
        self.calls = []

    def tool_call(self, name, args, kwargs, answer=None, error=None):
        self.calls.append((name, args, kwargs, answer, error))


def test_each_tool_call_is_logged_with_its_answer_or_its_error():
    def grasp(pose, speed=1.0):
        """Grasps at pose."""
        if pose is None:
            raise ValueError("no pose")
        return "held"

    log = RecordingLog()
    namespace = logged_namespace({"grasp": grasp, "np": SimpleNamespace(), "Pose": SimpleNamespace}, log)
    assert namespace["grasp"]("p", speed=0.5) == "held"
    with pytest.raises(ValueError, match="no pose"):
        namespace["grasp"](None)
    assert log.calls == [
        ("grasp", ("p",), {"speed": 0.5}, "held", None),
        ("grasp", (None,), {}, None, "ValueError: no pose"),
    ]
    assert namespace["Pose"] is SimpleNamespace  # classes and modules are not tools
    assert namespace["grasp"].__doc__ == "Grasps at pose."
