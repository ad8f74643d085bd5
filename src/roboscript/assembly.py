"""Assembly: the tool API for a backend, with perception and the planning scene as a perception mode says.

The one place that decides, for a given backend, where the tools' knowledge comes from: the simulator's state
(ground truth, for the ablations) or the backend's sensors (cameras, segmentation images, joint states). The layers
below it speak only to the :class:`~roboscript.backends.base.Backend` interface; this module and the ground-truth
modules are the only ones above the backends that know of the simulator.
"""

from __future__ import annotations

from roboscript import extras
from roboscript.api.tools import ToolAPI
from roboscript.backends.base import Backend, BackendError
from roboscript.perception.base import Perception
from roboscript.perception.modes import GROUND_TRUTH, PerceptionMode, perception_mode
from roboscript.perception.reconstruction.fusion import FusionSettings
from roboscript.planning.motion import MotionPlanner
from roboscript.sim.world_file import WorldSpec

SCENE_PADDING = 0.005  # metres: contacts closer than this count as collisions in the planning scene
FUSED_BELOW_BASE = 0.25  # metres below the robot's base (it stands on the table) down to which the cameras' views
# are fused: the table's edges and anything low beside it, not the floor


def build_tools(
    backend: Backend, perception: PerceptionMode | str = GROUND_TRUTH, seed: int = 0, scene: WorldSpec | None = None
) -> ToolAPI:
    """The tools on ``backend``, with perception and the planning scene as the mode ``perception`` says (ground
    truth by default; a string is parsed with :func:`~roboscript.perception.modes.perception_mode`).

    On a robot (no ground truth), ``scene`` describes what the cameras will see: the objects to look for and the
    furniture's parts (which handle moves which drawer); without it, the objects are those the segmentation labels
    name and no furniture is known."""
    mode = perception_mode(perception)
    seen = build_perception(backend, mode, seed, scene)  # refuses a mode the backend cannot serve
    motion = build_motion(backend, seen, mode, seed)
    return ToolAPI(backend, seen, motion, seed)


def build_perception(
    backend: Backend, mode: PerceptionMode | str = GROUND_TRUTH, seed: int = 0, scene: WorldSpec | None = None
) -> Perception:
    """The perception ``mode`` asks for on ``backend`` (``scene``: see :func:`build_tools`)."""
    from roboscript.perception.ground_truth import GroundTruthPerception

    mode = perception_mode(mode)
    _check_truth(backend, mode)
    if mode.uses_cameras(simulated=backend.ground_truth is not None):
        require_camera_pipeline(mode)
    if backend.ground_truth is None:
        return _perception_from_sensors(backend, mode, seed, scene)
    if not mode.needs_ground_truth:
        # Nothing from the simulator's state: only the description it was built from (the world file: names,
        # types, furniture rows), as a robot is given one.
        return _perception_from_sensors(backend, mode, seed, scene or backend.ground_truth.world.spec)
    truth = GroundTruthPerception(backend)
    if not mode.observed_objects:
        # One look before anything moves, as a tracker that has watched the scene from the start would have had: a
        # program that pulls a drawer before it asks about a mug would otherwise see the mug first with the arm in
        # front of it. (The camera pipeline looks at everything at the first question anyway.)
        truth.detect(None)
        return truth
    from roboscript.perception.detection.grounding import SegmentationGrounder
    from roboscript.perception.pipeline import PipelinePerception

    world = backend.ground_truth.world
    if mode.needs_detector:
        grounder = _detector(mode, scene or world.spec)
    else:
        grounder = SegmentationGrounder(world.entities, seed=seed)
    return PipelinePerception(
        backend,
        grounder,
        world.entity_names(("object",)),
        truth,
        robot_index=_robot_label(backend),
        settings=fusion_settings(backend),
    )


def build_motion(
    backend: Backend, perception: Perception, mode: PerceptionMode | str = GROUND_TRUTH, seed: int = 0, **kwargs
) -> MotionPlanner:
    """The motion planner for ``backend``: its scene the simulator's geometry where ``mode`` takes the scene from
    ground truth, else built from what ``perception`` saw; ``kwargs`` go to :class:`MotionPlanner`."""
    mode = perception_mode(mode)
    if not mode.observed_scene:
        from roboscript.planning.ground_truth_scene import ground_truth_motion

        _check_truth(backend, mode)
        return ground_truth_motion(backend, padding=SCENE_PADDING, seed=seed, **kwargs)
    return perceived_motion(backend, perception, seed=seed, **kwargs)


