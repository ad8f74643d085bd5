"""A trial run with MuJoCo's stepping timed, for ``trial_speed.py``: the function a trial worker forks to run
(:func:`roboscript.bench.workers.serve`'s ``run``). The stepping time travels in the record's phases."""

from __future__ import annotations

import time

import mujoco

from roboscript.bench.trial import TrialSpec, run_trial

STEPPING = "mj_step"  # the key of the stepping time in the record's phases


def run(spec: TrialSpec) -> dict:
    stepping = [0.0]
    step = mujoco.mj_step

    def timed_step(*args, **kwargs):
        started = time.perf_counter()
        step(*args, **kwargs)
        stepping[0] += time.perf_counter() - started

    mujoco.mj_step = timed_step
    try:
        record = run_trial(spec).to_dict()
    finally:
        mujoco.mj_step = step
    record["phases"][STEPPING] = stepping[0]
    return record
