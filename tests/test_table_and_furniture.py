"""The table and the furniture are objects to every perception tool, in ground truth and from the cameras (as the
original benchmark's queries list ``table`` and ``cabinet`` among the objects)."""

import numpy as np
import pytest

from roboscript.api import Pose
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend

MODES = ["gt", "gt-2d"]
TABLE_TOP = 0.82


@pytest.fixture(scope="module", params=MODES)
def tools(request):
    """world_5: a white and yellow mug beside a cabinet of three drawers above a door."""
    backend = MujocoBackend("world_5_mug_to_cabinet", robot="panda", settle=0.5)
    yield build_tools(backend, perception=request.param)
    backend.close()


def _cabinet_truth(tools) -> np.ndarray:
    truth = tools.backend.ground_truth
    return truth.box("cabinet").as_array()


def test_the_name_list_begins_with_the_table_and_the_cabinet(tools):
    tools.detect_objects()
    names = tools.get_object_name_list()
    assert names[:2] == ["table", "cabinet"]
    assert "white_and_yellow_mug" in names and "cabinet.drawer_1" in names and "cabinet.handle_1" in names


def test_bbox_and_centre_of_the_table_and_the_cabinet(tools):
    table = tools.get_3d_bbox("table")
    assert table[5] == pytest.approx(TABLE_TOP, abs=0.005)  # its top, where things stand
    mug = tools.get_object_center_position("white_and_yellow_mug")
    assert np.all(table[:2] < mug[:2]) and np.all(mug[:2] < table[3:5])  # the mug stands on it
    cabinet = tools.get_object_center_position("cabinet")
    truth = _cabinet_truth(tools)
    assert np.all(cabinet > truth[:3]) and np.all(cabinet < truth[3:])
    box = tools.get_3d_bbox("cabinet")
    assert box[5] == pytest.approx(truth[5], abs=0.02) and box[2] > TABLE_TOP - 0.01


def test_pose_of_the_table_and_the_cabinet(tools):
    for name in ("table", "cabinet"):
        pose = tools.get_object_pose(name)
        assert isinstance(pose, Pose)
        box = tools.get_3d_bbox(name)
        assert box[0] - 0.01 <= pose.position.x <= box[3] + 0.01 and box[1] - 0.01 <= pose.position.y <= box[4] + 0.01


def test_plane_normals_of_the_table_top_and_the_cabinet_front(tools):
    mug = tools.get_object_center_position("white_and_yellow_mug")
    up = tools.get_plane_normal("table", [mug[0] + 0.15, mug[1], TABLE_TOP])
    np.testing.assert_allclose(up, [0.0, 0.0, 1.0], atol=0.05)
    front = tools.get_3d_bbox("cabinet.drawer_1")
    middle = [front[3], (front[1] + front[4]) / 2, (front[2] + front[5]) / 2]
    normal = tools.get_plane_normal("cabinet.drawer_1", middle)
    np.testing.assert_allclose(normal, [1.0, 0.0, 0.0], atol=0.05)


def test_joint_info_of_the_cabinet_and_none_for_the_table(tools):
    handle = tools.get_object_center_position("cabinet.handle_1")
    joint = tools.get_object_joint_info("cabinet", handle, type="prismatic")
    np.testing.assert_allclose(joint["joint_axis"], [1.0, 0.0, 0.0], atol=0.02)
    with pytest.raises(ValueError, match="'table' has no joint"):
        tools.get_object_joint_info("table", handle)


def test_detecting_the_table_by_name_does_not_make_it_an_object(tools):
    tools.detect_objects(category_list=["table", "cabinet", "white_and_yellow_mug"])
    names = tools.get_object_name_list()
    assert names.count("table") == 1 and "table" not in tools.perception.objects()


def test_placing_on_the_table_puts_the_object_aside_on_its_top(tools):
    """The mug, grasped and lifted, gets a place pose on the table: clear of where it was, at the table's height."""
    tools.open_gripper()
    start = tools.get_object_center_position("white_and_yellow_mug")
    tools.grasp(tools.parse_adaptive_shape_grasp_pose("white_and_yellow_mug", preferred_approach_direction=[0, 0, -1]))
    tools.close_gripper()
    tools.attach_object("white_and_yellow_mug")
    tools.move_in_direction([0, 0, 1], 0.1)
    place = tools.parse_place_pose("white_and_yellow_mug", "table")
    tools.move_to_pose(place)
    tools.open_gripper()
    tools.detach_object("white_and_yellow_mug")
    tools.move_in_direction([0, 0, 1], 0.1)
    tools.backend.wait(0.5)
    truth = tools.backend.ground_truth.box("white_and_yellow_mug")
    assert truth.lower[2] == pytest.approx(TABLE_TOP, abs=0.01)  # standing on the table
    assert np.linalg.norm(truth.center[:2] - start[:2]) > 0.1  # somewhere else