def perceived_motion(
    backend: Backend, perception: Perception, padding: float = SCENE_PADDING, **kwargs
) -> MotionPlanner:
    """A planner whose scene is built from what ``perception`` saw; only the robot's joint states are read."""
    from roboscript.planning.kinematics import ArmKinematics
    from roboscript.planning.perceived_scene import PerceivedSceneSource

    description, mount = backend.robot, backend.base_pose()
    source = PerceivedSceneSource(perception, description, mount, backend.joint_states, padding)
    # The scene is built at the first motion: by then the program has said what to look for.
    return MotionPlanner(backend, None, ArmKinematics(description, mount), source.state, scene_source=source, **kwargs)


def _perception_from_sensors(backend: Backend, mode: PerceptionMode, seed: int, scene: WorldSpec | None) -> Perception:
    """The camera pipeline from the backend's sensors alone: boxes from its segmentation node or a detector,
    labels of furniture from the scene's description; the robot's own pixels from its segmentation where that
    labels them, else from its model and joint readings (the self-filter)."""
    from roboscript.perception.detection.grounding import SegmentationGrounder
    from roboscript.perception.detection.labels import FurnitureLabels, segment_labels
    from roboscript.perception.modes import SEGMENTATION
    from roboscript.perception.pipeline import PipelinePerception
    from roboscript.perception.reconstruction.self_filter import SelfFilter

    labels = furniture_labels(scene) if scene is not None else FurnitureLabels()
    robot_index = None
    if mode.detector is not None and mode.detector.kind == SEGMENTATION:
        segments = segment_labels(backend.segmentation_labels(), labels.furniture())
        if not segments:
            raise BackendError(
                f"the {backend.robot.name}'s cameras publish no segmentation labels: configure the segmentation topics "
                "and the labels' topic, or give a detector (trained, owlv2:DIR or grounding-dino:DIR)"
            )
        grounder = SegmentationGrounder(segments, seed=seed)
        named = [s.name for s in segments if s.kind == "object"]
        robot_index = _robot_label(backend)
    else:
        grounder, named = _detector(mode, scene), []
    vocabulary = scene.object_names() if scene is not None else named
    robot = SelfFilter(backend.robot, backend.base_pose()) if robot_index is None else None
    return PipelinePerception(
        backend,
        grounder,
        vocabulary,
        labels,
        robot_index=robot_index,
        settings=fusion_settings(backend),
        self_filter=robot,
    )


def fusion_settings(backend: Backend) -> FusionSettings:
    """How the cameras' views are fused on ``backend``: down to :data:`FUSED_BELOW_BASE` below the robot's base."""
    return FusionSettings(lowest=float(backend.base_pose().position[2]) - FUSED_BELOW_BASE)


def furniture_labels(scene: WorldSpec):
    """The furniture of a world's description as labels: each cabinet, its drawers and doors and their handles."""
    from roboscript.perception.detection.labels import FurnitureLabels, PartLabel

    parts = []
    for cabinet in scene.cabinets:
        names = cabinet.part_names()  # each row's drawer or door, then its handle
        for moving, handle in zip(names[0::2], names[1::2], strict=True):
            joint = "prismatic" if ".drawer_" in moving else "revolute"
            parts.append(PartLabel(moving, joint, handle))
    return FurnitureLabels([c.name for c in scene.cabinets], parts)


def _robot_label(backend: Backend) -> int | None:
    """The segmentation label of the robot's own pixels, if the backend's segmentation has one."""
    return next((index for index, name in backend.segmentation_labels().items() if name == "robot"), None)


def _check_truth(backend: Backend, mode: PerceptionMode) -> None:
    if mode.needs_ground_truth and backend.ground_truth is None:
        raise BackendError(
            f"perception {mode} takes {', '.join(sorted(mode.from_truth))} from ground truth, which only a simulation "
            f"has; on a robot ({backend.robot.name}) use --perception full"
        )


def require_camera_pipeline(mode: PerceptionMode) -> None:
    """The camera pipeline fuses depth images with Open3D, an optional dependency: say so before anything moves."""
    extras.require("perception", f"--perception {mode}")


def _detector(mode: PerceptionMode, scene: WorldSpec | None):
    """The detector ``mode`` names; the trained one knows what ``scene``'s description says (objects' types,
    furniture's rows)."""
    from roboscript.perception.detection.detectors import DetectorError, OpenVocabularyDetector
    from roboscript.perception.modes import TRAINED

    if mode.detector is None:
        raise DetectorError(
            f"perception {mode} needs a detector: make the mode with perception_mode({mode.name!r}, 'KIND:PATH') "
            "(the command line's --detector or $ROBOSCRIPT_DETECTOR)"
        )
    if mode.detector.kind == TRAINED:
        from roboscript.perception.detection.detector_model import load_detector_model
        from roboscript.perception.detection.trained_detector import TrainedDetector

        return TrainedDetector.for_scene(scene, load_detector_model(mode.detector.directory or None))
    return OpenVocabularyDetector(mode.detector.kind, mode.detector.directory)
