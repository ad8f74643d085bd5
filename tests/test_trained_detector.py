"""The detector the project trains: its training (on a couple of generated scenes, so that the test is quick), its
model file, and the packaged model's detections on a world of the paper's benchmark."""

from __future__ import annotations

import json
import subprocess
import sys

import mujoco
import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.tasks import get_task
from roboscript.detector_training.classes import class_names, look_alike_classes
from roboscript.detector_training.samples import view_samples
from roboscript.detector_training.scenes import scene_views
from roboscript.objects import object_types
from roboscript.perception.detection.detector_model import (
    FURNITURE,
    HANDLE,
    OTHER,
    DetectorModelError,
    load_detector_model,
)
from roboscript.perception.detection.grounding import SegmentationGrounder, image_box_iou, normalize_phrase
from roboscript.perception.detection.mlp import Training, train_mlp
from roboscript.perception.detection.trained_detector import TrainedDetector
from roboscript.perception.modes import perception_mode
from roboscript.perception.points import without_pixels
from roboscript.perception.reconstruction.self_filter import SelfFilter
from roboscript.sim.world_catalog import load_world


def test_look_alike_types_share_a_class():
    classes = look_alike_classes()
    assert classes["white_mug"] == classes["white_porcelain_mug"] == "white_mug+white_porcelain_mug"
    assert classes["white_mug"] != classes["white_and_yellow_mug"] != classes["red_mug"]
    names = class_names(classes)
    assert names[-3:] == [FURNITURE, HANDLE, OTHER]
    assert sorted(t for name in names[:-3] for t in name.split("+")) == sorted(object_types())


def test_training_samples_and_networks_come_out_the_same_for_a_seed():
    classes = look_alike_classes()
    first = [view_samples(v, classes) for v in scene_views(5, 0)]
    again = [view_samples(v, classes) for v in scene_views(5, 0)]
    assert len(first) == 9  # three cameras, three poses
    for a, b in zip(first, again, strict=True):
        assert np.array_equal(a.pair_features, b.pair_features) and a.segment_classes == b.segment_classes
    assert set(look_alike_classes().values()) & {c for s in first for c in s.segment_classes}
    x = np.concatenate([s.pair_features for s in first])
    y = np.concatenate([s.pair_targets for s in first])
    assert set(y.tolist()) == {0, 1}
    one, two = (train_mlp(x, y, 2, Training(hidden=(8,), epochs=2), seed=3) for _ in range(2))
    assert all(np.array_equal(p, q) for p, q in zip(one.weights, two.weights, strict=True))


def test_train_detector_writes_a_model_and_prints_how_it_scores(tmp_path):
    out, report = tmp_path / "detector.npz", tmp_path / "detector.json"
    command = [sys.executable, "-m", "roboscript.cli", "train-detector", "--worlds", "2", "--validation-worlds", "1"]
    run = subprocess.run(
        [*command, "--jobs", "1", "--out", str(out), "--json", str(report)], capture_output=True, text=True, timeout=600
    )
    assert run.returncode == 0, run.stderr
    assert "objects (per view, IoU >= 0.5): precision" in run.stdout and "classifier: training accuracy" in run.stdout
    assert "2/2 worlds rendered" in run.stderr  # progress
    model = load_detector_model(out)
    info = json.loads(report.read_text())
    assert info["settings"]["worlds"] == 2 and info["training"]["views"] == 18
    assert 0.0 <= info["validation_detection"]["objects"]["recall"] <= 1.0
    assert model.info["training"] == info["training"]
    assert perception_mode("full", f"trained:{out}").detector.directory == str(out)


def test_a_bad_model_file_says_what_is_wrong(tmp_path):
    with pytest.raises(DetectorModelError, match=r"no detector model at '.*nothing.npz'; make one with roboscript"):
        load_detector_model(tmp_path / "nothing.npz")
    (tmp_path / "junk.npz").write_bytes(b"not a model")
    with pytest.raises(DetectorModelError, match="could not read the detector model"):
        load_detector_model(tmp_path / "junk.npz")
    other = tmp_path / "other.npz"
    np.savez(other, meta=np.array(json.dumps({"format": "someone-else/2"})))
    with pytest.raises(DetectorModelError, match="is a 'someone-else/2' file, not 'roboscript-detector/1'"):
        load_detector_model(other)


