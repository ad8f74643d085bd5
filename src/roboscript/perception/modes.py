"""Perception modes: which stages of perception the tools' knowledge comes from, for the benchmark's ablations.

Perception has three stages that can each be replaced by ground truth: ``2d`` (boxes of the phrases in each camera
image), ``3d`` (objects' boxes, poses and points, from fused RGB-D views) and ``scene`` (the planning scene, from
observed surfaces as occupancy boxes). ``full`` takes none from ground truth, ``gt`` all; ``gt-2d``, ``gt-3d`` and
``gt-scene`` each take one, and can be combined with ``+`` (``gt-2d+gt-scene``) to isolate the rest.

Without ground-truth 2D boxes, the boxes come from an open-vocabulary detector whose weights the user provides
(``$ROBOSCRIPT_DETECTOR=owlv2:DIR`` or ``grounding-dino:DIR``). Where objects are observed, furniture is too:
its boxes, points, joints (:mod:`roboscript.perception.articulation`) and drawers' insides
(:mod:`roboscript.perception.drawers`) come from the points of the carcass, fronts and handles; only the labels
(what parts there are, which part a handle moves, sliding or turning) come from the furniture's description.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

from roboscript.backends.base import Backend
from roboscript.perception.base import Perception

STAGES = ("2d", "3d", "scene")
PERCEPTION_MODES = {
    "gt": "ground truth everywhere",
    "full": "nothing from ground truth: 2D boxes from an open-vocabulary detector ($ROBOSCRIPT_DETECTOR="
    "owlv2:DIR or grounding-dino:DIR), objects from fused RGB-D views, the planning scene from observed surfaces",
    "gt-2d": "as full, with ground-truth 2D boxes (the simulator's segmentation)",
    "gt-3d": "as full, with objects' 3D boxes, poses and points from ground truth (the planning scene observed)",
    "gt-scene": "as full, with the ground-truth planning scene (the simulator's geometry)",
}
DETECTOR_ENV = "ROBOSCRIPT_DETECTOR"
ALIASES = {"det-2d": "gt-scene"}  # the earlier name of detector boxes with the exact planning scene, for old runs


@dataclass(frozen=True)
class PerceptionMode:
    """The stages a mode takes from ground truth."""

    name: str
    from_truth: frozenset[str]

    @property
    def needs_detector(self) -> bool:
        return not {"2d", "3d"} & self.from_truth

    @property
    def observed_objects(self) -> bool:
        return "3d" not in self.from_truth

    @property
    def observed_scene(self) -> bool:
        return "scene" not in self.from_truth


def parse_mode(mode: str) -> PerceptionMode:
    """The :class:`PerceptionMode` named by ``mode``: one of :data:`PERCEPTION_MODES`, or ``gt-...`` modes joined
    by ``+``."""
    if not isinstance(mode, str):
        raise TypeError(f"a perception mode is a string such as 'gt-2d', got {type(mode).__name__} {mode!r}")
    if mode in ALIASES:
        return PerceptionMode(mode, parse_mode(ALIASES[mode]).from_truth)
    if mode == "gt":
        return PerceptionMode(mode, frozenset(STAGES))
    if mode == "full":
        return PerceptionMode(mode, frozenset())
    stages = []
    for part in mode.split("+"):
        stage = part.removeprefix("gt-")
        if not part.startswith("gt-") or stage not in STAGES or stage in stages:
            known = "; ".join(f"{m} ({what})" for m, what in PERCEPTION_MODES.items())
            raise ValueError(
                f"unknown perception mode {mode!r}; modes: {known}; gt-2d, gt-3d and gt-scene combine with '+' "
                "(e.g. gt-2d+gt-scene)"
            )
        stages.append(stage)
    return PerceptionMode(mode, frozenset(stages))


def check_mode(mode: str) -> str:
    parse_mode(mode)
    return mode


def make_perception(mode: str, backend: Backend, seed: int = 0) -> Perception:
    """The perception of ``mode`` for a simulated ``backend``."""
    from roboscript.perception.ground_truth import GroundTruthPerception

    parsed = parse_mode(mode)
    truth = GroundTruthPerception(backend)
    if not parsed.observed_objects:
        return truth
    from roboscript.perception.grounding import SegmentationGrounder
    from roboscript.perception.pipeline import PipelinePerception

    world = backend.ground_truth.world
    grounder = detector_from_env() if parsed.needs_detector else SegmentationGrounder(world.entities, seed=seed)
    vocabulary = world.entity_names(("object",))
    return PipelinePerception(backend, grounder, vocabulary, truth, robot_index=world.entity("robot").index)


def detector_spec(mode: str = "full") -> tuple[str, str]:
    """``(kind, directory)`` of the detector ``$ROBOSCRIPT_DETECTOR`` names (``KIND:DIR``), checked, not loaded."""
    from roboscript.perception.detectors import DETECTOR_KINDS, DetectorError, check_model_dir

    spec = os.environ.get(DETECTOR_ENV, "")
    kind, sep, path = spec.partition(":")
    if not sep or not path:
        raise DetectorError(
            f"perception {mode} needs a detector: set {DETECTOR_ENV}=KIND:DIR with KIND one of "
            f"{', '.join(DETECTOR_KINDS)} and DIR a model saved with save_pretrained (got {spec!r}), or take the "
            f"2D boxes from ground truth with {_with_truth_2d(mode)}"
        )
    return kind, check_model_dir(kind, path)


def _with_truth_2d(mode: str) -> str:
    """``mode`` with ground-truth 2D boxes added: ``full`` -> ``gt-2d``, ``gt-scene`` -> ``gt-2d+gt-scene``."""
    stages = ["2d", *(s for s in STAGES if s in parse_mode(mode).from_truth)]
    return "+".join(f"gt-{s}" for s in stages)


def require_ready(mode: str) -> None:
    """Fails now, clearly, if ``mode`` cannot work (unknown, or its detector missing), before worlds are built."""
    if parse_mode(mode).needs_detector:
        detector_spec(mode)


def detector_from_env():
    """The detector ``$ROBOSCRIPT_DETECTOR`` names, loaded."""
    from roboscript.perception.detectors import OpenVocabularyDetector

    return OpenVocabularyDetector(*detector_spec())
