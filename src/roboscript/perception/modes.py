"""Perception modes: where the tools' knowledge of the world comes from, for the benchmark's ablations.

``gt``: everything from the simulator's state. ``gt-2d``: 2D boxes from the simulator's segmentation, and
everything about objects (their 3D boxes, poses, points, containers' interiors) from fused camera views. ``det-2d``:
the same with the 2D boxes from an open-vocabulary detector whose weights the user provides.
Furniture parts, their joints and the planning scene come from ground truth in every mode so far.
"""

from __future__ import annotations

import os

from roboscript.backends.base import Backend
from roboscript.perception.base import Perception

PERCEPTION_MODES = {
    "gt": "ground truth everywhere",
    "gt-2d": "ground-truth 2D boxes; 3D boxes, poses and points of objects from fused RGB-D views",
    "det-2d": "2D boxes from an open-vocabulary detector ($ROBOSCRIPT_DETECTOR=owlv2:DIR or grounding-dino:DIR); "
    "the rest as gt-2d",
}
DETECTOR_ENV = "ROBOSCRIPT_DETECTOR"


def check_mode(mode: str) -> str:
    if mode not in PERCEPTION_MODES:
        known = "; ".join(f"{m} ({what})" for m, what in PERCEPTION_MODES.items())
        raise ValueError(f"unknown perception mode {mode!r}; modes: {known}")
    return mode


def make_perception(mode: str, backend: Backend, seed: int = 0) -> Perception:
    """The perception of ``mode`` for a simulated ``backend``."""
    from roboscript.perception.ground_truth import GroundTruthPerception

    check_mode(mode)
    truth = GroundTruthPerception(backend)
    if mode == "gt":
        return truth
    from roboscript.perception.grounding import SegmentationGrounder
    from roboscript.perception.pipeline import PipelinePerception

    world = backend.ground_truth.world
    grounder = detector_from_env() if mode == "det-2d" else SegmentationGrounder(world.entities, seed=seed)
    vocabulary = world.entity_names(("object",))
    return PipelinePerception(backend, grounder, vocabulary, truth, robot_index=world.entity("robot").index)


def detector_spec() -> tuple[str, str]:
    """``(kind, directory)`` of the detector ``$ROBOSCRIPT_DETECTOR`` names (``KIND:DIR``), checked, not loaded."""
    from roboscript.perception.detectors import DETECTOR_KINDS, DetectorError, check_model_dir

    spec = os.environ.get(DETECTOR_ENV, "")
    kind, sep, path = spec.partition(":")
    if not sep or not path:
        raise DetectorError(
            f"perception det-2d needs a detector: set {DETECTOR_ENV}=KIND:DIR with KIND one of "
            f"{', '.join(DETECTOR_KINDS)} and DIR a model saved with save_pretrained (got {spec!r})"
        )
    return kind, check_model_dir(kind, path)


def require_ready(mode: str) -> None:
    """Fails now, clearly, if ``mode`` cannot work (unknown, or its detector missing), before worlds are built."""
    check_mode(mode)
    if mode == "det-2d":
        detector_spec()


def detector_from_env():
    """The detector ``$ROBOSCRIPT_DETECTOR`` names, loaded."""
    from roboscript.perception.detectors import OpenVocabularyDetector

    return OpenVocabularyDetector(*detector_spec())
