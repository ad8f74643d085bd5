"""The roots of every error RoboScript raises on purpose.

Two branches say whose move it is:

- :class:`FailureError`: the input was valid but the robot could not do it (no path, no grasp, no free spot, an
  arm blocked on its way). A benchmark counts these as the robot's failures; a program may catch them and try
  another way.
- :class:`UsageError`: the input was wrong (an unknown name, a malformed world or task file, a bad argument). The
  message says what was wrong and what would be valid.

What lies outside both (a language model that does not answer, a detector that cannot load, a backend that
breaks) derives from :class:`RoboScriptError` directly. Each class also keeps the builtin base its callers have
always caught (``RuntimeError``, ``ValueError``, ``KeyError``, ``TypeError``), so ``except ValueError`` goes on
working.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class RoboScriptError(Exception):
    """Anything RoboScript raises on purpose."""


class FailureError(RoboScriptError):
    """A valid request the robot could not carry out: planning, grasping, placing, tracking."""


class UsageError(RoboScriptError):
    """An invalid request: the message names what was wrong and what would be valid."""


class InvalidArgumentError(UsageError, ValueError):
    """A value given to a command, a run or a call that cannot be used (too few trials, a bad mode, a missing
    file); the message says what was given and what would be valid."""


def error_message(exc: BaseException) -> str:
    """The message of ``exc`` as a person should read it (a ``KeyError`` shows its text without quotes)."""
    if isinstance(exc, KeyError) and exc.args:
        return str(exc.args[0])
    return str(exc)


MAX_SUGGESTED = 64  # characters: longer words and choices are not compared (difflib's work grows as their product)
MAX_CHOICES = 2000  # choices compared at most


def did_you_mean(word: object, choices: Iterable[str], n: int = 3, cutoff: float = 0.5, quoted: bool = False) -> str:
    """``"did you mean a, b?"`` naming the ``n`` choices closest to ``word``, or ``""`` where none is close: the one
    way every error that refuses a name suggests what was meant."""
    word = str(word)
    if len(word) > MAX_SUGGESTED:  # no name that long was meant as another: comparing it would be quadratic work
        return ""
    candidates = [c for c in choices if len(c) <= MAX_SUGGESTED][:MAX_CHOICES]
    close = difflib.get_close_matches(word, candidates, n=n, cutoff=cutoff)
    if not close:
        return ""
    return f"did you mean {', '.join(repr(c) if quoted else c for c in close)}?"


def unknown_name(
    what: str, name: object, choices: Iterable[str], listing: str | None = None, n: int = 3, cutoff: float = 0.5
) -> str:
    """The one message that refuses a name: ``unknown <what> <name>; did you mean <closest>? <listing>``, the
    listing being every valid choice unless ``listing`` says otherwise (how to list them where they are many)."""
    choices = list(choices)
    close = did_you_mean(name, choices, n=n, cutoff=cutoff)
    listing = f"valid: {', '.join(choices) or 'none'}" if listing is None else listing
    return f"unknown {what} {name!r}; " + (f"{close} " if close else "") + listing


class UnknownNameError(UsageError, KeyError):
    """A name that names nothing of its kind (a world, a suite, a study, an object type); the message
    (:func:`unknown_name`) suggests the closest and says what is valid."""

    def __str__(self) -> str:  # KeyError would print the message in quotes
        return str(self.args[0])


class MissingExtraError(UsageError, RuntimeError):
    """An optional part (a ``pyproject`` extra) that a request needs is not installed; the message names the extra
    and the command that installs it (:func:`roboscript.extras.install_hint`)."""
