"""A program runs in a process of its own; its tool calls are forwarded to the process that holds the backend.

The program's process is forked from the caller, so it starts with the same modules, but the only way it can act on
the world is through the tools: each call is sent over a pipe, run by the caller, and its result (or exception)
sent back. Whatever the program does to its own process (exhausts memory, trips the CPU-time limit, corrupts its
interpreter) stays there: the caller survives, with the world as the tools left it, and can still judge it.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import signal
import sys
import time
from collections.abc import Callable, Collection
from multiprocessing import Pipe
from multiprocessing.connection import Connection

from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult, Limits, execute

EXIT_GRACE = 10.0  # seconds past the time limit before a program's process that does not report is killed


class ToolArgumentError(TypeError):
    """A tool was given something that cannot be passed to it (a function, a generator...)."""


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
    pid = os.fork()
    if pid == 0:  # the program's process: never returns
        here.close()
        _program_side(program, namespace, limits, forwarded, there)
    there.close()
    try:
        return _tool_side(pid, namespace, limits, here)
    finally:
        here.close()
        _reap(pid)


def _program_side(program: str, namespace: dict, limits: Limits, forwarded: Collection[str], conn: Connection):
    code = 1
    try:
        stand_ins = {name: _stand_in(name, conn) for name in forwarded}
        result = execute(program, {**namespace, **stand_ins}, limits)
        conn.send(("done", result))
        code = 0
    finally:
        os._exit(code)  # no atexit handlers or finalizers of the caller's objects in this copy


def _stand_in(name: str, conn: Connection) -> Callable:
    def call(*args, **kwargs):
        try:
            conn.send(("call", name, args, kwargs))
        except (pickle.PicklingError, TypeError, AttributeError) as exc:
            raise ToolArgumentError(
                f"{name}() can only be given data (numbers, strings, lists, arrays, poses): {exc}"
            ) from None
        kind, payload = conn.recv()
        if kind == "return":
            return payload
        raise _rebuilt(*payload)

    call.__name__ = call.__qualname__ = name
    return call


def _tool_side(pid: int, namespace: dict, limits: Limits, conn: Connection) -> ExecutionResult:
    deadline = time.monotonic() + limits.timeout + EXIT_GRACE
    while True:
        remaining = deadline - time.monotonic()
        try:
            ready = remaining > 0 and conn.poll(remaining)
            message = conn.recv() if ready else None
        except (EOFError, OSError):
            return _died(pid, limits)
        if message is None:
            os.kill(pid, signal.SIGKILL)
            error = f"TimeoutError: the program ran longer than its {limits.timeout:g} s limit (its process killed)"
            return ExecutionResult(Outcome.TIMEOUT, error, "")
        if message[0] == "done":
            return message[1]
        _, name, args, kwargs = message
        try:
            reply = ("return", namespace[name](*args, **kwargs))
        except Exception as exc:
            reply = ("raise", _portable(exc))
        try:
            conn.send(reply)
        except (pickle.PicklingError, TypeError, AttributeError) as exc:
            conn.send(("raise", (RuntimeError, (f"{name}() returned something that cannot be passed back: {exc}",))))
        except (BrokenPipeError, ConnectionResetError):
            pass  # the program stopped (its time ran out) while the tool ran; its report follows


def _portable(exc: Exception) -> tuple[type, tuple]:
    """The exception's class and arguments, if they survive pickling; else a RuntimeError that names them."""
    try:
        pickle.loads(pickle.dumps((type(exc), exc.args)))
        return type(exc), exc.args
    except Exception:
        return RuntimeError, (f"{type(exc).__name__}: {exc}",)


def _rebuilt(cls: type, args: tuple) -> BaseException:
    """An exception of the tool's class with its message, made without the class's ``__init__`` (whose
    parameters may differ from its ``args``), so that ``except`` clauses and the outcome categories see the type."""
    exc = cls.__new__(cls)
    exc.args = args
    return exc


def _died(pid: int, limits: Limits) -> ExecutionResult:
    status = _reap(pid)
    if status is not None and os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGXCPU:
        error = f"TimeoutError: the program ran past its CPU-time limit ({limits.timeout:g} s and a margin; killed)"
        return ExecutionResult(Outcome.TIMEOUT, error, "")
    how = f"signal {os.WTERMSIG(status)}" if status is not None and os.WIFSIGNALED(status) else "without a report"
    return ExecutionResult(Outcome.RUNTIME_ERROR, f"the program's process died ({how})", "")


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
