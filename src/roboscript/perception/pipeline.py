"""Perception from the cameras: ``detect_objects`` looks with every camera, grounds the phrases asked for in 2D,
fuses the views, matches boxes across views and cuts out 3D instances; the tools' questions about objects are then
answered from what was seen (:mod:`roboscript.perception.observation`).

Objects are named after the phrase that found them: ``apple`` when one was found, ``box_0``, ``box_1``... when
several were. Without a list, ``detect_objects()`` looks for the vocabulary the task names (the ``objects = [...]``
of its query). When the robot has let something go, the store is stale: the next question looks again, for
everything looked for so far, and each object seen again keeps its name (matched to where the store expected it:
what the robot carried moved with the gripper). Something not seen again (hidden in a drawer) keeps its last
estimate.

Furniture and its parts (``cabinet``, ``cabinet.drawer_1``, ``cabinet.handle_1``) are looked for with every look
too, and answered for from their points as objects are: boxes, points, plane normals, joints
(:mod:`roboscript.perception.articulation`) and drawers' insides (:mod:`roboscript.perception.drawers`). What
parts there are, and which part each handle moves and how (slides, turns), are their labels (``parts``: the
furniture's description); a part no camera has seen yet is "not found".
The planning scene is built from what this store saw (:mod:`roboscript.planning.perceived_scene`) unless the mode
takes it from ground truth.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from roboscript.backends.base import Backend
from roboscript.geometry import Box3D, Transform, quat_from_yaw
from roboscript.names import kind_of
from roboscript.objects import ObjectType, object_types
from roboscript.perception.articulation import DRAWER_TRAVEL, estimate_joint, front_plane, moved_with_handle
from roboscript.perception.base import (
    OCCUPANCY_MARGIN,
    TABLE,
    ArticulationJoint,
    ObjectPoints,
    Perception,
    Receptacle,
    UnknownObjectError,
    outside,
)
from roboscript.perception.compartments import CompartmentUnseenError, compartment_inside, door_angle
from roboscript.perception.drawers import (
    carcass_front,
    closed_drawer,
    drawer_receptacle,
    opening_frame,
    unseen_inside,
)
from roboscript.perception.faces import plane_normal_at
from roboscript.perception.footprints import footprint_of, outline_of
from roboscript.perception.free_space import stands_empty
from roboscript.perception.furniture_parts import row_bands
from roboscript.perception.fusion import FusionSettings
from roboscript.perception.grounding import Grounder, normalize_phrase
from roboscript.perception.in_hand import register
from roboscript.perception.instances import (
    PIXEL_BLUR,
    Instance3D,
    claimed_by_boxes,
    fit_box,
    footprint_points,
    object_box,
    table_surface,
)
from roboscript.perception.labels import PartLabels
from roboscript.perception.observation import Observation, observe
from roboscript.perception.points import robot_masks, surface_points
from roboscript.perception.self_filter import SelfFilter
from roboscript.phases import timed

STILL = 0.006  # metres from what an earlier look saw of an object within which a later look's points show it unmoved
STILL_SHARE = 0.97  # the share of a later look's points that must lie there
SETTLE_TIME = 0.5  # seconds given to what was let go to come to rest before looking again
HANG_TIME = 0.3  # seconds given to what was just lifted to stop swinging in the hand before looking at it
SHALLOW = 0.035  # metres: containers lower than this (plates, saucers) hold things on top, not inside
RIM = 0.02  # metres of a shallow container's edge that things should not rest on
SURFACE_STRIDE = 2  # every how many depth pixels one stands for the observed surfaces (as ground truth's do)
HANDLE_PROUD = 0.004  # metres out of its front from which a point is the handle's, not the front's
MOVED = 0.005  # metres the gripper must have moved since a look for another look to be worth it
SETTLE_INSET = 0.01  # metres: the footprint a let-go object falls within, shrunk by this; smaller drops are none
JUMP = 0.05  # metres an untouched object's find may lie from where it stood before it must show it has gone
SAME_PLACE = 0.5  # box IoU above which a find stands where another known object does: it is that one
MIN_KEPT = 30  # points a find must keep of its own for what a settled thing takes back to be taken
OPEN_DRAWER = 0.04  # metres a drawer's front must stand out of its cabinet's for it to count as open


class ObjectNotFoundError(UnknownObjectError):
    """A name the program asked about was looked for and not seen; the message says what was seen."""

    def __init__(self, name: str, known: list[str], seen: str):
        self.name, self.known = name, list(known)
        message = f"{name!r} was not found: {seen}. Known objects: {', '.join(self.known) or 'none'}"
        KeyError.__init__(self, message)


@dataclass
class SeenObject:
    """An object in the store: what one look found, moved along when the robot carried it."""

    name: str
    phrase: str
    points: np.ndarray
    normals: np.ndarray
    views: int  # in how many views it was found
    support: float  # height of the table it was seen above
    floor: float  # height of its underside (below its lowest point seen where it stands on the table)
    kind: ObjectType | None = None  # the library's idea of the phrase, for containers' interiors
    box: Box3D = field(init=False)

    def __post_init__(self) -> None:
        # Its points are depth pixels (observation's refinement, where it found enough), sharp down to the table.
        box = object_box(self.points, self.support, PIXEL_BLUR)
        self.box = Box3D(np.array([*box.lower[:2], min(box.lower[2], self.floor)]), box.upper)

    @property
    def outline(self) -> np.ndarray:
        """The points that show its outline from above."""
        return footprint_points(self.points, self.support)

    @cached_property
    def footprint(self) -> tuple[np.ndarray, float, np.ndarray]:
        """``(center_xy, yaw, half_extents_xy)`` of :attr:`outline` (:func:`footprint_of`); asked for by every
        placement's obstacles, so worked out once per object seen (a moved object is a new one)."""
        return footprint_of(self.outline)


