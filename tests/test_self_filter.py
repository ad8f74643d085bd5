"""The self-filter: the robot's pixels told from its model and joint readings, checked against the simulator's
segmentation (which the filter never reads)."""

from __future__ import annotations

from dataclasses import replace

import mujoco
import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.reconstruction.self_filter import SelfFilter


@pytest.mark.parametrize("robot", ["panda", "ur5e"])
def test_the_robot_is_masked_and_the_scene_is_not(robot):
    with MujocoBackend("world_1_table_sort", robot=robot, settle=0) as backend:
        robot_index = next(i for i, n in backend.segmentation_labels().items() if n == "robot")
        objects = [e.index for e in backend.ground_truth.world.entities if e.kind == "object"]
        q = backend.joint_positions().copy()
        q[1] += 0.4  # leaning over the table, in front of objects from some cameras
        world = backend.sim_world
        world.data.qpos[world.robot.qpos] = q
        mujoco.mj_forward(world.model, world.data)
        frames = [backend.capture(c) for c in backend.camera_names()]
        self_filter = SelfFilter(backend.robot, backend.base_pose())
        masks = self_filter.masks(frames, backend.joint_states())
        # Told only where asked (a look at what the hand holds), the pixels asked about are told as before.
        wanted = [np.zeros(f.depth.shape, dtype=bool) for f in frames]
        for w in wanted:
            w[101:299, 201:499] = True  # odd edges: working pixels (2 x 2 blocks) half in, half out
            w[5, 7] = True  # and one pixel alone
        partial = self_filter.masks(frames, backend.joint_states(), wanted)
    for mask, part, w in zip(masks, partial, wanted, strict=True):
        np.testing.assert_array_equal(part[w], mask[w])
        assert part.sum() < mask.sum(), "rays were cast only where asked"
    for frame, mask in zip(frames, masks, strict=True):
        truth = frame.segmentation == robot_index
        assert mask.shape == truth.shape and truth.sum() > 1000
        assert (truth & ~mask).sum() <= 0.002 * truth.sum(), frame.name  # the arm's outline is covered
        assert (mask & ~truth).sum() <= 0.3 * truth.sum(), frame.name  # a fringe of a few pixels, no more
        shown = np.isin(frame.segmentation, objects)
        assert (mask & shown).sum() <= 0.05 * shown.sum(), frame.name  # only where things touch the arm


def test_something_in_front_of_the_arm_is_the_scene():
    with MujocoBackend("world_2_pick_and_place", robot="panda", settle=0) as backend:
        frame = backend.capture("camera_left")
        robot = SelfFilter(backend.robot, backend.base_pose())
        mask = robot.masks([frame], backend.joint_states())[0]
        index = next(i for i, n in backend.segmentation_labels().items() if n == "robot")
        rows, cols = np.nonzero(frame.segmentation == index)
        r, c = rows[len(rows) // 2], cols[len(cols) // 2]
        assert mask[r, c]
        closer = frame.depth.copy()
        closer[r - 10 : r + 11, c - 10 : c + 11] -= 0.1  # something 10 cm in front of the arm there
        mask = robot.masks([replace(frame, depth=closer)], backend.joint_states())[0]
        assert not mask[r, c]
