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

import numpy as np

from roboscript.codegen.guard import find_violations
from roboscript.codegen.outcomes import Outcome

PROGRAM_FILENAME = "<program>"
MAX_RECURSION = 200  # frames a program may stack on top of where it starts

_SAFE_BUILTIN_NAMES = (
    "abs", "all", "any", "bool", "dict", "divmod", "enumerate", "filter", "float", "frozenset", "int", "isinstance",
    "iter", "len", "list", "map", "max", "min", "next", "pow", "range", "repr", "reversed", "round", "set", "slice",
    "sorted", "str", "sum", "tuple", "zip", "chr", "ord", "True", "False", "None",
    "Exception", "ArithmeticError", "AssertionError", "IndexError", "KeyError", "LookupError", "RuntimeError",
    "StopIteration", "TypeError", "ValueError", "ZeroDivisionError", "NotImplementedError",
)  # fmt: skip

# numpy as programs see it: maths and arrays, not files, pointers or the module's internals.
_NUMPY_NAMES = (
    "array", "asarray", "zeros", "ones", "full", "eye", "arange", "linspace", "empty", "zeros_like", "ones_like",
    "concatenate", "stack", "vstack", "hstack", "column_stack", "reshape", "transpose", "flip", "roll", "tile",
    "repeat", "where", "argmin", "argmax", "argsort", "sort", "unique", "clip", "abs", "absolute", "sign", "sqrt",
    "square", "exp", "log", "log2", "log10", "sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "hypot",
    "degrees", "radians", "deg2rad", "rad2deg", "pi", "e", "inf", "nan", "isnan", "isfinite", "isclose",
    "allclose", "dot", "cross", "outer", "inner", "matmul", "sum", "prod", "mean", "median", "std", "var", "min",
    "max", "minimum", "maximum", "amin", "amax", "floor", "ceil", "round", "around", "rint", "mod", "cumsum",
    "diff", "all", "any", "logical_and", "logical_or", "logical_not", "count_nonzero", "nonzero", "ndarray",
    "float64", "float32", "int64", "int32", "bool_", "newaxis", "interp", "percentile", "trace", "diag",
)  # fmt: skip


PROGRAM_BUILTINS = frozenset((*_SAFE_BUILTIN_NAMES, "print"))  # every builtin name a program may call


def _proxy(name: str, module: types.ModuleType, names) -> types.SimpleNamespace:
    namespace = types.SimpleNamespace(**{n: getattr(module, n) for n in names if hasattr(module, n)})
    namespace.__name__ = name
    return namespace


def safe_numpy() -> types.SimpleNamespace:
    """The ``np`` a program gets: an allow-list of numpy, with ``linalg`` and ``random`` trimmed the same way."""
    proxy = _proxy("np", np, _NUMPY_NAMES)
    proxy.linalg = _proxy("np.linalg", np.linalg, ("norm", "inv", "pinv", "det", "solve", "eig", "svd", "lstsq"))
    proxy.random = _proxy(
        "np.random", np.random, ("default_rng", "uniform", "normal", "rand", "randn", "randint", "choice", "seed")
    )
    return proxy


def safe_builtins(output: io.StringIO) -> dict:
    """The builtins a program gets; ``print`` writes into ``output``."""
    allowed = {name: getattr(builtins, name) for name in _SAFE_BUILTIN_NAMES}
    allowed["print"] = lambda *args, sep=" ", end="\n", **_: output.write(sep.join(map(str, args)) + end)
    return allowed


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


def describe_exception(exc: BaseException) -> str:
    """``Type: message (program line N)``, the line being the deepest one in the program itself."""
    line = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if frame.filename == PROGRAM_FILENAME:
            line = frame.lineno
    if isinstance(exc, SyntaxError) and exc.filename == PROGRAM_FILENAME:
        line = exc.lineno
        message = f"SyntaxError: {exc.msg}"
    else:
        message = f"{type(exc).__name__}: {exc}"
    return message + (f" (program line {line})" if line else "")


