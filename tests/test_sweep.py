"""Sweeps: their files, the progress line, and running them on a process pool, on a real local Ray cluster, and
again after being killed."""

import io
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
import yaml

from helpers import sweep_outcomes
from roboscript.bench.progress import ProgressBar
from roboscript.bench.results import read_records
from roboscript.bench.stats import wilson_interval
from roboscript.bench.trial import TrialRecord
from roboscript.study.sweep import LocalExecutor, plan_sweep, run_sweep
from roboscript.study.sweep_file import SweepFileError, load_sweep_file, parse_sweep

# Cells of the object-shape study with an object every grasp tool takes and one too wide for the Panda's opening,
# so that outcomes differ between cells and must match trial by trial.
STUDY = {"name": "objects", "templates": ["pick_place"], "objects": ["apple", "tuna_can"]}


def _sweep(tmp_path: Path, **fields) -> Path:
    data = {"sweep": "small", "study": STUDY, "trials": 2, **fields}
    path = tmp_path / "sweep.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def test_wilson_interval_known_values():
    low, high = wilson_interval(5, 10)
    assert (round(low, 4), round(high, 4)) == (0.2366, 0.7634)
    assert wilson_interval(0, 10)[0] == 0.0 and round(wilson_interval(0, 10)[1], 4) == 0.2775
    assert round(wilson_interval(10, 10)[0], 4) == 0.7225 and wilson_interval(10, 10)[1] == pytest.approx(1.0)
    with pytest.raises(ValueError, match=r"within 0\.\.10"):
        wilson_interval(11, 10)


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ({"robots": ["panda", "kuka"]}, "unknown robot 'kuka'; valid robots: fr3, panda, ur5e"),
        ({"policies": ["gpt4"]}, "unknown policy 'gpt4'"),
        ({"perception": ["gt", "lidar"]}, "lidar"),
        ({"trials": 0}, "'trials' must be a whole number of at least 1"),
        ({"videos": "some"}, "videos must be one of none, failed, all"),
        ({"tasks": ["simple_0"]}, "a study's tasks are its cells"),
        ({"study": {"name": "objects", "objects": ["aple"]}}, "unknown object of the study 'aple'"),
        ({"study": {"name": "objects", "grasps": ["suction"]}}, "unknown grasp tool 'suction'"),
        ({"trails": 3}, "unknown field 'trails' (did you mean 'trials'?)"),
    ],
)
def test_sweep_file_errors_name_the_problem_and_the_choices(tmp_path, fields, message):
    with pytest.raises(SweepFileError, match=re.escape(message)) as info:
        load_sweep_file(_sweep(tmp_path, **fields))
    assert str(tmp_path / "sweep.yaml") in str(info.value)


def test_a_suite_sweep_names_unknown_tasks():
    with pytest.raises(
        SweepFileError, match=re.escape("no task 'simple_9' in suite 'paper'; did you mean simple_1, simple_0")
    ):
        parse_sweep({"sweep": "s", "suite": "paper", "tasks": ["simple_9"]})


def test_plan_makes_a_run_per_combination_and_skips_what_is_done(tmp_path):
    sweep = parse_sweep({"sweep": "s", "suite": "paper", "tasks": ["simple_0", "hard_2"], "trials": 3,
                         "robots": ["panda", "ur5e"], "perception": ["gt", "gt-3d"]})  # fmt: skip
    runs = plan_sweep(sweep, tmp_path)
    assert sorted(r.name for r in runs) == sorted(
        ["reference_panda_gt", "reference_panda_gt-3d", "reference_ur5e_gt", "reference_ur5e_gt-3d"]
    )
    assert all(len(r.pending) == 6 for r in runs)
    first = runs[0]
    done = TrialRecord(task="hard_2", robot=first.robot, trial=1, seed=1, ok=True, error=None)
    first.directory.append(done)
    again = {r.name: r for r in plan_sweep(sweep, tmp_path)}
    assert len(again[first.name].pending) == 5
    assert ("hard_2", 1) not in {(s.task, s.trial) for s in again[first.name].pending}
    assert {str(s.perception) for s in again["reference_ur5e_gt-3d"].pending} == {"gt-3d"}


def test_progress_bar_counts_and_estimates():
    now = [100.0]
    stream = io.StringIO()
    bar = ProgressBar(10, done_before=2, stream=stream, clock=lambda: now[0])
    assert bar.eta() is None
    for i in range(4):
        now[0] += 5.0
        ok = [{"check": "in(a, b)", "passed": i != 2}]
        bar.update(TrialRecord(task="t", robot="panda", trial=i, seed=i, ok=True, error=None, checks=ok))
    lines = stream.getvalue().splitlines()
    assert len(lines) == 4  # not a terminal: a line per trial
    assert "6/10" in lines[-1] and "ok 3 failed 1 (+2 earlier)" in lines[-1]
    assert bar.eta() == pytest.approx(20.0)  # 5 s a trial, 4 left
    assert "ETA 0m20s" in lines[-1] and "t #3: ok" in lines[-1]


