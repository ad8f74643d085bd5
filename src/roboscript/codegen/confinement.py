"""The kernel's part of the sandbox: a confined process may use the socket it holds and its own memory, nothing else.

Confinement is applied by the program's process to itself once it is set up (modules imported, the program
compiled), before the program runs, and cannot be undone:

- a seccomp-BPF filter (through libseccomp) allows an explicit list of system calls: reading and writing the
  descriptors it already has, memory, signals and timers for its own time limit, clocks, futexes, and exiting.
  Any other call (``open``, ``execve``, ``socket``, ``clone``, ``ptrace``, ``kill``, ``ioctl``...) kills the
  process at once with ``SIGSYS``, which the tools' side reports as a sandbox violation;
- ``no_new_privs`` (set by libseccomp), and as root, the process becomes ``nobody`` with no groups first;
- resource limits: no files written, no core dumps, no child processes.

Where libseccomp is missing the program does not run (:class:`ConfinementUnavailable` says how to install it),
unless ``ROBOSCRIPT_UNCONFINED=1`` is set on purpose (then only the guard and restricted builtins stand).
"""

from __future__ import annotations

import os
import resource
import signal

from roboscript.errors import RoboScriptError
from roboscript.processes import die_with_parent

# System calls a confined process may make. Everything Python and numpy do while a program computes and talks to
# the tools: no file system, no processes, no network, no signals to others, no descriptors made.
ALLOWED_SYSCALLS = (
    "read", "write", "readv", "writev", "close",
    "mmap", "munmap", "mremap", "mprotect", "brk", "madvise",
    "rt_sigaction", "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "setitimer", "getitimer",
    "clock_gettime", "clock_getres", "gettimeofday", "time", "nanosleep", "clock_nanosleep",
    "futex", "sched_yield", "getpid", "gettid", "getrusage", "getrandom", "getuid", "geteuid", "getgid", "getegid",
    "exit", "exit_group", "restart_syscall",
)  # fmt: skip

UNCONFINED_VARIABLE = "ROBOSCRIPT_UNCONFINED"
NOBODY = 65534
INSTALL_HINT = (
    "install libseccomp (Debian: apt-get install libseccomp2) and the pyseccomp package (pip install "
    "pyseccomp==0.1.2), or set ROBOSCRIPT_UNCONFINED=1 to run programs with the Python-level sandbox alone"
)


class ConfinementUnavailable(RoboScriptError, RuntimeError):
    """This machine cannot confine a program's process (no seccomp, no libseccomp)."""


def unconfined_by_choice(environ: dict[str, str] | None = None) -> bool:
    """Whether the user chose to run programs without the kernel's confinement (``ROBOSCRIPT_UNCONFINED=1``)."""
    return (os.environ if environ is None else environ).get(UNCONFINED_VARIABLE, "") == "1"


def why_unavailable() -> str | None:
    """Why a process cannot be confined here, or None when it can."""
    if not os.path.exists("/proc/self/status"):
        return "seccomp needs Linux"
    try:
        import pyseccomp  # noqa: F401
    except ImportError:
        return "the pyseccomp package is not installed"
    except RuntimeError as exc:  # pyseccomp raises this where libseccomp.so is missing
        return f"libseccomp is missing ({exc})"
    return None


def require() -> None:
    """Raises :class:`ConfinementUnavailable` unless confinement works here or was turned off on purpose."""
    if unconfined_by_choice():
        return
    reason = why_unavailable()
    if reason is not None:
        raise ConfinementUnavailable(f"cannot confine a program's process: {reason}; {INSTALL_HINT}")


def confine(parent: int) -> None:
    """Confines this process for good. ``parent``: the process it must die with (its death sends SIGKILL)."""
    import pyseccomp as seccomp

    for limit in (resource.RLIMIT_FSIZE, resource.RLIMIT_CORE, resource.RLIMIT_NPROC):
        resource.setrlimit(limit, (0, 0))
    if os.getuid() == 0:
        os.setgroups([])
        os.setgid(NOBODY)
        os.setuid(NOBODY)
    die_with_parent(signal.SIGKILL, parent)  # after the change of user, which clears the parent-death signal
    rules = seccomp.SyscallFilter(defaction=seccomp.KILL_PROCESS)
    rules.set_attr(seccomp.Attr.ACT_BADARCH, seccomp.KILL_PROCESS)  # a 32-bit or x32 system call is no way out
    for name in ALLOWED_SYSCALLS:
        try:
            rules.add_rule(seccomp.ALLOW, name)
        except (OSError, ValueError):  # a call this architecture does not have (``time`` on aarch64)
            continue
    rules.load()


def killed_by_confinement(status: int) -> bool:
    """Whether a wait status says the process was killed for a forbidden system call."""
    return os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGSYS
