"""The project's hostile corpus (tests/data/hostile_programs): every program contained, as a trial's program is.

Each file names its class in a header (``# class: ...``) and what must become of it (``# expect: contained``,
or ``refused``: the static checker must not pass it). It runs in a confined program process with test-double
tools that answer as the real ones would (names, poses, boxes); ``MARK`` in it becomes a path that must not exist
afterwards, and the caller's environment holds a secret that must not appear in any output. A sample of each
class that aims at the trial's process runs through the real command, ``roboscript exec --json``, on a task: its
stdout must be one JSON document under 1 MB, without the secret, with no success.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from roboscript.api import Pose
from roboscript.api.program_errors import PROGRAM_ERRORS
from roboscript.api.tools import ToolAPI
from roboscript.codegen.checker import check_program
from roboscript.codegen.outcomes import STATIC, Outcome
from roboscript.codegen.program_process import run_program
from roboscript.codegen.sandbox import Limits

CORPUS = Path(__file__).parent / "data" / "hostile_programs"
PROGRAMS = sorted(CORPUS.glob("*.py"))
SECRET = "rs-secret-7f3a9c"
CLASSES = {
    "numpy_raw_memory", "format_walk", "pickle_into_trusted", "lazy_iterator", "swallowed_timeout",
    "unbounded_trusted_work", "secrets", "file_or_process", "guard_bypass", "output_flood",
}  # fmt: skip
ESCAPED = ("<built-in function __import__>", "<built-in function open>", "<module '", "<frame at 0x")
THROUGH_THE_COMMAND = (
    "pickle_into_trusted_1", "swallowed_timeout_1", "output_flood_1", "output_flood_6", "output_flood_7", "secrets_1",
    "lazy_iterator_1", "guard_bypass_6", "guard_bypass_7", "unbounded_trusted_work_11", "unbounded_trusted_work_12",
    "guard_bypass_10", "unbounded_trusted_work_13",
)  # fmt: skip


def header(path: Path) -> dict[str, str]:
    fields = {}
    for line in path.read_text().splitlines():
        if not line.startswith("# ") or ":" not in line:
            break
        key, _, value = line[2:].partition(":")
        fields[key.strip()] = value.strip()
    return fields


# Test doubles for the tools: the shapes of what the real ones return, no robot behind them.
def _answers() -> dict:
    pose = Pose([0.5, 0.0, 0.2], [0.0, 1.0, 0.0, 0.0])
    joint = {"joint_position": np.zeros(3), "joint_axis": np.array([1.0, 0, 0]), "type": "prismatic"}
    answers = dict.fromkeys(ToolAPI.TOOL_NAMES)
    answers |= {
        "get_object_name_list": ["apple", "footed_bowl", "cabinet.drawer_0", "cabinet.handle_0"],
        "get_object_center_position": np.array([0.5, 0.0, 0.05]),
        "get_object_pose": pose,
        "get_3d_bbox": np.array([0.45, -0.05, 0.0, 0.55, 0.05, 0.1]),
        "get_object_joint_info": joint,
        "get_plane_normal": np.array([1.0, 0.0, 0.0]),
        "is_object_in": False,
        "parse_central_lift_grasp_pose": pose,
        "parse_horizontal_grasp_pose": pose,
        "parse_adaptive_shape_grasp_pose": pose,
        "get_gripper_pose": pose,
        "parse_place_pose": pose,
        "generate_arc_path_around_joint": [pose, pose],
    }
    return answers


def _namespace(calls: list) -> dict:
    def tool(name, answer):
        def call(*args, **kwargs):
            calls.append(f"{name}{repr(args)[:200]}{repr(kwargs)[:200]}")  # bounded: a program's arguments are large
            return answer

        return call

    return {name: tool(name, answer) for name, answer in _answers().items()} | {"Pose": Pose, **PROGRAM_ERRORS}


def test_the_corpus_covers_every_class_three_times():
    classes = [header(p).get("class") for p in PROGRAMS]
    assert set(classes) <= CLASSES, set(classes) - CLASSES
    assert all(classes.count(c) >= 3 for c in CLASSES), {c: classes.count(c) for c in CLASSES}


@pytest.mark.parametrize("path", PROGRAMS, ids=[p.stem for p in PROGRAMS])
def test_a_hostile_program_is_contained(tmp_path, monkeypatch, path):
    monkeypatch.setenv("ROBOSCRIPT_TEST_SECRET", SECRET)
    mark = tmp_path / "mark"
    program = path.read_text().replace("MARK", str(mark))
    findings = check_program(program)  # the static checker runs in the trial's own process: it must not fail
    assert all(len(f.message) <= 1000 for f in findings) and len(findings) <= 51  # MAX_FINDINGS and "... more"
    if header(path).get("expect") == "refused":  # a hole the guard closes: it may not pass the checker
        assert findings, "the checker let it through"
    calls: list = []
    result = run_program(program, _namespace(calls), Limits(timeout=3.0, memory=1024**3), ToolAPI.TOOL_NAMES)
    said = f"{result.error} {result.output} {calls}"
    assert not mark.exists() and os.listdir(tmp_path) == [], result
    assert SECRET not in said and "root:x:0:0" not in said  # nothing of the environment, no file's content
    # Nor anything only an escape reaches: the real builtins, a module, a frame (seccomp is the last wall, not the
    # only one: a program that reached these and wrote nothing would pass the lines above).
    assert not any(sign in said for sign in ESCAPED), result
    assert len(result.output) <= 10_000 and len(result.error or "") <= 10_000
    if header(path).get("class") == "swallowed_timeout":  # ran to its time limit, or was stopped before
        assert result.outcome is not Outcome.OK, result


@pytest.mark.slow
@pytest.mark.parametrize("name", THROUGH_THE_COMMAND)
def test_a_hostile_program_as_a_trials_program_forges_nothing(tmp_path, name):
    mark = tmp_path / "mark"
    program = tmp_path / "program.py"
    program.write_text((CORPUS / f"{name}.py").read_text().replace("MARK", str(mark)))
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", "--trials", "1"]
    environment = {**os.environ, "ROBOSCRIPT_TEST_SECRET": SECRET}
    done = subprocess.run(
        [*command, "--timeout", "3", "--json"], capture_output=True, env=environment, timeout=600, check=False
    )
    assert len(done.stdout) < 1024**2
    result = json.loads(done.stdout)  # one JSON document, nothing else
    assert done.returncode == 1 and result["whole_task_success"] == 0.0
    if result["trials"] == 0:  # refused by the checks before any trial
        assert Outcome(result["outcome"]) in STATIC and result["per_trial"] == []
    else:
        assert result["per_trial"][0]["outcome"] != Outcome.OK.value
    assert SECRET.encode() not in done.stdout + done.stderr
    assert not mark.exists()
