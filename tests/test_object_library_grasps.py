"""Every pickable object shape in the library, on both arms: the adaptive grasp (the one LLMs use for everything)
picks it up, lifts it 10 cm and holds it 2 s; the exceptions fail with an error that says why.

Colour variants share a shape (same parts, density and friction), so each shape is tried once, turned 30 degrees
so that no face is square to the fingers.
"""

import numpy as np
import pytest

from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.grasping.heuristics import GraspError
from roboscript.objects import object_types
from roboscript.sim.world_file import parse_world

# Shapes an arm's parallel gripper (Panda 8 cm, 2F-85 8.5 cm opening) cannot pick from a table, with the reason.
UNGRASPABLE = {
    "panda": {
        "softball": "a 9.6 cm ball: wider than the opening",
        "pudding_box": "11 x 8.9 cm lying flat, 3.5 cm tall: wider than the opening across its top, and the fingers "
        "cannot reach under it to pinch it top to bottom",
        "tuna_can": "8.6 cm across, 3.4 cm tall: as the pudding box",
    },
    "ur5e": {
        "softball": "a 9.6 cm ball: wider than the opening",
        "pudding_box": "as on the Panda: 8.9 cm is wider than the 2F-85's 8.5 cm",
    },
}


def _shapes() -> list[str]:
    """One type name per distinct pickable shape."""
    seen: dict[str, str] = {}
    for t in object_types().values():
        if not t.pickable:  # a receptacle: no tool grasps one, and no task asks to move one
            continue
        seen.setdefault(repr((t.parts, t.density, t.friction)), t.name)
    return list(seen.values())


SHAPES = _shapes()


def test_every_pickable_type_has_its_shape_tried():
    """Each type is a receptacle or shares its shape with a type tried below; the exceptions are real types."""
    tried = {repr((object_types()[n].parts, object_types()[n].density, object_types()[n].friction)) for n in SHAPES}
    for t in object_types().values():
        assert not t.pickable or repr((t.parts, t.density, t.friction)) in tried, t.name
    for arm_exceptions in UNGRASPABLE.values():
        assert set(arm_exceptions) <= set(SHAPES)
    assert len(SHAPES) >= 40


@pytest.mark.slow
@pytest.mark.parametrize("robot", ["panda", "ur5e"])
@pytest.mark.parametrize("type_name", SHAPES)
def test_the_adaptive_grasp_lifts_and_holds_every_pickable_shape(type_name, robot):
    placed = {"name": "obj", "type": type_name, "position": [0.05, -0.05], "yaw": 30}
    world = parse_world({"name": "grasp_" + type_name, "objects": [placed]})
    backend = MujocoBackend(world, robot=robot, settle=0.5)
    try:
        tools = build_tools(backend)
        if type_name in UNGRASPABLE[robot]:
            with pytest.raises(GraspError, match="wider than the gripper"):
                tools.parse_adaptive_shape_grasp_pose("obj")
            return
        resting = backend.ground_truth.box("obj").center
        tools.open_gripper()
        tools.grasp(tools.parse_adaptive_shape_grasp_pose("obj"))
        tools.close_gripper()
        tools.attach_object("obj")
        tools.move_in_direction([0, 0, 1], 0.1)
        backend.wait(2.0)
        lifted = backend.ground_truth.box("obj").center
        assert lifted[2] - resting[2] > 0.08, f"{type_name} on the {robot}: rose {lifted[2] - resting[2]:.3f} m"
        tcp = backend.tcp_pose().position
        assert np.linalg.norm(lifted - tcp) < 0.15, f"{type_name} on the {robot} is not in the hand"
    finally:
        backend.close()
