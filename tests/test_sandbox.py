"""The sandbox: hostile or broken programs are rejected or contained, the runner survives, nothing outside changes."""

from __future__ import annotations

import os

import numpy as np
import pytest

from roboscript.api import Pose
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.program_process import run_program
from roboscript.codegen.sandbox import Limits, execute

FORBIDDEN, RUNTIME, TIMEOUT = Outcome.FORBIDDEN_CONSTRUCT, Outcome.RUNTIME_ERROR, Outcome.TIMEOUT

# (program, expected outcome, a piece of the error). MARK is replaced by a path that must not exist afterwards.
HOSTILE = [
    ("import os\nos.system('touch MARK')", FORBIDDEN, "import of 'os' is not allowed"),
    ("from os import system\nsystem('touch MARK')", FORBIDDEN, "import of 'os' is not allowed"),
    ("__import__('os').system('touch MARK')", FORBIDDEN, "'__import__' is not allowed"),
    ("import builtins", FORBIDDEN, "import of 'builtins' is not allowed"),
    ("x = ().__class__.__bases__[0].__subclasses__()", FORBIDDEN, ".__class__"),
    ("x = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == 'Popen']", FORBIDDEN, ".__class__"),
    ("f = lambda: 0\ng = f.__globals__", FORBIDDEN, ".__globals__"),
    ("g = (x for x in [1])\nh = g.gi_frame.f_back.f_globals", FORBIDDEN, ".gi_frame"),
    ("try:\n    1 / 0\nexcept Exception as e:\n    t = e.__traceback__.tb_frame", FORBIDDEN, ".__traceback__"),
    ("open('MARK', 'w').write('x')", FORBIDDEN, "'open' is not allowed"),
    ("with open('MARK', 'w') as f:\n    f.write('x')", FORBIDDEN, "with statements are not allowed"),
    ("eval('1 + 1')", FORBIDDEN, "'eval' is not allowed"),
    ("exec('import os')", FORBIDDEN, "'exec' is not allowed"),
    ("c = compile('1', 'f', 'eval')", FORBIDDEN, "'compile' is not allowed"),
    ("getattr(np, 'load')('MARK')", FORBIDDEN, "'getattr' is not allowed"),
    ("np.save('MARK', np.zeros(3))", FORBIDDEN, ".save"),
    ("np.zeros(3).tofile('MARK')", FORBIDDEN, ".tofile"),
    ("m = np.lib.format.open_memmap('MARK', mode='w+', shape=(3,))", FORBIDDEN, ".lib"),
    ("p = np.zeros(3).ctypes.data", FORBIDDEN, ".ctypes"),
    ("alias = np\nalias.load('MARK')", FORBIDDEN, ".load"),
    ("b = globals()['__builtins__']", FORBIDDEN, "'globals' is not allowed"),
    ("X = type('X', (), {})", FORBIDDEN, "'type' is not allowed"),
    # A program's own classes (codegen/program_classes.py): plain ones run; nothing that hooks the interpreter.
    ("class X(metaclass=print):\n    pass", FORBIDDEN, "class keywords (metaclass=...) are not allowed"),
    ("class X(np.ndarray):\n    pass", FORBIDDEN, "may extend only object, an exception"),
    ("class X(Pose):\n    pass", FORBIDDEN, "may extend only object, an exception"),
    ("Exception = Pose\nclass X(Exception):\n    pass", FORBIDDEN, "may extend only object"),
    ("class E(Exception):\n    pass\nE = np\nclass F(E):\n    pass", FORBIDDEN, "may extend only object"),
    ("class X:\n    def __getattr__(self, name):\n        return 1", FORBIDDEN, "method __getattr__ is not allowed"),
    ("class X:\n    pass\ns = X.__subclasses__()", FORBIDDEN, ".__subclasses__"),
    ("class X:\n    def f(self):\n        return self.__class__", FORBIDDEN, ".__class__"),
    ("class X:\n    def f(self):\n        return self._core\nv = X.f(np)", RUNTIME, "has no attribute 'private_core'"),
    ("s = super()", FORBIDDEN, "'super' is not allowed"),
    ("class X(object):\n    base = object", FORBIDDEN, "'object' is not allowed"),
    ("class X:\n    @print\n    def f(self):\n        pass", FORBIDDEN, "decorators are not allowed"),
    ("@staticmethod\ndef f():\n    pass", FORBIDDEN, "decorators are not allowed"),
    ("class __X:\n    pass", FORBIDDEN, "'__X' is not allowed"),
    ("__name__ = 'x'", FORBIDDEN, "'__name__' is not allowed"),
    ("class E(RuntimeError):\n    robot_failure = True\nraise E('faked')", RUNTIME, "E: faked"),
    ("async def f():\n    pass", FORBIDDEN, "async code is not allowed"),
    ("def f():\n    yield 1", FORBIDDEN, "generators (yield) are not allowed"),
    ("s = '{0.__class__}'.format(1)", FORBIDDEN, "format strings may not name dunder attributes"),
    ("m = print.__self__", FORBIDDEN, ".__self__"),
    ("def f():\n    pass\nf.__name__ = 'g'", FORBIDDEN, ".__name__"),  # read only
    ("n = np.__name__.__class__", FORBIDDEN, ".__class__"),
    ("t = type", FORBIDDEN, "'type' is not allowed"),  # type only as type(x).__name__
    ("C = type('C', (), {}).__name__", FORBIDDEN, "'type' is not allowed"),
    ("m = type(type(1)).__name__", FORBIDDEN, "'type' is not allowed"),
    ("m = type(1).mro()", FORBIDDEN, ".mro"),
    ("d = type(1).__dict__", FORBIDDEN, ".__dict__"),
    ("g = Pose.__init__.__globals__", FORBIDDEN, ".__init__"),
    ("d = vars(np)", FORBIDDEN, "'vars' is not allowed"),
    ("breakpoint()", FORBIDDEN, "'breakpoint' is not allowed"),
    ("try:\n    pass\nexcept:\n    pass", FORBIDDEN, "bare except"),
    ("r = [].__class__.__mro__", FORBIDDEN, ".__class__"),
    ("while True:\n    pass", TIMEOUT, "longer than its 2 s limit"),
    ("while True:\n    try:\n        x = 1\n    except Exception:\n        pass", TIMEOUT, "longer than its 2 s"),
    ("x = [0] * (10 ** 10)", RUNTIME, "MemoryError"),
    ("s = 'a' * (10 ** 11)", RUNTIME, "MemoryError"),
    ("a = np.zeros(10 ** 11)", RUNTIME, "MemoryError"),
    ("def f(n):\n    return f(n + 1)\nf(0)", RUNTIME, "RecursionError"),
    ("x = 1 / 0", RUNTIME, "ZeroDivisionError: division by zero (program line 1)"),
    ("raise SystemExit(0)", RUNTIME, "NameError: name 'SystemExit' is not defined"),
    ("x = undefined_name + 1", RUNTIME, "NameError"),
    # C code the timer signal cannot interrupt: the CPU-time limit or, on a busy machine, the wall deadline ends it.
    ("x = sum(range(10 ** 13))", TIMEOUT, "TimeoutError: the program ran"),
    ("os = 3\nx = np.os", FORBIDDEN, ".os"),
    # numpy's raw memory: no object or record arrays, no reinterpreted bytes, no constructor over a buffer.
    ("a = np.array([1, None])", RUNTIME, "ObjectArrayError: np.array() would make an array of Python objects"),
    ("a = np.zeros(3, dtype=object)", FORBIDDEN, "the name 'object' is not allowed"),
    ("a = np.zeros(3, dtype='object')", RUNTIME, "ObjectArrayError"),
    ("a = np.zeros(2, 'O')", RUNTIME, "ObjectArrayError"),
    ("a = np.array([1.0], dtype=[('a', 'O')])", RUNTIME, "ObjectArrayError"),
    ("a = np.full(2, 7, 'V8')", RUNTIME, "ObjectArrayError"),
    ("a = np.ndarray((1,), dtype='O', buffer=np.zeros(1))", RUNTIME, "np.ndarray(...) cannot be called"),
    ("a = np.arange(3).view('O')", FORBIDDEN, ".view is not allowed"),
    ("a = np.arange(3)\na.dtype = 'O'", FORBIDDEN, "assigning .dtype is not allowed"),
    ("b = np.array([1.0]).astype(object).tobytes()", FORBIDDEN, ".tobytes"),
    ("m = np.zeros(1).data", FORBIDDEN, ".data"),
    ("g = np.random.default_rng().bit_generator.cffi", FORBIDDEN, ".cffi"),
    # Format templates built while the program runs may not walk attributes.
    ("t = '{0.' + '__class__}'\ns = t.format(1)", RUNTIME, "FormatTemplateError: format fields may not read"),
    ("t = '{0' + chr(46) + 'real}'\ns = t.format(1)", RUNTIME, "format fields may not read attributes"),
    ("s = str.format('{0.' + 'real}', 1)", RUNTIME, "format fields may not read attributes"),
    ("t = '{0:{1.' + 'real}}'\ns = t.format(1, 2)", RUNTIME, "format fields may not read attributes"),
    ("f = str.format", FORBIDDEN, "take .format only to call it"),
    ("f = 'x {}'.format\ns = f(1)", FORBIDDEN, "take .format only to call it"),
    ("t = '{0.' + 'real}'\ns = np.array(['x']).dtype.type.format(t, 1)", RUNTIME, "format fields may not read"),
    ("a = np.array([1.0]).astype('O')", RUNTIME, "ObjectArrayError: astype()"),
    ("a = np.array(['a']).astype([('f', 'O')])", RUNTIME, "ObjectArrayError"),
    ("f = np.zeros(2).astype", FORBIDDEN, "take .astype only to call it"),
    ("a = np.zeros(4)\na.resize(8, refcheck=False)", FORBIDDEN, ".resize is not allowed"),
    ("try:\n    x = 1 / 0\nexcept ZeroDivisionError as __builtins__:\n    pass", FORBIDDEN, "'__builtins__'"),
    ("Pose.position_array = lambda self: [0.0, 0.0, 0.0]", RUNTIME, "Pose's methods and properties cannot be"),
    # Programs the parser chokes on are syntax errors, here and in the static checker (the trial's own process).
    ("x = " + "-" * 50_000 + "1", Outcome.SYNTAX, "cannot be parsed"),
    ("x = 1\n" * 20_000, Outcome.SYNTAX, "characters long; at most 100000"),
    ("def f(" + ", ".join(f"a{i}" for i in range(100)) + "):\n    pass", FORBIDDEN, "a function of 100 parameters"),
    ("x = 1\0", Outcome.SYNTAX, "SyntaxError"),
    # A time-out caught and swallowed is still a time-out.
    ("for _ in range(1):\n    try:\n        while True:\n            pass\n    finally:\n        break", TIMEOUT,
     "longer than its 2 s limit"),
    ("while True:\n    try:\n        while True:\n            pass\n    finally:\n        continue", TIMEOUT,
     "longer than its 2 s limit"),
]


