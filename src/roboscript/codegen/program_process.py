"""A program runs in a confined process of its own; its tool calls are served by the process that holds the backend.

The program's process is a fresh interpreter (:mod:`roboscript.codegen.jail`) with an environment that holds no
credentials and no descriptor but its socket; it confines itself with seccomp before the program starts
(:mod:`roboscript.codegen.confinement`). Tool calls arrive as data (:mod:`roboscript.codegen.protocol`), checked
and bounded before anything here acts on them; nothing from the program is unpickled or evaluated in this process.
What the program's process reports is only a claim about how the program ended: a deadline this side saw pass is
a time-out whatever it claims, a broken protocol or a forbidden system call is a sandbox violation, and the task's
checks are judged by the caller from the world, after the program's process has ended.

This side bounds its own time too: a tool still running at the program's limit is stopped by this process's timer
signal; one stuck in native code, where no signal reaches, is ended by the trial's watchdog in its parent
(``announce`` tells it when the program's run must be over, see :mod:`roboscript.bench.workers`).
"""

from __future__ import annotations

import contextlib
import dataclasses
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Collection
from pathlib import Path

from roboscript import notices
from roboscript.codegen import channel, confinement, protocol, wire
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import MAX_ERROR, ExecutionResult, Limits, shortened
from roboscript.errors import RoboScriptError
from roboscript.phases import phase

EXIT_GRACE = 5.0  # seconds past the time limit before a program's process that does not report is killed
STARTUP_LIMIT = 60.0  # seconds a program's process may take to start and confine itself (stretched by load)
MAX_TOOL_ERROR = 2000  # characters of a tool's error message sent to the program
JAIL_NAMES = frozenset(("np", "Pose", "Point", "Quaternion"))  # made in the program's process itself
# What the program's process is told of its surroundings: nothing the user's environment holds (API keys), only
# what makes it start quickly and alone (one BLAS thread: it may not start threads once confined).
JAIL_ENVIRONMENT = {
    "PATH": "/usr/bin:/bin",
    "LANG": "C.UTF-8",
    "HOME": "/nonexistent",
    "OPENBLAS_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
    "MUJOCO_GL": "disabled",  # roboscript's import looks for a GL library unless told; the program needs none
}
REPORTABLE = frozenset(
    (Outcome.OK, Outcome.RUNTIME_ERROR, Outcome.PLANNING_FAILURE, Outcome.TIMEOUT, Outcome.SYNTAX,
     Outcome.FORBIDDEN_CONSTRUCT)
)  # fmt: skip


# The program's process: isolated mode (no user site, no PYTHON* variables, no current directory on the path), with
# the folders this process imports from put first, by name: this roboscript's own folder, then the caller's sys.path.
# Its dependencies (numpy, pyseccomp) are found wherever the caller found them: site-packages, a PYTHONPATH, a ROS
# workspace's overlay, a `pip install --target` folder.
BOOTSTRAP = (
    "import os, sys; sys.path[:0] = sys.argv[1].split(os.pathsep); "
    "from roboscript.codegen.jail import main; main(sys.argv[1:])"
)
PACKAGE_ROOT = str(Path(__file__).resolve().parents[2])


def import_path() -> str:
    """The folders (and zip files) the program's process imports from, joined by ``os.pathsep``: this roboscript's
    folder, then every absolute entry of this process's ``sys.path`` that exists."""
    entries = [PACKAGE_ROOT]
    for entry in sys.path:
        usable = entry and os.path.isabs(entry) and os.pathsep not in entry and os.path.exists(entry)
        if usable and entry not in entries:
            entries.append(entry)
    return os.pathsep.join(entries)


class SandboxSetupError(RoboScriptError, RuntimeError):
    """The program's process could not be started or set up (not the program's fault)."""


def run_program(
    program: str,
    namespace: dict,
    limits: Limits | None = None,
    forwarded: Collection[str] = (),
    announce: Callable[[float | None], None] | None = None,
    probe: tuple[str, str] | None = None,
) -> ExecutionResult:
    """Runs ``program`` (guarded, within ``limits``) in a confined process where each name in ``forwarded`` is a
    stand-in that calls ``namespace[name]`` here; every other name of ``namespace`` must be data.

    ``announce(t)`` is told the ``time.monotonic()`` by which the program's run will be over, once it starts, and
    ``None`` when it is over. ``probe``: for tests, code run unguarded in the program's process, its first part
    before the process is confined, its second once it is.
    """
    limits = limits or Limits()
    missing = [name for name in forwarded if not callable(namespace.get(name))]
    if missing:
        raise ValueError(f"forwarded names must be callables in the namespace; not: {', '.join(missing)}")
    confine = not confinement.unconfined_by_choice()
    if confine:
        confinement.require()
    init = {
        "program": program,
        "limits": dataclasses.asdict(limits),
        "tools": list(forwarded),
        "data": _data(namespace, forwarded),
        "errors": protocol.error_family(_errors(namespace)),
        "confine": confine,
        "probe": probe,
    }  # fmt: skip
    here, there = socket.socketpair()
    with here, there:
        # Each end's blocking mode set here: a default socket timeout (set by ROS, say) makes new sockets non-blocking.
        os.set_blocking(there.fileno(), True)
        os.set_blocking(here.fileno(), False)
        process = _start(there)
        there.close()
        side = _ToolSide(process, namespace, limits, forwarded, here.fileno(), announce)
        try:
            channel.send_raw(here.fileno(), channel.json_bytes(init), deadline=time.monotonic() + STARTUP_LIMIT)
            return side.serve()
        except (BrokenPipeError, channel.ChannelTimeout):
            return side.died(None)
        finally:
            side.end()


