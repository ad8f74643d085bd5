"""What the gripper holds: one list, and one event to everything that must follow it.

A program says what it holds with ``attach_object`` and ``detach_object``. Three parts act on it: the planning
scene carries a held object with the hand, perception moves what it saw of the object as the hand moves, and the
contact allowances let the fingers touch what they hold (a drawer with its handle). Each keeps the data its own
job needs (an attachment's body and grip, the gripper pose an object was taken at), but none decides what is held:
:class:`Held` does, and tells them when something is taken (in the order they are given) or let go (in the
reverse order: perception moves what was let go before the planning scene is rebuilt from it).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Protocol

import numpy as np

from roboscript.api.arguments import ArgumentError
from roboscript.geometry import Transform

if TYPE_CHECKING:
    from roboscript.perception.base import Perception
    from roboscript.planning.contacts import ContactAllowances
    from roboscript.planning.motion import MotionPlanner


class HoldFollower(Protocol):
    """A part that acts when the gripper takes or lets go of something."""

    def taken(self, name: str, is_object: bool, gripper: Transform) -> None:
        """``name`` is held from now on (``is_object``: a free object, not a drawer, door or handle), taken with
        the gripper at ``gripper``."""

    def let_go(self, name: str, is_object: bool, gripper: Transform) -> None:
        """``name`` was let go with the gripper at ``gripper``."""


class Held:
    """The names the gripper holds, in the order taken; the followers hear of every change."""

    def __init__(self, followers: Sequence[HoldFollower] = ()):
        self._names: list[str] = []
        self._objects: dict[str, bool] = {}
        self._taken_from: dict[str, np.ndarray] = {}  # where the hand took each (x, y of the TCP)
        self.followers = list(followers)

    @property
    def names(self) -> list[str]:
        return list(self._names)

    @property
    def objects(self) -> list[str]:
        """The held names that are free objects (not a drawer, door or handle)."""
        return [name for name in self._names if self._objects[name]]

    def __contains__(self, name: object) -> bool:
        return name in self._names

    def __iter__(self) -> Iterator[str]:
        return iter(list(self._names))

    def __len__(self) -> int:
        return len(self._names)

    def __bool__(self) -> bool:
        return bool(self._names)

    def require(self, name: str, tool: str) -> None:
        """Raises :class:`ArgumentError` naming what the hand holds unless it holds ``name`` (``tool`` needs it)."""
        if name not in self:
            raise ArgumentError(
                f"{tool} needs {name!r} in the gripper (it holds {', '.join(self.names) or 'nothing'}): "
                f"grasp it, close_gripper() and attach_object({name!r}) first"
            )

    def taken_from(self, name: str) -> np.ndarray | None:
        """Where (x, y) the hand took ``name``, while it holds it; None for what it does not hold."""
        where = self._taken_from.get(name)
        return None if where is None else where.copy()

    def take(self, name: str, is_object: bool, gripper: Transform) -> None:
        """Holds ``name`` and tells the followers; nothing happens if it is held already."""
        if name in self._names:
            return
        self._names.append(name)
        self._objects[name] = is_object
        self._taken_from[name] = np.array(gripper.position[:2], dtype=float)
        for follower in self.followers:
            follower.taken(name, is_object, gripper)

    def let_go(self, name: str, gripper: Transform) -> None:
        """Lets go of ``name`` and tells the followers; a name not held is a usage error that names what is."""
        if name not in self._names:
            raise ValueError(f"{name!r} is not attached; attached: {', '.join(self._names) or 'nothing'}")
        self._names.remove(name)
        is_object = self._objects.pop(name)
        self._taken_from.pop(name, None)
        for follower in reversed(self.followers):
            follower.let_go(name, is_object, gripper)


class PlanningFollower:
    """The planning side: the fingers may touch what they hold (a drawer with its handle); a held object is
    carried by the planning scene, and left behind in it when let go."""

    def __init__(self, motion: MotionPlanner, contacts: ContactAllowances):
        self.motion = motion
        self.contacts = contacts
        self._part_taken_at: dict[str, Transform] = {}  # the gripper's pose where it took hold of each part

    def taken(self, name: str, is_object: bool, gripper: Transform) -> None:
        if is_object:
            self.contacts.allow_touch([name])
            self.motion.attach(name)
        else:  # a drawer or door with its handle: it moves on its joint, with the hand
            self.contacts.hold_part(name)
            self._part_taken_at[name] = gripper

    def let_go(self, name: str, is_object: bool, gripper: Transform) -> None:
        if is_object:
            self.motion.detach(name)
        self.contacts.released(name, is_object)
        if is_object:
            self.motion.world_changed()
            return
        # A part let go has moved with the hand (pulled, pushed, swung), its handle with it.
        start = self._part_taken_at.pop(name, gripper)
        self.motion.world_changed({part: (start.position, gripper.position) for part in self.contacts.family(name)})


class PerceptionFollower:
    """The perception side: what was seen of a held object goes with the gripper (:meth:`Perception.carried`)."""

    def __init__(self, perception: Perception):
        self.perception = perception

    def taken(self, name: str, is_object: bool, gripper: Transform) -> None:
        if is_object:
            self.perception.carried(name, gripper)

    def let_go(self, name: str, is_object: bool, gripper: Transform) -> None:
        self.perception.released(name, gripper)
