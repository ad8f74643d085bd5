"""What the gripper may touch: the object it goes to grasp and, for a drawer or door, the whole part with its
handle; what lies near a point (the goal of a motion); contacts a motion starts in."""

from __future__ import annotations

import numpy as np

from roboscript.api.held import Held
from roboscript.names import is_part
from roboscript.perception.base import Perception, joints_if_known
from roboscript.planning.contacts import ContactAllowances

NEAR = 0.02  # metres: what lies this near a motion's goal may be touched there


def grasp_family(perception: Perception, name: str) -> list[str]:
    """What a grasp of ``name`` may touch: an object itself; a part with its handle and the part the handle is
    on (``cabinet.drawer_1`` <-> ``cabinet.handle_1``)."""
    if name in perception.objects():
        return [name]
    family = {name}
    for joint in perception.joints(name):
        family.add(joint.part)
    prefix = name.rpartition(".")[0]
    if is_part(name):
        for other in perception.names():
            if other.startswith(prefix + ".") and any(j.part in family for j in joints_if_known(perception, other)):
                family.add(other)
    return sorted(family)


class Touching:
    """Contact allowances for the tools' motions, from what perception knows lies where."""

    def __init__(self, perception: Perception, contacts: ContactAllowances, held: Held):
        self.perception, self.contacts, self.held = perception, contacts, held

    def near(self, point: np.ndarray, distance: float = NEAR) -> list[str]:
        """Objects and furniture whose box is within ``distance`` of ``point`` (never the table, which everything
        low is near)."""
        out = []
        for name in [*self.perception.objects(), *self.perception.furniture()]:
            box = self.perception.box(name)
            gap = np.maximum(np.maximum(box.lower - point, point - box.upper), 0.0)
            if float(np.linalg.norm(gap)) < distance:
                out.append(name)
        return out

    def allow_near(self, point: np.ndarray) -> None:
        """Lets the fingers touch what lies at the goal (the object to be grasped); withdrawn once clear of it.
        Not while holding something: then the goal is a place pose, and the fingers must keep clear of the
        receptacle."""
        if not self.held:
            self.contacts.allow_touch(self.near(point))

    def new_near(self, point: np.ndarray) -> list[str]:
        """Parts near ``point`` the gripper may not touch yet (for a temporary allowance)."""
        return [] if self.held else self.contacts.not_yet_allowed(self.near(point))

    def leave_where_started(self) -> None:
        """Before a motion: contacts it starts in may be left, not pushed into (:class:`ContactAllowances`)."""
        self.contacts.leave_where_started(set(self.perception.names()))
