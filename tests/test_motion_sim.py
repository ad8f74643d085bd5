"""Planned motions executed in simulation, both arms: pick-and-place into a bowl, and opening a drawer."""

import numpy as np
import pytest

from helpers import ARMS
from helpers import DOWN_QUAT as DOWN
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform, matrix_to_quat
from roboscript.planning.ground_truth_scene import ground_truth_motion
from roboscript.sim.world_file import parse_world

ROBOTS = ARMS


@pytest.mark.parametrize("robot", ROBOTS)
def test_pick_a_box_and_place_it_into_a_bowl(robot):
    world = parse_world(
        {
            "name": "pick_and_place",
            "objects": [
                {"name": "box", "type": "blue_box", "position": [0.0, -0.2]},
                {"name": "bowl", "type": "white_bowl", "position": [0.0, 0.2]},
            ],
        }
    )
    backend = MujocoBackend(world, robot=robot, settle=0.5)
    motion = ground_truth_motion(backend)
    gt = backend.ground_truth
    center = gt.box("box").center
    motion.move_to_pose(Transform(center + np.array([0.0, 0.0, 0.125]), DOWN))
    motion.scene.allow("gripper", "box")
    motion.move_in_direction([0, 0, -1], 0.12)
    assert backend.close_gripper().blocked
    motion.attach("box")
    motion.move_in_direction([0, 0, 1], 0.15)
    bowl = gt.box("bowl")
    motion.move_to_pose(Transform(np.array([*bowl.center[:2], bowl.upper[2] + 0.12]), DOWN))
    motion.move_in_direction([0, 0, -1], 0.06)
    backend.open_gripper()
    motion.detach("box")
    motion.move_in_direction([0, 0, 1], 0.1)
    backend.wait(0.5)
    box = gt.box("box")
    assert np.all(box.lower[:2] >= bowl.lower[:2]) and np.all(box.upper[:2] <= bowl.upper[:2]), (box, bowl)
    assert bowl.lower[2] < box.lower[2] < bowl.lower[2] + 0.03, "the box rests on the bowl's floor"


@pytest.mark.parametrize("robot", ROBOTS)
def test_open_a_drawer_by_its_handle(robot):
    world = parse_world(
        {
            "name": "drawer",
            "objects": [{"name": "box", "type": "gelatin_box", "inside": "cabinet.drawer_1"}],
            "furniture": [{"name": "cabinet", "type": "cabinet", "position": [-0.42, 0.62], "rows": ["drawer"] * 3}],
        }
    )
    backend = MujocoBackend(world, robot=robot, settle=0.5)
    motion = ground_truth_motion(backend)
    gt = backend.ground_truth
    handle = gt.box("cabinet.handle_1").center
    box_before = gt.pose("box").position
    # Horizontal approach against the drawer front (-x), turned 40 degrees towards the robot, which keeps the
    # wrist within reach when the drawer is pulled out; the fingers close vertically around the bar.
    alpha = 0.7
    approach = np.array([-np.cos(alpha), np.sin(alpha), 0.0])
    closing = np.array([0.0, 0.0, 1.0])
    grasp = matrix_to_quat(np.column_stack([np.cross(closing, approach), closing, approach]))
    motion.move_to_pose(Transform(handle - 0.1 * approach, grasp))
    motion.scene.allow("gripper", "cabinet.handle_1")
    motion.scene.allow("gripper", "cabinet.drawer_1")
    motion.move_in_direction(approach, 0.1)
    assert backend.close_gripper().blocked
    motion.move_in_direction([1, 0, 0], 0.2)
    opened = gt.joint("cabinet.drawer_1").value
    assert opened == pytest.approx(0.2, abs=0.02)
    moved = gt.pose("box").position - box_before
    assert moved[0] == pytest.approx(opened, abs=0.02), "the box inside comes out with the drawer"


def _peak_speed_fraction(trajectory, robot) -> float:
    """The largest joint speed of ``trajectory`` as a fraction of that joint's limit."""
    return float(np.max(np.abs(trajectory.velocities) / np.asarray(robot.max_velocity)))


def test_a_held_object_is_carried_at_the_carrying_speed():
    """Motions with an object in the hand are timed at ``carry_speed_scale`` of the arm's limits, motions without at
    ``speed_scale`` (a spy on the backend records the trajectories it is given)."""
    world = parse_world({"name": "carry", "objects": [{"name": "box", "type": "blue_box", "position": [0.0, -0.2]}]})
    backend = MujocoBackend(world, robot="panda", settle=0.5)
    motion = ground_truth_motion(backend)
    assert motion.carry_speed_scale < motion.speed_scale
    timed = []
    execute = backend.execute_trajectory

    def spy(trajectory):
        timed.append(trajectory)
        return execute(trajectory)

    backend.execute_trajectory = spy
    center = backend.ground_truth.box("box").center
    motion.move_to_pose(Transform(center + np.array([0.0, 0.0, 0.2]), DOWN))
    motion.move_in_direction([0, 0, -1], 0.2)
    free = _peak_speed_fraction(timed[0], backend.robot)
    assert backend.close_gripper().blocked
    motion.attach("box")
    motion.move_to_pose(Transform(center + np.array([0.15, 0.35, 0.2]), DOWN))
    carried = _peak_speed_fraction(timed[-1], backend.robot)
    assert motion.carry_speed_scale * 0.9 < carried <= motion.carry_speed_scale + 1e-6
    assert carried < free <= motion.speed_scale + 1e-6


def test_a_held_banana_does_not_creep_out_of_the_fingers():
    """Held still for 6 s, a banana pinched across its body stays where the fingers hold it. MuJoCo's soft friction
    let it creep out at 0.14 mm/s until the no-slip pass was turned on (sim.world.NOSLIP_ITERATIONS)."""

    world = parse_world({"name": "creep", "objects": [{"name": "banana", "type": "banana", "position": [0.05, -0.1]}]})
    backend = MujocoBackend(world, robot="panda", settle=0.5)
    tools = build_tools(backend)
    tools.open_gripper()
    tools.grasp(tools.parse_central_lift_grasp_pose("banana"))
    tools.close_gripper()
    tools.attach_object("banana")

    def offset() -> np.ndarray:
        tcp = backend.tcp_pose()
        return tcp.rotation.T @ (backend.ground_truth.pose("banana").position - tcp.position)

    before = offset()
    backend.wait(6.0)
    assert np.linalg.norm(offset() - before) < 3e-4, (before, offset())
