"""Progress of a run as its trials end: a line per trial (``exec``), or a bar with trials done of all, how many
succeeded and failed, time spent and an estimate of the time left (``bench``, sweeps; from this session's pace, so a
resumed run does not count what an earlier session did)."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import TextIO

from roboscript.bench.trial import TrialRecord


def trial_status(record: TrialRecord) -> str:
    """How a trial ended, in a word or two: ``ok`` (every check passed), ``checks failed`` (the program ran to its
    end and left the world short of them), ``ran`` (it ran to its end and nothing was checked), or its error."""
    if not record.ok:
        return f"error: {record.error.splitlines()[0] if record.error else record.outcome}"
    if not record.checks:
        return "ran"
    return "ok" if record.success else "checks failed"


def progress_printer(total: int, stream: TextIO | None = None) -> Callable[[TrialRecord], None]:
    """A line per trial as it ends: ``[2/10] simple_0 trial 1: 0/1 checks, checks failed (3.2 s)``."""
    count = [0]

    def report(record: TrialRecord) -> None:
        count[0] += 1
        checks = f"{record.passed}/{len(record.checks)} checks, " if record.checks else ""
        print(
            f"[{count[0]}/{total}] {record.task} trial {record.trial}: {checks}{trial_status(record)} "
            f"({record.wall_time_s:.1f} s)",
            file=stream if stream is not None else sys.stderr,
            flush=True,
        )

    return report


def _duration(seconds: float) -> str:
    seconds = round(seconds)
    hours, rest = divmod(seconds, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}h{minutes:02d}m" if hours else f"{minutes}m{secs:02d}s"


class ProgressBar:
    """Counts trials as they end and shows ``[####----] 120/400 30% | ok 110 failed 10 | 4m10s, ETA 9m44s``.

    On a terminal the line is redrawn in place; elsewhere (a log file, CI) each trial writes one line, so the log
    keeps which trial ended how."""

    WIDTH = 24

    def __init__(self, total: int, done_before: int = 0, stream: TextIO | None = None, clock=time.monotonic):
        self.total, self.done_before = total, done_before
        self.stream = stream if stream is not None else sys.stderr
        self.clock = clock
        self.started = clock()
        self.done = self.succeeded = 0
        self.interactive = bool(getattr(self.stream, "isatty", lambda: False)())

    @property
    def finished(self) -> int:
        return self.done_before + self.done

    def eta(self) -> float | None:
        """Seconds left at this session's pace; None before the first trial of this session has ended."""
        if self.done == 0:
            return None
        return (self.clock() - self.started) / self.done * (self.total - self.finished)

    def line(self, last: str = "") -> str:
        fraction = self.finished / self.total if self.total else 1.0
        filled = round(fraction * self.WIDTH)
        eta = self.eta()
        parts = [
            f"[{'#' * filled}{'-' * (self.WIDTH - filled)}] {self.finished}/{self.total} {fraction:4.0%}",
            f"ok {self.succeeded} failed {self.done - self.succeeded}"
            + (f" (+{self.done_before} earlier)" if self.done_before else ""),
            f"{_duration(self.clock() - self.started)}, ETA {'?' if eta is None else _duration(eta)}",
        ]
        return " | ".join(parts) + (f" | {last}" if last else "")

    def update(self, record: TrialRecord, label: str = "") -> None:
        self.done += 1
        self.succeeded += record.success
        last = f"{label or record.task} #{record.trial}: {trial_status(record)}"
        if self.interactive:
            self.stream.write("\r\033[K" + self.line(last))
            if self.finished >= self.total:
                self.stream.write("\n")
        else:
            self.stream.write(self.line(last) + "\n")
        self.stream.flush()
