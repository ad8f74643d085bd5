"""Runs trials in child processes, a few at a time, and hands each record over as soon as it is finished.

Each trial runs in its own process, forked from a trial worker (:mod:`roboscript.bench.workers`, itself started
from a clean fork server) that keeps what trials share: a program that crashes the interpreter, exhausts memory or
never returns costs that trial only. The trial enforces the program's time limit itself (so the world is still
judged); the runner kills a trial that outlives its budget (stuck in native code), with its worker, and records it.
"""

from __future__ import annotations

import contextlib
import multiprocessing as mp
import os
import signal
import sys
import time
from collections.abc import Callable, Iterable
from multiprocessing.connection import wait

from roboscript.bench import workers
from roboscript.bench.trial import COULD_NOT_RUN, TrialRecord, TrialSpec
from roboscript.codegen.outcomes import Outcome
from roboscript.errors import InvalidArgumentError
from roboscript.load import load_factor

KILL_GRACE = 60.0  # seconds beyond the program's limit for world building and judging
LLM_GRACE = 600.0  # seconds an LLM may take to write (or repair) one program, helpers included


def wall_budget(spec: TrialSpec) -> float:
    """How long a trial may take before its process is killed: each attempt's limit and margins."""
    per_attempt = spec.timeout + KILL_GRACE + (LLM_GRACE if spec.author is not None else 0.0)
    return spec.attempts() * per_attempt


def failed_record(
    spec: TrialSpec, error: str, started: float | None = None, outcome: Outcome = Outcome.RUNTIME_ERROR
) -> TrialRecord:
    """The record of a trial that ended without reporting (killed, its process or worker died): no checks run;
    the wall time since ``started`` (a ``perf_counter`` reading) where known."""
    return TrialRecord(
        task=spec.task,
        robot=spec.robot,
        trial=spec.trial,
        seed=spec.seed,
        ok=False,
        error=error,
        checks=[],
        wall_time_s=round(time.perf_counter() - started, 3) if started is not None else 0.0,
        outcome=outcome.value,
    )


def _death(spec: TrialSpec, exitcode: int | None, started: float) -> TrialRecord:
    if exitcode == -signal.SIGXCPU:  # the sandbox's CPU-time backstop (a C-level loop the timer cannot stop)
        error = f"TimeoutError: the program ran past its CPU-time limit ({spec.timeout:g} s and a margin; killed)"
        return failed_record(spec, error, started, Outcome.TIMEOUT)
    return failed_record(spec, f"the trial's process died (exit code {exitcode})", started)


def trial_context() -> mp.context.BaseContext:
    """Trial workers start from a fork server: a clean process that has imported the simulator and the tools but
    run nothing but compile each robot once (:mod:`roboscript.bench.warm`: a trial then builds its world in a tenth
    of a second instead of four). Forking the caller itself would copy whatever state it is in, and a process that
    has run OpenMP code (Open3D's fusion) hangs its forked children the moment they run OpenMP code too."""
    context = mp.get_context("forkserver")
    context.set_forkserver_preload(
        [
            "roboscript.bench.trial",
            "roboscript.bench.workers",
            "roboscript.api",
            "roboscript.backends.mujoco_backend",
            "roboscript.bench.warm",
        ]
    )
    return context


def default_jobs() -> int:
    return max(1, min(os.cpu_count() or 1, 8))


class _Worker:
    """The runner's handle on one trial worker (:mod:`roboscript.bench.workers`) and the trial it runs."""

    def __init__(self, context: mp.context.BaseContext, serve_args: tuple):
        self.conn, theirs = context.Pipe(duplex=True)
        sys.stdout.flush()
        sys.stderr.flush()
        self.process = context.Process(target=workers.serve, args=(theirs, *serve_args), daemon=True)
        self.process.start()
        theirs.close()
        self.spec: TrialSpec | None = None
        self.started = 0.0
        self.trial_pid: int | None = None

    def give(self, spec: TrialSpec) -> None:
        self.spec, self.started, self.trial_pid = spec, time.perf_counter(), None
        self.conn.send(spec)

    def kill(self) -> None:
        """Kills the trial and the worker (a trial dies with its worker anyway; this does not wait for that)."""
        for pid in (self.trial_pid, self.process.pid):
            if pid is not None:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, signal.SIGKILL)
        self.process.join(5)

    def stop(self) -> None:
        with contextlib.suppress(OSError):
            self.conn.send(None)
        self.process.join(5)
        if self.process.is_alive():
            self.kill()


