"""What the tool API asks of perception: names, boxes, poses, joints, planes, object points, receptacles.

Ground truth (from the simulator) and the perception pipeline (RGB-D, grounding, fusion) answer the same
questions, so the tools and the benchmark's ablations switch between them without changing a line.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from roboscript.errors import UnknownNameError, did_you_mean
from roboscript.geometry import Box3D, Transform
from roboscript.names import TABLE
from roboscript.perception.footprints import rectangle_outline

OCCUPANCY_MARGIN = 0.02  # metres around an ignored object's box whose points are taken to be its own
# Room kept between the carcass front and where things are put into an open drawer: the panel above the drawer
# overhangs that line and fingers need space.
DRAWER_FRONT_CLEARANCE = 0.03


class UnknownObjectError(UnknownNameError):
    """No object of that name is known; the message suggests the closest known names."""

    def __init__(self, name: object, known: list[str]):

        self.name, self.known = name, list(known)
        close = did_you_mean(name, self.known, cutoff=0.4, quoted=True)
        hint = f"; {close} " if close else ". "
        message = f"no object named {name!r}{hint}Known objects: {', '.join(self.known)}"
        super().__init__(message)


class ObjectNotFoundError(UnknownObjectError):
    """A name the program asked about was looked for and not seen; the message says what was seen."""

    def __init__(self, name: str, known: list[str], seen: str):
        self.name, self.known = name, list(known)
        message = f"{name!r} was not found: {seen}. Known objects: {', '.join(self.known) or 'none'}"
        KeyError.__init__(self, message)


@dataclass(frozen=True)
class ArticulationJoint:
    """A joint of an articulated object in world coordinates; ``position`` is a point on its axis."""

    part: str  # the moving part, e.g. ``cabinet.drawer_1``
    type: str  # "prismatic" or "revolute"
    position: np.ndarray
    axis: np.ndarray  # for drawers: the opening direction; for doors: positive angles open
    value: float
    lower: float
    upper: float


@dataclass(frozen=True)
class Receptacle:
    """The free volume of a container or drawer: the box ``[lower, upper]`` in the frame ``frame``; with
    ``round_floor``, of its floor only the ellipse inscribed in the box's (a plate's, a bowl's)."""

    name: str
    frame: Transform
    lower: np.ndarray
    upper: np.ndarray
    round_floor: bool = False

    def corners(self) -> np.ndarray:
        signs = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=float)
        local = self.lower + signs * (self.upper - self.lower)
        return self.frame.apply(local)


@dataclass(frozen=True)
class ObjectPoints:
    """Surface points of one object with outward normals, in the world frame."""

    points: np.ndarray  # (N, 3)
    normals: np.ndarray  # (N, 3), unit


