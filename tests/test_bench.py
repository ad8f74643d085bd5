"""The benchmark: checks on ground truth, metrics, resumable run directories, and ``roboscript exec`` on
programs that fail in every way a program can (run through the real command, in child processes)."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.checks import Check, at, inside, joint_above, on
from roboscript.bench.metrics import metrics
from roboscript.bench.results import RunDirectory, provenance
from roboscript.bench.tasks import get_task
from roboscript.bench.trial import COULD_NOT_RUN, TrialRecord

GENERATED = Path(__file__).parent / "data" / "generated_code"


def record(trial, ok, passed, total=2):
    checks = [{"check": f"c{i}", "passed": i < passed, "detail": ""} for i in range(total)]
    return TrialRecord("simple_0", "panda", trial, trial, ok, None if ok else "boom", checks)


def test_checks_on_ground_truth():
    backend = MujocoBackend("world_3_mug_to_empty_plate", settle=0.5)
    gt = backend.ground_truth
    assert on("lemon", "turquoise_salad_plate").evaluate(gt).passed
    assert not on("lemon", "white_ceramic_plate").evaluate(gt).passed
    assert not inside("lemon", "white_ceramic_plate").evaluate(gt).passed
    assert on("lemon", "table").evaluate(gt).passed
    assert Check("on", "lemon", "white_ceramic_plate", negate=True).evaluate(gt).passed
    below = on("turquoise_salad_plate", "lemon").evaluate(gt)  # the plate is not above the lemon
    assert not below.passed and "above: False" in below.detail
    assert json.loads(json.dumps(below.to_dict()))["passed"] is False  # records hold plain booleans
    lemon = gt.box("lemon").center
    assert at("lemon", lemon).evaluate(gt).passed
    assert not at("lemon", lemon + np.array([0.15, 0, 0])).evaluate(gt).passed
    backend.close()
    cabinet = MujocoBackend("world_5_mug_to_cabinet", settle=0.2)
    result = joint_above("cabinet.drawer_1", 0.1).evaluate(cabinet.ground_truth)
    assert not result.passed and "at 0.000" in result.detail
    cabinet.close()


def test_metrics():
    m = metrics([record(0, True, 2), record(1, False, 1), record(2, True, 0)])
    assert m == {
        "grammar_correctness": pytest.approx(2 / 3, abs=1e-4),
        "semantic_correctness": 1.0,
        "finished_steps_ratio": pytest.approx(0.5),
        "whole_task_success": pytest.approx(1 / 3, abs=1e-4),
    }
    assert metrics([record(0, True, 1)])["semantic_correctness"] == 0.0


def test_run_directory_resumes_and_refuses_mixing(tmp_path):
    run = provenance("reference", "panda", 3, 0, {"simple_0": "program A"}, "gt")
    directory = RunDirectory(tmp_path, run)
    directory.append(record(0, True, 2))
    with directory.results.open("a") as f:
        f.write('{"task": "simple_0", "rob')  # a line cut short by an interruption
    again = RunDirectory(tmp_path, provenance("reference", "panda", 3, 0, {"simple_0": "program A"}, "gt"))
    assert again.done() == {("simple_0", "panda", 0)}
    summary = again.write_summary(["simple_0"])
    assert summary["tasks"]["simple_0"]["whole_task_success"] == 1.0
    assert "| Whole task success | 1.00 |" in (tmp_path / "summary.md").read_text()
    assert (tmp_path / "summary.csv").read_text().startswith("task,trials,grammar_correctness")
    with pytest.raises(ValueError, match="another program for simple_0"):
        RunDirectory(tmp_path, provenance("reference", "panda", 3, 0, {"simple_0": "program B"}, "gt"))
    with pytest.raises(ValueError, match="robot='panda', not 'ur5e'"):
        RunDirectory(tmp_path, provenance("reference", "ur5e", 3, 0, {"simple_0": "program A"}, "gt"))
    with pytest.raises(ValueError, match="backend='mujoco', not 'ros'"):
        RunDirectory(tmp_path, provenance("reference", "panda", 3, 0, {"simple_0": "program A"}, "gt", backend="ros"))


def test_a_run_resumed_from_other_code_names_every_commit_that_wrote_to_it(tmp_path):
    first = {**provenance("reference", "panda", 3, 0, {"simple_0": "program A"}, "gt"), "git_commit": "aaa"}
    RunDirectory(tmp_path, first)
    RunDirectory(tmp_path, {**first, "git_commit": "bbb"})
    again = RunDirectory(tmp_path, {**first, "git_commit": "bbb"})
    assert again.run["git_commit"] == "aaa"  # where it began
    assert again.run["git_commits"] == ["aaa", "bbb"]


def test_a_resumed_run_tries_again_the_trials_that_never_ran_and_counts_each_trial_once(tmp_path):
    """A trial whose world or sandbox could not be set up (a missing library, a full disk) is not the program's
    failure: resuming runs it again, and its new record stands for it (once run on a machine where every trial
    failed so, a resumed run used to take them all as done)."""
    run = provenance("reference", "panda", 2, 0, {"simple_0": "program A"}, "gt")
    directory = RunDirectory(tmp_path, run)
    directory.append(TrialRecord("simple_0", "panda", 0, 0, False, f"{COULD_NOT_RUN}: ImportError: no EGL", []))
    directory.append(record(1, False, 1))  # the program's own failure stands
    again = RunDirectory(tmp_path, provenance("reference", "panda", 2, 0, {"simple_0": "program A"}, "gt"))
    assert again.done() == {("simple_0", "panda", 1)}
    again.append(record(0, True, 2))
    assert [(r.trial, r.ok) for r in again.records()] == [(0, True), (1, False)]
    assert again.write_summary(["simple_0"])["tasks"]["simple_0"]["whole_task_success"] == 0.5


def exec_json(tmp_path, source, *args, code=0):
    """``roboscript exec --json`` of ``source`` on simple_0; its exit code must be ``code``."""
    program = tmp_path / "program.py"
    program.write_text(source)
    out = subprocess.run(
        [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", "--json", *args],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert out.returncode == code, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize(
    ("source", "error"),
    [
        (
            "x = get_object_center_position('aple')\n",
            "UnknownObjectError: no object named 'aple'; did you mean 'apple'",
        ),
        ("while True:\n    pass\n", "TimeoutError: the program ran longer than its 3 s limit"),
    ],
)
def test_exec_reports_each_failing_trial_as_a_grammar_failure_and_goes_on(tmp_path, source, error):
    result = exec_json(tmp_path, source, "--trials", "2", "--timeout", "3", "--jobs", "2", code=1)
    assert result["task"] == "simple_0" and result["trials"] == 2
    assert result["grammar_correctness"] == 0.0 and result["whole_task_success"] == 0.0
    assert [t["trial"] for t in result["per_trial"]] == [0, 1]
    for trial in result["per_trial"]:
        assert trial["ok"] is False and error in trial["error"]
        assert trial["checks"] and trial["checks"][0]["passed"] is False
    if "line" in error:
        assert "(program line 1)" in result["per_trial"][0]["error"]


@pytest.mark.parametrize(
    ("source", "outcome", "error"),
    [
        ("print('hello')\nopen_gripper(\n", "syntax", "SyntaxError: '(' was never closed (program line 2)"),
        ("get_object_names()\n", "unknown_function", "did you mean get_object_name_list"),
        ("import os\n", "forbidden_construct", "import of 'os' is not allowed"),
    ],
)
def test_exec_reports_a_program_the_checks_refuse_once_before_any_trial(tmp_path, source, outcome, error):
    """Ten trials of a program that cannot run would say the same thing ten times: it is said once, nothing runs,
    and the exit status says the task failed."""
    program = tmp_path / "program.py"
    program.write_text(source)
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", "--trials", "10"]
    out = subprocess.run(command, capture_output=True, text=True, timeout=600)
    assert out.returncode == 1, out.stderr
    assert out.stdout.count(error) == 1 and "not run: refused before any trial" in out.stdout
    assert "trial 0" not in out.stdout + out.stderr and "hello" not in out.stdout  # no trial ran, nothing printed
    result = exec_json(tmp_path, source, "--trials", "10", code=1)
    assert result["trials"] == 0 and result["outcome"] == outcome and error in result["error"]
    assert result["per_trial"] == [] and result["grammar_correctness"] == 0.0  # a run's document, with no trial


def test_an_llm_runs_default_folder_is_named_by_its_model_not_its_endpoint():
    from roboscript.bench.benchmark import default_out, folder_label

    local = "llm:openai:gpt-4o@http://127.0.0.1:8080/v1"
    assert default_out(folder_label(local), "panda") == "out/bench/llm-gpt-4o_panda"
    assert folder_label("llm:llama:/models/qwen2.5-coder-7b.Q4_K_M.gguf", 1) == "llm-qwen2.5-coder-7b.Q4_K_M+repair1"
    assert folder_label("llm:cache:out/cache=openai:gpt-4o-mini@http://h/v1") == "llm-gpt-4o-mini"
    assert folder_label("programs:tests/data/gpt4_answers/") == "programs-gpt4_answers"
    assert folder_label("reference") == "reference"


def test_exec_runs_the_reference_program_and_records_a_video(tmp_path):
    video = tmp_path / "trial.mp4"
    source = get_task("simple_0").reference_program()
    result = exec_json(tmp_path, source, "--trials", "1", "--video", str(video))
    (trial,) = result["per_trial"]
    assert trial["ok"], trial["error"]
    assert result["whole_task_success"] == 1.0
    data = video.read_bytes()
    assert len(data) > 10_000 and b"ftyp" in data[:64]


def test_a_trial_is_repeatable_from_its_seed(tmp_path):
    """The seed fixes the world's randomisation and the sampling planners: the same trial runs the same way."""
    source = get_task("moderate_1").reference_program()
    args = ("--task", "moderate_1", "--trials", "1", "--seed", "5")  # a drawer, a pick and a place
    runs = [exec_json(tmp_path, source, *args)["per_trial"][0] for _ in range(2)]
    assert runs[0]["ok"], runs[0]["error"]
    assert runs[0]["sim_time_s"] == runs[1]["sim_time_s"]
    assert runs[0]["checks"] == runs[1]["checks"]


