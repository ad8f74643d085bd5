"""The log of a run on a robot driven without ROS (libfranka through franky): a JSON-lines file, a line an event, on
one clock (``t``: seconds since the log began), written and flushed as the run goes, so that a run cut short leaves
all it did.

Events (``kind``): ``run`` (the run's description: robot configuration, scene, perception, the program), ``tool_call``
(a tool, its arguments and its answer or error), ``trajectory`` and ``gripper`` (each command sent, as
:class:`~roboscript.backends.logged.LoggedBackend` reports it, joint names included), ``state`` (where the arm was
before the first command and after each), ``error`` (a command that raised), ``note`` (e.g. the twin's run) and
``outcome`` (how the run ended). :func:`read_json_log` decodes it to a :class:`~roboscript.run_record.RunRecord` for
``roboscript replay``. A ROS run writes a rosbag instead (:mod:`roboscript.ros.run_log`); both take tool calls from
:func:`logged_namespace`.
"""

from __future__ import annotations

import json
import logging
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Protocol

import numpy as np

from roboscript.robot_config import RobotConfig, load_robot_config
from roboscript.run_record import Command, RunRecord
from roboscript.trajectory import JointTrajectory

_log = logging.getLogger(__name__)


class RunLog(Protocol):
    """What a run on a robot tells its log, whatever the log's format."""

    def run(self, description: dict) -> None: ...
    def note(self, topic: str, data: dict) -> None: ...
    def tool_call(self, name: str, args: tuple, kwargs: dict, answer: object = None, error: str | None = None): ...
    def outcome(self, outcome: dict) -> None: ...
    def close(self) -> None: ...


class JsonRunLog:
    """Writes a run's events to the JSON-lines file at ``path`` (replacing one that is there) until :meth:`close`."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file = self.path.open("w")
        self._lock = threading.Lock()
        self._start = time.monotonic()
        self.counts: dict[str, int] = {}

    def write(self, kind: str, event: dict) -> None:
        """Appends one event of ``kind`` (its other fields: ``event``), stamped with the log's clock."""
        line = to_json({"t": round(time.monotonic() - self._start, 4), "kind": kind, **event})
        with self._lock:
            if self._file.closed:
                return
            self._file.write(line + "\n")
            self._file.flush()
            self.counts[kind] = self.counts.get(kind, 0) + 1

    def backend_event(self, entry: dict) -> None:
        """A :class:`~roboscript.backends.logged.LoggedBackend` listener: its commands and states, as they come."""
        self.write(entry["kind"], {k: v for k, v in entry.items() if k != "kind"})

    def run(self, description: dict) -> None:
        self.write("run", {"run": description})

    def note(self, topic: str, data: dict) -> None:
        self.write("note", {"topic": topic, "data": data})

    def tool_call(self, name: str, args: tuple, kwargs: dict, answer: object = None, error: str | None = None) -> None:
        call = {"tool": name, "args": list(args), "kwargs": kwargs}
        self.write("tool_call", {**call, "error": error} if error is not None else {**call, "answer": answer})

    def outcome(self, outcome: dict) -> None:
        self.write("outcome", {"outcome": outcome})

    def close(self) -> None:
        with self._lock:
            self._file.close()

    def __enter__(self) -> JsonRunLog:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def logged_namespace(namespace: dict, log: RunLog) -> dict:
    """``namespace`` with each tool wrapped so that its calls and answers go into ``log``."""

    def keep(*call, **outcome) -> None:
        # the log serves the run, not the other way round: a log that cannot take a call (a full disk) is warned
        # of, and the program goes on with what the tool did
        try:
            log.tool_call(*call, **outcome)
        except Exception as exc:
            _log.warning("the run's log did not take a call of %s: %s", call[0], exc)

    def logged(name: str, tool: Callable) -> Callable:
        def call(*args, **kwargs):
            try:
                answer = tool(*args, **kwargs)
            except BaseException as exc:
                keep(name, args, kwargs, error=f"{type(exc).__name__}: {exc}")
                raise
            keep(name, args, kwargs, answer=answer)
            return answer

        call.__name__ = getattr(tool, "__name__", name)
        call.__doc__ = getattr(tool, "__doc__", None)
        call.__wrapped__ = tool
        return call

    return {k: logged(k, v) if callable(v) and not isinstance(v, type) else v for k, v in namespace.items()}


