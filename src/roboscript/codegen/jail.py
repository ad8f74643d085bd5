"""A program's process: ``main([ROOT, FD, PARENT])`` in ``python -I``, started by the tools' side.

It starts from nothing of the caller's (a fresh interpreter, an environment without credentials, no descriptors
but its socket), reads the program and its limits, imports and warms what the program may use, confines itself
(:mod:`roboscript.codegen.confinement`) and only then runs the program, whose tool calls go over the socket as
data (:mod:`roboscript.codegen.protocol`). It reports how the program ended and exits; what it reports is a claim
the tools' side checks, never the task's result.
"""

from __future__ import annotations

import contextlib
import io
import linecache
import os
import signal
import sys
import traceback
import warnings

import numpy as np

from roboscript.api.pose import Point, Pose, Quaternion
from roboscript.codegen import channel, confinement, protocol, wire
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import (
    MAX_ERROR,
    ExecutionResult,
    Limits,
    ProgramTimeout,
    _timer,
    impose_limits,
    prepare,
    program_scope,
    program_timer,
    run_code,
    shortened,
)
from roboscript.notices import notice_line


def main(argv: list[str]) -> None:
    fd, parent = int(argv[1]), int(argv[2])
    code = 1
    try:
        try:
            init = channel.receive(fd, protocol.MAX_INIT)
            run = _Run(fd, init)
        except Exception as exc:
            channel.send(fd, {"failed": shortened(f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}", MAX_ERROR)})
            return
        run.start(parent)
        code = 0
    finally:
        os._exit(code)  # no clean-up that might need a system call the confinement forbids


class _Run:
    """One program, set up and run."""

    def __init__(self, fd: int, init: dict):
        self.fd = fd
        self.limits = Limits(**init["limits"])
        self.confine = init["confine"] is True
        self.probe = init.get("probe")  # a test's (setup, act): code run unguarded, before and once confined
        self.probe_scope: dict = {"__builtins__": __builtins__, "channel_fd": fd}
        if self.probe is not None:
            exec(self.probe[0], self.probe_scope)
        self.output = io.StringIO()
        stand_ins = {name: _stand_in(name, fd, self.output) for name in init["tools"]}
        data = wire.from_tree(init["data"])
        errors = protocol.program_error_classes(init.get("errors", {}))
        namespace = {**data, **errors, "Pose": Pose, "Point": Point, "Quaternion": Quaternion, **stand_ins}
        self.program = init["program"]
        self.scope = program_scope(namespace, self.output)
        _quiet_runtime(self.output)
        _warm_up()

    def start(self, parent: int) -> None:
        channel.send(self.fd, {"ready": True})  # the program's time starts: compiling it counts (it can be slow)
        code = prepare(self.program)
        if isinstance(code, ExecutionResult):
            self._report(code.outcome, code.error)  # the guard or the parser refused it
            return
        try:
            impose_limits(self.limits)
            if self.confine:
                confinement.confine(parent)
        except Exception as exc:  # not the program's doing: the tools' side raises it as a set-up error
            channel.send(self.fd, {"failed": f"{type(exc).__name__}: {exc}"})
            return
        channel.send(self.fd, {"confined": True})  # from here on, it may be the program that speaks
        if self.probe is not None:  # shows what the confinement stops
            try:
                exec(self.probe[1], self.probe_scope)
            except Exception as exc:
                self._report(Outcome.RUNTIME_ERROR, f"probe: {type(exc).__name__}: {exc}")
                return
        with program_timer(self.limits):
            outcome, error = run_code(code, self.scope, self.limits)
        self._report(outcome, error)

    def _report(self, outcome: Outcome, error: str | None) -> None:
        output = shortened(self.output.getvalue(), protocol.MAX_REPORTED_OUTPUT)
        error = None if error is None else shortened(error, MAX_ERROR)
        with _timer_held():
            channel.send(self.fd, {"done": {"outcome": outcome.value, "error": error, "output": output}})


def _stand_in(name: str, fd: int, output: io.StringIO):
    """The program's ``name``: sends the call to the tools as data and returns (or raises) what they answer; what
    the tool noticed on the program's behalf goes into the program's output."""

    def call(*args, **kwargs):
        odd = [key for key in kwargs if not key.isidentifier()]
        if odd:
            raise protocol.ToolArgumentError(f"{name}() takes keyword arguments by their names, not {odd[0][:40]!r}")
        try:
            arguments = wire.to_tree(list(args), protocol.MAX_ARGUMENTS)
            keywords = {key: wire.to_tree(value, protocol.MAX_ARGUMENTS) for key, value in kwargs.items()}
            data = channel.json_bytes({"call": name, "args": arguments, "kwargs": keywords})
        except wire.TooMuchData:
            data = None
        except wire.WireError as exc:
            raise protocol.ToolArgumentError(f"{name}() can only be given data ({wire.WHAT_MAY_PASS}): {exc}") from None
        if data is None or len(data) > protocol.MAX_ARGUMENTS:
            raise protocol.ToolArgumentError(
                f"{name}() was given more than {protocol.MAX_ARGUMENTS} bytes of arguments; at most "
                f"{protocol.MAX_ARGUMENTS} (pass names and a few numbers, not bulk data)"
            )
        with _timer_held():
            channel.send_raw(fd, data)
            reply = channel.receive(fd, protocol.MAX_REPLY)
        for text in reply.get("notices", ()):
            output.write(notice_line(text))
        if "return" in reply:
            return wire.from_tree(reply["return"])
        if "timeout" in reply:
            _timer.expired = True
            raise ProgramTimeout
        raise protocol.rebuild_exception(reply["raise"])

    call.__name__ = call.__qualname__ = name
    return call


@contextlib.contextmanager
def _timer_held():
    """Holds the timer signal back (it is delivered when released), so it cannot cut a message in half."""
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGALRM})


def _quiet_runtime(output: io.StringIO) -> None:
    """Nothing the interpreter does on its own may reach for a file once confined: warnings go to the program's
    output without their source line, and no source line is ever read."""

    def show(message, category, filename, lineno, file=None, line=None):
        output.write(f"{category.__name__}: {message}\n")

    warnings.showwarning = show
    linecache.updatecache = lambda *args, **kwargs: []
    linecache.checkcache = lambda *args, **kwargs: None


def _warm_up() -> None:
    """Runs once what loads numpy's lazy parts, so that no import is left for the program to trigger."""
    rng = np.random.default_rng(0)
    rng.uniform(size=3), rng.normal(size=3), rng.integers(0, 3), rng.choice([1, 2])
    np.random.seed(0)
    np.random.uniform(), np.random.normal(), np.random.rand(2), np.random.randn(2), np.random.randint(0, 3)
    matrix = np.eye(3) + 0.1
    np.linalg.inv(matrix), np.linalg.pinv(matrix), np.linalg.det(matrix), np.linalg.eig(matrix)
    np.linalg.svd(matrix), np.linalg.solve(matrix, np.ones(3)), np.linalg.lstsq(matrix, np.ones(3), rcond=None)
    values = np.array([3.0, 1.0, 2.0])
    np.percentile(values, 50), np.median(values), np.unique(values), np.interp(0.5, [0, 1], [0, 1])
    np.sort(values), np.argsort(values), np.std(values), np.var(values), np.cross(values, values)
    repr(values), str(values), repr(np.float64(1.5)), str(np.eye(2, dtype=int)), f"{np.float64(2.5):.2f}"
    repr(Pose())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        np.mean(np.array([])), np.array([1.0]) / 0


if __name__ == "__main__":
    main(sys.argv)
