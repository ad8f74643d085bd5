"""Things costly to make, kept for a process: at most a given number, the least recently used given up first."""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

V = TypeVar("V")


class Kept(Generic[V]):
    """At most ``size`` values by key; ``give_up`` (if given) is called on each value dropped."""

    def __init__(self, size: int, give_up: Callable[[V], None] | None = None):
        if size < 1:
            raise ValueError(f"a store keeps at least one value, got size {size}")
        self.size, self._give_up = size, give_up
        self._values: OrderedDict[Hashable, V] = OrderedDict()

    def get(self, key: Hashable, make: Callable[[], V]) -> V:
        """The value kept for ``key``, made with ``make`` (and kept) the first time."""
        if key in self._values:
            self._values.move_to_end(key)
            return self._values[key]
        value = self._values[key] = make()
        while len(self._values) > self.size:
            self._drop(self._values.popitem(last=False)[1])
        return value

    def clear(self) -> None:
        """Gives up every value."""
        while self._values:
            self._drop(self._values.popitem(last=False)[1])

    def __len__(self) -> int:
        return len(self._values)

    def _drop(self, value: V) -> None:
        if self._give_up is not None:
            self._give_up(value)
