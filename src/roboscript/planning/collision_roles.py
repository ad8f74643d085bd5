"""Which geoms of a planning model may collide with which: each body takes a role (the moving arm, the environment,
the fixed base, the first link, the gripper, a held object), and a role is a pair of MuJoCo contype/conaffinity
bits and a margin (MuJoCo reports pairs closer than the larger margin of the two)."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.robots.description import RobotDescription
from roboscript.robots.mujoco_model import RobotBinding, is_descendant

# Two geoms collide if the type of either shares a bit with the affinity of the other. Moving arm links collide with
# everything; the environment only with the robot and held objects (objects resting on the table are no planning
# problem); the fixed base not with the table it stands on; the first moving link not with the base it turns on
# (MuJoCo's parent-child filter skips bodies welded to the world); the gripper's parts not with each other (its
# linkage touches itself); a held object not with the gripper holding it.
_ARM, _ENV, _BASE, _FIRST, _GRIPPER, _HELD = 1, 2, 4, 8, 16, 32
ROLES = {
    "arm": (_ARM, _ARM | _ENV | _BASE),
    "env": (_ENV, _ARM),
    "base": (_BASE, _ARM),
    "first_link": (_FIRST, _ARM | _ENV),
    "gripper": (_GRIPPER, _ARM | _ENV | _BASE | _FIRST),
    "held": (_HELD, _ARM | _ENV | _BASE | _FIRST),
}


@dataclass(frozen=True)
class RobotBodies:
    """The robot's bodies as a planning model's queries tell them apart."""

    is_robot: np.ndarray  # mask over the model's bodies
    gripper: np.ndarray  # ids of the bodies below the TCP's
    placed_by_tcp: np.ndarray  # mask: the last arm joint's body and all it carries (the TCP's pose alone places them)
    moving: np.ndarray  # ids of the bodies the arm's joints move (the base stays where it is mounted)


def assign_roles(model: mujoco.MjModel, robot: RobotBinding, padding: float, collides: np.ndarray) -> RobotBodies:
    """Gives every colliding geom of ``model`` (``collides``, a mask) its role: the robot's arm links and gripper
    with the ``padding`` as their margin, the rest of the world as environment. Returns the robot's bodies."""
    nbody = model.nbody
    is_robot = np.zeros(nbody, dtype=bool)
    is_robot[list(robot.body_ids)] = True
    tcp_body = model.site_bodyid[robot.tcp_site]
    gripper_bodies = np.array([b for b in robot.body_ids if is_descendant(model, b, tcp_body)])
    wrist = model.dof_bodyid[robot.dof[-1]]
    placed_by_tcp = np.array([is_descendant(model, b, wrist) for b in range(nbody)])
    moved = np.array([moved_by_arm(model, b, robot) for b in range(nbody)])
    base = is_robot & ~moved
    first_link = is_robot & moved & base[model.body_parentid]
    gripper = np.zeros(nbody, dtype=bool)
    gripper[gripper_bodies] = True

    def role(bodies: np.ndarray, name: str, margin: float) -> None:
        set_role(model, bodies[model.geom_bodyid] & collides, name, margin)

    role(~is_robot, "env", 0.0)
    # The floor is out of the arm's reach (the table is in the way) and a plane is tested against every geom.
    planes = (model.geom_type == mujoco.mjtGeom.mjGEOM_PLANE) & (model.geom_bodyid == 0)
    model.geom_contype[planes], model.geom_conaffinity[planes] = 0, 0
    role(is_robot & moved & ~first_link & ~gripper, "arm", padding)
    role(base, "base", 0.0)
    # The first link only turns about the base's axis, and it may be mounted closer to the table than the padding
    # (a UR5e's shoulder, 3 mm): with the padding it would collide in every configuration.
    role(first_link, "first_link", 0.0)
    role(gripper, "gripper", padding)
    return RobotBodies(is_robot, gripper_bodies, placed_by_tcp, np.flatnonzero(is_robot & moved))


def set_role(model: mujoco.MjModel, geoms: np.ndarray, role: str, margin: float) -> None:
    """Gives the geoms of the mask ``geoms`` the bits of ``role`` and the margin ``margin``."""
    model.geom_contype[geoms], model.geom_conaffinity[geoms] = ROLES[role]
    model.geom_margin[geoms] = margin


def sync_body_margins(model: mujoco.MjModel, collides: np.ndarray) -> None:
    """Each body's margin, the largest of its colliding geoms' (``collides``, a mask of geoms). MuJoCo's midphase
    prunes pairs of bodies of several geoms each by the body margins compiled into the model (zero here), not by the
    geoms': without this a gripper link 2.7 mm above the table (the padding is 5 mm) passed as free."""
    margins = np.zeros(model.nbody)
    geoms = np.flatnonzero(collides)
    np.maximum.at(margins, model.geom_bodyid[geoms], model.geom_margin[geoms])
    model.body_margin[:] = margins


def moved_by_arm(model: mujoco.MjModel, body: int, robot: RobotBinding) -> bool:
    """Whether one of the arm's joints moves ``body`` (it hangs below one)."""
    arm_dofs = set(robot.dof.tolist())
    while body > 0:
        if model.body_dofnum[body] > 0 and model.body_dofadr[body] in arm_dofs:
            return True
        body = model.body_parentid[body]
    return False


def open_finger_positions(
    model: mujoco.MjModel, robot: RobotBinding, gripper_bodies: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The qpos addresses of the gripper's joints and their values when it is fully open: the description's open
    positions for its driven joints, the model's reference for the rest of a linkage (open at zero, as the 2F-85's
    followers are)."""
    open_by_name = dict(
        zip(
            (RobotDescription.qualified(j) for j in robot.description.gripper.joints),
            robot.description.gripper.open_qpos,
            strict=True,
        )
    )
    joints = [j for j in range(model.njnt) if model.jnt_bodyid[j] in set(gripper_bodies.tolist())]
    addresses = np.array([model.jnt_qposadr[j] for j in joints], dtype=int)
    values = np.array([open_by_name.get(model.joint(j).name, model.qpos0[model.jnt_qposadr[j]]) for j in joints])
    return addresses, values
