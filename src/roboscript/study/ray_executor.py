"""Trials on a Ray cluster (the ``ray`` extra): one actor per CPU slot, each a trial pool of one on its node.

An actor keeps its trial worker between trials (:mod:`roboscript.bench.workers`), so what a world's trials share is
made once per node and world, as on one machine; each trial still runs in a process of its own. Records (and the
videos that are kept) travel back to the driver, which alone writes them.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from roboscript import extras
from roboscript.bench.trial import TrialRecord, TrialSpec
from roboscript.datafile import names_a_file
from roboscript.errors import InvalidArgumentError
from roboscript.study.sweep import Executor

CLOSE_TIMEOUT = 30.0  # seconds the actors are given to remove their scratch folders at the end of a run


def _ray():
    try:
        import ray
    except ImportError:
        raise extras.missing("ray", "--ray") from None
    return ray


def pack_suite(suite: str) -> dict[str, bytes]:
    """A suite file with the world files and reference programs it names, by path relative to its folder: what a
    node without the driver's files needs to run its tasks (a study's suite is written on the driver)."""
    from roboscript.bench.task_file import load_suite_file

    path = Path(suite).resolve()
    base = path.parent
    files = [path]
    for task in load_suite_file(path):
        for named in (Path(task.world) if Path(task.world).suffix else None, task.reference):
            if named is not None and named.is_file():
                files.append(named.resolve())
    packed = {}
    for file in files:
        if not file.is_relative_to(base):
            raise InvalidArgumentError(
                f"{file} is outside the suite's folder {base}; on Ray a suite's files must lie beside it"
            )
        packed[str(file.relative_to(base))] = file.read_bytes()
    return packed


class TrialActor:
    """Runs trials one at a time on its node; Ray makes it remote (``ray.remote(num_cpus=1)``)."""

    def __init__(self) -> None:
        from roboscript.bench.runner import TrialPool

        self.pool = TrialPool(1)
        self.scratch = Path(tempfile.mkdtemp(prefix="roboscript-ray-"))
        self.suites: dict[str, str] = {}  # the driver's suite file -> this node's copy

    def _local_suite(self, suite: str, packed: dict[str, bytes]) -> str:
        if suite not in self.suites:
            folder = self.scratch / f"suite{len(self.suites)}"
            for relative, data in packed.items():
                (folder / relative).parent.mkdir(parents=True, exist_ok=True)
                (folder / relative).write_bytes(data)
            self.suites[suite] = str(folder / Path(suite).name)
        return self.suites[suite]

    def close(self) -> None:
        """Removes this actor's scratch folder (its copies of suites, and videos not yet sent)."""
        shutil.rmtree(self.scratch, ignore_errors=True)

    def run(self, spec: TrialSpec, packed_suite: dict[str, bytes] | None = None) -> tuple[dict, bytes | None]:
        """The trial's record, and its video's bytes where it recorded one (written here in a scratch folder:
        the driver's paths need not exist on this node). A suite given as a file comes packed
        (:func:`pack_suite`) and runs from this node's copy."""
        if packed_suite is not None:
            spec = replace(spec, suite=self._local_suite(spec.suite, packed_suite))
        video = None
        if spec.video:
            video = self.scratch / f"{os.getpid()}_{Path(spec.video).name}"
            spec = replace(spec, video=str(video))
        record = self.pool.run([spec])[0]
        record.node = _ray().util.get_node_ip_address()
        data = None
        if video is not None and video.is_file():
            data = video.read_bytes()
            video.unlink()
        return record.to_dict(), data


class RayExecutor(Executor):
    """Runs trials on the Ray cluster at ``address`` (``auto``, ``host:port``), or on a local one that it starts
    on loopback with ``jobs`` CPUs when no address is given; ``jobs`` actors (default: the cluster's CPUs) run at
    once. Each record names the node that ran it (``node``, its address)."""

    def __init__(self, address: str | None = None, jobs: int | None = None):
        ray = _ray()
        os.environ.setdefault("RAY_AUTH_MODE", "disabled")
        self.started_here = not ray.is_initialized()
        if self.started_here and address is None:
            _start_local(ray, jobs)
        elif self.started_here:
            ray.init(address=address, include_dashboard=False, log_to_driver=False)
        self.jobs = jobs or max(1, int(ray.cluster_resources().get("CPU", 1)))

    def run(self, specs: list[TrialSpec], on_result: Callable[[TrialSpec, TrialRecord], None]) -> None:
        ray = _ray()
        remote = ray.remote(num_cpus=1)(TrialActor)
        actors = [remote.remote() for _ in range(min(self.jobs, len(specs)))]
        pending = list(specs)
        running: dict = {}
        packed = {suite: ray.put(pack_suite(suite)) for suite in {s.suite for s in specs} if names_a_file(suite)}

        def give(actor) -> None:
            spec = pending.pop(0)
            running[actor.run.remote(spec, packed.get(spec.suite))] = (actor, spec)

        try:
            for actor in actors:
                if pending:
                    give(actor)
            while running:
                ready, _ = ray.wait(list(running), num_returns=1)
                actor, spec = running.pop(ready[0])
                try:
                    payload, video = ray.get(ready[0])
                    record = TrialRecord(**payload)
                except ray.exceptions.RayError as exc:  # the actor or its node died: the trial is lost
                    record = _lost(spec, exc)
                    actor = remote.remote()
                    actors.append(actor)
                    video = None
                if video is not None and spec.video:
                    Path(spec.video).parent.mkdir(parents=True, exist_ok=True)
                    Path(spec.video).write_bytes(video)
                on_result(spec, record)
                if pending:
                    give(actor)
        finally:
            closing = []
            busy = {id(actor) for actor, _ in running.values()}  # a run cut short: these are killed as they are
            for actor in actors:
                if id(actor) in busy:
                    continue
                with contextlib.suppress(Exception):  # already dead with its node
                    closing.append(actor.close.remote())
            with contextlib.suppress(Exception):  # an actor that does not answer keeps its folder
                ray.wait(closing, num_returns=len(closing), timeout=CLOSE_TIMEOUT)
            for actor in actors:
                with contextlib.suppress(Exception):
                    ray.kill(actor)

    def close(self) -> None:
        if self.started_here:
            _ray().shutdown()


def _start_local(ray, cpus: int | None) -> None:
    """Starts a Ray cluster of this machine alone, on loopback: its processes listen on 127.0.0.1, not on every
    interface. Ray replaces 127.0.0.1 with this machine's interface address (for other nodes to join) unless it
    believes multi-node clusters are off, which it reads from ``RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER`` once, on import;
    so it is told they are off while it starts (a private constant of Ray's: the extra pins Ray's version)."""
    from ray._private import ray_constants

    clusters = ray_constants.ENABLE_RAY_CLUSTER
    ray_constants.ENABLE_RAY_CLUSTER = False
    try:
        options = {"num_cpus": cpus} if cpus else {}
        ray.init(include_dashboard=False, log_to_driver=False, _node_ip_address="127.0.0.1", **options)
    finally:
        ray_constants.ENABLE_RAY_CLUSTER = clusters


def _lost(spec: TrialSpec, exc: Exception) -> TrialRecord:
    from roboscript.bench.runner import failed_record

    first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
    return failed_record(spec, f"the trial's Ray actor died: {first}")
