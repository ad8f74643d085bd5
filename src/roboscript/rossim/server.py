"""The simulation as a ROS robot (``roboscript ros-sim``): the MuJoCo world served through the interfaces a real arm's
driver offers, under the names of a robot configuration (franka_ros's for the Panda, ur_robot_driver's for the
UR5e), so that the ROS backend cannot tell it from the robot.

Served: joint states (``state_rate`` Hz of simulated time) and ``/clock`` (``/use_sim_time`` is set), the
``FollowJointTrajectory`` action with feedback, preemption and result codes, the gripper's action
(``control_msgs/GripperCommand``, or franka_gripper's ``move`` and ``grasp``), RGB-D images with camera info and a
labelled segmentation image per camera at ``camera_rate`` Hz of simulated time while anyone listens, the labels
on a latched topic, and TF (the robot's base and each camera's optical frame in the world frame).

One thread owns the simulation: it steps the physics paced to ``real_time_factor`` times the wall clock, and runs
the goals the action servers' threads hand it. Cameras render in a thread of their own from a copy of the state.
"""

from __future__ import annotations

import json
import queue
import threading
import time
from dataclasses import dataclass, field

import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.robot_config import RobotConfig
from roboscript.ros.master import check_master
from roboscript.ros.messages import action_types
from roboscript.rossim.cameras import OPTICAL_FRAME, CameraPublisher
from roboscript.sim.cameras import camera_pose_opencv
from roboscript.trajectory import JointTrajectory

FEEDBACK_RATE = 20.0  # Hz of simulated time: trajectory feedback
MAX_LAG = 0.1  # seconds of wall time the simulation may fall behind its pace before the pace starts afresh
# A push on the arm, for fault tests (a collision, a person's hand): JSON {"force": [fx, fy, fz], "duration": s},
# newtons on the body that carries the TCP, world frame, for that many simulated seconds.
DISTURB_TOPIC = "/roboscript/disturb"


class _Preempted(Exception):
    """Raised inside the simulation's step to stop a goal that was cancelled."""


@dataclass
class _Job:
    kind: str  # "trajectory", "gripper", "move", "grasp"
    handle: object  # the actionlib ServerGoalHandle
    cancelled: threading.Event = field(default_factory=threading.Event)


