"""A robot's MuJoCo model placed in a scene: the physics options every model shares, the robot attached at its
mount, and the binding of its joints, actuators and bodies in the compiled model.

The simulator, the planning scene and the kinematics all compile models this way, so what the planner checks is
what the simulator steps.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.geometry import Transform, quat_to_mujoco
from roboscript.kept import Kept
from roboscript.robots.description import ROBOT_PREFIX, RobotDescription

TIMESTEP = 0.002  # 500 Hz physics
NOSLIP_ITERATIONS = 3  # see configure_options


def configure_options(spec: mujoco.MjSpec) -> None:
    """Physics (and rendering) options of every world; robots attached later keep the world's."""
    spec.compiler.degree = False  # every angle this project writes is in radians (MjSpec defaults to degrees)
    spec.option.timestep = TIMESTEP
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = 10.0
    # MuJoCo's friction is soft: below the friction limit a contact still slides a little under load, so a held
    # object crept out of the pads (a 0.27 kg banana pinched with 20 N per finger, 0.14 mm/s at rest, 2 cm in one
    # brisk transfer). The no-slip pass after the main solver removes that creep; it costs about a tenth of a
    # step where contacts are many.
    spec.option.noslip_iterations = NOSLIP_ITERATIONS
    # Objects at rest sleep: a resting tree costs no collision or constraint work until something touches it,
    # which roughly doubles the speed of a cluttered table. Actuated trees (the arm) never sleep.
    spec.option.enableflags |= mujoco.mjtEnableBit.mjENBL_SLEEP
    spec.visual.global_.offwidth = 1920
    spec.visual.global_.offheight = 1080
    spec.visual.quality.shadowsize = 0
    spec.visual.headlight.ambient = [0.35, 0.35, 0.35]
    spec.visual.headlight.diffuse = [0.5, 0.5, 0.5]
    spec.stat.center = [0.0, 0.0, 0.8]
    spec.stat.extent = 2.0


def attach_robot(
    spec: mujoco.MjSpec, description: RobotDescription, mount: Transform, visual: bool = True
) -> None:
    """Adds the robot (names prefixed ``robot/``) to ``spec`` with its base frame at ``mount``; with ``visual``
    false, only the geoms that collide (:func:`strip_visual`)."""
    frame = spec.worldbody.add_frame(pos=list(mount.position), quat=list(quat_to_mujoco(mount.quaternion)))
    robot = description.build_spec() if visual else _colliding_specs.get(description, lambda: _colliding(description))
    spec.attach(robot.copy(), prefix=ROBOT_PREFIX, frame=frame)


COLLIDING_SPECS_KEPT = 4  # robots' specs stripped to what collides that a process keeps (a perceived scene's each)
_colliding_specs: Kept[mujoco.MjSpec] = Kept(COLLIDING_SPECS_KEPT)


def _colliding(description: RobotDescription) -> mujoco.MjSpec:
    spec = description.build_spec()
    strip_visual(spec)
    return spec


def strip_visual(spec: mujoco.MjSpec) -> None:
    """Removes the geoms that collide with nothing, and the meshes only they drew, from ``spec``.

    A model that is never rendered or stepped (a planning scene) needs only what collides: the visual meshes were
    four in five of the Panda's and made its compile 0.3 s instead of 0.05 s, paid at every rebuild of a perceived
    scene. A body whose inertia came from its visual geoms gets another (the UR5e's and FR3's links): only models
    that are not stepped may be stripped."""
    kept_meshes = set()
    for geom in list(spec.geoms):
        if geom.contype == 0 and geom.conaffinity == 0:
            spec.delete(geom)
        elif geom.type == mujoco.mjtGeom.mjGEOM_MESH:
            kept_meshes.add(geom.meshname)
    for mesh in list(spec.meshes):
        if mesh.name not in kept_meshes:
            spec.delete(mesh)


