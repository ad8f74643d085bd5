"""Child processes that do not outlive the process that started them, and clean-up when a process ends."""

from __future__ import annotations

import atexit
import contextlib
import ctypes
import os
import signal
from collections.abc import Callable

PR_SET_PDEATHSIG = 1


def die_with_parent(sig: int = signal.SIGTERM, parent: int | None = None) -> None:
    """In a child (after fork, or before exec): Linux sends it ``sig`` when its parent exits, however that exits (a
    SIGKILL, an os._exit that runs no clean-up). ``parent``: the parent's pid as the parent knew it, so that a
    parent that died before this call is noticed too. Does nothing where prctl is missing (not Linux)."""
    try:
        libc = ctypes.CDLL("libc.so.6", use_errno=True)
    except OSError:
        return
    libc.prctl(PR_SET_PDEATHSIG, sig)
    if parent is not None and os.getppid() != parent:
        os.kill(os.getpid(), sig)


_exit_hooks: list[Callable[[], None]] = []


def at_process_exit(hook: Callable[[], None]) -> None:
    """Calls ``hook`` when this process ends: at the interpreter's exit, or at the end of a benchmark trial's
    process, which leaves with ``os._exit`` (no atexit handlers) once it has run :func:`run_exit_hooks`. Hooks run
    last registered first; a forked child starts with none of its parent's."""
    if not _exit_hooks:
        atexit.register(run_exit_hooks)
    _exit_hooks.append(hook)


def run_exit_hooks() -> None:
    """Runs the hooks registered with :func:`at_process_exit`, each once; one that fails does not stop the rest."""
    while _exit_hooks:
        hook = _exit_hooks.pop()
        with contextlib.suppress(Exception):
            hook()


os.register_at_fork(after_in_child=_exit_hooks.clear)
