"""The perception chain on the packaged worlds: ground-truth 2D boxes, TSDF fusion, cross-view matching, 3D
instances; and its handling of bad input."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.spatial import cKDTree

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.detection.grounding import (
    Detection2D,
    GroundingNoise,
    SegmentationGrounder,
    entity_phrases,
    normalize_phrase,
)
from roboscript.perception.evaluation import score_instances, tuple_is_correct
from roboscript.perception.points import DepthSurface, normal_map, pixels_outside, point_map
from roboscript.perception.reconstruction.fusion import FusionSettings, depth_problem, fuse, heights
from roboscript.perception.reconstruction.matching import match_views
from roboscript.perception.reconstruction.observation import observe, why_not_found
from roboscript.sim.world_catalog import world_names


def _look(world: str):
    backend = MujocoBackend(world, robot="panda")
    frames = [backend.capture(c) for c in backend.camera_names()]
    return backend, frames


def _observe(backend, frames, noise=None):
    gt = backend.ground_truth
    objects = [e for e in gt.world.entities if e.kind == "object"]
    robot = gt.world.entity("robot").index
    grounder = SegmentationGrounder(gt.world.entities, noise=noise)
    return observe(frames, grounder, [e.name for e in objects], robot_masks=[f.segmentation == robot for f in frames])


@pytest.mark.parametrize("world", world_names())
def test_ground_truth_boxes_give_3d_boxes_close_to_the_truth(world):
    backend, frames = _look(world)
    try:
        seen = _observe(backend, frames)
        scores = score_instances(seen.instances, seen.detections, backend.ground_truth)
    finally:
        backend.close()
    objects = [e.name for e in backend.ground_truth.world.entities if e.kind == "object"]
    visible = {s.name for s in scores}
    assert len(visible) >= len(objects) - 1, f"found {sorted(visible)} of {objects}"  # one may hide in a drawer
    assert np.median([s.iou for s in scores]) >= 0.6, scores
    assert np.median([s.center_error for s in scores]) <= 0.01, scores
    correct = [tuple_is_correct(m, seen.detections) for m in seen.matched]
    assert np.mean(correct) >= 0.95


def test_a_broken_depth_image_is_reported_and_skipped():
    backend, frames = _look("world_2_pick_and_place")
    backend.close()
    broken = dataclasses.replace(frames[1], depth=np.full_like(frames[1].depth, np.nan))
    scene = fuse([frames[0], broken, frames[2]], FusionSettings())
    assert scene.used == [frames[0].name, frames[2].name]
    assert "NaN" in scene.skipped[broken.name]
    assert len(scene.points) > 1000
    assert len(scene.mesh().triangles) > 1000  # the same surface as a mesh
    settings = FusionSettings()
    assert "in range" in depth_problem(dataclasses.replace(frames[0], depth=np.zeros_like(frames[0].depth)), settings)
    assert "negative" in depth_problem(dataclasses.replace(frames[0], depth=-frames[0].depth), settings)
    assert "colour image" in depth_problem(dataclasses.replace(frames[0], depth=frames[0].depth[:10]), settings)
    with pytest.raises(ValueError, match="no camera gave a usable depth image"):
        observe([broken], SegmentationGrounder([]), ["apple"])


def test_phrases_name_objects_by_name_category_or_colour():
    backend = MujocoBackend("cluttered_6_mug_to_same_color_plate", robot="panda", settle=0)
    mug = backend.ground_truth.world.entity("white_mug")
    backend.close()
    assert normalize_phrase(" White_Mug ") == "white mug"
    assert {"white mug", "mug"} <= entity_phrases(mug)


def test_noise_drops_confuses_and_moves_boxes_as_asked():
    backend, frames = _look("cluttered_2_pick_and_place")
    entities = backend.ground_truth.world.entities
    backend.close()
    phrases = ["apple", "lemon", "plum"]
    clean = SegmentationGrounder(entities).detect(frames[0], phrases)
    assert sorted(d.label for d in clean) == sorted(phrases)
    assert SegmentationGrounder(entities, noise=GroundingNoise(dropout=1.0)).detect(frames[0], phrases) == []
    confused = SegmentationGrounder(entities, noise=GroundingNoise(confusion=1.0)).detect(frames[0], phrases)
    names = {e.index: e.name for e in entities}
    assert all(d.label != names[d.source] for d in confused)
    moved = SegmentationGrounder(entities, noise=GroundingNoise(box_jitter=0.3), seed=1).detect(frames[0], phrases)
    assert [d.box for d in moved] != [d.box for d in clean]
    with pytest.raises(ValueError, match="dropout must be between 0 and 1"):
        GroundingNoise(dropout=1.5)


def test_matching_is_greedy_one_box_per_view_with_majority_labels():
    def vec(*on):
        v = np.zeros(10, dtype=bool)
        v[list(on)] = True
        return v

    # Views 0 and 1 see an apple (points 0-3) and a lemon (5-8); view 2 sees the apple only, labelled wrongly.
    memberships = [[vec(0, 1, 2, 3), vec(5, 6, 7, 8)], [vec(5, 6, 7), vec(0, 1, 2)], [vec(0, 1, 2, 3)]]
    box = (0, 0, 1, 1)
    detections = [
        [Detection2D("apple", box), Detection2D("lemon", box)],
        [Detection2D("lemon", box), Detection2D("apple", box)],
        [Detection2D("lemon", box)],
    ]
    matched = sorted(match_views(memberships, detections), key=lambda m: m.boxes)
    assert [m.boxes for m in matched] == [(0, 1, 0), (1, 0, -1)]
    assert [m.label for m in matched] == ["apple", "lemon"]
    assert matched[0].votes == {"apple": 2, "lemon": 1}
    lonely = match_views([[vec(0)], [vec(9)]], [[Detection2D("a", box)], [Detection2D("b", box)]])
    assert sorted(m.boxes for m in lonely) == [(-1, 0), (0, -1)]


def test_fusion_leaves_out_what_lies_below_the_lowest_height_and_keeps_the_rest():
    """The floor seen past the table's edges is left out of the fused surface; what stands on the table is fused
    as before (the table's far edges aside, where the floor's rays no longer pass)."""
    backend, frames = _look("world_2_pick_and_place")
    backend.close()
    for frame in frames:  # each pixel's height is its point's
        seen = frame.depth > 0
        np.testing.assert_allclose(heights(frame)[seen], point_map(frame)[seen][:, 2], atol=1e-9)
    everything = fuse(frames, FusionSettings())
    lowest = 0.5
    above = fuse(frames, FusionSettings(lowest=lowest))
    assert (everything.points[:, 2] < lowest).sum() > 0.1 * len(everything.points)  # the floor is in view
    assert above.points[:, 2].min() >= lowest - FusionSettings().truncation
    on_table = everything.points[everything.points[:, 2] > 0.9]
    gaps, _ = cKDTree(above.points).query(on_table)
    assert np.median(gaps) == 0.0 and np.mean(gaps < 0.003) > 0.99


def test_points_and_normals_made_within_the_boxes_equal_the_whole_frames_maps_there():
    backend, frames = _look("world_2_pick_and_place")
    apple = backend.ground_truth.box("apple")
    backend.close()
    boxes = [(100, 50, 220, 160), (300, 200, 401, 300), (0, 0, 640, 7), (633, 470, 640, 480)]
    for frame in frames:
        hidden = np.zeros(frame.depth.shape, dtype=bool)
        hidden[120:140, 150:260] = True  # a strip across the first box, as the arm would hide
        for mask in (None, hidden):
            whole = point_map(frame, mask)
            normals = normal_map(whole, frame.extrinsics.position)
            surface = DepthSurface(frame, mask)
            for x0, y0, x1, y1 in boxes:
                for stride in (1, 2):
                    points, made = surface.within((x0, y0, x1, y1), stride)
                    expected = whole[y0:y1:stride, x0:x1:stride].reshape(-1, 3)
                    np.testing.assert_array_equal(points, expected)
                    seen = np.isfinite(expected).all(axis=1)  # a hidden pixel's normal is never read
                    np.testing.assert_array_equal(
                        made[seen], normals[y0:y1:stride, x0:x1:stride].reshape(-1, 3)[seen]
                    )
        # The pixels a look confined to the apple's box keeps are those whose points lie in it.
        kept = ~pixels_outside(frame, apple)
        inside = np.all((whole > apple.lower) & (whole < apple.upper), axis=2)
        np.testing.assert_array_equal(kept, inside)
        assert kept.sum() > 50 or frame.name == "camera_top"


def test_a_look_whose_masks_leave_nothing_finds_nothing_and_says_so():
    """A look confined to where nothing is (an in-hand look at an empty hand) fuses nothing and finds nothing."""
    backend, frames = _look("world_2_pick_and_place")
    backend.close()
    nothing = [np.ones(f.depth.shape, dtype=bool) for f in frames]
    seen = observe(frames, SegmentationGrounder(backend.ground_truth.world.entities), ["apple"], robot_masks=nothing)
    assert seen.instances == [] and len(seen.scene.points) == 0
    assert "found 'apple'" in why_not_found(seen, "apple")
