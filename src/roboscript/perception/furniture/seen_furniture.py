"""Furniture, its parts and the table as the looks saw them, and what is measured from their points: boxes, the
joints of the parts that move (from each one's front and its handle, :mod:`~.articulation`), a drawer's free inside
(:mod:`~.drawers`) and the compartment behind a door (:mod:`~.compartments`).

What parts there are, and which part each handle moves and how (slides, turns), are their labels (the furniture's
description); where and along what they move is from the points. A part no camera has seen yet is "not found".
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from roboscript.geometry import Box3D
from roboscript.names import kind_of
from roboscript.perception.base import TABLE, ArticulationJoint, ObjectNotFoundError, ObjectPoints, Receptacle
from roboscript.perception.detection.furniture_parts import row_bands
from roboscript.perception.detection.grounding import normalize_phrase
from roboscript.perception.detection.labels import PartLabels
from roboscript.perception.furniture.articulation import (
    DRAWER_TRAVEL,
    estimate_joint,
    front_plane,
    moved_with_handle,
)
from roboscript.perception.furniture.compartments import CompartmentUnseenError, compartment_inside, door_angle
from roboscript.perception.furniture.drawers import (
    carcass_front,
    closed_drawer,
    drawer_receptacle,
    opening_frame,
    unseen_inside,
)
from roboscript.perception.reconstruction.instances import fit_box, table_surface
from roboscript.perception.reconstruction.observation import Observation

HANDLE_PROUD = 0.004  # metres out of its front from which a point is the handle's, not the front's
OPEN_DRAWER = 0.04  # metres a drawer's front must stand out of its cabinet's for it to count as open
DOOR_SWUNG = 0.03  # metres a door's handle stands from where the hinge was told: the door is no longer shut


class SeenFurniture:
    """The furniture ``parts`` labels, as seen. ``known`` gives the names the store knows, for what a "not found"
    says."""

    def __init__(self, parts: PartLabels, known: Callable[[], list[str]]):
        self.labels, self._known = parts, known
        self.phrases = {normalize_phrase(n): n for n in parts.furniture()}  # phrase -> name
        self.seen: dict[str, ObjectPoints] = {}  # furniture and its parts, as last seen
        self.look_of: dict[str, int] = {}  # the look each of them is from
        self.table_height = math.nan  # the height of the table's top, as the last look that saw it measured
        handles = [n for n in self.phrases.values() if kind_of(n) == "handle"]
        self._moved_by = {n: _labelled_part(parts, n) for n in handles}
        self._joints: dict[str, ArticulationJoint] = {}  # estimated from the last look, by moving part
        # Per part: the support of its best joint estimate, the joint, and where its handle and front stood then.
        self._best_joint: dict[str, tuple[int, ArticulationJoint, np.ndarray, np.ndarray]] = {}
        # The middle of each door's front and its handle when the door was first seen, taken as shut: how far a door
        # stands open is how far they have turned about the hinge since (a door swung open may be seen better).
        self._door_shut: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # (front's middle, handle's centre)

    def record(self, seen: Observation, look: int) -> None:
        """Takes in what look number ``look`` saw of the table, the furniture and its parts."""
        self._joints.clear()
        table = table_surface(seen.scene.points, seen.scene.normals, seen.support)
        # The table is no phrase a detector is asked for: it is the plane things stand on. It does not move, so
        # the look that saw most of it (the least hidden by the arm and by objects) stands for it.
        if table is not None and (TABLE not in self.seen or len(table[0]) > len(self.seen[TABLE].points)):
            self.seen[TABLE] = ObjectPoints(*table)
            self.look_of[TABLE] = look
            self.table_height = seen.support
        for phrase, part in self.phrases.items():
            found = [i for i in seen.instances if i.label == phrase]
            if found:
                biggest = max(found, key=lambda i: len(i.points))
                self.seen[part] = ObjectPoints(biggest.points, biggest.normals)
                self.look_of[part] = look
        self._trim_handles(look)
        self._keep_parts_in_rows(look)

    def names(self) -> list[str]:
        """The furniture and parts seen so far, in the labels' order."""
        return [n for n in self.phrases.values() if n in self.seen]

    def box(self, name: str) -> Box3D:
        """The box of what was seen of ``name``; of the table, of its top, up to the surface things stand on."""
        box = fit_box(self.seen[name].points)
        if name == TABLE:
            return Box3D(box.lower, np.array([*box.upper[:2], self.table_height]))
        return box

    def _trim_handles(self, look: int) -> None:
        """Keeps of each handle the points standing out of its part's front: its 2D boxes hold some of the front
        around it, and the handle's centre decides where the gripper closes and where the joint's line runs. Only
        a handle and a front of this look: one seen earlier may have moved since."""
        for handle in [n for n in self.seen if kind_of(n) == "handle" and self.look_of[n] == look]:
            part = self._moved_by[handle]
            if part is None or self.look_of.get(part) != look:
                continue
            points, normals = self.seen[handle].points, self.seen[handle].normals
            try:
                front = self.seen[part]
                center, normal, _ = front_plane(front.points, points.mean(axis=0), normals=front.normals)
            except ValueError:  # the front was seen too poorly to tell
                continue
            proud = (points - center) @ normal > HANDLE_PROUD
            if proud.sum() >= 10:
                self.seen[handle] = ObjectPoints(points[proud], normals[proud])

    def _keep_parts_in_rows(self, look: int) -> None:
        """Keeps of each drawer and door of this look the points within its row's height (rows placed by the
        handles seen): a part is found from its boxes in the images, and a drawer pulled out stands in front of
        the door below it there (its floor was taken for the door's top, and an arm pushing the drawer shut was
        refused on it). A drawer slides and a door swings level: neither leaves its row's height."""
        for furniture in {n.split(".", 1)[0] for n in self._moved_by}:
            if furniture not in self.seen or not math.isfinite(self.table_height):
                continue
            handles = [n for n in self._moved_by if n.startswith(furniture + ".")]
            heights = {
                int(n.rsplit("_", 1)[1]): float(np.median(self.seen[n].points[:, 2]))
                for n in handles
                if n in self.seen and self.look_of[n] == look
            }
            if not heights:
                continue
            top = float(np.nanpercentile(self.seen[furniture].points[:, 2], 99))
            bands = row_bands(heights, len(handles), top, self.table_height)
            for handle in handles:
                part = self._moved_by[handle]
                if part is None or part not in self.seen or self.look_of[part] != look:
                    continue
                low, high = bands[int(handle.rsplit("_", 1)[1])]
                seen = self.seen[part]
                inside = (seen.points[:, 2] >= low) & (seen.points[:, 2] <= high)
                if inside.sum() >= 10:
                    self.seen[part] = ObjectPoints(seen.points[inside], seen.normals[inside])

    # --- joints -----------------------------------------------------------------------------------------------

    def joints(self, name: str) -> list[ArticulationJoint]:
        """The joints of furniture or a part, estimated from the points of each moving part's front and its
        handle. A question about the whole cabinet is answered from the parts seen well enough: a drawer pulled
        out hides the front of the one below it, which should not keep the program from the one it means."""
        joints, missing = [], None
        for truth in self.labels.joints(name):
            try:
                joints.append(self.estimated(truth))
            except ObjectNotFoundError as exc:
                missing = missing or exc
        if missing is not None and (not joints or "." in name):
            raise missing
        return joints

    def estimated(self, labelled: ArticulationJoint) -> ArticulationJoint:
        """The joint of ``labelled.part`` from its front and its handle as one look saw them (a drawer pulled
        since an earlier look has moved away from a handle seen then). It does not look again by itself: it is
        asked for every part near the gripper, and a look for each would cost a second apiece."""
        part = labelled.part
        if part in self._joints:
            return self._joints[part]
        front = self.seen[part].points if part in self.seen else None
        if front is None or len(front) < 10:
            points = 0 if front is None else len(front)
            raise ObjectNotFoundError(
                part, self._known(), f"its front was not seen well enough to estimate its joint ({points} points)"
            )
        handle = self._handle(part)
        best = self._best_joint.get(part)
        if self.look_of[handle] == self.look_of[part]:
            handle_center = self.seen[handle].points.mean(axis=0)
        elif best is not None:
            # The handle hidden in the front's look (by the hand, or what it carries): a part moves as one body,
            # so its handle stands where it stood beside the front when both were last seen together.
            handle_center = front.mean(axis=0) + best[2] - best[3]
        else:
            why = (
                f"its front and its handle {handle!r} were last seen in different looks ({self.look_of[part]} and "
                f"{self.look_of[handle]}), and its joint is estimated from both as they stand together"
            )
            raise ObjectNotFoundError(part, self._known(), why)
        try:
            joint, support = estimate_joint(labelled.type, part, front, handle_center, self.seen[part].normals)
        except ValueError as exc:
            if best is None:
                raise ObjectNotFoundError(part, self._known(), f"its joint could not be estimated: {exc}") from exc
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
            if self.look_of[handle] > self.look_of[joint.part]:
                # The handle was seen since the front (the detector missed the front swung open): it turns as one.
                angle = door_angle(joint, shut_handle, self.seen[handle].points.mean(axis=0))
            else:
                angle = door_angle(joint, shut_front, self.seen[joint.part].points)
            return dataclasses.replace(joint, value=max(0.0, angle))
        furniture = joint.part.split(".", 1)[0]
        if joint.type != "prismatic" or furniture not in self.seen:
            return joint
        try:
            seen = self.seen[furniture]
            carcass = carcass_front(seen.points, opening_frame(joint), DRAWER_TRAVEL + 0.05, seen.normals)
        except ValueError:
            return joint
        return dataclasses.replace(joint, value=float(np.clip(-carcass, joint.lower, joint.upper)))

    def _handle(self, part: str) -> str:
        """The handle the labels put on ``part`` (the one seen last); "not found" if none was seen."""
        handles = [n for n, moved in self._moved_by.items() if moved == part]
        seen = [n for n in handles if n in self.seen]
        if not seen:
            why = f"its handle ({', '.join(handles) or 'none'}) was not seen, and its geometry is measured from it"
            raise ObjectNotFoundError(part, self._known(), why)
        return max(seen, key=lambda n: self.look_of[n])

    # --- insides ----------------------------------------------------------------------------------------------

    def opening(self, name: str) -> ArticulationJoint | None:
        """The labelled joint of the drawer or door ``name`` whose inside can be measured, or None for furniture
        and parts that hold nothing."""
        joints = self.labels.joints(name) if kind_of(name) in ("drawer", "door") else []
        wanted = "revolute" if kind_of(name) == "door" else "prismatic"
        if not joints or joints[0].type != wanted or joints[0].part != name:
            return None
        return joints[0]

    def inside(self, labelled: ArticulationJoint) -> Receptacle:
        """The free inside of the drawer or behind the door that ``labelled`` (from :meth:`opening`) moves."""
        if labelled.type == "revolute":
            return self._compartment(labelled)
        return self._drawer_inside(labelled)

    def _drawer_inside(self, labelled: ArticulationJoint) -> Receptacle:
        """The free inside of a drawer, from its points, its joint, its handle and its cabinet's front."""
        name = labelled.part
        frame = opening_frame(self.estimated(labelled))
        furniture = name.split(".", 1)[0]
        if furniture not in self.seen:
            raise ObjectNotFoundError(
                furniture,
                self._known(),
                f"no camera has seen it, and how far {name!r} stands out of it is measured from its front",
            )
        seen = self.seen[furniture]
        carcass = carcass_front(seen.points, frame, DRAWER_TRAVEL + 0.05, seen.normals)
        points = self.seen[name].points
        inside = drawer_receptacle(name, points, self.seen[name].normals, frame, carcass)
        if inside is None and -carcass > OPEN_DRAWER:
            # Its front stands out of the carcass, so it is open, though no look showed its bottom.
            return unseen_inside(name, points, frame, carcass)
        return inside if inside is not None else closed_drawer(name, points, frame)

    def _compartment(self, labelled: ArticulationJoint) -> Receptacle:
        """The free inside behind a door (:mod:`~.compartments`)."""
        name = labelled.part
        joint = self.estimated(labelled)
        furniture = name.split(".", 1)[0]
        if furniture not in self.seen:
            why = f"no camera has seen it, and {name!r} is behind its front"
            raise ObjectNotFoundError(furniture, self._known(), why)
        seen = self.seen[furniture]
        try:
            return compartment_inside(
                name, joint, self._door_shut[name][0], seen.points, seen.normals, self.seen[name].points
            )
        except CompartmentUnseenError as exc:
            raise ObjectNotFoundError(name, self._known(), str(exc)) from exc


def shows_in_pieces(name: str) -> bool:
    """Whether furniture or a part may be seen as several unconnected pieces: a drawer, a door or a carcass may (an
    open drawer's front and, apart from it, its inside); a handle is one piece."""
    return kind_of(name) != "handle"


def _labelled_part(parts: PartLabels, handle: str) -> str | None:
    """The part a handle moves, as the labels say (which handle is on which drawer)."""
    joints = parts.joints(handle)
    return joints[0].part if joints else None


def _swung(labelled: ArticulationJoint, best: tuple, handle_center: np.ndarray) -> bool:
    """Whether a door has swung since its best estimate was made (its handle moved): a hinge is told shut only."""
    return labelled.type == "revolute" and float(np.linalg.norm(handle_center - best[2])) > DOOR_SWUNG
