"""The ROS 1 driver: joint states from a topic, trajectories through a ``FollowJointTrajectory`` action, the
gripper through ``control_msgs/GripperCommand`` or franka_gripper's actions, RGB-D images with camera info, a
labelled segmentation image where one is published, and camera poses from TF.

``rospy`` allows one node per process: the first driver made starts it (``init_node``), later ones share it.
"""

from __future__ import annotations

import collections
import json
import threading
import time

import numpy as np

from roboscript.drivers.base import (
    CameraSource,
    Driver,
    DriverError,
    GoalStatus,
    GripperResult,
    JointStateReading,
    TrackingSample,
    TrajectoryGoal,
)
from roboscript.drivers.realsense import RealSenseCameras
from roboscript.geometry import Transform
from roboscript.robot_config import RobotConfig
from roboscript.robot_io import CameraFrame
from roboscript.ros.master import check_master
from roboscript.ros.messages import action_types
from roboscript.trajectory import JointTrajectory

_NODE_LOCK = threading.Lock()
_NODE_STARTED = False
LABELS_TOPIC = "/roboscript/segmentation_labels"
CONNECT_TIMEOUT = 10.0  # seconds to connect to an action server the master knows of (a busy machine is slow)
FRAME_HISTORY = 4  # messages kept a camera topic: enough to find a complete frame when one topic lags the others
LABELS_WAIT = 10.0  # seconds to wait for the latched labels: a busy machine delays a new subscriber's first message
ENCODINGS = {"rgb8": (np.uint8, 3), "bgr8": (np.uint8, 3), "32FC1": (np.float32, 1), "16UC1": (np.uint16, 1)}
ENCODINGS["32SC1"] = (np.int32, 1)
_STATES = {  # actionlib's GoalStatus codes
    0: "active",  # pending
    1: "active",
    2: "cancelled",  # preempted
    3: "succeeded",
    4: "aborted",
    5: "rejected",
    6: "active",  # preempting
    7: "active",  # recalling
    8: "cancelled",  # recalled
    9: "lost",
}


def start_node(name: str = "roboscript") -> None:
    """Starts this process's ROS node once (``ROS_MASTER_URI`` names the master); Ctrl-C stays Python's. Raises
    :class:`DriverError` within :data:`roboscript.ros.master.MASTER_TIMEOUT` if no master answers."""
    global _NODE_STARTED
    import rospy

    with _NODE_LOCK:
        if not _NODE_STARTED:
            check_master()
            rospy.init_node(name, anonymous=True, disable_signals=True)
            _NODE_STARTED = True


class _Goal(TrajectoryGoal):
    def __init__(self, client, action: str):
        self._client, self._action = client, action
        self._tracking: TrackingSample | None = None

    def on_feedback(self, feedback) -> None:
        self._tracking = TrackingSample(np.array(feedback.desired.positions), np.array(feedback.actual.positions))

    def tracking(self) -> TrackingSample | None:
        return self._tracking

    def status(self) -> GoalStatus:
        return _goal_status(self._client)

    def cancel(self) -> None:
        self._client.cancel_goal()


