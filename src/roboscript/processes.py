"""Child processes that do not outlive the process that started them."""

from __future__ import annotations

import ctypes
import os
import signal

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
