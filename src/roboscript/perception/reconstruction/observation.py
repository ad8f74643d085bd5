"""One look at the scene: ground every view in 2D, fuse the views in 3D, match boxes across views, cut out 3D
instances. :func:`observe` is the whole chain; each step is its own module."""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.perception.detection.grounding import Detection2D, Grounder
from roboscript.perception.points import DepthSurface, without_pixels
from roboscript.perception.reconstruction.fusion import FusedScene, FusionSettings, fuse
from roboscript.perception.reconstruction.instances import Instance3D, build_instances, ground, support_height
from roboscript.perception.reconstruction.matching import MatchedObject, Projection, match_views, membership, project
from roboscript.perception.reconstruction.refinement import refine_all
from roboscript.robot_io import CameraFrame


@dataclass
class Observation:
    """Everything one look produced, step by step (kept for inspection and evaluation)."""

    frames: list[CameraFrame]  # the frames fused and grounded (broken ones left out)
    scene: FusedScene
    detections: list[list[Detection2D]]
    projections: list[Projection]
    memberships: list[list[np.ndarray]]
    matched: list[MatchedObject]
    instances: list[Instance3D]
    support: float  # the table's height

    @property
    def skipped(self) -> dict[str, str]:
        """Frames left out, with the reason."""
        return self.scene.skipped


def observe(
    frames: Sequence[CameraFrame],
    grounder: Grounder,
    phrases: Sequence[str],
    settings: FusionSettings | None = None,
    robot_masks: Sequence[np.ndarray] | None = None,
    pieces: Collection[str] = (),
    furniture: Collection[str] = (),
) -> Observation:
    """Runs the chain on ``frames`` for the things ``phrases`` name. ``robot_masks``: per frame, the pixels of the
    robot itself (from its model), left out of the fused surface; ``pieces``: the phrases of furniture parts,
    which may be seen in several pieces (an open drawer's front and its inside); ``furniture``: the phrases of
    furniture and all its parts (see :func:`~roboscript.perception.reconstruction.refinement.refine_all`)."""
    if not frames:
        raise ValueError("observe needs at least one camera frame")
    scene = fuse(frames, settings, robot_masks)
    if not scene.used:
        problems = "; ".join(f"{name}: {why}" for name, why in scene.skipped.items())
        raise ValueError(f"no camera gave a usable depth image ({problems})")
    usable = [f for f in frames if f.name in scene.used]
    if len(scene.points) == 0:  # the masks left nothing to fuse (a look confined to an empty place): nothing found
        nothing = [[] for _ in usable]
        return Observation(usable, scene, nothing, [], nothing, [], [], float("nan"))
    # The robot's own pixels are no object's, nor any part's.
    hidden = dict(zip((f.name for f in frames), robot_masks or [None] * len(frames), strict=True))
    detections = [grounder.detect(without_pixels(f, hidden[f.name]), phrases) for f in usable]
    projections = [project(scene.points, f) for f in usable]
    memberships = [[membership(p, d.box) for d in ds] for p, ds in zip(projections, detections, strict=True)]
    matched = match_views(memberships, detections)
    support = support_height(scene.points)
    areas = [[(d.box[2] - d.box[0]) * (d.box[3] - d.box[1]) for d in ds] for ds in detections]
    instances = build_instances(
        matched, scene.points, scene.normals, memberships, projections, support, areas, pieces=pieces
    )
    surfaces = [DepthSurface(f, hidden[f.name]) for f in usable]
    instances = refine_all(instances, detections, surfaces, support, furniture)
    instances = ground(instances, support)
    return Observation(usable, scene, detections, projections, memberships, matched, instances, support)


def why_not_found(seen: Observation, phrase: str, account: str = "") -> str:
    """What a look that found nothing of ``phrase`` saw instead, per view (and the detector's ``account`` of the
    phrase): the "not found" a program reads."""
    views = len(seen.frames)
    found = {}
    for detections in seen.detections:
        for d in detections:
            found[d.label] = found.get(d.label, 0) + 1
    asked = f"no view of {views} ({', '.join(f.name for f in seen.frames)}) found {phrase!r}"
    if seen.skipped:
        asked += "; skipped: " + ", ".join(f"{n} ({why})" for n, why in seen.skipped.items())
    if account:
        asked += f"; {account}"
    if not found:
        return asked + "; nothing asked for was seen"
    return asked + "; seen: " + ", ".join(f"{label} in {n} view{'s' * (n > 1)}" for label, n in sorted(found.items()))
