"""Which contacts a motion may make, and for how long: the one owner of the planning scene's allowances.

The scene refuses every contact of the arm by default. Some are part of the work: the fingers touch what they
grasp (but only on the final approach, not on the way to it); a motion starts in contact with what was just let
go, or with furniture a link ended a motion a few millimetres inside the padding of, and must be able to leave it
without pushing deeper. Each allowance is made here and withdrawn here once the arm has moved clear.

Names are the scene's: objects and furniture parts. ``family`` maps a name to everything that moves with it
(a drawer with its handle), which is allowed or withdrawn together.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Iterator
from contextlib import AbstractContextManager, contextmanager

import numpy as np

from roboscript.planning.motion import MotionPlanner


class ContactAllowances:
    """The gripper's and the links' allowed contacts in ``motion``'s planning scene (rebuilt scenes included:
    the scene is always asked of ``motion`` anew)."""

    def __init__(self, motion: MotionPlanner, family: Callable[[str], list[str]]):
        self.motion = motion
        self.family = family
        self.touched: set[str] = set()  # names the gripper may touch until it has moved clear of them
        self._links: set[tuple[str, str]] = set()  # pairs allowed to leave a contact they started in

    def allow_touch(self, names: Iterable[str]) -> None:
        """Lets the gripper touch ``names`` (and what moves with them) until it has moved clear of them."""
        scene = self.motion.scene
        for name in names:
            if name not in self.touched:
                for part in self.family(name):
                    scene.allow("gripper", part)
                self.touched.add(name)

    def not_yet_allowed(self, names: Iterable[str], held: Collection[str] = ()) -> list[str]:
        """The parts of ``names`` (families included) the gripper may not touch yet."""
        fresh = [n for n in names if n not in self.touched and n not in held]
        return sorted({part for n in fresh for part in self.family(n)})

    def touching(self, parts: list[str]) -> AbstractContextManager[None]:
        """The gripper may touch ``parts`` within the block (candidate grasps checked, an approach searched); the
        allowance is withdrawn from the scene in use at the end, which a look on the way may have rebuilt."""
        return self._within(parts, allowed=True)

    def withheld(self, parts: list[str]) -> AbstractContextManager[None]:
        """Within the block the gripper may not touch ``parts``, which it may touch now (a check of an approach
        that may touch a handle's door only at the handle); the allowance is made again at the end."""
        return self._within(parts, allowed=False)

    @contextmanager
    def _within(self, parts: list[str], allowed: bool) -> Iterator[None]:
        """``parts`` allowed (or not) to the gripper within the block, the other way again at its end, in the
        scene in use then."""
        for part in parts:
            self.motion.scene.allow("gripper", part, allowed)
        try:
            yield
        finally:
            for part in parts:
                self.motion.scene.allow("gripper", part, not allowed)

    @contextmanager
    def part_moving(self, name: str, q: np.ndarray, held: bool) -> Iterator[None]:
        """Within the block the drawer or door ``name`` moves with the hand from the arm at ``q``, where the scene
        can move it (:meth:`PlanningScene.part_following`): the fingers may touch it, as they hold its handle, but
        the links may not, for it no longer stands where it was seen (a door swung open sweeps toward the arm).
        Where the scene cannot move it, the links may touch it as while it is held (:meth:`hold_part`). ``held``:
        whether the hand holds it now (its allowances stay after the block)."""
        scene = self.motion.scene
        parts = self.family(name)
        with scene.part_following(name, q) as moving:
            for part in parts:
                scene.allow("gripper", part)
                scene.allow("arm", part, not moving)
            try:
                yield
            finally:
                for part in parts:
                    self.motion.scene.allow("gripper", part, held or name in self.touched)
                    self.motion.scene.allow("arm", part, held)

    def hold_part(self, name: str) -> None:
        """A drawer or door is held: it moves with the hand, while the scene keeps it where it was last seen, so
        the arm may touch it (and its handle) until it is let go (a wrist following a drawer pushed shut met the
        drawer's front as the scene still had it)."""
        self.allow_touch([name])
        for part in self.family(name):
            self.motion.scene.allow("arm", part)

    def released(self, name: str, is_object: bool) -> None:
        """``name`` was let go: the open fingers may back out of it, never sweep through it (an object put down
        would be knocked over; a handle would be caught)."""
        scene = self.motion.scene
        q = self.motion.sync()
        for part in self.family(name):
            if not is_object:
                scene.allow("gripper", part, False)
                scene.allow("arm", part, False)
            scene.allow_leaving("gripper", part, q)
        self.touched.add(name)

    def leave_where_started(self, known: Collection[str]) -> None:
        """Before a motion: the gripper may leave what of ``known`` it touches now (an object that settled against
        the fingers after being let go), and a link may leave the furniture it ended the last motion inside the
        padding of (tracking is not exact), but neither may push deeper in."""
        scene = self.motion.scene
        q = self.motion.sync()
        for pair in scene.collisions(q):
            for name in pair:
                if name in known and scene.touching("gripper", name, q):
                    for part in self.family(name):
                        scene.allow_leaving("gripper", part, q)
                    self.touched.add(name)
        for pair in scene.collisions(q):
            scene.allow_leaving(*pair, q)
            self._links.add(pair)

    def withdraw_cleared(self, held: Collection[str]) -> None:
        """After a motion: withdraws the allowances the arm has moved clear of (never for what it holds)."""
        scene = self.motion.scene
        q = self.motion.sync()
        for pair in list(self._links):
            if not scene.touching(*pair, q):
                scene.allow(*pair, False)
                self._links.discard(pair)
        for name in list(self.touched):
            if name in held:
                continue
            family = self.family(name)
            if not any(scene.touching("gripper", part, q) for part in family):
                for part in family:
                    scene.allow("gripper", part, False)
                self.touched.discard(name)
