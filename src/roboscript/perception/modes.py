"""Perception modes: which stages of perception the tools' knowledge comes from, for the benchmark's ablations.

Perception has three stages that can each be replaced by ground truth: ``2d`` (boxes of the phrases in each camera
image), ``3d`` (objects' boxes, poses and points, from fused RGB-D views) and ``scene`` (the planning scene, from
observed surfaces as occupancy boxes). ``full`` takes none from ground truth, ``gt`` all; ``gt-2d``, ``gt-3d`` and
``gt-scene`` each take one, and can be combined with ``+`` (``gt-2d+gt-scene``) to isolate the rest.

Without ground-truth 2D boxes, the boxes come from a detector: by default the one the project trains itself on its
generated scenes and ships (``trained``, :mod:`roboscript.perception.detection.trained_detector`), or another model of
it (``trained:FILE.npz``, from ``roboscript train-detector``), or an open-vocabulary detector whose weights the user
provides (``owlv2:DIR`` or ``grounding-dino:DIR``); ``--detector`` or ``$ROBOSCRIPT_DETECTOR`` (read by the command
line only) choose.
Where objects are observed, furniture is too: its boxes, points, joints
(:mod:`roboscript.perception.furniture.articulation`) and drawers' insides
(:mod:`roboscript.perception.furniture.drawers`) come from the points of the carcass, fronts and handles; only the
labels (what parts there are, which part a handle moves, sliding or turning) come from the furniture's description.
:mod:`roboscript.assembly` builds the perception a mode asks for.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

STAGES = ("2d", "3d", "scene")
PERCEPTION_MODES = {
    "gt": "ground truth everywhere",
    "full": "nothing from ground truth: 2D boxes from a detector (the packaged trained one by default; --detector or "
    "$ROBOSCRIPT_DETECTOR: trained:FILE.npz, owlv2:DIR or grounding-dino:DIR), objects from fused RGB-D views, the "
    "planning scene from observed surfaces",
    "gt-2d": "as full, with ground-truth 2D boxes (the simulator's segmentation)",
    "gt-3d": "as full, with objects' 3D boxes, poses and points from ground truth (the planning scene observed)",
    "gt-scene": "as full, with the ground-truth planning scene (the simulator's geometry)",
}
DETECTOR_ENV = "ROBOSCRIPT_DETECTOR"
SEGMENTATION = "segmentation"  # the 2D boxes of a segmentation node's labelled images, on a robot that has one
TRAINED = "trained"  # the detector this project trains (roboscript train-detector); the packaged model by default
ALIASES = {"det-2d": "gt-scene"}  # the earlier name of detector boxes with the exact planning scene, for old runs


@dataclass(frozen=True)
class DetectorSpec:
    """A detector's kind (``trained``, ``owlv2``, ``grounding-dino``, ``segmentation``) and where its weights are
    (a directory of an open-vocabulary model, a model file of the trained one; empty: the packaged model)."""

    kind: str
    directory: str

    def __str__(self) -> str:
        return f"{self.kind}:{self.directory}" if self.directory else self.kind


@dataclass(frozen=True)
class PerceptionMode:
    """The stages a mode takes from ground truth, and the detector it uses where it takes no 2D boxes from it.

    Made once, where a run is configured (:func:`perception_mode`); everything below takes this value."""

    name: str
    from_truth: frozenset[str]
    detector: DetectorSpec | None = None

    def __str__(self) -> str:
        return self.name

    @property
    def needs_detector(self) -> bool:
        return not {"2d", "3d"} & self.from_truth

    @property
    def observed_objects(self) -> bool:
        return "3d" not in self.from_truth

    @property
    def observed_scene(self) -> bool:
        return "scene" not in self.from_truth

    def uses_cameras(self, simulated: bool = True) -> bool:
        """Whether the tools fuse the cameras' RGB-D images (with Open3D, the ``perception`` extra): where objects
        are observed, and on a robot, which has no ground truth to take them from."""
        return self.observed_objects or not simulated

    @property
    def needs_ground_truth(self) -> bool:
        return bool(self.from_truth)


def perception_mode(mode: str | PerceptionMode, detector: str | None = None) -> PerceptionMode:
    """The mode ``mode`` names, with the detector ``detector`` names (``KIND:PATH``; the packaged trained detector
    where none is named) where the mode needs one, checked (its weights are there) but not loaded. Raises
    ``ValueError`` for an unknown mode and :class:`~roboscript.perception.detection.detectors.DetectorError` for a bad
    detector."""
    parsed = mode if isinstance(mode, PerceptionMode) else parse_mode(mode)
    if not parsed.needs_detector or parsed.detector is not None:
        return parsed
    return replace(parsed, detector=parse_detector(detector or TRAINED, parsed.name))


def parse_mode(mode: str) -> PerceptionMode:
    """The :class:`PerceptionMode` named by ``mode`` (no detector yet): one of :data:`PERCEPTION_MODES`, or
    ``gt-...`` modes joined by ``+``."""
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
            raise ValueError(
                f"unknown perception mode {mode!r}; modes: {', '.join(PERCEPTION_MODES)}; gt-2d, gt-3d and gt-scene "
                "combine with '+' (e.g. gt-2d+gt-scene); --help says what each takes from ground truth"
            )
        stages.append(stage)
    return PerceptionMode(mode, frozenset(stages))


GROUND_TRUTH = parse_mode("gt")


def parse_detector(spec: str, mode: str = "full") -> DetectorSpec:
    """The detector ``spec`` (``KIND:DIR``) names, checked, not loaded; ``mode`` is named in the error."""
    from roboscript.perception.detection.detectors import DETECTOR_KINDS, DetectorError, check_model_dir

    if spec == SEGMENTATION:
        return DetectorSpec(SEGMENTATION, "")
    kind, sep, path = spec.partition(":")
    if kind == TRAINED:
        from roboscript.perception.detection.detector_model import check_model_file

        return DetectorSpec(TRAINED, check_model_file(path) if path else "")
    if not sep or not path:
        raise DetectorError(
            f"perception {mode} needs a detector: pass --detector or set {DETECTOR_ENV} to {TRAINED} (the packaged "
            f"model), {TRAINED}:FILE.npz (one from roboscript train-detector), KIND:DIR with KIND one of "
            f"{', '.join(DETECTOR_KINDS)} and DIR a model saved with save_pretrained, or {SEGMENTATION} for a "
            f"robot's segmentation topic (got {spec!r}), or take the 2D boxes from ground truth with "
            f"{_with_truth_2d(mode)}"
        )
    return DetectorSpec(kind, check_model_dir(kind, path))


def _with_truth_2d(mode: str) -> str:
    """``mode`` with ground-truth 2D boxes added: ``full`` -> ``gt-2d``, ``gt-scene`` -> ``gt-2d+gt-scene``."""
    stages = ["2d", *(s for s in STAGES if s in parse_mode(mode).from_truth)]
    return "+".join(f"gt-{s}" for s in stages)