def run_contained(program: str) -> tuple[str, str | None]:
    """Runs ``program`` as trials do: in a process of its own; returns its outcome and error."""
    limits = Limits(timeout=2.0, memory=512 * 1024**2, cpu_margin=1.0)
    result = run_program(program, {"Pose": Pose}, limits)
    return result.outcome.value, result.error


def test_the_corpus_is_large_enough():
    assert len(HOSTILE) >= 30


@pytest.mark.parametrize(("program", "outcome", "error"), HOSTILE, ids=[f"p{i}" for i in range(len(HOSTILE))])
def test_hostile_programs_are_rejected_or_contained(tmp_path, program, outcome, error):
    mark = tmp_path / "mark"
    outcome_got, error_got = run_contained(program.replace("MARK", str(mark)))
    assert outcome_got == outcome.value, error_got
    assert error in error_got
    assert not mark.exists() and os.listdir(tmp_path) == []


@pytest.mark.parametrize(
    "program", ["x = " + "-" * 50_000 + "1", "x = 1\0", "x = " + "not " * 20_000 + "1", "def f(a, a):\n    pass"],
    ids=["deep", "null", "long", "duplicate"],
)
def test_the_static_checker_reports_what_cannot_be_parsed_as_syntax(program):
    from roboscript.codegen.checker import check_program

    (finding,) = check_program(program)
    assert finding.outcome is Outcome.SYNTAX and finding.message.startswith("SyntaxError: ")