class RosDriver(Driver):
    """The robot ``config`` describes, over ROS 1; waits up to ``config.server_timeout`` for each action server."""

    def __init__(self, config: RobotConfig, node_name: str = "roboscript"):
        import actionlib
        import rospy
        import tf2_ros
        from sensor_msgs.msg import CameraInfo, Image, JointState
        from std_msgs.msg import String

        start_node(node_name)
        self.config, self._rospy = config, rospy
        self._lock = threading.Lock()
        self._state: JointStateReading | None = None
        self._subscribers = [rospy.Subscriber(config.joint_states, JointState, self._on_state, queue_size=5)]
        timeout = config.server_timeout
        self._trajectory_types = action_types("control_msgs/FollowJointTrajectory")
        self._trajectory = actionlib.SimpleActionClient(config.trajectory_action, self._trajectory_types.action)
        self._wait_for(self._trajectory, config.trajectory_action, timeout, connecting=True)
        gripper = config.gripper
        if gripper.kind == "franka":
            self._move_types = action_types("franka_gripper/Move")
            self._grasp_types = action_types("franka_gripper/Grasp")
            self._move = actionlib.SimpleActionClient(f"{gripper.action}/move", self._move_types.action)
            self._grasp = actionlib.SimpleActionClient(f"{gripper.action}/grasp", self._grasp_types.action)
            self._wait_for(self._move, f"{gripper.action}/move", timeout, connecting=True)
            self._wait_for(self._grasp, f"{gripper.action}/grasp", timeout, connecting=True)
        else:
            self._gripper_types = action_types("control_msgs/GripperCommand")
            self._gripper = actionlib.SimpleActionClient(gripper.action, self._gripper_types.action)
            self._wait_for(self._gripper, gripper.action, timeout, connecting=True)
        self._tf = tf2_ros.Buffer()
        self._tf_listener = tf2_ros.TransformListener(self._tf)
        self._images: dict[tuple[str, str], collections.deque] = {}
        self._direct: CameraSource | None = None
        for camera in (c for c in config.cameras if c.over_ros):
            topics = {"rgb": (camera.rgb, Image), "depth": (camera.depth, Image), "info": (camera.info, CameraInfo)}
            if camera.segmentation:
                topics["segmentation"] = (camera.segmentation, Image)
            for part, (topic, kind) in topics.items():
                callback = self._keeper(camera.name, part)
                self._subscribers.append(rospy.Subscriber(topic, kind, callback, queue_size=1, buff_size=2**24))
        self._labels: dict[int, str] = {}
        labels_topic = config.segmentation_labels or LABELS_TOPIC
        self._subscribers.append(rospy.Subscriber(labels_topic, String, self._on_labels, queue_size=1))
        try:
            self._direct = _direct_cameras(config)
        except BaseException:
            self.close()
            raise

    @staticmethod
    def _wait_for(client, name: str, timeout: float, connecting: bool = False) -> None:
        """Waits on the wall clock: actionlib's own wait counts ROS time, which stands still when a simulated
        robot that publishes /clock is gone.

        ``connecting``: the first wait, while this node's connections to the server are still being made. A server
        the master does not know of fails after ``timeout``; one it knows of, which a busy machine may take seconds
        to connect to, is waited on up to ``CONNECT_TIMEOUT``."""
        started, known = time.monotonic(), None
        while not _server_ready(client):
            waited = time.monotonic() - started
            if waited > timeout and connecting and known is None:
                known = _advertised(f"{name}/status")  # asked once: the master's answer does not change meanwhile
            if waited > timeout and not (known and waited < CONNECT_TIMEOUT):
                raise DriverError(
                    f"no action server at {name} within {waited:.1f} s: is the robot's driver (or "
                    "`roboscript ros-sim`) running on this ROS master, and is this its action's name?"
                )
            time.sleep(0.01)

    # --- subscriptions (rospy's threads) ---

    def _on_state(self, message) -> None:
        reading = JointStateReading(
            dict(zip(message.name, map(float, message.position), strict=False)),
            message.header.stamp.to_sec(),
            time.monotonic(),
        )
        with self._lock:
            self._state = reading

    def _keeper(self, camera: str, part: str):
        def keep(message) -> None:
            with self._lock:
                kept = self._images.setdefault((camera, part), collections.deque(maxlen=FRAME_HISTORY))
                kept.append(message)

        return keep

    def _on_labels(self, message) -> None:
        labels = {int(k): str(v) for k, v in json.loads(message.data).items()}
        with self._lock:
            self._labels = labels

    # --- the Driver interface ---

    def joint_state(self) -> JointStateReading | None:
        with self._lock:
            return self._state

    def now(self) -> float:
        return self._rospy.get_time()

    def send_trajectory(self, joint_names: list[str], trajectory: JointTrajectory) -> TrajectoryGoal:
        from trajectory_msgs.msg import JointTrajectoryPoint

        goal = self._trajectory_types.goal()
        goal.trajectory.joint_names = list(joint_names)
        goal.trajectory.points = [
            JointTrajectoryPoint(
                positions=list(map(float, q)),
                velocities=list(map(float, v)),
                time_from_start=self._rospy.Duration.from_sec(float(t)),
            )
            for t, q, v in zip(trajectory.times, trajectory.positions, trajectory.velocities, strict=True)
        ]
        self._wait_for(self._trajectory, self.config.trajectory_action, self.config.server_timeout)
        handle = _Goal(self._trajectory, self.config.trajectory_action)
        self._trajectory.send_goal(goal, feedback_cb=handle.on_feedback)
        return handle

    def command_gripper(self, position: float, closing: bool, timeout: float) -> GripperResult:
        gripper = self.config.gripper
        if gripper.kind == "franka":
            if closing:
                goal = self._grasp_types.goal(width=position, speed=gripper.speed, force=gripper.max_effort)
                goal.epsilon.inner = goal.epsilon.outer = 0.08  # any width: the result says what was grasped
                client, name = self._grasp, f"{gripper.action}/grasp"
            else:
                goal = self._move_types.goal(width=position, speed=gripper.speed)
                client, name = self._move, f"{gripper.action}/move"
        else:
            goal = self._gripper_types.goal()
            goal.command.position, goal.command.max_effort = position, gripper.max_effort
            client, name = self._gripper, gripper.action
        self._wait_for(client, name, self.config.server_timeout)
        client.send_goal(goal)
        deadline = time.monotonic() + timeout
        while not _goal_status(client).done:
            if time.monotonic() > deadline:
                client.cancel_goal()
                raise DriverError(
                    f"the gripper at {name} did not finish within {timeout:.1f} s; the goal was cancelled"
                )
            time.sleep(0.01)
        result, status = client.get_result(), _goal_status(client)
        if status.state != "succeeded" or result is None:
            raise DriverError(f"the gripper at {name} {status.state} the command: {status.detail}")
        if gripper.kind == "franka":
            return GripperResult(position, stalled=None, reached=bool(result.success))
        return GripperResult(result.position, bool(result.stalled), bool(result.reached_goal))

    def camera_names(self) -> list[str]:
        return [c.name for c in self.config.cameras]

    def camera_frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        if self._direct is not None and camera in self._direct.names():
            # read apart from ROS, stamped on this host's monotonic clock rather than ROS time
            return self._direct.frame(camera, timeout, time.monotonic() - (self.now() - not_before))
        config = next(c for c in self.config.cameras if c.name == camera)
        parts = ["rgb", "depth", "info"] + (["segmentation"] if config.segmentation else [])
        deadline = time.monotonic() + timeout
        while True:
            with self._lock:
                kept = {p: list(self._images.get((camera, p), ())) for p in parts}
            messages = _newest_complete(kept, not_before)
            if messages is not None:
                break
            if time.monotonic() > deadline:
                missing = [p for p, m in kept.items() if not m]
                raise DriverError(
                    f"no complete frame from camera {camera!r} within {timeout:.1f} s"
                    + (
                        f" (nothing yet on {', '.join(missing)})"
                        if missing
                        else f" (none of the last {FRAME_HISTORY} images of each part share a stamp after "
                        f"{not_before:.2f} s)"
                    )
                )
            time.sleep(0.01)
        info = messages["info"]
        return CameraFrame(
            name=camera,
            rgb=_image_array(messages["rgb"]),
            depth=_depth_metres(messages["depth"]),
            segmentation=_image_array(messages["segmentation"]) if config.segmentation else None,
            intrinsics=np.array(info.K, dtype=float).reshape(3, 3),
            extrinsics=self.frame_pose(messages["rgb"].header.frame_id, timeout),
        )

    def frame_pose(self, frame: str, timeout: float = 2.0) -> Transform:
        """Where ``frame`` is in the configuration's world frame, from TF."""
        import tf2_ros

        world, latest = self.config.world_frame, self._rospy.Time(0)
        deadline = time.monotonic() + timeout  # the wall clock's: ROS time stands still without /clock
        while not self._tf.can_transform(world, frame, latest):
            if time.monotonic() > deadline:
                raise DriverError(f"no transform from {world} to {frame} in TF within {timeout:.1f} s")
            time.sleep(0.01)
        try:
            t = self._tf.lookup_transform(world, frame, latest).transform
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException) as exc:
            raise DriverError(f"no transform from {world} to {frame} in TF: {exc}") from None
        return Transform(
            np.array([t.translation.x, t.translation.y, t.translation.z]),
            np.array([t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w]),
        )

    def segmentation_labels(self) -> dict[int, str]:
        """The labels' latched message, waited for (up to :data:`LABELS_WAIT`) where cameras publish segmentation."""
        deadline = time.monotonic() + max(self.config.server_timeout, LABELS_WAIT)
        wanted = any(c.segmentation for c in self.config.cameras)
        while True:
            with self._lock:
                if self._labels or not wanted or time.monotonic() > deadline:
                    return dict(self._labels)
            time.sleep(0.01)

    def close(self) -> None:
        for subscriber in self._subscribers:
            subscriber.unregister()
        self._subscribers.clear()
        if self._direct is not None:
            self._direct.close()
            self._direct = None


