"""Open-vocabulary detectors: the loading and inference code of OWLv2 and Grounding DINO, run on tiny randomly
initialised models that the test builds and saves (no weights can be fetched here). The boxes of a random model
mean nothing; what is pinned is that the path works end to end and its output keeps its promises."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from roboscript.assembly import build_perception, build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.detection.detectors import DetectorError, OpenVocabularyDetector, closest_phrase
from roboscript.perception.detection.grounding import image_box_iou
from roboscript.perception.detection.trained_detector import TrainedDetector
from roboscript.perception.modes import DETECTOR_ENV, DetectorSpec, perception_mode
from roboscript.perception.reconstruction.observation import observe

PHRASES = ["apple", "footed bowl", "lemon"]


def _tiny_owlv2(path) -> str:
    """A one-layer OWLv2 with a tokenizer of single letters."""
    import torch
    from transformers import CLIPTokenizer, Owlv2Config, Owlv2ForObjectDetection, Owlv2ImageProcessor, Owlv2Processor

    path.mkdir()
    vocab = {"!": 0, "<|startoftext|>": 1, "<|endoftext|>": 2}  # OWL skips queries whose first token id is 0
    for c in "abcdefghijklmnopqrstuvwxyz.":
        vocab.setdefault(c, len(vocab))
        vocab.setdefault(c + "</w>", len(vocab))
    (path / "vocab.json").write_text(json.dumps(vocab))
    (path / "merges.txt").write_text("#version: 0.2\n")
    tokenizer = CLIPTokenizer(str(path / "vocab.json"), str(path / "merges.txt"), pad_token="!", model_max_length=16)
    image = Owlv2ImageProcessor(size={"height": 64, "width": 64})
    text = dict(
        vocab_size=len(vocab),
        hidden_size=32,
        intermediate_size=37,
        num_hidden_layers=1,
        num_attention_heads=2,
        max_position_embeddings=32,
        bos_token_id=1,
        eos_token_id=2,
        pad_token_id=0,
    )
    vision = dict(
        hidden_size=32, intermediate_size=37, num_hidden_layers=1, num_attention_heads=2, image_size=64, patch_size=16
    )
    torch.manual_seed(0)
    Owlv2ForObjectDetection(Owlv2Config(text_config=text, vision_config=vision, projection_dim=32)).save_pretrained(
        path
    )
    Owlv2Processor(image_processor=image, tokenizer=tokenizer).save_pretrained(path)
    return str(path)


def _tiny_grounding_dino(path) -> str:
    """A Grounding DINO with a one-layer text encoder, a two-stage Swin and two decoder layers."""
    import torch
    from transformers import (
        BertConfig,
        BertTokenizer,
        GroundingDinoConfig,
        GroundingDinoForObjectDetection,
        GroundingDinoImageProcessor,
        GroundingDinoProcessor,
        SwinConfig,
    )

    path.mkdir()
    words = ["[PAD]", "[UNK]", "[CLS]", "[SEP]", "[MASK]", ".", "apple", "footed", "bowl", "lemon"]
    (path / "vocab.txt").write_text("\n".join(words) + "\n")
    image = GroundingDinoImageProcessor(size={"shortest_edge": 64, "longest_edge": 96})
    backbone = SwinConfig(
        image_size=64,
        patch_size=4,
        embed_dim=8,
        depths=[1, 1],
        num_heads=[1, 1],
        window_size=2,
        out_features=["stage1", "stage2"],
    )
    text = BertConfig(
        vocab_size=len(words),
        hidden_size=32,
        num_hidden_layers=1,
        num_attention_heads=2,
        intermediate_size=16,
        max_position_embeddings=32,
    )
    config = GroundingDinoConfig(
        backbone_config=backbone,
        text_config=text,
        d_model=32,
        encoder_layers=1,
        decoder_layers=2,
        encoder_attention_heads=2,
        decoder_attention_heads=2,
        encoder_ffn_dim=32,
        decoder_ffn_dim=32,
        num_queries=8,
        num_feature_levels=2,
        encoder_n_points=1,
        decoder_n_points=1,
        max_text_len=32,
    )
    torch.manual_seed(0)
    GroundingDinoForObjectDetection(config).save_pretrained(path)
    tokenizer = BertTokenizer(str(path / "vocab.txt"))
    GroundingDinoProcessor(image_processor=image, tokenizer=tokenizer).save_pretrained(path)
    return str(path)


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    root = tmp_path_factory.mktemp("detectors")
    return {"owlv2": _tiny_owlv2(root / "owlv2"), "grounding-dino": _tiny_grounding_dino(root / "gdino")}


@pytest.fixture(scope="module")
def frames():
    backend = MujocoBackend("world_2_pick_and_place", robot="panda", settle=0)
    try:
        yield [backend.capture(c) for c in backend.camera_names()]
    finally:
        backend.close()


@pytest.mark.parametrize("kind", ["owlv2", "grounding-dino"])
def test_a_detector_loads_and_its_boxes_keep_their_promises(models, frames, kind):
    detector = OpenVocabularyDetector(kind, models[kind], threshold=0.0)
    frame = frames[0]
    h, w = frame.rgb.shape[:2]
    detections = detector.detect(frame, PHRASES)
    assert detections, "a threshold of 0 keeps every box"
    for d in detections:
        assert d.label in PHRASES
        x0, y0, x1, y1 = d.box
        assert 0 <= x0 < x1 <= w and 0 <= y0 < y1 <= h
    scores = [d.score for d in detections]
    assert scores == sorted(scores, reverse=True)
    assert all(image_box_iou(a.box, b.box) <= 0.5 for i, a in enumerate(detections) for b in detections[i + 1 :])
    assert OpenVocabularyDetector(kind, models[kind], threshold=1.01).detect(frame, PHRASES) == []
    seen = observe(frames, detector, PHRASES)  # the whole chain runs on a detector's boxes
    assert len(seen.detections) == len(frames) and all(i.label in PHRASES for i in seen.instances)


def test_bad_detector_input_says_what_is_wrong(tmp_path, models):
    with pytest.raises(DetectorError, match="unknown detector 'yolo'; detectors: owlv2, grounding-dino"):
        OpenVocabularyDetector("yolo", models["owlv2"])
    with pytest.raises(DetectorError, match=r"missing: config\.json"):
        OpenVocabularyDetector("owlv2", tmp_path)
    assert closest_phrase("footed bowl", PHRASES) == "footed bowl"
    assert closest_phrase("bowl", PHRASES) == "footed bowl"  # a model may return part of a phrase
    assert closest_phrase("table", PHRASES) is None


def test_full_perception_takes_the_detector_the_command_line_resolves(models, monkeypatch):
    mode = perception_mode("full", f"owlv2:{models['owlv2']}")
    assert mode.detector == DetectorSpec("owlv2", models["owlv2"])
    # Below the command line nothing reads the environment: a mode made without a detector has the packaged one.
    monkeypatch.setenv(DETECTOR_ENV, f"owlv2:{models['owlv2']}")
    assert perception_mode("full").detector == DetectorSpec("trained", "")
    backend = MujocoBackend("world_2_pick_and_place", robot="panda", settle=0)
    try:
        assert isinstance(build_perception(backend, "full").grounder, TrainedDetector)
        gt_scene = perception_mode("gt-scene", f"owlv2:{models['owlv2']}")
        assert isinstance(build_perception(backend, gt_scene).grounder, OpenVocabularyDetector)
        api = build_tools(backend, perception=mode)
        assert isinstance(api.perception.grounder, OpenVocabularyDetector)
        api.detect_objects(["apple"])  # a random model finds what it finds; the look must go through
        assert api.perception.looks == 1
        scene = api.motion.scene  # and the planning scene is built from what the cameras saw
        assert api.motion.scene_source is not None and "scene" in scene.body_labels
        assert scene.is_free(backend.joint_positions())
    finally:
        backend.close()
    command = [sys.executable, "-m", "roboscript.cli", "exec", "x.py", "--task", "simple_0", "--perception", "full"]
    run = subprocess.run([*command, "--detector", "yolo"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 2 and "perception full needs a detector: pass --detector or set " in run.stderr
    assert "trained (the packaged model), trained:FILE.npz" in run.stderr
    run = subprocess.run([*command, "--detector", "owlv2:/nowhere"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 2 and "no owlv2 model in '/nowhere'" in run.stderr
    run = subprocess.run([*command, "--detector", "trained:/nowhere.npz"], capture_output=True, text=True, timeout=120)
    assert run.returncode == 2 and "no detector model file at '/nowhere.npz'" in run.stderr
