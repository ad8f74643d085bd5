"""Runs a generated program: the guard first, then ``exec`` with restricted builtins and resource limits.

Meant to run in a process of the program's own (see :mod:`roboscript.codegen.program_process`): the limits set
here (address space, CPU time) apply to the whole process.
"""

from __future__ import annotations

import ast
import builtins
import io
import resource
import signal
import sys
import traceback
import types
from dataclasses import dataclass, replace

from roboscript.codegen.checked_calls import helpers, rewrite_checked_calls
from roboscript.codegen.guard import find_violations
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.program_classes import class_builtins, rewrite_classes
from roboscript.codegen.program_imports import program_importer
from roboscript.codegen.program_numpy import program_numpy

PROGRAM_FILENAME = "<program>"
# A program runs as a script does: `if __name__ == "__main__": main()` runs main(); its classes belong to it.
PROGRAM_MODULE = "__main__"
MAX_RECURSION = 200  # frames a program may stack on top of where it starts

_SAFE_BUILTIN_NAMES = (
    "abs", "all", "any", "bool", "dict", "divmod", "enumerate", "filter", "float", "frozenset", "int", "isinstance",
    "iter", "len", "list", "map", "max", "min", "next", "pow", "range", "repr", "reversed", "round", "set", "slice",
    "sorted", "str", "sum", "tuple", "zip", "chr", "ord", "True", "False", "None",
    "Exception", "ArithmeticError", "AssertionError", "IndexError", "KeyError", "LookupError", "RuntimeError",
    "StopIteration", "TypeError", "ValueError", "ZeroDivisionError", "NotImplementedError",
)  # fmt: skip

PROGRAM_BUILTINS = frozenset((*_SAFE_BUILTIN_NAMES, "print", "type"))  # every builtin name a program may call


def safe_numpy() -> types.SimpleNamespace:
    """The ``np`` a program gets (:mod:`roboscript.codegen.program_numpy`)."""
    return program_numpy()


def safe_builtins(output: io.StringIO, np: types.SimpleNamespace | None = None) -> dict:
    """The builtins a program gets; ``print`` writes into ``output``; ``import numpy`` gives ``np``."""
    allowed = {name: getattr(builtins, name) for name in _SAFE_BUILTIN_NAMES}
    allowed["__import__"] = program_importer(np)
    allowed["print"] = lambda *args, sep=" ", end="\n", **_: output.write(sep.join(map(str, args)) + end)
    allowed["type"] = type_name
    allowed.update(helpers())
    allowed.update(class_builtins())
    return allowed


def type_name(value: object) -> types.SimpleNamespace:
    """What ``type(value)`` gives a program: the name of its class as ``.__name__`` and nothing else (the guard
    lets ``type`` stand only in ``type(x).__name__``; a class itself would reach ``type`` and so new classes)."""
    return types.SimpleNamespace(__name__=builtins.type(value).__name__)


class ProgramTimeout(BaseException):  # not an Exception, so that a program's ``except Exception`` cannot hide it
    """The program ran past its time limit."""


@dataclass(frozen=True)
class Limits:
    """``timeout``: wall seconds; ``memory``: bytes of address space the program may add to the process;
    ``cpu_margin``: CPU seconds beyond ``timeout`` after which the process is killed (a C-level loop that the
    timer cannot interrupt)."""

    timeout: float = 300.0
    memory: int = 2 * 1024**3
    cpu_margin: float = 30.0
    asked: float | None = None  # the time limit as set, where the load stretched ``timeout``

    def scaled_to_load(self) -> Limits:
        """These limits with the time limit stretched by the machine's load (see :mod:`roboscript.load`)."""
        from roboscript.load import load_factor

        return replace(self, timeout=self.timeout * load_factor(), asked=self.asked or self.timeout)

    def describe(self) -> str:
        """The time limit as the user set it, and how much the load stretched it."""
        if self.asked is None or abs(self.timeout - self.asked) < 0.05:
            return f"{self.timeout:g} s limit"
        return f"{self.asked:g} s limit (stretched to {self.timeout:.0f} s for the machine's load)"


