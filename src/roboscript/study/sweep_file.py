"""Sweep files: the product of tasks (or a study's cells), trials, policies, robots and perception modes.

::

    sweep: ablation                  # a name (the default output folder is out/sweeps/<name>)
    suite: paper                     # a packaged suite or a suite file; or, instead of suite and tasks:
    # study: {name: objects, templates: [drawer], objects: [apple, banana], grasps: [central]}
    tasks: [simple_0, hard_2]        # default: every task of the suite
    policies: [reference, "llm:openai:gpt-4o"]
    robots: [panda, ur5e]
    perception: [gt, gt-2d]
    trials: 10                       # per task and combination; trial i uses seed + i
    seed: 0
    timeout: 300                     # seconds a program may run
    repair_rounds: 0
    videos: failed                   # none, failed (kept for trials that did not succeed) or all

Every problem is a :class:`SweepFileError` that names the file, the entry and what would be valid.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from roboscript.bench.results import VIDEO_CHOICES
from roboscript.datafile import DataFileError, Reader, names_a_file, read_data_file
from roboscript.errors import InvalidArgumentError

_FIELDS = {
    "sweep", "description", "suite", "study", "tasks", "policies", "robots", "perception", "trials", "seed",
    "timeout", "repair_rounds", "videos",
}  # fmt: skip
_STUDY_FIELDS = {"name", "templates", "objects", "grasps"}


class SweepFileError(DataFileError):
    """A sweep file that cannot be loaded; the message names the file, the entry and the problem."""

    kind = "sweep"


@dataclass(frozen=True)
class StudySelection:
    """The cells of a study a sweep runs: its templates, objects and grasp tools (all of each where None)."""

    name: str
    templates: tuple[str, ...] | None = None
    objects: tuple[str, ...] | None = None
    grasps: tuple[str, ...] | None = None


@dataclass(frozen=True)
class Sweep:
    """A validated sweep: every combination of policy, robot and perception mode is a run (a run directory), and
    every task and trial of a run an independent job."""

    name: str
    suite: str = "paper"
    study: StudySelection | None = None
    tasks: tuple[str, ...] | None = None
    policies: tuple[str, ...] = ("reference",)
    robots: tuple[str, ...] = ("panda",)
    perception: tuple[str, ...] = ("gt",)
    trials: int = 10
    seed: int = 0
    timeout: float = 300.0
    repair_rounds: int = 0
    videos: str = "none"
    description: str = ""

    def __post_init__(self) -> None:
        if self.trials < 1:
            raise InvalidArgumentError(f"a sweep needs at least 1 trial, got {self.trials}")
        if self.videos not in VIDEO_CHOICES:
            raise InvalidArgumentError(f"videos must be one of {', '.join(VIDEO_CHOICES)}, got {self.videos!r}")


def _names(reader: Reader, key: str, default: tuple[str, ...] | None) -> tuple[str, ...] | None:
    value = reader.data.get(key)
    if value is None:
        return default
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not value or not all(isinstance(v, str) and v for v in value):
        reader.fail(f"field {key!r} must be a name or a non-empty list of names, got {value!r}")
    if len(set(value)) != len(value):
        reader.fail(f"field {key!r} lists a name twice: {value}")
    return tuple(value)


def _valid(reader: Reader, names: tuple[str, ...], check: Callable[[str], object]) -> tuple[str, ...]:
    """``names``, each accepted by ``check``; the first it refuses fails the entry with ``check``'s message (which
    names the valid choices)."""
    for name in names:
        try:
            check(name)
        except ValueError as exc:
            reader.fail(str(exc))
    return names


def _whole(reader: Reader, key: str, default: int, least: int) -> int:
    value = reader.data.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        reader.fail(f"field {key!r} must be a whole number of at least {least}, got {value!r}")
    return value


def parse_sweep(data: Any, source: str = "<memory>", base: Path | None = None) -> Sweep:
    """Validates a sweep given as parsed YAML/JSON data; a suite file it names is found relative to ``base``.
    Policies, perception modes, suites and studies are checked here too, so a typo fails before any trial runs."""
    from roboscript.bench.benchmark import policy_llm
    from roboscript.perception.modes import parse_mode
    from roboscript.robots import get_robot

    r = Reader(source, "sweep", data, _FIELDS, SweepFileError)
    name = r.string("sweep")
    if "suite" in r.data and "study" in r.data:
        r.fail("give either 'suite' (with 'tasks') or 'study' (its cells are the tasks), not both")
    study = None
    suite = r.string("suite", "paper")
    if "study" in r.data:
        if "tasks" in r.data:
            r.fail("a study's tasks are its cells: choose them with study.templates, study.objects, study.grasps")
        study = _parse_study(source, r.data["study"])
    elif names_a_file(suite) and base is not None and not Path(suite).is_absolute():
        suite = str((base / suite).resolve())
    robots = _valid(r, _names(r, "robots", ("panda",)), get_robot)
    policies = _valid(r, _names(r, "policies", ("reference",)), policy_llm)
    perception = _valid(r, _names(r, "perception", ("gt",)), parse_mode)
    videos = r.string("videos", "none")
    if videos not in VIDEO_CHOICES:
        r.fail(f"videos must be one of {', '.join(VIDEO_CHOICES)}, got {videos!r}")
    timeout = r.number("timeout", 300.0)
    if timeout <= 0:
        r.fail(f"timeout must be positive, got {timeout}")
    sweep = Sweep(
        name=name,
        suite=suite,
        study=study,
        tasks=_names(r, "tasks", None),
        policies=policies,
        robots=robots,
        perception=perception,
        trials=_whole(r, "trials", 10, 1),
        seed=_whole(r, "seed", 0, 0),
        timeout=timeout,
        repair_rounds=_whole(r, "repair_rounds", 0, 0),
        videos=videos,
        description=r.text("description"),
    )
    _check_tasks(r, sweep)
    return sweep


def _parse_study(source: str, data: Any) -> StudySelection:
    if isinstance(data, str):
        data = {"name": data}
    s = Reader(source, "sweep.study", data, _STUDY_FIELDS, SweepFileError)
    return StudySelection(
        s.string("name"), _names(s, "templates", None), _names(s, "objects", None), _names(s, "grasps", None)
    )


def _check_tasks(r: Reader, sweep: Sweep) -> None:
    """The suite (or study) exists and holds every task named."""
    try:
        if sweep.study is not None:
            from roboscript.study.cells import select_cells
            from roboscript.study.study_file import load_study

            s = sweep.study
            select_cells(load_study(s.name), s.templates, s.objects, s.grasps)
            return
        from roboscript.bench.tasks import get_task, load_suite

        load_suite(sweep.suite)
        for task in sweep.tasks or ():
            get_task(task, sweep.suite)
    except (KeyError, ValueError) as exc:
        r.fail(exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc))


def load_sweep_file(path: str | Path) -> Sweep:
    """Reads and validates a ``.yaml``/``.yml``/``.json`` sweep file."""
    path = Path(path)
    return parse_sweep(read_data_file(path, SweepFileError), str(path), path.parent.resolve())