def test_a_thing_put_aside_leaves_room_for_fingers_to_come_for_it_again():
    """A gelatin box (2.8 cm high) put aside next to a Rubik's cube would be out of a hand's reach: the fingers of a
    hand coming from above for it would land on the cube. The spot chosen keeps 3.5 cm clear of its neighbours."""
    from roboscript.api.place_requests import ASIDE_CLEARANCE
    from roboscript.sim.world_file import parse_world

    world = parse_world(
        {
            "name": "aside",
            "objects": [
                {"name": "green_plate", "type": "green_plate", "position": [-0.37, 0.288], "yaw": 148.6},
                {"name": "white_saucer", "type": "white_saucer", "position": [-0.028, 0.211], "yaw": 15.7},
                {"name": "gelatin_box", "type": "gelatin_box", "position": [-0.364, -0.346], "yaw": 61.4},
                {"name": "green_cup", "type": "green_cup", "position": [-0.023, -0.107], "yaw": 179.0},
                {"name": "rubiks_cube", "type": "rubiks_cube", "position": [-0.154, -0.336], "yaw": 79.7},
            ],
            "randomize": {"position": 0.02, "yaw": 15},
        }
    )
    with MujocoBackend(world, robot="panda", seed=0, randomize=True, settle=0.5) as backend:
        tools = build_tools(backend, perception="gt")
        tools.open_gripper()
        tools.grasp(tools.parse_adaptive_shape_grasp_pose("gelatin_box", preferred_approach_direction=[0, 0, -1]))
        tools.close_gripper()
        tools.attach_object("gelatin_box")
        tools.move_in_direction([0, 0, 1], 0.1)
        tools.move_to_pose(tools.parse_place_pose("gelatin_box", "table"))
        tools.open_gripper()
        tools.detach_object("gelatin_box")
        tools.move_in_direction([0, 0, 1], 0.1)
        truth = backend.ground_truth
        box = truth.box("gelatin_box")
        for other in ("rubiks_cube", "green_cup", "white_saucer"):
            near = truth.box(other)
            gap = np.max(np.maximum(near.lower[:2] - box.upper[:2], box.lower[:2] - near.upper[:2]))
            assert gap > ASIDE_CLEARANCE - 0.01, (other, gap)  # boxes aligned with the world: a little slack
        tools.grasp(tools.parse_adaptive_shape_grasp_pose("gelatin_box", preferred_approach_direction=[0, 0, -1]))


def test_a_pear_set_down_beside_a_plate_stands():
    """A pear (10.7 cm tall) put at a position next to a plate: released no higher than it must be to clear the
    plate's rim, it stands on its flattened bottom (a pear of two spheres balanced on a point toppled)."""
    from roboscript.sim.world_file import parse_world

    world = parse_world(
        {
            "name": "pear",
            "objects": [
                {"name": "pear", "type": "pear", "position": [-0.05, -0.25]},
                {"name": "white_plate", "type": "white_plate", "position": [0.0, 0.15]},
            ],
            "randomize": {"position": 0.03, "yaw": 180},
        }
    )
    with MujocoBackend(world, robot="panda", seed=1, randomize=True, settle=0.5) as backend:
        tools = build_tools(backend, perception="gt")
        tools.open_gripper()
        tools.grasp(tools.parse_adaptive_shape_grasp_pose("pear", preferred_approach_direction=[0, 0, -1]))
        tools.close_gripper()
        tools.attach_object("pear")
        tools.move_in_direction([0, 0, 1], 0.1)
        tools.move_to_pose(tools.parse_place_pose("pear", position=[0.0, 0.0, 0.0]))
        assert backend.ground_truth.box("pear").lower[2] < TABLE_TOP + 0.025  # released low
        tools.open_gripper()
        tools.detach_object("pear")
        tools.move_in_direction([0, 0, 1], 0.1)
        backend.wait(1.0)
        upright = backend.ground_truth.pose("pear").rotation[2, 2]
        assert upright > np.cos(np.radians(15)), np.degrees(np.arccos(upright))
        # The plate's rim reaches under [0, 0] (its box, 3.6 cm away, less the randomised shift): the pear goes to
        # the nearest spot clear of it.
        pear = backend.ground_truth.box("pear")
        assert np.linalg.norm(pear.center[:2]) < 0.07
        assert pear.upper[1] < backend.ground_truth.box("white_plate").lower[1] + 0.01
