"""Runs trials in child processes, a few at a time, and hands each record over as soon as it is finished.

Each trial runs in its own process (forked from a clean fork server): a program that crashes the interpreter,
exhausts memory or never returns costs that trial only. The child enforces the program's time limit itself (so the
world is still judged); the parent kills a child that outlives its budget (stuck in native code) and records it.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import signal
import sys
import time
from collections.abc import Callable, Iterable
from multiprocessing.connection import wait

from roboscript.bench.trial import TrialRecord, TrialSpec, run_trial
from roboscript.codegen.outcomes import Outcome
from roboscript.load import load_factor

KILL_GRACE = 60.0  # seconds beyond the program's limit for world building and judging
LLM_GRACE = 600.0  # seconds an LLM may take to write (or repair) one program, helpers included


def wall_budget(spec: TrialSpec) -> float:
    """How long a trial may take before its process is killed: each attempt's limit and margins."""
    per_attempt = spec.timeout + KILL_GRACE + (LLM_GRACE if spec.llm is not None else 0.0)
    return spec.attempts() * per_attempt


def _child(spec: TrialSpec, conn) -> None:
    try:
        record = run_trial(spec)
        conn.send(("ok", record.to_dict()))
    except BaseException as exc:  # the world could not be built, or judging failed: report, do not hang
        import traceback

        conn.send(("error", f"{type(exc).__name__}: {exc}\n{traceback.format_exc(limit=4)}"))
    finally:
        conn.close()


def _failed(spec: TrialSpec, error: str, started: float, outcome: Outcome = Outcome.RUNTIME_ERROR) -> TrialRecord:
    return TrialRecord(
        task=spec.task,
        robot=spec.robot,
        trial=spec.trial,
        seed=spec.seed,
        ok=False,
        error=error,
        checks=[],
        wall_time_s=round(time.perf_counter() - started, 3),
        outcome=outcome.value,
    )


def _death(spec: TrialSpec, exitcode: int | None, started: float) -> TrialRecord:
    if exitcode == -signal.SIGXCPU:  # the sandbox's CPU-time backstop (a C-level loop the timer cannot stop)
        error = f"TimeoutError: the program ran past its CPU-time limit ({spec.timeout:g} s and a margin; killed)"
        return _failed(spec, error, started, Outcome.TIMEOUT)
    return _failed(spec, f"the trial's process died (exit code {exitcode})", started)


def trial_context() -> mp.context.BaseContext:
    """Trials start from a fork server: a clean process that has imported the simulator and the tools but run
    nothing but compile each robot once (:mod:`roboscript.bench.warm`: a trial then builds its world in a third
    of a second instead of four). Forking the caller itself would copy whatever state it is in, and a process that
    has run OpenMP code (Open3D's fusion) hangs its forked children the moment they run OpenMP code too."""
    context = mp.get_context("forkserver")
    context.set_forkserver_preload(
        ["roboscript.bench.trial", "roboscript.api", "roboscript.backends.mujoco_backend", "roboscript.bench.warm"]
    )
    return context


def default_jobs() -> int:
    return max(1, min(os.cpu_count() or 1, 8))


def run_isolated(
    specs: Iterable[TrialSpec], jobs: int = 1, on_record: Callable[[TrialRecord], None] | None = None
) -> list[TrialRecord]:
    """Runs every trial in a child process, at most ``jobs`` at once; ``on_record`` gets each as it ends."""
    if jobs < 1:
        raise ValueError(f"jobs must be at least 1, got {jobs}")
    context = trial_context()
    pending = list(specs)
    running: dict[object, tuple[TrialSpec, object, float]] = {}
    records: list[TrialRecord] = []

    def finish(record: TrialRecord) -> None:
        records.append(record)
        if on_record is not None:
            on_record(record)

    try:
        while pending or running:
            while pending and len(running) < jobs:
                spec = pending.pop(0)
                receiver, sender = context.Pipe(duplex=False)
                process = context.Process(target=_child, args=(spec, sender), daemon=True)
                sys.stdout.flush()
                sys.stderr.flush()
                process.start()
                sender.close()
                running[receiver] = (spec, process, time.perf_counter())
            ready = wait(list(running), timeout=1.0)
            for receiver in ready:
                spec, process, started = running.pop(receiver)
                try:
                    status, payload = receiver.recv()
                except EOFError:
                    process.join(5)
                    finish(_death(spec, process.exitcode, started))
                    continue
                process.join(5)
                if status == "ok":
                    finish(TrialRecord(**payload))
                else:
                    finish(_failed(spec, f"the trial could not be run: {payload}", started))
            now = time.perf_counter()
            for receiver, (spec, process, started) in list(running.items()):
                if now - started > wall_budget(spec) * load_factor():  # the trial's own limit scaled alike
                    process.kill()
                    process.join(5)
                    running.pop(receiver)
                    finish(
                        _failed(
                            spec,
                            f"TimeoutError: the program ran longer than its {spec.timeout:g} s limit (killed)",
                            started,
                            Outcome.TIMEOUT,
                        )
                    )
    finally:
        # An interrupted run (Ctrl-C, SIGTERM, an error here) leaves no trial running: each one's master and twin
        # go with it (see roboscript.ros.launch).
        for _, process, _ in running.values():
            process.kill()
            process.join(5)
    return records