def _direct_cameras(config: RobotConfig) -> CameraSource | None:
    """The configuration's cameras read without ROS (RealSense cameras through librealsense), if it has any."""
    direct = [c for c in config.cameras if not c.over_ros]
    if not direct:
        return None
    return RealSenseCameras(direct)


def _newest_complete(kept: dict[str, list], not_before: float) -> dict | None:
    """The newest set of one message a part that share a stamp at or after ``not_before``; ``None`` if none.

    A camera's image, depth, info and segmentation travel on topics of their own, and under load one lags another
    by a frame or more: the newest of each are then of different instants, while an older complete set is kept."""
    if not all(kept.values()):
        return None
    by_part = {p: {m.header.stamp.to_sec(): m for m in messages} for p, messages in kept.items()}
    common = set.intersection(*(set(stamps) for stamps in by_part.values()))
    usable = [t for t in common if t >= not_before]
    if not usable:
        return None
    newest = max(usable)
    return {p: stamps[newest] for p, stamps in by_part.items()}


def _advertised(topic: str) -> bool:
    """Whether a live node publishes ``topic``: the master lists it, and the node's own API still accepts a
    connection (a node that was killed stays listed on the master). A master that does not answer knows of none."""
    import socket
    from urllib.parse import urlparse

    import rosgraph

    try:
        master = rosgraph.Master("/roboscript_probe")
        publishers = next((nodes for name, nodes in master.getSystemState()[0] if name == topic), [])
        for node in publishers:
            api = urlparse(master.lookupNode(node))
            try:
                socket.create_connection((api.hostname, api.port), timeout=0.5).close()
                return True
            except OSError:
                continue
    except Exception:  # the master gone or unreachable
        return False
    return False


