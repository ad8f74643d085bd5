"""The program's process as the kernel confines it, and the protocol its tool calls cross: whatever runs in it
cannot open a file, start a process, reach the network or another process, learn a secret of the caller's, or make
the caller do unbounded work; a broken protocol or a forbidden system call is a sandbox violation."""

from __future__ import annotations

import os

import pytest

from roboscript.api import Pose
from roboscript.codegen import confinement
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.program_process import run_program
from roboscript.codegen.sandbox import Limits

VIOLATION = Outcome.SANDBOX_VIOLATION
LIMITS = Limits(timeout=3.0, memory=512 * 1024**2, cpu_margin=1.0)


def probe(act: str, setup: str = "import os, socket", namespace: dict | None = None, **kwargs):
    """Runs a trivial program whose process, once confined, runs ``act`` unguarded (the test-only hook)."""
    return run_program("x = 1", namespace or {}, LIMITS, probe=(setup, act), **kwargs)


def test_this_machine_can_confine_a_program():
    assert confinement.why_unavailable() is None


@pytest.mark.parametrize(
    "act",
    [
        "os.open('/etc/hostname', os.O_RDONLY)",
        "open('/etc/hostname').read()",
        "os.open(MARK, os.O_WRONLY | os.O_CREAT)",
        "os.execv('/bin/sh', ['sh', '-c', 'touch ' + MARK])",
        "os.system('touch ' + MARK)",
        "os.fork()",
        "socket.socket(socket.AF_INET, socket.SOCK_STREAM)",
        "socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)",
        "os.kill(os.getppid(), 9)",
        "os.dup(0)",
        "os.listdir('/')",
        "os.stat('/etc/passwd')",
    ],
)
def test_a_confined_process_cannot_use_files_processes_the_network_or_signals(tmp_path, act):
    mark = tmp_path / "mark"
    result = probe(act.replace("MARK", repr(str(mark))))
    assert result.outcome is VIOLATION, result
    assert "system call the sandbox forbids" in result.error
    assert not mark.exists() and os.listdir(tmp_path) == []


def test_what_a_confined_process_may_still_do_a_program_needs():
    result = probe(
        "import time\nv = np.linalg.inv(np.eye(3) * 2)\nt = time.monotonic()\ntime.sleep(0.01)\nr = np.random.rand()",
        setup="import numpy as np",
    )
    assert result.outcome is Outcome.OK, result