class PipelinePerception(Perception):
    """Perception from ``backend``'s cameras through ``grounder``; ``parts`` labels furniture and its parts (what
    parts there are, which part a handle moves and how).

    ``vocabulary``: the phrases ``detect_objects()`` looks for when given none. The robot's own pixels are left out
    of what is grounded and fused: ``robot_index``, the segmentation index of the robot, tells them where the frames
    carry a segmentation that labels it; else ``self_filter`` tells them from the robot's model and its joint
    readings (:mod:`roboscript.perception.self_filter`), as a real rig does.
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
        self.backend, self.grounder, self.parts = backend, grounder, parts
        self.vocabulary = [normalize_phrase(v) for v in vocabulary]
        self.robot_index, self.settings, self.self_filter = robot_index, settings, self_filter
        self.masks: list[np.ndarray | None] = []  # the robot's pixels in each frame of the last look
        self.store: dict[str, SeenObject] = {}
        self.parts_seen: dict[str, ObjectPoints] = {}  # furniture and its parts, as last seen
        self.not_found: dict[str, str] = {}
        self.scene: np.ndarray = np.zeros((0, 3))
        self.last: Observation | None = None
        self.looks = 0  # how many times the cameras were used
        self._asked: list[str] = []  # every phrase looked for, in order
        self._carried: dict[str, Transform] = {}  # objects in the gripper, with where the gripper took them
        self._let_go: set[str] = set()  # objects let go since the last look
        self._looked = False
        self._stale = False
        self._joints: dict[str, ArticulationJoint] = {}  # estimated from the last look, by moving part
        # Per part: the support of its best joint estimate, the joint, and where its handle and front stood then.
        self._best_joint: dict[str, tuple[int, ArticulationJoint, np.ndarray, np.ndarray]] = {}
        # The middle of each door's front and its handle when the door was first seen, taken as shut: how far a door
        # stands open is how far they have turned about the hinge since (a door swung open may be seen better).
        self._door_shut: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # (front's middle, handle's centre)
        self._vacated: list[Box3D] = []  # where objects were taken from since the last look
        self._holding_looks = False
        self._look_tcp: np.ndarray | None = None  # where the gripper was at the last look
        self._part_look: dict[str, int] = {}  # the look each part in parts_seen is from
        # The labels, which do not change: phrase -> name of furniture and each of its parts, and what each handle
        # moves.
        self.furniture_phrases = {normalize_phrase(n): n for n in parts.furniture()}  # phrase -> name
        self._table_height = math.nan  # the height of the table's top, as the last look that saw it measured
        handles = [n for n in self.furniture_phrases.values() if kind_of(n) == "handle"]
        self._moved_by = {n: _labelled_part(parts, n) for n in handles}

    # --- looking ----------------------------------------------------------------------------------------------

    @timed("perceive")
    def detect(self, categories: list[str] | None = None) -> None:
        phrases = [normalize_phrase(c) for c in categories] if categories else list(self.vocabulary)
        if not phrases:
            raise ValueError("nothing to look for: pass category_list, e.g. ['apple', 'bowl']")
        self._look(phrases)

    def _look(self, asked: list[str]) -> None:
        frames = [self.backend.capture(c) for c in self.backend.camera_names()]
        masks = self._robot_masks(frames)
        # The table is measured (the level surface things stand on), not found.
        phrases = [p for p in asked if p not in self.furniture_phrases and p != TABLE]
        furniture = list(self.furniture_phrases)
        pieces = {p for p, n in self.furniture_phrases.items() if shows_in_pieces(n)}
        seen = observe(frames, self.grounder, phrases + furniture, self.settings, masks, pieces, furniture)
        self.last, self._looked, self._stale = seen, True, False
        self.masks = [masks[k] for k, f in enumerate(frames) if f.name in seen.scene.used]
        self._look_tcp = self.backend.tcp_pose().position.copy()
        self._vacated = []
        self.looks += 1
        used = [k for k, f in enumerate(frames) if f.name in seen.scene.used]  # broken depth images are not
        self.scene = surface_points([frames[k] for k in used], [masks[k] for k in used], SURFACE_STRIDE)
        self._asked += [p for p in phrases if p not in self._asked]
        self._joints.clear()
        table = table_surface(seen.scene.points, seen.scene.normals, seen.support)
        # The table is no phrase a detector is asked for: it is the plane things stand on. It does not move, so
        # the look that saw most of it (the least hidden by the arm and by objects) stands for it.
        if table is not None and (TABLE not in self.parts_seen or len(table[0]) > len(self.parts_seen[TABLE].points)):
            self.parts_seen[TABLE] = ObjectPoints(*table)
            self._part_look[TABLE] = self.looks
            self._table_height = seen.support
        for phrase, part in self.furniture_phrases.items():
            found = [i for i in seen.instances if i.label == phrase]
            if found:
                biggest = max(found, key=lambda i: len(i.points))
                self.parts_seen[part] = ObjectPoints(biggest.points, biggest.normals)
                self._part_look[part] = self.looks
        self._trim_handles()
        self._keep_parts_in_rows()
        seen_again = set()
        for phrase in phrases:
            found = [i for i in seen.instances if i.label == phrase]
            if phrase in self.vocabulary and len(found) > 1:
                # The scene's description names one thing so: the one seen best is it, the rest are mistaken.
                found = [max(found, key=lambda i: (sum(b != -1 for b in i.boxes), len(i.points)))]
            self.not_found.pop(phrase, None)
            if not found:
                if not any(o.phrase == phrase for o in self.store.values()):
                    self.not_found[phrase] = _seen_summary(seen, phrase, self.grounder.account(phrase))
                continue
            seen_again |= self._update(phrase, found, seen)
        settled = {n for n in self._let_go - seen_again if n in self.store and n not in self._carried}
        for name in settled:
            self._settle(name)
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

    def _robot_masks(self, frames: list) -> list[np.ndarray | None]:
        if self.robot_index is not None or self.self_filter is None:
            return robot_masks(frames, self.robot_index)
        return self.self_filter.masks(frames, self.backend.joint_states())

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
        base = _name(phrase)
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
                fresh = self._seen(names[k], phrase, instance, seen)
                before = self.store.get(names[k])
                if before is not None and not self._may_have_gone(before, fresh, seen):
                    continue
                if before is not None and self._held_by_another(fresh, seen):
                    missed.add(names[k])  # what was let go and not seen again settles where it was let go
                    continue
                # Seen by fewer cameras than before (the arm in the way, a detector's miss) where it stood still:
                # the earlier look saw more of it (a mug's rim from one side only has no grasp pairs).
                still = before is not None and names[k] not in self._let_go and _part_of(fresh, before)
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
        place (:func:`~roboscript.perception.free_space.stands_empty`), or sees the find better than it was seen.
        Else the detector put its name on something else (a mug's on an open drawer's front) and missed it."""
        if before.name in self._let_go or fresh.views > before.views:
            return True
        if float(np.linalg.norm(fresh.box.center - before.box.center)) < JUMP:
            return True
        return stands_empty(before.points, seen.frames, self.masks)

    def _in_hand(self, expected: SeenObject, instance: Instance3D) -> SeenObject:
        """A carried object seen in the hand: the whole of it as seen before, moved to where this look shows the
        part of it the hand leaves in view (:func:`~roboscript.perception.in_hand.register`), or where the
        gripper has taken it where that part says too little; from here on it goes with the gripper."""
        self._carried[expected.name] = self.backend.tcp_pose()
        motion = register(expected.points, instance.points)
        return expected if motion is None else _moved(expected, motion)

    def hangs_free(self, name: str) -> bool:
        """Looks at ``name`` alone in the hand once it hangs free: where it settled between the fingers (turned,
        slid down) is where it is carried and set down from. The rest of what is known stays as the last full look
        saw it (a look with the arm low over the table sees less of it). True where ``name`` moved in the hand."""
        if name not in self._carried or self._holding_looks:
            return False
        self.backend.wait(HANG_TIME)
        frames = [self.backend.capture(c) for c in self.backend.camera_names()]
        phrase = self.store[name].phrase
        seen = observe(frames, self.grounder, [phrase], self.settings, self._robot_masks(frames))
        found = [i for i in seen.instances if i.label == phrase]
        if not found:
            return False
        expected = self._expected(name)
        nearest = min(found, key=lambda i: float(np.linalg.norm(i.box.center - expected.box.center)))
        self.store[name] = self._in_hand(expected, nearest)
        return self.store[name] is not expected

    def _seen(self, name: str, phrase: str, instance: Instance3D, seen: Observation) -> SeenObject:
        views = sum(1 for b in instance.boxes if b != -1)
        floor = float(instance.box.lower[2])
        return SeenObject(
            name, phrase, instance.points, instance.normals, views, seen.support, floor, _library_type(phrase)
        )

    def _trim_handles(self) -> None:
        """Keeps of each handle the points standing out of its part's front: its 2D boxes hold some of the front
        around it, and the handle's centre decides where the gripper closes and where the joint's line runs. Only
        a handle and a front of this look: one seen earlier may have moved since."""
        for handle in [n for n in self.parts_seen if kind_of(n) == "handle" and self._part_look[n] == self.looks]:
            part = self._moved_by[handle]
            if part is None or self._part_look.get(part) != self.looks:
                continue
            points, normals = self.parts_seen[handle].points, self.parts_seen[handle].normals
            try:
                front = self.parts_seen[part]
                center, normal, _ = front_plane(front.points, points.mean(axis=0), normals=front.normals)
            except ValueError:  # the front was seen too poorly to tell
                continue
            proud = (points - center) @ normal > HANDLE_PROUD
            if proud.sum() >= 10:
                self.parts_seen[handle] = ObjectPoints(points[proud], normals[proud])

    def _keep_parts_in_rows(self) -> None:
        """Keeps of each drawer and door of this look the points within its row's height (rows placed by the
        handles seen): a part is found from its boxes in the images, and a drawer pulled out stands in front of
        the door below it there (its floor was taken for the door's top, and an arm pushing the drawer shut was
        refused on it). A drawer slides and a door swings level: neither leaves its row's height."""
        for furniture in {n.split(".", 1)[0] for n in self._moved_by}:
            if furniture not in self.parts_seen or not math.isfinite(self._table_height):
                continue
            handles = [n for n in self._moved_by if n.startswith(furniture + ".")]
            heights = {
                int(n.rsplit("_", 1)[1]): float(np.median(self.parts_seen[n].points[:, 2]))
                for n in handles
                if n in self.parts_seen and self._part_look[n] == self.looks
            }
            if not heights:
                continue
            top = float(np.nanpercentile(self.parts_seen[furniture].points[:, 2], 99))
            bands = row_bands(heights, len(handles), top, self._table_height)
            for handle in handles:
                part = self._moved_by[handle]
                if part is None or part not in self.parts_seen or self._part_look[part] != self.looks:
                    continue
                low, high = bands[int(handle.rsplit("_", 1)[1])]
                seen = self.parts_seen[part]
                inside = (seen.points[:, 2] >= low) & (seen.points[:, 2] <= high)
                if inside.sum() >= 10:
                    self.parts_seen[part] = ObjectPoints(seen.points[inside], seen.normals[inside])

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
            self.store[name] = _moved(self.store[name], gripper.compose(start.inverse()))
            self._let_go.add(name)

    def _settle(self, name: str) -> None:
        """Something let go that the last look did not find again (what it lies in hid it, or the detector took it
        for part of that) has fallen: from above, what the cameras see within its footprint is its own top, so its
        top goes to the highest surface seen there, though not below what it stands on (the lowest seen)."""
        obj = self.store[name]
        lower, upper = obj.box.lower, obj.box.upper
        xy = self.scene[:, :2]
        under = np.all((xy > lower[:2] + SETTLE_INSET) & (xy < upper[:2] - SETTLE_INSET), axis=1)
        below = self.scene[under & (self.scene[:, 2] < upper[2] + SETTLE_INSET), 2]
        if len(below) < 10:
            return
        low, high = np.percentile(below, [2, 98])
        drop = float(min(upper[2] - high, lower[2] - low))
        if drop > SETTLE_INSET:
            self.store[name] = _moved(obj, Transform(np.array([0.0, 0.0, -drop]), np.array([0.0, 0.0, 0.0, 1.0])))

    # --- the questions ----------------------------------------------------------------------------------------

    def furniture(self) -> list[str]:
        self._ensure_looked(fresh=False)
        return [n for n in self.furniture_phrases.values() if n in self.parts_seen]

    def names(self) -> list[str]:
        """In the order of the original benchmark's queries: the table, furniture, objects, furniture parts."""
        self._ensure_looked(fresh=False)
        seen = [n for n in self.furniture_phrases.values() if n in self.parts_seen]
        table = [TABLE] if TABLE in self.parts_seen else []
        return table + [n for n in seen if "." not in n] + list(self.store) + [n for n in seen if "." in n]

    def objects(self) -> list[str]:
        self._ensure_looked(fresh=False)
        return list(self.store)

    def require(self, name: object) -> str:
        if isinstance(name, str) and name not in self.names():
            phrase = normalize_phrase(name)
            if phrase in self.not_found:
                raise ObjectNotFoundError(name, self.names(), self.not_found[phrase])
            if name in self.furniture_phrases.values():
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
            return _moved(self.store[name], self.backend.tcp_pose().compose(self._carried[name].inverse()))
        return self.store[name]

    def _part(self, name: str) -> ObjectPoints:
        """The points of furniture or a part as last seen (:meth:`_object` has checked the name)."""
        return self.parts_seen[name]

    def box(self, name: str) -> Box3D:
        """Of furniture, the box of its carcass as seen (its parts have boxes of their own); of the table, the box
        of its top as seen, up to the height of the surface things stand on."""
        obj = self._object(name)
        return obj.box if obj else self._part_box(name)

    def _part_box(self, name: str) -> Box3D:
        box = fit_box(self._part(name).points)
        if name == TABLE:
            return Box3D(box.lower, np.array([*box.upper[:2], self._table_height]))
        return box

    def footprint(self, name: str) -> tuple[np.ndarray, float, np.ndarray]:
        """Of furniture and parts, their box from above (as ground truth gives it)."""
        obj = self._object(name)
        if obj is None:
            box = self._part_box(name)
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
        handle (:mod:`roboscript.perception.articulation`). Which parts move, and whether they slide or turn, is
        what their labels say (``parts``); where and along what they move is from the points."""
        if self._object(name):
            return []
        # A question about the whole cabinet is answered from the parts seen well enough: a drawer pulled out
        # hides the front of the one below it, which should not keep the program from the one it means.
        joints, missing = [], None
        for truth in self.parts.joints(name):
            try:
                joints.append(self._estimated(truth))
            except ObjectNotFoundError as exc:
                missing = missing or exc
        if missing is not None and (not joints or "." in name):
            raise missing
        return joints

    def _estimated(self, labelled: ArticulationJoint) -> ArticulationJoint:
        """The joint of ``labelled.part`` from its front and its handle as one look saw them (a drawer pulled
        since an earlier look has moved away from a handle seen then). It does not look again by itself: it is
        asked for every part near the gripper, and a look for each would cost a second apiece."""
        part = labelled.part
        if part in self._joints:
            return self._joints[part]
        front = self.parts_seen[part].points if part in self.parts_seen else None
        if front is None or len(front) < 10:
            points = 0 if front is None else len(front)
            raise ObjectNotFoundError(
                part, self.names(), f"its front was not seen well enough to estimate its joint ({points} points)"
            )
        handle = self._handle(part)
        best = self._best_joint.get(part)
        if self._part_look[handle] == self._part_look[part]:
            handle_center = self.parts_seen[handle].points.mean(axis=0)
        elif best is not None:
            # The handle hidden in the front's look (by the hand, or what it carries): a part moves as one body,
            # so its handle stands where it stood beside the front when both were last seen together.
            handle_center = front.mean(axis=0) + best[2] - best[3]
        else:
            why = (
                f"its front and its handle {handle!r} were last seen in different looks ({self._part_look[part]} and "
                f"{self._part_look[handle]}), and its joint is estimated from both as they stand together"
            )
            raise ObjectNotFoundError(part, self.names(), why)
        try:
            joint, support = estimate_joint(labelled.type, part, front, handle_center, self.parts_seen[part].normals)
        except ValueError as exc:
            if best is None:
                raise ObjectNotFoundError(part, self.names(), f"its joint could not be estimated: {exc}") from exc
            joint, support = best[1], -1
        # A joint does not move with its part: a drawer slides along one line, a door turns about one hinge. The
        # estimate from the look that saw most of the front stands (the arm at a pulled drawer's handle hides
        # most of it), moved along with the handle. A door's hinge is the one told while it was shut: swung open,
        # the door's box in the images takes in the compartment it opens on, whose walls carry its plane's edge
        # past the hinge (6 cm deep into a cabinet, the compartment's frame turned 18 degrees with it).
        if best is not None and (best[0] >= support or _swung(labelled, best, handle_center)):
            joint = moved_with_handle(best[1], best[2], handle_center)
        else:
            self._best_joint[part] = (support, joint, handle_center, front.mean(axis=0))
        if joint.type == "revolute":
            self._door_shut.setdefault(part, (front.mean(axis=0), handle_center))
        joint = self._with_opening(joint, handle_center)
        self._joints[part] = joint
        return joint

    def _with_opening(self, joint: ArticulationJoint, handle_center: np.ndarray) -> ArticulationJoint:
        """A drawer's joint with how far it is pulled out: how far its front stands before its cabinet's (0
        where the cabinet was not seen well enough to tell); a door's with how far it has swung open: how far its
        front has turned about the hinge since the door was first seen, shut."""
        if joint.type == "revolute":
            shut_front, shut_handle = self._door_shut[joint.part]
            handle = self._handle(joint.part)
            if self._part_look[handle] > self._part_look[joint.part]:
                # The handle was seen since the front (the detector missed the front swung open): it turns as one.
                angle = door_angle(joint, shut_handle, self.parts_seen[handle].points.mean(axis=0))
            else:
                angle = door_angle(joint, shut_front, self.parts_seen[joint.part].points)
            return dataclasses.replace(joint, value=max(0.0, angle))
        furniture = joint.part.split(".", 1)[0]
        if joint.type != "prismatic" or furniture not in self.parts_seen:
            return joint
        try:
            seen = self.parts_seen[furniture]
            carcass = carcass_front(seen.points, opening_frame(joint), DRAWER_TRAVEL + 0.05, seen.normals)
        except ValueError:
            return joint
        return dataclasses.replace(joint, value=float(np.clip(-carcass, joint.lower, joint.upper)))

    def _handle(self, part: str) -> str:
        """The handle the labels put on ``part`` (the one seen last); "not found" if none was seen."""
        handles = [n for n, moved in self._moved_by.items() if moved == part]
        seen = [n for n in handles if n in self.parts_seen]
        if not seen:
            why = f"its handle ({', '.join(handles) or 'none'}) was not seen, and its geometry is measured from it"
            raise ObjectNotFoundError(part, self.names(), why)
        return max(seen, key=lambda n: self._part_look[n])

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
        obj = self._object(name)
        if obj is None:
            return self._compartment(name) if kind_of(name) == "door" else self._drawer_inside(name)
        if obj.kind is None or not obj.kind.container or obj.kind.interior is None:
            return None
        return interior_of(obj.points, obj.outline, obj.kind, name)

    def _drawer_inside(self, name: str) -> Receptacle | None:
        """The free inside of a drawer, from its points, its joint, its handle and its cabinet's front; other
        furniture and parts hold nothing."""
        joints = self.parts.joints(name) if kind_of(name) == "drawer" else []
        if not joints or joints[0].type != "prismatic" or joints[0].part != name:
            return None
        self._fresh_look_inside()
        frame = opening_frame(self._estimated(joints[0]))
        furniture = name.split(".", 1)[0]
        if furniture not in self.parts_seen:
            raise ObjectNotFoundError(
                furniture,
                self.names(),
                f"no camera has seen it, and how far {name!r} stands out of it is measured from its front",
            )
        seen = self.parts_seen[furniture]
        carcass = carcass_front(seen.points, frame, DRAWER_TRAVEL + 0.05, seen.normals)
        points = self._part(name).points
        inside = drawer_receptacle(name, points, self._part(name).normals, frame, carcass)
        if inside is None and -carcass > OPEN_DRAWER:
            # Its front stands out of the carcass, so it is open, though no look showed its bottom.
            return unseen_inside(name, points, frame, carcass)
        return inside if inside is not None else closed_drawer(name, points, frame)

    def _compartment(self, name: str) -> Receptacle | None:
        """The free inside behind a door (:mod:`roboscript.perception.compartments`)."""
        joints = self.parts.joints(name)
        if not joints or joints[0].type != "revolute" or joints[0].part != name:
            return None
        self._fresh_look_inside()
        joint = self._estimated(joints[0])
        furniture = name.split(".", 1)[0]
        if furniture not in self.parts_seen:
            why = f"no camera has seen it, and {name!r} is behind its front"
            raise ObjectNotFoundError(furniture, self.names(), why)
        seen = self.parts_seen[furniture]
        try:
            return compartment_inside(
                name, joint, self._door_shut[name][0], seen.points, seen.normals, self._part(name).points
            )
        except CompartmentUnseenError as exc:
            raise ObjectNotFoundError(name, self.names(), str(exc)) from exc

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


def shows_in_pieces(name: str) -> bool:
    """Whether furniture or a part may be seen as several unconnected pieces: a drawer, a door or a carcass may (an
    open drawer's front and, apart from it, its inside); a handle is one piece."""
    return kind_of(name) != "handle"


def _labelled_part(parts: PartLabels, handle: str) -> str | None:
    """The part a handle moves, as the labels say (which handle is on which drawer)."""
    joints = parts.joints(handle)
    return joints[0].part if joints else None


def _part_of(fresh: SeenObject, before: SeenObject) -> bool:
    """Whether what ``fresh`` saw lies on what ``before`` saw (all but a few points within :data:`STILL` of its
    points): it has not moved since. A box pushed 2 cm shows a strip of its top where none was."""
    from scipy.spatial import cKDTree

    if len(fresh.points) == 0 or len(before.points) == 0:
        return False
    distance, _ = cKDTree(before.points).query(fresh.points, distance_upper_bound=STILL)
    return float(np.mean(np.isfinite(distance))) >= STILL_SHARE


def _moved(obj: SeenObject, motion: Transform) -> SeenObject:
    """``obj`` as it is after the rigid ``motion`` (world frame); its support and underside rise and fall as its
    lowest point does."""
    points = motion.apply(obj.points)
    rise = float(points[:, 2].min() - obj.points[:, 2].min()) if len(points) else float(motion.position[2])
    return SeenObject(
        obj.name,
        obj.phrase,
        points,
        obj.normals @ motion.rotation.T,
        obj.views,
        obj.support + rise,
        obj.floor + rise,
        obj.kind,
    )


def _name(phrase: str) -> str:
    return phrase.replace(" ", "_")


def _library_type(phrase: str) -> ObjectType | None:
    """The object type a phrase names (``footed bowl``, ``white plate``), or the first of a category it names."""
    types = object_types()
    key = _name(phrase)
    if key in types:
        return types[key]
    for kind in types.values():
        if normalize_phrase(kind.category) == phrase or phrase.endswith(" " + normalize_phrase(kind.category)):
            return kind
    return None


def _seen_summary(seen: Observation, phrase: str, account: str = "") -> str:
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


def interior_of(points: np.ndarray, outline: np.ndarray, kind: ObjectType, name: str) -> Receptacle:
    """The free volume of a seen container, from the lowest point seen near its middle up. Across: a shallow
    one (a plate) holds what rests on it up to its rim, so its footprint less a rim; a deep one (a bowl, a
    basket) holds things inside its walls, so its footprint shrunk as the library's type of it is (a bowl's
    opening is about 60% of its width)."""
    center, yaw, half = footprint_of(outline)
    bottom = float(points[:, 2].min())
    frame = Transform(np.array([center[0], center[1], bottom]), quat_from_yaw(yaw))
    local = frame.inverse().apply(points)
    height = float(local[:, 2].max())
    (lx, ly, lz), (ux, uy, uz) = kind.interior
    bounds_lower, bounds_upper = (np.asarray(b, dtype=float) for b in kind.bounds)
    if height < SHALLOW:
        inner_half = np.maximum(half - RIM, half * 0.5)
    else:
        type_half = (bounds_upper[:2] - bounds_lower[:2]) / 2
        inner_half = half * float(np.min(np.array([(ux - lx) / 2, (uy - ly) / 2]) / type_half))
    middle = local[np.all(np.abs(local[:, :2]) < inner_half * 0.6, axis=1)]
    floor = float(middle[:, 2].min()) if len(middle) >= 5 else lz
    top = max(height + (uz - bounds_upper[2]), floor + 0.05)
    lower, upper = np.array([-inner_half[0], -inner_half[1], floor]), np.array([*inner_half, top])
    return Receptacle(name, frame, lower, upper, kind.round_floor)


DOOR_SWUNG = 0.03  # metres a door's handle stands from where the hinge was told: the door is no longer shut


def _swung(labelled: ArticulationJoint, best: tuple, handle_center: np.ndarray) -> bool:
    """Whether a door has swung since its best estimate was made (its handle moved): a hinge is told shut only."""
    return labelled.type == "revolute" and float(np.linalg.norm(handle_center - best[2])) > DOOR_SWUNG
