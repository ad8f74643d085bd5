"""Code generation: the checker's categories, prompts from the API itself, code extraction, and the whole path
(generate, check, execute in simulation, evaluate) through the openai client against a local server."""

from __future__ import annotations

import inspect
import json
import subprocess
import sys

import pytest

from chat_server import ScriptedChatServer
from roboscript.api import ToolAPI
from roboscript.bench.benchmark import run_benchmark
from roboscript.bench.runner import run_isolated
from roboscript.bench.tasks import get_task
from roboscript.bench.trial import LLMAuthor, TrialSpec
from roboscript.codegen.agent import CodeAgent
from roboscript.codegen.checker import check_program, undefined_calls
from roboscript.codegen.extract import extract_code
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.program_process import run_program
from roboscript.codegen.prompt import load_examples, program_messages, system_prompt, task_query
from roboscript.codegen.sandbox import Limits, execute
from roboscript.llm import make_llm


@pytest.mark.parametrize(
    ("program", "outcome", "message"),
    [
        ("pick_up('apple')", Outcome.UNKNOWN_FUNCTION, "unknown function pick_up()"),
        ("grasp_object('apple')", Outcome.UNKNOWN_FUNCTION, "did you mean"),
        ("p = parse_central_lift_grasp_pose(obj='apple')", Outcome.BAD_ARGUMENTS, "has no argument 'obj'"),
        ("p = parse_place_pose('apple', receptacle='bowl')", Outcome.BAD_ARGUMENTS, "did you mean receptacle_name"),
        ("move_in_direction([0, 0, 1])", Outcome.BAD_ARGUMENTS, "missing a required argument: 'distance'"),
        ("open_gripper(1.0)", Outcome.BAD_ARGUMENTS, "too many positional arguments"),
        ("def f(a):\n    return a\nf(1, 2)", Outcome.BAD_ARGUMENTS, "too many positional arguments"),
        ("x = np.linalg.nrm([1, 2])", Outcome.UNKNOWN_FUNCTION, "did you mean norm"),
        ("import copy", Outcome.FORBIDDEN_CONSTRUCT, "may import only numpy, math, typing, time, random"),
        ("move_to_pose(Pose(", Outcome.SYNTAX, "SyntaxError"),
    ],
)
def test_the_checker_names_each_problem_with_its_category_and_line(program, outcome, message):
    (finding,) = [f for f in check_program(program) if f.outcome is outcome]
    assert message in finding.message and finding.line >= 1


def test_habits_of_llms_that_do_no_harm_are_accepted_and_run():
    # Told not to import, LLMs still write `import numpy as np`; some keep a counter with `global`, test with :=,
    # run main() under `if __name__ == "__main__":`.
    program = (
        "import numpy as np\nimport math\nfrom math import pi, sqrt\nfrom typing import List, Optional\n"
        "import numpy.linalg\nfrom numpy.linalg import norm\ncounter = 0\n\n\n"
        "def bump(k: int) -> List[int]:\n    global counter\n    counter += k\n    return [counter]\n\n\n"
        "def dist(a, b) -> Optional[float]:\n    if (d := norm(np.array(a) - np.array(b))) > 0:\n"
        "        return float(d)\n    return None\n\n\n"
        "print(bump(2), round(math.cos(pi), 3), sqrt(4.0), dist([0, 0], [3, 4]), numpy.linalg.norm([1, 0]))\n"
        "import time\nimport random\ntime.sleep(0.01)\nrandom.seed(3)\nassert 0 <= random.uniform(0, 1) <= 1\n"
        "for object in ['apple']:\n    print(object)\n"
        "def main():\n    print('main')\n\n\nif __name__ == '__main__':\n    main()\n"
    )
    assert check_program(program) == []
    result = execute(program, {})
    assert result.outcome is Outcome.OK, result.error
    assert result.output == "[2] -1.0 2.0 5.0 1.0\napple\nmain\n"
    contained = run_program(program, {}, Limits(timeout=10.0))  # in a confined process, as trials run it
    assert contained.outcome is Outcome.OK and contained.output == result.output, contained.error