def test_the_program_process_imports_from_where_the_caller_does(tmp_path, monkeypatch):
    """Dependencies found through a PYTHONPATH, a ROS overlay or a ``pip install --target`` folder are found by the
    program's process too (it runs isolated, so it is told the caller's folders by name)."""
    (tmp_path / "roboscript_test_extra_module.py").write_text("VALUE = 41\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    result = probe("assert roboscript_test_extra_module.VALUE == 41", setup="import roboscript_test_extra_module")
    assert result.outcome is Outcome.OK, result


def test_the_program_process_holds_no_secret_of_the_callers(monkeypatch):
    monkeypatch.setenv("ROBOSCRIPT_TEST_SECRET", "hunter2-sk-test")
    monkeypatch.setenv("OPENAI_API_KEY", "sk-not-for-programs")
    setup = (
        "import os\nenviron = repr(dict(os.environ))\n"
        "cmdline = open('/proc/self/cmdline', 'rb').read().decode(errors='replace')\n"
        "descriptors = sorted(int(n) for n in os.listdir('/proc/self/fd'))\n"
    )
    act = "assert 'hunter2' not in environ and 'sk-not' not in environ, environ\nassert 'hunter2' not in cmdline\n"
    act += "assert len(descriptors) <= 5, descriptors\nassert os.getuid() != 0 and os.geteuid() != 0"
    result = probe(act, setup=setup)
    assert result.outcome is Outcome.OK, result  # an assertion that failed would have been a runtime error


def test_the_program_process_is_not_the_callers_and_judges_nothing():
    result = run_program("x = 1", {}, LIMITS)
    assert result.ran_in.startswith("process ") and result.ran_in != f"process {os.getpid()}"


# --- the protocol: what the tools' side accepts from a program's process ---------------------------------------

FRAME = "import struct, json\nfd = {fd}\ndef frame(data):\n    os.write(fd, struct.pack('>I', len(data)) + data)\n"


def _tools_probe(act: str, namespace: dict | None = None):
    namespace = namespace or {"where": lambda name: [1.0, 2.0], "Pose": Pose}
    forwarded = [n for n in namespace if n != "Pose"]
    setup = "import os\n" + FRAME.replace("{fd}", "channel_fd")  # the hook's scope holds the socket's descriptor
    return run_program("x = 1", namespace, LIMITS, forwarded=forwarded, probe=(setup, act))


@pytest.mark.parametrize(
    ("act", "why"),
    [
        ("frame(b'\\x80\\x04\\x95' + b'cos\\nsystem\\n' * 4)", "a frame that is not JSON"),
        ("os.write(fd, struct.pack('>I', 10**9))", "a frame of 1000000000 bytes"),
        ("frame(json.dumps({'call': 'open', 'args': [], 'kwargs': {}}).encode())", "could not have made"),
        ("frame(json.dumps({'call': 'where', 'args': [{'$': 'pickle', 'v': 'x'}], 'kwargs': {}}).encode())",
         "could not have made"),
        ("frame(json.dumps({'done': {'outcome': 'checks_failed', 'error': None, 'output': ''}}).encode())",
         "a report that is not one"),
        ("frame(json.dumps([1, 2]).encode())", "not a JSON object"),
        ("frame(json.dumps({'hello': 1}).encode())", "an unexpected message"),
    ],
)  # fmt: skip
def test_a_process_that_breaks_the_protocol_is_stopped_as_a_violation(act, why):
    result = _tools_probe(act)
    assert result.outcome is VIOLATION, result
    assert why in result.error


def test_a_report_after_the_deadline_is_a_timeout_whatever_it_claims():
    done = "{'done': {'outcome': 'ok', 'error': None, 'output': ''}}"
    act = f"import time\ntime.sleep(3.5)\nframe(json.dumps({done}).encode())"
    result = _tools_probe(act)
    assert result.outcome is Outcome.TIMEOUT, result


def test_a_silent_process_is_killed_at_its_limit_and_a_small_margin():
    result = _tools_probe("import time\ntime.sleep(600)")  # a test that hangs without the kill
    assert result.outcome is Outcome.TIMEOUT and "(its process killed)" in result.error


# --- what a program can hand the tools ---------------------------------------------------------------------------


def _with_tools(program: str, **tools):
    namespace = {**tools, "Pose": Pose}
    return run_program(program, namespace, LIMITS, forwarded=list(tools))


def test_data_arrives_as_data_and_the_tool_never_sees_code():
    seen = []

    def take(*args, **kwargs):
        seen.append((args, kwargs))
        return {"echo": list(args), "pose": Pose([1, 2, 3])}

    program = (
        "r = take(1, 2.5, 'a', None, True, [1, [2]], (3, 4), {'k': 1}, np.arange(3), Pose([0, 0, 1]),"
        " {'b', 'a'}, flag=np.float64(2.0))\nprint(r['pose'].position.z, r['echo'][6], isinstance(r['echo'][6], tuple))"
    )
    result = _with_tools(program, take=take)
    assert result.outcome is Outcome.OK, result
    assert result.output == "3.0 (3, 4) True\n"
    ((args, kwargs),) = seen
    assert args[:8] == (1, 2.5, "a", None, True, [1, [2]], (3, 4), {"k": 1})
    assert args[8].tolist() == [0, 1, 2] and args[9] == Pose([0, 0, 1]) and args[10] == ["a", "b"]
    assert kwargs == {"flag": 2.0}


@pytest.mark.parametrize(
    ("argument", "why"),
    [
        ("lambda: 0", "a function"),
        ("print", "a function"),
        ("map(int, [1])", "a map cannot be passed"),
        ("iter(int, 1)", "cannot be passed"),
        ("range(10 ** 18)", "a range cannot be passed"),
        ("(x for x in [1])", "a generator cannot be passed"),
        ("np.array([1.0]).astype('U3')", "an array of dtype"),
        ("10 ** 100", "larger than 2**63"),
        ("{1: 'a'}", "keys must be strings"),
        ("ValueError('x')", "a ValueError cannot be passed"),
    ],
)
def test_what_is_not_data_is_refused_in_the_program_with_what_may_pass(argument, why):
    calls = []
    result = _with_tools(f"take({argument})", take=lambda *a: calls.append(a))
    assert result.outcome is Outcome.RUNTIME_ERROR, result
    assert "ToolArgumentError: take() can only be given data (numbers, strings" in result.error and why in result.error
    assert calls == []


@pytest.mark.parametrize(
    "program",
    [
        "a = [0.0] * 1000\nb = [a] * 1000\nc = [b] * 1000\ntake(c)",  # shared parts: tiny to pickle, huge to expand
        "x = []\nfor i in range(100):\n    x = [x, x]\ntake(x)",
        "take('x' * (2 * 1024 ** 2))",
        "take(np.zeros(10 ** 6))",
    ],
)
def test_small_programs_cannot_make_the_tools_side_build_large_things(program):
    calls = []
    result = _with_tools(program, take=lambda *a: calls.append(a))
    assert result.outcome is Outcome.RUNTIME_ERROR, result
    assert "ToolArgumentError" in result.error and calls == []


def test_deep_nesting_is_refused():
    result = _with_tools("x = []\nfor i in range(100):\n    x = [x]\ntake(x)", take=lambda *a: None)
    assert result.outcome is Outcome.RUNTIME_ERROR and "nested deeper than" in result.error


def test_a_tools_long_error_reaches_the_program_shortened():
    def fail(text):
        raise ValueError(text * 100_000)

    result = _with_tools("fail('abc')", fail=fail)
    assert result.outcome is Outcome.RUNTIME_ERROR
    assert result.error.startswith("ValueError: abcabc") and "characters left out" in result.error
    assert len(result.error) < 5000


def test_a_programs_giant_error_and_output_come_back_shortened():
    result = _with_tools("print('y' * 10 ** 7)\nraise ValueError('x' * 10 ** 7)")
    assert result.outcome is Outcome.RUNTIME_ERROR
    assert len(result.error) < 5000 and len(result.output) < 10_000


def test_a_programs_exception_carrying_the_tools_objects_cannot_send_them():
    result = _with_tools("try:\n    fail()\nexcept ValueError as e:\n    take(e)", fail=_raise, take=lambda *a: None)
    assert result.outcome is Outcome.RUNTIME_ERROR and "cannot be passed" in result.error


def _raise():
    raise ValueError("no")


def test_tool_calls_work_where_sockets_default_to_a_timeout():
    import socket

    before = socket.getdefaulttimeout()
    socket.setdefaulttimeout(5.0)  # what ROS's client sets in the trial's process; new sockets then do not block
    try:
        program = "for i in range(10):\n    x = take(list(range(20000)))\nprint(len(x))"  # more than a socket buffer
        result = run_program(program, {"take": lambda v: v}, Limits(timeout=60), forwarded=["take"])
    finally:
        socket.setdefaulttimeout(before)
    assert result.outcome is Outcome.OK and result.output == "20000\n", result


def test_what_a_tool_noticed_on_the_programs_behalf_is_in_its_output_and_never_printed(capsys):
    from roboscript.notices import notice

    def move():
        notice("retreat: backed off 0.030 m of 0.060 m: the rest is out of reach")
        return None

    result = run_program("move()\nprint('after')", {"move": move}, LIMITS, forwarded=["move"])
    assert result.outcome is Outcome.OK, result
    assert result.output == "[notice] retreat: backed off 0.030 m of 0.060 m: the rest is out of reach\nafter\n"
    assert "retreat" not in capsys.readouterr().out


def test_a_program_catches_the_tools_errors_by_the_names_their_doc_strings_give():
    # "GraspError where no grasp fits": a program's `except GraspError:` raised NameError just when the grasp
    # failed. The names are the program's own classes, related as the tools' are: PlanningError catches an IKError
    # and a planner time-out alike, FailureError any failure, and a builtin base still works.
    from roboscript.api.program_errors import PROGRAM_ERRORS
    from roboscript.grasping.heuristics import GraspError
    from roboscript.planning.errors import IKError, PlannerTimeoutError

    def grasp_it():
        raise GraspError("no grasp fits")

    def reach():
        raise IKError([0.1, 0.2, 0.3], 0.05, 0.0, "out of reach")

    def plan():
        raise PlannerTimeoutError("RRTConnect", 1.0)

    program = """
caught = []
for tool, kind in ((grasp_it, GraspError), (reach, PlanningError), (plan, PlanningError), (grasp_it, FailureError),
                   (grasp_it, ValueError)):
    try:
        tool()
    except kind as error:
        caught.append(kind.__name__)  # not caught: the program fails
try:
    raise PlacementError('made by the program')
except RuntimeError as error:
    caught.append(str(error))
print(caught)
"""
    namespace = {"Pose": Pose, "grasp_it": grasp_it, "reach": reach, "plan": plan, **PROGRAM_ERRORS}
    result = run_program(program, namespace, LIMITS, forwarded=["grasp_it", "reach", "plan"])
    assert result.outcome is Outcome.OK, result
    assert result.output == (
        "['GraspError', 'PlanningError', 'PlanningError', 'FailureError', 'ValueError', 'made by the program']\n"
    )
