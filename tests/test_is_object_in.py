"""``is_object_in``: whether a thing stands in or on a receptacle, in the receptacle's own axes and from the same
perception as every other tool (sort_by_kind.gen_057: a gelatin box beside a turned basket stands in a corner of
the basket's world-aligned box, and three prompt-only programs took it for already in the basket)."""

import mujoco
import numpy as np
import pytest

from roboscript.api.arguments import ArgumentError
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.tasks import load_suite
from roboscript.perception.base import UnknownObjectError

TASK = load_suite("generated")["sort_by_kind.gen_057"]


def _set_on(backend, thing: str, support: str, lift: float) -> None:
    """Drops ``thing`` onto ``support`` from ``lift`` above its origin and lets it settle (the simulator, not a
    tool)."""
    world, gt = backend.sim_world, backend.ground_truth
    address = world.model.jnt_qposadr[world.model.body(thing).jntadr[0]]
    world.data.qpos[address : address + 3] = gt.pose(support).position + np.array([0.0, 0.0, lift])
    world.data.qvel[:] = 0.0
    mujoco.mj_forward(world.model, world.data)
    for _ in range(400):
        mujoco.mj_step(world.model, world.data)


@pytest.mark.parametrize("mode", ["gt", "full"])
def test_a_thing_is_in_what_holds_it_not_in_the_corner_of_a_turned_baskets_box(mode):
    with MujocoBackend(TASK.world, robot="panda", seed=0, randomize=True) as backend:
        gt = backend.ground_truth
        corner = gt.box("gelatin_box").intersection(gt.box("basket")).volume / gt.box("gelatin_box").volume
        assert corner > 0.4  # beside the basket, yet half within its world-aligned box
        _set_on(backend, "red_box", "basket", 0.05)
        tools = build_tools(backend, mode, seed=0).namespace()
        tools["detect_objects"]()
        is_in = tools["is_object_in"]
        assert not is_in("gelatin_box", "basket") and is_in("gelatin_box", "table")
        assert is_in("red_box", "basket") and not is_in("red_box", "table")
        # The green mug starts on the red plate, the red block on the blue saucer.
        assert is_in("green_mug", "red_plate") and not is_in("green_mug", "table") and is_in("red_plate", "table")
        assert is_in("red_block", "blue_saucer") and not is_in("red_block", "red_plate")
        assert not is_in("basket", "basket") and not is_in("red_cup", "gelatin_box")


def test_a_held_thing_is_in_nothing_and_a_bad_name_is_refused():
    with MujocoBackend(TASK.world, robot="panda", seed=0, randomize=True) as backend:
        tools = build_tools(backend).namespace()
        tools["open_gripper"]()
        tools["grasp"](tools["parse_central_lift_grasp_pose"](object_name="red_block"))
        tools["close_gripper"]()
        tools["attach_object"]("red_block")
        assert not tools["is_object_in"]("red_block", "blue_saucer")
        with pytest.raises((ArgumentError, UnknownObjectError), match="baskett"):
            tools["is_object_in"]("red_box", "baskett")