def test_a_well_behaved_program_runs_with_numpy_and_prints():
    program = "v = np.linalg.norm(np.array([3.0, 4.0]))\nnames = sorted(['b', 'a'])\nprint(v, names)\n"
    result = execute(program, {}, Limits(timeout=5))
    assert result.outcome is Outcome.OK and result.error is None
    assert result.output == "5.0 ['a', 'b']\n"


def test_a_program_may_define_classes_as_an_llm_writes_them():
    program = """
class GraspFailed(RuntimeError):
    def __init__(self, name):
        super().__init__(f"could not grasp {name}")
        self.name = name


class Robot(object):
    def __init__(self, lift=0.1):
        self._held = None
        self.lift = lift

    @staticmethod
    def width(box):
        return box[3] - box[0]

    @property
    def holding(self):
        return self._held is not None

    def pick(self, name):
        self._held = name
        return self.width([0, 0, 0, 0.05, 0, 0])

    def __repr__(self):
        return f"Robot({self._held})"


robot = Robot()
print(robot.pick("apple"), robot.holding, robot)
try:
    raise GraspFailed("apple")
except GraspFailed as exc:
    print(exc, exc.name)
raise GraspFailed("pear")
"""
    from roboscript.codegen.checker import check_program

    assert check_program(program) == []
    result = run_program(program, {"Pose": Pose}, Limits(timeout=5.0))
    assert result.output == "0.05 True Robot(apple)\ncould not grasp apple apple\n"
    assert result.outcome is Outcome.RUNTIME_ERROR  # the program's own error, not the robot's failure
    assert result.error.startswith("GraspFailed: could not grasp pear (program line 35)")


