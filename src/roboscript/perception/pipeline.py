"""Perception from the cameras: ``detect_objects`` looks with every camera, grounds the phrases asked for in 2D,
fuses the views, matches boxes across views and cuts out 3D instances; the tools' questions about objects are then
answered from what was seen (:mod:`roboscript.perception.reconstruction.observation`).

Objects are named after the phrase that found them: ``apple`` when one was found, ``box_0``, ``box_1``... when
several were. Without a list, ``detect_objects()`` looks for the vocabulary the task names (the ``objects = [...]``
of its query). When the robot has let something go, the store is stale: the next question looks again, for
everything looked for so far, and each object seen again keeps its name (matched to where the store expected it:
what the robot carried moved with the gripper). Something not seen again (hidden in a drawer) keeps its last
estimate.

Furniture and its parts (``cabinet``, ``cabinet.drawer_1``, ``cabinet.handle_1``) are looked for with every look
too, and answered for from their points as objects are (:mod:`roboscript.perception.furniture.seen_furniture`).
The planning scene is built from what this store saw (:mod:`roboscript.planning.perceived_scene`) unless the mode
takes it from ground truth.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Sequence
from contextlib import contextmanager

import numpy as np

from roboscript.backends.base import Backend
from roboscript.geometry import Box3D, Transform, quat_from_yaw
from roboscript.perception.base import (
    OCCUPANCY_MARGIN,
    TABLE,
    ArticulationJoint,
    ObjectNotFoundError,
    ObjectPoints,
    Perception,
    Receptacle,
    outside,
)
from roboscript.perception.detection.grounding import Grounder, normalize_phrase
from roboscript.perception.detection.labels import PartLabels
from roboscript.perception.footprints import outline_of
from roboscript.perception.furniture.seen_furniture import SeenFurniture, shows_in_pieces
from roboscript.perception.points import pixels_outside, robot_masks, surface_points
from roboscript.perception.reconstruction.faces import plane_normal_at
from roboscript.perception.reconstruction.free_space import stands_empty
from roboscript.perception.reconstruction.fusion import FusionSettings
from roboscript.perception.reconstruction.in_hand import register
from roboscript.perception.reconstruction.instances import Instance3D
from roboscript.perception.reconstruction.observation import Observation, observe, why_not_found
from roboscript.perception.reconstruction.refinement import claimed_by_boxes
from roboscript.perception.reconstruction.self_filter import SelfFilter
from roboscript.perception.seen_objects import (
    SeenObject,
    fallen,
    found_object,
    interior_of,
    moved,
    object_name,
    part_of,
)
from roboscript.phases import timed
from roboscript.robot_io import CameraFrame

SETTLE_TIME = 0.5  # seconds given to what was let go to come to rest before looking again
HANG_TIME = 0.3  # seconds given to what was just lifted to stop swinging in the hand before looking at it
SURFACE_STRIDE = 2  # every how many depth pixels one stands for the observed surfaces (as ground truth's do)
MOVED = 0.005  # metres the gripper must have moved since a look for another look to be worth it
JUMP = 0.05  # metres an untouched object's find may lie from where it stood before it must show it has gone
SAME_PLACE = 0.5  # box IoU above which a find stands where another known object does: it is that one
MIN_KEPT = 30  # points a find must keep of its own for what a settled thing takes back to be taken
IN_HAND_REACH = 0.06  # metres round where a carried object should hang within which the in-hand look looks for it


class PipelinePerception(Perception):
    """Perception from ``backend``'s cameras through ``grounder``; ``parts`` labels furniture and its parts (what
    parts there are, which part a handle moves and how).

    ``vocabulary``: the phrases ``detect_objects()`` looks for when given none. The robot's own pixels are left out
    of what is grounded and fused: ``robot_index``, the segmentation index of the robot, tells them where the frames
    carry a segmentation that labels it; else ``self_filter`` tells them from the robot's model and its joint
    readings (:mod:`roboscript.perception.reconstruction.self_filter`), as a real rig does.
    """

    def __init__(
        self,
        backend: Backend,
        grounder: Grounder,
        vocabulary: Sequence[str],
        parts: PartLabels,
        robot_index: int | None = None,
        settings: FusionSettings | None = None,
        self_filter: SelfFilter | None = None,
    ):
        self.backend, self.grounder = backend, grounder
        self.vocabulary = [normalize_phrase(v) for v in vocabulary]
        self.robot_index, self.settings, self.self_filter = robot_index, settings, self_filter
        self.masks: list[np.ndarray | None] = []  # the robot's pixels in each frame of the last look
        self.store: dict[str, SeenObject] = {}
        self.furniture_seen = SeenFurniture(parts, self.names)
        self.not_found: dict[str, str] = {}
        self.scene: np.ndarray = np.zeros((0, 3))
        self.last: Observation | None = None
        self.looks = 0  # how many times the cameras were used
        self._asked: list[str] = []  # every phrase looked for, in order
        self._carried: dict[str, Transform] = {}  # objects in the gripper, with where the gripper took them
        self._let_go: set[str] = set()  # objects let go since the last look
        self._looked = False
        self._stale = False
        self._vacated: list[Box3D] = []  # where objects were taken from since the last look
        self._holding_looks = False
        self._look_tcp: np.ndarray | None = None  # where the gripper was at the last look

    # --- looking ----------------------------------------------------------------------------------------------

    @timed("perceive")
    def detect(self, categories: list[str] | None = None) -> None:
        phrases = [normalize_phrase(c) for c in categories] if categories else list(self.vocabulary)
        if not phrases:
            raise ValueError("nothing to look for: pass category_list, e.g. ['apple', 'bowl']")
        self._look(phrases)

    def _look(self, asked: list[str]) -> None:
        frames = self._capture()
        masks = self._robot_masks(frames)
        # The table is measured (the level surface things stand on), not found.
        furniture_phrases = self.furniture_seen.phrases
        phrases = [p for p in asked if p not in furniture_phrases and p != TABLE]
        furniture = list(furniture_phrases)
        pieces = {p for p, n in furniture_phrases.items() if shows_in_pieces(n)}
        seen = observe(frames, self.grounder, phrases + furniture, self.settings, masks, pieces, furniture)
        self.last, self._looked, self._stale = seen, True, False
        self.masks = [masks[k] for k, f in enumerate(frames) if f.name in seen.scene.used]
        self._look_tcp = self.backend.tcp_pose().position.copy()
        self._vacated = []
        self.looks += 1
        used = [k for k, f in enumerate(frames) if f.name in seen.scene.used]  # broken depth images are not
        self.scene = surface_points([frames[k] for k in used], [masks[k] for k in used], SURFACE_STRIDE)
        self._asked += [p for p in phrases if p not in self._asked]
        self.furniture_seen.record(seen, self.looks)
        seen_again = set()
        for phrase in phrases:
            found = [i for i in seen.instances if i.label == phrase]
            if phrase in self.vocabulary and len(found) > 1:
                # The scene's description names one thing so: the one seen best is it, the rest are mistaken.
                found = [max(found, key=lambda i: (sum(b != -1 for b in i.boxes), len(i.points)))]
            self.not_found.pop(phrase, None)
            if not found:
                if not any(o.phrase == phrase for o in self.store.values()):
                    self.not_found[phrase] = why_not_found(seen, phrase, self.grounder.account(phrase))
                continue
            seen_again |= self._update(phrase, found, seen)
        settled = {n for n in self._let_go - seen_again if n in self.store and n not in self._carried}
        for name in settled:
            self.store[name] = fallen(self.store[name], self.scene)
        self._give_back(settled, seen_again - settled)
        self._let_go.clear()

    def _give_back(self, settled: set[str], found: set[str]) -> None:
        """What this look's finds of other things (``found``) hold of where a thing let go and not seen again
        (``settled``) lies is that thing's: two things do not fill one place. A block let go on a box was missed by
        the detector in every view; the box's one 2D box took in the block's lower half, and the box stood 3.6 cm
        taller than it is."""
        boxes = [self.store[n].box for n in settled]
        for name in found - set(self._carried):
            obj = self.store.get(name)
            if obj is None or not any(obj.box.intersection(b).volume > 0 for b in boxes):
                continue
            keep = ~claimed_by_boxes(boxes, obj.points)
            if MIN_KEPT <= keep.sum() < len(keep):
                self.store[name] = dataclasses.replace(obj, points=obj.points[keep], normals=obj.normals[keep])

    def _capture(self) -> list[CameraFrame]:
        """A frame of every camera, with segmentation only where something here reads it."""
        segmentation = self.robot_index is not None or self.grounder.reads_segmentation
        return [self.backend.capture(c, segmentation=segmentation) for c in self.backend.camera_names()]

    def _robot_masks(self, frames: list, wanted: list[np.ndarray] | None = None) -> list[np.ndarray | None]:
        """The robot's pixels in each frame (``wanted``: those of each frame whose answer matters, where only some
        do)."""
        if self.robot_index is not None or self.self_filter is None:
            return robot_masks(frames, self.robot_index)
        return self.self_filter.masks(frames, self.backend.joint_states(), wanted)

    def _update(self, phrase: str, found: list[Instance3D], seen: Observation) -> set[str]:
        """Puts what was found for ``phrase`` into the store, and returns the names it stored. Earlier objects of
        the phrase keep their names, given to the nearest new finds (however far they went: one apple seen again
        is the apple, wherever it rolled); finds beyond their number get new names."""
        old = {n: self._expected(n) for n, o in self.store.items() if o.phrase == phrase}
        found = sorted(found, key=lambda i: (round(float(i.box.center[1]), 3), round(float(i.box.center[0]), 3)))
        pairs = sorted(
            (float(np.linalg.norm(i.box.center - o.box.center)), k, n)
            for k, i in enumerate(found)
            for n, o in old.items()
        )
        names: dict[int, str] = {}
        for _, k, n in pairs:
            if k not in names and n not in names.values():
                names[k] = n
        base = object_name(phrase)
        if not old and len(found) == 1:
            names[0] = base
        taken = set(self.store)
        counter = 0
        for k in range(len(found)):
            if k in names:
                continue
            while f"{base}_{counter}" in taken:
                counter += 1
            names[k] = f"{base}_{counter}"
            taken.add(names[k])
        missed: set[str] = set()
        for k, instance in enumerate(found):
            if names[k] in self._carried:
                # Its surfaces in this look are not obstacles: where the fit is not believed, they stand out of the
                # box it is carried in, and it would collide with itself.
                self.scene = outside(self.scene, instance.box, OCCUPANCY_MARGIN)
                self.store[names[k]] = self._in_hand(old[names[k]], instance)
            else:
                fresh = found_object(names[k], phrase, instance, seen.support)
                before = self.store.get(names[k])
                if before is not None and not self._may_have_gone(before, fresh, seen):
                    continue
                if before is not None and self._held_by_another(fresh, seen):
                    missed.add(names[k])  # what was let go and not seen again settles where it was let go
                    continue
                # Seen by fewer cameras than before (the arm in the way, a detector's miss) where it stood still:
                # the earlier look saw more of it (a mug's rim from one side only has no grasp pairs).
                still = before is not None and names[k] not in self._let_go and part_of(fresh, before)
                self.store[names[k]] = before if still and fresh.views < before.views else fresh
        return set(names.values()) - missed

    def _held_by_another(self, fresh: SeenObject, seen: Observation) -> bool:
        """Whether ``fresh`` is where another known object of another phrase stands, one the robot has not moved
        and this look does not find elsewhere: two things do not fill one place, so the detector put this name on
        that one (a wooden bar let go inside a cabinet, out of every camera's sight, found on the wooden block)."""

        def found_elsewhere(other: SeenObject) -> bool:
            return any(i.label == other.phrase and i.box.iou(other.box) <= SAME_PLACE for i in seen.instances)

        return any(
            other.phrase != fresh.phrase
            and other.name not in self._let_go
            and other.name not in self._carried
            and fresh.box.iou(other.box) > SAME_PLACE
            and not found_elsewhere(other)
            for other in self.store.values()
        )

    def _may_have_gone(self, before: SeenObject, fresh: SeenObject, seen: Observation) -> bool:
        """Whether ``fresh``, found :data:`JUMP` or more from where ``before`` stood, may be it. The robot has not
        touched it since, so it went only if pushed or carried along (in a drawer): this look sees through its old
        place (:func:`~roboscript.perception.reconstruction.free_space.stands_empty`), or sees the find better than it
        was seen. Else the detector put its name on something else (a mug's on an open drawer's front) and missed it."""
        if before.name in self._let_go or fresh.views > before.views:
            return True
        if float(np.linalg.norm(fresh.box.center - before.box.center)) < JUMP:
            return True
        return stands_empty(before.points, seen.frames, self.masks)

    def _in_hand(self, expected: SeenObject, instance: Instance3D) -> SeenObject:
        """A carried object seen in the hand: the whole of it as seen before, moved to where this look shows the
        part of it the hand leaves in view (:func:`~roboscript.perception.reconstruction.in_hand.register`), or where
        the gripper has taken it where that part says too little; from here on it goes with the gripper."""
        self._carried[expected.name] = self.backend.tcp_pose()
        motion = register(expected.points, instance.points)
        return expected if motion is None else moved(expected, motion)

    @timed("perceive")
    def hangs_free(self, name: str) -> bool:
        """Looks at ``name`` alone in the hand once it hangs free: where it settled between the fingers (turned,
        slid down) is where it is carried and set down from. The rest of what is known stays as the last full look
        saw it (a look with the arm low over the table sees less of it). True where ``name`` moved in the hand."""
        if name not in self._carried or self._holding_looks:
            return False
        self.backend.wait(HANG_TIME)
        frames = self._capture()
        phrase = self.store[name].phrase
        expected = self._expected(name)
        # Only what lies about where it should hang is looked at, and the table below it (what a look measures
        # heights from): the rest of the scene is as the last look saw it.
        lower = expected.box.lower - IN_HAND_REACH
        if self.last is not None:
            lower[2] = min(lower[2], self.last.support - IN_HAND_REACH)
        around = Box3D(lower, expected.box.upper + IN_HAND_REACH)
        away = [pixels_outside(f, around) for f in frames]
        robot = self._robot_masks(frames, wanted=[~a for a in away])
        masks = [a if m is None else a | m for a, m in zip(away, robot, strict=True)]
        seen = observe(frames, self.grounder, [phrase], self.settings, masks)
        found = [i for i in seen.instances if i.label == phrase]
        if not found:
            return False
        nearest = min(found, key=lambda i: float(np.linalg.norm(i.box.center - expected.box.center)))
        self.store[name] = self._in_hand(expected, nearest)
        return self.store[name] is not expected

    def _ensure_looked(self, fresh: bool = True) -> None:
        """Looks if nothing was seen yet; with ``fresh``, also if something was let go since the last look (names
        do not need a fresh look, geometry does: by the time it is asked for the hand has usually moved away)."""
        if not self._looked:
            self.detect(None)
        elif fresh and self._stale and not self._holding_looks:
            self.backend.wait(SETTLE_TIME)  # what was let go may still be rolling
            self._look(list(self._asked))

    @contextmanager
    def without_looking(self) -> Iterator[None]:
        holding, self._holding_looks = self._holding_looks, True
        try:
            yield
        finally:
            self._holding_looks = holding

    def carried(self, name: str, gripper: Transform) -> None:
        if name in self.store:
            self._carried[name] = gripper
            self._vacated.append(self.store[name].box)

    def released(self, name: str, gripper: Transform) -> None:
        """``name`` was let go: its points move as the gripper did since it was taken; the next question looks
        again (a part let go, a drawer pulled, has moved too)."""
        self._stale = True  # what was let go may settle, roll or push others: look again before answering
        start = self._carried.pop(name, None)
        if start is not None:
            self.store[name] = moved(self.store[name], gripper.compose(start.inverse()))
            self._let_go.add(name)

    # --- the questions ----------------------------------------------------------------------------------------

    def furniture(self) -> list[str]:
        self._ensure_looked(fresh=False)
        return self.furniture_seen.names()

    def names(self) -> list[str]:
        """In the order of the original benchmark's queries: the table, furniture, objects, furniture parts."""
        self._ensure_looked(fresh=False)
        seen = self.furniture_seen.names()
        table = [TABLE] if TABLE in self.furniture_seen.seen else []
        return table + [n for n in seen if "." not in n] + list(self.store) + [n for n in seen if "." in n]

    def objects(self) -> list[str]:
        self._ensure_looked(fresh=False)
        return list(self.store)

    def require(self, name: object) -> str:
        if isinstance(name, str) and name not in self.names():
            phrase = normalize_phrase(name)
            if phrase in self.not_found:
                raise ObjectNotFoundError(name, self.names(), self.not_found[phrase])
            if name in self.furniture_seen.phrases.values():
                raise ObjectNotFoundError(name, self.names(), f"no camera has seen it in {self.looks} looks")
            if name == TABLE:
                why = f"no look of {self.looks} saw a level surface under the objects (the table's top)"
                raise ObjectNotFoundError(name, self.names(), why)
        return super().require(name)

    def _object(self, name: str) -> SeenObject | None:
        self._ensure_looked()
        if name in self.store:
            return self._expected(name)
        self.require(name)
        return None

    def _expected(self, name: str) -> SeenObject:
        """The stored object where it should be now: in the gripper, where the gripper has taken it since."""
        if name in self._carried:
            return moved(self.store[name], self.backend.tcp_pose().compose(self._carried[name].inverse()))
        return self.store[name]

    def _part(self, name: str) -> ObjectPoints:
        """The points of furniture or a part as last seen (:meth:`_object` has checked the name)."""
        return self.furniture_seen.seen[name]

    def box(self, name: str) -> Box3D:
        """Of furniture, the box of its carcass as seen (its parts have boxes of their own); of the table, the box
        of its top as seen, up to the height of the surface things stand on."""
        obj = self._object(name)
        return obj.box if obj else self.furniture_seen.box(name)

    def footprint(self, name: str) -> tuple[np.ndarray, float, np.ndarray]:
        """Of furniture and parts, their box from above (as ground truth gives it)."""
        obj = self._object(name)
        if obj is None:
            box = self.furniture_seen.box(name)
            return box.center[:2], 0.0, box.size[:2] / 2
        return obj.footprint

    def outline(self, name: str) -> np.ndarray:
        """Of objects, the convex outline of their points from above; of furniture and parts, their box's."""
        obj = self._object(name)
        return super().outline(name) if obj is None else outline_of(obj.outline, footprint=obj.footprint)

    def pose(self, name: str) -> Transform:
        """Of objects, the centre of their bottom face turned as their footprint; of furniture and parts, the
        centre of their box, unturned."""
        obj = self._object(name)
        if obj is None:
            return Transform(self.box(name).center, quat_from_yaw(0.0))
        center, yaw, _ = obj.footprint
        return Transform(np.array([center[0], center[1], obj.box.lower[2]]), quat_from_yaw(yaw))

    def joints(self, name: str) -> list[ArticulationJoint]:
        """The joints of furniture or a part, estimated from the points of each moving part's front and its
        handle (:mod:`roboscript.perception.furniture.articulation`). Which parts move, and whether they slide or turn,
        is what their labels say (``parts``); where and along what they move is from the points."""
        if self._object(name):
            return []
        return self.furniture_seen.joints(name)

    def plane_normal(self, name: str, position: np.ndarray) -> np.ndarray:
        obj = self._object(name)
        if obj is None:  # a front seen from one side: its normal faces the cameras, as its points' normals do
            seen = self._part(name)
            return plane_normal_at(seen.points, np.asarray(position, dtype=float), normals=seen.normals)
        return plane_normal_at(obj.points, np.asarray(position, dtype=float))

    @timed("perceive")
    def points(self, name: str) -> ObjectPoints:
        obj = self._object(name)
        if obj is None:
            return self._part(name)
        return ObjectPoints(obj.points, obj.normals)

    @timed("perceive")
    def scene_points(self) -> np.ndarray:
        """The surfaces of the last look, less where objects were taken from since (they are gone from there)."""
        self._ensure_looked()
        points = self.scene
        for box in self._vacated:
            points = outside(points, box, OCCUPANCY_MARGIN)
        return points

    def last_frames(self) -> list:
        return list(self.last.frames) if self.last else []

    def last_masks(self) -> list:
        return list(self.masks) if self.last else []

    def receptacle(self, name: str) -> Receptacle | None:
        return self._receptacle(name, look_again=True)

    def seen_receptacle(self, name: str) -> Receptacle | None:
        return self._receptacle(name, look_again=False)

    def _receptacle(self, name: str, look_again: bool) -> Receptacle | None:
        obj = self._object(name)
        if obj is None:
            opening = self.furniture_seen.opening(name)
            if opening is None:
                return None
            if look_again:
                self._fresh_look_inside()
            return self.furniture_seen.inside(opening)
        if obj.kind is None or not obj.kind.container or obj.kind.interior is None:
            return None
        return interior_of(obj.points, obj.outline, obj.kind, name)

    def _fresh_look_inside(self) -> None:
        """Looks again before an inside is measured if the arm has moved since the last look. The arm that has just
        pulled a drawer or swung a door stands in front of it. From that look, the handle may be hidden, or the
        bottom, or part of it: the inside then comes out as much smaller as the arm hid of it (a drawer 13 cm deep
        instead of 18, on the FR3, which hides more than the Panda). No second look can show more than this one:
        the arm does not move while an inside is measured."""
        if self._may_look_again():
            self._look(list(self._asked))

    def _may_look_again(self) -> bool:
        """Whether a new look could show more than the last: the gripper has moved since (the arm hides less, or
        other things), and looking is not held off."""
        if self._holding_looks or self._look_tcp is None:
            return False
        return float(np.linalg.norm(self.backend.tcp_pose().position - self._look_tcp)) > MOVED