@pytest.mark.parametrize(
    ("program", "message"),
    [
        ("import os", "import of 'os' is not allowed"),
        ("import numpy.ctypeslib", "import of 'numpy.ctypeslib' is not allowed"),
        ("from numpy import *", "'from numpy import *' is not allowed"),
        ("from . import tools", "relative imports are not allowed"),
        ("from numpy import _core", "the name '_core' is not allowed"),
        ("from numpy import load", "the name 'load' is not allowed"),
        ("import math as __builtins__", "the name '__builtins__' is not allowed"),
        ("global __builtins__", "__builtins__ are not all allowed"),
    ],
)
def test_imports_beyond_numpy_math_and_typing_are_refused_with_what_is_accepted(program, message):
    assert any(message in f.message for f in check_program(program))


def test_an_import_the_guard_would_refuse_fails_at_run_time_too():
    # The importer is the program's __import__: nothing but the three namespaces, whatever reached it.
    from roboscript.codegen.program_imports import program_importer

    importer = program_importer()
    assert importer("math").sqrt(9.0) == 3.0
    assert importer("numpy.linalg", fromlist=("norm",)).norm([3.0, 4.0]) == 5.0
    with pytest.raises(ImportError, match="may import only numpy, math, typing, time, random; 'os' is not among them"):
        importer("os")
    with pytest.raises(ImportError, match=r"'numpy\.ctypeslib'"):
        importer("numpy.ctypeslib", fromlist=("x",))


def test_the_checker_accepts_aliases_defined_functions_and_callable_variables():
    program = (
        "def lift(height=0.1):\n    move_in_direction(direction=[0, 0, 1], distance=height)\n"
        "p = get_object_center_position(obj_name='apple')\nlift()\nlift(0.2)\n"
        "f = lambda v: v * 2\ny = f(3)\npose = Pose()\npose.position.x = 0.3\n"
    )
    assert check_program(program) == []


def test_a_program_s_own_function_binds_before_a_tool_of_the_same_name_and_may_take_keywords():
    # GPT-4 defined its own move_in_direction(direction, distance=0.25) from get_gripper_pose and move_to_pose.
    own = "def move_in_direction(direction, distance=0.25, speed=1.0):\n    pass\n"
    assert check_program(own + "move_in_direction([1, 0, 0], speed=0.5)\n") == []
    (finding,) = check_program(own + "move_in_direction([1, 0, 0], axis=[0, 0, 1])\n")  # no aliases for its own
    assert finding.outcome == Outcome.BAD_ARGUMENTS and "(direction, distance, speed)" in finding.message
    helper = "def carry(name, **where):\n    pass\ncarry('apple', receptacle_name='table')\n"
    assert check_program(helper) == []


def test_the_prompt_is_built_from_the_tool_api_itself():
    prompt = system_prompt()
    for name in ToolAPI.TOOL_NAMES:
        method = getattr(ToolAPI, name)
        assert f"def {method.usage}:" in prompt
        assert inspect.getdoc(method).splitlines()[0] in prompt


def test_the_prompt_says_where_the_robots_base_stands_where_that_is_known():
    # Two authors of a batch read "the robot's frame" as the base at the origin, and kept only spots 30 to 75 cm
    # from it; the world's origin is the middle of the table. The rules say the origin is not the base, and where
    # the base is when the backend is known.
    plain = " ".join(system_prompt().split())
    assert "in the world's frame" in plain and "Its origin is not the robot's base." in plain
    assert "robot's frame" not in plain
    told = " ".join(system_prompt((-0.45, 0.0)).split())
    assert "Its origin is not the robot's base, which stands at x = -0.45, y = 0.00." in told


def test_the_examples_are_ten_or_more_and_pass_the_checker():
    examples = load_examples()
    assert len(examples) >= 10
    for example in examples:
        assert example.query.startswith("objects = [") and " ; # " in example.query
        assert example.program.startswith("# "), f"{example.name}: planning comments come first"
        assert check_program(example.program) == [], example.name
    messages = program_messages(task_query(["apple"], "lift the apple"), examples)
    assert len(messages) == 2 + 2 * len(examples) and messages[-1]["content"].endswith("# lift the apple")


def test_code_is_taken_out_of_fences_or_used_as_it_is():
    assert extract_code("Here:\n```python\nopen_gripper()\n```\nDone.") == "open_gripper()\n"
    assert extract_code("```\na = 1\n```\ntext\n```py\nb = 2\n```") == "a = 1\n\nb = 2\n"
    assert extract_code("```python\nopen_gripper()\n") == "open_gripper()\n"
    assert extract_code("close_gripper()") == "close_gripper()\n"