def test_stored_programs_in_the_originals_generated_code_format_run_as_a_policy(tmp_path):
    """A JSON file as the original stores its LLMs' programs: its entry for simple_0 (matched by its query, in
    the eval-items form) runs with its generated function; an entry for no task of the suite is reported."""
    policy = ["--policy", f"programs:{GENERATED}", "--tasks", "simple_0", "--trials", "1", "--jobs", "1"]
    command = [sys.executable, "-m", "roboscript.cli", "bench", *policy, "--out", str(tmp_path / "run"), "--json"]
    out = subprocess.run(command, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "not used: " in out.stderr and "put the bowl on the apple" in out.stderr
    result = json.loads(out.stdout.strip().splitlines()[-1])
    assert result["tasks"]["simple_0"]["whole_task_success"] == 1.0
    (record,) = [json.loads(line) for line in (tmp_path / "run" / "results.jsonl").read_text().splitlines()]
    assert record["program_source"].endswith("raw_world_2_pick_and_place.json[0]")
    run = json.loads((tmp_path / "run" / "run.json").read_text())
    assert run["policy"] == f"programs:{GENERATED}" and run["suite"] == "paper"


def test_stored_programs_missing_a_task_are_refused_before_anything_runs(tmp_path):
    (tmp_path / "simple_0.py").write_text("open_gripper()\n")
    (tmp_path / "simple_9.py").write_text("open_gripper()\n")
    policy = ["--policy", f"programs:{tmp_path}", "--tasks", "simple_0,hard_2"]
    command = [sys.executable, "-m", "roboscript.cli", "bench", *policy, "--out", str(tmp_path / "run")]
    out = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert out.returncode == 2
    assert "no stored program in" in out.stderr and "for hard_2 (programs found for: simple_0)" in out.stderr
    assert "simple_9.py (no task 'simple_9')" in out.stderr
    assert not (tmp_path / "run" / "results.jsonl").exists()


def _descendants(pid: int) -> set[int]:
    """Every process below ``pid``, from /proc."""
    parents: dict[int, int] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                parents[int(entry.name)] = int((entry / "stat").read_text().rsplit(")", 1)[1].split()[1])
            except (OSError, ValueError, IndexError):
                continue
    found, frontier = set(), {pid}
    while frontier:
        frontier = {child for child, parent in parents.items() if parent in frontier} - found
        found |= frontier
    return found


def test_a_run_stopped_with_sigterm_leaves_no_trial_running(tmp_path):
    import signal
    import time

    program = tmp_path / "slow.py"
    program.write_text("for i in range(100000):\n    get_gripper_pose()\n")
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", "--trials", "2"]
    run = subprocess.Popen([*command, "--jobs", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    trials: set[int] = set()
    while len(trials) < 3 and time.monotonic() < deadline:  # the fork server and both trials
        time.sleep(0.5)
        trials = _descendants(run.pid)
    assert len(trials) >= 3, "the trials did not start"
    time.sleep(3.0)
    run.send_signal(signal.SIGTERM)
    run.wait(timeout=60)
    # The fork server and its resource tracker end when their pipes close, which on a busy machine (two benchmarks
    # beside the suite) takes seconds: waited for, up to a minute, rather than looked at once.
    deadline = time.monotonic() + 60
    alive = _running(trials)
    while alive and time.monotonic() < deadline:
        time.sleep(0.5)
        alive = _running(trials)
    assert alive == {}, f"left running: {alive}"


def _running(pids: set[int]) -> dict[int, bytes]:
    """Of ``pids``, those still running (not exited, not a zombie waiting to be reaped), with their command lines."""
    alive = {}
    for pid in pids:
        try:
            state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
            command = Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ")[:200]
        except OSError:
            continue
        if state != "Z":  # a zombie has exited: it only waits to be reaped (by init, here)
            alive[pid] = command
    return alive


JSON_LOOKING = """print('{"task": "not the report", "whole_task_success": 1.0}')
print('[1, 2, 3]')
open_gripper()
grasp(parse_central_lift_grasp_pose('apple', 'center'))
close_gripper()
attach_object('apple')
beside = get_object_center_position('footed_bowl') + np.array([0.0, -0.12, 0.0])
move_to_pose(parse_place_pose('apple', 'table', position=beside))
open_gripper()
detach_object('apple')
print('}')
"""


def test_exec_json_is_one_document_whatever_the_program_and_the_tools_print(tmp_path):
    """Lines that look like JSON from the program, and a tool's notice (the apple's spot, taken by the bowl's rim,
    moved aside), go into the trial's output, never onto stdout beside the document."""
    program = tmp_path / "program.py"
    program.write_text(JSON_LOOKING)
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", "--trials", "1"]
    out = subprocess.run([*command, "--json"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 1, out.stderr  # the apple is beside the bowl, not in it: the task failed
    result = json.loads(out.stdout)  # the whole of stdout, not its last line
    trial = result["per_trial"][0]
    assert trial["error"] is None, trial["error"]
    lines = trial["output"].splitlines()
    assert lines[:2] == ['{"task": "not the report", "whole_task_success": 1.0}', "[1, 2, 3]"]
    assert any(line.startswith("[notice] parse_place_pose:") and "cm away" in line for line in lines)
    assert lines[-1] == "}"


def test_exec_shows_what_the_program_printed_and_what_the_tools_noticed_each_under_its_label(tmp_path):
    program = tmp_path / "program.py"
    program.write_text(JSON_LOOKING)
    video = tmp_path / "beside.mp4"
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0"]
    out = subprocess.run([*command, "--video", str(video)], capture_output=True, text=True, timeout=600)
    assert out.returncode == 1, out.stderr
    assert "  trial 0 (seed 0): checks failed, 0/1 checks" in out.stdout
    printed = '    printed:\n      {"task": "not the report", "whole_task_success": 1.0}\n      [1, 2, 3]\n      }\n'
    assert printed in out.stdout
    notices = out.stdout.split("    notices:\n", 1)[1].splitlines()
    assert notices[0].startswith("      parse_place_pose:") and "cm away" in notices[0]
    assert "[notice]" not in out.stdout
    assert f"    video: {video}" in out.stdout and video.stat().st_size > 0  # where the video went