def test_only_a_failure_a_tool_raised_ends_a_program_as_the_robots_failure():
    # The program's process is the program's: it can raise GraspError itself, or mark any error class a failure.
    from roboscript.api.program_errors import PROGRAM_ERRORS
    from roboscript.grasping.heuristics import GraspError

    def grasp_nothing(name):
        raise GraspError(f"no grasp fits {name}")

    namespace = {"grasp_nothing": grasp_nothing, "Pose": Pose, **PROGRAM_ERRORS}
    limits, tools = Limits(timeout=5.0), ["grasp_nothing"]
    tool_failed = run_program("grasp_nothing('apple')", namespace, limits, tools)
    assert tool_failed.outcome is Outcome.PLANNING_FAILURE, tool_failed.error
    own = run_program("raise GraspError('no grasp fits the list')", namespace, limits, tools)
    assert own.outcome is Outcome.RUNTIME_ERROR and own.error.startswith("GraspError: no grasp fits the list")
    # A failure a tool raised, caught, and the same class raised later for the program's own bug.
    caught = "try:\n    grasp_nothing('apple')\nexcept GraspError:\n    pass\nraise GraspError('no grasp: [].pop()')"
    caught = run_program(caught, namespace, limits, tools)
    assert caught.outcome is Outcome.RUNTIME_ERROR, caught.error
    reraised = run_program("try:\n    grasp_nothing('apple')\nexcept GraspError:\n    raise", namespace, limits, tools)
    assert reraised.outcome is Outcome.PLANNING_FAILURE, reraised.error
    marked = "UnknownObjectError.robot_failure = True\nraise UnknownObjectError('aple')"
    marked = run_program(marked, namespace, limits, tools)
    assert marked.outcome is Outcome.RUNTIME_ERROR, marked.error


def test_limits_are_restored_after_a_run():
    import resource
    import signal
    import sys

    before = (resource.getrlimit(resource.RLIMIT_AS), resource.getrlimit(resource.RLIMIT_CPU), sys.getrecursionlimit())
    execute("x = 1", {}, Limits(timeout=5))
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
    after = (resource.getrlimit(resource.RLIMIT_AS), resource.getrlimit(resource.RLIMIT_CPU), sys.getrecursionlimit())
    assert after == before


def test_tool_calls_run_in_the_callers_process_and_only_their_results_reach_the_program():
    calls, names = [], ["apple", "bowl"]

    def where(tag):  # a tool: runs here, in the test's process
        calls.append(tag)
        return {"pid": os.getpid(), "pose": Pose([0.5, 0.0, 0.2], [0, 0, 0, 1])}

    def object_names():
        return names

    program = "r = where('a')\nn = object_names()\nn.append('stolen')\nprint(r['pid'], r['pose'].position.x, len(n))"
    namespace = {"where": where, "object_names": object_names, "Pose": Pose}
    result = run_program(program, namespace, Limits(timeout=5), forwarded=["where", "object_names"])
    assert result.outcome is Outcome.OK, result.error
    assert result.output == f"{os.getpid()} 0.5 3\n"
    assert calls == ["a"] and names == ["apple", "bowl"]  # the program changed its copy, not the tool's list


def test_a_tools_exception_reaches_the_program_with_its_type_and_line():
    from roboscript.planning.errors import IKError

    def plan():  # an exception whose __init__ takes other arguments than its message
        raise IKError([0.9, 0.0, 0.1], 0.12, 0.3, "out of reach")

    program = "try:\n    plan()\nexcept RuntimeError as e:\n    print('caught', e.position_error)\nplan()"
    result = run_program(program, {"plan": plan}, Limits(timeout=5), forwarded=["plan"])
    assert result.output == "caught 0.12\n"  # its attributes came along
    assert result.outcome is Outcome.PLANNING_FAILURE
    assert result.error.startswith("IKError: no IK solution for the TCP at [0.900, 0.000, 0.100]: out of reach")
    assert result.error.endswith("(program line 5)")


