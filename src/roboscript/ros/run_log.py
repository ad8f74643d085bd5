"""The log every run on a ROS robot leaves: a rosbag (format 2.0, readable by ``rosbag info``, ``rqt_bag`` and
``rosbag play``) of what the robot said and what it was told.

Topics, as the robot configuration names them, recorded as they arrived (their own message types and definitions):

- the joint states, every message;
- the trajectory action's ``goal``, ``cancel``, ``status``, ``feedback`` and ``result`` (the goals this run sent
  included: the log's node hears its own publications);
- the gripper's actions' ``goal`` and ``result``;
- each camera's image, depth, camera info and segmentation image, at most one message a topic every
  ``camera_period`` seconds; the segmentation labels and ``/tf_static``.

Chunks are LZ4-compressed where ROS's LZ4 module is installed (a minute of a run is then a few tens of MB).

And, written by the run itself as ``std_msgs/String`` JSON:

- ``/roboscript/run``: the run's description (robot configuration, scene, perception, the program);
- ``/roboscript/tool_call``: each tool call, its arguments and its answer (or the error it raised);
- ``/roboscript/outcome``: how the run ended.

:mod:`roboscript.ros.replay` reads such a bag back, :mod:`roboscript.replay` replays its goals on the simulated twin;
tool calls come from :func:`roboscript.run_log.logged_namespace`.
"""

from __future__ import annotations

import threading
import time
import types
from collections.abc import Callable
from pathlib import Path

import numpy as np

from roboscript.robot_config import RobotConfig
from roboscript.run_log import to_json

RUN_TOPIC = "/roboscript/run"
TOOL_CALL_TOPIC = "/roboscript/tool_call"
OUTCOME_TOPIC = "/roboscript/outcome"
ACTION_TOPICS = ("goal", "cancel", "status", "feedback", "result")
CAMERA_PERIOD = 10.0  # wall seconds between two logged images of one camera topic (a 640 x 480 frame is ~1 MB)


def action_namespaces(config: RobotConfig) -> list[str]:
    """The action servers a configuration sends goals to: the trajectory's, then the gripper's."""
    gripper = config.gripper
    hands = [f"{gripper.action}/move", f"{gripper.action}/grasp"] if gripper.kind == "franka" else [gripper.action]
    return [config.trajectory_action, *hands]


def logged_topics(config: RobotConfig) -> tuple[list[str], list[str]]:
    """``(every message, throttled)``: the topics a run's log records, as the configuration names them."""
    every = [config.joint_states, "/tf_static"]
    every += [f"{ns}/{t}" for t in ACTION_TOPICS for ns in action_namespaces(config)[:1]]
    every += [f"{ns}/{t}" for ns in action_namespaces(config)[1:] for t in ("goal", "result")]
    if config.segmentation_labels:
        every.append(config.segmentation_labels)
    throttled = []
    for camera in (c for c in config.cameras if c.over_ros):
        throttled += [camera.rgb, camera.depth, camera.info] + ([camera.segmentation] if camera.segmentation else [])
    return every, throttled


class RosRunLog:
    """Records a run on the robot ``config`` describes into the bag at ``path`` until :meth:`close`.

    Starts this process's ROS node if no driver has yet."""

    def __init__(self, config: RobotConfig, path: str | Path, camera_period: float = CAMERA_PERIOD):
        import rosbag
        import rospy

        from roboscript.ros.driver import start_node

        start_node()
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._rospy = rospy
        self._bag = rosbag.Bag(str(self.path), "w", compression=_compression())
        self._lock = threading.Lock()
        self._closed = False
        self._camera_period = camera_period
        self._last_logged: dict[str, float] = {}
        self.counts: dict[str, int] = {}
        every, throttled = logged_topics(config)
        self._subscribers = [rospy.Subscriber(t, rospy.AnyMsg, self._keeper(t, False), queue_size=50) for t in every]
        self._subscribers += [
            rospy.Subscriber(t, rospy.AnyMsg, self._keeper(t, True), queue_size=1, buff_size=2**24) for t in throttled
        ]

    def _keeper(self, topic: str, throttled: bool) -> Callable:
        def keep(message) -> None:
            if throttled:
                now = time.monotonic()
                if now - self._last_logged.get(topic, -np.inf) < self._camera_period:
                    return
                self._last_logged[topic] = now
            if not hasattr(message, "_buff"):
                # rospy keeps one subscription a topic in a node: where the driver subscribed first with the
                # message's class, this callback gets the message decoded, which the bag writes as it is.
                self._write(topic, message)
                return
            header = message._connection_header
            # The bag needs the type's MD5 sum and definition, which the connection header carries: no class of
            # the type has to exist in this process.
            kind = types.SimpleNamespace(_md5sum=header["md5sum"], _full_text=header["message_definition"])
            raw = (header["type"], message._buff, header["md5sum"], kind)
            self._write(topic, raw, raw=True, connection_header={**header, "topic": topic})

        return keep

    def _write(self, topic: str, message, raw: bool = False, connection_header: dict | None = None) -> None:
        with self._lock:
            if self._closed:
                return
            self._bag.write(topic, message, self._stamp(), raw=raw, connection_header=connection_header)
            self.counts[topic] = self.counts.get(topic, 0) + 1

    def _stamp(self):
        now = self._rospy.Time.now()
        return now if not now.is_zero() else self._rospy.Time.from_sec(time.time())

    def note(self, topic: str, data: dict) -> None:
        """Writes ``data`` as JSON on ``topic`` (a ``std_msgs/String``)."""
        from std_msgs.msg import String

        self._write(topic, String(data=to_json(data)))

    def run(self, description: dict) -> None:
        self.note(RUN_TOPIC, description)

    def tool_call(self, name: str, args: tuple, kwargs: dict, answer: object = None, error: str | None = None) -> None:
        call = {"tool": name, "args": list(args), "kwargs": kwargs}
        self.note(TOOL_CALL_TOPIC, {**call, "error": error} if error is not None else {**call, "answer": answer})

    def outcome(self, outcome: dict) -> None:
        self.note(OUTCOME_TOPIC, outcome)

    def close(self) -> None:
        """Stops recording and closes the bag (it is indexed then: a bag cut short by a crash is mended by
        ``rosbag reindex``)."""
        for subscriber in self._subscribers:
            subscriber.unregister()
        with self._lock:
            if not self._closed:
                self._closed = True
                self._bag.close()

    def __enter__(self) -> RosRunLog:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _compression() -> str:
    """LZ4 where ROS's LZ4 module is installed (fast enough to keep up with the cameras), else none."""
    import rosbag

    try:
        import roslz4  # noqa: F401 - only whether it imports

        return rosbag.Compression.LZ4
    except ImportError:
        return rosbag.Compression.NONE
