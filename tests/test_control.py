"""Trajectory tracking, grasping and articulated furniture, with both arms."""

import mujoco
import numpy as np
import pytest

from helpers import ARMS, min_jerk_through, tcp_ik
from roboscript.backends import BackendError
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.sim.world_file import parse_world
from roboscript.trajectory import JointTrajectory

ROBOTS = ARMS
TABLE = 0.82


def cube_world():
    return parse_world({"name": "cube", "objects": [{"name": "cube", "type": "wooden_block", "position": [0.0, 0.0]}]})


@pytest.mark.parametrize("robot", ROBOTS)
def test_tcp_tracks_scripted_joint_trajectory_within_1cm(robot):
    backend = MujocoBackend(cube_world(), robot=robot, settle=0.2)
    sim = backend.sim_world
    targets = [
        [0.1, -0.25, TABLE + 0.3],
        [0.15, 0.3, TABLE + 0.2],
        [-0.1, 0.35, TABLE + 0.45],
        [0.0, -0.3, TABLE + 0.25],
    ]
    q = backend.joint_positions()
    waypoints = [q]
    for target in targets:
        q = tcp_ik(sim, target, q0=q)
        waypoints.append(q)
    d = backend.robot
    trajectory = min_jerk_through(np.array(waypoints), d.max_velocity, d.max_acceleration, speed_scale=0.6)
    report = backend.execute_trajectory(trajectory)
    assert report.max_tcp_error < 0.01, report
    assert report.final_tcp_error < 0.002, report
    np.testing.assert_allclose(backend.tcp_pose().position, targets[-1], atol=0.003)


@pytest.mark.parametrize("robot", ROBOTS)
def test_gripper_closes_on_5cm_cube_and_lifts_it_10cm(robot):
    backend = MujocoBackend(cube_world(), robot=robot, settle=0.3)
    sim, d = backend.sim_world, backend.robot
    top = TABLE + 0.025  # grasp at the cube's centre height
    q_above = tcp_ik(sim, [0, 0, top + 0.12], q0=backend.joint_positions())
    q_grasp = tcp_ik(sim, [0, 0, top], q0=q_above)
    q_lift = tcp_ik(sim, [0, 0, top + 0.10], q0=q_grasp)
    backend.execute_trajectory(
        min_jerk_through([backend.joint_positions(), q_above, q_grasp], d.max_velocity, d.max_acceleration, 0.5)
    )
    closed = backend.close_gripper()
    assert closed.blocked and closed.width == pytest.approx(0.05, abs=0.004), closed
    z_before = backend.ground_truth.pose("cube").position[2]
    backend.execute_trajectory(
        min_jerk_through([backend.joint_positions(), q_lift], d.max_velocity, d.max_acceleration, 0.5)
    )
    backend.wait(0.5)
    lifted = backend.ground_truth.pose("cube").position[2] - z_before
    assert lifted == pytest.approx(0.10, abs=0.01), f"cube rose {lifted:.4f} m"
    backend.open_gripper()
    backend.wait(1.0)
    assert backend.ground_truth.pose("cube").position[2] == pytest.approx(TABLE, abs=0.005), "released cube falls"


def drawer_world():
    objects = [{"name": f"box_{k}", "type": "gelatin_box", "inside": f"cabinet.drawer_{k}"} for k in range(3)]
    return parse_world(
        {
            "name": "drawers",
            "objects": objects,
            "furniture": [
                {
                    "name": "cabinet",
                    "type": "cabinet",
                    "position": [-0.42, 0.62],
                    "rows": ["drawer"] * 3 + ["door"],
                }
            ],
        }
    )


@pytest.mark.parametrize("drawer", [0, 1, 2])
def test_pulling_a_drawer_carries_the_object_inside(drawer):
    backend = MujocoBackend(drawer_world(), settle=0.5)
    gt = backend.ground_truth
    info = gt.joint(f"cabinet.drawer_{drawer}")
    assert info.type == "prismatic"
    np.testing.assert_allclose(info.axis, [1, 0, 0], atol=1e-9)  # drawers open along world +x
    assert gt.joint(f"cabinet.handle_{drawer}").name == info.name  # a handle reports its drawer's joint
    box_before = gt.pose(f"box_{drawer}").position
    others_before = {k: gt.pose(f"box_{k}").position for k in range(3) if k != drawer}
    model, data = backend.sim_world.model, backend.sim_world.data
    joint = model.joint(info.name)
    dof, adr = joint.dofadr[0], joint.qposadr[0]

    def pull(simulator):  # a hand pulling the drawer toward 0.2 m open, at most 30 N
        force = 150.0 * (0.2 - data.qpos[adr]) - 40.0 * data.qvel[dof]
        data.qfrc_applied[dof] = np.clip(force, -30.0, 30.0)

    backend.simulator.add_step_callback(pull)
    backend.wait(2.0)
    backend.simulator.remove_step_callback(pull)
    data.qfrc_applied[dof] = 0.0
    backend.wait(0.3)
    opened = gt.joint(f"cabinet.drawer_{drawer}").value
    assert opened > 0.18, f"drawer opened only {opened:.3f} m"
    moved = gt.pose(f"box_{drawer}").position - box_before
    assert moved[0] == pytest.approx(opened, abs=0.01), f"box moved {moved.round(4)}, drawer {opened:.3f}"
    assert abs(moved[1]) < 0.01 and abs(moved[2]) < 0.005
    for k, before in others_before.items():
        assert np.linalg.norm(gt.pose(f"box_{k}").position - before) < 0.003, "other drawers stay shut"