def test_the_packaged_model_finds_the_objects_of_a_benchmark_world():
    model = load_detector_model()
    assert set(model.classes[-3:]) == {FURNITURE, HANDLE, OTHER} and model.info["validation_detection"]
    spec = load_world("world_3_mug_to_empty_plate")
    detector = TrainedDetector.for_scene(spec, model)
    objects = [normalize_phrase(o.name) for o in spec.objects]
    parts = [normalize_phrase(n) for n in ("cabinet", *spec.part_names())]
    with MujocoBackend(spec, settle=0.3) as backend:
        frames = [backend.capture(c) for c in backend.camera_names()]
        masks = SelfFilter(backend.robot, backend.base_pose()).masks(frames, backend.joint_states())
        truth = SegmentationGrounder(backend.ground_truth.world.entities)
        right = {"objects": [0, 0], "parts": [0, 0]}
        for frame, mask in zip(frames, masks, strict=True):
            expected = {d.label: d.box for d in truth.detect(frame, objects + parts)}
            found = detector.detect(without_pixels(frame, mask), objects + parts)
            labels = [d.label for d in found if d.label in objects]
            assert len(labels) == len(set(labels)), labels  # one box per thing the description names once
            for d in found:
                tally = right["objects" if d.label in objects else "parts"]
                tally[0] += d.label in expected and image_box_iou(expected[d.label], d.box) >= 0.5
                tally[1] += 1
        assert right["objects"][0] >= 0.9 * right["objects"][1] and right["objects"][1] >= 8, right
        # Parts seen nearly edge-on from above are a few pixels high: a pixel off is an IoU below 0.5.
        assert right["parts"][0] >= 0.6 * right["parts"][1], right
        plates = detector.detect(without_pixels(frames[2], masks[2]), ["plate"])  # a category: every plate
        assert sorted(d.label for d in plates) == ["plate", "plate"]
        assert detector.detect(without_pixels(frames[2], masks[2]), ["unicorn"]) == []
        assert "names nothing the detector knows" in detector.account("unicorn")
        assert "the detector saw" in detector.account("lemon")


# Where full perception once stacked the green block on the red box of stack.gen_034 (seed 5), and where the arm was
# left: the block's free joint (position, quaternion wxyz) and the arm's joints. Set, not stacked anew, so that the
# detector is judged on one scene: 0.04 mm and 0.03 degrees from here, the right camera's merger joined block and box
# into one thing of no class.
STACKED_BLOCK = [-0.19695, -0.24992, 0.86992, 0.82636, 1e-05, -0.0, -0.56315]
ARM_AFTER_STACKING = [-1.1753, -0.3667, 0.4431, -2.8373, 0.2562, 2.4871, 2.5885]


def test_a_block_stacked_on_a_box_is_found_as_the_things_the_scene_holds():
    # A green block stacked on a red box, as full perception put it there: the classifier took the block, seen
    # with one of its sides, for a green mug, which the scene does not hold. With the description's types every
    # view finds both, where each is.
    task = get_task("stack.gen_034", "generated")
    with MujocoBackend(task.world, robot="panda", seed=5, randomize=True) as backend:
        world = backend.sim_world
        block = world.model.jnt_qposadr[world.model.body("green_block").jntadr[0]]
        world.data.qpos[block : block + 7] = STACKED_BLOCK
        world.data.qpos[world.robot.qpos] = ARM_AFTER_STACKING
        mujoco.mj_forward(world.model, world.data)
        frames = [backend.capture(c) for c in backend.camera_names()]
        masks = SelfFilter(backend.robot, backend.base_pose()).masks(frames, backend.joint_states())
        truth = SegmentationGrounder(backend.ground_truth.world.entities)
        detector = TrainedDetector.for_scene(backend.ground_truth.world.spec)
        found = {"green block": 0, "red box": 0}
        for frame, mask in zip(frames, masks, strict=True):
            expected = {d.label: d.box for d in truth.detect(frame, list(found))}
            for d in detector.detect(without_pixels(frame, mask), list(found)):
                assert image_box_iou(expected[d.label], d.box) >= 0.5, (frame.name, d)
                found[d.label] += 1
        assert found["green block"] == 3 and found["red box"] >= 2, found