MAIN = """Here is the program.
```python
# Task: put the apple into the footed bowl.
# Plan:
# 1. Pick the apple and place it into the footed bowl with a helper.
detect_objects()
pick_and_place('apple', 'footed_bowl')
```"""

HELPER = """```python
def pick_and_place(name, receptacle):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    lift(0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    lift(0.1)


pick_and_place('apple', 'footed_bowl')  # an example call, dropped
```"""

LIFT = "```python\ndef lift(height):\n    move_in_direction([0, 0, 1], height)\n```"


def test_an_undefined_helper_is_generated_and_the_task_done_through_a_real_server():
    with ScriptedChatServer([{"text": MAIN}, {"text": HELPER}, {"text": LIFT}]) as server:
        spec = TrialSpec("simple_0", "panda", 0, 0, LLMAuthor(f"openai:scripted@{server.url}"), timeout=120)
        (record,) = run_isolated([spec])
    assert record.ok, record.error
    assert record.outcome == Outcome.OK.value and record.success
    assert "def pick_and_place(name, receptacle):" in record.program and "def lift(height):" in record.program
    assert record.program.count("pick_and_place('apple', 'footed_bowl')") == 1
    assert [e["purpose"] for e in record.llm_exchanges] == ["program", "function pick_and_place", "function lift"]
    assert len(server.requests) == 3
    query = server.requests[0]["messages"][-1]["content"]
    assert query == get_task("simple_0").query  # the paper's query, verbatim
    rules = " ".join(server.requests[0]["messages"][0]["content"].split())
    assert "the robot's base, which stands at x = -0.45, y = 0.00." in rules  # the trial's backend told it
    assert "pick_and_place" in server.requests[1]["messages"][-1]["content"]


def test_helper_generation_is_bounded_and_cycle_safe():
    looping = "```python\ndef a():\n    b()\n\ndef b():\n    a()\n    c()\n```"
    with ScriptedChatServer([{"text": "```python\na()\n```"}, {"text": looping}, {"text": "no code here"}]) as server:
        generation = CodeAgent(make_llm(f"openai:m@{server.url}"), examples=[], max_depth=2).write_program("q")
    assert generation.helpers == ["a"] and generation.unresolved == ["c"]
    assert undefined_calls(generation.program)[0].name == "c"
    assert len(server.requests) == 3  # the program, a (which brought b along), c (no definition)


def test_a_model_whose_every_helper_calls_new_names_is_asked_a_bounded_number_of_times():
    from roboscript.codegen.agent import MAX_DEFINED

    # The program calls ten names; each definition asked for calls ten new ones: 1 + 10 + 100 requests unbounded.
    answers = [{"text": "```python\n" + "\n".join(f"f{i}()" for i in range(10)) + "\n```"}]
    for i in range(10):
        calls = "\n".join(f"    g{i}_{k}()" for k in range(10))
        answers.append({"text": f"```python\ndef f{i}():\n{calls}\n```"})
    answers.append({"text": "no code here"})
    with ScriptedChatServer(answers) as server:
        generation = CodeAgent(make_llm(f"openai:m@{server.url}"), examples=[], max_depth=3).write_program("q")
    assert generation.helpers == [f"f{i}" for i in range(10)]
    assert len(server.requests) == 1 + MAX_DEFINED
    assert generation.unresolved  # what was left undefined is said, and the checker will refuse the program


def test_a_model_that_cannot_be_reached_is_an_llm_error_trial():
    spec = TrialSpec("simple_0", "panda", 0, 0, LLMAuthor("openai:m@http://127.0.0.1:9/v1"), timeout=60)
    (record,) = run_isolated([spec])
    assert record.outcome == Outcome.LLM_ERROR.value and "cannot reach" in record.error
    assert not record.success


def test_run_with_an_llm_that_cannot_be_reached_is_a_usage_error_not_a_failed_task():
    run = _cli("run", "Put the apple into the footed bowl", "--task", "simple_0", "--llm", "openai:m@http://127.0.0.1:9/v1")
    assert run.returncode == 2, run.stdout + run.stderr
    assert "roboscript: error: the LLM could not be asked, so no program ran: LLMError: cannot reach" in run.stderr
    assert "trial 0 (seed 0): no program: the LLM could not be asked" in run.stdout
    assert "failed: in(apple" not in run.stdout  # nothing ran, so no check is reported as failed


