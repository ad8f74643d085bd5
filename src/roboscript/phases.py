"""Where a process's wall time goes: exclusive time per phase (building, rendering, grasp search, IK, planning,
physics...).

Code marks its costly parts with :func:`phase`; time is charged to the innermost phase open, so the phases of a
trial add up to no more than its wall time and what no phase claims is "the rest". A trial reads
:func:`totals` before and after and keeps the difference (:class:`PhaseClock`). Marking costs a microsecond or two (a
marked call inside the same phase costs next to nothing), so only calls that take a good part of a millisecond or
more are marked, or those made mostly from within their own phase.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

F = TypeVar("F", bound=Callable)

# The phases, in the order they are reported; anything else is a programming error.
# "scene": the planning scene built from what perception saw; "program": waiting while the program's own process
# runs its code between tool calls (its start included).
PHASES = ("build", "llm", "program", "render", "perceive", "scene", "grasp", "place", "ik", "planning", "physics")

_totals: dict[str, float] = dict.fromkeys(PHASES, 0.0)
_open: list[list] = []  # [name, when it last resumed] of each phase open, innermost last


@contextmanager
def phase(name: str) -> Iterator[None]:
    """Charges the time spent inside to ``name`` (one of :data:`PHASES`), less the phases opened within."""
    if name not in _totals:
        raise ValueError(f"unknown phase {name!r}; phases: {', '.join(PHASES)}")
    _enter(name)
    try:
        yield
    finally:
        _leave()


def _enter(name: str) -> None:
    now = time.perf_counter()
    if _open:
        outer = _open[-1]
        _totals[outer[0]] += now - outer[1]
    _open.append([name, now])


def _leave() -> None:
    now = time.perf_counter()
    inner = _open.pop()
    _totals[inner[0]] += now - inner[1]
    if _open:
        _open[-1][1] = now


def totals() -> dict[str, float]:
    """Seconds charged to each phase so far in this process (phases still open count up to now)."""
    out = dict(_totals)
    if _open:
        name, resumed = _open[-1]
        out[name] += time.perf_counter() - resumed
    return out


class PhaseClock:
    """Times one stretch of work: wall time and each phase's share of it, from :meth:`start` to :meth:`read`."""

    def __init__(self) -> None:
        self._wall = time.perf_counter()
        self._start = totals()

    def read(self) -> dict[str, float]:
        """Seconds per phase since the clock started, ``rest`` (what no phase claimed) and ``wall``, rounded."""
        now = totals()
        wall = time.perf_counter() - self._wall
        spent = {name: now[name] - self._start[name] for name in PHASES}
        out = {name: round(value, 4) for name, value in spent.items()}
        out["rest"] = round(max(0.0, wall - sum(spent.values())), 4)
        out["wall"] = round(wall, 4)
        return out


def timed(name: str) -> Callable[[F], F]:
    """Decorates a function so that its calls are charged to phase ``name`` (see :func:`phase`)."""
    if name not in _totals:
        raise ValueError(f"unknown phase {name!r}; phases: {', '.join(PHASES)}")

    def decorate(function: F) -> F:
        @functools.wraps(function)
        def charged(*args, **kwargs):
            if _open and _open[-1][0] == name:
                # Already charging to this phase (a collision check inside a plan): nothing to account, and
                # such calls come by the ten thousand.
                return function(*args, **kwargs)
            _enter(name)
            try:
                return function(*args, **kwargs)
            finally:
                _leave()

        return charged  # type: ignore[return-value]

    return decorate