def read_json_log(path: str | Path, config: RobotConfig | str | Path | None = None) -> RunRecord:
    """The run logged at ``path`` by :class:`JsonRunLog`; ``config`` overrides the robot configuration it names.
    A last line cut short (the run was killed while writing it) is left out; any other bad line is an error."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"no run log at {path}")
    events = _events(path)
    runs = [e["run"] for e in events if e["kind"] == "run"]
    if not runs:
        raise ValueError(f"{path} has no 'run' event: it is not a RoboScript run's log")
    reference = config if config is not None else runs[0]["robot_config"]
    config = reference if isinstance(reference, RobotConfig) else load_robot_config(reference)
    order = list(config.robot.arm_joints)
    commands = [_command(e, order) for e in events if e["kind"] in ("trajectory", "gripper")]
    states = [e for e in events if e["kind"] == "state"]  # none where the run ended before it reached the arm
    outcomes = [e["outcome"] for e in events if e["kind"] == "outcome"]
    return RunRecord(
        path,
        runs[0],
        config,
        commands,
        np.array([e["t"] for e in states], dtype=float),
        np.array([np.asarray(e["positions"])[_columns(e, order)] for e in states]).reshape(len(states), len(order)),
        [{k: v for k, v in e.items() if k not in ("t", "kind")} for e in events if e["kind"] == "tool_call"],
        outcomes[-1] if outcomes else None,
    )


def _events(path: Path) -> list[dict]:
    lines = path.read_text().splitlines()
    events = []
    for number, line in enumerate(lines, 1):
        try:
            event = json.loads(line)
        except json.JSONDecodeError as exc:
            if number == len(lines):
                break
            raise ValueError(f"{path}:{number}: not a JSON event ({exc.msg})") from None
        if not isinstance(event, dict) or "kind" not in event or "t" not in event:
            raise ValueError(f"{path}:{number}: an event is a JSON object with 't' and 'kind', got {line[:80]!r}")
        events.append(event)
    return _in_written_order(events)


def _in_written_order(events: list[dict]) -> list[dict]:
    """``events`` with the stamps of those written within one tick of the log's clock (0.1 ms) told apart in the
    order they were written, by a nanosecond each. The state after a command and the next command sent, on a fast
    machine, share a stamp; a replay pairing each command with the last state before the next one took the state
    before the command instead (a twin "0.3 rad off" a robot that went where it was sent)."""
    tick, same = None, 0
    for event in events:
        same = same + 1 if event["t"] == tick else 0
        tick = event["t"]
        if same:
            event["t"] = tick + same * 1e-9
    return events


def _columns(event: dict, order: list[str]) -> list[int]:
    """Where the event's columns of the arm's joints are, in the model's order."""
    names = event["joint_names"]
    missing = [n for n in order if n not in names]
    if missing:
        raise ValueError(f"the {event['kind']} at t={event['t']} s names no joint {', '.join(missing)} of the arm")
    return [names.index(n) for n in order]


def _command(event: dict, order: list[str]) -> Command:
    if event["kind"] == "gripper":
        return Command(event["t"], "gripper", closed=float(event["closed"]))
    columns = _columns(event, order)
    positions, velocities = np.array(event["positions"]), np.array(event["velocities"])
    return Command(
        event["t"],
        "trajectory",
        JointTrajectory(np.array(event["times"]), positions[:, columns], velocities[:, columns]),
    )


def to_json(data: dict) -> str:
    """``data`` as a run's log writes it: numpy arrays and numbers as JSON's, keys as strings, anything else as its
    ``repr``."""
    return json.dumps(_string_keys(data), default=_jsonable)


def _string_keys(value: object) -> object:
    """``value`` with every mapping's keys as strings (JSON's; a tool's answer may be keyed by numbers)."""
    if isinstance(value, dict):
        return {k if isinstance(k, str) else str(_jsonable(k)): _string_keys(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_string_keys(v) for v in value]
    return value


def _jsonable(value: object) -> object:
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return repr(value)