def _cli(*args: str) -> subprocess.CompletedProcess:
    command = [sys.executable, "-m", "roboscript.cli", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=600)


def test_run_and_bench_with_an_llm_policy_save_each_generated_program(tmp_path):
    reply = "```python\n" + get_task("simple_0").reference_program() + "```"
    with ScriptedChatServer([{"text": reply}]) as server:
        llm = f"openai:scripted@{server.url}"
        run = _cli("run", "Put the apple into the footed bowl", "--task", "simple_0", "--llm", llm, "--json")
        assert run.returncode == 0, run.stderr
        result = json.loads(run.stdout.strip().splitlines()[-1])
        assert result["whole_task_success"] == 1.0 and result["programs"][0].startswith("# Task")
        assert server.requests[0]["messages"][-1]["content"].endswith("# Put the apple into the footed bowl")
        out = tmp_path / "bench"
        bench = _cli("bench", "--policy", f"llm:{llm}", "--tasks", "simple_0", "--trials", "1", "--out", str(out))
        assert bench.returncode == 0, bench.stderr
        assert "1/1 100% | ok 1 failed 0 |" in bench.stderr and "ETA" in bench.stderr  # the progress bar
        assert "1 trial in " in bench.stdout and " trials an hour with " in bench.stdout
    (record,) = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
    assert record["outcome"] == "ok" and record["program"].startswith("# Task")
    assert record["llm_exchanges"][0]["response"] == reply
    missing = _cli("run", "x", "--task", "simple_0", "--llm", "nonsense")
    assert missing.returncode == 2 and "bad LLM spec 'nonsense'" in missing.stderr


def test_checker_errors_are_fed_back_and_the_repaired_program_runs():
    broken = "```python\n" + get_task("simple_0").reference_program().replace("object_name='apple'", "obj='apple'")
    fixed = "```python\n" + get_task("simple_0").reference_program() + "```"
    with ScriptedChatServer([{"text": broken + "```"}, {"text": broken + "```"}, {"text": fixed}]) as server:
        llm = f"openai:scripted@{server.url}"
        unrepaired = TrialSpec("simple_0", "panda", 0, 0, LLMAuthor(llm), timeout=120)
        repaired = TrialSpec("simple_0", "panda", 0, 0, LLMAuthor(llm, 2), timeout=120)
        first, second = run_isolated([unrepaired]) + run_isolated([repaired])
    assert first.outcome == Outcome.BAD_ARGUMENTS.value and "has no argument 'obj'" in first.error
    assert first.repairs == 0 and not first.success and first.attempts == []
    assert second.outcome == Outcome.OK.value and second.success and second.repairs == 1
    assert [a["outcome"] for a in second.attempts] == ["bad_arguments", "ok"]
    feedback = server.requests[-1]["messages"][-1]["content"]
    assert "bad_arguments" in feedback and "has no argument 'obj'" in feedback
    assert server.requests[-1]["messages"][-2]["role"] == "assistant"


def test_a_runtime_error_is_fed_back_and_the_repair_runs_in_a_fresh_world_both_results_reported(tmp_path):
    # The first program prints, then fails; the LLM sees the error and the output and writes the reference program.
    failing = (
        "```python\nopen_gripper()\napple = get_object_center_position('apple')\n"
        "print('apple at', apple)\nsteps = {'grasp': 1}\nnext_step = steps['place']\n```"
    )
    fixed = "```python\n" + get_task("simple_0").reference_program() + "```"
    with ScriptedChatServer([{"text": failing}, {"text": fixed}]) as server:
        policy = f"llm:openai:scripted@{server.url}"
        result = run_benchmark(
            policy, ["simple_0"], "panda", 1, 0, tmp_path, jobs=1, timeout=120, progress=False, repair_rounds=2
        )
    (record,) = [json.loads(line) for line in (tmp_path / "results.jsonl").read_text().splitlines()]
    assert [a["outcome"] for a in record["attempts"]] == ["runtime_error", "ok"] and record["repairs"] == 1
    assert "KeyError: 'place' (program line 5)" in record["attempts"][0]["error"]
    feedback = server.requests[-1]["messages"][-1]["content"]
    assert "runtime_error: KeyError: 'place' (program line 5)" in feedback and "apple at [" in feedback
    assert "reset" in feedback
    assert result["summary"]["simple_0"]["whole_task_success"] == 1.0
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["without_repair"]["simple_0"]["whole_task_success"] == 0.0
    assert summary["without_repair"]["simple_0"]["grammar_correctness"] == 0.0
    table = (tmp_path / "summary.md").read_text()
    assert "| Whole task success, no repair | 0.00 |" in table and "| Whole task success, repair ≤2 | 1.00 |" in table
    assert "| Outcomes, no repair | runtime_error 1 |" in table and "| Outcomes, repair ≤2 | ok 1 |" in table


