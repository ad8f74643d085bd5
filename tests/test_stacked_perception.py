"""Full perception of a stack the program has just made: a block let go on a box, looked at again. The detector
may miss the block, or put some of the box's side into its 2D boxes; neither may make the box taller than it is
nor put the block down on the table through the box."""

from __future__ import annotations

import pytest

from helpers import stack_on
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.tasks import get_task


@pytest.mark.parametrize(
    ("task_id", "seed", "block", "lift"),
    [
        ("stack.gen_066", 7, "blue_block", 0.15),  # the detector finds the block in no view
        ("stack.gen_034", 5, "green_block", 0.1),  # the block's boxes hold a few points of the box's side
    ],
)
def test_a_block_just_stacked_on_a_box_is_seen_on_it(task_id, seed, block, lift):
    task = get_task(task_id, "generated")
    with MujocoBackend(task.world, robot="panda", seed=seed, randomize=True) as backend:
        tools = build_tools(backend, "full", seed=seed).namespace()
        tools["detect_objects"]()
        stack_on(tools, block, "red_box", lift)
        tools["detect_objects"](object_list=[block, "red_box"])
        truth = backend.ground_truth
        box_top = truth.box("red_box").upper[2]
        assert truth.box(block).lower[2] > box_top - 0.005  # it stands on the box
        seen_box, seen_block = tools["get_3d_bbox"]("red_box"), tools["get_3d_bbox"](block)
        assert abs(seen_box[5] - box_top) < 0.015, (seen_box, box_top)
        assert seen_block[2] > box_top - 0.015, (seen_block, box_top)
