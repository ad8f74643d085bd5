"""MuJoCo's stepping timed around a trial, for ``trial_speed.py``: :func:`run` is the function a trial worker forks
to run (:func:`roboscript.bench.workers.serve`'s ``run``), and carries the stepping time in the record's phases."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TypeVar

import mujoco

from roboscript.bench.trial import TrialSpec, run_trial

STEPPING = "mj_step"  # the key of the stepping time in the record's phases
T = TypeVar("T")


def stepping_timed(call: Callable[[], T]) -> tuple[T, float]:
    """What ``call()`` returns, and the seconds it spent in ``mujoco.mj_step``."""
    stepping = [0.0]
    step = mujoco.mj_step

    def timed_step(*args, **kwargs):
        started = time.perf_counter()
        step(*args, **kwargs)
        stepping[0] += time.perf_counter() - started

    mujoco.mj_step = timed_step
    try:
        return call(), stepping[0]
    finally:
        mujoco.mj_step = step


def run(spec: TrialSpec) -> dict:
    record, stepping = stepping_timed(lambda: run_trial(spec).to_dict())
    record["phases"][STEPPING] = stepping
    return record