def test_a_sweep_on_ray_ends_each_trial_as_the_process_pool_does(tmp_path):
    ray = pytest.importorskip("ray")
    from roboscript.study.ray_executor import RayExecutor

    sweep = load_sweep_file(_sweep(tmp_path))
    pool_runs = run_sweep(sweep, tmp_path / "pool", LocalExecutor(2), progress=False)
    scratch_before = set(Path(tempfile.gettempdir()).glob("roboscript-ray-*"))
    executor = RayExecutor(jobs=2)  # a local cluster it starts, on loopback
    try:
        assert ray.cluster_resources()["CPU"] == 2
        assert [n["NodeManagerAddress"] for n in ray.nodes()] == ["127.0.0.1"]
        ray_runs = run_sweep(sweep, tmp_path / "ray", executor, progress=False)
    finally:
        executor.close()
    (pool_run,), (ray_run,) = pool_runs, ray_runs
    pooled, rayed = sweep_outcomes(pool_run.directory.path), sweep_outcomes(ray_run.directory.path)
    assert len(pooled) == 2 * 3 * 2  # 2 objects x 3 grasp tools x 2 trials
    assert rayed == pooled
    assert {o[1] for o in pooled.values()} == {"ok", "planning_failure"}  # the can is wider than the opening
    assert {r.node for r in pool_run.directory.records()} == {""}
    assert {r.node for r in ray_run.directory.records()} == {"127.0.0.1"}
    # The actors removed their scratch folders (copies of the suite) as the run ended.
    assert set(Path(tempfile.gettempdir()).glob("roboscript-ray-*")) <= scratch_before


def test_a_record_keeps_the_node_that_ran_it_and_one_written_before_nodes_were_kept_still_reads(tmp_path):
    results = tmp_path / "results.jsonl"
    record = TrialRecord(task="t", robot="panda", trial=0, seed=0, ok=True, error=None, node="10.0.0.2")
    older = {k: v for k, v in record.to_dict().items() if k != "node"}
    results.write_text(json.dumps(record.to_dict()) + "\n" + json.dumps({**older, "trial": 1}) + "\n")
    assert [(r.trial, r.node) for r in read_records(results)] == [(0, "10.0.0.2"), (1, "")]


def test_a_killed_sweep_resumes_with_nothing_lost_or_repeated(tmp_path):
    path = _sweep(tmp_path, study={**STUDY, "objects": ["apple"], "grasps": ["central", "adaptive"]})
    out = tmp_path / "out"
    command = [sys.executable, "-m", "roboscript.cli", "sweep", str(path), "--jobs", "1", "--out", str(out)]
    results = out / "reference_panda_gt" / "results.jsonl"
    process = subprocess.Popen(command, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 600
        while not (results.is_file() and len(results.read_text().splitlines()) >= 2):
            assert process.poll() is None, process.stderr.read().decode()
            assert time.monotonic() < deadline, "no two trials ended in 10 minutes"
            time.sleep(0.2)
    finally:
        os.killpg(process.pid, signal.SIGKILL)  # the sweep, its workers and the trial running: nothing cleans up
        process.wait()
    before = results.read_text().splitlines()
    assert 2 <= len(before) < 4
    finished = subprocess.run(command, capture_output=True, text=True, timeout=900)
    assert finished.returncode == 0, finished.stderr
    after = results.read_text().splitlines()
    assert after[: len(before)] == before  # what ended before the kill is kept as it was
    keys = [(r["task"], r["trial"]) for r in map(json.loads, after)]
    assert sorted(keys) == sorted(
        (f"pick_place.apple.{g}", t) for g in ("central", "adaptive") for t in range(2)
    )  # every trial once
    assert f"(+{len(before)} earlier)" in finished.stderr


def test_an_unknown_task_of_a_large_suite_says_how_many_there_are_instead_of_listing_them():
    from roboscript.bench.tasks import get_task

    with pytest.raises(KeyError) as small:
        get_task("simple_9", "paper")
    assert "Tasks: simple_0" in str(small.value)  # eight tasks: listed
    with pytest.raises(KeyError) as large:
        get_task("swap.gen_999", "generated")
    message = str(large.value)
    assert "did you mean swap.gen_" in message and "roboscript tasks --suite generated" in message
    assert "onto_plate.gen_000" not in message and len(message) < 300