def _errors(namespace: dict) -> dict[str, type]:
    """The exception classes of ``namespace``: the program's process makes its own of those names."""
    return {k: v for k, v in namespace.items() if isinstance(v, type) and issubclass(v, BaseException)}


def _data(namespace: dict, forwarded: Collection[str]) -> object:
    skipped = {*forwarded, *JAIL_NAMES, *_errors(namespace)}
    data = {k: v for k, v in namespace.items() if k not in skipped}
    try:
        return wire.to_tree(data, protocol.MAX_INIT)
    except wire.WireError as exc:
        raise ValueError(f"a program's namespace holds tools (forwarded) and data only: {exc}") from None


def _start(there: socket.socket) -> subprocess.Popen:
    environment = dict(JAIL_ENVIRONMENT)
    if confinement.unconfined_by_choice():
        environment[confinement.UNCONFINED_VARIABLE] = "1"
    command = [sys.executable, "-I", "-c", BOOTSTRAP, import_path(), str(there.fileno()), str(os.getpid())]
    try:
        return subprocess.Popen(
            command,
            pass_fds=(there.fileno(),),
            env=environment,
            cwd="/",
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
    except OSError as exc:
        raise SandboxSetupError(f"cannot start a program's process: {exc}") from exc


FAILURE_PREFIX = 120  # characters of a failure's "Name: message" that must match one a tool raised


class _ToolSide:
    """Serves the program's tool calls until it reports, dies, breaks the protocol or runs out of time."""

    def __init__(self, process, namespace, limits, forwarded, fd, announce):
        self.process, self.namespace, self.limits, self.fd = process, namespace, limits, fd
        self.forwarded = frozenset(forwarded)
        self.announce = announce or (lambda deadline: None)
        self.started: float | None = None
        self.confined = False  # what arrives after that may be the program's doing
        self.ran_in = f"process {process.pid}"
        # The robot's failures the tools raised here, as the program sees them ("GraspError: no grasp fits..."):
        # only such an error ends a program as a failure of the robot's, whatever the program's side says (it can
        # raise GraspError itself for its own bug, or mark any class a failure: it is the program's process).
        self.failures: set[str] = set()

    @property
    def deadline(self) -> float:
        """When the program's time is up (its limit from when it started)."""
        return (self.started or time.monotonic()) + self.limits.timeout

    def serve(self) -> ExecutionResult:
        from roboscript.load import load_factor

        startup = time.monotonic() + STARTUP_LIMIT * load_factor()
        while True:
            cutoff = self.deadline + EXIT_GRACE if self.started is not None else startup
            try:
                with phase("program"):  # the program's own process at work (or starting) between tool calls
                    message = channel.receive(self.fd, protocol.MAX_ARGUMENTS + 4096, deadline=cutoff)
            except channel.ChannelTimeout:
                return self._kill_for_time() if self.started is not None else self._setup_failed("no answer")
            except (channel.ChannelClosed, ConnectionError):
                return self.died(None)
            except channel.ChannelError as exc:
                return self._violation(f"it broke the tool protocol: {exc}")
            if self.started is None and message.get("ready") is True:
                self.started = time.monotonic()
                self.announce(self.deadline + EXIT_GRACE)
                continue
            if message.get("confined") is True and not self.confined:
                self.confined = True
                continue
            if "failed" in message and not self.confined:  # its process could not set itself up
                return self._setup_failed(str(message["failed"])[:4000])
            if "done" in message:
                return self._finish(message["done"])
            if "call" in message and self.started is not None:
                reply = self._call(message)
                if reply is None:
                    return self._violation("it broke the tool protocol: a call that its own side could not have made")
                try:
                    channel.send_raw(self.fd, reply, deadline=self.deadline + EXIT_GRACE)
                except channel.ChannelTimeout:
                    return self._kill_for_time()
                except OSError:
                    return self.died(None)
                continue
            return self._violation(f"it broke the tool protocol: an unexpected message ({sorted(message)[:5]})")

    def _call(self, message: dict) -> bytes | None:
        name = message.get("call")
        if not isinstance(name, str) or name not in self.forwarded or set(message) != {"call", "args", "kwargs"}:
            return None
        if not isinstance(message["args"], list) or not isinstance(message["kwargs"], dict):
            return None
        try:
            args = wire.from_tree(message["args"])
            kwargs = {key: wire.from_tree(tree) for key, tree in message["kwargs"].items()}
        except Exception:  # anything its own encoder would not have made
            return None
        if not isinstance(args, list) or not all(isinstance(key, str) and key.isidentifier() for key in kwargs):
            return None
        left = self.deadline - time.monotonic()
        if left <= 0:
            return channel.json_bytes({"timeout": True})
        with notices.collected() as noticed:
            try:
                with _time_limit(left):
                    value = self.namespace[name](*args, **kwargs)
            except _ToolTimeout:
                return channel.json_bytes({"timeout": True})
            except Exception as exc:
                spec = protocol.exception_spec(exc, MAX_TOOL_ERROR)
                if spec["failure"]:
                    self.failures.add(f"{spec['name']}: {spec['message']}"[:FAILURE_PREFIX])
                return channel.json_bytes({"raise": spec, "notices": noticed})
        try:
            return channel.json_bytes({"return": wire.to_tree(value, protocol.MAX_REPLY), "notices": noticed})
        except wire.WireError as exc:
            error = RuntimeError(f"{name}() returned what cannot be sent to the program: {exc}")
            return channel.json_bytes({"raise": protocol.exception_spec(error, MAX_TOOL_ERROR), "notices": noticed})

    def _finish(self, done: object) -> ExecutionResult:
        if not isinstance(done, dict):
            return self._violation("it broke the tool protocol: a report that is not one")
        try:
            outcome = Outcome(done.get("outcome"))
        except ValueError:
            outcome = None
        error, output = done.get("error"), done.get("output", "")
        if outcome not in REPORTABLE or not (error is None or isinstance(error, str)) or not isinstance(output, str):
            return self._violation("it broke the tool protocol: a report that is not one")
        output = shortened(_printable(output), protocol.MAX_REPORTED_OUTPUT)
        error = None if error is None else shortened(_printable(error), MAX_ERROR)
        if outcome is Outcome.TIMEOUT or (self.started is not None and time.monotonic() > self.deadline):
            outcome, error = Outcome.TIMEOUT, self._timeout_error("")
        elif outcome is Outcome.PLANNING_FAILURE and not any((error or "").startswith(f) for f in self.failures):
            outcome = Outcome.RUNTIME_ERROR  # no tool failed so: the program's own error
        return self._result(outcome, error, output)

    def _kill_for_time(self) -> ExecutionResult:
        self._kill()
        return self._result(Outcome.TIMEOUT, self._timeout_error(" (its process killed)"), "")

    def _timeout_error(self, how: str) -> str:
        return f"TimeoutError: the program ran longer than its {self.limits.describe()}{how}"

    def died(self, cause: BaseException | None) -> ExecutionResult:
        """The result when the program's process ended without a report."""
        status = self._wait(1.0)
        if status is not None and status < 0 and -status == signal.SIGSYS:
            return self._violation("it made a system call the sandbox forbids (files, processes, network, signals)")
        if status is not None and status < 0 and -status == signal.SIGXCPU:
            error = self._timeout_error(" and its CPU-time margin (its process killed)")
            return self._result(Outcome.TIMEOUT, error, "")
        if self.started is not None and time.monotonic() > self.deadline:
            return self._result(Outcome.TIMEOUT, self._timeout_error(" (its process died)"), "")
        how = f"killed by signal {-status}" if status is not None and status < 0 else f"exit status {status}"
        return self._result(Outcome.RUNTIME_ERROR, f"the program's process died ({how}) without a report", "")

    def _violation(self, what: str) -> ExecutionResult:
        self._kill()
        error = f"SandboxViolation: the program's process was stopped: {what}"
        return self._result(Outcome.SANDBOX_VIOLATION, error, "")

    def _setup_failed(self, why: str) -> ExecutionResult:
        self._kill()
        raise SandboxSetupError(f"the program's process could not be set up: {why}")

    def _result(self, outcome: Outcome, error: str | None, output: str) -> ExecutionResult:
        return ExecutionResult(outcome, error, output, ran_in=self.ran_in)

    def _kill(self) -> None:
        with contextlib.suppress(ProcessLookupError):
            self.process.kill()

    def _wait(self, seconds: float) -> int | None:
        try:
            return self.process.wait(seconds)
        except subprocess.TimeoutExpired:
            self._kill()
            return self.process.wait()

    def end(self) -> None:
        """Makes sure the program's process is gone, and tells the watchdog that the run is over."""
        if self.process.poll() is None:
            self._wait(1.0)
        self.announce(None)


def _printable(text: str) -> str:
    """``text`` as UTF-8 can carry it: a program's lone surrogates (``chr(0xD800)``) would break every writer."""
    return text.encode("utf-8", "backslashreplace").decode("utf-8")


class _ToolTimeout(BaseException):
    """The program's time ran out while a tool was running for it."""


@contextlib.contextmanager
def _time_limit(seconds: float):
    """Raises :class:`_ToolTimeout` in the tool after ``seconds`` (only in the main thread, where signals go)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def expire(signum, frame):
        raise _ToolTimeout

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, max(seconds, 1e-3))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
