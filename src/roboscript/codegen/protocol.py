"""The messages between a program's process and the tools, and their bounds.

Program to tools: ``{"ready": true}`` once set up (its time starts; it then compiles the program),
``{"confined": true}`` once confined (a set-up failure, ``{"failed": text}``, is believed only before),
``{"call": name, "args": tree, "kwargs": tree}`` for each tool call, ``{"done": {"outcome", "error", "output"}}``
at the end. Tools to program: the ``init`` message first, then for each call ``{"return": tree}``,
``{"raise": spec}`` (both with the ``"notices"`` the tool gave, :mod:`roboscript.notices`) or
``{"timeout": true}``. Trees are :mod:`roboscript.codegen.wire` values.

An exception crosses as its class's name, the builtin exception classes it derives from (what a program's
``except`` can name), whether it is the robot's failure, its message and its data attributes: the program's side
makes a class of that name from those builtins, never a class of the tools' side.
"""

from __future__ import annotations

import contextlib

from roboscript.codegen import wire
from roboscript.codegen.sandbox import shortened
from roboscript.errors import FailureError, RoboScriptError, UsageError, error_message

MAX_ARGUMENTS = 1024**2  # bytes of one tool call (a path of 1000 poses takes about 150 kB)
MAX_REPLY = 64 * 1024**2  # bytes of one tool's answer
MAX_INIT = 4 * 1024**2  # bytes of the program and its data
MAX_DONE = 64 * 1024  # bytes of the final report: the error and the output are shortened before
MAX_ERROR_ATTRIBUTES = 16 * 1024  # bytes of an exception's data attributes
MAX_REPORTED_OUTPUT = 8000  # characters of a program's printed output reported (its start and its end)
MAX_EXCEPTION_NAME = 64

# The builtin exceptions a relayed one may derive from: those a program can name, and their relatives.
RELAYABLE_BASES = (
    Exception, ArithmeticError, AssertionError, AttributeError, IndexError, KeyError, LookupError, RuntimeError,
    TypeError, ValueError, ZeroDivisionError, NotImplementedError, OSError, TimeoutError, StopIteration,
    OverflowError, FloatingPointError, RecursionError, MemoryError,
)  # fmt: skip
_RELAYABLE = {cls.__name__: cls for cls in RELAYABLE_BASES}


class ToolArgumentError(UsageError, TypeError):
    """A tool was given something that cannot be passed to it (a function, a generator, too much data)."""


def exception_spec(exc: BaseException, message_limit: int) -> dict:
    """A tool's exception as it crosses to the program."""
    cls = type(exc)
    builtins = [c for c in cls.__mro__ if c in _RELAYABLE.values()]
    most_specific = [c.__name__ for c in builtins if not any(o is not c and issubclass(o, c) for o in builtins)]
    message = error_message(exc)
    message = shortened(message, message_limit)
    attributes = {}
    for key, value in getattr(exc, "__dict__", {}).items():
        if key.isidentifier() and not key.startswith("_"):
            with contextlib.suppress(wire.WireError):
                attributes[key] = wire.to_tree(value, MAX_ERROR_ATTRIBUTES)
    return {
        "name": cls.__name__[:MAX_EXCEPTION_NAME],
        # The project's error classes it derives from, nearest first: a program's ``except PlanningError`` catches
        # an IKError (see :func:`error_family`).
        "lineage": [c.__name__ for c in cls.__mro__[1:] if issubclass(c, RoboScriptError)][:8],
        "bases": most_specific or ["RuntimeError"],
        "failure": isinstance(exc, FailureError),
        "message": message,
        "attributes": attributes,
    }


_made: dict[tuple, type] = {}
_named: dict[str, type] = {}  # the program's own error classes, by name (see program_error_classes)


def error_family(classes: dict[str, type]) -> dict:
    """How the error classes a program may name (``classes``, by name) derive from one another and from the
    builtins, for :func:`program_error_classes` to make the program's own: the nearest of them each derives from,
    the builtins it adds, whether it is the robot's failure."""
    family = {}
    for name, cls in classes.items():
        parents = [n for n, c in classes.items() if c is not cls and issubclass(cls, c)]
        parents = [p for p in parents if not any(q != p and issubclass(classes[q], classes[p]) for q in parents)]
        builtins = [c for c in cls.__mro__ if c in _RELAYABLE.values() and c is not Exception]
        builtins = [b for b in builtins if not any(issubclass(classes[p], b) for p in parents)]
        builtins = [b for b in builtins if not any(o is not b and issubclass(o, b) for o in builtins)]
        family[name] = {
            "parents": parents,
            "bases": [b.__name__ for b in builtins],
            "failure": issubclass(cls, FailureError),
        }
    return family


def program_error_classes(family: dict) -> dict[str, type]:
    """The program's own error classes from :func:`error_family`'s description, parents first; the tools' errors
    of those names are raised as these (:func:`rebuild_exception`)."""
    pending = dict(family)
    while pending:
        ready = [n for n, d in pending.items() if all(p in _named for p in d.get("parents", ()))]
        if not ready:
            break  # a parent that is not described: those left keep the builtins only
        for name in ready:
            described = pending.pop(name)
            parents = tuple(_named[p] for p in described["parents"])
            builtins = tuple(_RELAYABLE[b] for b in described.get("bases", ()) if b in _RELAYABLE)
            _named[name] = _exception_class(name, parents + builtins or (Exception,), described.get("failure") is True)
    return {name: _named[name] for name in family if name in _named}


def rebuild_exception(spec: dict) -> BaseException:
    """The exception a spec describes, as the program's side raises it: of the program's own class of that name,
    or of a class deriving from the nearest of them it derives from, or from its builtins alone."""
    name = spec.get("name")
    if not isinstance(name, str) or not name.isidentifier() or len(name) > MAX_EXCEPTION_NAME:
        name = "ToolError"
    bases = tuple(_RELAYABLE[b] for b in spec.get("bases", ()) if isinstance(b, str) and b in _RELAYABLE)
    failure = spec.get("failure") is True
    kin = [_named[n] for n in spec.get("lineage", ()) if isinstance(n, str) and n in _named]
    if name in _named:
        cls = _named[name]
    elif kin:
        cls = _exception_class(name, (kin[0],), failure)
    else:
        cls = _exception_class(name, bases or (RuntimeError,), failure)
    message = spec.get("message")
    exc = cls(message if isinstance(message, str) else "")
    attributes = spec.get("attributes")
    for key, tree in attributes.items() if isinstance(attributes, dict) else ():
        if isinstance(key, str) and key.isidentifier() and not key.startswith("_"):
            with contextlib.suppress(wire.WireError, AttributeError, TypeError):
                setattr(exc, key, wire.from_tree(tree))
    return exc


def _exception_class(name: str, bases: tuple[type, ...], failure: bool) -> type:
    key = (name, bases, failure)
    if key not in _made:
        body = {"robot_failure": failure, "__module__": "tools", "__str__": _message_of}
        try:
            _made[key] = type(name, bases, body)
        except TypeError:  # builtins whose layouts do not combine: the first one stands for them
            _made[key] = type(name, bases[:1], body)
    return _made[key]


def _message_of(exc: BaseException) -> str:
    return str(exc.args[0]) if exc.args else ""