@dataclass(frozen=True)
class ExecutionResult:
    outcome: Outcome  # OK, or why the program stopped (the task's checks are judged elsewhere)
    error: str | None
    output: str
    ran_in: str = ""  # the process the program ran in, where not the caller's


def describe_exception(exc: BaseException) -> str:
    """``Type: message (program line N)``, the line being the deepest one in the program itself. Reads no source
    files (a confined process cannot open them)."""
    line = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if frame.f_code.co_filename == PROGRAM_FILENAME:
            line = lineno
    if isinstance(exc, SyntaxError) and exc.filename == PROGRAM_FILENAME:
        line = exc.lineno
        message = f"SyntaxError: {exc.msg}"
    else:
        message = f"{type(exc).__name__}: {_message(exc)}"
    return shortened(message, MAX_ERROR) + (f" (program line {line})" if line else "")


MAX_ERROR = 4000  # characters of an error message kept (its start and its end)


def shortened(text: str, limit: int) -> str:
    """``text``, or its start and end with how much was left out between them when it is longer than ``limit``."""
    if len(text) <= limit:
        return text
    half = limit // 2
    return f"{text[:half]}\n[... {len(text) - 2 * half} characters left out ...]\n{text[-half:]}"


def _message(exc: BaseException) -> str:
    try:
        return str(exc)
    except Exception:  # a message that cannot be made is no reason to lose the error
        return "(its message could not be shown)"


def classify_exception(exc: BaseException) -> Outcome:
    """Failures (the robot could not do what was asked: :class:`~roboscript.errors.FailureError`) apart from
    other runtime errors. A tool's error relayed into a program's process says so itself (``robot_failure``); an
    error class of the program's own is the program's error, whatever it says."""
    from roboscript.errors import FailureError

    relayed = type(exc).__module__ != PROGRAM_MODULE and getattr(type(exc), "robot_failure", False) is True
    failure = isinstance(exc, FailureError) or relayed
    return Outcome.PLANNING_FAILURE if failure else Outcome.RUNTIME_ERROR


def parse_program(program: str) -> ast.Module:
    """The program's syntax tree; a :class:`SyntaxError` for anything that cannot be parsed, however it fails (null
    bytes, nesting deeper than the parser's stack, a recursion limit)."""
    try:
        return ast.parse(program, PROGRAM_FILENAME)
    except SyntaxError:
        raise
    except (ValueError, RecursionError, MemoryError) as exc:
        error = SyntaxError(f"the program cannot be parsed: {type(exc).__name__}: {str(exc)[:200] or 'too deep'}")
        error.filename, error.lineno = PROGRAM_FILENAME, 1
        raise error from None


MAX_PROGRAM = 100_000  # characters: the longest program of any corpus here is under 10,000


def prepare(program: str) -> types.CodeType | ExecutionResult:
    """The program compiled, its format calls checked at run time; or why it may not run."""
    if len(program) > MAX_PROGRAM:
        error = f"SyntaxError: the program is {len(program)} characters long; at most {MAX_PROGRAM}"
        return ExecutionResult(Outcome.SYNTAX, error, "")
    try:
        tree = parse_program(program)
    except SyntaxError as exc:
        return ExecutionResult(Outcome.SYNTAX, describe_exception(exc), "")
    try:
        violations = find_violations(tree)
    except (ValueError, TypeError, RecursionError, MemoryError) as exc:
        return ExecutionResult(Outcome.SYNTAX, f"SyntaxError: the program cannot be checked: {type(exc).__name__}", "")
    if violations:
        return ExecutionResult(Outcome.FORBIDDEN_CONSTRUCT, "; ".join(map(str, violations[:5])), "")
    try:
        return compile(rewrite_classes(rewrite_checked_calls(tree)), PROGRAM_FILENAME, "exec")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        return ExecutionResult(Outcome.SYNTAX, f"SyntaxError: the program cannot be compiled: {type(exc).__name__}", "")


def program_scope(namespace: dict, output: io.StringIO) -> dict:
    """The globals a program runs in: ``namespace``, the program's ``np`` and the restricted builtins."""
    # __name__: read by `if __name__ == "__main__":`, and by a class statement for its class's module.
    np = safe_numpy()
    return {**namespace, "np": np, "__builtins__": safe_builtins(output, np), "__name__": PROGRAM_MODULE}