def test_a_tool_cannot_be_given_code():
    result = run_program("where(lambda: 0)", {"where": lambda f: f}, Limits(timeout=5), forwarded=["where"])
    assert result.outcome is Outcome.RUNTIME_ERROR
    assert "ToolArgumentError: where() can only be given data" in result.error and "line 1" in result.error


def test_forwarded_names_must_be_tools():
    with pytest.raises(ValueError, match="not: move"):
        run_program("x = 1", {}, Limits(timeout=5), forwarded=["move"])


def test_the_time_limit_stops_a_tool_that_runs_too_long_and_the_report_still_arrives():
    import time

    calls = []

    def slow():  # a tool still busy when the program's time runs out
        calls.append("started")
        time.sleep(30)
        calls.append("finished")  # not reached: the limit cuts the call short
        return np.zeros(10**6)  # a reply larger than a pipe holds

    def quick():
        return "quick-result"

    program = "print('x' * 10 ** 6)\ntry:\n    slow()\nfinally:\n    print(quick())"
    result = run_program(program, {"slow": slow, "quick": quick}, Limits(timeout=1), forwarded=["slow", "quick"])
    assert calls == ["started"]
    assert result.outcome is Outcome.TIMEOUT, result.error
    assert "quick-result" not in result.output  # no reply to an earlier call read as a later call's
    assert len(result.output) < 10_000 and "characters left out" in result.output


@pytest.mark.parametrize("argument", ["[0.5] * 10 ** 6", "'x' * 10 ** 8"], ids=["list", "string"])
def test_too_much_data_for_a_tool_is_refused_in_the_program(argument):
    # A megabyte's worth is enough: 30 million ints took longer to make than the time limit on a loaded machine.
    result = run_program(f"where({argument})", {"where": len}, Limits(timeout=10), forwarded=["where"])
    assert result.outcome is Outcome.RUNTIME_ERROR and "bytes of arguments; at most" in result.error


def test_a_time_limit_stretches_with_the_machines_load_up_to_a_cap(monkeypatch):
    cpus = os.cpu_count() or 1
    monkeypatch.setattr(os, "getloadavg", lambda: (2.5 * cpus, 0.0, 0.0))  # test double: a busy machine
    limits = Limits(timeout=10.0).scaled_to_load()
    assert limits.timeout == 25.0 and limits.asked == 10.0
    assert limits.describe() == "10 s limit (stretched to 25 s for the machine's load)"
    monkeypatch.setattr(os, "getloadavg", lambda: (100.0 * cpus, 0.0, 0.0))
    assert Limits(timeout=10.0).scaled_to_load().timeout == 40.0  # an endless loop still ends
    monkeypatch.setattr(os, "getloadavg", lambda: (0.1, 0.0, 0.0))
    assert Limits(timeout=10.0).scaled_to_load().describe() == "10 s limit"


def test_a_program_may_name_an_errors_class_in_its_message_and_reach_nothing_from_it():
    program = (
        "try:\n    x = [1][2]\nexcept Exception as e:\n    print(f'{type(e).__name__}: {e}')\n"
        "print(type(np.zeros(2)).__name__, type(1.5).__name__)\n"
    )
    result = execute(program, {}, Limits(timeout=5))
    assert result.outcome is Outcome.OK and result.error is None
    assert result.output == "IndexError: list index out of range\nndarray float\n"
    # A program that binds the name itself reads the builtin bare where its binding does not reach (an adversarial
    # review's find): what it gets is still the name and nothing else.
    bare = "def never():\n    global type\nt = type\nns = t(1)\nprint(ns.__name__, t(ns).__name__)\n"
    result = execute(bare, {}, Limits(timeout=5))
    assert result.outcome is Outcome.OK and result.output == "int SimpleNamespace\n"
    # What type(x) gives at run time is the name and nothing else: no class to call or climb.
    from roboscript.codegen.sandbox import type_name

    assert type_name(ValueError("x")).__name__ == "ValueError" and not callable(type_name(1))


def test_a_program_may_read_a_functions_name_for_its_messages():
    program = "def make_grasp(name):\n    return name\nprint('no', make_grasp.__name__, 'for', 'apple')\n"
    result = execute(program, {}, Limits(timeout=5))
    assert result.outcome is Outcome.OK and result.error is None
    assert result.output == "no make_grasp for apple\n"