class Perception(ABC):
    """The object store behind the perception tools."""

    @abstractmethod
    def detect(self, categories: list[str] | None = None) -> None:
        """Looks at the scene and updates what is known (in ground truth, only what the cameras show of each
        object, for grasp detection: the rest is read from the simulator's state when asked)."""

    @abstractmethod
    def names(self) -> list[str]:
        """Every name a tool may take: the table, furniture, objects and furniture parts."""

    def require(self, name: object) -> str:
        """``name`` if it is known, else :class:`UnknownObjectError` with the closest names."""
        if not isinstance(name, str):
            raise TypeError(
                f"an object name must be a string such as {self.names()[0]!r}, got {type(name).__name__} {name!r}"
            )
        if name not in self.names():
            raise UnknownObjectError(name, self.names())
        return name

    @abstractmethod
    def box(self, name: str) -> Box3D:
        """World axis-aligned 3D box."""

    @abstractmethod
    def pose(self, name: str) -> Transform:
        """Pose of the object's frame (for objects: the centre of the bottom face)."""

    @abstractmethod
    def footprint(self, name: str) -> tuple[np.ndarray, float, np.ndarray]:
        """``(center_xy, yaw, half_extents_xy)``: the object's footprint as a rectangle turned by ``yaw``."""

    def outline(self, name: str) -> np.ndarray:
        """The object's outline from above, as far as it is known: the corners ``(K, 2)`` of a convex polygon round
        what it covers of the table, counter-clockwise, in the world. By default its footprint's rectangle."""
        return rectangle_outline(*self.footprint(name))

    @abstractmethod
    def joints(self, name: str) -> list[ArticulationJoint]:
        """Joints of an articulated object or part (a cabinet has one per drawer or door); empty if none."""

    @abstractmethod
    def plane_normal(self, name: str, position: np.ndarray) -> np.ndarray:
        """Outward normal of the object's planar face closest to ``position``."""

    @abstractmethod
    def points(self, name: str) -> ObjectPoints:
        """The object's observed surface points with normals."""

    @abstractmethod
    def scene_points(self) -> np.ndarray:
        """Every observed surface point, (N, 3): for collision checks of grasp candidates."""

    def last_frames(self) -> list:
        """The camera frames :meth:`scene_points` came from (empty if it did not come from cameras)."""
        return []

    def last_masks(self) -> list:
        """Per frame of :meth:`last_frames`, the (H, W) pixels that show the robot itself, or None where that is
        not known."""
        return [None] * len(self.last_frames())

    @abstractmethod
    def receptacle(self, name: str) -> Receptacle | None:
        """The volume where things put into ``name`` go, or ``None`` if it holds nothing (an apple)."""

    def seen_receptacle(self, name: str) -> Receptacle | None:
        """:meth:`receptacle` as already measured, without looking again first (perception that looks again
        before it measures a drawer's inside, where the arm may have hidden part of it, may then find it larger);
        by default the same."""
        return self.receptacle(name)

    @abstractmethod
    def objects(self) -> list[str]:
        """Movable objects (not the table, furniture or its parts)."""

    def furniture(self) -> list[str]:
        """Furniture and its parts: what is neither a movable object nor the table."""
        movable = set(self.objects())
        return [n for n in self.names() if n not in movable and n != TABLE]

    def occupied(self, ignore: list[str]) -> np.ndarray:
        """Observed surface points, (N, 3), without those of the objects in ``ignore`` (what the robot holds):
        space that is taken whether or not perception knows what takes it."""
        points = self.scene_points()
        for name in ignore:
            points = outside(points, self.box(name), OCCUPANCY_MARGIN)
        return points

    @contextmanager
    def without_looking(self) -> Iterator[None]:
        """Within this block, questions are answered from what is known, without looking again. The planning
        scene is rebuilt at the first motion after a let-go, while the hand still hides what it let go of: that
        look would be a poor one, and the next question about an object, asked once the hand has moved away,
        makes a better one."""
        yield

    def carried(self, name: str, gripper: Transform) -> None:  # noqa: B027 (a hook: nothing to do by default)
        """The robot took hold of ``name`` with its gripper at ``gripper``: until :meth:`released`, it goes where
        the gripper goes. Perception that keeps what it saw follows it; perception that reads the world's state
        has nothing to do."""

    def hangs_free(self, name: str) -> bool:
        """The carried ``name`` has just been lifted off its support and hangs in the hand. Perception that keeps
        what it saw may look again, for where it settled between the fingers, and says True where it moved there;
        perception that reads the world's state has nothing to do."""
        return False

    def released(self, name: str, gripper: Transform) -> None:  # noqa: B027 (a hook: nothing to do by default)
        """The robot let ``name`` go with its gripper at ``gripper``: it moved as the gripper did since
        :meth:`carried` (or, for a part such as a drawer, as the robot pulled it). Perception that keeps what it
        saw moves it along; perception that reads the world's state has nothing to do."""


def joints_if_known(perception: Perception, name: str) -> list[ArticulationJoint]:
    """The joints of ``name``, or none where perception cannot tell them (a part whose handle was not seen): a
    question about one part should not fail over another."""
    try:
        return perception.joints(name)
    except (UnknownObjectError, ValueError):
        return []


def within(points: np.ndarray, box: Box3D, margin: float = 0.0) -> np.ndarray:
    """Which of the points, (N,) bool, lie within ``box`` grown by ``margin``."""
    return np.all((points > box.lower - margin) & (points < box.upper + margin), axis=1)


def outside(points: np.ndarray, box: Box3D, margin: float = 0.0) -> np.ndarray:
    """The points not within ``box`` grown by ``margin``."""
    return points[~within(points, box, margin)]
