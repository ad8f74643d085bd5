"""Robot configuration files: how a real (or served) robot is reached and kept safe.

A YAML file names the robot's description (``panda``, ``ur5e``, ``fr3``) and its driver: ``ros`` (the default: the
driver's joint names for the model's joints, where joint states, trajectories and the gripper are found as ROS topics
and action servers, the frames) or ``franky`` (libfranka's address, and where the base stands). Then the cameras
(:mod:`roboscript.camera_config`) and the safety limits: a speed scale, the workspace box every trajectory must stay
in, and the table's height no TCP may go below. Packaged examples live in ``robot_configs/`` (:func:`config_names`
lists them).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from roboscript.camera_config import CameraConfig, parse_cameras
from roboscript.datafile import DataFileError, PackagedFiles, Reader, names_a_file, read_data_file
from roboscript.errors import UsageError
from roboscript.geometry import Transform
from roboscript.robots import ROBOTS, RobotDescription, get_robot

GRIPPER_KINDS = ("gripper_command", "franka")
DRIVERS = ("ros", "franky")
FRANKA_ROBOTS = (
    "fr3",
    "panda",
)  # the arms libfranka drives  # how the arm is reached: ROS 1 topics and actions, or libfranka through franky
# The packaged configuration of each arm: what ros-sim serves by default, and what a ROS trial connects with.
DEFAULT_CONFIGS = {"panda": "panda_franka_ros", "ur5e": "ur5e_ur_robot_driver"}
DEFAULT_SPEED_SCALE = 0.25  # of the arm's limits: what a real arm runs at unless its configuration says otherwise


class RobotConfigError(DataFileError):
    kind = "robot configuration"


@dataclass(frozen=True)
class GripperConfig:
    """How the gripper is commanded and read.

    ``gripper_command``: a ``control_msgs/GripperCommand`` action at ``action``; the command's position is
    ``open_position`` when open and ``closed_position`` when closed (metres of opening for a Franka hand, the driver
    joint's angle for a Robotiq 2F-85). ``franka``: franka_gripper's ``move`` and ``grasp`` actions under
    ``action`` (a namespace such as ``/franka_gripper``). The opening is read from ``width_joints`` in the joint
    states: ``width = width_scale * sum(positions) + width_offset``.
    """

    kind: str
    action: str
    open_position: float
    closed_position: float
    max_effort: float
    speed: float
    width_joints: tuple[str, ...]
    width_scale: float
    width_offset: float


@dataclass(frozen=True)
class FrankySettings:
    """A Franka arm driven through libfranka (franky): the robot's control address, whether libfranka insists on a
    real-time kernel, and where the arm's base stands in the world frame (libfranka knows nothing of the world)."""

    host: str
    realtime: bool
    base_pose: Transform


@dataclass(frozen=True)
class Workspace:
    """The box every link of the arm must stay inside, and the table's top, which the TCP must stay above."""

    lower: tuple[float, float, float]
    upper: tuple[float, float, float]
    table_height: float

    def contains(self, point) -> bool:
        return all(lo <= p <= hi for lo, p, hi in zip(self.lower, point, self.upper, strict=True))


@dataclass(frozen=True)
class RobotConfig:
    """A robot reached through a driver; see the module's docstring for the fields."""

    name: str
    robot: RobotDescription
    joint_names: dict[str, str]  # model joint name -> driver joint name
    joint_states: str
    trajectory_action: str
    gripper: GripperConfig
    cameras: tuple[CameraConfig, ...]
    world_frame: str
    base_frame: str
    segmentation_labels: str | None  # the topic that names the segmentation images' labels
    speed_scale: float
    workspace: Workspace
    tracking_tolerance: float  # radians any joint may lag its set-point before the goal is cancelled
    state_timeout: float  # seconds without a joint state after which the robot is stopped
    server_timeout: float  # seconds to wait for an action server; for a result once the set-point stands still
    source: str = ""
    driver: str = "ros"
    franky: FrankySettings | None = None

    def driver_joint(self, model_joint: str) -> str:
        return self.joint_names.get(model_joint, model_joint)

    def arm_driver_joints(self) -> list[str]:
        return [self.driver_joint(j) for j in self.robot.arm_joints]


def franky_at(config: RobotConfig, host: str, realtime: bool | None = None) -> RobotConfig:
    """``config`` (driven through franky) pointed at the arm at ``host``; ``realtime``: whether libfranka insists on
    a real-time kernel (default: as configured). Every message that names the arm's address names the new one."""
    if config.franky is None:
        raise RobotConfigError(config.source or config.name, "driver", f"is {config.driver}, not franky")
    settings = replace(config.franky, host=host, realtime=config.franky.realtime if realtime is None else realtime)
    where = f"libfranka at {host}"
    return replace(config, franky=settings, joint_states=where, trajectory_action=where)


def ros_config_for(robot: str) -> str:
    """The packaged ROS configuration of ``robot``; a :class:`UsageError` that says what to pass where there is
    none (the FR3 is packaged for libfranka only)."""
    if robot not in DEFAULT_CONFIGS:
        raise UsageError(
            f"no packaged ROS configuration for the {robot}: name one with --robot-config FILE (packaged ROS ones: "
            f"{', '.join(f'{r}: {c}' for r, c in DEFAULT_CONFIGS.items())})"
        )
    return DEFAULT_CONFIGS[robot]


CONFIGS = PackagedFiles("robot_configs", "robot configuration")


def config_names() -> list[str]:
    """The packaged robot configurations."""
    return CONFIGS.names()


def config_path(reference: str | Path) -> Path:
    """A packaged configuration's file, or ``reference`` itself where it names a file."""
    if names_a_file(reference):
        return Path(reference)
    names = config_names()
    if str(reference) not in names:
        raise RobotConfigError(str(reference), "file", f"no such packaged configuration; packaged: {', '.join(names)}")
    return CONFIGS.directory() / f"{reference}.yaml"


def load_robot_config(reference: str | Path) -> RobotConfig:
    """The configuration in a file (or a packaged one's name), validated."""
    path = config_path(reference)
    return parse_robot_config(read_data_file(path, RobotConfigError), str(path))


def parse_robot_config(data, source: str = "<config>") -> RobotConfig:
    """Validates parsed YAML into a :class:`RobotConfig`; errors name the field and what would be valid."""
    fields = {"name", "robot", "joints", "driver", "ros", "franky", "gripper", "cameras", "safety", "description"}
    top = Reader(source, "configuration", data, fields, RobotConfigError)
    driver = top.string("driver", "ros")
    if driver not in DRIVERS:
        top.fail(f"unknown driver {driver!r}; drivers: {', '.join(DRIVERS)}")
    elsewhere = {"ros": "franky", "franky": "ros"}[driver]
    if elsewhere in top.data:
        top.fail(f"field {elsewhere!r} is for driver {elsewhere}, and this configuration's driver is {driver}")
    robot_name = top.string("robot")
    if robot_name not in ROBOTS:
        top.fail(f"unknown robot {robot_name!r}; robots: {', '.join(sorted(ROBOTS))}")
    robot = get_robot(robot_name)
    joints = top.data.get("joints", {})
    if not isinstance(joints, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in joints.items()):
        top.fail(f"field 'joints' must map the model's joint names to the driver's, got {joints!r}")
    known = set(robot.arm_joints) | set(robot.gripper.joints)
    unknown = sorted(set(joints) - known)
    if unknown:
        top.fail(f"joints: {unknown[0]!r} is no joint of the {robot_name}; its joints: {', '.join(sorted(known))}")
    franky = (
        _franky(Reader(source, "franky", top.required("franky"), _FRANKY_FIELDS, RobotConfigError))
        if (driver == "franky")
        else None
    )
    ros_fields = {"joint_states", "trajectory_action", "world_frame", "base_frame", "segmentation_labels"}
    ros = Reader(source, "ros", top.required("ros") if franky is None else {}, ros_fields, RobotConfigError)
    gripper_data = top.required("gripper") if franky is None else top.data.get("gripper", {"kind": "franka"})
    gripper = _gripper(Reader(source, "gripper", gripper_data, set(_GRIPPER_FIELDS), RobotConfigError), robot, driver)
    cameras = top.data.get("cameras", [])
    if franky is not None and robot_name not in FRANKA_ROBOTS:
        top.fail(
            f"driver franky drives a Franka arm; robot must be one of {', '.join(FRANKA_ROBOTS)}, got {robot_name!r}"
        )
    for index, camera in enumerate(cameras if isinstance(cameras, list) else []):
        if franky is not None and not (isinstance(camera, dict) and "realsense" in camera):
            top.fail(
                f"cameras[{index}]: a robot driven through franky reads its cameras directly, so each camera needs a "
                "'realsense' entry (serial, position, quaternion)"
            )
    safety = Reader(source, "safety", top.data.get("safety", {}), set(_SAFETY_FIELDS), RobotConfigError)
    speed_scale = safety.number("speed_scale", DEFAULT_SPEED_SCALE)
    if not 0 < speed_scale <= 1:
        safety.fail(f"speed_scale must be in (0, 1], got {speed_scale}")
    lower = safety.vector("workspace_lower", (3,))
    upper = safety.vector("workspace_upper", (3,))
    if any(lo >= hi for lo, hi in zip(lower, upper, strict=True)):
        safety.fail(f"workspace_lower {lower} must be below workspace_upper {upper} on every axis")
    timeouts = {k: safety.number(k, d) for k, d in _SAFETY_FIELDS.items() if d is not None}
    for key, value in timeouts.items():
        if value <= 0:
            safety.fail(f"{key} must be positive, got {value}")
    segmentation_labels = ros.data.get("segmentation_labels")
    if segmentation_labels is not None:
        segmentation_labels = ros.string("segmentation_labels")
    return RobotConfig(
        name=top.string("name", Path(source).stem),
        robot=robot,
        joint_names=dict(joints),
        joint_states=ros.string("joint_states", "/joint_states") if franky is None else f"libfranka at {franky.host}",
        trajectory_action=ros.string("trajectory_action") if franky is None else f"libfranka at {franky.host}",
        gripper=gripper,
        cameras=parse_cameras(source, cameras, RobotConfigError),
        world_frame=ros.string("world_frame", "world"),
        base_frame=ros.string("base_frame") if franky is None else "",
        segmentation_labels=segmentation_labels,
        speed_scale=speed_scale,
        workspace=Workspace(lower, upper, safety.number("table_height")),
        tracking_tolerance=timeouts["tracking_tolerance"],
        state_timeout=timeouts["state_timeout"],
        server_timeout=timeouts["server_timeout"],
        source=source,
        driver=driver,
        franky=franky,
    )


_FRANKY_FIELDS = {"host", "realtime", "base_position", "base_quaternion"}


def _franky(reader: Reader) -> FrankySettings:
    realtime = reader.data.get("realtime", "enforce")
    if realtime not in ("enforce", "ignore"):
        reader.fail(
            f"realtime must be 'enforce' (libfranka's default: a real-time kernel) or 'ignore' (franky-sim, or a "
            f"machine without one), got {realtime!r}"
        )
    quaternion = np.array(reader.vector("base_quaternion", (4,), (1.0, 0.0, 0.0, 0.0)))
    if not 0.9 < np.linalg.norm(quaternion) < 1.1:
        reader.fail(f"base_quaternion {tuple(quaternion)} (w, x, y, z) must have length 1")
    return FrankySettings(
        host=reader.string("host"),
        realtime=realtime == "enforce",
        base_pose=Transform.from_mujoco(
            np.array(reader.vector("base_position", (3,))), quaternion / np.linalg.norm(quaternion)
        ),
    )


_GRIPPER_FIELDS = (
    "kind",
    "action",
    "open_position",
    "closed_position",
    "max_effort",
    "speed",
    "width_joints",
    "width_scale",
    "width_offset",
)
_SAFETY_FIELDS = {
    "speed_scale": None,
    "workspace_lower": None,
    "workspace_upper": None,
    "table_height": None,
    "tracking_tolerance": 0.1,
    "state_timeout": 1.0,
    "server_timeout": 1.5,
}


def _gripper(reader: Reader, robot: RobotDescription, driver: str = "ros") -> GripperConfig:
    kind = reader.string("kind")
    if kind not in GRIPPER_KINDS:
        reader.fail(f"unknown gripper kind {kind!r}; kinds: {', '.join(GRIPPER_KINDS)}")
    if driver == "franky" and kind != "franka":
        reader.fail(f"a robot driven through franky has the Franka hand: kind 'franka', got {kind!r}")
    # libfranka reads the hand's width itself; the driver reports it as the model's finger joints
    width_joints = (
        reader.required("width_joints")
        if driver == "ros"
        else reader.data.get("width_joints", list(robot.gripper.joints))
    )
    if not isinstance(width_joints, list) or not width_joints or not all(isinstance(j, str) for j in width_joints):
        reader.fail(f"width_joints must be a list of joint names, got {width_joints!r}")
    return GripperConfig(
        kind=kind,
        action=reader.string("action") if driver == "ros" else _no_action(reader),
        # franka_gripper speaks metres of opening: open is the hand's full width
        open_position=reader.number("open_position", robot.gripper.max_width if kind == "franka" else None),
        closed_position=reader.number("closed_position", 0.0 if kind == "franka" else None),
        max_effort=reader.number("max_effort", 40.0),
        speed=reader.number("speed", 0.1),
        width_joints=tuple(width_joints),
        width_scale=reader.number("width_scale", 1.0),
        width_offset=reader.number("width_offset", 0.0),
    )


def _no_action(reader: Reader) -> str:
    if "action" in reader.data:
        reader.fail("field 'action' names a ROS action; libfranka drives the Franka hand itself (leave it out)")
    return ""