def classify_exception(exc: BaseException) -> Outcome:
    """Failures (the robot could not do what was asked: :class:`~roboscript.errors.FailureError`) apart from
    other runtime errors."""
    from roboscript.errors import FailureError

    return Outcome.PLANNING_FAILURE if isinstance(exc, FailureError) else Outcome.RUNTIME_ERROR


def execute(program: str, namespace: dict, limits: Limits = Limits()) -> ExecutionResult:
    """Checks ``program`` with the guard, then runs it in a copy of ``namespace`` within ``limits``."""
    output = io.StringIO()
    try:
        tree = ast.parse(program, PROGRAM_FILENAME)
    except SyntaxError as exc:
        return ExecutionResult(Outcome.SYNTAX, describe_exception(exc), "")
    violations = find_violations(tree)
    if violations:
        return ExecutionResult(Outcome.FORBIDDEN_CONSTRUCT, "; ".join(map(str, violations[:5])), "")
    code = compile(tree, PROGRAM_FILENAME, "exec")
    scope = {**namespace, "np": safe_numpy(), "__builtins__": safe_builtins(output)}
    with _limited(limits):
        try:
            exec(code, scope)
            outcome, error = Outcome.OK, None
        except ProgramTimeout:
            outcome = Outcome.TIMEOUT
            error = f"TimeoutError: the program ran longer than its {limits.describe()}"
        except MemoryError:
            outcome, error = Outcome.RUNTIME_ERROR, "MemoryError: the program used more memory than it may"
        except RecursionError as exc:
            outcome, error = Outcome.RUNTIME_ERROR, describe_exception(exc)
        except Exception as exc:
            outcome, error = classify_exception(exc), describe_exception(exc)
    return ExecutionResult(outcome, error, output.getvalue())


def _on_alarm(signum, frame):
    raise ProgramTimeout


class _limited:
    """Time, memory and recursion limits around a program run, restored afterwards.

    The timer signal stops Python code; a single C-level operation that never returns (``10 ** 10 ** 10``) is
    stopped by the CPU-time limit, which kills the process: the runner reports that as a crashed trial.
    """

    def __init__(self, limits: Limits):
        self.limits = limits

    def __enter__(self):
        self._alarm = signal.signal(signal.SIGALRM, _on_alarm)
        # Repeats each second after the limit, in case a handler swallowed the first one.
        signal.setitimer(signal.ITIMER_REAL, self.limits.timeout, 1.0)
        self._recursion = sys.getrecursionlimit()
        sys.setrecursionlimit(len(traceback.extract_stack()) + MAX_RECURSION + 100)
        self._as = resource.getrlimit(resource.RLIMIT_AS)
        self._cpu = resource.getrlimit(resource.RLIMIT_CPU)
        used = _address_space()
        if used is not None:
            resource.setrlimit(resource.RLIMIT_AS, (used + self.limits.memory, self._as[1]))
        cpu_now = resource.getrusage(resource.RUSAGE_SELF).ru_utime + resource.getrusage(resource.RUSAGE_SELF).ru_stime
        cpu_limit = int(cpu_now + self.limits.timeout + self.limits.cpu_margin) + 1
        if self._cpu[1] == resource.RLIM_INFINITY or cpu_limit < self._cpu[1]:
            resource.setrlimit(resource.RLIMIT_CPU, (cpu_limit, self._cpu[1]))
        return self

    def __exit__(self, *exc):
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, self._alarm)
        sys.setrecursionlimit(self._recursion)
        resource.setrlimit(resource.RLIMIT_AS, self._as)
        resource.setrlimit(resource.RLIMIT_CPU, self._cpu)
        return False


def _address_space() -> int | None:
    """Bytes of address space the process maps now (Linux), or None where that cannot be read."""
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[0]) * resource.getpagesize()
    except (OSError, ValueError, IndexError):
        return None
