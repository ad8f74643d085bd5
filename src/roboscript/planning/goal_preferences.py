"""Configurations chosen for poses ahead of the motions to them: a place pose chosen because the hand can leave it
from one configuration, a handle's grasp on the branch that can swing its door. A motion to such a pose ends there,
where the IK nearest its start would otherwise decide; a narrow place may also have a straight way in."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from roboscript.geometry import Transform

KEPT = 8  # poses remembered at once (the latest)


class GoalPreferences:
    """The configurations preferred for poses, and the straight ways out of them."""

    def __init__(self) -> None:
        self._preferred: list[tuple[Transform, np.ndarray]] = []
        self._ways_out: list[tuple[Transform, np.ndarray]] = []

    def prefer(self, pose: Transform, q: np.ndarray, way_out: np.ndarray | None = None) -> None:
        """Makes ``q`` the goal of the next motion to ``pose``. ``way_out``: the TCP's straight way out of a narrow
        place (a compartment behind a door), as a displacement."""
        self._preferred = [*self._preferred[1 - KEPT :], (pose, np.asarray(q, dtype=float).copy())]
        self._ways_out = [(known, out) for known, out in self._ways_out[1 - KEPT :] if not same_pose(known, pose)]
        if way_out is not None:
            self._ways_out.append((pose, np.asarray(way_out, dtype=float).copy()))

    def preferred_for(
        self, pose: Transform, is_valid: Callable[[np.ndarray], bool], consume: bool = False
    ) -> np.ndarray | None:
        """The configuration preferred for ``pose``, if one was chosen and is still valid (``is_valid``); with
        ``consume`` it is forgotten (a motion has gone there)."""
        for k in range(len(self._preferred) - 1, -1, -1):
            known, q = self._preferred[k]
            if same_pose(known, pose):
                if consume:
                    del self._preferred[k]
                return q if is_valid(q) else None
        return None

    def way_out(self, pose: Transform) -> np.ndarray | None:
        """The straight way out registered with ``pose``, if any."""
        return next((out for known, out in reversed(self._ways_out) if same_pose(known, pose)), None)

    def seeds(self) -> list[np.ndarray]:
        """Every preferred configuration: seeds for the IK of poses near theirs."""
        return [q for _, q in self._preferred]

    def clear(self) -> None:
        """Forgets everything (chosen for placing what the gripper held, which it has let go)."""
        self._preferred.clear()
        self._ways_out.clear()


def same_pose(a: Transform, b: Transform) -> bool:
    """Whether two poses are one (a pose handed back by a program)."""
    same_place = float(np.linalg.norm(a.position - b.position)) < 1e-4
    return same_place and abs(float(np.dot(a.quaternion, b.quaternion))) > 1 - 1e-8