@dataclass(frozen=True)
class RobotBinding:
    """Indices of the robot's elements in the compiled model."""

    description: RobotDescription
    qpos: np.ndarray  # qpos addresses of the arm joints
    dof: np.ndarray  # dof addresses of the arm joints
    actuators: np.ndarray  # arm actuator ids
    kp: np.ndarray  # position gain of each arm actuator
    kv: np.ndarray  # velocity gain of each arm actuator
    joint_lower: np.ndarray
    joint_upper: np.ndarray
    tcp_site: int
    gripper_actuator: int
    finger_bodies: tuple[int, int]
    body_ids: frozenset[int]  # every body of the robot, gripper included

    @staticmethod
    def bind(model: mujoco.MjModel, description: RobotDescription) -> RobotBinding:
        q = RobotDescription.qualified
        joints = [model.joint(q(j)) for j in description.arm_joints]
        actuators = [model.actuator(q(a)) for a in description.arm_actuators]
        root = model.body(q(description.root_body)).id
        bodies = frozenset(b for b in range(model.nbody) if is_descendant(model, b, root))
        return RobotBinding(
            description=description,
            qpos=np.array([j.qposadr[0] for j in joints]),
            dof=np.array([j.dofadr[0] for j in joints]),
            actuators=np.array([a.id for a in actuators]),
            kp=np.array([a.gainprm[0] for a in actuators]),
            kv=np.array([-a.biasprm[2] for a in actuators]),
            joint_lower=np.array([j.range[0] for j in joints]),
            joint_upper=np.array([j.range[1] for j in joints]),
            tcp_site=model.site(q(description.tcp_site)).id,
            gripper_actuator=model.actuator(q(description.gripper.actuator)).id,
            finger_bodies=tuple(model.body(q(b)).id for b in description.gripper.finger_bodies),
            body_ids=bodies,
        )


def is_descendant(model: mujoco.MjModel, body: int, root: int) -> bool:
    """Whether ``body`` is ``root`` or lies in its subtree."""
    while body > 0:
        if body == root:
            return True
        body = model.body_parentid[body]
    return False


COMPILED_ROBOTS_KEPT = 8  # robot models compiled alone that a process keeps (a robot, a mount each)
_compiled_robots: Kept[mujoco.MjModel] = Kept(COMPILED_ROBOTS_KEPT)


def compiled_robot(description: RobotDescription, mount: Transform) -> mujoco.MjModel:
    """The robot alone at ``mount``, compiled once per process for each robot and mount (a benchmark's trials ask for
    the same few again and again). The model is shared: read it, never write it."""
    key = (description, *np.asarray(mount.position, float).tolist(), *np.asarray(mount.quaternion, float).tolist())
    return _compiled_robots.get(key, lambda: _compile_robot(description, mount))


def _compile_robot(description: RobotDescription, mount: Transform) -> mujoco.MjModel:
    spec = mujoco.MjSpec()
    configure_options(spec)
    attach_robot(spec, description, mount)
    return spec.compile()


class RobotModel:
    """The robot alone at its mount: where its TCP and links are at a joint configuration (forward kinematics),
    for backends that read only joint positions off a real arm."""

    def __init__(self, description: RobotDescription, mount: Transform):
        self.description, self.mount = description, mount
        self.model = compiled_robot(description, mount)
        self.data = mujoco.MjData(self.model)
        q = RobotDescription.qualified
        self._qpos = np.array([self.model.joint(q(j)).qposadr[0] for j in description.arm_joints])
        self._site = self.model.site(q(description.tcp_site)).id
        self.link_names = [self.model.body(b).name.removeprefix(ROBOT_PREFIX) for b in range(1, self.model.nbody)]
        self.joint_lower = np.array([self.model.joint(q(j)).range[0] for j in description.arm_joints])
        self.joint_upper = np.array([self.model.joint(q(j)).range[1] for j in description.arm_joints])

    def _at(self, q: np.ndarray) -> None:
        self.data.qpos[self._qpos] = q
        mujoco.mj_kinematics(self.model, self.data)

    def tcp(self, q: np.ndarray) -> Transform:
        """The TCP pose at arm configuration ``q``."""
        self._at(q)
        return Transform.from_rotation(self.data.site_xpos[self._site], self.data.site_xmat[self._site].reshape(3, 3))

    def link_positions(self, q: np.ndarray) -> np.ndarray:
        """The origin of every link (body) at ``q``, (n, 3), in :attr:`link_names` order."""
        self._at(q)
        return self.data.xpos[1:].copy()