def run_isolated(
    specs: Iterable[TrialSpec],
    jobs: int = 1,
    on_record: Callable[[TrialRecord], None] | None = None,
    on_stage: Callable[[TrialSpec, str], None] | None = None,
) -> list[TrialRecord]:
    """Runs every trial in a process of its own, at most ``jobs`` at once; ``on_record`` gets each as it ends,
    ``on_stage`` each stage a trial reports (what it is doing, in words) with the trial's spec."""
    with TrialPool(jobs) as pool:
        return pool.run(specs, on_record, on_stage=on_stage)


class TrialPool:
    """Up to ``jobs`` trial workers (:mod:`roboscript.bench.workers`), kept across :meth:`run` calls so that what
    they have made for earlier trials serves later ones. ``serve_args`` go to
    :func:`roboscript.bench.workers.serve` (the runner's tests give it trials that crash or hang)."""

    def __init__(self, jobs: int = 1, serve_args: tuple = ()):
        if jobs < 1:
            raise InvalidArgumentError(f"jobs must be at least 1, got {jobs}")
        self.jobs, self._serve_args = jobs, serve_args
        self._context = trial_context()
        self._idle: list[_Worker] = []

    def __enter__(self) -> TrialPool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        """Stops the idle workers."""
        while self._idle:
            self._idle.pop().stop()

    def run(
        self,
        specs: Iterable[TrialSpec],
        on_record: Callable[[TrialRecord], None] | None = None,
        on_result: Callable[[TrialSpec, TrialRecord], None] | None = None,
        on_stage: Callable[[TrialSpec, str], None] | None = None,
    ) -> list[TrialRecord]:
        """Runs every trial, at most ``jobs`` at once; ``on_record`` gets each record as it ends, ``on_result``
        the spec it was run from with it, ``on_stage`` each stage a trial reports. Returns the records in the order
        they ended."""
        pending = list(specs)
        busy: dict[object, _Worker] = {}
        records: list[TrialRecord] = []

        def finish(spec: TrialSpec, record: TrialRecord) -> None:
            records.append(record)
            if on_record is not None:
                on_record(record)
            if on_result is not None:
                on_result(spec, record)

        try:
            while pending or busy:
                while pending and len(busy) < self.jobs:
                    worker = self._idle.pop() if self._idle else _Worker(self._context, self._serve_args)
                    worker.give(pending.pop(0))
                    busy[worker.conn] = worker
                for conn in wait(list(busy), timeout=1.0):
                    worker = busy[conn]
                    spec, started = worker.spec, worker.started
                    try:
                        status, payload = conn.recv()
                    except (EOFError, OSError):  # the worker itself died: its trial is lost, a new one takes over
                        del busy[conn]
                        worker.kill()
                        error = f"the trial's worker died (exit code {worker.process.exitcode})"
                        finish(spec, failed_record(spec, error, started))
                        continue
                    if status == "started":
                        worker.trial_pid = payload
                        continue
                    if status == "stage":
                        if on_stage is not None:
                            on_stage(spec, payload)
                        continue
                    del busy[conn]
                    self._idle.append(worker)
                    if status == "ok":
                        finish(spec, TrialRecord(**payload))
                    elif status == "died":
                        finish(spec, _death(spec, payload, started))
                    elif status == "timeout":  # the worker's watchdog ended it
                        finish(spec, failed_record(spec, payload, started, Outcome.TIMEOUT))
                    else:
                        finish(spec, failed_record(spec, f"{COULD_NOT_RUN}: {payload}", started))
                now = time.perf_counter()
                for conn, worker in list(busy.items()):
                    spec = worker.spec
                    if now - worker.started > wall_budget(spec) * load_factor():  # the trial's limit scaled alike
                        del busy[conn]
                        worker.kill()  # a trial stuck in native code; its worker goes too, a fresh one takes over
                        error = f"TimeoutError: the program ran longer than its {spec.timeout:g} s limit (killed)"
                        finish(spec, failed_record(spec, error, worker.started, Outcome.TIMEOUT))
        finally:
            # An interrupted run (Ctrl-C, SIGTERM, an error here) leaves no trial running: each one's master and
            # twin go with it (see roboscript.ros.launch).
            for worker in busy.values():
                worker.kill()
        return records