def _goal_status(client) -> GoalStatus:
    """A SimpleActionClient's goal, done only once its result has arrived (a terminal status may come first)."""
    from actionlib import CommState, SimpleGoalState

    if client.simple_state != SimpleGoalState.DONE:
        # SimpleActionClient.send_goal learns its goal's handle only after sending the goal: the transitions of a
        # goal the server rejects (or ends) before then are dropped ("a goal handle that we're not tracking") and
        # the simple state stays pending for ever. The handle's own state machine did follow them.
        handle = client.gh
        if handle is None or handle.get_comm_state() != CommState.DONE:
            return GoalStatus("active")
    return GoalStatus(_STATES.get(client.get_state(), "lost"), client.get_goal_status_text())


def _server_ready(client) -> bool:
    """Whether a SimpleActionClient's server is there: it has heard the server's status, and the server is connected
    to its goal and cancel topics and it to the server's result and feedback (actionlib's own test, without its
    wait)."""
    inner = client.action_client
    status = inner.last_status_msg
    if status is None:
        return False
    server = status._connection_header["callerid"]
    if not (inner.pub_goal.impl.has_connection(server) and inner.pub_cancel.impl.has_connection(server)):
        return False
    return all(
        any(c.callerid_pub == server for c in subscriber.impl.connections)
        for subscriber in (inner.result_sub, inner.feedback_sub)
    )


def _image_array(message) -> np.ndarray:
    if message.encoding not in ENCODINGS:
        raise DriverError(f"image encoding {message.encoding!r} is not read; encodings: {', '.join(ENCODINGS)}")
    dtype, channels = ENCODINGS[message.encoding]
    array = np.frombuffer(message.data, dtype=dtype).reshape(message.height, message.width, channels)
    if message.encoding == "bgr8":
        array = array[..., ::-1]
    return np.ascontiguousarray(array if channels > 1 else array[..., 0])


def _depth_metres(message) -> np.ndarray:
    depth = _image_array(message)
    return depth.astype(np.float32) / 1000.0 if message.encoding == "16UC1" else depth.astype(np.float32)
