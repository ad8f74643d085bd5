"""The trial runner and its workers: a trial that crashes or hangs costs that trial only, later trials run on, and
a renderer kept for one build of a world renders another build of it exactly as its own would."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench import runner, workers
from roboscript.bench.runner import TrialPool
from roboscript.bench.trial import TrialRecord, TrialSpec
from roboscript.codegen.outcomes import Outcome
from roboscript.processes import at_process_exit
from roboscript.sim import shared_gl
from roboscript.sim.cameras import Renderer


# Test doubles for the trial a worker forks (module functions: the worker imports them by name).
def _fake_trial(spec: TrialSpec) -> dict:
    """Crashes, hangs or reports its own process id and whether it shares renderers, as the spec's task says."""
    if spec.task == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    if spec.task == "hang":
        time.sleep(3600)
    if spec.task == "stuck":  # a program's run that should be over in a second, in a tool that never returns
        workers._announce(time.monotonic() + 1.0)
        time.sleep(3600)
    if spec.task == "raise":
        raise RuntimeError("no world here")
    if spec.task == "noisy":  # a library that prints, in Python and in C
        print('{"whole_task_success": 1.0}', flush=True)
        os.write(1, b"NOISE from C\n")
    if spec.task == "clean up":  # what a trial's process must do before it ends (a ROS trial stops its master)
        at_process_exit(lambda: Path(spec.program).write_text("cleaned up"))
    if spec.task == "linger":  # leaves a process behind that holds the trial's end of the pipe to the worker
        lingering = os.fork()
        if lingering == 0:
            time.sleep(3600)
            os._exit(0)
        return TrialRecord(spec.task, spec.robot, 0, 0, True, None, output=str(lingering)).to_dict()
    return TrialRecord(spec.task, spec.robot, spec.trial, spec.seed, True, None, output=str(os.getpid())).to_dict()


def _no_warm(spec: TrialSpec) -> None:
    pass


def _spec(task: str, timeout: float = 300.0) -> TrialSpec:
    return TrialSpec(task, "panda", 0, 0, "", timeout=timeout)


def test_a_crashed_or_failing_trial_costs_only_itself_and_each_trial_has_a_process_of_its_own():
    with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:
        records = pool.run([_spec("ok"), _spec("crash"), _spec("raise"), _spec("ok")])
        again = pool.run([_spec("ok")])
    first, crashed, raised, last = records
    assert first.ok and last.ok and again[0].ok
    assert "process died (exit code -11)" in crashed.error and crashed.outcome == Outcome.RUNTIME_ERROR.value
    assert "RuntimeError: no world here" in raised.error
    # Forked afresh for each trial, from the same worker: distinct processes.
    assert len({first.output, last.output, again[0].output}) == 3


def test_a_trial_past_its_budget_is_killed_with_its_worker_and_the_next_runs(monkeypatch):
    monkeypatch.setattr(runner, "KILL_GRACE", 0.0)
    with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:
        hung, after = pool.run([_spec("hang", timeout=1.0), _spec("ok")])
    assert hung.outcome == Outcome.TIMEOUT.value and "(killed)" in hung.error
    assert after.ok


def test_a_trial_is_over_when_it_has_reported_though_a_process_it_left_holds_its_pipe(monkeypatch):
    monkeypatch.setattr(runner, "KILL_GRACE", 0.0)
    with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:
        (record,) = pool.run([_spec("linger", timeout=20.0)])  # waiting for the pipe's end would reach the limit
    os.kill(int(record.output), signal.SIGKILL)
    assert record.ok and record.outcome == Outcome.OK.value


def test_what_a_trial_registered_for_its_process_end_runs_when_it_ends(tmp_path):
    marker = tmp_path / "marker"
    spec = TrialSpec("clean up", "panda", 0, 0, str(marker))
    with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:
        (record,) = pool.run([spec])
    assert record.ok and marker.read_text() == "cleaned up"


def test_jobs_must_be_positive():
    with pytest.raises(ValueError, match="jobs must be at least 1, got 0"):
        TrialPool(0)


def test_gl_is_kept_across_forks_only_on_a_threadless_software_rasteriser(monkeypatch):
    monkeypatch.setenv("LP_NUM_THREADS", "4")
    assert not shared_gl.fork_safe()
    monkeypatch.setenv("LP_NUM_THREADS", "0")
    if os.environ.get("MUJOCO_GL") in ("egl", "osmesa"):  # this machine renders on Mesa's CPU rasteriser
        assert shared_gl.fork_safe()


def test_a_renderer_kept_for_one_build_of_a_world_renders_another_exactly_as_its_own():
    seed0 = MujocoBackend("world_1_table_sort", robot="panda", seed=0, randomize=True, settle=0.0)
    seed1 = MujocoBackend("world_1_table_sort", robot="panda", seed=1, randomize=True, settle=0.0)
    world0, world1 = seed0.sim_world, seed1.sim_world
    assert shared_gl.geometry_key(world0.model) == shared_gl.geometry_key(world1.model)
    assert not np.allclose(world0.model.body_pos, world1.model.body_pos)  # the seeds placed objects apart
    own = Renderer(world1.model, world1.geom_entity, 160, 120, antialiasing=False)
    depth, segments = own.depth_and_segmentation(world1.data, "camera_left")
    shared_gl.share_renderers()
    try:
        first = Renderer(world0.model, world0.geom_entity, 160, 120, antialiasing=False)
        first.depth(world0.data, "camera_left")
        kept = Renderer(world1.model, world1.geom_entity, 160, 120, antialiasing=False)
        assert kept._renderer is first._renderer  # the GL side is the one made for seed 0's world
        kept_depth, kept_segments = kept.depth_and_segmentation(world1.data, "camera_left")
    finally:
        shared_gl.stop_sharing()
    np.testing.assert_array_equal(kept_depth, depth)
    np.testing.assert_array_equal(kept_segments, segments)
    own.close()
    seed0.close()
    seed1.close()


def test_a_trial_stuck_in_a_tool_past_its_announced_deadline_is_ended_by_the_watchdog_as_a_timeout():
    with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:
        stuck, after = pool.run([_spec("stuck", timeout=300.0), _spec("ok")])
    # Ended by the watchdog, not by the runner's own budget (the limit and a minute), which says "(killed)".
    assert stuck.outcome == Outcome.TIMEOUT.value and "a tool it called did not return" in stuck.error
    assert after.ok


def test_what_a_trial_prints_goes_to_stderr_and_the_commands_stdout_stays_its_own():
    code = (
        "from test_runner import _fake_trial, _no_warm, _spec\nfrom roboscript.bench.runner import TrialPool\n"
        "with TrialPool(1, serve_args=(_fake_trial, _no_warm)) as pool:\n    (record,) = pool.run([_spec('noisy')])\n"
        "print('RESULT', record.ok)"
    )
    environment = {**os.environ, "PYTHONPATH": str(Path(__file__).parent)}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=environment, timeout=300)
    assert done.stdout == "RESULT True\n", done.stdout
    assert "NOISE from C" in done.stderr and "whole_task_success" in done.stderr
