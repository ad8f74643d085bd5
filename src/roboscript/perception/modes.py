"""Perception modes: where the tools' knowledge of the world comes from, for the benchmark's ablations.

``gt``: everything from the simulator's state. ``gt-2d``: 2D boxes from the simulator's segmentation, and
everything about objects (their 3D boxes, poses, points, containers' interiors) from fused camera views.
Furniture parts, their joints and the planning scene come from ground truth in every mode so far.
"""

from __future__ import annotations

from roboscript.backends.base import Backend
from roboscript.perception.base import Perception

PERCEPTION_MODES = {
    "gt": "ground truth everywhere",
    "gt-2d": "ground-truth 2D boxes; 3D boxes, poses and points of objects from fused RGB-D views",
}


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
    grounder = SegmentationGrounder(world.entities, seed=seed)
    vocabulary = world.entity_names(("object",))
    return PipelinePerception(backend, grounder, vocabulary, truth, robot_index=world.entity("robot").index)