def test_door_swings_outward_on_its_hinge():
    backend = MujocoBackend(drawer_world(), settle=0.2)
    gt = backend.ground_truth
    info = gt.joint("cabinet.door_0")
    assert info.type == "revolute"
    np.testing.assert_allclose(np.abs(info.axis), [0, 0, 1], atol=1e-9)
    handle_before = gt.box("cabinet.handle_3").center
    model, data = backend.sim_world.model, backend.sim_world.data
    data.qfrc_applied[model.jnt_dofadr[model.joint(info.name).id]] = 3.0
    backend.wait(1.0)
    assert gt.joint("cabinet.door_0").value > 0.8
    assert gt.box("cabinet.handle_3").center[0] > handle_before[0] + 0.15, "the free edge moves out, toward +x"


def test_trajectory_errors_are_explained():
    backend = MujocoBackend(cube_world(), settle=0.0)
    q = backend.joint_positions()
    far = q + 0.5
    with pytest.raises(BackendError, match=r"starts .* away from the current configuration"):
        backend.execute_trajectory(JointTrajectory(np.array([0.0, 1.0]), np.array([far, far]), np.zeros((2, 7))))
    beyond = q.copy()
    beyond[3] = 0.5  # the Panda's joint 4 must stay below -0.07 rad
    with pytest.raises(BackendError, match="leaves the joint limits"):
        backend.execute_trajectory(JointTrajectory(np.array([0.0, 1.0]), np.array([q, beyond]), np.zeros((2, 7))))
    with pytest.raises(BackendError, match="has 6 joints, the panda arm has 7"):
        backend.execute_trajectory(JointTrajectory(np.array([0.0, 1.0]), np.zeros((2, 6)), np.zeros((2, 6))))
    with pytest.raises(ValueError, match=r"within 0 \(open\) and 1 \(closed\)"):
        backend.set_gripper(1.5)


def test_objects_at_rest_sleep_and_wake_when_touched_or_moved():
    backend = MujocoBackend(cube_world(), robot="panda", settle=0.0)
    sim, model, data = backend.simulator, backend.sim_world.model, backend.sim_world.data
    assert sim.sleeping_enabled
    backend.wait(1.5)
    cube = model.body("cube")
    cube_tree = model.body_treeid[cube.id]
    assert data.tree_asleep[cube_tree] >= 0, "a cube at rest on the table should be asleep"
    # The arm never sleeps, and set-point kinematics stays exact while the rest of the world sleeps.
    q = backend.joint_positions()
    np.testing.assert_allclose(sim.tcp_position_at(q), sim.tcp_position(), atol=1e-9)
    # Moving a sleeping body by hand wakes it: it falls back onto the table.
    adr = model.jnt_qposadr[model.body_jntadr[cube.id]]
    data.qpos[adr + 2] += 0.05
    backend.wait(0.5)
    assert backend.ground_truth.pose("cube").position[2] == pytest.approx(TABLE, abs=0.005)


def test_sleeping_can_be_switched_off():
    backend = MujocoBackend(cube_world(), robot="panda", settle=0.0)
    backend.simulator.sleeping_enabled = False
    backend.wait(1.5)
    model, data = backend.sim_world.model, backend.sim_world.data
    assert data.tree_asleep[model.body_treeid[model.body("cube").id]] < 0


def test_panda_grip_force_hardly_depends_on_the_objects_width():
    """A grasp presses with a set force (the real hand's), not in proportion to the width: a mug's 6 mm rim is
    held as firmly as a box; and closing on nothing stops at the fingers' limits instead of pushing through."""
    backend = MujocoBackend(cube_world(), robot="panda", settle=0.0)
    model, data = backend.sim_world.model, backend.sim_world.data
    actuator = backend.simulator.robot.gripper_actuator
    joints = [model.joint(name).qposadr[0] for name in ("robot/finger_joint1", "robot/finger_joint2")]
    backend.set_gripper(1.0)
    assert backend.gripper_width() < 0.001
    assert min(data.qpos[j] for j in joints) > -0.001, "the fingers must not be pushed through their limits"
    squeeze = []
    for width in (0.006, 0.05):
        data.qpos[joints] = width / 2
        data.qvel[:] = 0
        mujoco.mj_forward(model, data)
        squeeze.append(-data.actuator_force[actuator] / 2)  # the tendon's force is shared by the two fingers
    assert squeeze[0] >= 12.0, f"only {squeeze[0]:.1f} N per finger on a 6 mm rim"
    assert squeeze[1] <= 25.0 and squeeze[0] >= 0.6 * squeeze[1], squeeze