class RosSimServer:
    """Serves ``backend``'s simulation as the robot ``config`` describes (see the module's docstring)."""

    def __init__(
        self,
        backend: MujocoBackend,
        config: RobotConfig,
        real_time_factor: float = 1.0,
        state_rate: float = 100.0,
        camera_rate: float = 1.0,
        labels_topic: str = "/roboscript/segmentation_labels",
        checks: list | None = None,
    ):
        import actionlib
        import rospy
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import CameraInfo, Image, JointState
        from std_msgs.msg import String

        if real_time_factor <= 0 or state_rate <= 0 or camera_rate <= 0:
            raise ValueError(
                f"rates must be positive: real-time factor {real_time_factor}, state {state_rate} Hz, "
                f"camera {camera_rate} Hz"
            )
        self.backend, self.config = backend, config
        self.simulator = backend.simulator
        self.rtf, self.state_period, self.camera_period = real_time_factor, 1.0 / state_rate, 1.0 / camera_rate
        self._rospy = rospy
        self._jobs: queue.Queue[_Job] = queue.Queue()
        self._current: _Job | None = None
        self._state_pub = rospy.Publisher(config.joint_states, JointState, queue_size=10)
        self._clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)
        self._joint_names = self._published_joints()
        self._next_state = 0.0
        self._next_feedback = 0.0
        self._wall_start, self._sim_start = time.monotonic(), self.simulator.time
        self._stop = threading.Event()

        trajectory = action_types("control_msgs/FollowJointTrajectory")
        self._trajectory_types = trajectory
        self._servers = [
            actionlib.ActionServer(
                config.trajectory_action, trajectory.action, self._on_goal("trajectory"), self._on_cancel, False
            )
        ]
        gripper = config.gripper
        if gripper.kind == "franka":
            self._move_types = action_types("franka_gripper/Move")
            self._grasp_types = action_types("franka_gripper/Grasp")
            self._servers += [
                actionlib.ActionServer(
                    f"{gripper.action}/move", self._move_types.action, self._on_goal("move"), self._on_cancel, False
                ),
                actionlib.ActionServer(
                    f"{gripper.action}/grasp", self._grasp_types.action, self._on_goal("grasp"), self._on_cancel, False
                ),
            ]
        else:
            self._gripper_types = action_types("control_msgs/GripperCommand")
            self._servers.append(
                actionlib.ActionServer(
                    gripper.action, self._gripper_types.action, self._on_goal("gripper"), self._on_cancel, False
                )
            )

        self._checks = checks
        if checks is not None:
            from roboscript.ros.launch import EVALUATE_TOPIC, EVALUATION_TOPIC

            self._evaluation = rospy.Publisher(EVALUATION_TOPIC, String, queue_size=5, latch=True)
            self._evaluate = rospy.Subscriber(EVALUATE_TOPIC, String, self._on_goal("evaluate"), queue_size=5)
        self._disturbance: tuple[np.ndarray, float] | None = None  # (force on the TCP's body, until when)
        self._disturb = rospy.Subscriber(DISTURB_TOPIC, String, self._on_disturb, queue_size=5)
        self._cameras = CameraPublisher(backend, config, Image, CameraInfo, labels_topic, self._stop)
        self._next_camera = 0.0
        self._publish_static_frames()
        self._trajectory_goal: tuple[JointTrajectory, list[str], float] | None = None  # the one being run
        self.simulator.add_step_callback(self._on_tick)
        self._ticking = True

    # --- names ---

    def _published_joints(self) -> list[tuple[str, str]]:
        """(published name, model name) of every arm and gripper joint, the arm's first."""
        model_names = list(self.backend.joint_states())
        return [(self.config.driver_joint(name), name) for name in model_names]

    # --- the action servers' threads ---

    def _on_goal(self, kind: str):
        def accept(handle) -> None:
            self._jobs.put(_Job(kind, handle))

        return accept

    def _on_cancel(self, handle) -> None:
        current = self._current
        if current is None or current.kind == "evaluate":
            return
        if current.handle.get_goal_id().id == handle.get_goal_id().id:
            current.cancelled.set()

    def _on_disturb(self, message) -> None:
        try:
            asked = json.loads(message.data)
            force = np.array(asked["force"], dtype=float).reshape(3)
            duration = float(asked["duration"])
        except (ValueError, KeyError, TypeError) as exc:
            self._rospy.logerr("ros-sim: %s wants {'force': [fx, fy, fz], 'duration': s}: %s", DISTURB_TOPIC, exc)
            return
        self._disturbance = (force, self.simulator.time + duration)

    # --- the simulation's thread ---

    def start(self) -> None:
        for server in self._servers:
            server.start()
        self._cameras.start()

    def spin(self, until: float | None = None) -> None:
        """Steps the simulation, running goals as they come, until ROS shuts down (or ``until`` simulated seconds)."""
        self.start()
        tick = self.simulator.model.opt.timestep * self.simulator.control_stride
        while not self._rospy.is_shutdown() and not self._stop.is_set():
            if until is not None and self.simulator.time >= until:
                break
            try:
                job = self._jobs.get_nowait()
            except queue.Empty:
                self.simulator.step(tick)
                continue
            self._run(job)
        self.close()

    def close(self) -> None:
        self._stop.set()
        if self._ticking:
            self.simulator.remove_step_callback(self._on_tick)
            self._ticking = False

    def _run(self, job: _Job) -> None:
        self._current = job
        try:
            if job.kind == "evaluate":
                self._run_evaluation(job)
            elif job.kind == "trajectory":
                self._run_trajectory(job)
            elif job.kind == "gripper":
                self._run_gripper_command(job)
            else:
                self._run_franka(job)
        finally:
            self._current = None

    def _run_trajectory(self, job: _Job) -> None:
        types, handle = self._trajectory_types, job.handle
        goal = handle.get_goal().trajectory
        result = types.result()
        arm = self.config.arm_driver_joints()
        if sorted(goal.joint_names) != sorted(arm) or not goal.points:
            result.error_code = types.result.INVALID_JOINTS if goal.points else types.result.INVALID_GOAL
            result.error_string = (
                f"joints {list(goal.joint_names)} are not this controller's {arm}"
                if goal.points
                else "the trajectory has no points"
            )
            handle.set_rejected(result, result.error_string)
            return
        order = [list(goal.joint_names).index(name) for name in arm]
        times = np.array([p.time_from_start.to_sec() for p in goal.points])
        positions = np.array([[p.positions[i] for i in order] for p in goal.points])
        velocities = np.array(
            [[p.velocities[i] for i in order] if len(p.velocities) else np.zeros(len(arm)) for p in goal.points]
        )
        if times[0] > 0:  # the controller starts from where the arm is, as ros_control's does
            current = self.simulator.joint_positions()
            times = np.insert(times, 0, 0.0)
            positions = np.vstack([current, positions])
            velocities = np.vstack([np.zeros(len(arm)), velocities])
        try:
            trajectory = JointTrajectory(times, positions, velocities)
        except ValueError as exc:
            result.error_code = types.result.INVALID_GOAL
            result.error_string = str(exc)
            handle.set_rejected(result, str(exc))
            return
        handle.set_accepted()
        self._trajectory_goal = (trajectory, arm, self.simulator.time)
        try:
            self.simulator.execute(trajectory, settle=0.0)
        except _Preempted:
            self.simulator.hold(self.simulator.joint_positions())
            handle.set_canceled(result, "cancelled")
            return
        except ValueError as exc:  # the start or the joint limits: what a controller would refuse
            self.simulator.hold(self.simulator.joint_positions())
            result.error_code = types.result.INVALID_GOAL
            result.error_string = str(exc)
            handle.set_aborted(result, str(exc))
            return
        finally:
            self._trajectory_goal = None
        result.error_code = types.result.SUCCESSFUL
        handle.set_succeeded(result)

    def _run_evaluation(self, job: _Job) -> None:
        """The task's checks on the simulation's own state, for the harness that asked (never for the backend)."""
        from std_msgs.msg import String

        asked = json.loads(job.handle.data).get("id")
        try:
            truth = self.backend.ground_truth
            answer = {"id": asked, "checks": [c.evaluate(truth).to_dict() for c in self._checks]}
        except Exception as exc:  # a check that cannot be evaluated: the harness is told, the twin serves on
            answer = {"id": asked, "error": f"{type(exc).__name__}: {exc}"}
        answer["time"] = self.simulator.time
        self._evaluation.publish(String(data=json.dumps(answer)))

    def _closed_fraction(self, position: float) -> float:
        gripper = self.config.gripper
        span = gripper.closed_position - gripper.open_position
        return float(np.clip((position - gripper.open_position) / span, 0.0, 1.0)) if span else 1.0

    def _run_gripper_command(self, job: _Job) -> None:
        types, handle = self._gripper_types, job.handle
        closed = self._closed_fraction(handle.get_goal().command.position)
        handle.set_accepted()
        result = types.result()
        try:
            report = self.simulator.set_gripper(closed)
        except _Preempted:
            handle.set_canceled(result, "cancelled")
            return
        gripper = self.config.gripper
        fraction = 1.0 - report.width / self.config.robot.gripper.max_width
        result.position = gripper.open_position + fraction * (gripper.closed_position - gripper.open_position)
        result.stalled, result.reached_goal = report.blocked, not report.blocked
        handle.set_succeeded(result)

    def _run_franka(self, job: _Job) -> None:
        handle = job.handle
        goal = handle.get_goal()
        types = self._move_types if job.kind == "move" else self._grasp_types
        handle.set_accepted()
        result = types.result()
        max_width = self.config.robot.gripper.max_width
        closed = 1.0 if job.kind == "grasp" else float(np.clip(1.0 - goal.width / max_width, 0.0, 1.0))
        try:
            report = self.simulator.set_gripper(closed)
        except _Preempted:
            handle.set_canceled(result, "cancelled")
            return
        if job.kind == "grasp":
            inner, outer = goal.epsilon.inner, goal.epsilon.outer
            result.success = bool(goal.width - inner <= report.width <= goal.width + outer)
            result.error = "" if result.success else f"grasped at {report.width:.4f} m, not {goal.width:.4f} m"
        else:
            result.success, result.error = True, ""
        handle.set_succeeded(result)

    # --- every control tick ---

    def _on_tick(self, simulator) -> None:
        now = simulator.time
        if self._disturbance is not None:
            self._push(simulator, now)
        if now >= self._next_state:
            self._publish_state(now)
            self._next_state = now + self.state_period
        if now >= self._next_camera:
            self._cameras.offer(simulator, now)
            self._next_camera = now + self.camera_period
        goal = self._trajectory_goal
        if goal is not None and now >= self._next_feedback:
            self._publish_feedback(goal, now)
            self._next_feedback = now + 1.0 / FEEDBACK_RATE
        current = self._current
        if current is not None and current.cancelled.is_set():
            raise _Preempted()
        wall = time.monotonic()
        ahead = (now - self._sim_start) / self.rtf - (wall - self._wall_start)
        if ahead > 0:
            time.sleep(ahead)
        elif ahead < -MAX_LAG:
            # Behind the pace (a busy machine): from here on, not racing to make the time up. A robot never runs
            # faster to catch up, and a race ran whole trajectories in a fraction of their wall time.
            self._wall_start, self._sim_start = wall, now

    def _push(self, simulator, now: float) -> None:
        force, until = self._disturbance
        model, data = simulator.model, simulator.data
        body = model.site_bodyid[self.backend.sim_world.robot.tcp_site]
        data.xfrc_applied[body, :3] = force if now < until else 0.0
        if now >= until:
            self._disturbance = None

    def _stamp(self, now: float):
        return self._rospy.Time.from_sec(now)

    def _publish_state(self, now: float) -> None:
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import JointState

        self._clock_pub.publish(Clock(clock=self._stamp(now)))
        states = self.backend.joint_states()
        message = JointState()
        message.header.stamp = self._stamp(now)
        message.name = [published for published, _ in self._joint_names]
        message.position = [states[model] for _, model in self._joint_names]
        self._state_pub.publish(message)

    def _publish_feedback(self, goal, now: float) -> None:
        from trajectory_msgs.msg import JointTrajectoryPoint

        trajectory, arm, started = goal
        feedback = self._trajectory_types.feedback()
        feedback.header.stamp = self._stamp(now)
        feedback.joint_names = arm
        desired = trajectory.sample(now - started)[0]
        actual = self.simulator.joint_positions()
        feedback.desired = JointTrajectoryPoint(positions=list(desired))
        feedback.actual = JointTrajectoryPoint(positions=list(actual))
        feedback.error = JointTrajectoryPoint(positions=list(desired - actual))
        current = self._current
        if current is not None:
            current.handle.publish_feedback(feedback)

    def _publish_static_frames(self) -> None:
        import rospy
        from geometry_msgs.msg import TransformStamped
        from tf2_msgs.msg import TFMessage

        frames = {self.config.base_frame: self.backend.base_pose()}
        world = self.backend.sim_world
        for camera in self.backend.camera_names():
            frames[OPTICAL_FRAME.format(camera=camera)] = camera_pose_opencv(world.model, world.data, camera)
        message = TFMessage()
        for child, pose in frames.items():
            t = TransformStamped()
            t.header.frame_id, t.child_frame_id = self.config.world_frame, child
            t.header.stamp = self._stamp(self.simulator.time)
            t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = map(float, pose.position)
            qx, qy, qz, qw = map(float, pose.quaternion)
            t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w = (
                qx,
                qy,
                qz,
                qw,
            )
            message.transforms.append(t)
        self._tf_static = rospy.Publisher("/tf_static", TFMessage, queue_size=1, latch=True)
        self._tf_static.publish(message)


def serve(
    world: str,
    robot: str,
    config: RobotConfig,
    real_time_factor: float = 1.0,
    camera_rate: float = 1.0,
    seed: int = 0,
    randomize: bool = False,
    node_name: str = "roboscript_sim",
    task=None,
) -> None:
    """Runs ``roboscript ros-sim``: the world served as a ROS robot until ROS shuts down or the process is killed."""
    import rospy

    check_master()  # rospy would wait for an absent master for ever
    rospy.set_param("/use_sim_time", True)  # before any node of ours reads it: clients follow /clock
    rospy.init_node(node_name, disable_signals=False)
    with MujocoBackend(world, robot=robot, seed=seed, randomize=randomize) as backend:
        checks = task.build_checks(backend.ground_truth) if task is not None else None
        server = RosSimServer(
            backend, config, real_time_factor=real_time_factor, camera_rate=camera_rate, checks=checks
        )
        rospy.loginfo("ros-sim: %s with the %s served as %s", world, robot, config.name)
        print(f"ros-sim: serving {world} ({robot}) as {config.name}; Ctrl-C stops", flush=True)
        server.spin()
