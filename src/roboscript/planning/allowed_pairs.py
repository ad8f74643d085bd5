"""The contacts a planning scene lets happen, body by body: pairs always allowed (the fingers and what they grasp),
and pairs that may be left but not deepened (a contact a motion starts in), each with the least distance allowed.
What is allowed when, and for how long, is decided above (:mod:`roboscript.planning.contacts`)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np

LEAVING_TOLERANCE = 0.002  # metres a contact being left may go deeper than it started (or than touching)


class AllowedPairs:
    """The allowances among ``nbody`` bodies."""

    def __init__(self, nbody: int):
        self.allowed = np.zeros((nbody, nbody), dtype=bool)
        # Contacts that may be left but not deepened: body pair -> the least distance allowed (the start's).
        self.leaving: dict[tuple[int, int], float] = {}

    def allow(self, first: Iterable[int], second: Iterable[int], allowed: bool = True) -> None:
        """Allows (or forbids again) every contact between a body of ``first`` and one of ``second``; forbidding
        also ends an allowance to leave."""
        first, second = list(first), list(second)
        for i in first:
            for j in second:
                self.allowed[i, j] = self.allowed[j, i] = allowed
                if not allowed:
                    self.leaving.pop((i, j), None)
                    self.leaving.pop((j, i), None)

    def leave(self, first: Sequence[int], second: Sequence[int], floors: dict[tuple[int, int], float]) -> None:
        """Lets each pair of a body of ``first`` and one of ``second`` be left, never deeper than ``floors`` has it
        (pairs in contact, in either order, with their least distance; 0 for pairs not in contact)."""
        pairs = {(i, j): 0.0 for i in first for j in second}
        for (x, y), floor in floors.items():
            pair = (x, y) if (x, y) in pairs else (y, x)
            if pair in pairs:
                pairs[pair] = min(pairs[pair], floor)
        # Measured anew each time: a contact left shallower than it was may not be pushed back in.
        for (i, j), floor in pairs.items():
            self.leaving[(i, j)] = self.leaving[(j, i)] = floor

    def leave_all(self, floors: dict[tuple[int, int], float]) -> None:
        """Lets every pair of ``floors`` not allowed outright be left (as :meth:`leave`), where it was not yet."""
        saved = set(self.leaving)
        for (a, b), floor in floors.items():
            if not self.allowed[a, b] and (a, b) not in saved:
                floor = min(self.leaving.get((a, b), 0.0), floor)  # the pair may come in both orders
                self.leaving[(a, b)] = self.leaving[(b, a)] = floor

    def permits(self, a: int, b: int, distance: float) -> bool:
        """Whether a contact of bodies ``a`` and ``b`` at ``distance`` is allowed, outright or as one being left."""
        if self.allowed[a, b]:
            return True
        floor = self.leaving.get((a, b))
        return floor is not None and distance >= floor - LEAVING_TOLERANCE

    def leaving_only(self, bodies: np.ndarray, distances: np.ndarray) -> bool:
        """Whether every contact of ``bodies`` (pairs) at ``distances`` is one being left, no deeper than where the
        motion started."""
        for (a, b), distance in zip(bodies, distances, strict=True):
            floor = self.leaving.get((int(a), int(b)))
            if floor is None or distance < floor - LEAVING_TOLERANCE:
                return False
        return True

    def release(self, body: int) -> None:
        """Ends every allowance of ``body`` (an object let go)."""
        self.allowed[body, :] = self.allowed[:, body] = False
        self.leaving = {pair: floor for pair, floor in self.leaving.items() if body not in pair}

    def allowed_names(self, labels: Sequence[str]) -> set[tuple[str, str]]:
        """The allowed pairs as names (``labels``, by body), to carry them into a rebuilt scene."""
        return {(labels[a], labels[b]) for a, b in zip(*np.nonzero(np.triu(self.allowed)), strict=True)}

    def leaving_names(self, labels: Sequence[str]) -> set[tuple[str, str]]:
        """The pairs allowed to be left as names, to carry them into a rebuilt scene."""
        return {(labels[a], labels[b]) for a, b in self.leaving if a < b}