def test_run_in_a_world_without_a_task_acts_and_checks_nothing():
    program = "```python\nopen_gripper()\nmove_in_direction([0, 0, 1], 0.05)\nprint('done')\n```"
    with ScriptedChatServer([{"text": program}]) as server:
        llm = f"openai:scripted@{server.url}"
        run = _cli("run", "Lift the hand a little", "--world", "world_2_pick_and_place", "--llm", llm, "--show-code")
    assert run.returncode == 0, run.stderr
    assert "trial 0 (seed 0): ran to its end" in run.stdout and "nothing was checked" in run.stdout
    assert "move_in_direction" in run.stdout and "    printed:\n      done" in run.stdout
    # what the trial is doing is shown as it happens, on stderr
    stages = ["building the world", "asking openai:scripted@", "checking the program", "running the program",
              "the program ended", "evaluating what it did"]  # fmt: skip
    at = [run.stderr.find(f"trial 0: {stage}") for stage in stages]
    assert -1 not in at and at == sorted(at), run.stderr
    assert server.requests[0]["messages"][-1]["content"].endswith("# Lift the hand a little")
    both = _cli("run", "x", "--world", "world_2_pick_and_place", "--task", "simple_0", "--llm", llm)
    assert both.returncode == 2 and "not allowed with argument" in both.stderr
    unknown = _cli("run", "x", "--world", "world_99", "--llm", llm)
    assert unknown.returncode == 2 and "world_99" in unknown.stderr


def test_an_llm_that_fails_during_repair_leaves_the_attempt_standing_with_the_reason():
    failing = "```python\nsteps = {}\nnext_step = steps['place']\n```"
    with ScriptedChatServer([{"text": failing}, {"status": 500}]) as server:
        llm = f"openai:scripted@{server.url}"
        spec = TrialSpec("simple_0", "panda", 0, 0, LLMAuthor(llm, 2), timeout=60)
        (record,) = run_isolated([spec])
    assert record.outcome == Outcome.RUNTIME_ERROR.value and "KeyError" in record.error
    (attempt,) = record.attempts
    assert attempt["repair_error"].startswith("LLMError:") and "500" in attempt["repair_error"]
    with pytest.raises(ValueError, match="repair rounds must be 0 or more"):
        LLMAuthor(llm, -1)


def test_the_prompt_names_every_kind_of_thing_the_gripper_cannot_pick_up():
    # A sorting task's readers (three of three) took a blue saucer for one of "the blue objects" and failed at its
    # grasp: what cannot be moved is a fact a program cannot have unless the prompt says it.
    from roboscript.objects.library import object_types

    prompt = system_prompt()
    start = prompt.index("- Plates, saucers")
    rule = prompt[start : prompt.index("\n- ", start + 1)].lower()
    kinds = {t.category.split()[-1] for t in object_types().values() if not t.pickable}
    assert kinds and all(f"{kind}s" in rule for kind in kinds) and "cannot pick" in rule


def test_every_query_lists_a_cabinets_drawers_and_doors_from_the_top_row_down():
    # The prompt says so: where a cabinet has a door and drawers, the handles' numbers say nothing of which row is
    # the door's, and a reader of the query (three door programs of a batch) had to guess it from the heights.
    import re

    from roboscript.bench.tasks import load_suite
    from roboscript.sim.world_catalog import load_world

    assert "lists a cabinet's drawers\n  and doors row by row from the top, whatever their kind" in system_prompt()
    listed = 0
    for suite in ("paper", "generated"):
        for task in load_suite(suite).values():
            names = re.search(r"objects = \[(.*?)\]", task.query).group(1).split(", ")
            for cabinet in load_world(task.world).cabinets:
                rows = [part for _, part in cabinet.row_parts()]
                parts = [n for n in names if n in rows]
                assert parts == [r for r in rows if r in parts], (task.query, rows)
                listed += bool(parts)
    assert listed > 100
