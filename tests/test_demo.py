"""`roboscript demo`: the first task end to end with a video and a report, from the configured LLM or, said on
screen and in the report, from the reference program."""

from __future__ import annotations

import json
import os
import subprocess
import sys

from chat_server import ScriptedChatServer
from roboscript.bench.tasks import get_task


def _demo(out, env: dict) -> subprocess.CompletedProcess:
    clean = {k: v for k, v in os.environ.items() if not k.startswith("ROBOSCRIPT_LLM")}
    command = [sys.executable, "-m", "roboscript.cli", "demo", "--out", str(out)]
    return subprocess.run(command, capture_output=True, text=True, timeout=600, env={**clean, **env})


def _check_outputs(out) -> dict:
    report = json.loads((out / "report.json").read_text())
    assert report["record"]["outcome"] == "ok" and report["record"]["checks"][0]["passed"]
    video = out / "simple_0.mp4"
    assert video.stat().st_size > 10_000 and video.read_bytes()[4:8] == b"ftyp"  # an MP4 container
    assert "in(apple, footed_bowl) | yes" in (out / "report.md").read_text()
    return report


def test_demo_without_an_llm_runs_the_reference_program_and_says_so(tmp_path):
    run = _demo(tmp_path, {})
    assert run.returncode == 0, run.stderr
    assert "program: the reference program of simple_0: no LLM is configured" in run.stdout
    assert "task done" in run.stdout
    report = _check_outputs(tmp_path)
    assert "no LLM is configured" in report["program_source"]
    assert "no LLM is configured" in (tmp_path / "report.md").read_text()


def test_demo_with_the_llm_the_environment_configures(tmp_path):
    reply = "```python\n" + get_task("simple_0").reference_program() + "```"
    with ScriptedChatServer([{"text": reply}]) as server:
        run = _demo(tmp_path, {"ROBOSCRIPT_LLM": f"openai:scripted@{server.url}"})
    assert run.returncode == 0, run.stderr
    assert f"program: written by the LLM openai:scripted@{server.url}" in run.stdout
    report = _check_outputs(tmp_path)
    assert report["record"]["llm_exchanges"][0]["response"] == reply
    assert len(server.requests) == 1