def execute(program: str, namespace: dict, limits: Limits = Limits()) -> ExecutionResult:
    """Checks ``program`` with the guard, then runs it in a copy of ``namespace`` within ``limits``, in this
    process (whose limits are restored afterwards)."""
    code = prepare(program)
    if isinstance(code, ExecutionResult):
        return code
    output = io.StringIO()
    scope = program_scope(namespace, output)
    saved = impose_limits(limits)
    try:
        with program_timer(limits):
            outcome, error = run_code(code, scope, limits)
    finally:
        restore_limits(saved)
    return ExecutionResult(outcome, error, output.getvalue())


def run_code(code: types.CodeType, scope: dict, limits: Limits) -> tuple[Outcome, str | None]:
    """Runs compiled program code (under :func:`program_timer`); its outcome and error."""
    try:
        exec(code, scope)
        outcome, error = Outcome.OK, None
    except ProgramTimeout:
        outcome, error = Outcome.TIMEOUT, None
    except MemoryError:
        outcome, error = Outcome.RUNTIME_ERROR, "MemoryError: the program used more memory than it may"
    except RecursionError as exc:
        outcome, error = Outcome.RUNTIME_ERROR, describe_exception(exc)
    except Exception as exc:
        outcome, error = classify_exception(exc), describe_exception(exc)
    if _timer.expired:  # ran past its limit, whatever it caught on the way (a finally that went on, a loop)
        outcome = Outcome.TIMEOUT
    if outcome is Outcome.TIMEOUT:
        error = f"TimeoutError: the program ran longer than its {limits.describe()}"
    return outcome, error


class _Timer:
    expired = False


_timer = _Timer()


def _on_alarm(signum, frame):
    _timer.expired = True
    raise ProgramTimeout


class program_timer:
    """The program's wall-time limit: ``ProgramTimeout`` at the limit, and again each second after it in case a
    handler swallowed the first one. Leaves the timer off and the previous handler back."""

    def __init__(self, limits: Limits):
        self.limits = limits

    def __enter__(self):
        _timer.expired = False
        self._previous = signal.signal(signal.SIGALRM, _on_alarm)
        signal.setitimer(signal.ITIMER_REAL, self.limits.timeout, 1.0)
        return self

    def __exit__(self, *exc):
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, self._previous)
        return False


def impose_limits(limits: Limits) -> tuple:
    """Memory (address space), CPU-time and recursion limits on this process; what they were, to restore.

    The timer stops Python code; a single C-level operation that never returns (``10 ** 10 ** 10``) is stopped by
    the CPU-time limit, which kills the process: the tools' side reports that as a time-out.
    """
    saved = (resource.getrlimit(resource.RLIMIT_AS), resource.getrlimit(resource.RLIMIT_CPU), sys.getrecursionlimit())
    sys.setrecursionlimit(_stack_depth() + MAX_RECURSION + 100)
    used = address_space()
    if used is not None:
        resource.setrlimit(resource.RLIMIT_AS, (used + limits.memory, saved[0][1]))
    usage = resource.getrusage(resource.RUSAGE_SELF)
    cpu_limit = int(usage.ru_utime + usage.ru_stime + limits.timeout + limits.cpu_margin) + 1
    if saved[1][1] == resource.RLIM_INFINITY or cpu_limit < saved[1][1]:
        resource.setrlimit(resource.RLIMIT_CPU, (cpu_limit, saved[1][1]))
    return saved


def restore_limits(saved: tuple) -> None:
    """Puts back what :func:`impose_limits` returned."""
    address_space, cpu, recursion = saved
    resource.setrlimit(resource.RLIMIT_AS, address_space)
    resource.setrlimit(resource.RLIMIT_CPU, cpu)
    sys.setrecursionlimit(recursion)


def _stack_depth() -> int:
    depth, frame = 0, sys._getframe()
    while frame is not None:
        depth, frame = depth + 1, frame.f_back
    return depth


def address_space() -> int | None:
    """Bytes of address space the process maps now (Linux), or None where that cannot be read."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[0]) * resource.getpagesize()
    except (OSError, ValueError, IndexError):
        return None
