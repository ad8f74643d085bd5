"""A program runs in a process of its own; its tool calls are forwarded to the process that holds the backend.

The program's process is forked from the caller, so it starts with the same modules, but it acts on the world only
through the tools: each call is sent over a pipe, run by the caller, and its result (or exception) sent back.
Whatever the program does to its own process (exhausts its memory, trips the CPU-time limit, corrupts its
interpreter) stays there: the caller survives, with the world as the tools left it, and can still judge it. This
is fault isolation; what keeps a program from reaching outside is the guard (:mod:`roboscript.codegen.guard`).

The protocol is strictly call and reply. The program's timer signal is held while a call is under way, so a
message is never cut in half; the caller enforces the time limit on the tool itself (the same timer signal, in
its own process) and the program stops as soon as the reply arrives.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import signal
import sys
import threading
import time
from collections.abc import Callable, Collection
from multiprocessing import Pipe
from multiprocessing.connection import Connection

from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult, Limits, ProgramTimeout, execute
from roboscript.errors import UsageError
from roboscript.processes import die_with_parent

EXIT_GRACE = 10.0  # seconds past the time limit before a program's process that does not report is killed
MAX_MESSAGE = 64 * 1024**2  # bytes of one tool call's arguments or one reply
MAX_REPORTED_OUTPUT = 8000  # characters of printed output sent back (its start and its end)


class ToolArgumentError(UsageError, TypeError):
    """A tool was given something that cannot be passed to it (a function, a generator, too much data)."""


def run_program(
    program: str, namespace: dict, limits: Limits | None = None, forwarded: Collection[str] = ()
) -> ExecutionResult:
    """Runs ``program`` (guarded, within ``limits``) in a forked process where each name in ``forwarded`` is a
    stand-in that calls ``namespace[name]`` here."""
    limits = limits or Limits()
    missing = [name for name in forwarded if not callable(namespace.get(name))]
    if missing:
        raise ValueError(f"forwarded names must be callables in the namespace; not: {', '.join(missing)}")
    here, there = Pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    parent = os.getpid()
    pid = os.fork()
    if pid == 0:  # the program's process: never returns
        die_with_parent(signal.SIGKILL, parent)  # a killed trial takes its program along
        _program_side(program, namespace, limits, forwarded, there, keep=there.fileno())
    there.close()
    try:
        return _ToolSide(pid, namespace, limits, here).serve()
    finally:
        here.close()
        _reap(pid)


# --- the program's side ----------------------------------------------------------------------------------------


def _program_side(
    program: str, namespace: dict, limits: Limits, forwarded: Collection[str], conn: Connection, keep: int
) -> None:
    code = 1
    try:
        _close_inherited_files(keep)
        stand_ins = {name: _stand_in(name, conn) for name in forwarded}
        result = execute(program, {**namespace, **stand_ins}, limits)
        result = ExecutionResult(result.outcome, result.error, _shortened(result.output))
        with _timer_held():
            conn.send_bytes(pickle.dumps(("done", result)))
        code = 0
    finally:
        os._exit(code)  # no atexit handlers or finalizers of the caller's objects in this copy


def _close_inherited_files(keep: int) -> None:
    """Closes every descriptor but stdio and the pipe: the caller's pipes (to its runner, to ffmpeg, to an LLM)
    must see their peer go when the caller does, not when this process ends."""
    os.closerange(3, keep)
    os.closerange(keep + 1, 1 << 16)


def _shortened(output: str) -> str:
    if len(output) <= MAX_REPORTED_OUTPUT:
        return output
    half = MAX_REPORTED_OUTPUT // 2
    return f"{output[:half]}\n[... {len(output) - 2 * half} characters left out ...]\n{output[-half:]}"


@contextlib.contextmanager
def _timer_held():
    """Holds the timer signal back (it is delivered when released), so it cannot cut a message in half."""
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGALRM})


def _stand_in(name: str, conn: Connection) -> Callable:
    def call(*args, **kwargs):
        try:
            message = pickle.dumps(("call", name, args, kwargs))
        except Exception as exc:  # lambdas, generators, modules...
            raise ToolArgumentError(
                f"{name}() can only be given data (numbers, strings, lists, arrays, poses): {exc}"
            ) from None
        if len(message) > MAX_MESSAGE:
            raise ToolArgumentError(f"{name}() was given {len(message)} bytes of arguments; at most {MAX_MESSAGE}")
        with _timer_held():
            conn.send_bytes(message)
            kind, payload = pickle.loads(conn.recv_bytes())
        if kind == "return":
            return payload
        if kind == "timeout":
            raise ProgramTimeout
        raise _rebuilt(*payload)

    call.__name__ = call.__qualname__ = name
    return call


def _rebuilt(cls: type, args: tuple, state: dict, message: str) -> BaseException:
    """The tool's exception, of its class (so ``except`` clauses and the outcome categories see it), with its
    arguments and attributes where they could be carried; its message in any case."""
    try:
        exc = cls(*args)
    except Exception:
        exc = cls.__new__(cls)
        exc.args = args
    with contextlib.suppress(Exception):
        exc.__dict__.update(state)
    try:
        if str(exc) == message:
            return exc
    except Exception:
        pass
    return _relayed(cls, message)


def _relayed(cls: type, message: str) -> BaseException:
    """An exception of ``cls`` whose message is ``message``, whatever ``cls`` does with its arguments."""
    relayed = type(cls.__name__, (cls,), {"__str__": lambda self: message, "__module__": cls.__module__})
    exc = relayed.__new__(relayed)
    exc.args = (message,)
    return exc


# --- the tools' side -------------------------------------------------------------------------------------------


class _ToolTimeout(BaseException):
    """The program's time ran out while a tool was running for it."""


class _ToolSide:
    """Serves the program's tool calls until it reports, dies, or runs out of time."""

    def __init__(self, pid: int, namespace: dict, limits: Limits, conn: Connection):
        self.pid, self.namespace, self.limits, self.conn = pid, namespace, limits, conn
        self.started = time.monotonic()
        self.deadline = self.started + limits.timeout + EXIT_GRACE

    def serve(self) -> ExecutionResult:
        while True:
            try:
                ready = self.conn.poll(max(self.deadline - time.monotonic(), 0.0))
                message = pickle.loads(self.conn.recv_bytes(MAX_MESSAGE)) if ready else None
            except (EOFError, OSError, pickle.UnpicklingError, MemoryError, ValueError) as exc:
                return self._died(exc)
            if message is None:
                return self._kill()
            if message[0] == "done":
                return message[1]
            _, name, args, kwargs = message
            reply = self._call(name, args, kwargs)
            try:
                data = pickle.dumps(reply)
            except Exception as exc:
                data = pickle.dumps(("raise", _portable(RuntimeError(f"{name}() returned what cannot be sent: {exc}"))))
            try:
                self.conn.send_bytes(data)
            except OSError as exc:
                return self._died(exc)

    def _call(self, name: str, args: tuple, kwargs: dict) -> tuple:
        left = self.started + self.limits.timeout - time.monotonic()
        if left <= 0:
            return ("timeout", None)
        try:
            with _time_limit(left):
                return ("return", self.namespace[name](*args, **kwargs))
        except _ToolTimeout:
            return ("timeout", None)
        except Exception as exc:
            return ("raise", _portable(exc))

    def _kill(self) -> ExecutionResult:
        with contextlib.suppress(ProcessLookupError):
            os.kill(self.pid, signal.SIGKILL)
        error = f"TimeoutError: the program ran longer than its {self.limits.describe()} (its process killed)"
        return ExecutionResult(Outcome.TIMEOUT, error, "")

    def _died(self, cause: BaseException) -> ExecutionResult:
        status = _reap(self.pid)
        if status is not None and os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGXCPU:
            error = (
                f"TimeoutError: the program ran past its CPU-time limit ({self.limits.timeout:g} s and a margin; "
                "its process killed)"
            )
            return ExecutionResult(Outcome.TIMEOUT, error, "")
        if status is not None and os.WIFSIGNALED(status):
            how = f"killed by signal {os.WTERMSIG(status)}"
        else:
            how = f"without a report: {type(cause).__name__}: {cause}"
        return ExecutionResult(Outcome.RUNTIME_ERROR, f"the program's process died ({how})", "")


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


def _portable(exc: BaseException) -> tuple[type, tuple, dict, str]:
    """The exception as it can travel: class, arguments, attributes (those that pickle) and message."""
    message = str(exc)
    try:
        pickle.loads(pickle.dumps((type(exc), exc.args)))
        cls, args = type(exc), exc.args
    except Exception:
        cls, args = RuntimeError, (f"{type(exc).__name__}: {message}",)
        message = args[0]
    state = {}
    for key, value in getattr(exc, "__dict__", {}).items():
        with contextlib.suppress(Exception):
            state[key] = pickle.loads(pickle.dumps(value))
    return cls, args, state, message


def _reap(pid: int) -> int | None:
    """The process's wait status once it has ended (killed if it lingers past a second), None if already reaped."""
    deadline = time.monotonic() + 1.0
    while True:
        try:
            done, status = os.waitpid(pid, os.WNOHANG)
        except ChildProcessError:
            return None
        if done:
            return status
        if time.monotonic() > deadline:
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
            try:
                return os.waitpid(pid, 0)[1]
            except ChildProcessError:
                return None
        time.sleep(0.01)
